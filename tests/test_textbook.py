"""Book vs exact: verdicts computed from the data, never from the printed numbers."""

import pytest

from mechanisms import load_preset
from solvers.textbook import check, printed_unit, verdict


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
