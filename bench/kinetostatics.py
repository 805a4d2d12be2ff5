"""Kinetostatics benchmark: cycle resolution → time, peak driving torque error, agreement.

    .venv/bin/python bench/kinetostatics.py           # print the table
    .venv/bin/python bench/kinetostatics.py --write   # and regenerate its part of docs/performance.md

The reference for the peak is the same analysis at 36 000 positions; the agreement is the
largest difference of the three driving torques (groups, lever, power balance) relative
to the size of the load terms, over the cycle.
"""

import dataclasses
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from bench.publish import publish  # noqa: E402
from mechanisms import load_preset  # noqa: E402
from solvers.diagnostics import sweep_values  # noqa: E402
from solvers.kinetostatics import analyse  # noqa: E402

STEPS = (12, 72, 360, 3600)
MARK = "<!-- kinetostatics table -->"


def scenes():
    yield load_preset("predavanja-kinetostatika")
    yield load_preset("zbirka-5.3")
    yield load_preset("zbirka-5.4")
    triad = load_preset("triad-full-turn")  # class III: give its members masses
    members = {n: dataclasses.replace(m, mass=1.0, gyration=0.05) for n, m in triad.members.items()}
    yield dataclasses.replace(triad, members=members, gravity=9.81)


def peak(scene, steps: int) -> tuple[float, str]:
    """The peak |M_p| over the cycle, or why it has none: a dead point of a group (its
    velocities, and so the inertia forces, grow without bound there)."""
    k = analyse(scene, sweep_values(scene, steps))
    dead = [i for i in k.motion.issues if i.problem == "near-singular"]
    where = f"none: dead point near {np.degrees(dead[0].ranges[0][0]):.1f}°" if dead else ""
    return float(np.nanmax(np.abs(k.driving))), where


def table() -> str:
    rows = ["| scene | positions | time, ms | peak \\|M_p\\|, N·m | peak error | three methods agree to |",
            "|---|---:|---:|---:|---:|---:|"]
    for scene in scenes():
        reference, dead = peak(scene, 36_000)
        for steps in STEPS:
            values = sweep_values(scene, steps)
            analyse(scene, values)
            runs = []
            for _ in range(20):
                start = time.perf_counter()
                k = analyse(scene, values)
                runs.append(time.perf_counter() - start)
            top = float(np.nanmax(np.abs(k.driving)))
            error = dead or f"{100 * (top - reference) / reference:+.3f} %"
            rows.append(f"| {scene.id} | {steps} | {1e3 * np.median(runs):.2f} | {top:.5g} | "
                        f"{error} | {np.nanmax(k.disagreement):.0e} |")
    return "\n".join(rows)


if __name__ == "__main__":
    publish(table(), MARK, 20)
