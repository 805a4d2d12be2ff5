"""Real-browser test: Debian's chromium driven by Playwright against a running app.

Skipped on a developer machine without /usr/bin/chromium; in CI (CI=true) a missing
browser is a failure, never a silent skip.
"""

import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = "/usr/bin/chromium"
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage"]

pytestmark = pytest.mark.browser

if not Path(CHROMIUM).exists():
    if os.environ.get("CI") == "true":
        raise RuntimeError(f"{CHROMIUM} is missing in CI: .ci/run must install Debian's chromium")
    pytest.skip(f"{CHROMIUM} not installed (run .ci/run or see README)", allow_module_level=True)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture(scope="module")
def app_url(tmp_path_factory):
    port = free_port()
    log = open(tmp_path_factory.mktemp("server") / "streamlit.log", "w")
    server = subprocess.Popen(
        [sys.executable, "-m", "streamlit", "run", "app.py", "--server.headless", "true",
         "--server.port", str(port), "--browser.gatherUsageStats", "false"],
        cwd=ROOT, stdout=log, stderr=subprocess.STDOUT)
    url = f"http://localhost:{port}"
    try:
        for _ in range(200):
            try:
                if urllib.request.urlopen(f"{url}/_stcore/health", timeout=1).read() == b"ok":
                    break
            except OSError:
                time.sleep(0.1)
        else:
            raise RuntimeError("the app did not start")
        yield url
    finally:
        server.terminate()
        server.wait(timeout=10)
        log.close()


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        context = p.chromium.launch_persistent_context(
            str(tmp_path_factory.mktemp("profile")), executable_path=CHROMIUM, args=FLAGS,
            viewport={"width": 1400, "height": 900})
        yield context
        context.close()


def wait_idle(page) -> None:
    page.wait_for_selector("[data-testid='stApp'][data-test-script-state='notRunning']",
                           timeout=30_000)


def plot_x(page) -> list:
    """The x data of every trace of the Plotly chart, as the browser holds it."""
    return page.evaluate("() => document.querySelector('.js-plotly-plot').data"
                         ".map(t => Array.from(t.x || []).map(v => v === null ? null : +v))")


def test_moving_the_crank_slider_redraws_the_mechanism(app_url, browser, tmp_path):
    page = browser.new_page()
    page.goto(f"{app_url}/trajectories")
    wait_idle(page)
    page.wait_for_selector(".js-plotly-plot")
    before = plot_x(page)
    thumb = page.locator("[data-testid='stSlider'] input[type='range']").first
    thumb.focus()
    for _ in range(30):
        thumb.press("ArrowRight")
    page.wait_for_function(
        "before => JSON.stringify(document.querySelector('.js-plotly-plot').data"
        ".map(t => Array.from(t.x || []).map(v => v === null ? null : +v))) !== before",
        arg=__import__("json").dumps(before), timeout=30_000)
    wait_idle(page)
    after = plot_x(page)
    assert after[0] == before[0]  # the path of the first point is the whole cycle: unchanged
    assert after != before  # the members moved
    shot = tmp_path / "trajectories.png"
    page.screenshot(path=str(shot), full_page=True)
    assert shot.stat().st_size > 10_000
    keep = os.environ.get("SCREENSHOT_DIR")
    if keep:
        Path(keep).mkdir(parents=True, exist_ok=True)
        shutil.copy(shot, Path(keep) / shot.name)
