"""The chapter 4 page as a user meets it (AppTest through app.py)."""

from __future__ import annotations

import json

import pytest

from tests.test_pages import chart, charts, page, typed
from ui.numbers import parse

PAGE = "pages/assur_groups.py"


def texts(at) -> str:
    return " ".join(m.value for m in at.markdown)


def test_the_default_scene_is_task_4_1_with_its_structure_and_special_point():
    at = page(PAGE, lang="en")
    assert not at.exception
    assert "I(1,2) → III(3,4,5,6)" in texts(at)
    assert [m.value for m in at.metric] == ["5", "7", "0", "1"]
    special = at.dataframe[1].value
    assert list(special.iloc[:, 0]) == ["S"]
    assert any("cannot close" in w.value for w in at.warning)  # the locked range, explained
    assert len(charts(at)) == 1


def test_two_dyads_in_series_step_through_group_by_group():
    at = page(PAGE, lang="en", scene="zbirka-2.1")
    assert "I(1,2) → II(3,4) → II(5,6)" in texts(at)
    full = len(json.dumps(chart(at, "structure")))
    at.slider(key="upto").set_value(1).run()
    assert not at.exception
    assert len(json.dumps(chart(at, "structure"))) < full  # members 5, 6 not drawn yet


@pytest.mark.parametrize("lang", ["sr", "en", "sr-cyrl"])
def test_the_page_speaks_every_language(lang):
    at = page(PAGE, lang=lang, scene="zbirka-4.2")
    assert not at.exception and not at.error


def test_a_position_the_group_cannot_reach_is_an_explanation_not_a_traceback():
    at = page(PAGE, lang="en", scene="zbirka-4.1")
    at.slider(key="at").set_value(90.0).run()
    assert not at.exception
    assert any("cannot be drawn" in e.value for e in at.error)


def test_the_plans_page_draws_a_class_iii_scene_through_s():
    at = page("pages/velocity_plans.py", lang="en", scene="zbirka-4.3", step=2)
    assert not at.exception and not at.info
    assert at.latex[0].value.strip("$\n").startswith(r"\vec v_{S} = ")


def test_check_my_answer_grades_the_degrees_of_freedom_and_s():
    at = page(PAGE, lang="en", scene="triad-full-turn", self_open=True)
    at.text_input(key="self_value").input("1").run()  # W
    assert any(s.value.startswith("Right") for s in at.success)
    labels = at.selectbox(key="self_quantity").options
    assert "x_S [m]" in labels
    at.text_input(key="self_value").input("2").run()
    assert any(w.value.startswith("The sign is right, but the size is not.") for w in at.warning)


@pytest.mark.parametrize("lang, done", [("en", "Newton step(s)"), ("sr", "Njutnovih koraka"),
                                        ("sr-cyrl", "Њутнових корака")])
def test_newton_is_shown_iteration_by_iteration(lang, done):
    """Task 4.1 from the pose 5° earlier: a row per iterate, the residual ending below the
    tolerance, and the last angles equal to the page's own solution; a start too far away
    says so instead of showing a wrong pose."""
    closed = page("pages/assur_groups.py", lang=lang, scene="triad-full-turn")
    assert not any("k" in d.value.columns for d in closed.dataframe)  # closed: not computed
    at = page("pages/assur_groups.py", lang=lang, scene="triad-full-turn", newton_iterations=True)
    assert not at.exception and not at.error
    table = at.dataframe[-1].value
    residuals = [parse(r, "sr") for r in table.iloc[:, 1]]  # 1,74e-02 in Serbian
    assert list(table["k"]) == list(range(len(table))) and residuals[-1] < 1e-9 < residuals[0]
    assert any(done in c.value for c in at.caption)
    typed(at, "back", 15.0).run()  # too far for this triad (it wanders)
    assert not at.exception
    assert any("15" not in w.value and ("converge" in w.value or "konvergen" in w.value
                                        or "конверген" in w.value) for w in at.warning)
