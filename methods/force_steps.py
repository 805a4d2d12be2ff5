"""Kinetostatics the graphical way, step by step (problem collection, tasks 5.1–5.2; the
kinetostatics lectures' worked example).

The book takes the mechanism apart group by group, from the last Assur group toward the
driver, and at one position finds every reaction with the simplest equation that has a single
unknown left:
  * a revolute pair's reaction on a member is split into a **normal** part along the member
    (towards its other joint in the group) and a **tangential** part across it; the moment of
    that member about its other joint holds only the tangential part;
  * the force polygon of the group is then closed with the two parts whose directions are
    known (the normals, or the force across a guide);
  * where three directions remain (a class III group), the moment of the whole group about
    the point where two of them meet (the Assur point S) gives the third;
  * a member's polygon gives what is left at its inner joint; a guide's couple F·h follows
    from a moment equation; the driver's torque M_p from the moment about its pivot.

``steps`` does exactly that with the numbers, independently of the batched solve in
``solvers.kinetostatics`` (a test holds the two equal), and records each equation so that a
page can show it and draw each polygon to scale. A body for which no single-unknown equation
is left is solved all at once, and the step says so.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from itertools import combinations

import numpy as np

from mechanisms.schema import DRIVER, Pair
from solvers.kinetostatics import Kinetostatics
from solvers.loops import cross
from solvers.state import value_at

ZERO = 1e-9  # a lever arm or determinant this small (relative to the body's size) is zero


@dataclass(frozen=True)
class Unknown:
    """One unknown scalar: a unit action of member ``by`` on member ``on`` (the force
    ``force`` through ``point`` plus the couple ``couple``), as the book names it."""

    name: str  # F_45^t, F_45^n, F_16, F_16·h_16, M_p, F_34 (its x or y part)
    part: str  # "t", "n", "x", "y", "N" (a force across a guide), "Fh" (its couple), "drive"
    pair: Pair | None
    by: int
    on: int
    force: complex
    point: complex
    couple: float = 0.0

    def sign(self, member: int) -> float:
        return 1.0 if member == self.on else -1.0 if member == self.by else 0.0


@dataclass(frozen=True)
class Term:
    """One action in an equation: its name, its force (0 for a couple), and its moment about
    the equation's point (N·m) or, for a polygon, the force itself."""

    name: str
    force: complex
    moment: float  # for the unknown of a moment equation: its lever arm (1 for a couple)
    unknown: bool = False
    point: complex | None = None  # where the force acts; None for a couple


@dataclass
class Step:
    """One equation of the construction and what it gave."""

    group: str  # the Assur group's name ("3-4") or "driver"
    kind: str  # "moment" (of a member or a body about a point), "polygon" or "together"
    members: tuple[int, ...]
    about: str  # the point's letter, "S" for a meeting point of two lines; "" for a polygon
    terms: list[Term]
    found: dict[str, tuple[float, str]]  # what was found here: value and unit (N, N·m); a
    # whole reaction (both parts at once) as its magnitude
    closing: list[tuple[str, complex]] = field(default_factory=list)  # the polygon's last sides
    at: complex | None = None  # the point moments are taken about (world, m)

    def forces(self) -> list[tuple[str, complex, complex]]:
        """The forces of a moment equation as (name, point, force), to draw its free body."""
        return [(t.name, t.point, t.force) for t in self.terms if t.point is not None]


@dataclass
class Construction:
    steps: list[Step]
    reactions: dict[tuple[int, int], tuple[complex, complex, float]]  # (p, q) → F_pq, point, couple
    driving: float  # M_p (N·m) or, for a linear driver, F_p (N)


def steps(k: Kinetostatics, index: int = 0) -> Construction:
    """The whole construction at position ``index`` of ``k``: every group from the last one,
    then the driver."""
    motion = k.motion
    groups = {g.name: g for g in motion.structure.groups}
    known: dict[tuple[int, int], tuple[complex, complex, float]] = {}
    out: list[Step] = []
    driving = float("nan")
    for name in k.order:
        if name == "driver":
            pair = motion.scene.pair(motion.scene.driver.pair)
            body = _Body(k, index, name, (DRIVER,), (pair,), known)
            body.unknowns.append(_drive(k, index, pair))
        else:
            group = groups[name]
            body = _Body(k, index, name, group.members, group.pairs, known)
        out += _solve(body)
        body.record()
        if name == "driver":
            driving = body.values[len(body.unknowns) - 1]
    return Construction(out, known, driving)


def _drive(k: Kinetostatics, index: int, pair: Pair) -> Unknown:
    """M_p as a couple on member 2, or F_p along the driver's guide."""
    if k.rotating:
        return Unknown("M_p", "drive", None, 0, DRIVER, 0j, 0j, 1.0)
    bodies = k.motion.bodies
    guide, slider = pair.members
    direction = complex(value_at(np.exp(1j * pair.angle) * bodies[guide].rot, index))
    point = complex(value_at(bodies[slider].position(k.motion.scene.points_of(slider)[pair.point]), index))
    return Unknown("F_p", "drive", None, 0, DRIVER, direction, point)


class _Body:
    """The equations of one free body (a group, or the driving member) at one position."""

    def __init__(self, k: Kinetostatics, index: int, name: str, members: tuple[int, ...],
                 pairs: tuple[Pair, ...], known: dict):
        self.k, self.index, self.name, self.members, self.pairs = k, index, name, members, pairs
        self.known = known
        scene, bodies = k.motion.scene, k.motion.bodies
        self.position = {}  # (member, letter) → world point
        for m in members:
            for letter, local in scene.points_of(m).items():
                self.position[(m, letter)] = complex(value_at(bodies[m].position(local), index))
        self.size = max([abs(a - b) for a, b in combinations(self.position.values(), 2)] + [1e-9])
        self.unknowns: list[Unknown] = []
        for pair in pairs:
            self.unknowns += _pair_unknowns(self, pair)
        self.values: dict[int, float] = {}

    def _actions(self, member: int) -> list[tuple[str, complex, complex | None, float]]:
        """Every known action on ``member`` as (name, force, point, couple): loads, couples,
        and the reactions of the groups solved before."""
        i = self.index
        out = [(ld.name, complex(value_at(ld.force, i)), complex(value_at(ld.point, i)), 0.0)
               for ld in self.k.loads if ld.member == member]
        out += [(c.name, 0j, None, float(value_at(c.value, i)))
                for c in self.k.couples if c.member == member]
        out += [(f"F_{p}{q}", f, z, c) for (p, q), (f, z, c) in self.known.items()
                if q == member and p not in self.members]
        return out

    def _inside(self, u: Unknown, body: tuple[int, ...]) -> bool:
        return u.by in body and u.on in body

    def moment(self, body: tuple[int, ...], about: complex):
        """ΣM about ``about`` of the forces on ``body``: coefficients of the unknowns, and the
        known terms (their moments)."""
        terms = [Term(name, f, (0.0 if z is None else cross(z - about, f)) + c, point=z)
                 for m in body for name, f, z, c in self._actions(m)]
        coef = np.array([0.0 if self._inside(u, body) else
                         sum(u.sign(m) for m in body) * (cross(u.point - about, u.force) + u.couple)
                         for u in self.unknowns])
        return coef, terms

    def polygon(self, body: tuple[int, ...]):
        """ΣF on ``body``: coefficients (complex) of the unknowns, and the known forces."""
        terms = [Term(name, f, 0.0, point=z) for m in body for name, f, z, _ in self._actions(m)
                 if z is not None and f != 0]
        coef = np.array([0j if self._inside(u, body) else sum(u.sign(m) for m in body) * u.force
                         for u in self.unknowns])
        return coef, terms

    def _appears(self, j: int, coef, moment: bool) -> bool:
        """Unknown ``j`` enters the equation (a lever arm of a ten-millionth of the body is
        none: the force passes through the point)."""
        force = self.unknowns[j].force != 0
        return abs(coef[j]) > ZERO * (self.size if moment and force else 1.0)

    def _open(self, coef, moment: bool) -> list[int]:
        """Unsolved unknowns that appear in an equation."""
        return [j for j in range(len(self.unknowns))
                if j not in self.values and self._appears(j, coef, moment)]

    def _rest(self, coef, known) -> complex:
        """The equation's known part: known terms plus the unknowns solved so far."""
        return known + sum((coef[j] * v for j, v in self.values.items()), 0.0)

    def _solved(self, coef, body, moment: bool) -> list[Term]:
        """Parts found in earlier steps of this body that enter the equation (the x and y of
        one reaction as one vector)."""
        out: dict[str, Term] = {}
        for j in (j for j in self.values if self._appears(j, coef, moment)):
            u, v = self.unknowns[j], self.values[j]
            old = out.get(u.name, Term(u.name, 0j, 0.0))
            out[u.name] = Term(u.name, old.force + u.force * v,
                               old.moment + (coef[j] * v if moment else 0.0),
                               point=None if u.force == 0 else u.point)
        return list(out.values())

    def found_term(self, j: int, arm: float) -> Term:
        """An unknown of a moment equation: its lever arm, and the force it was found to be."""
        u = self.unknowns[j]
        return Term(u.name, u.force * self.values[j], arm, unknown=True,
                    point=None if u.force == 0 else u.point)

    def found(self, indices: list[int]) -> dict[str, tuple[float, str]]:
        """Each unknown found, with its unit: a couple F·h or a torque in N·m, else N (the
        x and y of one reaction are added up into its magnitude)."""
        out: dict[str, tuple[float, str]] = {}
        for j in indices:
            u = self.unknowns[j]
            if u.part in ("x", "y"):
                whole = sum(v.force * self.values[i] for i, v in enumerate(self.unknowns)
                            if v.name == u.name and i in self.values)
                out[u.name] = (abs(whole), "N")
            else:
                out[u.name] = (self.values[j], "N" if u.force != 0 else "N·m")
        return out

    def record(self) -> None:
        """The body's reactions, F_pq and F_qp = −F_pq, for the groups that follow."""
        by_pair: dict[tuple[int, int], list] = {}
        for j, u in enumerate(self.unknowns):
            if u.pair is None:
                continue
            f, z, c = by_pair.get((u.by, u.on), (0j, u.point, 0.0))
            by_pair[(u.by, u.on)] = (f + u.force * self.values[j], z, c + u.couple * self.values[j])
        for (p, q), (f, z, c) in by_pair.items():
            self.known[(p, q)] = (f, z, c)
            self.known[(q, p)] = (-f, z, -c)


# --- one pair's unknowns -----------------------------------------------------------------

def _pair_unknowns(body: _Body, pair: Pair) -> list[Unknown]:
    """Two unknown scalars per pair, as actions of the member outside the body (or of
    the pair's first member) on the member inside."""
    a, b = pair.members
    inner = a in body.members and b in body.members
    by, on = (a, b) if inner or b in body.members else (b, a)
    scene, bodies = body.k.motion.scene, body.k.motion.bodies
    point = complex(value_at(bodies[b].position(scene.points_of(b)[pair.point]), body.index))
    name = f"F_{by}{on}"
    if pair.kind == "prismatic":
        normal = 1j * complex(value_at(np.exp(1j * pair.angle) * bodies[a].rot, body.index))
        return [Unknown(name, "N", pair, by, on, normal, point),
                Unknown(f"{name}·h_{by}{on}", "Fh", pair, by, on, 0j, point, 1.0)]
    towards = None if inner else _other_joint(body, on, pair, point)
    if towards is None:  # the driver's pivot, an inner joint: the whole vector closes
        return [Unknown(name, "x", pair, by, on, 1.0 + 0j, point),
                Unknown(name, "y", pair, by, on, 1j, point)]
    n = (towards - point) / abs(towards - point)
    return [Unknown(f"{name}^t", "t", pair, by, on, 1j * n, point),
            Unknown(f"{name}^n", "n", pair, by, on, n, point)]


def _other_joint(body: _Body, member: int, pair: Pair, point: complex) -> complex | None:
    """The member's next joint inside the group: the normal part points along the member
    to it, so that the moment about it holds the tangential part alone."""
    for other in body.pairs:
        if other is not pair and member in other.members and other.kind == "revolute":
            z = body.position.get((member, other.point))
            if z is not None and abs(z - point) > ZERO * body.size:
                return z
    return None


# --- the construction: which equation has a single unknown left ---------------------------

def _solve(body: _Body) -> list[Step]:
    """The book's order: the simplest equation with a single unknown left, until none is."""
    out: list[Step] = []
    while len(body.values) < len(body.unknowns):
        step = (_moment_step(body, parts=("t", "drive")) or _polygon_step(body, body.members)
                or _special_point_step(body)
                or next((s for m in body.members if (s := _polygon_step(body, (m,)))), None)
                or _moment_step(body, parts=None) or _two_moments_step(body)
                or _together(body))
        out += step if isinstance(step, list) else [step]
    return out


def _points(body: _Body, member: int) -> dict[str, complex]:
    """The member's pair points in this body (their letters): moments are taken about them."""
    return {p.point: body.position[(member, p.point)] for p in body.pairs
            if member in p.members and (member, p.point) in body.position}


def _moment_step(body: _Body, parts) -> Step | None:
    """A member's moment about one of its joints with a single unknown (of ``parts``) left."""
    for m in body.members:
        for letter, about in _points(body, m).items():
            coef, terms = body.moment((m,), about)
            left = body._open(coef, moment=True)
            if len(left) == 1 and (parts is None or body.unknowns[left[0]].part in parts):
                return _moment_found(body, (m,), letter, coef, terms, left[0], about)
    return None


def _two_moments_step(body: _Body) -> Step | None:
    """Two members' moments about their own joints that share the same two unknowns (a
    block on a guide: the force across the guide and its couple F·h), solved together."""
    equations = [(m, letter, *body.moment((m,), about)) for m in body.members
                 for letter, about in _points(body, m).items()]
    for (m1, p1, c1, t1), (m2, p2, c2, t2) in combinations(equations, 2):
        left = body._open(c1, moment=True)
        if m1 == m2 or len(left) != 2 or left != body._open(c2, moment=True):
            continue
        a = np.array([[c1[j] for j in left], [c2[j] for j in left]])
        if abs(np.linalg.det(a)) < 1e-6 * np.abs(a).max() ** 2:
            continue
        rests = [body._rest(c, sum(t.moment for t in ts)).real for c, ts in ((c1, t1), (c2, t2))]
        x = np.linalg.solve(a, -np.array(rests))
        solved = [body._solved(c, (m,), moment=True) for c, m in ((c1, m1), (c2, m2))]
        body.values.update(dict(zip(left, x)))
        names = body.found(left)
        first = Step(body.name, "moment", (m1,), p1, t1 + solved[0] + [
            body.found_term(j, c1[j]) for j in left], {}, at=body.position[(m1, p1)])
        return [first, Step(body.name, "moment", (m2,), p2, t2 + solved[1] + [
            body.found_term(j, c2[j]) for j in left], names, at=body.position[(m2, p2)])]
    return None


def _special_point_step(body: _Body) -> Step | None:
    """The moment of the whole body about the point where two unknown lines meet."""
    lines = [j for j, u in enumerate(body.unknowns) if j not in body.values
             and u.part in ("n", "N", "t") and not body._inside(u, body.members)]
    for a, b in combinations(lines, 2):
        ua, ub = body.unknowns[a], body.unknowns[b]
        det = cross(ua.force, ub.force) / abs(ua.force * ub.force)
        if abs(det) < 1e-6:  # parallel: they meet far away, if at all
            continue
        about = ua.point + cross(ub.point - ua.point, ub.force) / cross(ua.force, ub.force) * ua.force
        coef, terms = body.moment(body.members, about)
        left = body._open(coef, moment=True)
        if len(left) == 1:
            return _moment_found(body, body.members, "S", coef, terms, left[0], about)
    return None


def _moment_found(body: _Body, members, letter, coef, terms, j, about: complex) -> Step:
    """A moment equation with one unknown left: solve it and record the step."""
    known = sum(t.moment for t in terms)
    value = -float(body._rest(coef, known).real) / coef[j]
    solved = body._solved(coef, members, moment=True)
    body.values[j] = value
    return Step(body.name, "moment", members, letter,
                terms + solved + [body.found_term(j, coef[j])], body.found([j]), at=about)


def _polygon_step(body: _Body, members: tuple[int, ...]) -> Step | None:
    """The force polygon of ``members`` when it closes with two unknown parts."""
    coef, terms = body.polygon(members)
    left = body._open(coef, moment=False)
    if len(left) != 2:
        return None
    a, b = (coef[j] for j in left)
    det = cross(a, b)
    if abs(det) < 1e-6 * abs(a) * abs(b):  # parallel: the polygon cannot close
        return None
    solved = body._solved(coef, members, moment=False)
    rest = -complex(body._rest(coef, sum((t.force for t in terms), 0j)))
    x, y = cross(rest, b) / det, cross(a, rest) / det  # rest = x·a + y·b
    body.values.update({left[0]: x, left[1]: y})
    closing = _closing(body, left, coef)
    found = ({closing[0][0]: (abs(closing[0][1]), "N")} if len(closing) == 1
             else body.found(left))
    return Step(body.name, "polygon", members, "", terms + solved, found, closing)


def _closing(body: _Body, left: list[int], coef) -> list[tuple[str, complex]]:
    """The polygon's closing sides: two parts, or one whole vector (x and y of a pair)."""
    us = [body.unknowns[j] for j in left]
    if us[0].name == us[1].name:
        return [(us[0].name, complex(sum(coef[j] * body.values[j] for j in left)))]
    return [(body.unknowns[j].name, complex(coef[j] * body.values[j])) for j in left]


def _together(body: _Body) -> Step:
    """Every remaining unknown from all the body's equations at once (least squares of a
    consistent system), when no equation with one or two unknowns is left."""
    rows, rhs = [], []
    for m in body.members:
        coef, terms = body.polygon((m,))
        rest = body._rest(coef, sum((t.force for t in terms), 0j))
        rows += [coef.real, coef.imag]
        rhs += [-rest.real, -rest.imag]
        coef, terms = body.moment((m,), next(iter(_points(body, m).values())))
        rows.append(coef / body.size)
        rhs.append(-body._rest(coef, sum(t.moment for t in terms)).real / body.size)
    left = [j for j in range(len(body.unknowns)) if j not in body.values]
    x = np.linalg.lstsq(np.array(rows)[:, left], np.array(rhs), rcond=None)[0]
    body.values.update(dict(zip(left, x)))
    return Step(body.name, "together", body.members, "", [], body.found(left))


# --- the steps as the book writes them ------------------------------------------------------

def latex_name(name: str) -> str:
    """F_45^t → F_{45}^{t}; F_16·h_16 → F_{16}\\cdot h_{16}."""
    name = re.sub(r"_([A-Za-z0-9]+)", r"_{\1}", name)
    return re.sub(r"\^([A-Za-z0-9]+)", r"^{\1}", name).replace("·", r"\cdot ")


def number(x: float) -> str:
    """A value for an equation: 4 digits, a negative one in parentheses, round-off as 0."""
    text = f"{x + 0.0:.4g}" if abs(x) > 1e-12 else "0"
    return f"({text})" if x < 0 else text


def wrapped(head: str, terms: list[str], tail: str, per_line: int = 4) -> str:
    """``head`` + the terms joined by + + ``tail``, broken into lines of ``per_line`` terms
    (st.latex does not wrap, and a long sum ran off a projected page)."""
    rows = [" + ".join(terms[i:i + per_line]) for i in range(0, len(terms), per_line)]
    if len(rows) <= 1:
        return head + " + ".join(terms) + tail
    return (r"\begin{aligned}&" + head + r" \\ &\quad + ".join(rows) + tail
            + r"\end{aligned}")


def equation(step: Step, size: float | None = None) -> list[str]:
    """The step's equation as LaTeX lines: the symbols, then the numbers and what they give.
    Moments: each force times its signed lever arm (m), couples as they are (N·m); polygons:
    the vector sum in the order the polygon is drawn."""
    found = r",\quad ".join(rf"{latex_name(n)} = {number(v).strip('()')}\ \mathrm{{{u}}}".replace("·", r"\cdot ")
                            for n, (v, u) in step.found.items())
    body = ",".join(str(m) for m in sorted(step.members))
    if step.kind == "together":
        return [rf"\sum \vec F^{{({body})}} = 0,\ \sum M^{{({body})}} = 0 \;\Rightarrow\; {found}"]
    if step.kind == "polygon":
        names = [latex_name(t.name) for t in step.terms] + [latex_name(n) for n, _ in step.closing]
        return [wrapped(rf"\sum \vec F^{{({body})}} = ", [rf"\vec {n}" for n in names], " = 0"),
                rf"\Rightarrow\; {found}"]
    symbols, numbers = [], []
    for t in step.terms:
        if t.unknown:  # with its signed lever arm (a couple: alone)
            symbols.append(latex_name(t.name) + ("" if t.point is None else r"\cdot h"))
            numbers.append(latex_name(t.name) + ("" if t.point is None else rf"\cdot {number(t.moment)}"))
        elif t.point is None:
            symbols.append(latex_name(t.name))
            numbers.append(number(t.moment))
        else:
            arm = t.moment / abs(t.force)
            symbols.append(latex_name(t.name) + r"\cdot h")
            numbers.append(f"{abs(t.force):.4g}" + rf"\cdot {number(arm)}")
    about = step.about
    return [wrapped(rf"\sum M_{{{about}}}^{{({body})}} = ", symbols, " = 0"),
            wrapped("", numbers, rf" = 0 \;\Rightarrow\; {found}")]
