"""Kinematics benchmark: the solver against a closed-form numpy four-bar at 12 … 3600 positions.

    .venv/bin/python bench/kinematics.py           # print the table
    .venv/bin/python bench/kinematics.py --write   # and regenerate docs/performance.md
"""

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from bench.publish import publish  # noqa: E402
from cli.bench import measure  # noqa: E402
from mechanisms import load_preset  # noqa: E402

SCENES = ("four-bar-crank-rocker", "analitika-2.1", "analitika-2.2")
STEPS = (12, 72, 360, 3600)


def table() -> str:
    rows = ["| scene | positions | positions only, ms | pos + vel + acc, ms | closed form, ms | ratio | max angle error, rad | max ω, ε error (rel.) |",
            "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for preset in SCENES:
        for steps in STEPS:
            r = measure(load_preset(preset), steps, repeat=300)
            base = "—" if r.baseline_ms is None else f"{r.baseline_ms:.3f}"
            ratio = "—" if r.ratio is None else f"{r.ratio:.2f}×"
            err_a = "—" if r.angle_error is None else f"{r.angle_error:.1e}"
            err_r = "—" if r.rate_error is None else f"{r.rate_error:.1e}"
            rows.append(f"| {preset} | {steps} | {r.positions_ms:.3f} | {r.full_ms:.3f} | {base} | "
                        f"{ratio} | {err_a} | {err_r} |")
    return "\n".join(rows)


if __name__ == "__main__":
    publish(table(), '<!-- kinematics table -->', 300)
