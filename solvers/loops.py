"""Class II Assur groups (dyads) as vector loops, solved the way the complex-number method does.

A dyad (members j, k; pairs outer_j, inner, outer_k) is walked as a closed vector loop
from a known point on the member it hangs on, through j and k, to a known point on the
other member it hangs on. Each leg is a vector fixed in a member (turning with it) or a
slide along a guide (length s, the pair's relative displacement). Every dyad kind then
has exactly two unknowns among the angles and the slides:

* RRR — two angles: circle–circle intersection;
* RRP, RPR — one angle and one slide: a quadratic in the slide;
* PRP, RPP — two slides: a 2×2 linear system.

Differentiating the loop once and twice ("equations B and C" of the complex-number
method) gives the same 2×2 matrix for the unknown rates (ω or ṡ) and for the unknown
accelerations (ε or s̈); the Coriolis term 2·ṡ·ω appears by itself. Everything is
vectorised over the cycle; no Python loop runs over positions.
"""

from __future__ import annotations

import cmath
import functools
from dataclasses import dataclass

import numpy as np

from mechanisms.messages import Text
from mechanisms.schema import Pair, Scene

from .state import Body, cplx
from .structure import Group, StructureError


@dataclass(frozen=True)
class Leg:
    """A loop vector ``local·e^{iθ_ref}`` (times the slide s if ``slide`` is set).

    ``ref`` is the member whose angle turns the leg: a free dyad member (unknown angle)
    or an already known member; offsets of locked angles are folded into ``local``.
    """

    ref: int
    local: complex
    slide: str | None = None


@dataclass(frozen=True)
class Visit:
    """The loop reaches point ``local`` of dyad ``member``: this places the member."""

    member: int
    local: complex


@dataclass(frozen=True)
class DyadLoop:
    group: Group
    start: tuple[int, complex]  # (known member, point in its frame)
    steps: tuple[Leg | Visit, ...]
    end: tuple[int, complex]
    angle_of: dict[int, tuple[int, float]]  # dyad member -> (ref member, angle offset)
    free: tuple[int, ...]  # dyad members whose angle is unknown
    slides: tuple[str, ...]  # prismatic pairs whose slide is unknown
    branch: int
    size: float  # the group's own length scale, to compare angle and slide columns

    @property
    def unknowns(self) -> tuple:
        return self.free + self.slides

    # What every solve of the loop reads, worked out once per loop (solves at 360 positions
    # take tens of microseconds, so walking the steps each time was a fair part of them)
    @functools.cached_property
    def legs(self) -> tuple[Leg, ...]:
        return tuple(st for st in self.steps if isinstance(st, Leg))

    @functools.cached_property
    def free_sums(self) -> dict[int, complex]:
        """Each free member's fixed legs added up: its A in Σ A_m·e^{iθ_m} + … = D."""
        sums = dict.fromkeys(self.free, 0j)
        for leg in self.legs:
            if leg.ref in sums and not leg.slide:
                sums[leg.ref] += leg.local
        return sums

    @functools.cached_property
    def triangle(self) -> tuple[int, int, complex, complex, float, float]:
        """An RRR loop's free members, their sums A₁, A₂, then |A₁|² and (|A₁|² − |A₂|²)/2."""
        (m1, a1), (m2, a2) = self.free_sums.items()
        return m1, m2, a1, a2, abs(a1) ** 2, 0.5 * (abs(a1) ** 2 - abs(a2) ** 2)

    @functools.cached_property
    def known_legs(self) -> tuple[Leg, ...]:
        """The fixed legs on members already known: they move D, the loop's closing vector."""
        return tuple(leg for leg in self.legs if leg.ref not in self.free_sums and not leg.slide)

    @functools.cached_property
    def slide_legs(self) -> tuple[Leg, ...]:
        """The legs along a guide, one per prismatic pair: s times a direction."""
        return tuple(leg for leg in self.legs if leg.slide)

    @functools.cached_property
    def visits(self) -> tuple[tuple[int, complex, int], ...]:
        """(member, point, legs walked before it) where the loop first reaches each member."""
        out, walked, seen = [], 0, set()
        for st in self.steps:
            if isinstance(st, Leg):
                walked += 1
            elif st.member not in seen:
                seen.add(st.member)
                out.append((st.member, st.local, walked))
        return tuple(out)


def build_loop(scene: Scene, group: Group, branch: int | None = None) -> DyadLoop:
    """Lay the vector loop of a class II group (independent of the cycle) on ``branch``
    (±1; default: the scene's ``[assembly]`` sign for the group, else 1)."""
    if group.cls != 2:
        raise StructureError(Text("structure.unsupported", cls=group.cls, label=group.label(),
                                  kind=group.kind))
    j, _ = group.members
    outer_j = group.pairs[0]
    body = outer_j.other(j)
    at = scene.points_of(body)[_anchor(outer_j, body)]
    start = (body, at)
    raw: list = []
    for pair in group.pairs:
        more, body, at = _cross(scene, pair, body, at)
        raw += more
    free, angle_of = _angle_relations(group)
    steps = []
    for st in raw:
        if isinstance(st, Visit):
            if st.member in group.members:
                steps.append(st)
            continue
        ref, off = angle_of.get(st.member, (st.member, 0.0))
        steps.append(Leg(ref, st.local * cmath.exp(1j * off), st.slide))
    slides = tuple(p.name for p in group.pairs if p.kind == "prismatic")
    if branch is None:
        branch = scene.assembly.get(tuple(sorted(group.members)), 1)
    return DyadLoop(group, start, tuple(steps), (body, at), angle_of, free, slides, branch,
                    group_size(scene, group))


def group_size(scene: Scene, group: Group) -> float:
    """The group's members' extent, or else the scene's (sliders alone have no length)."""
    own = [abs(c) for m in group.members for c in scene.members[m].points.values()]
    if max(own) > 0:
        return max(own)
    first = next(iter(scene.frame.values()))
    spans = [abs(z - first) for z in scene.frame.values()]
    spans += [abs(c) for m in scene.members.values() for c in m.points.values()]
    return max(spans) or 1.0


@dataclass(frozen=True)
class _RawLeg:
    member: int
    local: complex
    slide: str | None = None


def _anchor(pair: Pair, member: int) -> str:
    """The point of ``member`` at which ``pair`` acts."""
    if pair.kind == "prismatic" and member == pair.members[0]:
        return pair.through
    return pair.point


def _cross(scene: Scene, pair: Pair, member: int, at: complex) -> tuple[list, int, complex]:
    """Legs that carry the loop from point ``at`` of ``member`` across ``pair``."""
    nxt = pair.other(member)
    here = scene.points_of(member)
    if pair.kind == "revolute":
        legs = [_RawLeg(member, here[pair.point] - at)]
    elif member == pair.members[0]:  # guide → slider: along the guide by +s
        legs = [_RawLeg(member, here[pair.through] - at),
                _RawLeg(member, cmath.exp(1j * pair.angle), pair.name)]
    else:  # slider → guide: back along the guide by −s
        legs = [_RawLeg(member, here[pair.point] - at),
                _RawLeg(nxt, -cmath.exp(1j * pair.angle), pair.name)]
    arrive = scene.points_of(nxt)[_anchor(pair, nxt)]
    return [g for g in legs if g.slide or g.local != 0] + [Visit(nxt, arrive)], nxt, arrive


def _angle_relations(group: Group) -> tuple[tuple[int, ...], dict[int, tuple[int, float]]]:
    """Which dyad members have unknown angles, and how the locked ones follow."""
    j, k = group.members
    outer_j, inner, outer_k = group.pairs

    def lock(pair: Pair, member: int) -> float:
        return pair.lock if member == pair.members[1] else -pair.lock

    angle_of: dict[int, tuple[int, float]] = {}
    for pair, m in ((outer_j, j), (outer_k, k)):
        if pair.kind == "prismatic":
            angle_of[m] = (pair.other(m), lock(pair, m))
    if inner.kind == "prismatic":
        for a, b in ((j, k), (k, j)):
            if a in angle_of and b not in angle_of:
                ref, off = angle_of[a]
                angle_of[b] = (ref, off + lock(inner, b))
        if j not in angle_of:  # neither is locked: the guide's angle is the unknown, as the
            guide, slider = inner.members  # complex-number method writes it (φ₄ of a slotted lever)
            angle_of[slider] = (guide, lock(inner, slider))
    free = tuple(m for m in (j, k) if m not in angle_of)
    for m in free:
        angle_of[m] = (m, 0.0)
    return free, angle_of


def cross(a, b):
    """z-component of the cross product of plane vectors given as complex numbers."""
    return a.real * b.imag - a.imag * b.real


@dataclass
class DyadSolution:
    bodies: dict[int, Body]
    transmission: np.ndarray | None  # how far from a dead centre: 0 = singular, ~1 = well off
    closed: np.ndarray  # where the loop closes


def solve_dyad(loop: DyadLoop, known: dict[int, Body], order: int) -> DyadSolution:
    """Positions (and velocities, accelerations up to ``order``) of one dyad over the cycle.

    Where the loop cannot close the results are NaN and ``closed`` is False; call under
    ``np.errstate(invalid="ignore", divide="ignore", over="ignore")`` as ``kinematics.solve``
    does.
    """
    b_start, c_start = known[loop.start[0]], loop.start[1]
    b_end, c_end = known[loop.end[0]], loop.end[1]
    legs = loop.legs

    # positions: Σ_free A_m·e^{iθ_m} + Σ s·(direction) = D
    start = b_start.position(c_start)
    d = b_end.position(c_end) - start
    for leg in loop.known_legs:
        d = d - leg.local * known[leg.ref].rot
    slide_dir: dict[str, tuple[int | None, object]] = {
        leg.slide: (leg.ref, leg.local) if leg.ref in loop.free_sums
        else (None, leg.local * known[leg.ref].rot) for leg in loop.slide_legs}
    rots, s, closed = _close(loop, slide_dir, d)

    refs = {m: Body(rot=r) for m, r in rots.items()}
    ref_of = {**known, **refs}
    units = [leg.local * ref_of[leg.ref].rot for leg in legs]
    values = [u * s[leg.slide] if leg.slide else u for leg, u in zip(legs, units)] if s else units
    bodies = {m: refs[m] if ref == m else _follow(ref_of[ref], off)
              for m, (ref, off) in loop.angle_of.items()}
    _place(loop, bodies, start, values, "z")
    if order < 1:
        return DyadSolution(bodies, None, closed)

    # velocities — equation B: the unknown rates multiply two fixed columns
    columns = [_sum(1j * v for leg, v in zip(legs, values) if leg.ref == m) for m in loop.free]
    columns += [next(u for leg, u in zip(legs, units) if leg.slide == name) for name in loop.slides]
    c1, c2 = columns
    det = cross(c1, c2)
    # |det| with every angle column measured against the group's size: about the sine of the
    # transmission angle for two links, and s/size when a slider runs into its guide's pivot
    transmission = np.abs(det) / loop.size ** len(loop.free)
    rhs = b_end.velocity(c_end) - b_start.velocity(c_start)
    for leg, v in zip(legs, values):
        if leg.ref not in loop.free_sums:
            rhs = rhs - 1j * known[leg.ref].omega * v
    rate = _solve2(loop, c1, c2, det, rhs)
    for m in loop.free:
        refs[m].omega = rate[m]
    sdot = {name: rate[name] for name in loop.slides}
    turn = [1j * ref_of[leg.ref].omega * v for leg, v in zip(legs, values)]
    dvalues = [t + sdot[leg.slide] * u if leg.slide else t for leg, u, t in zip(legs, units, turn)]
    for m, (ref, _) in loop.angle_of.items():
        bodies[m].omega = ref_of[ref].omega
    _place(loop, bodies, b_start.velocity(c_start), dvalues, "v")
    if order < 2:
        return DyadSolution(bodies, transmission, closed)

    # accelerations — equation C, with the Coriolis term 2·ṡ·ω for every slide
    rhs = b_end.acceleration(c_end) - b_start.acceleration(c_start)
    for leg, u, v, t in zip(legs, units, values, turn):
        w = ref_of[leg.ref].omega
        known_part = 1j * w * t  # −ω²·L
        if leg.slide:
            known_part = known_part + 2 * sdot[leg.slide] * (1j * w * u)
        if leg.ref not in loop.free_sums:
            known_part = known_part + 1j * known[leg.ref].epsilon * v
        rhs = rhs - known_part
    acc = _solve2(loop, c1, c2, det, rhs)
    for m in loop.free:
        refs[m].epsilon = acc[m]
    ddvalues = []
    for leg, u, v, t in zip(legs, units, values, turn):
        r = ref_of[leg.ref]
        a = 1j * r.epsilon * v + 1j * r.omega * t
        if leg.slide:
            a = a + (acc[leg.slide] + 2j * sdot[leg.slide] * r.omega) * u
        ddvalues.append(a)
    for m, (ref, _) in loop.angle_of.items():
        bodies[m].epsilon = ref_of[ref].epsilon
    _place(loop, bodies, b_start.acceleration(c_start), ddvalues, "a")
    return DyadSolution(bodies, transmission, closed)


def _sum(terms):
    total = 0j
    for t in terms:
        total = total + t
    return total


def _solve2(loop: DyadLoop, c1, c2, det, rhs) -> dict:
    """Cramer's rule for x₁·c₁ + x₂·c₂ = rhs (complex columns = two real equations)."""
    inv = 1.0 / det
    return dict(zip(loop.unknowns, (cross(rhs, c2) * inv, cross(c1, rhs) * inv)))


def _follow(ref: Body, offset: float) -> Body:
    """A member whose angle is ``ref``'s angle plus a constant offset."""
    return Body(rot=ref.rot * cmath.exp(1j * offset) if offset else ref.rot)


def _place(loop: DyadLoop, bodies: dict[int, Body], start, increments: list, field: str) -> None:
    """Walk the loop summing leg values (or their rates); the point where a member is first
    visited becomes its reference point, with that position, velocity or acceleration."""
    total, walked = start, 0
    for member, local, k in loop.visits:
        for step in increments[walked:k]:
            total = total + step
        walked = k
        bodies[member].ref = local
        setattr(bodies[member], field, total)


def _close(loop: DyadLoop, slide_dir: dict, d) -> tuple[dict, dict, np.ndarray]:
    """Closed-form position of the loop: e^{iθ} of the free members, the slides, and
    where the loop closes (elsewhere the values are NaN)."""
    sign = loop.branch
    if len(loop.free) == 2:  # RRR: |A₁|, |A₂| and the distance |D| make a triangle
        m1, m2, a1, a2, r1r1, half = loop.triangle
        # A₁·e^{iθ₁} = D·(k ± i·m): k = x/|D| along D and m = h/|D| across it, in real
        # arithmetic on |D|² (fewer whole-array steps than through |D|)
        inv = 1.0 / (d * d.conj()).real
        k = 0.5 + half * inv
        reach = r1r1 * inv  # (r₁/|D|)²
        m = _root(reach - k * k, reach)
        u1 = d * cplx(k, m if sign > 0 else -m)
        return {m1: u1 * (1 / a1), m2: (d - u1) * (1 / a2)}, {}, np.isfinite(m)
    if len(loop.free) == 1:
        (m, a), = loop.free_sums.items()
        (name, (ref, direction)), = slide_dir.items()
        if ref is None:  # RRP: e^{iθ}·A + s·E = D, E known
            p = (d * np.conj(direction)).real
            s = p + sign * _root(p * p - np.abs(d) ** 2 + abs(a) ** 2, abs(a) ** 2)
            return {m: (d - s * direction) * (1 / a)}, {name: s}, np.isfinite(s)
        # RPR: e^{iθ}·(A + s·B) = D
        p = (a * np.conj(direction)).real
        s = -p + sign * _root(p * p - abs(a) ** 2 + np.abs(d) ** 2, np.abs(d) ** 2)
        return {m: d / (a + s * direction)}, {name: s}, np.isfinite(s)
    (n1, (_, e1)), (n2, (_, e2)) = slide_dir.items()  # PRP, RPP: s₁·E₁ + s₂·E₂ = D
    det = cross(e1, e2)
    det = np.where(np.abs(det) < 1e-12, np.nan, det)
    s1 = cross(d, e2) / det
    return {}, {n1: s1, n2: cross(e1, d) / det}, np.isfinite(s1)


def _root(disc, scale):
    """√disc, taking a round-off negative at an exact limit position as zero (not open)."""
    if np.asarray(disc).min() < 0:  # NaN (an open position already) compares False
        disc = np.where((disc < 0) & (disc > -1e-12 * scale), 0.0, disc)
    return np.sqrt(disc)
