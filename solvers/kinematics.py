"""Kinematics of a linkage over an array of driver positions: the shared core of every page.

``solve(scene, at)`` solves the driver and then the Assur groups in the order the
structure gives, each over the whole array at once. It computes only what is asked:
``order`` 0 = positions, 1 = + velocities, 2 = + accelerations, and with ``points``
only the groups those points depend on.
"""

from __future__ import annotations

import cmath
import functools
import math
from dataclasses import dataclass, field

import numpy as np

from mechanisms.schema import DRIVER, FRAME, Scene

from .loops import build_loop, solve_dyad
from .state import Body, unit
from .structure import Structure, decompose

NEAR_SINGULAR = 1e-3  # |sin| of the angle between a group's unknown directions
SINGULAR = 1e-9


@dataclass
class PointMotion:
    """A point over the cycle; x, y in m, velocities in m/s, accelerations in m/s²."""

    z: np.ndarray
    v: np.ndarray | None = None
    a: np.ndarray | None = None

    x = property(lambda self: self.z.real)
    y = property(lambda self: self.z.imag)
    vx = property(lambda self: self.v.real)
    vy = property(lambda self: self.v.imag)
    ax = property(lambda self: self.a.real)
    ay = property(lambda self: self.a.imag)


@dataclass
class MemberMotion:
    """A member's rotation e^{iθ}, angle θ (rad, from +x, counter-clockwise; computed when
    first read), ω (rad/s) and ε (rad/s²)."""

    rot: np.ndarray
    omega: np.ndarray | None = None
    epsilon: np.ndarray | None = None

    @functools.cached_property
    def angle(self) -> np.ndarray:
        return np.angle(self.rot)


@dataclass
class SliderMotion:
    """A prismatic pair: the slider point's displacement s along the guide from the guide's
    point ``through`` (m), its rate v (m/s) and a (m/s²), and the Coriolis acceleration
    2·ω_guide × v_rel (complex, m/s²)."""

    s: np.ndarray
    v: np.ndarray | None = None
    a: np.ndarray | None = None
    coriolis: np.ndarray | None = None


@dataclass
class GroupIssue:
    """Where a group fails to close or is near a dead centre, as driver ranges."""

    group: str
    kind: str
    problem: str  # "open" or "near-singular"
    ranges: list[tuple[float, float]]  # driver values (rad or m), inclusive
    worst_condition: float = math.inf


@dataclass
class Motion:
    scene: Scene
    structure: Structure
    at: np.ndarray  # driver coordinate: φ₂ in rad, or s in m
    order: int
    points: dict[str, PointMotion]
    members: dict[int, MemberMotion]
    sliders: dict[str, SliderMotion]
    feasible: np.ndarray  # False where some solved group cannot close
    transmission: dict[str, np.ndarray] = field(default_factory=dict)
    issues: list[GroupIssue] = field(default_factory=list)

    @property
    def condition(self) -> np.ndarray:
        """Worst condition number (1/transmission) over the solved groups at each position:
        1 is a well-placed group, 10³ and above is near a dead centre."""
        if not self.transmission:
            return np.ones_like(self.at)
        worst = np.min(np.vstack(list(self.transmission.values())), axis=0)
        with np.errstate(divide="ignore"):
            return 1.0 / worst


def driver_body(scene: Scene, at: np.ndarray) -> Body:
    d = scene.driver
    pair = scene.pair(d.pair)
    if d.kind == "rotating":
        return Body(rot=unit(at), z=scene.frame[pair.point], ref=0j, omega=d.speed, v=0j,
                    epsilon=d.accel, a=0j, angle=at)
    direction = cmath.exp(1j * pair.angle)
    theta = pair.lock
    rot = cmath.exp(1j * theta)
    local = scene.members[DRIVER].points[pair.point]
    return Body(rot=rot, z=scene.frame[pair.through] + at * direction, ref=local, omega=0.0,
                v=d.speed * direction, epsilon=0.0, a=d.accel * direction, angle=theta)


def solve(scene: Scene, at=None, *, order: int = 2, points: list[str] | None = None,
          structure: Structure | None = None) -> Motion:
    """Solve the scene at driver value(s) ``at`` (rad or m; default: the scene's instant)."""
    at = np.atleast_1d(np.asarray(scene.driver.at if at is None else at, dtype=float))
    structure = structure or decompose(scene)
    if points is None:
        groups = structure.groups
    else:
        wanted = {m for m, mem in scene.members.items() if set(points) & set(mem.points)}
        groups = structure.groups_for(wanted)
    with np.errstate(invalid="ignore", divide="ignore"):  # open positions are NaN, and masked
        return _solve_groups(scene, structure, groups, at, order, points)


def _solve_groups(scene, structure, groups, at, order, points) -> Motion:
    bodies: dict[int, Body] = {FRAME: Body.frame(), DRIVER: driver_body(scene, at)}
    feasible = np.ones(at.shape, dtype=bool)
    transmission, issues = {}, []
    for group in groups:
        solution = solve_dyad(build_loop(scene, group), bodies, order)
        bodies.update(solution.bodies)
        opened = ~solution.closed & feasible
        if opened.any():
            issues.append(GroupIssue(group.name, group.kind, "open", _ranges(at, opened)))
        feasible &= solution.closed
        if solution.transmission is not None:
            t = np.where(feasible, solution.transmission, np.nan)
            transmission[group.name] = t
            weak = feasible & (t < NEAR_SINGULAR)
            if weak.any():
                issues.append(GroupIssue(group.name, group.kind, "near-singular",
                                         _ranges(at, weak), float(1.0 / np.nanmin(t))))
    return _collect(scene, structure, at, order, bodies, feasible, transmission, issues, points)


def _collect(scene, structure, at, order, bodies, feasible, transmission, issues, wanted) -> Motion:
    def n(value):  # constants (the frame, a constant ω₂) as read-only arrays over the cycle
        return value if np.shape(value) == at.shape else np.broadcast_to(value, at.shape)

    point_motion: dict[str, PointMotion] = {}
    for number in [FRAME, *scene.members]:
        if number not in bodies:
            continue
        b = bodies[number]
        for name, local in scene.points_of(number).items():
            if name in point_motion or (wanted is not None and name not in wanted):
                continue
            point_motion[name] = PointMotion(
                z=n(b.position(local)),
                v=n(b.velocity(local)) if order >= 1 else None,
                a=n(b.acceleration(local)) if order >= 2 else None)
    member_motion = {
        m: MemberMotion(n(b.rot), n(b.omega) if order >= 1 else None,
                        n(b.epsilon) if order >= 2 else None)
        for m, b in bodies.items() if m != FRAME}
    member_motion[DRIVER].angle = n(bodies[DRIVER].theta)  # φ₂ exactly as given
    sliders = {p.name: _slider(scene, p, bodies, order, n) for p in scene.pairs
               if p.kind == "prismatic" and p.members[0] in bodies and p.members[1] in bodies}
    return Motion(scene, structure, at, order, point_motion, member_motion, sliders, feasible,
                  transmission, issues)


def _slider(scene: Scene, pair, bodies: dict[int, Body], order: int, n) -> SliderMotion:
    """Relative motion of a prismatic pair, read from the two members' motions."""
    guide, slider = bodies[pair.members[0]], bodies[pair.members[1]]
    scene_local_t = scene.points_of(pair.members[0])[pair.through]
    scene_local_p = scene.points_of(pair.members[1])[pair.point]
    direction = cmath.exp(1j * pair.angle) * guide.rot
    z_slider = slider.position(scene_local_p)
    s = n((np.conj(direction) * (z_slider - guide.position(scene_local_t))).real)
    if order < 1:
        return SliderMotion(s)
    # the guide's coincident point (B₄ in the method of extension) sits under the slider
    local_on_guide = guide.ref + (z_slider - guide.z) / guide.rot
    v_rel = slider.velocity(scene_local_p) - guide.velocity(local_on_guide)
    v = n((np.conj(direction) * v_rel).real)
    if order < 2:
        return SliderMotion(s, v)
    coriolis = n(2j * guide.omega * v * direction)
    a_rel = slider.acceleration(scene_local_p) - guide.acceleration(local_on_guide) - coriolis
    return SliderMotion(s, v, n((np.conj(direction) * a_rel).real), coriolis)


def _ranges(at: np.ndarray, mask: np.ndarray) -> list[tuple[float, float]]:
    """Contiguous runs of ``mask`` as (first, last) driver values."""
    idx = np.flatnonzero(mask)
    if idx.size == 0:
        return []
    breaks = np.flatnonzero(np.diff(idx) > 1)
    starts = [idx[0], *idx[breaks + 1]]
    ends = [*idx[breaks], idx[-1]]
    return [(float(at[a]), float(at[b])) for a, b in zip(starts, ends)]


