"""Grading a typed answer against the exact value."""

from ui.selfcheck import Quantity, grade


def test_grades():
    q = Quantity("m", 0.354, "kg", drawing=0.01)
    assert grade(0.3541, q)[0] == "correct"
    assert grade(0.36, q)[0] == "drawing"
    verdict, relative = grade(0.5, q)
    assert verdict == "off" and abs(relative - (0.5 - 0.354) / 0.354) < 1e-12
    assert grade(0.36, Quantity("t", 0.354, "s"))[0] == "off"  # no drawing: 0.5 % only
