"""Every way an Assur group can close at the drawn instant, so a student can put it on the
side the exam sheet draws it.

With the members before it in place, a class II group closes in two mirror assemblies (an
RRR dyad's inner joint on either side of the line between its outer joints), or in one at a
limit position, or in none; a class III group may close in up to six. The solver takes the
closure nearest to the drawn points (``[guess]``); this module lists them all, the drawn
one first, each as the places of the group's points, so the builder can move the drawing to
another one and the solver follows.
"""

from __future__ import annotations

import numpy as np

from mechanisms.messages import Text
from mechanisms.schema import Scene

from .kinematics import bodies_before, solve
from .loops import build_loop, group_size, solve_dyad
from .state import Body
from .structure import StructureError, decompose
from .triads import pose_bodies, poses

SAME = 1e-7  # two closures whose points differ by less than this (relative to the group) are one


def closures(scene: Scene, group_name: str) -> list[dict[str, complex]]:
    """The group's distinct closures at the scene's drawn instant, each as {point: place}
    for every point of its members; the one the scene is drawn in first, then by distance
    from it. Empty when the group cannot close there (StructureError for an unknown group)."""
    structure = decompose(scene)
    index = next((i for i, g in enumerate(structure.groups) if g.name == group_name), None)
    if index is None:
        raise StructureError(Text("structure.no_group", group=group_name))
    group = structure.groups[index]
    at = scene.driver.at if scene.guess_at is None else scene.guess_at
    known = bodies_before(scene, structure.groups[:index], at)
    size = group_size(scene, group)
    if group.cls == 2:
        with np.errstate(invalid="ignore"):  # a sign that cannot close is NaN, and left out
            found = [solve_dyad(build_loop(scene, group, sign), known, 0).bodies
                     for sign in (1, -1)]
    else:
        reached = poses(scene, group, known, size, starts=256)
        found = [] if reached is None else [pose_bodies(scene, group, size, *reached)]
    motion = solve(scene, np.array([at]), order=0)
    drawn = {name: complex(motion.points[name].z[0])
             for m in group.members for name in scene.members[m].points}
    return _distinct([p for bodies in found for p in _points(scene, group.members, bodies)],
                     drawn, size)


def _points(scene: Scene, members, bodies: dict[int, Body]) -> list[dict[str, complex]]:
    """Each pose the bodies hold (one per start for a class III group) as point places."""
    count = max(np.size(bodies[m].rot) for m in members)
    return [{name: complex(np.ravel(bodies[m].position(local))[k if count > 1 else 0])
             for m in members for name, local in scene.members[m].points.items()}
            for k in range(count)]


def _distinct(found: list[dict[str, complex]], drawn: dict[str, complex],
              size: float) -> list[dict[str, complex]]:
    """The closures that are real and different, the drawn one first, then nearest first."""
    def distance(p: dict[str, complex], q: dict[str, complex]) -> float:
        return max(abs(p[n] - q[n]) for n in q)

    real = sorted((p for p in found if all(np.isfinite(abs(z)) for z in p.values())),
                  key=lambda p: distance(p, drawn))
    out: list[dict[str, complex]] = []
    for p in real:
        if all(distance(p, q) > SAME * size for q in out):
            out.append(p)
    return out
