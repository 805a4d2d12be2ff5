"""Book vs exact: verdicts computed from the data, never from the printed numbers."""

import dataclasses
import math

import pytest

from mechanisms import load_preset
from reports.textbook import check, printed_unit, verdict


def test_the_printed_precision_is_read_from_the_number():
    assert printed_unit(8.148) == pytest.approx(0.001)
    assert printed_unit(118.0) == 1.0 and printed_unit(0.0558) == pytest.approx(0.0001)


def test_verdicts_follow_the_size_of_the_difference():
    assert verdict("x", 7.84, 7.8368) == "agrees"  # within one unit of the last digit
    assert verdict("x", 0.196, 0.1907) == "close"  # 2.8 %: a value read off a drawing
    assert verdict("x", 8.148, 7.8368) == "differs"  # 4 %: the swapped digits of task 2.1
    assert verdict("c.angle_deg", 359.9, 0.05) == "close"  # angles compare across 0°/360°
    assert verdict("c.angle_deg", 1.0, 359.0) == "close"  # 2°: as a protractor reads
    assert verdict("c.angle_deg", 10.0, 5.0) == "differs"


def test_task_2_1s_swapped_digits_are_flagged_with_the_reason():
    rows = {r.key: r for r in check(load_preset("analitika-2.1"))}
    omega4 = rows["members.4.omega"]
    assert omega4.verdict == "differs" and "swapped" in omega4.note
    assert omega4.exact == pytest.approx(7.8368, abs=1e-4)
    assert rows["members.5.omega"].verdict == "agrees"


def test_the_tedders_travel_numbers_agree_with_the_book():
    assert {r.verdict for r in check(load_preset("zbirka-1.3"))} == {"agrees"}


def test_a_slip_the_book_made_is_reproduced_by_its_own_formula():
    """2.3: the book divides a_D by DC where ε₄ needs the tangential part; repeating that on
    the exact a_D gives the printed value, so the layout is right and the arithmetic is not."""
    from mechanisms import load_preset
    from reports.textbook import check

    scene = load_preset("zbirka-2.3")
    row = {r.key: r for r in check(scene)}["members.4.epsilon"]
    exact_a_d = {r.key: r for r in check(scene)}["points.D.a"].exact
    assert row.slip == pytest.approx(-exact_a_d / 0.91)
    assert row.verdict == "slip"
    plain = dataclasses.replace(scene, book_slips={})
    assert {r.key: r for r in check(plain)}["members.4.epsilon"].verdict == "differs"


@pytest.mark.parametrize("formula, message", [
    ('__import__("os").system("true")', "calls only"),
    ("points.D.a.real", "may use only"),
    ("x + 1", "not a result key"),
    ("1 +", "not a formula"),
])
def test_a_slip_formula_can_only_compute(formula, message):
    from mechanisms.formula import formula_keys

    with pytest.raises(ValueError, match=message):
        formula_keys(formula)


def test_a_slip_formula_evaluates_safely():
    from mechanisms.formula import evaluate

    assert evaluate("sqrt(points.D.a**2 - 16**2) / 0.91", {"points.D.a": 20.0}) == pytest.approx(12 / 0.91)
    assert evaluate("points.D.a / 0", {"points.D.a": 1.0}) != evaluate("1", {})  # nan, no crash
    assert evaluate("points.Z.a * 2", {"points.D.a": 1.0}) is None
    assert math.isnan(evaluate("9.0 ** 9 ** 9", {}))


def test_a_slip_must_name_a_printed_value():
    from mechanisms import SceneError, load_preset, parse_document
    from mechanisms.writer import to_text

    text = to_text(load_preset("zbirka-2.3"))
    with pytest.raises(SceneError, match="book_slips"):
        parse_document(text.replace('"members.4.epsilon" = "-points.D.a', '"members.9.epsilon" = "-points.D.a'))
    with pytest.raises(SceneError, match="book_slips"):
        parse_document(text.replace('"-points.D.a / 0.91"', '"open(1)"'))


def test_chapter_5s_lever_arms_and_reaction_parts_are_read_off_the_solved_figure():
    """arms.G_5.F: G_5 acts straight down at S5, so its arm about F is their horizontal
    distance; reactions.4-5.normal/tangential split F_45 along D→F and across it."""
    from reports.values import exact_values
    from solvers.diagnostics import solve_instant
    from solvers.kinetostatics import analyse

    scene = load_preset("zbirka-5.1")
    exact = exact_values(scene)
    motion = solve_instant(scene, None)
    z = {name: p.z[0] for name, p in motion.points.items()}
    assert exact["arms.G_5.F"] == pytest.approx(abs((z["S5"] - z["F"]).real), rel=1e-12)
    f45 = analyse(scene, motion=motion).reactions[(4, 5)].force[0]
    along = (z["F"] - z["D"]) / abs(z["F"] - z["D"])
    normal = abs(f45.real * along.real + f45.imag * along.imag)
    assert exact["reactions.4-5.normal"] == pytest.approx(normal, rel=1e-12)
    assert math.hypot(exact["reactions.4-5.normal"], exact["reactions.4-5.tangential"]) \
        == pytest.approx(abs(f45), rel=1e-12)
    # the reaction F_54's arm about C times its size is its moment about C
    d, c = z["D"], z["C"]
    moment = (d - c).real * (-f45).imag - (d - c).imag * (-f45).real
    assert exact["arms.5-4.C"] * abs(f45) == pytest.approx(abs(moment), rel=1e-12)
