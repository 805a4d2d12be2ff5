"""Plain-language explanations of where and why a linkage cannot move or is near a dead centre."""

from __future__ import annotations

import math
import time

import numpy as np

from mechanisms.messages import Joined, Text
from mechanisms.schema import Scene

from .kinematics import SINGULAR, GroupIssue, Motion, solve
from .loops import group_size
from .triads import TOL, Iterate, newton_trace
from .kinetostatics import analyse
from .structure import Structure, decompose
from .budget import Unsolvable  # defined there, where the time budget needs it; imported from here

# the dyads whose failure to close has a sentence of its own (``why_open.<kind>``)
WHY_OPEN = {"RRR", "RRP", "RPR", "PRP", "RPP"}


def format_driver(scene: Scene, value: float) -> Text:
    if scene.driver.kind == "rotating":
        return Text("driver.angle", angle=math.degrees(value))
    return Text("driver.stroke", s=value)


def format_range(scene: Scene, lo: float, hi: float) -> Text:
    if lo == hi:
        return format_driver(scene, lo)
    if scene.driver.kind == "rotating":
        return Text("driver.angles", lo=round(math.degrees(lo), 1), hi=round(math.degrees(hi), 1))
    return Text("driver.strokes", lo=float(f"{lo:.4g}"), hi=float(f"{hi:.4g}"))


def format_ranges(scene: Scene, ranges: list[tuple[float, float]]) -> Joined:
    """Several driver ranges in one place of a sentence."""
    return Joined(format_range(scene, lo, hi) for lo, hi in ranges)


def sweep_values(scene: Scene, steps: int = 3600) -> np.ndarray:
    """Driver values for a survey: a full turn, or ± the sum of link lengths for a slider."""
    if scene.driver.kind == "rotating":
        return np.linspace(0.0, 2 * math.pi, steps, endpoint=False)
    reach = sum(scene.lengths.values()) + max(abs(z) for z in scene.frame.values())
    return np.linspace(scene.driver.at - reach, scene.driver.at + reach, steps)


def dead_zones(scene: Scene, structure: Structure | None = None,
               steps: int = 3600) -> list[GroupIssue]:
    """Where each group cannot close over a full survey of the driver (positions only)."""
    motion = solve(scene, sweep_values(scene, steps), order=0, structure=structure)
    return [issue for issue in motion.issues if issue.problem == "open"]


def explain_open(scene: Scene, at: float, issue: GroupIssue,
                 structure: Structure | None = None) -> str:
    """Why the group fails at ``at``, and the driver ranges where the mechanism cannot go."""
    structure = structure or decompose(scene)
    zones = [z for z in dead_zones(scene, structure) if z.group == issue.group]
    ranges = [r for z in zones for r in _wrap(scene, z.ranges)]
    why = Text(f"why_open.{issue.kind}" if issue.kind in WHY_OPEN else "why_open.other")
    where = ""
    if ranges:
        rotating = scene.driver.kind == "rotating"
        where = Text("open.crank_cannot" if rotating else "open.slider_cannot",
                     ranges=format_ranges(scene, ranges))
    return Text("open.group", group=issue.group, kind=issue.kind, at=format_driver(scene, at),
                why=why, where=where)


def _wrap(scene: Scene, ranges: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Join a range that runs over 360° with the one that starts at 0°."""
    if scene.driver.kind != "rotating" or len(ranges) < 2:
        return ranges
    step = 2 * math.pi / 3600
    (a0, b0), (a1, b1) = ranges[0], ranges[-1]
    if a0 < step / 2 and b1 > 2 * math.pi - 1.5 * step:
        return [(a1 - 2 * math.pi, b0)] + ranges[1:-1]
    return ranges


def explain_singular(scene: Scene, at: float, group: str, condition: float) -> Text:
    return Text("open.dead_centre", group=group, at=format_driver(scene, at),
                condition=float(f"{condition:.3g}"))


def _driver_value(scene: Scene, at: float | None) -> float:
    if at is None:
        return scene.driver.at
    return math.radians(at) if scene.driver.kind == "rotating" else at


def solve_instant(scene: Scene, at: float | None, tol: float = TOL) -> Motion:
    """Solve one instant (driver value in degrees or metres, default the scene's own), or
    raise ``Unsolvable`` with the reason; ``tol`` as for ``solve``."""
    value = _driver_value(scene, at)
    structure = decompose(scene)
    motion = solve(scene, value, structure=structure, tol=tol)
    for issue in motion.issues:
        if issue.problem == "open":
            raise Unsolvable(explain_open(scene, value, issue, structure))
    for name, t in motion.transmission.items():
        if t[0] < SINGULAR:
            raise Unsolvable(explain_singular(scene, value, name, 1.0 / max(t[0], 1e-300)))
    return motion


TOLERANCES = (1e-3, 1e-6, 1e-9, 1e-12)
# the reference solve: 1e-14 is below round-off for some groups (task 4.2 lost 85 % of its
# positions there, and the error column silently compared the rest), 1e-13 is not
REFERENCE = 1e-13


def newton_iterations(scene: Scene, back: float, tol: float = TOL) -> dict[str, list[Iterate]]:
    """Newton's method for each class III group at the scene's instant, iterate by iterate,
    started from the group's pose ``back`` earlier (rad or m: the last position a student
    drew), or ``back`` later where the mechanism cannot be earlier (the end of a stroke). A
    start it cannot reach either way gives an empty list."""
    structure = decompose(scene)
    triads = [g for g in structure.groups if g.cls == 3]
    if not triads:
        return {}
    at = scene.driver.at
    motion = solve(scene, np.array([at, at - back, at + back]), order=0, structure=structure,
                   tol=REFERENCE)
    out = {}
    for group in triads:
        reached = [i for i in (1, 2) if all(np.isfinite(motion.bodies[m].z[i]) for m in group.members)]
        out[group.name] = newton_trace(scene, group, motion, 0, reached[0], group_size(
            scene, group), tol) if reached else []
    return out


def newton_accuracy(scene: Scene, values: np.ndarray, tolerances=TOLERANCES,
                    repeat: int = 3, progress=None) -> list[dict]:
    """Speed against accuracy of the class III groups' Newton solve, measured: for each
    tolerance (largest constraint violation / group size), the iterations per position
    (mean, max), the median solve time (ms, positions only) and the largest position error
    of any point (m) against a solve at ``REFERENCE``. ``progress(fraction)`` is told how far
    it is."""
    structure = decompose(scene)
    reference = solve(scene, values, order=0, structure=structure, tol=REFERENCE)
    rows = []
    for tol in tolerances:
        times = []
        for _ in range(repeat):
            start = time.perf_counter()
            motion = solve(scene, values, order=0, structure=structure, tol=tol)
            times.append(time.perf_counter() - start)
        ok = motion.feasible & reference.feasible
        error = max((float(np.max(np.abs(p.z[ok] - reference.points[n].z[ok]), initial=0.0))
                     for n, p in motion.points.items()), default=0.0)
        iterations = np.concatenate([r.iterations[ok] for r in motion.newton.values()] or [[]])
        rows.append({"tol": tol, "iterations_mean": float(np.mean(iterations)) if iterations.size else 0.0,
                     "iterations_max": int(np.max(iterations, initial=0)),
                     "solve_ms": 1e3 * float(np.median(times)), "error_m": error})
        if progress:
            progress(len(rows) / len(tolerances))
    return rows


def torque_resolution(scene: Scene, resolutions, inertia: bool = True, progress=None) -> list[dict]:
    """Speed against accuracy of the driving-torque curve, measured: for each number of
    positions per cycle, the time of a whole kinetostatic cycle (ms), its peak |M_p| (or
    |F_p|) and how far that peak is from the finest resolution's (%). A coarse cycle misses
    the peak. ``progress(fraction)`` is told how far it is (the work grows with positions)."""
    rows: list[dict] = []
    for steps in resolutions:
        if progress:
            progress(sum(r["steps"] for r in rows) / sum(resolutions))
        start = time.perf_counter()
        k = analyse(scene, sweep_values(scene, steps), inertia=inertia)
        rows.append({"steps": steps, "ms": 1e3 * (time.perf_counter() - start),
                     "peak": float(np.nanmax(np.abs(k.driving), initial=0.0))})
    finest = rows[-1]["peak"]
    for row in rows:
        row["change"] = 100 * (row["peak"] - finest) / finest if finest else 0.0
    return rows
