"""Accuracy the user trades for speed, measured in three tables:

* finite differences against the solver's exact velocities and accelerations, at the
  resolutions the pages offer (the error a differentiating tool would carry);
* Newton's tolerance for class III groups → iterations, time and position error;
* the graphical plans at the book's scales, drawn to 0.5 mm → the uncertainty of what is
  read off them.

    .venv/bin/python bench/accuracy.py           # print the tables
    .venv/bin/python bench/accuracy.py --write   # and regenerate them in docs/performance.md
"""

import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from bench.publish import publish  # noqa: E402
from mechanisms import load_preset  # noqa: E402
from methods.plans import build, readings  # noqa: E402
from solvers.diagnostics import newton_accuracy, solve_instant, sweep_values  # noqa: E402
from solvers.kinematics import solve  # noqa: E402

STEPS = (12, 72, 360, 3600)
DIFFERENCES = (("four-bar-crank-rocker", "E"), ("slider-crank", "B"), ("zbirka-2.2", "D"))
TRIADS = ("triad-full-turn", "zbirka-4.3")
BOOK_SCALES = ("zbirka-2.1", "zbirka-2.2", "zbirka-2.5", "zbirka-3.1")
PRECISION_CM = 0.05


def difference_errors(scene, point: str, steps: int) -> tuple[float, float]:
    """Largest error of central differences of the point's path against the exact velocity
    and acceleration over a full turn, relative to the largest exact value."""
    phi = np.linspace(0.0, 2 * np.pi, steps, endpoint=False)
    motion = solve(scene, phi)
    p = motion.points[point]
    h = 2 * np.pi / steps / scene.driver.speed  # time between positions at constant ω₂
    z = p.z
    v = (np.roll(z, -1) - np.roll(z, 1)) / (2 * h)
    a = (np.roll(z, -1) - 2 * z + np.roll(z, 1)) / h**2
    return (float(np.max(np.abs(v - p.v)) / np.max(np.abs(p.v))),
            float(np.max(np.abs(a - p.a)) / np.max(np.abs(p.a))))


def differences_table() -> str:
    rows = ["| scene, point | positions | velocity error (rel.) | acceleration error (rel.) |",
            "|---|---:|---:|---:|"]
    for pid, point in DIFFERENCES:
        scene = load_preset(pid)
        for steps in STEPS:
            ev, ea = difference_errors(scene, point, steps)
            rows.append(f"| {pid}, {point} | {steps} | {ev:.1e} | {ea:.1e} |")
    return "\n".join(rows)


def newton_table() -> str:
    rows = ["| scene | tolerance | iterations mean / max | time, ms (360 positions) | position error, m |",
            "|---|---:|---:|---:|---:|"]
    for pid in TRIADS:
        scene = load_preset(pid)
        for r in newton_accuracy(scene, sweep_values(scene, 360)):
            rows.append(f"| {pid} | {r['tol']:.0e} | {r['iterations_mean']:.2f} / "
                        f"{r['iterations_max']} | {r['solve_ms']:.1f} | {r['error_m']:.1e} |")
    return "\n".join(rows)


def graphical_table() -> str:
    rows = ["| scene | U_L, m/cm | U_v, m/s per cm | U_a, m/s² per cm | values read | median ± | largest ± |",
            "|---|---:|---:|---:|---:|---:|---:|"]
    for pid in BOOK_SCALES:
        scene = load_preset(pid)
        read = readings(build(solve_instant(scene, None)), scene.scales, PRECISION_CM)
        relative = [100 * r.uncertainty / r.exact for r in read if r.exact > 0]
        rows.append(f"| {pid} | {scene.scales['L']:g} | {scene.scales['v']:g} | "
                    f"{scene.scales['a']:g} | {len(relative)} | {np.median(relative):.1f} % | "
                    f"{max(relative):.1f} % |")
    return "\n".join(rows)


if __name__ == "__main__":
    publish(differences_table(), "<!-- differences table -->", 1)
    publish(newton_table(), "<!-- newton table -->", 3)  # newton_accuracy's repeat
    publish(graphical_table(), "<!-- graphical table -->", 1)
