"""Variants as a Moodle question bank (exams/moodle.py): the file is the XML Moodle's
importer reads, each variant one cloze question whose parts hold the key and the usual
mistakes, and Moodle's rule (the first answer whose interval holds the response) gives each
planted answer the words the app's own grader gives it."""

from __future__ import annotations

import base64
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from exams.codes import Settings
from exams.moodle import asked_steps, choices, matching, moodle_xml
from exams.variants import generate
from mechanisms.gears import GearTrain
from mechanisms.rotor import Rotor
from methods.practice import grade
from ui.i18n import table

# a task of every chapter that has a key
TASKS = ["zbirka-2.1", "zbirka-3.1", "zbirka-4.1", "zbirka-5.1", "zbirka-6.1", "zbirka-7.1"]
PART = re.compile(r"\{1:NUMERICAL:(.*?)\}(?= )")
# a number as Moodle's cloze reads it (question/type/multianswer/questiontype.php)
NUMBER = re.compile(r"-?(([0-9]+[.,]?[0-9]*|[.,][0-9]+)([eE][-+]?[0-9]+)?)")


def made(task: str, count: int = 3):
    return generate(Settings(task, 7), count)


def parts_of(text: str) -> list[list[tuple[str, float | None, float | None, str]]]:
    """Each NUMERICAL part of a cloze text as (fraction, value, tolerance, feedback), read as
    Moodle's cloze parser reads it (answers split at unescaped ~, feedback after #)."""
    out = []
    for body in PART.findall(text):
        answers = []
        for answer in re.split(r"(?<!\\)~", body):
            head, _, feedback = answer.partition("#")
            fraction, _, rest = (head[1:].partition("%") if head.startswith("%") else ("100", "", head[1:]))
            value, tolerance = (None, None) if rest == "*" else map(float, rest.split(":"))
            assert rest == "*" or all(NUMBER.fullmatch(n) for n in rest.split(":")), rest
            answers.append((fraction, value, tolerance, re.sub(r"\\(.)", r"\1", feedback)))
        out.append(answers)
    return out


@pytest.mark.parametrize("language", ["sr", "en"])
@pytest.mark.parametrize("task", TASKS)
def test_the_file_has_what_moodles_importer_reads(task, language):
    found = made(task)
    root = ET.fromstring(moodle_xml(found, task, language, table(language).__getitem__).encode())
    assert root.tag == "quiz"
    category, *questions = root.findall("question")
    assert category.get("type") == "category"
    assert category.findtext("category/text") == "$course$/top/" + (
        f"Varijante zadatka {task} (seme 7, ± 20 %)" if language == "sr"
        else f"Variants of {task} (seed 7, ± 20 %)")
    assert len(questions) == len(found.variants)
    for question, variant in zip(questions, found.variants):
        assert question.get("type") == "cloze"
        assert question.findtext("name/text") == variant.code == question.findtext("idnumber")
        assert question.find("questiontext").get("format") == "html"
        for tag in ("generalfeedback", "penalty", "hidden"):
            assert question.find(tag) is not None, tag
        text = question.findtext("questiontext/text")
        asked = [a for a in variant.key if a.asked]
        assert len(parts_of(text)) == len(asked)
        assert ("3,8266" if language == "sr" else "3.8266") in text  # how to type a decimal
        for g, value in variant.given:  # the given values, the language's way
            shown = f"{value:.6g}"
            assert (shown.replace(".", ",") if language == "sr" else shown) in text
        for file in question.findall("questiontext/file"):  # the drawing, carried in the file
            assert f'@@PLUGINFILE@@/{file.get("name")}' in text
            assert base64.b64decode(file.text).startswith(b"<svg")
        assert len(question.findall("questiontext/file")) == (
            1 if variant.drawn or isinstance(variant.scene, GearTrain) else 2 if isinstance(variant.scene, Rotor) else 0)
        for answers in parts_of(text):
            assert answers[0][0] == "100" and answers[-1][1] is None  # key first, catch-all last
            assert all("." in f"{v!r}" or "e" in f"{v!r}" for _, v, _, _ in answers if v)


def planted(step, rng) -> list[float]:
    """Answers as the practice tests plant them: exact, reversed, ten times, a tenth, each
    term left out, and random wrong values."""
    x = float(step.expected)
    return [x, -x, 10 * x, x / 10, *(float(t.value) for t in step.missing),
            *(x * rng.uniform(-3, 3, 4))]


def test_moodle_gives_each_planted_answer_the_graders_diagnosis():
    """The share of planted answers whose Moodle feedback is the grader's diagnosis (goal
    100 %): printed, and every difference named."""
    rng = np.random.default_rng(3)
    same, differ = 0, []
    for task in TASKS:
        for variant in made(task, 2).variants:
            for _, step in asked_steps(variant):
                parts = choices(step)
                for answer in planted(step, rng):
                    ours, moodles = grade(step, answer).diagnosis, matching(parts, answer).diagnosis
                    if ours == moodles:
                        same += 1
                    else:
                        differ.append((variant.code, step.id, answer, ours, moodles))
    print(f"Moodle's feedback = the grader's diagnosis for {same} of {same + len(differ)} "
          f"planted answers")
    assert not differ, differ
    assert same > 300


def test_the_files_feedback_is_the_practice_hint_and_a_forgotten_term_is_named():
    found = made("zbirka-3.1", 1)
    text = moodle_xml(found, "3.1", "en", table("en").__getitem__)
    root = ET.fromstring(text.encode())
    parts = parts_of(root.find("question[@type='cloze']").findtext("questiontext/text"))
    feedback = [f for part in parts for _, _, _, f in part]
    assert "The size is right, but the sign is reversed." in feedback
    assert any(f.startswith("This is the sum without v_B") for f in feedback)
    assert any("Off by a factor of 10:" in f for f in feedback)


@pytest.mark.server
def test_the_command_line_writes_the_bank_in_the_language_asked(tmp_path):
    import subprocess
    import sys
    from pathlib import Path

    target = tmp_path / "bank.xml"
    done = subprocess.run([sys.executable, "-m", "solvers", "variants", "zbirka-3.1", "--count", "2",
                           "--moodle", str(target), "--language", "sr"],
                          cwd=Path(__file__).resolve().parents[1], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    root = ET.fromstring(target.read_bytes())
    assert len(root.findall("question[@type='cloze']")) == 2
    text = root.find("question[@type='cloze']").findtext("questiontext/text")
    assert "Dato" in text and "Veličina je tačna, ali je znak obrnut." in text
