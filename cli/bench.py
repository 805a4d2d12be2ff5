"""Benchmark: the kinematics core against a plain closed-form numpy four-bar.

The baseline below is written independently of the solver (textbook formulas in real
arithmetic), so it measures both speed and accuracy. It applies to scenes whose first
Assur group is an RRR dyad hung on the crank and the frame — a four-bar.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

from mechanisms.schema import DRIVER, FRAME, Scene
from solvers.kinematics import solve
from solvers.structure import Structure, decompose


def fourbar_closed_form(o, d, r2, r3, r4, phi2, omega2, eps2, sign):
    """φ₃, φ₄, ω₃, ω₄, ε₃, ε₄ of the loop O→A→C = O→D→C, C on the side ``sign``."""
    ax, ay = o[0] + r2 * np.cos(phi2), o[1] + r2 * np.sin(phi2)
    dx, dy = d[0] - ax, d[1] - ay
    dist = np.hypot(dx, dy)
    x = (r3 * r3 - r4 * r4 + dist * dist) / (2 * dist)
    h = np.sqrt(np.where(r3 * r3 >= x * x, r3 * r3 - x * x, np.nan))
    cx = ax + (x * dx - sign * h * dy) / dist
    cy = ay + (x * dy + sign * h * dx) / dist
    phi3 = np.arctan2(cy - ay, cx - ax)
    phi4 = np.arctan2(cy - d[1], cx - d[0])
    s2, c2, s3, c3, s4, c4 = (np.sin(phi2), np.cos(phi2), np.sin(phi3), np.cos(phi3),
                              np.sin(phi4), np.cos(phi4))
    # [[−r3·s3, r4·s4], [r3·c3, −r4·c4]]·(ω3, ω4) = (r2·ω2·s2, −r2·ω2·c2)
    det = r3 * r4 * (s3 * c4 - c3 * s4)
    bx, by = r2 * omega2 * s2, -r2 * omega2 * c2
    w3 = (bx * (-r4 * c4) - (r4 * s4) * by) / det
    w4 = ((-r3 * s3) * by - bx * (r3 * c3)) / det
    # the same matrix for ε3, ε4
    bx = r2 * eps2 * s2 + r2 * omega2**2 * c2 + r3 * w3**2 * c3 - r4 * w4**2 * c4
    by = -r2 * eps2 * c2 + r2 * omega2**2 * s2 + r3 * w3**2 * s3 - r4 * w4**2 * s4
    e3 = (bx * (-r4 * c4) - (r4 * s4) * by) / det
    e4 = ((-r3 * s3) * by - bx * (r3 * c3)) / det
    return phi3, phi4, w3, w4, e3, e4


def _fourbar_of(scene: Scene, structure: Structure):
    """The four-bar data of the scene's first group, or None when it is not a four-bar."""
    group = structure.groups[0]
    if group.kind != "RRR" or group.attached_to != {FRAME, DRIVER}:
        return None
    crank = scene.members[DRIVER]
    j, k = group.members
    if group.pairs[0].other(j) != DRIVER:
        j, k = k, j
    pin = scene.pair(scene.driver.pair).point
    a_name = next(p.point for p in scene.pairs if set(p.members) == {DRIVER, j})
    joint = next(p.point for p in scene.pairs if set(p.members) == {j, k})
    d_name = next(p.point for p in scene.pairs if set(p.members) == {k, FRAME})
    coupler, rocker = scene.members[j], scene.members[k]
    return dict(o=(scene.frame[pin].real, scene.frame[pin].imag),
                d=(scene.frame[d_name].real, scene.frame[d_name].imag),
                r2=abs(crank.points[a_name]), r3=abs(coupler.points[joint] - coupler.points[a_name]),
                r4=abs(rocker.points[joint] - rocker.points[d_name]), members=(j, k),
                point=joint)


def _median_time(fn, repeat: int) -> float:
    fn()
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return float(np.median(times))


@dataclass
class BenchResult:
    scene: str
    steps: int
    repeat: int
    positions_ms: float
    full_ms: float
    feasible: int
    baseline_ms: float | None = None  # closed-form four-bar, pos + vel + acc
    angle_error: float | None = None  # rad
    rate_error: float | None = None  # ω and ε, relative to their peak

    @property
    def ratio(self) -> float | None:
        return None if self.baseline_ms is None else self.full_ms / self.baseline_ms


def measure(scene: Scene, steps: int, repeat: int) -> BenchResult:
    """Time the solver over ``steps`` positions and compare it with the closed form."""
    phi = np.linspace(0.0, 2 * math.pi, steps, endpoint=False)
    structure = decompose(scene)
    fb = _fourbar_of(scene, structure)
    wanted = [fb["point"]] if fb else None
    t_pos = _median_time(lambda: solve(scene, phi, order=0, points=wanted, structure=structure), repeat)
    t_all = _median_time(lambda: solve(scene, phi, order=2, points=wanted, structure=structure), repeat)
    motion = solve(scene, phi, order=2, points=wanted, structure=structure)
    result = BenchResult(scene.id, steps, repeat, t_pos * 1e3, t_all * 1e3, int(motion.feasible.sum()))
    if fb is None:
        return result
    j, k = fb["members"]
    args = (fb["o"], fb["d"], fb["r2"], fb["r3"], fb["r4"], phi, scene.driver.speed,
            scene.driver.accel)
    ours = (motion.members[j].angle, motion.members[k].angle, motion.members[j].omega,
            motion.members[k].omega, motion.members[j].epsilon, motion.members[k].epsilon)
    sign = 1.0
    ref = fourbar_closed_form(*args, sign)
    if np.nanmax(np.abs(np.angle(np.exp(1j * (ref[0] - ours[0]))))) > 1e-6:
        sign = -1.0
        ref = fourbar_closed_form(*args, sign)
    result.baseline_ms = _median_time(lambda: fourbar_closed_form(*args, sign), repeat) * 1e3
    # the accuracy reference: the same closed form in extended precision (x87's 64-bit
    # mantissa where numpy has it). Near a dead centre the float64 closed form loses digits
    # too; against it, two exact float64 solvers differed by 1e-11 at task 2.1's dead zone
    # where both are within 3e-12 of the truth.
    extended = [np.asarray(a, dtype=np.longdouble) if isinstance(a, (tuple, np.ndarray))
                else np.longdouble(a) for a in args]
    ref = [np.asarray(r, dtype=np.longdouble) for r in fourbar_closed_form(*extended, sign)]
    ok = np.isfinite(ref[0]) & motion.feasible
    result.angle_error = max(float(np.max(np.abs(np.angle(np.exp(1j * (a - b).astype(float)))[ok])))
                             for a, b in zip(ref[:2], ours[:2]))
    result.rate_error = max(float(np.max(np.abs(a - b)[ok]) / np.max(np.abs(a[ok])))
                            for a, b in zip(ref[2:], ours[2:]))
    return result


def run_bench(scene: Scene, steps: int, repeat: int) -> str:
    """The benchmark as text, for the command line."""
    r = measure(scene, steps, repeat)
    lines = [f"benchmark: {r.scene}, N = {r.steps} positions, median of {r.repeat} runs",
             f"  mehanizmi, positions only          {r.positions_ms:8.3f} ms",
             f"  mehanizmi, pos + vel + acc         {r.full_ms:8.3f} ms"]
    if r.baseline_ms is None:
        lines.append("  (no closed-form baseline: the first group is not a four-bar on the crank)")
        return "\n".join(lines)
    lines += [f"  closed-form numpy baseline         {r.baseline_ms:8.3f} ms  (pos + vel + acc)",
              f"  ratio mehanizmi / baseline         {r.ratio:8.2f}×   (target ≤ 1.5×)",
              f"  max error vs baseline: angles {r.angle_error:.2e} rad, ω and ε {r.rate_error:.2e} "
              f"(relative to their peak); {r.feasible} of {r.steps} positions feasible"]
    return "\n".join(lines)
