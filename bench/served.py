"""The pages served through ``st.App`` (``asgi.py``: the LTI routes beside them, the score
sender's thread) against ``app.py`` served as before, each page's slider rerun measured on
both servers in turn (bench/pages.py's way: Streamlit's WebSocket protocol, median of
``CHANGES`` changes, warm caches), and the first HTML and a Plotly bundle fetched from both
(the compression and page head scripts/serve.py adds must still be there).

    .venv/bin/python bench/served.py
"""

from __future__ import annotations

import asyncio
import statistics
import sys
import time
import urllib.request
from pathlib import Path

import websockets

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from bench.pages import CHANGES, PAGES, QUIET, _opened  # noqa: E402
from deploy.client import free_port, start_server, wait_ready  # noqa: E402


async def in_turn(app_url: str, asgi_url: str, name: str, key: str, values: list) -> tuple[float, float]:
    """Medians (ms) of one page's reruns on the two servers, one change each in turn."""
    sides = [await _opened(url, name, key, values[-1]) for url in (app_url, asgi_url)]
    try:
        for i in range(CHANGES):
            for session, _, ws in sides:
                await session.run(ws, [(session.widgets[key][0], values[i % len(values)])])
                await asyncio.sleep(QUIET)
    finally:
        for _, _, ws in sides:
            await ws.close()
    return tuple(1e3 * statistics.median(report.times) for _, report, _ in sides)


def fetched(base: str, path: str) -> tuple[int, str, float]:
    """Bytes, Content-Encoding and ms of one GET as a browser that takes Brotli asks it."""
    request = urllib.request.Request(base + path, headers={"Accept-Encoding": "br, gzip"})
    started = time.perf_counter()
    with urllib.request.urlopen(request, timeout=30) as answer:
        body = answer.read()
        coding = answer.headers.get("Content-Encoding") or "none"
    return len(body), coding, 1e3 * (time.perf_counter() - started)


def main() -> None:
    servers, bases = [], []
    try:
        for script in ("app.py", "asgi.py"):
            port = free_port()
            servers.append(start_server(port, ROOT / script))
            bases.append(f"127.0.0.1:{port}")
        for base in bases:
            asyncio.run(wait_ready(f"ws://{base}/_stcore/stream"))
        print("| page | app.py, ms | asgi.py (st.App), ms | ÷ |\n|---|---:|---:|---:|")
        ratios = []
        for name, key, values in PAGES:
            plain, app = asyncio.run(in_turn(*(f"ws://{b}/_stcore/stream" for b in bases),
                                             name, key, values))
            ratios.append(app / plain)
            print(f"| {name} | {plain:.0f} | {app:.0f} | {app / plain:.2f} |")
        print(f"median ratio: {statistics.median(ratios):.2f}")
        bundle = "/app/static/plotly-basic-4.1.1.min.js"
        for path in ("/velocity_plans", bundle, bundle):
            said = [fetched(f"http://{b}", path) for b in bases]
            print(f"{path}: " + " vs ".join(f"{n} B {c} {ms:.0f} ms" for n, c, ms in said))
    finally:
        for server in servers:
            server.terminate()
            server.wait(timeout=30)


if __name__ == "__main__":
    main()
