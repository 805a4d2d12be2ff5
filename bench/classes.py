"""A class's check: what storing it adds to grading it. 1,000 checks of task 3.1's first
plan step, each graded (methods.practice) and, in turn, graded and stored (classes.store:
durable before the verdict) — on an SQLite file and on a PostgreSQL server started here
(Debian's postgresql, as tests/test_classes.py starts it). Each check is a new student's,
so the limit of 5 checks a second per student never waits.

    .venv/bin/python bench/classes.py [--checks N]
"""

import argparse
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from classes import store  # noqa: E402
from cli.practice import steps_for  # noqa: E402
from mechanisms import load_preset  # noqa: E402
from methods.practice import grade  # noqa: E402


def measure(url: str, checks: int) -> tuple[list[float], list[float]]:
    """Seconds a check takes graded alone and graded and stored, measured in turn."""
    step = steps_for(load_preset("zbirka-3.1"), "plans")[0]
    code, _ = store.create("zbirka-3.1", "plans", url=url)
    tokens = [store.join(code, url=url) for _ in range(checks)]
    alone, stored = [], []
    for i, token in enumerate(tokens):
        answer = complex(step.expected) * (1 + i / checks)
        start = time.perf_counter()
        grade(step, answer)
        alone.append(time.perf_counter() - start)
        start = time.perf_counter()
        verdict = grade(step, answer)
        store.record(code, token, step.id, [answer.real, answer.imag], verdict.diagnosis,
                     store.new_check(), url=url)
        stored.append(time.perf_counter() - start)
    return alone, stored


def row(name: str, alone: list[float], stored: list[float]) -> str:
    def ms(values, q):
        return sorted(values)[int(q * (len(values) - 1))] * 1e3
    return (f"| {name} | {statistics.median(alone) * 1e3:.3f} | {ms(alone, 0.95):.3f} | "
            f"{statistics.median(stored) * 1e3:.2f} | {ms(stored, 0.95):.2f} |")


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--checks", type=int, default=1000)
    checks = parser.parse_args().checks
    print(f"{checks} checks, in turn; ms per check")
    print("| store | graded, median | graded, p95 | graded and stored, median | … p95 |")
    print("|---|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as folder:
        print(row("SQLite file", *measure(f"sqlite:///{folder}/bench.db", checks)))
    from tests.test_classes import PG_BIN, Postgres
    if PG_BIN is None:
        print("| PostgreSQL | (not installed: scripts/test.sh installs it) |")
        return
    server = Postgres()
    try:
        print(row("PostgreSQL (loopback)", *measure(server.url, checks)))
    finally:
        server.stop()


if __name__ == "__main__":
    main()
