"""The velocity and acceleration plans of chapters 2–3, built from the exact solution.

A student draws a plan by walking the mechanism the way it is built: the driver first,
then each Assur group, where two vector equations meet at the group's inner point
(``v⃗_C = v⃗_B + v⃗_CB = v⃗_D + v⃗_CD``), and last every third point of a member by
similarity. This module lays out the same walk as data — the equations, and for each
term the arrow it draws on the plan — taking every vector's value from the solver's
exact motion, so the drawn plan closes to solver precision.

Images are labelled like the book: the image of point C is ``c``; the coincident point
of member 4 under a slider at B (method of extension) is ``B4`` with image ``b4``;
construction points of the acceleration plan are ``n1, n2, …`` (between a normal and a
tangential component) and ``k1, k2, …`` (after a Coriolis component). The pole is ``p``.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from mechanisms.messages import Text
from mechanisms.schema import DRIVER, FRAME, Pair, Scene
from solvers.kinematics import Motion, special_pairs
from solvers.structure import Group, StructureError

POLE = "p"


@dataclass(frozen=True)
class Arrow:
    """One vector of a plan, from image ``tail`` to image ``head`` (m/s or m/s²).

    ``symbol`` is its LaTeX name (``v_{CB}``, ``a^n_{CB}``); ``rule`` is what the student
    knows about its direction before drawing (a token and the points it refers to).
    """

    kind: str
    tail: str
    head: str
    value: complex
    symbol: str
    rule: tuple[str, ...]
    member: int = 0  # the member a relative, normal or tangential part turns with
    lever: float = 0.0  # |XY| in m for those parts (ω = v_XY/|XY|, ε = a^t_XY/|XY|)


@dataclass(frozen=True)
class Step:
    """One vector equation of the construction: each side runs from a known image to
    ``target``; a group's step has two sides that meet there."""

    target: str
    sides: tuple[tuple[str, tuple[Arrow, ...]], ...]  # (start image, arrows)
    latex: str
    group: str  # "driver", a group label such as "II(3,4)", or "similarity"


@dataclass
class Plan:
    quantity: str  # "velocity" or "acceleration"
    images: dict[str, complex]  # image label → vector from the pole
    steps: list[Step] = field(default_factory=list)

    @property
    def arrows(self) -> list[Arrow]:
        return [a for st in self.steps for _, side in st.sides for a in side]

    def closure(self) -> float:
        """Largest mismatch between a side's sum and its target image (should be ~0)."""
        worst = 0.0
        for st in self.steps:
            for start, side in st.sides:
                total = self.images[start] + sum(a.value for a in side)
                worst = max(worst, abs(total - self.images[st.target]))
        return worst


@dataclass(frozen=True)
class Station:
    """A point as the plan uses it: the point ``letter`` carried by ``member``."""

    member: int
    letter: str
    coincident: bool = False  # the guide's point under a slider (B₄)

    @property
    def name(self) -> str:
        return f"{self.letter}{self.member}" if self.coincident else self.letter

    @property
    def image(self) -> str:
        return self.name.lower()

    @property
    def tex(self) -> str:
        return f"{self.letter}_{{{self.member}}}" if self.coincident else self.letter


@dataclass
class Plans:
    velocity: Plan
    acceleration: Plan
    positions: dict[str, complex]  # mechanism position of every station, m
    members: dict[int, tuple[float, float]]  # member → (ω, ε) at the instant


def build(motion: Motion, i: int = 0) -> Plans:
    """Both plans at position ``i`` of a motion solved with ``order=2``.

    A class III group is drawn the book's way, through its special point S (where the lines
    of two binary members meet, ``Motion.special``). Raises ``StructureError`` for a class
    III group without one (a binary member that slides on the ternary member), or at an
    instant where the two lines are parallel."""
    return _walk(_Sheet(motion, i))


class _Sheet:
    """Where the walk stands: the motion at one instant, both plans' images so far and the
    mechanism position of every station placed."""

    def __init__(self, motion: Motion, i: int):
        if motion.order < 2:
            raise ValueError("plans need accelerations: solve with order=2")
        self.m, self.i, self.scene = motion, i, motion.scene
        self.vel = Plan("velocity", {POLE: 0j})
        self.acc = Plan("acceleration", {POLE: 0j})
        self.pos: dict[str, complex] = {}
        self.n_count = self.k_count = 0

    def omega(self, member: int) -> tuple[float, float]:
        if member == FRAME:
            return 0.0, 0.0
        mm = self.m.members[member]
        return float(mm.omega[self.i]), float(mm.epsilon[self.i])

    def state(self, st: Station, z: complex | None = None) -> tuple[complex, complex, complex]:
        """Position, velocity, acceleration of the station (rigid-body rule from a named
        point of its member for a coincident point)."""
        if not st.coincident:
            p = self.m.points[st.letter]
            return complex(p.z[self.i]), complex(p.v[self.i]), complex(p.a[self.i])
        ref = next(iter(self.scene.points_of(st.member)))
        zr, vr, ar = self.state(Station(st.member, ref))
        w, e = self.omega(st.member)
        r = z - zr
        return z, vr + 1j * w * r, ar + (1j * e - w * w) * r

    def place(self, st: Station, z: complex | None = None) -> None:
        z, v, a = self.state(st, z)
        self.pos[st.name] = z
        self.vel.images[st.image] = v
        self.acc.images[st.image] = a

    def known(self, st: Station) -> bool:
        return st.image in self.vel.images

    def position(self, st: Station) -> complex:
        if st.name not in self.pos:
            self.place(st) if st.member != FRAME or st.letter in self.scene.frame else None
        return self.pos[st.name]

    def first_known(self, member: int) -> str:
        return next(p for p in self.scene.points_of(member) if self.known(Station(member, p)))

    def normal_point(self, start: str, value: complex) -> str:
        """A construction point n of the acceleration plan: ``start`` plus a normal part."""
        self.n_count += 1
        n = f"n{self.n_count}"
        self.acc.images[n] = self.acc.images[start] + value
        return n

    def coriolis_point(self, start: str, value: complex) -> str:
        """A construction point k of the acceleration plan: ``start`` plus a Coriolis part."""
        self.k_count += 1
        k = f"k{self.k_count}"
        self.acc.images[k] = self.acc.images[start] + value
        return k


# --- the three kinds of move along a chain ---------------------------------------------------

def _rigid(sheet: _Sheet, member: int, frm: Station, to: Station) -> tuple[Arrow, list[Arrow]]:
    """Within one member: to = frm + relative (⊥ frm–to); in accelerations the normal part
    (toward frm) and the tangential part (⊥ frm–to)."""
    w, e = sheet.omega(member)
    r = sheet.pos[to.name] - sheet.pos[frm.name]
    sub = f"{to.tex}{frm.tex}"
    lever = abs(r)
    v = Arrow("relative", frm.image, to.image, 1j * w * r, f"v_{{{sub}}}",
              ("perp", frm.name, to.name), member, lever)
    n = sheet.normal_point(frm.image, -w * w * r)
    acc = [Arrow("normal", frm.image, n, -w * w * r, f"a^n_{{{sub}}}",
                 ("toward", to.name, frm.name), member, lever),
           Arrow("tangential", n, to.image, 1j * e * r, f"a^t_{{{sub}}}",
                 ("perp", frm.name, to.name), member, lever)]
    return v, acc


def _coriolis(sheet: _Sheet, guide: int, frm: Station, to: Station, v_rel: complex
              ) -> tuple[Arrow, str]:
    """The Coriolis part 2·ω_guide × v_rel of a slide from ``frm`` to ``to`` on a turning
    guide, and the construction point k it reaches."""
    w, _ = sheet.omega(guide)
    coriolis = 2j * w * v_rel
    k = sheet.coriolis_point(frm.image, coriolis)
    return Arrow("coriolis", frm.image, k, coriolis, f"a^k_{{{to.tex}{frm.tex}}}",
                 ("coriolis", str(guide))), k


def _slide(sheet: _Sheet, pair: Pair, frm: Station, to: Station) -> tuple[Arrow, list[Arrow]]:
    """Across a prismatic pair at one place: to = frm + sliding (∥ guide); in accelerations
    the Coriolis part, then the relative sliding part."""
    guide = pair.members[0]
    v_rel = sheet.vel.images[to.image] - sheet.vel.images[frm.image]
    a_rel = sheet.acc.images[to.image] - sheet.acc.images[frm.image]
    along = ("along", pair.name)
    if guide == FRAME:  # a fixed guide: the motion is absolute and has no Coriolis part
        name = (to if frm.member == FRAME else frm).tex
        return (Arrow("sliding", frm.image, to.image, v_rel, f"v_{{{name}}}", along),
                [Arrow("sliding", frm.image, to.image, a_rel, f"a_{{{name}}}", along)])
    sub = f"{to.tex}{frm.tex}"
    v = Arrow("sliding", frm.image, to.image, v_rel, f"v_{{{sub}}}", along)
    coriolis, k = _coriolis(sheet, guide, frm, to, v_rel)
    return v, [coriolis, Arrow("sliding", k, to.image, a_rel - coriolis.value,
                               f"a^r_{{{sub}}}", along)]


def _arc(sheet: _Sheet, pair: Pair, frm: Station, to: Station) -> tuple[Arrow, list[Arrow]]:
    """Across a circular slot, from the block's point B to the guide's point B₄ under it:
    v_B₄B ⊥ B₄H (H the slot's centre); in accelerations the Coriolis part 2·ω_guide ×
    v_B₄B, the normal part v²/R along HB and the tangential part ⊥ B₄H."""
    v_rel = sheet.vel.images[to.image] - sheet.vel.images[frm.image]
    a_rel = sheet.acc.images[to.image] - sheet.acc.images[frm.image]
    radial = sheet.pos[frm.name] - complex(sheet.m.points[pair.point].z[sheet.i])
    radius = abs(radial)
    sub = f"{to.tex}{frm.tex}"
    v = Arrow("relative", frm.image, to.image, v_rel, f"v_{{{sub}}}",
              ("perp", to.name, pair.point))
    normal = abs(v_rel) ** 2 / radius * radial / radius  # B₄ relative to the block: from H
    coriolis, k = _coriolis(sheet, pair.members[0], frm, to, v_rel)
    n = sheet.normal_point(k, normal)
    acc = [coriolis,
           Arrow("normal", k, n, normal, f"a^n_{{{sub}}}", ("toward", pair.point, frm.name)),
           Arrow("tangential", n, to.image, a_rel - coriolis.value - normal, f"a^t_{{{sub}}}",
                 ("perp", to.name, pair.point))]
    return v, acc


# --- the walk: driver, each group, third points by similarity ------------------------------

def _walk(sheet: _Sheet) -> Plans:
    scene = sheet.scene
    for letter in scene.frame:
        sheet.pos[letter] = scene.frame[letter]
        sheet.vel.images[letter.lower()] = 0j
        sheet.acc.images[letter.lower()] = 0j
    _driver(sheet)
    for group in sheet.m.structure.groups:
        if all(m in sheet.m.members for m in group.members):
            (_triad if group.cls == 3 else _dyad)(sheet, group)
    for member in [DRIVER, *(m for g in sheet.m.structure.groups for m in g.members)]:
        if member in sheet.m.members:
            _similar(sheet, member)
    return Plans(sheet.vel, sheet.acc, sheet.pos,
                 {n: sheet.omega(n) for n in sheet.m.members})


def _driver(sheet: _Sheet) -> None:
    """The driving member's point: by its rotation about the pivot, or given along its guide."""
    scene = sheet.scene
    pair = scene.pair(scene.driver.pair)
    own = scene.points_of(DRIVER)
    tip = next((p for p in own if p != pair.point), pair.point)
    if pair.kind == "revolute":
        centre = Station(FRAME, pair.point)
        target = Station(DRIVER, tip)
        sheet.place(target)
        v, acc = _rigid(sheet, DRIVER, centre, target)
        _record(sheet, "driver", target, [(centre, [v], acc)])
        return
    target = Station(DRIVER, pair.point)
    sheet.place(target)
    v = sheet.vel.images[target.image]
    a = sheet.acc.images[target.image]
    along = ("along", pair.name)
    _record(sheet, "driver", target,
            [(None, [Arrow("absolute", POLE, target.image, v, f"v_{{{target.tex}}}", along)],
              [Arrow("absolute", POLE, target.image, a, f"a_{{{target.tex}}}", along)])])


def _dyad(sheet: _Sheet, group: Group) -> None:
    """A class II group: two chains, one from each outer pair, that meet at the inner pair."""
    j, k = group.members
    outer_j, inner, outer_k = group.pairs
    sliding = inner.kind == "prismatic" or inner.on_slot
    if not sliding:
        meet = {j: Station(j, inner.point), k: Station(k, inner.point)}
        target = meet[j]
    else:  # the guide's point under the block's (B₄ under B) is where the chains meet
        guide, slider = inner.members
        at = inner.on_slot or inner.point
        meet = {guide: Station(guide, at, coincident=True), slider: Station(slider, at)}
        target = meet[guide]
        sheet.place(meet[slider])
        sheet.place(target, sheet.pos[meet[slider].name])
    chains = [_chain(sheet, member, outer, meet[member])
              for member, outer in ((j, outer_j), (k, outer_k))]
    if sliding:  # the slider's chain continues across the pair
        side = 0 if slider == j else 1
        start, v_arrows, a_arrows = chains[side]
        move = _arc if inner.on_slot else _slide
        v, acc = move(sheet, inner, meet[slider], target)
        chains[side] = (start, [*v_arrows, v], [*a_arrows, *acc])
    _record(sheet, group.label(), target, chains)


def _chain(sheet: _Sheet, member: int, outer: Pair, meet: Station):
    """From the known side of ``outer`` into ``member`` and on to ``meet``."""
    known = outer.other(member)
    v_arrows: list[Arrow] = []
    a_arrows: list[Arrow] = []
    if outer.kind == "revolute":
        start = entry = Station(known, outer.point)
        if not sheet.known(start):  # a third point of a known member
            _similar(sheet, known)
    elif member == outer.members[1]:  # member slides on a known guide
        entry = Station(member, outer.point)
        start = Station(known, outer.point, coincident=True)
        sheet.place(entry)
        _carried(sheet, start, sheet.pos[entry.name])
        v, acc = _slide(sheet, outer, start, entry)
        v_arrows.append(v)
        a_arrows += acc
    else:  # member is the guide of a known slider
        start = Station(known, outer.point)
        entry = Station(member, outer.point, coincident=True)
        sheet.place(entry, sheet.pos[start.name])
        v, acc = _slide(sheet, outer, start, entry)
        v_arrows.append(v)
        a_arrows += acc
    if meet.name != entry.name:
        if not meet.coincident:
            sheet.place(meet)
        v, acc = _rigid(sheet, member, entry, meet)
        v_arrows.append(v)
        a_arrows += acc
    return start, v_arrows, a_arrows


def _carried(sheet: _Sheet, st: Station, z: complex) -> None:
    """A known guide's point under a slider, by similarity from a named point."""
    sheet.place(st, z)
    if st.member != FRAME:
        base = Station(st.member, sheet.first_known(st.member))
        v, acc = _rigid(sheet, st.member, base, st)
        _record(sheet, "similarity", st, [(base, [v], acc)])


def _similar(sheet: _Sheet, member: int) -> None:
    """Third points of a member: their images by similarity to the member's shape."""
    base = Station(member, sheet.first_known(member))
    for letter in sheet.scene.points_of(member):
        st = Station(member, letter)
        if sheet.known(st):
            continue
        sheet.place(st)
        v, acc = _rigid(sheet, member, base, st)
        _record(sheet, "similarity", st, [(base, [v], acc)])


# --- a class III group, through its special point S ------------------------------------------

def _triad(sheet: _Sheet, group: Group) -> None:
    """A class III group through its special point S: S lies on the lines of two binary
    members, so S's image is found from their two known ends like a dyad's joint; then
    the third binary member's joint on the ternary member from S, as in a dyad; the rest
    by similarity."""
    name, b1, b2 = next(((n, a, b) for n, (g, a, b) in
                         special_pairs(sheet.scene, [group]).items()), (None, 0, 0))
    special = sheet.m.special.get(name) if name else None
    if special is None or not np.isfinite(special.z[sheet.i]):
        raise StructureError(Text("structure.no_special", label=group.label()))
    ternary = group.members[0]
    target = Station(ternary, name)
    sheet.pos[target.name] = complex(special.z[sheet.i])
    sheet.vel.images[target.image] = complex(special.v[sheet.i])
    sheet.acc.images[target.image] = complex(special.a[sheet.i])
    _record(sheet, group.label(), target,
            [_to_special(sheet, group, b, target) for b in (b1, b2)])
    third = next(m for m in group.members[1:] if m not in (b1, b2))
    inner = next(p for p in group.pairs if set(p.members) == {third, ternary})
    outer = next(p for p in group.pairs if third in p.members and p is not inner)
    joint = Station(ternary, inner.point)
    sheet.place(joint)
    v, acc = _rigid(sheet, ternary, target, joint)
    _record(sheet, group.label(), joint,
            [(target, [v], acc), _chain(sheet, third, outer, Station(third, inner.point))])


def _to_special(sheet: _Sheet, group: Group, binary: int, s: Station):
    """One side of S's equation along binary member ``binary`` (joint J on the ternary
    member): from its pivot P, v_S − v_P ⊥ PS and a_S = a_P + a^n_JP + a^n_SJ + a^t ⊥ PS;
    from a slider on a guide, v_S − v_J(guide) ∥ guide and a_S = a_J(guide) + a^k +
    a^n_SJ + a^r ∥ guide (the ternary's turning adds along the guide there)."""
    ternary = group.members[0]
    inner = next(p for p in group.pairs if set(p.members) == {binary, ternary})
    outer = next(p for p in group.pairs if binary in p.members and p is not inner)
    joint = sheet.pos.get(inner.point, complex(sheet.m.points[inner.point].z[sheet.i]))
    w_t, _ = sheet.omega(ternary)
    normal_sj = -w_t * w_t * (sheet.pos[s.name] - joint)
    if outer.kind == "revolute":
        start = Station(outer.other(binary), outer.point)
        rule = ("perp", start.name, s.name)
        w_b, _ = sheet.omega(binary)
        normals = [(-w_b * w_b * (joint - sheet.position(start)),
                    f"a^n_{{{inner.point}{start.tex}}}", ("toward", inner.point, start.name)),
                   (normal_sj, f"a^n_{{{s.tex}{inner.point}}}", ("toward", s.name, inner.point))]
        v_kind, a_kind = "relative", "tangential"
    else:  # the binary member slides on a guide of a known member
        guide = outer.members[0]
        start = Station(guide, outer.point, coincident=True) if guide != FRAME else \
            Station(FRAME, outer.through)
        if guide != FRAME:
            _carried(sheet, start, joint)
        rule = ("along", outer.name)
        w_g, _ = sheet.omega(guide)
        v_rel = complex(sheet.m.points[inner.point].v[sheet.i]) - sheet.vel.images[start.image]
        normals = [(2j * w_g * v_rel, f"a^k_{{{inner.point}{start.tex}}}",
                    ("coriolis", str(guide))),
                   (normal_sj, f"a^n_{{{s.tex}{inner.point}}}", ("toward", s.name, inner.point))]
        v_kind, a_kind = "sliding", "sliding"
    sub = f"{s.tex}{start.tex}"
    v = Arrow(v_kind, start.image, s.image,
              sheet.vel.images[s.image] - sheet.vel.images[start.image], f"v_{{{sub}}}", rule)
    arrows, image = [], start.image
    for value, symbol, how in normals:
        if abs(value) == 0.0:
            continue
        head = sheet.normal_point(image, value)
        kind = "coriolis" if how[0] == "coriolis" else "normal"
        arrows.append(Arrow(kind, image, head, value, symbol, how))
        image = head
    arrows.append(Arrow(a_kind, image, s.image, sheet.acc.images[s.image] - sheet.acc.images[image],
                        f"a^{{{'t' if a_kind == 'tangential' else 'r'}}}_{{{sub}}}", rule))
    return start, [v], arrows


# --- each step's equation --------------------------------------------------------------------

def _record(sheet: _Sheet, group: str, target: Station, chains) -> None:
    """One step in both plans: each chain becomes a side that runs from its start to the
    target."""
    v_sides, a_sides = [], []
    for start, v_arrows, a_arrows in chains:
        head = POLE if start is None else start.image
        v_sides.append((head, tuple(v_arrows)))
        a_sides.append((head, tuple(a_arrows)))
    starts = [s for s, _, _ in chains]
    sheet.vel.steps.append(Step(target.image, tuple(v_sides),
                                _latex(sheet.scene, "v", target, starts, v_sides), group))
    sheet.acc.steps.append(Step(target.image, tuple(a_sides),
                                _latex(sheet.scene, "a", target, starts, a_sides), group))


def _latex(scene: Scene, q: str, target: Station, starts, sides) -> str:
    """``\\vec v_{C} = \\vec v_{B} + \\vec v_{CB} = …`` for one step; a point on the
    frame adds nothing, and a slide along a fixed guide is stated as a direction."""
    head = f"\\vec {q}_{{{target.tex}}}"
    if starts == [None]:  # a linear driver's own motion
        return head + r"\ \text{(given)}"
    parts, notes = [], []
    for start, (_, arrows) in zip(starts, sides):
        if [a.kind for a in arrows] == ["sliding"] and _fixed_guide(scene, arrows[0]):
            notes.append(f"\\vec {arrows[0].symbol} \\parallel {_guide_tex(scene, arrows[0])}")
            continue
        fixed = start.member == FRAME or (start.letter in scene.frame and not start.coincident)
        terms = [] if fixed else [f"\\vec {q}_{{{start.tex}}}"]
        terms += [f"\\vec {a.symbol}" for a in arrows]
        parts.append(" + ".join(terms) if terms else "0")
    return ",\\quad ".join([head + " = " + " = ".join(parts), *notes])


def _fixed_guide(scene: Scene, arrow: Arrow) -> bool:
    return scene.pair(arrow.rule[1]).members[0] == FRAME


def _guide_tex(scene: Scene, arrow: Arrow) -> str:
    pair = scene.pair(arrow.rule[1])
    return f"\\overline{{{pair.through or pair.point}{pair.point}}}"


def describe(rule: tuple[str, ...], scene: Scene) -> str:
    """The direction rule in words with the book's symbols: ⊥ BC, ∥ guide, …"""
    kind, *args = rule
    if kind == "perp":
        return f"⊥ {args[0]}{args[1]}"
    if kind == "toward":
        return f"∥ {args[0]}{args[1]}, → {args[1]}"
    if kind == "along":
        pair = scene.pair(args[0])
        return f"∥ {pair.through or pair.point}–{pair.point} ({pair.members[0]})"
    return f"⊥ v_rel, ω{args[0]}"


@dataclass(frozen=True)
class Reading:
    """A value a student reads off the plans, and how well a drawing can give it."""

    symbol: str  # LaTeX-like name: v_{C}, \omega_{4}
    exact: float
    unit: str
    plan_cm: float | None  # its length on the plan (None for a derived value)
    uncertainty: float  # ± in ``unit``, from the drawing precision at the scales


def is_construction(image: str) -> bool:
    return image[0] in "nk" and image[1:].isdigit()


def readings(plans: Plans, scales: dict[str, float], precision_cm: float) -> list[Reading]:
    """Speeds and accelerations of the points (|Pv x|·U_v, |Pa x|·U_a), then ω and ε of each
    member from its longest relative part (ω = v_XY/XY, ε = a^t_XY/XY), with the error a
    drawing made to ``precision_cm`` brings: δ·U for a length read off, and for a ratio
    the sum of the relative errors of its plan length and of the link length at U_L."""
    out = []
    for plan, key, unit in ((plans.velocity, "v", "m/s"), (plans.acceleration, "a", "m/s²")):
        u = scales[key]
        for image, value in plan.images.items():
            if image == POLE or is_construction(image) or abs(value) < 1e-12:
                continue
            name = image.upper()
            tex = f"{name[0]}_{{{name[1:]}}}" if len(name) > 1 else name
            out.append(Reading(f"{key}_{{{tex}}}", abs(value), unit, abs(value) / u,
                               precision_cm * u))
    for member in sorted(m for m in plans.members if m != DRIVER):  # ω₂, ε₂ are given
        for plan, kind, key, symbol, unit in (
                (plans.velocity, "relative", "v", "\\omega", "s⁻¹"),
                (plans.acceleration, "tangential", "a", "\\varepsilon", "s⁻²")):
            parts = [a for a in plan.arrows if a.kind == kind and a.member == member and a.lever]
            if not parts:
                continue
            best = max(parts, key=lambda a: (a.lever, abs(a.value)))
            exact = abs(best.value) / best.lever
            u = scales[key]
            relative = (precision_cm * u / abs(best.value) if abs(best.value) > 1e-12 else np.inf)
            relative += precision_cm * scales["L"] / best.lever
            out.append(Reading(f"{symbol}_{{{member}}}", exact, unit, None,
                               exact * relative if np.isfinite(relative) else precision_cm * u / best.lever))
    return out
