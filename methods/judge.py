"""One judge for a typed value of a named quantity (issue 62): whether it is right and, if
not, which usual mistake it looks like — the same verdict in practice, the pages' self-check
box, ``python -m solvers check`` and the Moodle bank (exams/moodle.py writes its answers
from it, in the order it tries them).

One tolerance rule (docs/practice.md): a value read off a drawing is right within the error
a drawing at the task's scales allows (``drawing``); a value computed, not drawn, within
``COMPUTED`` of it (the rounding a hand calculation carries). Where a drawing's error is
known it wins, smaller than 0.5 % or not: a student who reads a plan is held to the plan.
The verdict itself is the practice grader's (``methods.practice.grade`` of a scalar step).
"""

from __future__ import annotations

import math
import re

from mechanisms.rotor import Rotor
from mechanisms.schema import Scene
from methods.plans import build, readings
from methods.practice import Step, Term, Verdict, grade
from methods.scales import PRECISION_CM, plan_scales
from solvers.balancing import balance, graphical_error
from solvers.diagnostics import Unsolvable, solve_instant
from solvers.structure import StructureError

COMPUTED = 0.005  # a computed value: right within 0.5 % of it


def tolerance(exact: float, drawing: float | None = None) -> float:
    """The one rule: the drawing's error where the value is read off a drawing, else 0.5 %
    of the value (of 1 for a value of 0)."""
    if drawing is not None:
        return float(drawing)
    return COMPUTED * abs(exact) or COMPUTED


def drawing_errors(scene, task_scene=None) -> dict[str, float]:
    """Result key → the error a drawing at the task's scales allows, for every value read
    off a drawing (a plan's speeds, accelerations, ω and ε; a force polygon's sides; a
    rotor's corrections): the task's printed scales (``task_scene``'s, a variant's task),
    else the round ones the plans page draws at (methods.scales.plan_scales). Practice's
    typed steps, the self-check box, ``check`` and the Moodle bank take their tolerance
    from here (through ``tolerance``)."""
    task_scene = task_scene or scene
    if isinstance(scene, Rotor):
        return _rotor_errors(scene)
    if not isinstance(scene, Scene):
        return {}
    try:
        plans = build(solve_instant(scene, None))
    except (Unsolvable, StructureError, NotImplementedError, KeyError):
        plans = None  # a class III group: its plans are not drawn here
    scales = {**plan_scales(scene, plans), **task_scene.scales}
    out = {}
    for point in scene.point_names:
        out[f"points.{point}.v"] = PRECISION_CM * scales["v"]
        out[f"points.{point}.a"] = PRECISION_CM * scales["a"]
    for pair in scene.pairs:
        out[f"sliders.{pair.name}.v"] = PRECISION_CM * scales["v"]
        out[f"sliders.{pair.name}.a"] = PRECISION_CM * scales["a"]
    if "F" in scales:
        for a in scene.members:
            for b in [1, *scene.members]:
                out[f"reactions.{a}-{b}.magnitude"] = PRECISION_CM * scales["F"]
                out[f"reactions.{b}-{a}.magnitude"] = PRECISION_CM * scales["F"]
    for r in readings(plans, scales, PRECISION_CM) if plans is not None else ():
        name, member = r.symbol.split("_", 1)
        quantity = {"\\omega": "omega", "\\varepsilon": "epsilon"}.get(name)
        if quantity:
            out[f"members.{member.strip('{}')}.{quantity}"] = r.uncertainty
    return out


def _rotor_errors(rotor: Rotor) -> dict[str, float]:
    """A polygon drawn at a scale that fits 10 cm, read to half a mm."""
    found = balance(rotor)
    out = {}
    sizes = [m.mass * m.radius for m in rotor.masses]
    scale = max(sizes) / 0.1  # kg·m per metre of drawing
    for plane, f in found.corrections.items():
        length, angle = graphical_error(f.mass * f.radius, scale, PRECISION_CM / 100,
                                        vectors=len(sizes) + 1)
        out[f"corrections.{plane}.mass"] = length / f.radius
        out[f"corrections.{plane}.radius"] = length / f.mass
        out[f"corrections.{plane}.angle_deg"] = math.degrees(angle)
    return out


# a practice step that asks a named result: its id → the result's key (the same value, so
# the same tolerance and verdict as the self-check box, ``check`` and Moodle give it)
NAMED = ((re.compile(r"(omega|epsilon)\.(\d+)"), r"members.\2.\1"),
         (re.compile(r"willis\.(\d+)"), r"members.\1.omega"),
         (re.compile(r"forces\.\d+\.F_(\d)(\d)\^t"), r"reactions.\1-\2.tangential"),
         (re.compile(r"forces\.\d+\.F_(\d)(\d)\^n"), r"reactions.\1-\2.normal"),
         (re.compile(r"(?:forces\.\d+|lever)\.M_p"), "driving.torque"),
         (re.compile(r"lever\.F_p"), "driving.force"))


def named_key(step_id: str) -> str | None:
    """The result key a practice step asks (``omega.3`` → ``members.3.omega``), or None for
    a step no other surface asks (an arrow, a moment's product)."""
    for pattern, key in NAMED:
        if pattern.fullmatch(step_id):
            return pattern.sub(key, step_id)
    return None


def rule_of(key: str, gears: bool = False) -> str:
    """The book's rule a named value's hint adds (methods.practice.RULES) — the one a
    practice step asking that value has too, so that its hint is said alike everywhere: ω
    and ε from a plan, a gear's ω by Willis, a reaction's part from a moment equation, the
    driving torque or force from the balance of moments."""
    head, _, last = key.rpartition(".")
    if head.startswith("members.") and last in ("omega", "epsilon"):
        return "stage" if gears else "rate"
    if head.startswith("reactions.") and last in ("tangential", "normal"):
        return "moment"
    if head == "driving" and last in ("torque", "force"):
        return "balancing"
    return ""


def value_step(name: str, exact: float, unit: str, drawing: float | None = None,
               missing: tuple[Term, ...] = (), symbol: str = "", rule: str = "") -> Step:
    """A named value as a scalar step the grader judges: its exact value, the one rule's
    tolerance, the values a left-out term would give, and the book's rule its hint adds
    (``rule_of``)."""
    return Step(name, name, symbol or name, "scalar", unit, float(exact),
                tolerance(exact, drawing), missing=missing, rule=rule, computed=drawing is None)


def left_out_sizes(step: Step) -> tuple[Term, ...]:
    """A plan's sum step (a point's v or a) as a value to type: the size the point's speed
    or acceleration has with each term left out — what a student who forgot that term
    types. The self-check box and the Moodle bank name those mistakes alike."""
    return tuple(Term(term.name, abs(complex(term.value))) for term in step.missing)


def judge(step: Step, typed: float) -> Verdict:
    """The verdict of ``typed`` (in the step's unit) for the value ``step`` asks."""
    return grade(step, float(typed))
