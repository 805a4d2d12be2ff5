"""One judge (methods.judge, issue 62): for every asked value of a task of every chapter
that prints its answers (a few variants each), a typed value gets the same diagnosis from
practice's grader, the pages' self-check box, ``python -m solvers check`` and Moodle's rule
over the written XML (the first answer whose interval holds it): the key ± 0.99 of its
tolerance is right and ± 1.01 is not; 0, −key and 10ᵏ·key are named alike in all four."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import pytest

from cli import main
from exams.moodle import asked_steps, choices, moodle_xml
from methods.judge import COMPUTED, judge, tolerance
from methods.practice import grade
from ui.i18n import table
from ui.selfcheck import Quantity, verdict

from .test_moodle import TASKS, made, parts_of


def typed_values(exact: float, tol: float) -> list[float]:
    return [exact + 0.99 * tol, exact - 0.99 * tol, exact + 1.01 * tol, exact - 1.01 * tol,
            0.0, -exact, *(exact * 10.0 ** k for k in (-7, -3, -1, 1, 2, 3, 7))]


def moodle_says(answers, response: float) -> int:
    """The index of the first written answer whose interval holds the response."""
    return next(i for i, (_, value, tol, _) in enumerate(answers)
                if value is None or abs(response - value) <= tol)


@pytest.mark.parametrize("task", TASKS)
def test_practice_self_check_command_line_and_moodle_agree(task, capsys):
    found = made(task, 2)
    root = ET.fromstring(moodle_xml(found, task, "en", table("en").__getitem__).encode())
    for question, variant in zip(root.findall("question")[1:], found.variants):
        written = parts_of(question.findtext("questiontext/text"))
        for (answer, step), answers in zip(asked_steps(variant), written):
            parts = choices(step)
            assert len(parts) == len(answers)
            quantity = Quantity(answer.key, answer.value, answer.unit, answer.tolerance, step.missing)
            for typed in typed_values(answer.value, step.tolerance) + [t.value for t in step.missing]:
                ours = judge(step, typed).diagnosis
                assert grade(step, typed).diagnosis == ours
                assert verdict(typed, quantity)[0].diagnosis == ours
                assert parts[moodle_says(answers, typed)].diagnosis == ours, (answer.key, typed)
            for typed, right in ((answer.value + 0.99 * step.tolerance, True),
                                 (answer.value + 1.01 * step.tolerance, False)):
                assert judge(step, typed).ok is right, (variant.code, answer.key, typed)
                assert main(["check", variant.code, answer.key, repr(typed), "--json"]) == 0
                said = json.loads(capsys.readouterr().out)
                assert (said["diagnosis"] == "ok") is right
                assert said["tolerance"] == pytest.approx(step.tolerance)


def test_the_one_tolerance_rule():
    assert tolerance(156.25, 0.5) == 0.5  # read off a drawing: the drawing's error, even < 0.5 %
    assert tolerance(200.0) == pytest.approx(COMPUTED * 200.0)  # computed: its rounding
    assert tolerance(0.0) == COMPUTED


def test_the_self_check_says_the_drawing_s_tolerance_where_practice_does():
    """a_E of variant 3.1-S42-02F is 156,25 ± 0,5: 156,875 was "correct, within 0.5 %"."""
    quantity = Quantity("a_E", 156.25, "m/s²", drawing=0.5)
    assert verdict(156.875, quantity)[0].diagnosis == "length"
    assert verdict(156.6, quantity)[0].ok


def test_check_refuses_in_words(capsys):
    for args in (["check", "zbirka-3.1", "points.Z.v", "1"], ["check", "zbirka-3.1", "points.E.a", "1,5"],
                 ["check", "3.1-S42-02X", "points.E.a", "1"], ["check", "zbirka-3.1", "points.E.a", "abc"]):
        assert main(args) == 2, args
        assert capsys.readouterr().err.startswith("error: ")
    assert main(["check", "zbirka-3.1", "points.E.a", "1,5", "--language", "sr", "--json"]) == 0
    assert set(json.loads(capsys.readouterr().out)) == {"name", "exact", "unit", "tolerance",
                                                        "diagnosis", "hint"}
