"""A class at once, for ``deploy/loadtest.py --class N``: N students (Streamlit's own
WebSocket protocol, deploy/client.py) practise task 3.1's plans in one class on
``deploy/start.sh`` (two app processes behind nginx, on PostgreSQL), each checking a step
every 3–8 s, while a lecturer's view stays open and records when each check shows on it.

Each student answers right, reversed or turned (an arrow; a number: right, of the other
sign or half as large again), so the diagnosis each should see is known; at the end every
verdict seen is looked up in the store. ``fault`` puts one failure in the middle of the run:
``kill`` (``kill -9`` of one app process: its students reconnect through nginx and resume
from the store) or ``database`` (PostgreSQL stopped for 10 s: checks in the gap say "not
saved" and are sent again).
"""

from __future__ import annotations

import asyncio
import cmath
import math
import os
import random
import shutil
import signal
import socket
import subprocess
import tempfile
import time
from collections import Counter
from contextlib import nullcontext
from dataclasses import dataclass, field
from pathlib import Path

import websockets

from classes import store
from mechanisms import load_preset
from methods.practice import TRIES, Step
from methods.practice_steps import steps_for

from . import hosts as lab
from .client import Report, Session, free_port, healthy, memory_mb, percentile

ROOT = Path(__file__).resolve().parents[1]
TASK = "zbirka-3.1"
GAP = 10.0  # s PostgreSQL stays down in the database fault
WAIT = (3.0, 8.0)  # s between two checks of one student
NOT_SAVED = "Not saved"  # the start of class.not_saved in English (the client asks lang=en)
EXACT = "Exact:"  # practice.exact: the page shows a step's exact value once it is done


@dataclass
class Seen:
    student: str
    step: str
    planted: str  # the diagnosis the answer was made to get
    verdict: str  # what the page showed: "success" or "warning"
    at: float  # monotonic time the verdict arrived
    host: str | None = None  # the app host that served it (with several hosts)


@dataclass
class ClassReport:
    seen: list[Seen] = field(default_factory=list)
    check_times: list[float] = field(default_factory=list)  # Check pressed → verdict, s
    view: list[tuple[float, int]] = field(default_factory=list)  # (time, checks on the view)
    errors: list[str] = field(default_factory=list)
    not_saved: int = 0
    reconnects: int = 0
    pages: Report = field(default_factory=Report)  # the students' page openings and reruns
    opened: list[float] = field(default_factory=list)  # when each student's page had opened
    on: dict[str, tuple[str | None, str]] = field(default_factory=dict)  # student → (host, step)
    lost: str | None = None  # the app host killed
    moved: dict[str, str] = field(default_factory=dict)  # its students → the step each was on
    resumed: set[str] = field(default_factory=set)  # of those, who went on at it on another host
    fault_at: float | None = None  # when the fault struck (monotonic)


@dataclass
class Deploy:
    """deploy/start.sh running: nginx's address, the app ports, the store, the script, its
    logs folder."""

    proxy: str
    ports: list[int]
    database: str
    pgdata: Path
    script: subprocess.Popen
    logs: Path

    def app_pids(self) -> list[int]:
        return [p for p in map(app_pid, self.ports) if p]

    def database_pids(self) -> list[int]:
        return postgres_pids(self.pgdata)

    def host_of(self, upstream: str) -> None:
        """One machine: no host to tell apart."""
        return None

    def stop(self, keep: bool = False) -> None:
        """Stopped as Ctrl-C stops it; its data and logs removed unless ``keep``."""
        if self.script.poll() is None:
            self.script.send_signal(signal.SIGTERM)
            self.script.wait(timeout=60)
        if not keep:
            shutil.rmtree(self.pgdata, ignore_errors=True)
            shutil.rmtree(self.logs, ignore_errors=True)


def consecutive_ports() -> int:
    """The first of two free ports in a row (the app processes')."""
    for _ in range(50):
        port = free_port()
        with socket.socket() as s:
            try:
                s.bind(("127.0.0.1", port + 1))
            except OSError:
                continue
        return port
    raise RuntimeError("no two free ports in a row")


def start_deploy(processes: int = 2, app: str = "asgi.py", cpus: set[int] | None = None) -> Deploy:
    """deploy/start.sh serving ``app`` with its own PostgreSQL in a temporary folder; returns
    when nginx and every process answer. ``cpus``: the cores it runs on (its processes
    inherit them), the simulated phones being kept off them."""
    pgdata = Path(tempfile.mkdtemp(prefix="mz-deploy-pg-"))
    logs = Path(tempfile.mkdtemp(prefix="mz-deploy-logs-"))
    if os.getuid() == 0:
        shutil.chown(pgdata, "postgres")
    port, first = free_port(), consecutive_ports()
    env = {**os.environ, "PROCESSES": str(processes), "PORT": str(port),
           "FIRST_APP_PORT": str(first), "MEHANIZMI_PGDATA": str(pgdata), "APP": app,
           "MEHANIZMI_LOGS": str(logs)}
    env.pop("MEHANIZMI_DATABASE_URL", None)
    script = subprocess.Popen(["bash", "deploy/start.sh"], cwd=ROOT, env=env, text=True,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              preexec_fn=(lambda: os.sched_setaffinity(0, cpus)) if cpus else None)
    database, lines = "", []
    for line in script.stdout:
        lines.append(line)
        if line.startswith("class store ready: "):
            database = line.split(": ", 1)[1].strip()
        if line.startswith("Mehanizmi: ") or len(lines) > 400:
            break
    if not database.startswith("postgresql"):
        script.kill()
        raise RuntimeError("deploy/start.sh did not start:\n" + "".join(lines[-20:]))
    ports = [first + i for i in range(processes)]
    for address in [port, *ports]:
        healthy(f"http://127.0.0.1:{address}")
    return Deploy(f"http://127.0.0.1:{port}", ports, database, pgdata, script, logs)


def app_pid(port: int) -> int | None:
    """The app process serving ``port`` (its command line names the port)."""
    for proc in Path("/proc").iterdir():
        try:
            args = (proc / "cmdline").read_bytes().split(b"\0")
        except OSError:
            continue
        if b"scripts/serve.py" in args and str(port).encode() in args:
            return int(proc.name)
    return None


def postgres_pids(pgdata: Path) -> list[int]:
    """The PostgreSQL server (its postmaster.pid) and every process it started."""
    try:
        root = int((pgdata / "postmaster.pid").read_text().split()[0])
    except (OSError, ValueError, IndexError):
        return []
    out = [root]
    for proc in Path("/proc").iterdir():
        try:
            if proc.name.isdigit() and int((proc / "stat").read_text().rsplit(")", 1)[1].split()[1]) == root:
                out.append(int(proc.name))
        except (OSError, ValueError, IndexError):
            continue
    return out


def cpu_seconds(pids: list[int]) -> float:
    total = 0.0
    for pid in pids:
        try:
            fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        total += (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    return total


def _answer(step: Step, planted: str) -> list[float]:
    """The typed values (length and angle in degrees, or a value) that get ``planted``."""
    if step.kind == "scalar":
        value = float(complex(step.expected).real)
        return [{"ok": value, "sense": -value, "length": 1.5 * value}[planted]]
    z = complex(step.expected)
    turn = {"ok": 0.0, "sense": 180.0, "direction": 40.0}[planted]
    return [abs(z), math.degrees(cmath.phase(z)) + turn]


def _plant(step: Step, rng: random.Random) -> str:
    if abs(complex(step.expected)) <= step.tolerance:
        return "ok"  # a zero step has no sense or direction to get wrong
    wrong = "length" if step.kind == "scalar" else "direction"
    return rng.choices(["ok", "sense", wrong], [0.6, 0.2, 0.2])[0]


def _resumed(steps: list[str], was: str, now: str, done: set[str]) -> bool:
    """A page reopened at the step the student was on (or, that one done, the next)."""
    if now == was:
        return True
    return was in done and steps.index(now) == steps.index(was) + 1


async def student(url: str, code: str, token: str, steps: dict[str, Step], until: float,
                  report: ClassReport, rng: random.Random, host_of=lambda upstream: None) -> None:
    """A student on a phone: checks a step every 3–8 s; reconnects when cut off.
    ``host_of``: the app host nginx's ``X-Mehanizmi-Upstream`` names (several hosts)."""
    tries: Counter = Counter()
    done: set[str] = set()
    pending: tuple[str, str] | None = None  # (step, planted) not saved: sent again
    link = f"class={code}&student={token}&scene={TASK}"
    while time.monotonic() < until:
        try:
            async with websockets.connect(url, subprotocols=["streamlit"], max_size=None,
                                          open_timeout=30, ping_timeout=60) as ws:
                host = host_of(ws.response.headers.get("X-Mehanizmi-Upstream", ""))
                fresh = True
                session = Session(url, "velocity_plans", link, report.pages)
                await session.run(ws)
                report.opened.append(time.monotonic())
                while time.monotonic() < until:
                    step_id = next((k.split("_", 3)[3] for k in session.drawn  # (this run's)
                                    if k.startswith(("pr_plans_len_", "pr_plans_value_"))), None)
                    if step_id is None:  # the store down at the page's opening: asked again
                        await asyncio.sleep(1.0)
                        await session.run(ws)
                        continue
                    if fresh:  # the page's first step on this connection
                        fresh = False
                        was = report.moved.get(token)
                        if was is not None and host != report.lost and _resumed(list(steps), was, step_id, done):
                            report.resumed.add(token)
                    report.on[token] = (host, step_id)
                    if any(text.startswith(EXACT) for text in session.texts):
                        done.add(step_id)  # done on the page (a check whose verdict a fall cut off)
                    if step_id in done and "pr_plans_next" in session.buttons:
                        await session.run(ws, [(session.buttons["pr_plans_next"], True)])
                        continue
                    await asyncio.sleep(rng.uniform(*WAIT))
                    if time.monotonic() >= until:
                        return
                    step = steps[step_id]
                    planted = pending[1] if pending and pending[0] == step_id else _plant(step, rng)
                    names = ("value",) if step.kind == "scalar" else ("len", "ang")
                    states = [(session.widgets[f"pr_plans_{n}_{step_id}"][0], v)
                              for n, v in zip(names, _answer(step, planted))]
                    started = time.perf_counter()
                    await session.run(ws, [*states, (session.buttons["submit"], True)])
                    took = time.perf_counter() - started
                    verdicts = [kind for kind, _ in session.alerts if kind in ("success", "warning")]
                    if any(kind == "error" and text.startswith(NOT_SAVED) for kind, text in session.alerts):
                        report.not_saved += 1
                        pending = (step_id, planted)
                        continue
                    if not verdicts:
                        report.errors.append(f"{step_id}: no verdict ({session.alerts[:2]})")
                        continue
                    pending = None
                    report.check_times.append(took)
                    report.seen.append(Seen(token, step_id, planted, verdicts[0], time.monotonic(), host))
                    tries[step_id] += 1
                    if planted == "ok" or tries[step_id] >= TRIES:
                        done.add(step_id)
                return
        except (websockets.ConnectionClosed, OSError, asyncio.TimeoutError):
            report.reconnects += 1
            await asyncio.sleep(1.0)


async def lecturer(url: str, code: str, key: str, until: float, report: ClassReport) -> None:
    """The lecturer's view, left open: when does each stored check show on it."""
    while time.monotonic() < until:
        try:
            async with websockets.connect(url, subprotocols=["streamlit"], max_size=None,
                                          open_timeout=30, ping_timeout=60) as ws:
                seen = Report()
                session = Session(url, "class", f"class={code}&key={key}", seen)
                await session.run(ws)
                if session.every is None:
                    report.errors.append(f"the class view has no timer: {seen.errors[:1]}")
                    return
                seconds, fragment = session.every
                while time.monotonic() < until:
                    await asyncio.sleep(seconds)  # as the browser's timer does
                    await session.run(ws, fragment=fragment)
                    shown = session.metrics.get("Checks stored")
                    if shown is not None:
                        report.view.append((time.monotonic(), int(shown)))
                return
        except (websockets.ConnectionClosed, OSError, asyncio.TimeoutError):
            report.reconnects += 1
            await asyncio.sleep(1.0)


async def fault(kind: str | None, deploy, at: float, report: ClassReport, gap: float = GAP) -> None:
    """The failure in the middle of the run (PostgreSQL down for ``gap`` seconds; ``host``:
    every process of the first app host killed, its students and their steps noted first)."""
    if kind is None:
        return
    await asyncio.sleep(max(0.0, at - time.monotonic()))
    report.fault_at = time.monotonic()
    if kind == "host":
        report.lost = deploy.apps[0]
        report.moved = {t: step for t, (host, step) in report.on.items() if host == report.lost}
        await asyncio.to_thread(deploy.kill, report.lost)
        return
    if kind == "kill":
        pid = app_pid(deploy.ports[0])
        if pid:
            os.kill(pid, signal.SIGKILL)
        return
    as_postgres = ["runuser", "-u", "postgres", "--"] if os.getuid() == 0 else []
    pg_ctl = str(next(iter(sorted(Path("/usr/lib/postgresql").glob("*/bin")))) / "pg_ctl")
    await asyncio.to_thread(subprocess.run, [*as_postgres, pg_ctl, "-D", str(deploy.pgdata),
                                             "-m", "fast", "-w", "stop"], capture_output=True)
    await asyncio.sleep(gap)
    await asyncio.to_thread(subprocess.run, [  # as deploy/start.sh starts it
        *as_postgres, pg_ctl, "-D", str(deploy.pgdata), "-w", "-l", f"{deploy.pgdata}/server.log",
        "-o", f"-k {deploy.pgdata} -c listen_addresses=''", "start"], capture_output=True)


def view_delays(report: ClassReport) -> list[float]:
    """For each check seen (in the order its verdict came), the time until the view first
    showed at least that many checks."""
    delays = []
    arrived = sorted(s.at for s in report.seen)
    samples = sorted(report.view)
    j = 0
    for i, at in enumerate(arrived):  # (both only grow: one pass)
        while j < len(samples) and (samples[j][0] < at or samples[j][1] < i + 1):
            j += 1
        if j == len(samples):
            break
        delays.append(samples[j][0] - at)
    return delays


def compare(report: ClassReport, rows: list[dict]) -> tuple[int, int]:
    """(checks seen that the store lacks, or holds with another diagnosis; verdicts that
    disagree with the planted diagnosis)."""
    stored = Counter((r["student"], r["step"], r["diagnosis"]) for r in rows)
    missing = 0
    for s in report.seen:
        if stored[(s.student, s.step, s.planted)] > 0:
            stored[(s.student, s.step, s.planted)] -= 1
        else:
            missing += 1
    disagree = sum((s.verdict == "success") != (s.planted == "ok") for s in report.seen)
    return missing, disagree


async def _run(deploy: Deploy, students: int, seconds: float, kind: str | None,
               gap: float = GAP) -> tuple:
    code, key = store.create(TASK, "plans", url=deploy.database)
    tokens = [store.join(code, f"s{i}", url=deploy.database) for i in range(students)]
    steps = {s.id: s for s in steps_for(load_preset(TASK), "plans")}
    url = f"ws://{deploy.proxy.removeprefix('http://')}/_stcore/stream"
    report = ClassReport()
    start = time.monotonic()
    until = start + seconds
    cpu = (cpu_seconds(deploy.app_pids()), cpu_seconds(deploy.database_pids()))
    work = [student(url, code, t, steps, until, report, random.Random(i), deploy.host_of)
            for i, t in enumerate(tokens)]
    await asyncio.gather(lecturer(url, code, key, until + 5.0, report),
                         fault(kind, deploy, start + seconds / 2, report, gap), *work)
    wall = time.monotonic() - start
    apps_now = deploy.app_pids()
    pg_now = deploy.database_pids()
    app_cpu = cpu_seconds(apps_now) - cpu[0]  # (a killed host's CPU is not counted)
    stored = store.export(code, key, url=deploy.database)
    usage = {"app_cpu_percent": round(100 * app_cpu / wall, 1),
             "app_cpu_ms_per_check": round(1e3 * app_cpu / max(len(stored), 1), 1), "wall": wall,
             "app_memory_mb": [round(memory_mb(p)) for p in apps_now],
             "database_cpu_percent": round(100 * (cpu_seconds(pg_now) - cpu[1]) / wall, 1),
             "database_memory_mb": round(sum(memory_mb(p) for p in pg_now))}
    return report, stored, usage


FLOOR = "bench/floor_class_app.py"  # a class's pages with nothing but the store behind them


def class_load(students: int, seconds: float, kind: str | None = None, floor: bool = False,
               clients_cpu: int | None = None, gap: float = GAP, hosts: int = 0) -> dict:
    """The whole run on a deploy of its own (of the floor's pages with ``floor``): the
    figures as one dict (the JSON line). ``clients_cpu``: the simulated phones on that core
    alone and the deployment (app processes, PostgreSQL, nginx) on the others, so that the
    server's own capacity shows apart from the clients' (both shared two cores before).
    ``gap``: how long PostgreSQL stays down in the ``database`` fault. ``hosts``: that many
    app hosts, PostgreSQL and nginx each on a machine of its own (deploy/hosts.py), the
    phones on another; the ``host`` fault kills every process of the first app host."""
    every = os.sched_getaffinity(0)
    server = every - {clients_cpu} if clients_cpu is not None else None
    if clients_cpu is not None and (clients_cpu not in every or not server):
        raise SystemExit(f"--clients-cpu {clients_cpu}: this machine's cores are {sorted(every)}")
    app = FLOOR if floor else "asgi.py"
    if hosts:
        deploy = lab.start(hosts, app=app)
        where = lab.inside(deploy, "client")  # (the phones' and the store's connections)
    else:
        deploy, where = start_deploy(app=app, cpus=server), nullcontext()
    if clients_cpu is not None:
        os.sched_setaffinity(0, {clients_cpu})
    clients = os.times()
    try:
        with where:
            report, rows, usage = asyncio.run(_run(deploy, students, seconds, kind, gap))
    finally:
        deploy.stop()
        if clients_cpu is not None:
            os.sched_setaffinity(0, every)
    used = os.times()
    usage["clients_cpu_percent"] = round(100 * (used.user + used.system - clients.user - clients.system)
                                         / usage.pop("wall"), 1)
    missing, disagree = compare(report, rows)
    delays = view_delays(report)
    settled = max(report.opened[:students], default=0.0)  # every page open: the class at work
    steady = [took for seen, took in zip(report.seen, report.check_times) if seen.at > settled]
    ms = lambda values, q: round(1e3 * percentile(values, q)) if values else None  # noqa: E731
    return {"students": students, "errors": len(report.errors) + missing + disagree,
            "sent": len(report.seen), "stored": len(rows),
            "check_p50_ms": ms(report.check_times, 0.5), "check_p95_ms": ms(report.check_times, 0.95),
            "view_p50_ms": ms(delays, 0.5), "view_p95_ms": ms(delays, 0.95),
            "check_p95_after_openings_ms": ms(steady, 0.95),
            "fault": kind, "floor": floor, "lost": missing, "verdict_disagrees": disagree,
            "not_saved": report.not_saved, "reconnects": report.reconnects,
            "view_last": report.view[-1][1] if report.view else None,
            "open_p50_ms": ms(report.pages.opening, 0.5), "open_p95_ms": ms(report.pages.opening, 0.95),
            "seconds": seconds, "server_cpus": len(server) if server else len(every),
            "clients_cpu": clients_cpu, **usage, **(_across(report, deploy.apps) if hosts else {}),
            "first_errors": report.errors[:5]}


def _across(report: ClassReport, apps: list[str]) -> dict:
    """Each app host's share of the checks (before the fault too), and with a host lost:
    its students, and how many of them went on at their step on another host."""
    before = report.fault_at if report.fault_at is not None else math.inf
    found = {"hosts": len(apps),
             "per_host_checks": {h: sum(s.host == h for s in report.seen) for h in apps},
             "per_host_checks_before_fault": {h: sum(s.host == h and s.at < before for s in report.seen)
                                              for h in apps}}
    if report.lost is not None:
        found |= {"host_lost": report.lost, "students_moved": len(report.moved),
                  "students_resumed": len(report.resumed & set(report.moved))}
    return found
