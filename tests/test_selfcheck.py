"""The self-check box's verdict is the one judge's (methods.judge): the drawing's error where
the value is read off a drawing, else 0.5 % (tests/test_judge.py holds it to practice, the
command line and Moodle)."""

from methods.judge import value_step
from ui.selfcheck import Quantity, computed, verdict


def test_grades():
    q = Quantity("m", value_step("m", 0.354, "kg", 0.01), drawing=True)
    assert verdict(0.3541, q)[0].ok
    assert verdict(0.36, q)[0].ok  # within what the drawing allows
    said, step = verdict(0.5, q)
    assert said.diagnosis == "length" and said.ratio == 0.5 / 0.354 and step.tolerance == 0.01
    assert not verdict(0.36, computed("t", 0.354, "s"))[0].ok  # no drawing: 0.5 % only
    assert verdict(-0.354, computed("t", 0.354, "s"))[0].diagnosis == "sense"
    assert verdict(3.54, computed("t", 0.354, "s"))[0].diagnosis == "scale"


def test_the_box_offers_the_one_table_signed():
    """Task 3.1's box: ω₃ as the book prints it, signed (−4,51716 right, +4,51716 the sense
    reversed), with the tolerance ``check`` gives it; not a magnitude of its own."""
    from exams.judged import table
    from mechanisms import load_preset
    from ui.selfcheck import named

    scene = load_preset("zbirka-3.1")
    box = {q.label: q for q in named(scene, scene)}
    omega = box["ω₃ [s⁻¹]"]
    assert verdict(-4.51716, omega)[0].ok and verdict(4.51716, omega)[0].diagnosis == "sense"
    (checked,) = [s for a, s in table(scene) if a.key == "members.3.omega"]
    assert omega.step == checked


def test_the_plans_pages_box_names_a_term_left_out_of_a_points_sum():
    """Task 3.1: v_E typed as if v_EB were left out of v_E = v_B + v_EB is named as that
    mistake, as practice, the command line and Moodle name it."""
    from mechanisms import load_preset
    from methods import practice_steps
    from methods.plans import build
    from methods.scales import plan_scales
    from solvers.diagnostics import solve_instant

    from .test_pages import page

    scene = load_preset("zbirka-3.1")
    plans = build(solve_instant(scene, None))
    (step,) = [s for s in practice_steps.plans(plans, plan_scales(scene, plans)) if s.id == "v.e"]
    forgot = abs(complex(step.missing[1].value))  # v_B alone
    at = page("pages/velocity_plans.py", lang="en", scene="zbirka-3.1", self_open=True)
    box = at.selectbox(key="self_quantity")
    box.set_value(box.options.index("v_E [m/s]")).run()
    at.text_input(key="self_value").input(f"{forgot:.6f}").run()
    said = " ".join(w.value for w in at.warning)
    assert "v_EB" in said, said
