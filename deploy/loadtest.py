"""A class of users at once: N concurrent sessions speaking Streamlit's own WebSocket protocol
(what a browser tab sends: open a page from a link, then move a slider, again and again).

    .venv/bin/python deploy/loadtest.py                      # starts the app itself, 30 sessions, 120 s
    .venv/bin/python deploy/loadtest.py --url http://127.0.0.1:8080 --sessions 40 --seconds 300
    .venv/bin/python deploy/loadtest.py --class 150 --seconds 120 --json [--fault kill|database] [--floor] [--clients-cpu 0]
    .venv/bin/python deploy/loadtest.py --class 150 --hosts 2 [--fault host] --json

``--class N`` is a class at once (deploy/classload.py): deploy/start.sh started here (two app
processes behind nginx, on PostgreSQL), N students checking steps, a lecturer's view open;
with ``--hosts H`` the deployment is H app hosts, PostgreSQL and nginx on machines of their
own (deploy/hosts.py: network namespaces).

Loopback only, and it stops by itself. Each session works one chapter page; on the
kinetostatics page every answer is checked against the solver run here for that
session's own φ₂, so one user's input showing up in another's page is caught. Reported:
reruns, errors, wrong answers, the p50/p95/max rerun time (slider sent → script finished),
apart from it the sessions' first runs (page opened → script finished, all sessions at
once) and both together, and the server's memory before and after (when it started the
server itself).
"""

from __future__ import annotations

import argparse
import asyncio
import json
import math
import random
import statistics
import sys
import time
from pathlib import Path
from urllib.parse import urlparse

import websockets

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from deploy.client import (  # noqa: E402
    Report,
    Session,
    free_port,
    memory_mb,
    percentile,
    start_server,
    wait_ready,
)
from mechanisms import load_preset  # noqa: E402
from solvers.kinetostatics import analyse  # noqa: E402

# page, link, the control a user moves and its range; the first page is checked answer by
# answer. (Until 2026-11-26 the trajectories sessions asked for a slider "steps" the page no
# longer had and the gear sessions moved nothing: both reran their page unchanged.)
PAGES = [
    ("kinetostatics", "scene=predavanja-kinetostatika", "at", (0.0, 359.5)),
    ("trajectories", "scene=zbirka-1.1", "L2", (0.04, 0.09)),  # the crank OA, 0.06 m as given
    ("velocity_plans", "scene=zbirka-2.1", "at", (0.0, 359.5)),
    ("assur_groups", "scene=triad-full-turn", "at", (0.0, 359.5)),
    ("planetary_gears", "scene=zbirka-6.8", "in5", (50.0, 150.0)),  # ω₅, 100 s⁻¹ as given
    ("rotor_balancing", "scene=zbirka-7.1", "precision", (0.1, 2.0)),
]
LECTURE = load_preset("predavanja-kinetostatika")


def expected_torque(phi_deg: float) -> float:
    return float(analyse(LECTURE.with_(at=math.radians(phi_deg))).driving[0])


async def user(url: str, index: int, until: float, report: Report) -> None:
    page, link, slider, span = PAGES[index % len(PAGES)]
    rng = random.Random(index)
    phi = round(rng.uniform(0, 359), 1) if slider == "at" else None
    if phi is not None:
        link += f"&at={phi}"
    session = Session(url, page, link, report)
    async with websockets.connect(url, subprotocols=["streamlit"], max_size=None,
                                  open_timeout=60) as ws:
        await session.run(ws)
        while time.monotonic() < until:
            await asyncio.sleep(rng.uniform(0.5, 2.0))  # a person reads before moving on
            if slider not in session.widgets:
                report.errors.append(f"{page}: no control {slider!r} to move")
                return
            widget_id, _ = session.widgets[slider]
            value = round(rng.uniform(*span), 4)
            await session.run(ws, [(widget_id, value)])
            if page == "kinetostatics":
                check(session, value, report)


def check(session: Session, phi: float, report: Report) -> None:
    shown = session.metrics.get("M_p group by group [N·m]", "")
    try:
        value = float(shown.split()[0])
    except (ValueError, IndexError):
        report.wrong.append(f"φ₂ = {phi}: no torque shown ({shown!r})")
        return
    exact = expected_torque(phi)
    if not math.isclose(value, exact, rel_tol=2e-4, abs_tol=1e-3):
        report.wrong.append(f"φ₂ = {phi}: page shows {value}, this session's answer is {exact:.5g}")


async def watch_memory(pid: int | None, until: float, samples: list[float]) -> None:
    """The server's memory every 20 s: it must level off once the caches are full."""
    while pid and time.monotonic() < until:
        samples.append(memory_mb(pid))
        await asyncio.sleep(min(20, max(0.0, until - time.monotonic())))  # (a short run
        # ended with a whole 20-s sleep: the 6-s test run took 20 s)


async def load(url: str, sessions: int, seconds: float, pid: int | None = None) -> Report:
    report = Report()
    until = time.monotonic() + seconds
    users = [user(url, i, until, report) for i in range(sessions)]
    results = await asyncio.gather(*users, watch_memory(pid, until, report.memory),
                                   return_exceptions=True)
    report.errors += [f"session {i}: {type(r).__name__}: {r}" for i, r in enumerate(results)
                      if isinstance(r, BaseException)]
    return report


def spread(seconds: list[float]) -> str:
    """p50, p95 and max of some run times, in ms."""
    ordered = sorted(seconds)
    return (f"p50 {1e3 * statistics.median(ordered):.0f} ms, "
            f"p95 {1e3 * percentile(ordered, 0.95):.0f} ms, max {1e3 * ordered[-1]:.0f} ms")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--url", help="a running app (http://127.0.0.1:PORT); default: start one")
    parser.add_argument("--sessions", type=int, default=30)
    parser.add_argument("--seconds", type=float, default=120.0)
    parser.add_argument("--warm", type=float, default=5.0, metavar="SECONDS",
                        help="warm the server's caches first with six sessions (0: open cold)")
    parser.add_argument("--class", dest="students", type=int, metavar="N",
                        help="a class of N students on deploy/start.sh (deploy/classload.py)")
    parser.add_argument("--fault", choices=("kill", "database", "host"),
                        help="with --class: kill -9 an app process, or stop PostgreSQL for 10 s, "
                             "or (with --hosts) kill every process of one app host, half-way through")
    parser.add_argument("--hosts", type=int, default=0, metavar="H",
                        help="with --class: H app hosts, PostgreSQL and nginx on machines of their "
                             "own (network namespaces made here: root)")
    parser.add_argument("--json", action="store_true", help="with --class: end with one JSON line")
    parser.add_argument("--clients-cpu", type=int, metavar="CPU",
                        help="with --class: the simulated phones on this core alone, the deployment "
                             "on the others (the server's capacity apart from the clients')")
    parser.add_argument("--floor", action="store_true",
                        help="with --class: the same class on pages that only store and answer a "
                             "check (bench/floor_class_app.py)")
    args = parser.parse_args(argv)
    if args.hosts and not args.students:
        parser.error("--hosts: with --class N")
    if args.hosts and args.fault in ("kill", "database"):
        parser.error(f"--fault {args.fault}: on one machine (without --hosts); with --hosts: --fault host")
    if args.fault == "host" and args.hosts < 2:
        parser.error("--fault host: with --hosts 2 or more (its students go on on another)")
    if args.hosts and args.clients_cpu is not None:
        parser.error("--clients-cpu: on one machine (without --hosts)")
    if args.hosts:
        from deploy.hosts import why_not

        if why_not():
            parser.error(f"--hosts: {why_not()}")
    if args.students:
        return _class(args)
    server = None
    if args.url:
        base = urlparse(args.url)
        if base.hostname not in ("127.0.0.1", "localhost"):
            parser.error("loopback only: give a 127.0.0.1 or localhost URL")
        url = f"ws://{base.netloc}/_stcore/stream"
    else:
        port = free_port()
        server = start_server(port)
        url = f"ws://127.0.0.1:{port}/_stcore/stream"
    try:
        asyncio.run(wait_ready(url))
        before = memory_mb(server.pid) if server else None
        if args.warm > 0:
            asyncio.run(load(url, min(args.sessions, 6), args.warm))  # warm the caches
        warm = memory_mb(server.pid) if server else None
        report = asyncio.run(load(url, args.sessions, args.seconds, server.pid if server else None))
        after = memory_mb(server.pid) if server else None
    finally:
        if server:
            server.terminate()
            server.wait(timeout=30)
    times = sorted(report.times)
    print(f"{args.sessions} sessions for {args.seconds:.0f} s against {url}")
    print(f"reruns: {len(times)}, errors: {len(report.errors)}, wrong answers: {len(report.wrong)}")
    if times:
        print(f"rerun time: {spread(times)}")
    if report.opening:  # all at once, as when a lecturer says "open the page"
        print(f"pages opened: {len(report.opening)}, first run: {spread(report.opening)}")
        print(f"all runs together: {spread(times + report.opening)}")
    for page, page_times in sorted(report.by_page.items()):
        print(f"  {page:16s} {len(page_times):5d} reruns, p50 {1e3 * statistics.median(page_times):5.0f} ms, "
              f"p95 {1e3 * percentile(page_times, 0.95):5.0f} ms")
    if server:
        print(f"server memory: {before:.0f} MB at start, {warm:.0f} MB warm, {after:.0f} MB after; "
              f"every 20 s: {', '.join(f'{m:.0f}' for m in report.memory)} MB")
    for line in (report.errors + report.wrong)[:10]:
        print("  " + line)
    return 1 if report.errors or report.wrong or not times else 0


def _class(args) -> int:
    """``--class N``: the figures, and as the last line the JSON the issue asks for."""
    from deploy.classload import class_load

    found = class_load(args.students, args.seconds, args.fault, args.floor, args.clients_cpu,
                       hosts=args.hosts)
    if not args.json:
        for name, value in found.items():
            print(f"{name}: {value}")
    print(json.dumps(found))
    return 1 if found["errors"] or found["sent"] == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
