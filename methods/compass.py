"""The textbook's 12-position compass construction (chapter 1) as steps a student follows.

First the crank circle is divided into the 12 positions of the crank pin. Then, position by
position and group by group, each joint of a class II group is found as the book finds it:
for an RRR dyad, an arc of one link's length about the joint it hangs on, an arc of the
other link's length about the other, and their intersection. Any other kind of group (a
slider's guide, a slotted member) is one step that places its joints. Further points of a
member follow from their offsets, and the last step draws each path through its 12 points.

Each intersection is computed here from the two arcs (the circle–circle construction),
not copied from the solver, so a test can hold the construction against the solution.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from mechanisms.schema import DRIVER, FRAME, Scene
from solvers.kinematics import Motion

POSITIONS = 12


@dataclass(frozen=True)
class CompassStep:
    """One thing drawn: ``what`` names it for the page's text (with ``values``), ``arcs``
    are (centre, radius) pairs, ``found`` the points it places (name → position)."""

    what: str  # "crank", "arc", "meet", "group", "offset" or "path"
    values: dict = field(default_factory=dict)
    arcs: tuple[tuple[complex, float], ...] = ()
    found: dict[str, complex] = field(default_factory=dict)


def numbered(point: str, k: int) -> str:
    return f"{point}{str(k).translate(str.maketrans('0123456789', '₀₁₂₃₄₅₆₇₈₉'))}"


def construction(motion: Motion, paths: list[str]) -> list[CompassStep]:
    """The steps for the 12 positions of ``motion`` (``cycle(scene, 12)``), ending with the
    paths of ``paths``. Positions where the mechanism does not assemble are skipped."""
    scene = motion.scene
    steps = [_crank(scene, motion)]
    for i in range(len(motion.at)):
        if not motion.feasible[i]:
            continue
        known = {name: complex(p.z[i]) for name, p in motion.points.items()
                 if name in scene.frame or name in scene.members[DRIVER].points}
        for group in motion.structure.groups:  # (a group may hang on a point placed by offset)
            steps += _offsets(scene, motion, i, known)
            steps += _group(scene, motion, group, i, known)
        steps += _offsets(scene, motion, i, known)
    for name in (p for p in paths if p not in scene.frame):  # a pivot has no path
        steps.append(CompassStep("path", {"point": name}, found={
            numbered(name, i + 1): complex(motion.points[name].z[i])
            for i in range(len(motion.at)) if motion.feasible[i]}))
    return steps


def _crank(scene: Scene, motion: Motion) -> CompassStep:
    """The crank circle divided in 12; a driver that is no crank (a slider on its guide) has
    its 12 positions placed in one step."""
    pivot = _pivot(scene)
    pin = _pin(scene)
    found = {numbered(pin, i + 1): complex(z) for i, z in enumerate(motion.points[pin].z)
             if np.isfinite(z)}  # (not where the driver itself cannot be placed)
    if pivot is None:
        return CompassStep("group", {"group": str(DRIVER), "position": f"1–{len(motion.at)}",
                                     "points": f"{numbered(pin, 1)} … {numbered(pin, len(motion.at))}"},
                           found=found)
    centre = scene.frame[pivot]
    radius = abs(scene.members[DRIVER].points[pin] - scene.members[DRIVER].points[pivot])
    return CompassStep("crank", {"pin": pin, "centre": pivot, "link": pivot + pin, "radius": radius},
                       ((centre, radius),), found)


def _group(scene: Scene, motion: Motion, group, i: int, known: dict[str, complex]) -> list[CompassStep]:
    k = i + 1
    if group.kind == "RRR" and all(pair.point in known for pair in group.pairs[::2]):
        (j, m), (outer_j, inner, outer_m) = group.members, group.pairs
        x, arcs, out = inner.point, [], []
        for member, outer in ((j, outer_j), (m, outer_m)):
            local = scene.points_of(member)
            radius = abs(local[x] - local[outer.point])
            centre = known[outer.point]
            arcs.append((centre, radius))
            name = outer.point if outer.point in scene.frame else numbered(outer.point, k)
            out.append(CompassStep("arc", {"link": outer.point + x, "radius": radius, "centre": name},
                                   ((centre, radius),)))
        where = _meet(*arcs, complex(motion.points[x].z[i]))
        known[x] = where
        out.append(CompassStep("meet", {"point": numbered(x, k), "letter": x,
                                        "crank": numbered(_pin(scene), k)},
                               tuple(arcs), {numbered(x, k): where}))
        return out
    placed = {}  # a slider's or a slotted member's group: its members' points, in one step
    for member in group.members:
        for name in scene.points_of(member):
            if name in motion.points and name not in known:
                known[name] = placed[name] = complex(motion.points[name].z[i])
    return [CompassStep("group", {"group": group.label(), "position": k,
                                  "points": ", ".join(numbered(n, k) for n in placed)},
                        found={numbered(n, k): z for n, z in placed.items()})] if placed else []


def _offsets(scene: Scene, motion: Motion, i: int, known: dict[str, complex]) -> list[CompassStep]:
    """Points of a member placed from two of its known points, as a student transfers the
    member's triangle (or its offsets along and across the link)."""
    out = []
    for number, member in scene.members.items():
        for name, local in member.points.items():
            if name in known or name not in motion.points:
                continue
            given = [p for p in member.points if p in known and p != name
                     and member.points[p] != member.points.get(name)]
            if len(given) < 2 or member.points[given[0]] == member.points[given[1]]:
                continue
            a, b = given[:2]
            axis = (member.points[b] - member.points[a]) / abs(member.points[b] - member.points[a])
            offset = (local - member.points[a]) / axis
            known[name] = complex(motion.points[name].z[i])
            out.append(CompassStep("offset", {"point": numbered(name, i + 1), "member": number,
                                              "from": numbered(a, i + 1), "to": numbered(b, i + 1),
                                              "along": offset.real, "left": offset.imag},
                                   found={numbered(name, i + 1): known[name]}))
    return out


def _pivot(scene: Scene) -> str | None:
    """The crank's frame pivot (None when the driver is not a crank)."""
    return next((p.point for p in scene.pairs if p.kind == "revolute"
                 and set(p.members) == {FRAME, DRIVER}), None)


def _pin(scene: Scene) -> str:
    """The driver's point the construction follows: the crank pin (or a slider's point)."""
    pivot = _pivot(scene)
    return next((n for n in scene.members[DRIVER].points if n != pivot and n not in scene.frame),
                next(iter(scene.members[DRIVER].points)))


def _meet(first: tuple[complex, float], second: tuple[complex, float], near: complex) -> complex:
    """Where two arcs cross: of the two intersections, the one the mechanism is assembled at
    (a student picks it from the sketch)."""
    (c1, r1), (c2, r2) = first, second
    d = abs(c2 - c1)
    along = (d * d + r1 * r1 - r2 * r2) / (2 * d)
    across = np.sqrt(max(r1 * r1 - along * along, 0.0))
    u = (c2 - c1) / d
    options = [c1 + u * (along + s * 1j * across) for s in (1, -1)]
    return min(options, key=lambda z: abs(z - near))
