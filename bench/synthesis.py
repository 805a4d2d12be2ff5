"""Synthesis benchmark: speed against accuracy on the literature's standard path-synthesis
cases, for budgets of 10³, 10⁴ and 10⁵ evaluations (and the default), over ten seeds.

    .venv/bin/python bench/synthesis.py             # print the table
    .venv/bin/python bench/synthesis.py --write     # and put it into docs/performance.md
    .venv/bin/python bench/synthesis.py --seeds 3   # a quicker look

Every objective is the re-solved one (``solvers.synthesis.certify``): Σ of squared distances
between the precision points and where the kinematics core puts the coupler point. The
cases are written as the command line's task files (docs/synthesis.md); the papers' rules
(bounds, timing, the crank turning fully) are their keys. ``published`` holds a paper's
best and mean Σ e² for the case where it was read from the paper itself; a cell left out
was not (the papers could not be read on the machine this was written on) and prints "—".
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from bench.publish import publish  # noqa: E402
from mechanisms.synthesis import parse_task  # noqa: E402
from solvers.synthesis import DEFAULT_BUDGET, DEFAULT_SECONDS, synthesize  # noqa: E402

CASES = {
    "five points, prescribed timing (Cabrera et al. 2002; Kunjur & Krishnamurty 1997)": dict(
        task="""points = [[3, 3], [2.759, 3.363], [2.372, 3.663], [1.890, 3.862], [1.355, 3.943]]
timing = "angles"
crank_angles = [30, 45, 60, 75, 90]
crank_pivot = [0, 0]
frame_angle = 0
max_length = 50
box = 50
""", published={}),
    "six points on a line, free timing (Cabrera et al. 2002)": dict(
        task="""points = [[20, 20], [20, 25], [20, 30], [20, 35], [20, 40], [20, 45]]
min_length = 5
max_length = 60
box = 60
""", published={}),
    "ten points on an ellipse, free timing (Cabrera et al. 2002; Acharyya & Mandal 2009)": dict(
        task="""points = [[20, 10], [17.66, 15.142], [11.736, 17.878], [5, 16.928], [0.60307, 12.736],
          [0.60307, 7.2638], [5, 3.0718], [11.736, 2.1215], [17.66, 4.8577], [20, 10]]
min_length = 5
max_length = 80
box = 80
""", published={}),
    "eighteen points of a closed path, free timing (Kunjur & Krishnamurty 1997)": dict(
        task="""points = [[0.5, 1.1], [0.4, 1.1], [0.3, 1.1], [0.2, 1.0], [0.1, 0.9], [0.005, 0.75],
          [0.02, 0.6], [0, 0.5], [0, 0.4], [0.03, 0.3], [0.1, 0.25], [0.15, 0.2],
          [0.2, 0.3], [0.3, 0.4], [0.4, 0.5], [0.5, 0.7], [0.6, 0.9], [0.6, 1.0]]
max_length = 50
box = 50
""", published={}),
}
BUDGETS = (1_000, 10_000, 100_000, DEFAULT_BUDGET)


def run(seeds: int) -> str:
    rows = ["| case | budget | best Σ e² | median Σ e² | worst Σ e² | median s | published best / mean |",
            "|---|---:|---:|---:|---:|---:|---|"]
    for name, case in CASES.items():
        task = parse_task(case["task"], source=name)
        published = case["published"]
        paper = (f"{published['best']:.4g} / {published['mean']:.4g}" if published else "—")
        for budget in BUDGETS:
            found, times = [], []
            for seed in range(1, seeds + 1):
                began = time.perf_counter()
                found.append(synthesize(task, seed=seed, budget=budget,
                                        seconds=DEFAULT_SECONDS).objective)
                times.append(time.perf_counter() - began)
            default = " (default)" if budget == DEFAULT_BUDGET else ""
            rows.append(f"| {name} | {budget:,}{default} | {min(found):.3g} | "
                        f"{statistics.median(found):.3g} | {max(found):.3g} | "
                        f"{statistics.median(times):.2f} | {paper} |")
    return "\n".join(rows)


if __name__ == "__main__":
    seeds = int(sys.argv[sys.argv.index("--seeds") + 1]) if "--seeds" in sys.argv else 10
    publish(run(seeds), "<!-- synthesis table -->", seeds)
