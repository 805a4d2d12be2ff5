"""Kinematics benchmark: the solver against a closed-form numpy four-bar, N = 12 … 3600.

Run: .venv/bin/python bench/kinematics.py   (prints time, ratio and error per resolution)
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from mechanisms import load_preset  # noqa: E402
from solvers.bench import run_bench  # noqa: E402

if __name__ == "__main__":
    for preset in ("analitika-2.1", "four-bar-crank-rocker", "analitika-2.2"):
        for steps in (12, 72, 360, 3600):
            print(run_bench(load_preset(preset), steps, repeat=200 if steps < 3600 else 300))
            print()
