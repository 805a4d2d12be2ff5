"""Per page: the server-side rerun after a slider change, measured as a browser sees it
(Streamlit's WebSocket protocol against a real server on this machine: slider sent →
script finished, median of ``CHANGES`` (40) changes, warm caches) and the size of the
figures it sends, against Streamlit's floor (bench/floor_app.py, its own server) rerun in
turn with it: a page's change, then the floor's, and so on.

    .venv/bin/python bench/pages.py           # print the table
    .venv/bin/python bench/pages.py --write   # and regenerate its part of docs/performance.md
"""

import asyncio
import statistics
import sys
from pathlib import Path

import websockets

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from bench.publish import publish  # noqa: E402
from deploy.client import Report, Session, free_port, start_server, wait_ready  # noqa: E402

# page (its default scene), the control a user moves and the values it goes through
PAGES = [
    ("trajectories", "omega", [5.0 + i for i in range(12)]),
    ("velocity_plans", "at", [20.0 + 5 * i for i in range(12)]),
    ("assur_groups", "at", [300.0 + 4 * i for i in range(12)]),  # zbirka-4.1 reaches 298–360°
    ("kinetostatics", "at", [100.0 + 7 * i for i in range(12)]),
    ("planetary_gears", "H", [1.5, 2.0, 2.5, 3.0] * 3),
    ("rotor_balancing", "precision", [0.3, 0.5, 0.7, 0.9] * 3),
    ("builder", "build_1_driver_at", [40.0 + 5 * i for i in range(12)]),  # φ₂ typed: redrawn
]
CHANGES = 40
QUIET = 0.02  # s after each rerun: what a server does after its script has ended is not the next's


async def _opened(url: str, name: str, key: str, last) -> tuple[Session, Report, object]:
    """A session on page ``name``, its first run, its whole run and one warm rerun done."""
    report = Report()
    session = Session(url, name, "", report)
    ws = await websockets.connect(url, subprotocols=["streamlit"], max_size=None)
    await session.run(ws)  # a fresh visit: what waits for the first chart's paint is left out
    await session.run(ws)  # the whole page, as the paint brings it (ω₂ among the sliders)
    await session.run(ws, [(session.widgets[key][0], last)])
    report.times.clear()
    return session, report, ws


async def in_turn(app: str, floor: str, name: str, key: str, values: list
                  ) -> tuple[float, float, float]:
    """Medians (ms) of the page's reruns and of the floor's, one after the other (so that the
    machine's speed, which moves by a third between runs, moves both alike), and the kB of
    figures the page's last rerun sent."""
    page, page_report, page_ws = await _opened(app, name, key, values[-1])
    bare, floor_report, floor_ws = await _opened(floor, "trajectories", "omega", 1.0)
    try:
        for i in range(CHANGES):
            await page.run(page_ws, [(page.widgets[key][0], values[i % len(values)])])
            await asyncio.sleep(QUIET)
            await bare.run(floor_ws, [(bare.widgets["omega"][0], float(i))])
            await asyncio.sleep(QUIET)
    finally:
        await page_ws.close()
        await floor_ws.close()
    if page_report.errors:
        raise RuntimeError(page_report.errors[0])
    return (1e3 * statistics.median(page_report.times),
            1e3 * statistics.median(floor_report.times), page.figure_bytes / 1024)


def table() -> str:
    """Each page's rerun, and its ratio to Streamlit's floor measured in turn with it (issue
    21's goal: at most 5×)."""
    servers, urls = [], []
    try:
        for script in (ROOT / "app.py", ROOT / "bench" / "floor_app.py"):
            port = free_port()
            servers.append(start_server(port, script))
            urls.append(f"ws://127.0.0.1:{port}/_stcore/stream")
        for url in urls:
            asyncio.run(wait_ready(url))
        rows = [(name, *asyncio.run(in_turn(*urls, name, key, values)))
                for name, key, values in PAGES]
    finally:
        for server in servers:
            server.terminate()
            server.wait(timeout=30)
    out = [f"| page | slider → page redrawn on the server, ms (median of {CHANGES}) | the floor "
           "in turn with it, ms | ÷ floor | figures sent, kB |", "|---|---:|---:|---:|---:|"]
    out += [f"| {name} | {ms:.0f} | {floor_ms:.0f} | {ms / floor_ms:.1f}× | {kb:.0f} |"
            for name, ms, floor_ms, kb in rows]
    return "\n".join(out)


if __name__ == "__main__":
    publish(table(), "<!-- pages table -->", CHANGES)
