"""Point paths over the cycle (chapter 1): the positions of the 12-step construction, the
accuracy of a path drawn from N positions, path metrics, animation order through dead zones,
and the path in the field of a machine that travels (task 1.3).
"""

from __future__ import annotations

import math
import time

import numpy as np

from mechanisms.schema import DRIVER, FRAME, Scene, Travel

from .kinematics import Motion, solve

REFERENCE_STEPS = 14_400  # a multiple of every offered resolution (12, 72, 360, 3600)


def cycle_values(scene: Scene, steps: int) -> np.ndarray:
    """φ₂ of the positions 1…N: from the scene's instant, in the sense of rotation.

    Position 1 is the scene's own instant, as B₁ is the starting point of the book's
    compass construction; equal steps of 2π/N follow in the direction ω₂ turns.
    """
    sense = 1.0 if scene.driver.speed >= 0 else -1.0
    return scene.driver.at + sense * 2 * math.pi * np.arange(steps) / steps


def numbered_points(scene: Scene, points: list[str]) -> list[str]:
    """The points whose positions the 12-step construction numbers: the driving member's
    moving point (B of tasks 1.1, C of 1.2) always, first, then ``points``."""
    member = scene.members[DRIVER]
    pin = next(p for p in member.axis[::-1] + tuple(member.points) if p not in scene.frame)
    return list(dict.fromkeys([pin, *points]))


def chord_deviation(scene: Scene, steps: int, points: list[str],
                    reference: Motion | None = None) -> dict[str, float]:
    """Largest distance (m) between each point's exact path and the polyline through N positions.

    The exact path is sampled at ``REFERENCE_STEPS`` positions; every sample between two
    drawn positions is measured against the chord joining them. Segments that touch a
    position where the mechanism cannot be are skipped (nothing is drawn there).
    """
    if REFERENCE_STEPS % steps:
        raise ValueError(f"{steps} positions do not divide {REFERENCE_STEPS}")
    fine = reference or solve(scene, cycle_values(scene, REFERENCE_STEPS), order=0, points=points)
    k = REFERENCE_STEPS // steps
    out = {}
    for name in points:
        z = fine.points[name].z.reshape(steps, k)  # row i: samples from position i to i+1
        start = z[:, :1]
        end = np.roll(z[:, 0], -1)[:, None]
        chord = end - start
        length = np.abs(chord)
        rel = z - start
        with np.errstate(invalid="ignore", divide="ignore"):
            t = np.clip((rel * np.conj(chord)).real / (length * length), 0.0, 1.0)
            dist = np.where(length > 0, np.abs(rel - t * chord), np.abs(rel))
        ok = np.isfinite(dist).all(axis=1)
        out[name] = float(dist[ok].max()) if ok.any() else math.nan
    return out


def path_length(z: np.ndarray) -> float:
    """Length of a closed path sampled over one cycle (m); open stretches are left out."""
    steps = np.abs(np.diff(np.append(z, z[:1])))
    return float(np.nansum(steps))


def strokes(motion: Motion) -> dict[str, float]:
    """Stroke (max − min of the relative displacement) of every prismatic pair (m)."""
    return {name: float(np.nanmax(s.s) - np.nanmin(s.s)) for name, s in motion.sliders.items()
            if np.isfinite(s.s).any()}


def swings(motion: Motion) -> dict[int, tuple[float, float]]:
    """Extreme angles (degrees) of every member pinned to the frame that does not turn fully
    — a rocker's two limit positions — from the solved cycle."""
    out = {}
    scene = motion.scene
    for pair in scene.pairs:
        if pair.kind != "revolute" or FRAME not in pair.members:
            continue
        number = pair.other(FRAME)
        if number == DRIVER or number not in motion.members:
            continue
        angle = motion.members[number].angle
        ok = np.isfinite(angle)
        if not ok.any():
            continue
        turned = np.unwrap(angle[ok])
        if np.ptp(turned) < 2 * math.pi - 1e-6:
            mid = np.angle(np.exp(1j * turned.mean()))  # a centre for the range, −180…180°
            rel = np.angle(np.exp(1j * (angle[ok] - mid)))
            out[number] = (math.degrees(mid + rel.min()), math.degrees(mid + rel.max()))
    return out


def cycle_time(scene: Scene) -> float:
    """Time of one crank turn, 2π/|ω₂| (s); infinite for a crank at rest."""
    return 2 * math.pi / abs(scene.driver.speed) if scene.driver.speed else math.inf


def animation_order(feasible: np.ndarray, start: int = 0) -> np.ndarray:
    """Frame indices that never jump across a dead zone.

    A crank that turns fully runs 0…N−1. Where the crank cannot pass a range, the
    mechanism rocks: forward from ``start`` to one limit, back to the other limit and
    forward again to ``start`` — the motion a real drive that reverses would show.
    """
    n = len(feasible)
    if feasible.all():
        return np.arange(n)
    if not feasible[start]:
        start = int(np.flatnonzero(feasible)[0]) if feasible.any() else 0
    if not feasible.any():
        return np.array([], dtype=int)
    forward = [start]
    while feasible[(forward[-1] + 1) % n] and len(forward) < n:
        forward.append((forward[-1] + 1) % n)
    backward = [start]
    while feasible[(backward[-1] - 1) % n] and len(backward) < n:
        backward.append((backward[-1] - 1) % n)
    arc = backward[::-1] + forward[1:]  # from one limit to the other, through start
    i = arc.index(start)
    return np.array(arc[i:] + arc[::-1][1:-1] + arc[:i], dtype=int)


def field_path(motion: Motion, travel: Travel, point: str, cycles: int) -> tuple[np.ndarray, np.ndarray]:
    """The point's path in the field over ``cycles`` turns: relative path + v_R·t.

    ``motion`` must hold one cycle from ``cycle_values``; returns (times in s, complex positions).
    """
    steps = len(motion.at)
    omega = motion.scene.driver.speed
    k = np.arange(steps * cycles + 1)
    t = k * (2 * math.pi / steps) / abs(omega)
    z = motion.points[point].z[k % steps]
    return t, z + travel.speed * t * np.exp(1j * travel.angle)


def loops_backward(motion: Motion, travel: Travel, point: str) -> tuple[bool, float]:
    """Whether the point's field path loops back (a true trochoid), and the smallest speed
    along the direction of travel (m/s; negative means it moves backwards in the field)."""
    direction = np.exp(1j * travel.angle)
    along = (motion.points[point].v * np.conj(direction)).real + travel.speed
    slowest = float(np.nanmin(along))
    return slowest < 0, slowest


def solve_times(scene: Scene, resolutions=(12, 72, 360, 3600), repeat: int = 5) -> dict[int, float]:
    """The median time (ms) to solve positions and velocities at each resolution. It depends
    on the mechanism's structure, not on its lengths: a page measures it once per mechanism
    (about 17 ms of solves) and not on every length change."""
    times = {}
    for n in resolutions:
        values = cycle_values(scene, n)
        runs = []
        for _ in range(repeat):
            start = time.perf_counter()
            solve(scene, values, order=1)
            runs.append(time.perf_counter() - start)
        times[n] = 1e3 * float(np.median(runs))
    return times


def path_errors(scene: Scene, points: list[str], resolutions=(12, 72, 360, 3600)) -> dict[int, float]:
    """The largest chord deviation (m) of the drawn paths of ``points`` from the exact ones, at
    each resolution (one exact solve shared by all)."""
    reference = solve(scene, cycle_values(scene, REFERENCE_STEPS), order=0, points=points)
    return {n: max(chord_deviation(scene, n, points, reference).values()) for n in resolutions}
