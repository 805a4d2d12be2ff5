"""Kinematics of a linkage over an array of driver positions: the shared core of every page.

``solve(scene, at)`` solves the driver and then the Assur groups in the order the
structure gives, each over the whole array at once. It computes only what is asked:
``order`` 0 = positions, 1 = + velocities, 2 = + accelerations, and with ``points``
only the groups those points depend on.
"""

from __future__ import annotations

import cmath
import dataclasses
import functools
import math
import weakref
from collections import OrderedDict
from dataclasses import dataclass, field

import numpy as np

from mechanisms.messages import Text
from mechanisms.schema import DRIVER, FRAME, Scene

from .budget import bounded, check
from .loops import build_loop, cross, group_size, solve_dyad
from .state import Body, unit
from .structure import Group, Structure, StructureError, decompose
from .triads import TOL, assemble, prepare_march, solve_triad

# A class III group's assembly and branch-carrying march depend on its geometry (not on the
# driver's position, speed or the requested values inside the marched range) and cost
# ~0.2 s: they are kept for the last few geometries, so moving φ₂ re-solves in milliseconds.
_PREPARED: OrderedDict[tuple, tuple] = OrderedDict()
PREPARED_MAX = 32
# A dyad's branch taken from the drawn positions, per geometry and group (see _drawn_branch)
_BRANCHES: OrderedDict[tuple, int] = OrderedDict()
# What a scene's solve needs before any position (its structure, each dyad's loop on its
# drawn branch, where each point is read, the constants spread over a cycle), kept per scene
# object for as long as the object lives: a page or a benchmark solving one scene again and
# again pays this Python work once (issue 21: it was over half of a 360-position solve).
# Scenes are frozen; a changed one is a new object.
_PLANS: dict[int, dict] = {}
# The crank's e^{iφ₂} for the angle arrays solved lately: a page solves the same cycle
# (its resolution's angles) again for every length, mass or ω₂ a student tries, and the
# trigonometry was a sixth of a 360-position solve (bench/peers.py). Keyed by the angles'
# bytes (1 µs at 360 against 9 µs of cos and sin); the arrays are shared, so read-only.
_TURNS: OrderedDict[tuple, np.ndarray] = OrderedDict()
TURNS_MAX = 16
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
    normal: np.ndarray | None = None  # a circular slot's v²/R towards its centre (complex)


@dataclass
class GroupIssue:
    """Where a group fails to close or is near a dead centre, as driver ranges."""

    group: str
    kind: str
    problem: str  # "open" or "near-singular"
    ranges: list[tuple[float, float]]  # driver values (rad or m), inclusive
    worst_condition: float = math.inf


@dataclass
class NewtonReport:
    """How Newton's method went for a class III group: iterations and the final largest
    constraint violation (m) at each position."""

    iterations: np.ndarray
    residual: np.ndarray


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
    newton: dict[str, NewtonReport] = field(default_factory=dict)  # per class III group
    special: dict[str, PointMotion] = field(default_factory=dict)  # Assur points S, as points
    # of the ternary member (NaN where the two lines are parallel: S at infinity)
    bodies: dict[int, Body] = field(default_factory=dict)  # every solved member's motion: any
    # point of it (a centre of mass, a point of action) follows from its local coordinates

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
        return Body(_turn(at), scene.frame[pair.point], 0j, d.speed, 0j, d.accel, 0j, at)
    direction = cmath.exp(1j * pair.angle)
    theta = pair.lock
    rot = cmath.exp(1j * theta)
    local = scene.members[DRIVER].points[pair.point]
    return Body(rot=rot, z=scene.frame[pair.through] + at * direction, ref=local, omega=0.0,
                v=d.speed * direction, epsilon=0.0, a=d.accel * direction, angle=theta)


def _turn(at: np.ndarray) -> np.ndarray:
    """e^{i·at}, kept for the last TURNS_MAX angle arrays (see _TURNS). The key holds the
    shape and type with the bytes: the same bytes in another shape are other angles."""
    key = (at.shape, at.dtype.char, at.tobytes())
    rot = _TURNS.get(key)
    if rot is None:
        rot = unit(at)
        rot.flags.writeable = False
        _remember(_TURNS, key, rot, TURNS_MAX)
    return rot


def _remember(cache: OrderedDict, key, value, most: int) -> None:
    """``cache[key] = value``; past ``most`` entries the oldest go (pages share this process,
    so every cache of a solve's work is bounded)."""
    cache[key] = value
    while len(cache) > most:
        cache.pop(next(iter(cache)), None)


@bounded
def solve(scene: Scene, at=None, *, order: int = 2, points: list[str] | None = None,
          structure: Structure | None = None, tol: float = TOL) -> Motion:
    """Solve the scene at driver value(s) ``at`` (rad or m; default: the scene's instant).

    ``tol`` is Newton's stopping residual for class III groups, relative to the group's size.
    """
    if not (isinstance(at, np.ndarray) and at.ndim == 1 and at.dtype == float):
        at = np.atleast_1d(np.asarray(scene.driver.at if at is None else at, dtype=float))
    plan = _plan(scene)
    structure = structure or _kept(plan, "structure", lambda: decompose(scene))
    if points is None:
        groups = structure.groups
    else:
        wanted = {m for m, mem in scene.members.items() if set(points) & set(mem.points)}
        groups = structure.groups_for(wanted)
    # open positions are NaN, and masked; at a position where the loop's ends meet (|d| → 0)
    # the closure's intermediate values overflow to inf on the way to the same NaN
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        solved = _Solved(scene, groups, at, order, tol, plan)
        return _collect(scene, structure, groups, at, order, solved, points, plan)


class _Solved:
    """The driver and the groups solved in order, each over the whole array ``at``."""

    def __init__(self, scene: Scene, groups, at: np.ndarray, order: int, tol: float,
                 plan: dict | None = None):
        plan = _plan(scene) if plan is None else plan
        self.bodies: dict[int, Body] = {FRAME: Body.frame(), DRIVER: driver_body(scene, at)}
        self.feasible = np.ones(at.shape, dtype=bool)
        self.somewhere_open = False
        self.transmission: dict[str, np.ndarray] = {}
        self.issues: list[GroupIssue] = []
        self.newton: dict[str, NewtonReport] = {}
        for i, group in enumerate(groups):
            check()
            if group.cls == 2:
                loop = _kept(plan, (group.name, tol), lambda: build_loop(
                    scene, group, _drawn_branch(scene, group, groups[:i], tol)))
                solution = solve_dyad(loop, self.bodies, order)
            else:
                solution = self._triad(scene, group, groups[:i], at, order, tol)
            self._add(group, solution, at)

    def _triad(self, scene, group: Group, before, at, order, tol):
        rate_scene = dataclasses.replace(
            scene, driver=dataclasses.replace(scene.driver, speed=1.0, accel=0.0))

        def known_at(values):  # the members the group hangs on, with rates per unit speed
            return _Solved(rate_scene, before, np.asarray(values, dtype=float), 1, tol).bodies

        size = group_size(scene, group)
        a0 = scene.driver.at if scene.guess_at is None else scene.guess_at
        span = _march_span(scene, at, a0)
        key = (repr(rate_scene.with_(at=0.0)), group.name, a0, span, tol)
        prepared = _PREPARED.get(key)
        if prepared is None:
            start = assemble(scene, group, known_at(np.array([a0])), size)
            if start is None:
                raise StructureError(Text("structure.no_assembly", label=group.label(),
                                          kind=group.kind))
            start = (a0, *start)
            prepared = start, prepare_march(scene, group, np.array(span), start, known_at, size)
            _remember(_PREPARED, key, prepared, PREPARED_MAX)
        start, march = prepared
        solution = solve_triad(scene, group, at, self.bodies, order, start, known_at,
                               tol=tol, size=size, march=march)
        self.newton[group.name] = NewtonReport(solution.iterations, solution.residual)
        return solution

    def _add(self, group: Group, solution, at: np.ndarray) -> None:
        self.bodies.update(solution.bodies)
        if not solution.closed.all():  # (most scenes close over the whole turn)
            opened = ~solution.closed & self.feasible
            if opened.any():
                self.issues.append(GroupIssue(group.name, group.kind, "open", _ranges(at, opened)))
            self.feasible &= solution.closed
            self.somewhere_open = True
        if solution.transmission is not None:
            t = solution.transmission
            if self.somewhere_open or np.shape(t) != at.shape:  # (or a constant: no column turns)
                t = np.where(self.feasible, t, np.nan)
            self.transmission[group.name] = t
            weak = t < NEAR_SINGULAR  # (False where NaN)
            if weak.any():
                self.issues.append(GroupIssue(group.name, group.kind, "near-singular",
                                              _ranges(at, weak), float(1.0 / np.nanmin(t))))


def bodies_before(scene: Scene, groups, at: float, tol: float = TOL) -> dict[int, Body]:
    """The frame, the driver and ``groups`` solved at one driver value: what the next group
    hangs on (solvers.assembly asks it for every way that group can close)."""
    return _Solved(scene, groups, np.array([at]), 0, tol).bodies


def _plan(scene: Scene) -> dict:
    """What is kept for this live scene object (see _PLANS)."""
    plan = _PLANS.get(id(scene))
    if plan is None:
        plan = _PLANS[id(scene)] = {}
        weakref.finalize(scene, _PLANS.pop, id(scene), None)
    return plan


def _kept(plan: dict, key, make):
    """``plan[key]``, made by ``make()`` the first time."""
    value = plan.get(key)
    if value is None:
        value = plan[key] = make()
    return value


def _drawn_branch(scene: Scene, group: Group, before, tol: float) -> int | None:
    """The dyad's assembly closest to the points the scene draws (``[guess]``) at the instant
    they were drawn: a file or a link never needs a ±1 sign. An explicit ``[assembly]`` sign
    wins (old files); a group with no drawn point keeps the default (None)."""
    members = tuple(sorted(group.members))
    drawn = [(m, local, scene.guess[name]) for m in members
             for name, local in scene.members[m].points.items() if name in scene.guess]
    if members in scene.assembly or not drawn or scene.guess_at is None:
        return None
    key = (repr((scene.frame, scene.members, scene.pairs, scene.guess, scene.guess_at,
                 scene.driver.kind)), group.name)
    if key in _BRANCHES:
        return _BRANCHES[key]
    known = _Solved(scene, before, np.array([scene.guess_at]), 0, tol).bodies
    miss = {}
    for sign in (1, -1):
        bodies = solve_dyad(build_loop(scene, group, sign), known, 0).bodies
        miss[sign] = sum(abs(complex(np.ravel(bodies[m].position(local))[0]) - place) ** 2
                         for m, local, place in drawn)
    best = -1 if miss[-1] < miss[1] else 1  # NaN (cannot close as drawn) keeps +1
    _remember(_BRANCHES, key, best, PREPARED_MAX * 8)
    return best


def _march_span(scene: Scene, at: np.ndarray, a0: float) -> tuple[float, float]:
    """The driver range a class III march covers. For a crank: a whole turn each way from
    the sketch's instant, whatever is asked (every angle is reached along the branch, see
    triads._onto_march). For a slider: the requested values and the instant, widened to
    whole multiples of the links' total length, so that values nearby reuse the march.
    Asked only at the sketch's instant itself (a variant checked where it is drawn), there
    is nothing to march over."""
    if np.all(at == a0):
        return a0, a0
    if scene.driver.kind == "rotating":
        return a0 - 2 * math.pi, a0 + 2 * math.pi
    lo, hi = float(np.min(at)), float(np.max(at))
    unit, origin = sum(scene.lengths.values()) or 1.0, a0
    lo = origin + unit * math.floor((lo - origin) / unit + 1e-12)
    hi = origin + unit * math.ceil((hi - origin) / unit - 1e-12)
    return min(lo, a0), max(hi, a0)


def special_pairs(scene: Scene, groups) -> dict[str, tuple[Group, int, int]]:
    """Each special point's name with its class III group and the two binary members whose
    lines meet there: the scene's ``[special]``, else ``S`` (``S2`` …) for the first two
    binary members of every class III group the scene names none for."""
    wanted = dict(scene.special)
    for group in groups:
        if group.cls == 3 and not any(set(p) <= set(group.members) for p in wanted.values()):
            name = "S" if "S" not in wanted else f"S{len(wanted) + 1}"
            wanted[name] = tuple(group.members[1:3])
    out = {}
    for name, (b1, b2) in wanted.items():
        group = next((g for g in groups if g.cls == 3 and {b1, b2} <= set(g.members[1:])), None)
        if group is not None:
            out[name] = (group, b1, b2)
    return out


def _special_points(scene: Scene, structure: Structure, groups, bodies: dict[int, Body],
                    order: int, plan: dict) -> dict:
    """The special points S as points of their group's ternary member."""
    out = {}
    key = "special" if groups is structure.groups else ("special", *(g.name for g in groups))
    pairs = _kept(plan, key, lambda: special_pairs(scene, groups))
    for name, (group, b1, b2) in pairs.items():
        z = special_point(scene, group, bodies, b1, b2)
        centre = bodies[group.members[0]]
        local = (z - centre.z) / centre.rot + centre.ref
        out[name] = PointMotion(z, centre.velocity(local) if order >= 1 else None,
                                centre.acceleration(local) if order >= 2 else None)
    return out


def binary_line(scene: Scene, group: Group, member: int, bodies: dict[int, Body]):
    """The line of a binary member of a triad: through its joint with the ternary member,
    toward its other joint — or, for a slider on a guide, normal to the guide. Along this
    line the member's joint moves, relative to the known member, at right angles.
    Returns (point, direction), or None when the member's own joint slides."""
    centre = group.members[0]
    inner = next(p for p in group.pairs if set(p.members) == {member, centre})
    outer = next(p for p in group.pairs if member in p.members and p is not inner)
    if inner.kind != "revolute":
        return None
    body = bodies[member]
    joint = body.position(scene.points_of(member)[inner.point])
    if outer.kind == "revolute":
        return joint, body.position(scene.points_of(member)[outer.point]) - joint
    guide = bodies[outer.members[0]]
    return joint, 1j * cmath.exp(1j * outer.angle) * guide.rot


def special_point(scene: Scene, group: Group, bodies: dict[int, Body], b1: int, b2: int):
    """Where the lines of binary members b1 and b2 meet (NaN where they are parallel)."""
    l1, l2 = binary_line(scene, group, b1, bodies), binary_line(scene, group, b2, bodies)
    if l1 is None or l2 is None:
        return np.full(np.shape(bodies[group.members[0]].z), np.nan + 0j)
    (p, d), (q, e) = l1, l2
    det = cross(d, e)
    parallel = np.abs(det) <= 1e-9 * np.abs(d) * np.abs(e)
    return p + cross(q - p, e) / np.where(parallel, np.nan, det) * d


def _collect(scene, structure, groups, at, order, solved: _Solved, wanted, plan) -> Motion:
    shape, bodies = at.shape, solved.bodies
    filled = _kept(plan, ("constants", shape), dict)

    def n(value):  # constants (the frame, a constant ω₂) as read-only arrays over the cycle
        if isinstance(value, np.ndarray):
            if value.shape == shape:
                return value
            value = value.item()  # a constant kept as a 0-d array
        key = (type(value), value)  # (0.0 == 0j, but they fill different arrays)
        out = filled.get(key)
        if out is None:  # filled once per live scene and shape (np.broadcast_to costs more)
            out = filled[key] = np.full(shape, value)
            out.flags.writeable = False
        return out

    def asked(value, level: int):  # a rate only when the order asks for it
        return n(value) if order >= level else None

    point_motion: dict[str, PointMotion] = {}
    # (the members solved follow from the scene and the points asked for)
    readers = _kept(plan, ("readers", None if wanted is None else tuple(wanted)),
                    lambda: _readers(scene, bodies, wanted))
    for name, member, local in readers:
        z, v, a = bodies[member].point(local, order)
        point_motion[name] = PointMotion(n(z), asked(v, 1), asked(a, 2))
    member_motion = {m: MemberMotion(n(b.rot), asked(b.omega, 1), asked(b.epsilon, 2))
                     for m, b in bodies.items() if m != FRAME}
    member_motion[DRIVER].angle = n(bodies[DRIVER].theta)  # φ₂ exactly as given
    sliding = _kept(plan, "sliding", lambda: [p for p in scene.pairs
                                              if p.kind == "prismatic" or p.on_slot])
    sliders = {p.name: (_arc if p.on_slot else _slider)(scene, p, bodies, order, n)
               for p in sliding if p.members[0] in bodies and p.members[1] in bodies}
    return Motion(scene, structure, at, order, point_motion, member_motion, sliders,
                  solved.feasible, solved.transmission, solved.issues, solved.newton,
                  _special_points(scene, structure, groups, bodies, order, plan), bodies)


def _readers(scene: Scene, bodies: dict[int, Body], wanted) -> list[tuple[str, int, complex]]:
    """Where each point is read: (name, member, point in its frame). A frame point is the
    frame's, exactly; any other is read at a member whose reference point it is (the solve
    left its motion in the body) before one it would have to be computed from. Which point
    is a member's reference depends only on the scene and the groups solved, so this is
    worked out once per both."""
    def rank(number: int, local: complex) -> int:  # lower is read first
        return 0 if number == FRAME else 1 if local == bodies[number].ref else 2

    chosen: dict[str, tuple[int, complex]] = {}
    for number in [FRAME, *scene.members]:
        if number not in bodies:
            continue
        for name, local in scene.points_of(number).items():
            if wanted is None or name in wanted:
                if name not in chosen or rank(number, local) < rank(*chosen[name]):
                    chosen[name] = (number, local)
    return [(name, number, local) for name, (number, local) in chosen.items()]


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


def _arc(scene: Scene, pair, bodies: dict[int, Body], order: int, n) -> SliderMotion:
    """A block in a circular slot: s is the arc from the guide's x-direction through the
    centre to the block's point (m), v and a its rates along the arc (the block turns
    about the centre relative to the guide), with the normal part v²/R of the relative
    acceleration and the Coriolis part 2·ω_guide × v_rel."""
    guide, slider = bodies[pair.members[0]], bodies[pair.members[1]]
    local = scene.points_of(pair.members[1])
    radial = slider.position(local[pair.on_slot]) - slider.position(local[pair.point])
    radius = abs(local[pair.on_slot] - local[pair.point])
    s = n(radius * np.angle(radial / guide.rot))
    if order < 1:
        return SliderMotion(s)
    v = n(radius * (slider.omega - guide.omega))
    if order < 2:
        return SliderMotion(s, v)
    tangent = 1j * radial / radius
    return SliderMotion(s, v, n(radius * (slider.epsilon - guide.epsilon)),
                        n(2j * guide.omega * v * tangent), n(-v ** 2 / radius * radial / radius))


def _ranges(at: np.ndarray, mask: np.ndarray) -> list[tuple[float, float]]:
    """Contiguous runs of ``mask`` as (first, last) driver values."""
    idx = np.flatnonzero(mask)
    if idx.size == 0:
        return []
    breaks = np.flatnonzero(np.diff(idx) > 1)
    starts = [idx[0], *idx[breaks + 1]]
    ends = [*idx[breaks], idx[-1]]
    return [(float(at[a]), float(at[b])) for a, b in zip(starts, ends)]


