"""Practice: what a step's feedback costs. A whole practice run through the plans of task 3.1
(every step answered reversed, then ten times too long, then right), the other methods' step
lists, and on the page a Check against an ordinary rerun, measured in turn (AppTest).

    .venv/bin/python bench/practice.py
"""

import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from cli.practice import steps_for  # noqa: E402
from mechanisms import load_preset  # noqa: E402
from methods.progress import Progress  # noqa: E402

RUNS = (("plans", "zbirka-3.1"), ("compass", "zbirka-1.1"), ("forces", "zbirka-5.1"),
        ("lever", "zbirka-5.1"), ("willis", "zbirka-6.4"), ("balance", "zbirka-7.1"))


def whole_run(method: str, pid: str) -> tuple[int, float, float]:
    """Steps, ms to make them, µs per graded answer (three answers a step)."""
    scene = load_preset(pid)
    start = time.perf_counter()
    steps = steps_for(scene, method)
    made = (time.perf_counter() - start) * 1e3
    answers = [(s, a) for s in steps for a in (-s.expected, s.expected * 10, s.expected)]
    best = float("inf")
    for _ in range(5):
        progress = Progress.start()
        start = time.perf_counter()
        for step, answer in answers:
            progress.give(step, answer)
        best = min(best, time.perf_counter() - start)
    assert progress.score(steps)["open"] == 0
    return len(steps), made, best / len(answers) * 1e6


def page_times(repeat: int = 15) -> tuple[float, float]:
    """Median ms of a Check on the plans page and of an ordinary rerun (ω₂ moved), in turn."""
    from tests.test_pages import page, typed
    at = page("pages/velocity_plans.py", lang="en", scene="zbirka-3.1")
    at.toggle(key="pr_plans_on").set_value(True).run()
    steps = steps_for(load_preset("zbirka-3.1"), "plans")
    check, rerun = [], []
    for i in range(repeat):
        step = steps[0]
        typed(at, f"pr_plans_len_{step.id}", abs(step.expected) * (1 + i / 100))
        typed(at, f"pr_plans_ang_{step.id}", 90.0)
        button = next(b for b in at.button if b.label == "Check")
        start = time.perf_counter()
        button.click().run()
        check.append(time.perf_counter() - start)
        start = time.perf_counter()
        at.slider(key="omega").set_value(10.0 + (i % 2)).run()
        rerun.append(time.perf_counter() - start)
    return statistics.median(check) * 1e3, statistics.median(rerun) * 1e3


def main() -> None:
    print("| method | task | steps | steps made, ms | per graded answer, µs |")
    print("|---|---|---:|---:|---:|")
    for method, pid in RUNS:
        count, made, per = whole_run(method, pid)
        print(f"| {method} | {pid} | {count} | {made:.1f} | {per:.1f} |")
    check, rerun = page_times()
    print(f"\nplans page (AppTest, median of 15, in turn): Check {check:.0f} ms, "
          f"an ordinary rerun (ω₂ moved) {rerun:.0f} ms, ratio {check / rerun:.2f}")


if __name__ == "__main__":
    main()
