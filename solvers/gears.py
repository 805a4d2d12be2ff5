"""Gear trains (chapter 6): the whole train as one linear system of angular velocities.

Each mesh gives the Willis relation relative to the carrier that holds both axes (the
frame for fixed axes): seen from the carrier the pitch point has one velocity on both
gears, (ω_a − ω_c)·R_a = ∓(ω_b − ω_c)·R_b, minus for external teeth, plus when one gear
is a ring. Shafts make members turn together, fixed members stand still, inputs give
values. The rank of the system tells the train's degrees of freedom; a train that is
under- or over-determined is explained, never answered with a least-squares guess.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from mechanisms.gears import GearTrain
from mechanisms.messages import Text


class TrainError(ValueError):
    """The train's structure is wrong (a mesh between planets of different carriers, …)."""


@dataclass(frozen=True)
class TrainSolution:
    train: GearTrain
    omega: dict[int, float]  # rad/s for every member that is determined
    dof: int  # degrees of freedom of the train without its inputs
    status: str  # "solved", "under" (missing inputs), "over" (inconsistent inputs)
    undetermined: tuple[int, ...] = ()
    message: Text | str = ""  # why not solved, or a remark on the solution
    # the speeds for a unit input, when the input is at rest (ratios do not depend on its speed)
    unit: dict[int, float] | None = None

    def ratio(self, a: int, b: int) -> float:
        """i_ab = ω_a/ω_b; infinite when member b does not turn (with the input at rest: as
        for any input speed)."""
        speeds = self.unit or self.omega
        wa, wb = speeds[a], speeds[b]
        if abs(wb) <= 1e-12 * max(abs(wa), 1.0):
            return math.inf
        return wa / wb

    def velocity(self, member: int, radius: float) -> float:
        """Peripheral velocity (m/s) of the point of ``member`` at ``radius`` from the central
        axis, on the side where the planets' axes are drawn (the half-section)."""
        m = self.train.members[member]
        carrier = 0.0 if m.carrier is None else self.omega[m.carrier]
        return self.omega[member] * radius + (carrier - self.omega[member]) * m.axis


def speed_scale(omega: dict[int, float]) -> float:
    """The train's largest speed (1 when all stand still): what round-off is measured against."""
    return max((abs(w) for w in omega.values()), default=1.0) or 1.0


def settled(value: float, scale: float) -> float:
    """A speed of round-off size against ``scale`` is a member at rest (relative to its
    carrier, for a relative speed): exactly 0, not 1e-15 rad/s."""
    return 0.0 if abs(value) <= 1e-12 * scale else value


def mesh_carrier(train: GearTrain, a: int, b: int) -> int | None:
    """The carrier holding both axes of a mesh (None: both axes fixed in the frame)."""
    carriers = {train.members[m].carrier for m in (a, b)} - {None}
    if len(carriers) > 1:
        raise TrainError(Text("train.carriers", a=a, b=b, carriers=sorted(carriers)))
    return carriers.pop() if carriers else None


@dataclass(frozen=True)
class Willis:
    """One mesh's Willis relation: i^c_ab = (ω_a − ω_c)/(ω_b − ω_c) = ∓R_b/R_a."""

    a: int
    b: int
    carrier: int | None  # None: fixed axes (ω_c = 0)
    ratio: float  # ∓R_b/R_a from the radii

    def check(self, omega: dict[int, float]) -> float:
        """The same ratio from the solved speeds (NaN when the member is at the carrier's speed)."""
        c = 0.0 if self.carrier is None else omega[self.carrier]
        below = omega[self.b] - c
        return (omega[self.a] - c) / below if abs(below) > 1e-9 * speed_scale(omega) else math.nan


def willis_table(train: GearTrain) -> list[Willis]:
    return [Willis(*mesh.members, mesh_carrier(train, *mesh.members),
                   (1.0 if mesh.internal is not None else -1.0) * mesh.radii[1] / mesh.radii[0])
            for mesh in train.meshes]


def geometry_notes(train: GearTrain, tolerance: float = 0.02) -> list[Text]:
    """Meshes whose pitch radii do not fit the distance between their axes (where both axes
    are known in one frame: both fixed, or both on the same carrier)."""
    notes = []
    for mesh in train.meshes:
        (a, b), (ra, rb) = mesh.members, mesh.radii
        ma, mb = train.members[a], train.members[b]
        central = {m for m in (ma, mb) if m.carrier is None and m.axis == 0}
        if mesh.bevel or not (ma.carrier == mb.carrier or central):
            continue  # the two axes are not both known in one plane of the drawing
        distance = abs(ma.axis - mb.axis)
        expected = abs(ra - rb) if mesh.internal is not None else ra + rb
        if abs(distance - expected) > tolerance * max(expected, 1e-12):
            notes.append(Text("train.axes", a=a, b=b, distance=_g4(distance), ra=_g4(ra),
                              rb=_g4(rb), expected=_g4(expected)))
    return notes


def _g4(value: float) -> float:
    """Four significant digits, as a message shows a length."""
    return float(f"{value:.4g}")


def equations(train: GearTrain, with_inputs: bool = True) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """Rows of A·ω = b over the members, and a description of each row.

    Dense, and kept dense: the loader's limits (mechanisms/limits.py) bound a train to 40
    members and about 220 rows, a 40-column SVD of well under a millisecond; a sparse
    solver would only pay off for trains thousands of times larger than any in the course."""
    index = {m: i for i, m in enumerate(train.members)}
    rows, rhs, what = [], [], []

    def row() -> np.ndarray:
        return np.zeros(len(index))

    for mesh in train.meshes:
        (a, b), (ra, rb) = mesh.members, mesh.radii
        sign = 1.0 if mesh.internal is not None else -1.0
        eq = row()
        eq[index[a]] += ra
        eq[index[b]] -= sign * rb
        carrier = mesh_carrier(train, a, b)
        if carrier is not None:
            eq[index[carrier]] += -ra + sign * rb
        rows.append(eq)
        rhs.append(0.0)
        what.append(f"mesh {a}–{b}")
    for shaft in train.shafts:
        for other in shaft[1:]:
            eq = row()
            eq[index[shaft[0]]], eq[index[other]] = 1.0, -1.0
            rows.append(eq)
            rhs.append(0.0)
            what.append(f"shaft {shaft[0]}={other}")
    for m in train.fixed:
        eq = row()
        eq[index[m]] = 1.0
        rows.append(eq)
        rhs.append(0.0)
        what.append(f"member {m} fixed")
    if with_inputs:
        for inp in train.inputs:
            eq = row()
            eq[index[inp.member]] = 1.0
            rows.append(eq)
            rhs.append(inp.omega)
            what.append(f"input ω{inp.member}")
    return np.array(rows).reshape(-1, len(index)), np.array(rhs), what


def solve_train(train: GearTrain) -> TrainSolution:
    members = list(train.members)
    a0, _, _ = equations(train, with_inputs=False)
    dof = int(len(members) - (np.linalg.matrix_rank(a0) if len(a0) else 0))
    a, b, _ = equations(train)
    scale = max(1.0, float(np.abs(b).max(initial=0.0)))
    rank = np.linalg.matrix_rank(a) if len(a) else 0
    if rank < len(members):
        _, _, vt = np.linalg.svd(a) if len(a) else (None, None, np.eye(len(members)))
        null = vt[rank:]
        free = tuple(m for i, m in enumerate(members) if np.abs(null[:, i]).max() > 1e-9)
        x, *_ = np.linalg.lstsq(a, b, rcond=None) if len(a) else (np.zeros(len(members)),)
        known = {m: float(x[i]) for i, m in enumerate(members) if m not in free}
        return TrainSolution(train, known, dof, "under", free,
                             Text("train.under", dof=dof, inputs=len(train.inputs),
                                  free=", ".join(map(str, free)), more=dof - len(train.inputs)))
    x, *_ = np.linalg.lstsq(a, b, rcond=None)
    residual = float(np.abs(a @ x - b).max())
    if residual > 1e-9 * scale:
        return TrainSolution(train, {}, dof, "over", (),
                             Text("train.over", dof=dof, inputs=len(train.inputs)))
    x[np.abs(x) <= 1e-12 * scale] = 0.0  # a member at rest is at rest, not at 1e-15 rad/s
    omega = {m: float(x[i]) + 0.0 for i, m in enumerate(members)}
    if dof == 1 and train.inputs and not any(omega.values()):
        unit = solve_train(train.with_(inputs=tuple(
            dataclasses.replace(i, omega=1.0, velocity=None) for i in train.inputs[:1])))
        return TrainSolution(train, omega, dof, "solved", unit=unit.omega,
                             message=Text("train.at_rest"))
    return TrainSolution(train, omega, dof, "solved")


@dataclass(frozen=True)
class Stage:
    """The meshes seen from one carrier (None: the gears on fixed axes), the way the book
    solves a train stage by stage: each member's speed relative to the carrier, and the
    stage's Willis ratio between its two end members, from the radii (∓ the product of the
    mesh ratios along the stage) and from the solved speeds."""

    carrier: int | None
    members: tuple[int, ...]  # the stage's gears, in mesh order
    relative: dict[int, float]  # ω_m − ω_c, rad/s
    ends: tuple[int, int]  # a, b of i^c_ab = (ω_a − ω_c)/(ω_b − ω_c)
    ratio: float | None  # from the radii (None when the ends are not joined by the stage)
    solved: float  # from the speeds (NaN when ω_b = ω_c)


def stages(solution: TrainSolution) -> list[Stage]:
    """One stage per carrier (the frame's first), with its ends: the two central gears a
    planetary stage turns between (sun and ring), or a fixed-axes chain's first and last."""
    train, omega = solution.train, solution.omega
    table = willis_table(train)
    scale = speed_scale(omega)
    out = []
    for carrier in dict.fromkeys(w.carrier for w in table):
        own = [w for w in table if w.carrier == carrier]
        members = tuple(dict.fromkeys(m for w in own for m in (w.a, w.b)))
        edges = _stage_edges(train, carrier, own, members)
        central = [m for m in members if train.members[m].carrier is None]
        ends = _ends(edges, central if carrier is not None and len(central) >= 2 else members)
        c = 0.0 if carrier is None else omega.get(carrier, math.nan)
        relative = {m: settled(omega.get(m, math.nan) - c, scale) for m in members}
        below = relative[ends[1]]
        solved = relative[ends[0]] / below if abs(below) > 1e-9 * scale else math.nan
        out.append(Stage(carrier, members, relative, ends, _path_ratio(edges, *ends), solved))
    return out


def _stage_edges(train: GearTrain, carrier: int | None, meshes: list[Willis],
                 members: tuple[int, ...]) -> dict:
    """member → {neighbour: (ω_m − ω_c)/(ω_n − ω_c)}: meshes, and shafts joining two of the
    stage's planets (they turn together, so the ratio is 1). A shaft joining two central
    gears is no path of the stage: it locks the stage (a differential driving straight)."""
    def locked(m: int) -> bool:  # a central gear of a planetary stage
        return carrier is not None and train.members[m].carrier is None

    edges: dict[int, dict[int, float]] = {m: {} for m in members}
    for w in meshes:
        edges[w.a][w.b] = w.ratio
        edges[w.b][w.a] = 1.0 / w.ratio
    for shaft in train.shafts:
        on = [m for m in shaft if m in edges]
        for a in on:
            for b in on:
                if a != b and not (locked(a) and locked(b)):
                    edges[a][b] = 1.0
    return edges


def _ends(edges: dict, candidates: list[int] | tuple[int, ...]) -> tuple[int, int]:
    """The two candidates farthest apart along the stage (its first and last gear)."""
    best = (candidates[0], candidates[-1])
    longest = -1
    for a in candidates:
        hops = _hops(edges, a)
        for b in candidates:
            if b != a and hops.get(b, -1) > longest:
                best, longest = (a, b), hops[b]
    return best


def _hops(edges: dict, start: int) -> dict[int, int]:
    seen, frontier = {start: 0}, [start]
    while frontier:
        nxt = []
        for m in frontier:
            for n in edges[m]:
                if n not in seen:
                    seen[n] = seen[m] + 1
                    nxt.append(n)
        frontier = nxt
    return seen


def _path_ratio(edges: dict, a: int, b: int) -> float | None:
    """The product of the mesh ratios along the stage from a to b (breadth first)."""
    ratio, frontier = {a: 1.0}, [a]
    while frontier and b not in ratio:
        nxt = []
        for m in frontier:
            for n, r in edges[m].items():
                if n not in ratio:
                    ratio[n] = ratio[m] * r
                    nxt.append(n)
        frontier = nxt
    return ratio.get(b)
