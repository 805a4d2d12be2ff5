"""Fixtures of the browser tests (tests/test_browser.py, tests/test_builder_browser.py): one
app server and one chromium profile per test module."""

import asyncio

import pytest

from deploy.client import free_port, start_server, wait_ready


@pytest.fixture(scope="module")
def app_url(tmp_path_factory):
    port = free_port()
    log = open(tmp_path_factory.mktemp("server") / "streamlit.log", "w")
    server = start_server(port, log=log)
    try:
        asyncio.run(wait_ready(f"ws://127.0.0.1:{port}/_stcore/stream"))
        yield f"http://127.0.0.1:{port}"
    finally:
        server.terminate()
        server.wait(timeout=10)
        log.close()


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    from playwright.sync_api import sync_playwright

    from .test_browser import CHROMIUM, FLAGS

    with sync_playwright() as p:
        context = p.chromium.launch_persistent_context(
            str(tmp_path_factory.mktemp("profile")), executable_path=CHROMIUM, args=FLAGS,
            viewport={"width": 1400, "height": 900})
        yield context
        context.close()
