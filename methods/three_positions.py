"""The three-position construction, step by step (docs/synthesis.md): three positions of the
coupler, each given by its two joints A and B, give the fixed pivots of a four-bar that
carries the coupler through them. A turns about O, so A₁, A₂, A₃ lie on one circle about O:
O is where the perpendicular bisectors of A₁A₂ and A₂A₃ cross, as with compass and ruler;
D likewise from B₁, B₂, B₃. A position may also be given as a point of the coupler and the
coupler's angle, with A and B placed on the coupler (``joints``).

The crossings are computed from the bisectors (two lines), not taken from a solver, and a
test holds them to the pivots of the four-bar the positions came from.
"""

from __future__ import annotations

import cmath
from dataclasses import dataclass, field

import numpy as np

from mechanisms import Scene, SceneError
from mechanisms.messages import Text
from solvers.kinematics import solve

PARALLEL = 1e-12  # |sin| of the bisectors' angle below which they are taken as parallel


@dataclass(frozen=True)
class Bisector:
    """The perpendicular bisector of the chord ``ends``: through its middle, square to it."""

    ends: tuple[complex, complex]
    middle: complex
    direction: complex  # unit


@dataclass(frozen=True)
class Stage:
    """One step: its sentence (a key of ``three.*`` and the values), the bisectors it draws
    and the points it finds."""

    key: str
    values: dict = field(default_factory=dict)
    lines: tuple[Bisector, ...] = ()
    found: dict[str, complex] = field(default_factory=dict)


def bisector(p: complex, q: complex) -> Bisector:
    if p == q:
        raise SceneError(Text("three.same_place"))
    return Bisector((p, q), (p + q) / 2, 1j * (q - p) / abs(q - p))


def crossing(first: Bisector, second: Bisector, pivot: str) -> complex:
    """Where two bisectors cross: the centre of the circle through the three positions of a
    joint. Three positions on one line have parallel bisectors and no centre: said."""
    d1, d2 = first.direction, second.direction
    sine = (d1.conjugate() * d2).imag
    if abs(sine) < PARALLEL:
        raise SceneError(Text("three.in_line", pivot=pivot))
    t = ((second.middle - first.middle).conjugate() * d2).imag / sine
    return first.middle + t * d1


def joints(point: complex, angle: float, a: complex, b: complex) -> tuple[complex, complex]:
    """A and B where the coupler's point is at ``point`` and the coupler turned by ``angle``
    (rad): ``a`` and ``b`` are A and B relative to the point in the coupler's own frame."""
    turn = cmath.exp(1j * angle)
    return point + turn * a, point + turn * b


def construction(a: list[complex], b: list[complex]) -> list[Stage]:
    """The steps for joints A₁A₂A₃ (of the crank) and B₁B₂B₃ (of the rocker)."""
    stages = []
    pivots = {}
    for joint, pivot, where in (("A", "O", a), ("B", "D", b)):
        first, second = bisector(where[0], where[1]), bisector(where[1], where[2])
        stages.append(Stage("three.chord", {"joint": joint, "i": 1, "j": 2}, (first,)))
        stages.append(Stage("three.chord", {"joint": joint, "i": 2, "j": 3}, (first, second)))
        pivots[pivot] = crossing(first, second, pivot)
        stages.append(Stage("three.pivot", {"joint": joint, "pivot": pivot}, (first, second),
                            {pivot: pivots[pivot]}))
    o, d = pivots["O"], pivots["D"]
    stages.append(Stage("three.links", {"crank": abs(a[0] - o), "coupler": abs(b[0] - a[0]),
                                        "rocker": abs(b[0] - d), "frame": abs(d - o)}))
    return stages


def of_scene(scene: Scene, angles_deg: list[float]) -> tuple[list[complex], list[complex]]:
    """Three positions of a four-bar's coupler as an exercise gives them: the joints of its
    crank and rocker (the builder's A and B, the book's B and C) at three crank angles. The
    construction then finds the scene's own pivots back."""
    crank, coupler = scene.members.get(2), scene.members.get(3)
    if (crank is None or coupler is None or len(coupler.axis) != 2 or len(scene.members) != 3
            or scene.driver.kind != "rotating" or any(p.kind != "revolute" for p in scene.pairs)):
        raise SceneError(Text("three.not_four_bar"))
    a_name, b_name = coupler.axis
    motion = solve(scene, np.radians(angles_deg), order=0, points=[a_name, b_name])
    if not np.all(motion.feasible):
        raise SceneError(Text("three.cannot_reach"))
    return list(motion.points[a_name].z), list(motion.points[b_name].z)
