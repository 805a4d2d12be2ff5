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

from methods.practice import Step, Term, Verdict, grade

COMPUTED = 0.005  # a computed value: right within 0.5 % of it


def tolerance(exact: float, drawing: float | None = None) -> float:
    """The one rule: the drawing's error where the value is read off a drawing, else 0.5 %
    of the value (of 1 for a value of 0)."""
    if drawing is not None:
        return float(drawing)
    return COMPUTED * abs(exact) or COMPUTED


def value_step(name: str, exact: float, unit: str, drawing: float | None = None,
               missing: tuple[Term, ...] = (), symbol: str = "") -> Step:
    """A named value as a scalar step the grader judges: its exact value, the one rule's
    tolerance, and the values a left-out term would give."""
    return Step(name, name, symbol or name, "scalar", unit, float(exact),
                tolerance(exact, drawing), missing=missing, rule="")


def left_out_sizes(step: Step) -> tuple[Term, ...]:
    """A plan's sum step (a point's v or a) as a value to type: the size the point's speed
    or acceleration has with each term left out — what a student who forgot that term
    types. The self-check box and the Moodle bank name those mistakes alike."""
    return tuple(Term(term.name, abs(complex(term.value))) for term in step.missing)


def judge(step: Step, typed: float) -> Verdict:
    """The verdict of ``typed`` (in the step's unit) for the value ``step`` asks."""
    return grade(step, float(typed))
