"""The final contour of the complex-number method (seed 001, the "završna kontura" of its
tasks): a point that is no joint, e.g. a coupler point, written as the chain of member vectors
from the origin, r_E = r_0 + l_2·e^{iφ₂} + l_3·e^{i(φ₃ + β)}, and differentiated twice
for v_E and a_E once the loops have given every φ, ω and ε.

The chain runs from the frame through revolute joints (the driver first, as the seed goes
through the crank), so every leg is a constant length turned by one member's angle.
"""

from __future__ import annotations

import cmath
from collections import deque
from dataclasses import dataclass

from mechanisms.schema import DRIVER, FRAME, Scene
from solvers.kinematics import Motion
from solvers.loops import Leg
from solvers.state import value_at

from .analytic import legs_latex


@dataclass(frozen=True)
class Contour:
    point: str
    legs: tuple[Leg, ...]
    joints: tuple[str, ...]  # the letters the chain passes: the frame's pivot, …, the point


def free_points(scene: Scene) -> list[str]:
    """Points of moving members that are no pair's point: they need a final contour."""
    joints = {p.point for p in scene.pairs} | {p.on_slot for p in scene.pairs if p.on_slot}
    joints |= {p.through for p in scene.pairs if p.through}
    return sorted({name for m in scene.members.values() for name in m.points} - joints
                  - set(scene.frame))


def contour(scene: Scene, point: str) -> Contour | None:
    """The chain of member vectors from the origin to ``point``; None when only a guide
    leads there (a slide would enter the chain: the loops already give that point)."""
    parents: dict[int, tuple[int, str]] = {}
    queue = deque([FRAME])
    while queue:
        member = queue.popleft()
        pairs = sorted((p for p in scene.pairs if p.kind == "revolute" and member in p.members),
                       key=lambda p: DRIVER not in p.members)
        for pair in pairs:
            other = pair.other(member)
            if other != FRAME and other not in parents:
                parents[other] = (member, pair.point)
                queue.append(other)
    owner = next((m for m in parents if point in scene.points_of(m)), None)
    if owner is None:
        return None
    legs, joints, target, member = [], [point], point, owner
    while member != FRAME:
        parent, joint = parents[member]
        local = scene.points_of(member)
        legs.insert(0, Leg(member, local[target] - local[joint]))
        joints.insert(0, joint)
        target, member = joint, parent
    legs.insert(0, Leg(FRAME, scene.frame[target]))
    return Contour(point, tuple(legs), tuple(joints))


def values(motion: Motion, c: Contour, i: int = 0) -> tuple[complex, complex, complex]:
    """r, v, a of the contour's point at position ``i``, summed leg by leg (equations A, B, C)."""
    r = v = a = 0j
    for leg in c.legs:
        if leg.ref == FRAME:
            r += leg.local
            continue
        body = motion.bodies[leg.ref]
        vec = leg.local * cmath.exp(1j * float(value_at(body.theta, i)))
        w, e = float(value_at(body.omega, i)), float(value_at(body.epsilon, i))
        r, v, a = r + vec, v + 1j * w * vec, a + (1j * e - w * w) * vec
    return r, v, a


def latex(motion: Motion, c: Contour, i: int = 0) -> list[str]:
    """Equations A, B and C of the final contour, each followed by its value at position
    ``i`` (on a line of its own: st.latex does not wrap)."""
    r, v, a = values(motion, c, i)
    p = c.point
    symbols = (rf"\vec r_{{{p}}}", rf"\vec v_{{{p}}}", rf"\vec a_{{{p}}}")
    units = ("m", "m/s", "m/s^2")
    lines = []
    for level, (symbol, value, unit) in enumerate(zip(symbols, (r, v, a), units)):
        legs = [leg for leg in c.legs if leg.local != 0]
        lines.append(rf"\text{{{'ABC'[level]}:}}\ {symbol} = {legs_latex(legs, level)}")
        lines.append(rf"{symbol} = ({value.real:.5g};\ {value.imag:.5g})\ \mathrm{{{unit}}},"
                     rf"\quad |{symbol[5:]}| = {abs(value):.5g}\ \mathrm{{{unit}}}")
    return lines
