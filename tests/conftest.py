"""Fixtures of the browser tests (tests/test_browser.py, tests/test_builder_browser.py): one
app server and one chromium profile per test module.

The suite runs on both cores (pytest-xdist, ``-n auto --dist loadgroup`` in pyproject.toml):
a module whose tests share something costly — a fixture of module or session scope (a
server, a browser, a PostgreSQL, a class found once) — is one group and runs on one worker,
so that cost is paid once; every other test goes to whichever worker is free
(``pytest_collection_modifyitems`` below: the groups come from the fixtures themselves, not
from a list kept by hand). Hypothesis runs the same examples each time (derandomised), and
``HYPOTHESIS_PROFILE=explore`` looks for new ones and keeps the failures it finds.

Every ``ui`` module is imported here, before any test: several tests patch
``ui.i18n.current`` (AppTest formats a choice outside the script run), and a module first
imported while it is patched would keep the patch in its ``from ui.i18n import current``
for the rest of the session — a page in English then wrote "0,5" (order-dependent).

The error boundary (ui/boundary.py) lets exceptions through in the suite and in the servers
it starts (``MEHANIZMI_ERRORS=raise``), with Streamlit's full details: a test sees a bug, not
a polite sentence. tests/test_boundary.py turns both back to what users get."""

import asyncio
import importlib
import os
import pkgutil
import shutil
from concurrent.futures import ThreadPoolExecutor

import pytest
from hypothesis import settings
from hypothesis.database import DirectoryBasedExampleDatabase
from streamlit import config as streamlit_config

import ui
from deploy.client import free_port, start_server, wait_ready

from .databases import PG_BIN, Postgres

os.environ.setdefault("MEHANIZMI_ERRORS", "raise")
os.environ.setdefault("STREAMLIT_CLIENT_SHOW_ERROR_DETAILS", "full")
streamlit_config.set_option("client.showErrorDetails", "full")  # (AppTest reads config.toml)
for _module in pkgutil.iter_modules(ui.__path__):
    importlib.import_module(f"ui.{_module.name}")

# the suite: the same examples every run (Hypothesis then keeps no database: a derandomised
# run has nothing new to remember); ``HYPOTHESIS_PROFILE=explore``: new random examples, and
# every failure found kept in .hypothesis/ and tried first on the next run (TESTING.md)
settings.register_profile("suite", derandomize=True)
settings.register_profile("explore", database=DirectoryBasedExampleDatabase(".hypothesis/examples"))
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "suite"))

SHARED = {"module", "package", "session"}
BUILT_IN = {"tmp_path_factory", "worker_id", "testrun_uid"}  # (session-wide, but cheap)


LONG = ("browser", "server", "sweep")  # the markers of the suite's long groups


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items):
    """A test that uses a fixture of module scope or wider runs in its module's group (one
    worker pays for the fixture once); the rest are spread freely. The long groups (a
    browser's, a server's, a sweep's) are handed out first and the many short tests fill
    in after them: begun last, a 60-s group kept one worker busy while the other idled at
    the end of the run (the longest-first order; each module's own order is kept)."""
    items.sort(key=lambda item: not any(item.get_closest_marker(m) for m in LONG))
    for item in items:
        info = getattr(item, "_fixtureinfo", None)
        if info is None or item.get_closest_marker("xdist_group"):
            continue
        shared = any(defs[-1].scope in SHARED for name, defs in info.name2fixturedefs.items()
                     if name not in BUILT_IN and defs)
        if shared:
            item.add_marker(pytest.mark.xdist_group(item.module.__name__))


def run_async(coroutine):
    """``asyncio.run`` in a thread of its own: a module's sync Playwright keeps an event loop
    running in the test's thread, where ``asyncio.run`` refuses to start."""
    with ThreadPoolExecutor(1) as pool:
        return pool.submit(asyncio.run, coroutine).result()


@pytest.fixture(scope="session")
def postgres():
    """One PostgreSQL for a worker's whole run (the store's tests, LTI's, the faults'):
    initdb and a start are ~2 s, paid once, not once per module."""
    if PG_BIN is None:
        if os.environ.get("CI"):
            raise RuntimeError("PostgreSQL is missing in CI: scripts/test.sh must install it")
        pytest.skip("Debian's postgresql is not installed (scripts/test.sh installs it)")
    server = Postgres()
    yield server
    server.stop()
    shutil.rmtree(server.dir, ignore_errors=True)


@pytest.fixture(params=["sqlite", "postgresql"])
def url(request, tmp_path):
    """A class store on SQLite and on PostgreSQL: each store test runs on both."""
    if request.param == "sqlite":
        return f"sqlite:///{tmp_path / 'classes.db'}"
    return request.getfixturevalue("postgres").url


@pytest.fixture(scope="session")
def app_url(tmp_path_factory):
    """One app server for a worker's whole run (a server start is ~2 s of imports, and its
    first page run warms the caches every later module then finds warm); each test opens
    its own pages, so nothing of one test's session reaches another's."""
    port = free_port()
    log = open(tmp_path_factory.mktemp("server") / "streamlit.log", "w")
    server = start_server(port, log=log)
    try:
        run_async(wait_ready(f"ws://127.0.0.1:{port}/_stcore/stream"))
        yield f"http://127.0.0.1:{port}"
    finally:
        server.terminate()
        server.wait(timeout=10)
        log.close()


@pytest.fixture(scope="module")
def profile(tmp_path_factory):
    """One chromium per test module (a launch is ~0.3 s; tests open pages in it)."""
    from playwright.sync_api import sync_playwright

    from .test_browser import CHROMIUM, FLAGS

    with sync_playwright() as p:
        context = p.chromium.launch_persistent_context(
            str(tmp_path_factory.mktemp("profile")), executable_path=CHROMIUM, args=FLAGS,
            viewport={"width": 1400, "height": 900})
        yield context
        context.close()


@pytest.fixture
def browser(profile):
    """The module's chromium; the pages a test opened are closed at its end (an open page keeps
    its app session alive, and the next test's clicks shared the machine with it)."""
    kept = set(profile.pages)  # (the profile's own blank page)
    yield profile
    for page in profile.pages:
        if page not in kept:
            page.close()


@pytest.fixture(scope="module")
def chromium():
    """A chromium for a class's people: the browser, and an iPhone 13's settings for a
    student's phone (``browser.new_context(**phone)``)."""
    from playwright.sync_api import sync_playwright

    from .test_browser import CHROMIUM, FLAGS

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        phone = {k: v for k, v in p.devices["iPhone 13"].items() if k != "default_browser_type"}
        yield browser, phone
        browser.close()
