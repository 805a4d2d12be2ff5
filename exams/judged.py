"""The one table of judged quantities (issue 67): every value a person may type for a scene —
a task's asked values, and what its chapter page's self-check box grades besides
(exams.variants.answers) — as the one judge's step (methods.judge.value_step): its exact
value, its one tolerance (a drawing's where it is read off one, else 0.5 %), its sign, and
the values a left-out term would give. The self-check box, ``python -m solvers check`` and
the Moodle bank take their quantities from here, so none can add one with a rule of its own;
practice's typed steps that ask the same value take the same tolerance (methods.judge)."""

from __future__ import annotations

from exams.variants import Answer, answers, symbol
from figures.plans import plain
from mechanisms.gears import GearTrain
from mechanisms.schema import Scene
from methods import practice_steps
from methods.judge import left_out_sizes, rule_of, value_step
from methods.plans import build
from methods.practice import Step, Term
from methods.scales import plan_scales
from reports.values import has_loads
from solvers.diagnostics import Unsolvable, solve_instant
from solvers.kinetostatics import analyse
from solvers.structure import StructureError


def judged_steps(scene, named: list[Answer]) -> list[tuple[Answer, Step]]:
    """Each named value of ``scene`` (``answers(scene, task)``, or a variant's key) as the
    judge's step."""
    terms, gears = left_out(scene), isinstance(scene, GearTrain)
    return [(answer, value_step(answer.key, answer.value, answer.unit, answer.tolerance,
                                terms.get(answer.key, ()), symbol(answer.key),
                                rule_of(answer.key, gears)))
            for answer in named]


def table(scene, task_scene=None) -> list[tuple[Answer, Step]]:
    """The scene's judged quantities (its task's scales and asked values: ``task_scene``,
    the scene itself by default)."""
    return judged_steps(scene, answers(scene, task_scene or scene))


def left_out(scene) -> dict[str, tuple[Term, ...]]:
    """For a linkage: result key → the values a left-out term gives: a point's v or a with
    one term of its plan's sum left out, M_p and F_p with one load's moment left out."""
    if not isinstance(scene, Scene):
        return {}
    try:
        motion = solve_instant(scene, None)
        plans = build(motion)
    except (Unsolvable, StructureError, NotImplementedError, KeyError):
        return {}  # a class III group: its plans are not drawn
    out = {}
    if has_loads(scene):  # M_p and F_p with a load's moment left out (the lever's, as practice)
        force, torque = practice_steps.balancing_missing(analyse(scene, motion=motion), 0)
        out["driving.force"] = tuple(Term(plain(t.name), t.value) for t in force)
        out["driving.torque"] = tuple(Term(plain(t.name), t.value) for t in torque)
    names = {n.lower(): n for n in scene.point_names}
    for step in practice_steps.plans(plans, plan_scales(scene, plans)):
        kind, _, point = step.id.partition(".")
        if step.rule == "sum" and kind in ("v", "a") and point in names:
            out[f"points.{names[point]}.{kind}"] = tuple(
                Term(plain(t.name), t.value) for t in left_out_sizes(step))
    return out
