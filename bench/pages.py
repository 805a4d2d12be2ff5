"""Per page: the server-side rerun after a slider change, measured as a browser sees it
(Streamlit's WebSocket protocol against a real server on this machine: slider sent →
script finished, median of 12 changes, warm caches) and the size of the figures it sends.

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


async def measure(url: str, name: str, key: str, values: list) -> tuple[float, float]:
    report = Report()
    session = Session(url, name, "", report)
    async with websockets.connect(url, subprotocols=["streamlit"], max_size=None) as ws:
        await session.run(ws)
        await session.run(ws, [(session.widgets[key][0], values[-1])])  # warm
        report.times.clear()
        for value in values:
            await session.run(ws, [(session.widgets[key][0], value)])
    if report.errors:
        raise RuntimeError(report.errors[0])
    return 1e3 * statistics.median(report.times), session.figure_bytes / 1024


def rerun_ms(script: Path, pages: list) -> list[tuple[str, float, float]]:
    """(page, median rerun ms, figures kB) for each page of an app served from ``script``."""
    port = free_port()
    server = start_server(port, script)
    url = f"ws://127.0.0.1:{port}/_stcore/stream"
    try:
        asyncio.run(wait_ready(url))
        return [(name, *asyncio.run(measure(url, name, key, values))) for name, key, values in pages]
    finally:
        server.terminate()
        server.wait(timeout=30)


def table() -> str:
    """Each page's rerun, and its ratio to Streamlit's floor measured in the same run (issue
    21's goal: at most 5×)."""
    pages = rerun_ms(ROOT / "app.py", PAGES)
    ((_, floor, _),) = rerun_ms(ROOT / "bench" / "floor_app.py", PAGES[:1])
    rows = ["| page | slider → page redrawn on the server, ms (median of 12) | ÷ floor "
            "| figures sent, kB |", "|---|---:|---:|---:|"]
    rows += [f"| {name} | {ms:.0f} | {ms / floor:.1f}× | {kb:.0f} |" for name, ms, kb in pages]
    rows.append(f"| (Streamlit's floor: one slider, one line of text) | {floor:.0f} | 1× | 0 |")
    return "\n".join(rows)


if __name__ == "__main__":
    publish(table(), "<!-- pages table -->", 12)
