"""Practice grading (methods.practice) on answers made from the exact solution of every method:
the exact answer, reversed, turned, lengthened, ten times, at the drawing scale, a term left
out, nothing; the step lists of each method; the command line's practice."""

from __future__ import annotations

import cmath
import json

import pytest

from cli import main
from cli.practice import steps_for
from mechanisms import load_preset
from methods.practice import Step, Term, grade, hint_keys, polar
from methods.progress import Progress

CASES = [("compass", "zbirka-1.1"), ("plans", "zbirka-3.1"), ("plans", "analitika-2.1"),
         ("plans", "triad-full-turn"), ("forces", "zbirka-5.1"), ("forces", "predavanja-kinetostatika"),
         ("lever", "zbirka-5.1"), ("willis", "zbirka-6.4"), ("willis", "zbirka-6.9"),
         ("balance", "zbirka-7.1"), ("balance", "zbirka-7.5")]


def _steps(method: str, pid: str) -> list[Step]:
    return steps_for(load_preset(pid), method)


def _big(steps: list[Step]) -> list[Step]:
    """Steps whose answer is well above their tolerance (a zero arrow has no sense)."""
    return [s for s in steps if abs(s.expected) > 20 * s.tolerance]


@pytest.mark.parametrize("method, pid", CASES, ids=[f"{m}-{p}" for m, p in CASES])
def test_every_step_diagnoses_the_usual_mistakes(method, pid):
    steps = _steps(method, pid)
    assert steps
    big = _big(steps)
    assert big, "nothing to grade"
    for s in steps:
        assert grade(s, s.expected).diagnosis == "ok", s.id
        assert grade(s, None).diagnosis == "none"
    for s in big:
        exact = s.expected
        if s.kind == "point":  # a point has no sense or length: only where it is
            continue
        assert grade(s, -exact).diagnosis == "sense", s.id
        longer = grade(s, exact * 1.3)
        assert (longer.diagnosis, round(longer.ratio, 6)) == ("length", 1.3), s.id
        tenfold = grade(s, exact * 10)
        assert (tenfold.diagnosis, tenfold.ratio) == ("scale", 10.0), s.id
        if s.kind == "vector":
            turned = grade(s, exact * cmath.exp(0.5j))
            assert turned.diagnosis == "direction" and round(turned.turn, 3) == round(
                28.6478897565, 3), s.id
            plan_length = exact / s.scale  # a plan length given as the value
            apart = all(abs(plan_length - complex(t.value)) > 2 * s.tolerance for t in s.missing)
            if s.scale not in (1.0, 10.0, 0.1) and apart:  # (else a forgotten term, as well)
                assert grade(s, plan_length).diagnosis == "scale", s.id


@pytest.mark.parametrize("method, pid", [c for c in CASES if c[0] in ("plans", "forces", "balance",
                                                                        "lever")])
def test_a_sum_without_one_of_its_terms_is_named(method, pid):
    found = 0
    for s in _big(_steps(method, pid)):
        for term in s.missing:
            answer = complex(term.value) if s.kind != "scalar" else float(term.value.real
                                                                            if isinstance(term.value, complex) else term.value)
            verdict = grade(s, answer)
            if abs(complex(answer) - complex(s.expected)) > 3 * s.tolerance and verdict.diagnosis == "missing-term":
                assert verdict.term in {t.name for t in s.missing}
                found += 1
    assert found, "no step named a forgotten term"


def test_a_forgotten_coriolis_part_is_named_at_its_step():
    steps = {s.id: s for s in _steps("plans", "zbirka-3.1")}
    coriolis = next(s for s in steps.values() if s.rule == "coriolis")
    image = next(s for s in steps.values() if coriolis.symbol in {t.name for t in s.missing})
    verdict = grade(image, image.expected - coriolis.expected)
    assert verdict.diagnosis == "missing-term" and verdict.term == coriolis.symbol
    assert grade(coriolis, -coriolis.expected).diagnosis == "sense"  # pointed the wrong way


def test_a_forgotten_inertia_force_is_named_in_the_polygon():
    steps = [s for s in _steps("forces", "four-bar-crank-rocker") if s.rule == "closing"]
    step = next(s for s in steps if any(t.name == "F_i3" for t in s.missing))
    forgot = next(t for t in step.missing if t.name == "F_i3")
    assert grade(step, forgot.value).diagnosis == "missing-term"
    assert grade(step, forgot.value).term == "F_i3"


def test_typed_length_and_direction_are_the_same_arrow():
    s = next(s for s in _steps("plans", "zbirka-3.1") if s.kind == "vector")
    z = complex(s.expected)
    assert grade(s, polar(abs(z), cmath.phase(z) * 180 / cmath.pi)).ok


def test_three_wrong_tries_reveal_the_step_and_the_score_counts_it():
    steps = _steps("willis", "zbirka-6.4")
    progress = Progress.start()
    first, second = steps[0], steps[1]
    assert progress.give(first, first.expected).ok
    for _ in range(3):
        progress.give(second, second.expected * 3 + 1)
    assert progress.done(second) and progress.outcome(second) == "revealed"
    score = progress.score(steps)
    assert score["first"] == 1 and score["revealed"] == 1


def test_a_point_near_the_exact_one_is_ok_and_a_slip_of_scale_is_named():
    steps = _steps("compass", "zbirka-1.1")
    s = steps[5]
    assert grade(s, complex(s.expected) + 0.5 * s.tolerance).ok
    assert grade(s, complex(s.expected) + 5 * s.tolerance).diagnosis == "wrong"
    assert grade(s, complex(s.expected) * 10).diagnosis == "scale"


def test_the_command_line_lists_the_steps_and_grades_answers(tmp_path, capsys):
    assert main(["practice", "zbirka-3.1", "--method", "plans", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["scene"] == "zbirka-3.1" and data["method"] == "plans"
    step = next(s for s in data["steps"] if s["terms"])
    assert set(step) == {"id", "asks", "kind", "unit", "expected", "tolerance", "terms"}
    assert step["kind"] == "vector" and len(step["expected"]) == 2
    total = [sum(t["value"][0] for t in step["terms"]), sum(t["value"][1] for t in step["terms"])]
    assert total == pytest.approx(step["expected"], abs=1e-9)  # an image is its terms' sum
    arrow = data["steps"][0]
    answers = {arrow["id"]: [-x for x in arrow["expected"]], step["id"]: step["expected"],
               "omega.3": -4.517}
    path = tmp_path / "answers.json"
    path.write_text(json.dumps({"answers": answers}))
    assert main(["practice", "zbirka-3.1", "--method", "plans", "--answers", str(path),
                 "--json"]) == 0
    graded = json.loads(capsys.readouterr().out)
    results = {r["id"]: r for r in graded["results"]}
    assert results[arrow["id"]]["diagnosis"] == "sense" and "points the other way" in results[arrow["id"]]["hint"]
    assert results[step["id"]]["diagnosis"] == "ok"
    assert results["omega.3"]["diagnosis"] == "ok"
    assert graded["score"] == {"ok": 2, "of": len(data["steps"])}


@pytest.mark.parametrize("args, says", [
    (["practice", "zbirka-3.1", "--method", "willis"], "needs a gear train; this is a linkage"),
    (["practice", "zbirka-6.4", "--method", "plans"], "needs a linkage; this is a gear train"),
    (["practice", "no-such-task", "--method", "plans"], "no-such-task"),
])
def test_a_scene_that_cannot_be_practised_gets_a_message_and_code_2(args, says, capsys):
    assert main(args) == 2
    assert says in capsys.readouterr().err


def test_a_bad_answers_file_gets_a_message_and_code_2(tmp_path, capsys):
    path = tmp_path / "a.json"
    for text, says in (("{", "is not JSON"), ('{"x": 1}', 'must hold {"answers"'),
                       ('{"answers": {"v.b": 3}}', "v.b must be a pair [x, y]"),
                       ('{"answers": {"omega.3": [1, 2]}}', "omega.3 must be a finite number"),
                           ('{"answers": {"omega.3": NaN}}', "NaN, which is not a number"),
                           ('{"answers": {"omega.3": 1e309}}', "omega.3 must be a finite number"),
                       ('{"answers": {"v.zz": [1, 2], "v.b": [0, 3]}}', "no step 'v.zz'")):
        path.write_text(text)
        assert main(["practice", "zbirka-3.1", "--method", "plans", "--answers", str(path)]) == 2
        assert says in capsys.readouterr().err
    with pytest.raises(SystemExit) as stopped:  # (the command line's own check of a file)
        main(["practice", "zbirka-3.1", "--method", "plans", "--answers", str(tmp_path / "none.json")])
    assert stopped.value.code == 2 and "none.json' does not exist" in capsys.readouterr().err


def test_a_missing_term_candidate_is_the_sum_without_it():
    s = Step("x", "", "x", "vector", "m/s", 3 + 4j, 0.05, 1.0,
             terms=(Term("a", 1 + 0j), Term("b", 2 + 4j)), missing=(Term("a", 2 + 4j), Term("b", 1 + 0j)))
    assert grade(s, 2 + 4j).term == "a" and grade(s, 1 + 0j).term == "b"
    assert grade(s, 3 + 4.04j).ok and grade(s, 5 + 5j).diagnosis == "wrong"


def test_any_scene_practises_a_link_and_an_exam_variant():
    from exams.codes import Settings
    from exams.variants import from_code, generate
    from mechanisms.link import decode, encode

    scene = load_preset("zbirka-3.1")
    linked = steps_for(decode(encode(scene)), "plans")
    direct = steps_for(scene, "plans")
    assert [s.id for s in linked] == [s.id for s in direct]
    assert all(abs(a.expected - b.expected) < 1e-12 * max(1.0, abs(b.expected))
               for a, b in zip(linked, direct))
    variant = generate(Settings("zbirka-3.1", 7), 1).variants[0]
    steps = steps_for(from_code(variant.code).scene, "plans")
    assert steps and all(grade(s, s.expected).ok for s in steps)
    book = {s.id: s.expected for s in steps_for(scene, "plans")}
    assert any(abs(complex(s.expected) - complex(book.get(s.id, 0))) > s.tolerance for s in steps)


def test_the_command_lines_hints_write_names_as_text_not_latex(tmp_path, capsys):
    """A forgotten Coriolis part is named aᵏ_… as the pages write it, not a^k_{…}."""
    steps = steps_for(load_preset("zbirka-3.1"), "plans")
    step = next(s for s in steps if any(m.name.startswith("a^k") for m in s.missing))
    term = next(m for m in step.missing if m.name.startswith("a^k"))
    path = tmp_path / "answers.json"
    path.write_text(json.dumps({"answers": {step.id: [term.value.real, term.value.imag]}}))
    assert main(["practice", "zbirka-3.1", "--method", "plans", "--answers", str(path),
                 "--json"]) == 0
    (result,) = [r for r in json.loads(capsys.readouterr().out)["results"] if r["id"] == step.id]
    assert result["diagnosis"] == "missing-term"
    assert "aᵏ_" in result["hint"] and "{" not in result["hint"] and "^" not in result["hint"]


def test_a_scalar_step_speaks_of_a_value_and_its_sign():
    step = Step("omega.3", "", "\\omega_3", "scalar", "s⁻¹", 4.5, 0.05, rule="rate")
    assert hint_keys(step, grade(step, -4.5))[0] == "practice.value_sense"
    assert hint_keys(step, grade(step, 45.0))[0] == "practice.value_scale"
    assert hint_keys(step, grade(step, 3.0))[0] == "practice.value_length"
    arrow = Step("v.b", "", "v_B", "vector", "m/s", 3 + 4j, 0.05)
    assert hint_keys(arrow, grade(arrow, -3 - 4j))[0] == "practice.hint_sense"
