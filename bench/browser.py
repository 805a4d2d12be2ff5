"""In a real browser (Debian's chromium through Playwright): a slider moved with the arrow
key → the page's figure redrawn, median of 20 changes per page, against a server on this
machine. This is what a user waits for: the rerun, the network, and Plotly drawing.

    .venv/bin/python bench/browser.py           # print the table
    .venv/bin/python bench/browser.py --write   # and regenerate its part of docs/performance.md
"""

import asyncio
import statistics
import sys
import tempfile
import time
from pathlib import Path

from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from bench.publish import publish  # noqa: E402
from deploy.client import free_port, start_server, wait_ready  # noqa: E402

CHANGES = 20
# page, part of the label of a slider that changes the page's first figure (English page),
# and the expander that holds it; the gear and rotor pages are driven by number inputs and
# tables instead of sliders
PAGES = [
    ("trajectories", "(member 2)", "Link lengths"),
    ("velocity_plans", "Crank angle", None),
    ("assur_groups", "Crank angle", None),
    ("kinetostatics", "Crank angle", None),
]
# a signature of the first chart's data (typed arrays included): it changes when the
# rerun's figure is drawn
SIGNATURE = """(() => { const gd = document.querySelector('.js-plotly-plot');
  if (!gd || !gd.data || !gd._fullLayout) return null;
  const s = JSON.stringify(gd.data.map(t => [t.x, t.y]));
  return s.length + s.slice(0, 300) + s.slice(-300); })()"""
MARK = f"() => {{ window.__before = {SIGNATURE}; }}"
REDRAWN = f"() => {{ const now = {SIGNATURE}; return now !== null && now !== window.__before; }}"


def measure(page, url: str, label: str, expander: str | None) -> float:
    page.goto(url)
    page.wait_for_selector(".js-plotly-plot", timeout=60_000)
    page.wait_for_timeout(1500)
    if expander:
        page.get_by_text(expander, exact=True).click()
    thumb = page.locator(f"[data-testid='stSlider'] input[type='range'][aria-label*='{label}']").first
    times = []
    for _ in range(CHANGES):
        page.evaluate(MARK)
        thumb.focus()
        start = time.perf_counter()
        page.keyboard.press("ArrowRight")
        page.wait_for_function(REDRAWN, timeout=30_000, polling="raf")
        page.evaluate("() => new Promise(requestAnimationFrame)")  # the frame it is drawn in
        times.append(time.perf_counter() - start)
        page.wait_for_timeout(300)  # let the page finish its rerun
    return 1e3 * statistics.median(times)


def table() -> str:
    port = free_port()
    server = start_server(port)
    rows = [f"| page | slider → figure redrawn in chromium, ms (median of {CHANGES}) |", "|---|---:|"]
    try:
        asyncio.run(wait_ready(f"ws://127.0.0.1:{port}/_stcore/stream"))
        with sync_playwright() as p, tempfile.TemporaryDirectory() as profile:
            context = p.chromium.launch_persistent_context(
                profile, executable_path="/usr/bin/chromium", headless=True,
                args=["--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"],
                viewport={"width": 1400, "height": 900})
            page = context.new_page()
            for name, label, expander in PAGES:
                ms = measure(page, f"http://127.0.0.1:{port}/{name}?lang=en", label, expander)
                rows.append(f"| {name} | {ms:.0f} |")
            context.close()
    finally:
        server.terminate()
        server.wait(timeout=30)
    return "\n".join(rows)


if __name__ == "__main__":
    publish(table(), "<!-- browser table -->", CHANGES)
