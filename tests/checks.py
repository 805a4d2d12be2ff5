"""Independent checks used by several tests: loop closure read from the results alone."""

from __future__ import annotations

import cmath

import numpy as np

from mechanisms.schema import FRAME, Scene
from solvers import Motion


def closure_residual(scene: Scene, motion: Motion) -> float:
    """Largest violation of the scene's constraints by the solved positions (m).

    Rigid members keep their point distances and orientation; every slider point stays
    on its guide line with the locked relative angle; frame points stay put. Positions
    come from the result only, so a wrong solver cannot hide here.
    """
    z = {name: p.z for name, p in motion.points.items()}
    worst = 0.0
    for name, c in scene.frame.items():
        worst = max(worst, float(np.nanmax(np.abs(z[name] - c))))
    for number, member in scene.members.items():
        names = list(member.points)
        theta = motion.members[number].angle
        for i, p in enumerate(names):
            for q in names[i + 1:]:
                local = member.points[q] - member.points[p]
                world = z[q] - z[p]
                expected = local * np.exp(1j * theta)
                worst = max(worst, float(np.nanmax(np.abs(world - expected))))
    for pair in scene.pairs:
        if pair.kind != "prismatic":
            continue
        guide, slider = pair.members
        theta_g = 0.0 if guide == FRAME else motion.members[guide].angle
        theta_s = 0.0 if slider == FRAME else motion.members[slider].angle
        direction = cmath.exp(1j * pair.angle) * np.exp(1j * theta_g)
        off_line = ((z[pair.point] - z[pair.through]) * np.conj(direction)).imag
        twist = np.angle(np.exp(1j * (theta_s - theta_g - pair.lock)))
        worst = max(worst, float(np.nanmax(np.abs(off_line))), float(np.nanmax(np.abs(twist))))
    return worst


def size(scene: Scene) -> float:
    """A length scale of the scene, for relative tolerances."""
    spans = [abs(c) for m in scene.members.values() for c in m.points.values()]
    spans += [abs(c) for c in scene.frame.values()]
    return max(spans)
