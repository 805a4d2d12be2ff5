"""The reduced mechanism (Zhukovsky's lever) the book's way (problem collection, tasks 5.3–5.4).

The velocity plan is turned 90°. Every force is moved to the image of its point of action.
A point between lettered ones is found by proportion, because the image of a member is
similar to the member (b⁰k⁰ = b⁰c⁰·BK/BC). Inertia forces act at Huygens' centre K. A couple
becomes two opposite forces. The balancing force F_p acts at the image of the crank pin, at
right angles to the crank. The moments about the pole then give F_p, and M_p = F_p·AB, with
no reaction at all.

``construction`` returns those lines with the numbers at one position of a ``Kinetostatics``.
The plan is at ω₂ (m/s), so each F·h is a power (W). ``latex`` writes them the way the
collection does.
"""

from __future__ import annotations

import cmath
from dataclasses import dataclass

from mechanisms.schema import DRIVER
from solvers.kinetostatics import Kinetostatics, LeverForce, centre_of_mass
from solvers.loops import cross
from solvers.state import value_at

from .force_steps import latex_name, number, wrapped

SAME = 1e-12  # m: a point of action this close to a lettered point is that point


@dataclass(frozen=True)
class Image:
    """Where a force at an unlettered point goes on the lever: how its image is found."""

    force: str  # the force's name
    point: str  # B, S_3, K_3
    base: tuple[str, str]  # the lettered points PQ it is proportioned from
    real: tuple[float, float]  # |PX|, |QX| on the mechanism (m)
    plan: tuple[float, float]  # |p⁰x⁰|, |q⁰x⁰| on the plan (m/s)
    along: bool  # X lies on the line PQ: one proportion is enough
    side: tuple[float, float]  # |PQ| (m) and |p⁰q⁰| (m/s)


@dataclass(frozen=True)
class Moment:
    name: str
    force: float  # |F|, N
    arm: float  # signed lever arm about the pole on the plan at ω₂ (m/s; ccw positive)

    @property
    def value(self) -> float:
        return self.force * self.arm


@dataclass
class Lever:
    images: list[Image]
    moments: list[Moment]
    balancing_arm: float  # h_p of a unit F_p at the crank pin's image (m/s)
    balancing: float  # F_p (N)
    torque: float | None  # M_p = F_p·AB (N·m); None for a linear driver
    crank: str = "AB"  # the crank's letters: pivot, pin


def construction(k: Kinetostatics, index: int = 0) -> Lever:
    """The lever at position ``index``: the forces' images, their moments, F_p and M_p."""
    scene = k.motion.scene
    speed = scene.driver.speed or 1.0  # a standing mechanism: the plan per unit ω₂
    moments, images = [], []
    forces = [complex(value_at(f.force, index)) for f in k.lever]  # names may repeat (G_3)
    plan = max((abs(value_at(f.image, index) * speed) for f in k.lever), default=1.0)
    biggest = max((abs(f) for f in forces), default=0.0)
    for f, force in zip(k.lever, forces):
        if abs(force) <= 1e-12 * biggest:  # none, or round-off (a point at rest)
            continue
        image = complex(value_at(f.image, index)) * speed
        arm = cross(image, force) / abs(force)
        moments.append(Moment(f.name, abs(force), 0.0 if abs(arm) < 1e-12 * plan else arm))
        image_step = _image(k, f, index, speed)
        if image_step is not None:
            images.append(image_step)
    if k.rotating:
        member = scene.members[DRIVER]
        pivot, pin = (member.points[p] for p in member.axis)
        crank = (pin - pivot) * complex(value_at(k.motion.bodies[DRIVER].rot, index))
        # the pin's image is −(B − A)·ω₂ turned 90° twice; F_p is at right angles to AB
        arm = cross(-crank * speed, 1j * crank / abs(crank))
    else:
        pair = scene.pair(scene.driver.pair)
        guide = complex(value_at(k.unit[pair.members[0]].rot, index)) * cmath.exp(1j * pair.angle)
        arm = cross(1j * guide * speed, guide)
    total = sum(m.value for m in moments)
    balancing = -total / arm
    torque = balancing * scene.members[DRIVER].length if k.rotating else None
    letters = "".join(scene.members[DRIVER].axis)
    return Lever(images, moments, arm, balancing, torque, letters)


def _image(k: Kinetostatics, f: LeverForce, index: int, speed: float) -> Image | None:
    """How the image of the force's point is found by proportion from the member's two
    lettered axis points (the member and its image are similar); None for a lettered point,
    whose image the plan has already (or a member with one point)."""
    member = k.motion.scene.members[f.member]
    letter = next((p for p, z in member.points.items() if abs(z - f.local) < SAME), None)
    if letter or len(member.axis) < 2:
        return None
    p, q = member.axis
    body = k.unit[f.member]
    plan = {c: complex(value_at(1j * body.velocity(member.points[c]), index)) * speed for c in (p, q)}
    x = complex(value_at(1j * body.velocity(f.local), index)) * speed
    pq = member.points[q] - member.points[p]
    along = abs(cross(pq, f.local - member.points[p])) < SAME * max(abs(pq), 1.0)
    return Image(f.name, _unlettered(k, f), (p, q),
                 (abs(f.local - member.points[p]), abs(f.local - member.points[q])),
                 (abs(x - plan[p]), abs(x - plan[q])), along,
                 (abs(pq), abs(plan[q] - plan[p])))


def _unlettered(k: Kinetostatics, f: LeverForce) -> str:
    """S_m for the centre of mass, K_m for Huygens' centre, X_m for any other point."""
    if abs(f.local - centre_of_mass(k.motion.scene, f.member)) < SAME:
        return f"S_{f.member}"
    inertia = k.inertia.get(f.member)
    if inertia is not None and inertia.huygens_local is not None \
            and abs(f.local - inertia.huygens_local) < SAME:
        return f"K_{f.member}"
    return f"X_{f.member}"


def latex(lever: Lever, rotating: bool) -> tuple[list[str], list[str]]:
    """(the proportions that place the unlettered points, the moment equation about the pole
    and what it gives)."""
    proportions = []
    for im in lever.images:
        p, q = im.base
        x = latex_name(im.point)
        first = (rf"\overline{{{p.lower()}^0{x.lower()}^0}} = \overline{{{p.lower()}^0{q.lower()}^0}}"
                 rf"\cdot\frac{{{p}{x}}}{{{p}{q}}} = {im.side[1]:.4g}\cdot\frac{{{im.real[0]:.4g}}}"
                 rf"{{{im.side[0]:.4g}}} = {im.plan[0]:.4g}\ \mathrm{{m/s}}")
        proportions.append(first)
        if not im.along:
            proportions.append(
                rf"\overline{{{q.lower()}^0{x.lower()}^0}} = \overline{{{p.lower()}^0{q.lower()}^0}}"
                rf"\cdot\frac{{{q}{x}}}{{{p}{q}}} = {im.plan[1]:.4g}\ \mathrm{{m/s}}")
    symbols = [r"F_p\cdot h_p"] + [rf"{latex_name(m.name)}\cdot h" for m in lever.moments]
    numbers = [rf"F_p\cdot {number(lever.balancing_arm)}"] + [
        rf"{m.force:.4g}\cdot {number(m.arm)}" for m in lever.moments]
    result = rf"F_p = {number(lever.balancing).strip('()')}\ \mathrm{{N}}"
    if rotating and lever.torque is not None:
        result += rf",\quad M_p = F_p\cdot\overline{{{lever.crank}}} = {number(lever.torque).strip('()')}\ \mathrm{{N\cdot m}}"
    return proportions, [wrapped(r"\sum M_P = ", symbols, " = 0"),
                         wrapped("", numbers, r" = 0"), rf"\Rightarrow\; {result}"]
