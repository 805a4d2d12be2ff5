"""A gear train solved the way the collection's chapter 6 does it by hand (task 6.1): from the
input, one unknown speed per equation — shafts, gears on fixed axes mesh by mesh, then each
carrier's stage between its two central gears, planets last — until the speed of every member,
and so the total ratio, is known.

The speeds are carried through these equations on their own, not read from the linear system
of ``solvers.gears``, so the two solutions check each other. A train whose speeds no single
equation can reach (a closed loop of stages) ends with a step that solves the rest together.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from mechanisms.gears import GearTrain
from solvers.gears import Stage, TrainSolution, settled, speed_scale, stages, willis_table


@dataclass(frozen=True)
class SpeedStep:
    """One member's speed found from one equation (``kind``: input, fixed, shaft, mesh, stage
    or system), written with its numbers."""

    member: int
    omega: float  # rad/s
    kind: str
    latex: str
    carrier: int | None = None  # the carrier the equation is written relative to


def _n(x: float) -> str:
    """A number in an equation, bracketed when negative so signs never run together."""
    text = f"{x:.5g}"
    return f"({text})" if text.startswith("-") else text


def _w(m: int) -> str:
    return f"\\omega_{{{m}}}"


# an equation: (ω_a − ω_c) = i·(ω_b − ω_c) between members a, b and carrier c (None: ω_c = 0)
Relation = tuple[int, int, int | None, float, str]  # a, b, c, i, kind


def _relations(solution: TrainSolution) -> list[Relation]:
    """Fixed-axes meshes first (the book goes gear by gear there), then each carrier's stage
    between its central gears, then the meshes that give the planets."""
    table = willis_table(solution.train)
    fixed = [(w.a, w.b, None, w.ratio, "mesh") for w in table if w.carrier is None]
    staged = [(s.ends[0], s.ends[1], s.carrier, s.ratio, "stage") for s in stages(solution)
              if s.carrier is not None and s.ratio is not None]
    planets = [(w.a, w.b, w.carrier, w.ratio, "mesh") for w in table if w.carrier is not None]
    return fixed + staged + planets


def _solve_relation(rel: Relation, known: dict[int, float], shafts: tuple[tuple[int, ...], ...],
                    scale: float) -> tuple[int, float, str] | None:
    """The one unknown of a relation with the other two known, and its equation; or both
    ends of a stage whose ends share a shaft (a differential driving straight), which then
    turn with the carrier. A result of round-off size against ``scale`` is written as 0."""
    a, b, c, i, _ = rel
    members = (a, b) if c is None else (a, b, c)
    unknown = [m for m in members if m not in known]
    if c is None:
        name, ratio = f"i_{{{a},{b}}}", f"\\frac{{{_w(a)}}}{{{_w(b)}}}"
    else:
        name = f"i^{{{c}}}_{{{a},{b}}}"
        ratio = f"\\frac{{{_w(a)} - {_w(c)}}}{{{_w(b)} - {_w(c)}}}"
    equation = f"{name} = {ratio} = {_n(i)}"
    if (unknown == [a, b] and c is not None and abs(1.0 - i) > 1e-12
            and any(a in shaft and b in shaft for shaft in shafts)):
        return a, known[c], _lines(f"{_w(a)} = {_w(b)},\\quad {equation}",
                                   f"{_w(a)} = {_w(c)}", f"{known[c]:.5g}")
    if len(unknown) != 1:
        return None
    x = unknown[0]
    if c is None:
        if x == b:
            value = settled(known[a] / i, scale)
            return x, value, _lines(equation, f"{_w(b)} = \\frac{{{_w(a)}}}{{{name}}}",
                                    f"\\frac{{{_n(known[a])}}}{{{_n(i)}}} = {value:.5g}")
        value = settled(i * known[b], scale)
        return x, value, _lines(equation, f"{_w(a)} = {name}\\,{_w(b)}",
                                f"{_n(i)}\\cdot{_n(known[b])} = {value:.5g}")
    wc = known.get(c)
    if x == b:
        value = settled(wc + (known[a] - wc) / i, scale)
        return x, value, _lines(equation, f"{_w(b)} = {_w(c)} + \\frac{{{_w(a)} - {_w(c)}}}{{{name}}}",
                                f"{_n(wc)} + \\frac{{{_n(known[a])} - {_n(wc)}}}{{{_n(i)}}} = {value:.5g}")
    if x == a:
        value = settled(wc + i * (known[b] - wc), scale)
        return x, value, _lines(equation, f"{_w(a)} = {_w(c)} + {name}\\,({_w(b)} - {_w(c)})",
                                f"{_n(wc)} + {_n(i)}\\cdot({_n(known[b])} - {_n(wc)}) = {value:.5g}")
    if abs(1.0 - i) < 1e-12:
        return None  # i = 1: the carrier's speed does not follow from this stage
    value = settled((known[a] - i * known[b]) / (1.0 - i), scale)
    return x, value, _lines(equation, f"{_w(c)} = \\frac{{{_w(a)} - {name}\\,{_w(b)}}}{{1 - {name}}}",
                            f"\\frac{{{_n(known[a])} - {_n(i)}\\cdot{_n(known[b])}}}{{1 - {_n(i)}}}"
                            f" = {value:.5g}")


def _lines(equation: str, solved_for: str, numbers: str) -> str:
    """The equation, what it gives for the unknown, and that with the numbers — one line each,
    so a long stage never runs off a narrow page."""
    return (f"\\begin{{gathered}}{equation}\\\\ \\Rightarrow\\; {solved_for}\\\\"
            f" = {numbers}\\end{{gathered}}")


def speed_steps(solution: TrainSolution) -> list[SpeedStep]:
    """Every member's speed in the book's order (empty unless the train is solved)."""
    if solution.status != "solved":
        return []
    train = solution.train
    known: dict[int, float] = {}
    out: list[SpeedStep] = []

    scale = speed_scale(solution.omega)

    def found(member: int, omega: float, kind: str, latex: str, carrier: int | None = None) -> None:
        known[member] = omega
        out.append(SpeedStep(member, omega, kind, latex, carrier))

    for inp in train.inputs:
        given = (f"{_w(inp.member)} = \\frac{{v}}{{R}} = \\frac{{{_n(inp.velocity)}}}{{{_n(inp.radius)}}}"
                 if inp.velocity is not None and inp.radius else _w(inp.member))
        found(inp.member, inp.omega, "input", f"{given} = {inp.omega:.5g}")
    for m in train.fixed:
        found(m, 0.0, "fixed", f"{_w(m)} = 0")
    relations = _relations(solution)
    while (step := _first(train, relations, known, scale)) is not None:
        found(*step)
    # what no single equation reaches (stages that need each other) comes from the system
    for m in [m for m in train.members if m not in known]:
        found(m, solution.omega[m], "system", f"{_w(m)} = {solution.omega[m]:.5g}")
    return out


def _first(train: GearTrain, relations: list[Relation], known: dict[int, float],
           scale: float) -> tuple[int, float, str, str, int | None] | None:
    """The first equation with one unknown: a shaft before any mesh, so a speed found is
    passed along its shaft at once, as the book does."""
    for shaft in train.shafts:
        source = next((m for m in shaft if m in known), None)
        target = next((m for m in shaft if m not in known), None)
        if source is not None and target is not None:
            return target, known[source], "shaft", f"{_w(target)} = {_w(source)} = {known[source]:.5g}", None
    for rel in relations:
        solved = _solve_relation(rel, known, train.shafts, scale)
        if solved is not None:
            member, value, latex = solved
            return member, value, rel[4], latex, rel[2]
    return None


def total_ratio(steps: list[SpeedStep], a: int, b: int) -> str | None:
    """i_ab = ω_a/ω_b with the speeds the steps found (None when member b stands still)."""
    omega = {s.member: s.omega for s in steps}
    if a not in omega or b not in omega or omega[b] == 0.0:
        return None
    return (f"i_{{{a},{b}}} = \\frac{{{_w(a)}}}{{{_w(b)}}} = \\frac{{{_n(omega[a])}}}{{{_n(omega[b])}}}"
            f" = {omega[a] / omega[b]:.5g}")


def stage_latex(stage: Stage, radii: str = "radii") -> str:
    """i^c_ab = (ω_a − ω_c)/(ω_b − ω_c) = (numbers) = value, then the value from the radii
    after the word ``radii`` (in the reader's language). Both ends turning with the carrier
    (0/0) leave only the radii's value."""
    a, b = stage.ends
    c = stage.carrier
    if c is None:
        head = f"i_{{{a},{b}}} = \\frac{{\\omega_{{{a}}}}}{{\\omega_{{{b}}}}}"
    else:
        head = (f"i^{{{c}}}_{{{a},{b}}} = \\frac{{\\omega_{{{a}}} - \\omega_{{{c}}}}}"
                f"{{\\omega_{{{b}}} - \\omega_{{{c}}}}}")
    numbers = f"\\frac{{{stage.relative[a]:.5g}}}{{{stage.relative[b]:.5g}}}"
    out = f"{head} = {numbers}" + ("" if math.isnan(stage.solved) else f" = {stage.solved:.5g}")
    return out if stage.ratio is None else f"{out},\\quad \\text{{{radii}: }} {{{stage.ratio:.5g}}}"
