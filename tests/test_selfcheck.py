"""The self-check box's verdict is the one judge's (methods.judge): the drawing's error where
the value is read off a drawing, else 0.5 % (tests/test_judge.py holds it to practice, the
command line and Moodle)."""

from ui.selfcheck import Quantity, verdict


def test_grades():
    q = Quantity("m", 0.354, "kg", drawing=0.01)
    assert verdict(0.3541, q)[0].ok
    assert verdict(0.36, q)[0].ok  # within what the drawing allows
    said, step = verdict(0.5, q)
    assert said.diagnosis == "length" and said.ratio == 0.5 / 0.354 and step.tolerance == 0.01
    assert not verdict(0.36, Quantity("t", 0.354, "s"))[0].ok  # no drawing: 0.5 % only
    assert verdict(-0.354, Quantity("t", 0.354, "s"))[0].diagnosis == "sense"
    assert verdict(3.54, Quantity("t", 0.354, "s"))[0].diagnosis == "scale"
