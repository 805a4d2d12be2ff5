"""Chapters 2–3 page as a student drives it (AppTest)."""

import pytest

from mechanisms import load_preset
from solvers.kinematics import solve

from .test_gears_page import read
from .test_pages import arrows as drawn_arrows, chart, charts, page, typed
from .test_plans import LINKAGES

PAGE = "pages/velocity_plans.py"


def plan_page(**state):
    return page(PAGE, lang="en", **state)


def arrows(at, key: str) -> list[tuple]:
    return drawn_arrows(chart(at, key))


@pytest.mark.parametrize("pid", [p for p in LINKAGES if not p.startswith("zbirka-1.3")])
def test_every_linkage_preset_draws_both_plans(pid):
    at = plan_page(scene=pid)
    assert not at.exception
    assert not at.error, [e.value for e in at.error]
    assert len(charts(at)) == 3  # mechanism, velocity plan, acceleration plan


def test_moving_the_crank_changes_the_plan():
    at = plan_page(scene="analitika-2.1")
    before = arrows(at, "fig_v")
    at.slider(key="at").set_value(70.0).run()
    assert not at.exception
    assert arrows(at, "fig_v") != before


def test_the_step_slider_shows_that_step_s_equation_and_fewer_arrows():
    at = plan_page(scene="analitika-2.1")
    full = len(arrows(at, "fig_a"))
    at.slider(key="step").set_value(1).run()
    assert at.latex[0].value.strip("$\n") == r"\vec v_{A} = \vec v_{AO}"
    assert len(arrows(at, "fig_a")) < full
    at.slider(key="step").set_value(2).run()
    assert at.latex[0].value.strip("$\n").startswith(r"\vec v_{C} = \vec v_{A} + \vec v_{CA}")


def test_a_coarser_velocity_scale_draws_a_smaller_plan():
    at = plan_page(scene="analitika-2.1", Uv=0.5)
    small = arrows(at, "fig_v")
    typed(at, "Uv", 1.0).run()
    halved = arrows(at, "fig_v")
    assert [round(2 * c[2], 6) for c in halved] == [round(c[2], 6) for c in small]


def test_an_unreachable_position_says_why_instead_of_a_traceback():
    at = plan_page(scene="analitika-2.1")
    at.slider(key="at").set_value(140.0).run()
    assert not at.exception
    assert "cannot" in at.error[0].value


@pytest.mark.parametrize("tab", ["Complex-number method", "Reading the plans: accuracy and book values"])
def test_the_other_tabs_render(tab):
    at = plan_page(scene="analitika-2.1", tab=tab)
    assert not at.exception
    text = " ".join(m.value for m in at.markdown) + " ".join(s.value for s in at.success)
    if tab.startswith("Complex"):
        assert any(r"\text{B:}" in x.value for x in at.latex)
        assert "Both methods agree" in text
    else:
        assert any("Book vs exact" in h.value for h in at.header)


def test_self_check_accepts_a_value_within_drawing_precision():
    at = plan_page(scene="analitika-2.1", Uv=0.5, prec=0.5, self_open=True)
    box = at.selectbox(key="self_quantity")
    index = next(i for i, o in enumerate(box.options) if o.startswith("v_C "))
    box.set_value(index).run()
    at.text_input(key="self_value").input("1.98").run()  # exact 1.959 m/s; ±0.025 m/s
    assert at.success and "what a drawing at the task's scales allows" in at.success[0].value
    at.text_input(key="self_value").input("2.2").run()
    assert at.warning


def test_a_crank_alone_has_one_step_and_no_stepper():
    from mechanisms.loader import parse_scene

    crank = parse_scene("""
pairs = [{ type = "revolute", members = [1, 2], point = "O" }]
[frame]
O = [0.0, 0.0]
[driver]
type = "rotating"
at = 30.0
omega = 5.0
[members.2]
points = ["O", "A"]
length = 0.2
""", default_id="crank")
    at = plan_page(uploaded_scene=crank, scene="upload")
    assert not at.exception
    assert not [s for s in at.slider if s.key == "step"]
    assert at.latex[0].value.strip("$\n") == r"\vec v_{A} = \vec v_{AO}"


def test_the_legend_names_each_kind_of_arrow_once_from_the_arrows_themselves():
    """No empty traces for the legend (each costs the browser a trace on every redraw): the
    arrow traces carry it, one entry per kind drawn, and a kind's arrows hide together."""
    at = plan_page(scene="zbirka-2.1", step=3)
    figure = chart(at, "fig_a")
    assert all(any(v is not None for v in tr["x"]) for tr in figure["data"])
    named = [tr for tr in figure["data"] if tr.get("showlegend") and tr.get("name")]
    assert sorted(tr["name"] for tr in named) == ["absolute", "normal", "tangential"]
    for entry in named:
        group = [tr for tr in figure["data"] if tr.get("legendgroup") == entry["legendgroup"]]
        assert {tr["line"]["color"] for tr in group} == {entry["line"]["color"]}


@pytest.mark.parametrize("lang, words", [("sr", "metodom proširenja"), ("en", "method of extension")])
def test_a_coincident_point_is_named_with_the_method_of_extension(lang, words):
    """Task 2.3, step 2: B₄ of the slotted rocker under the block, with its Coriolis part."""
    at = page(PAGE, lang=lang, scene="zbirka-2.3", step=2)
    assert "B_{4}" in at.latex[0].value
    assert any(words in c.value and "B4" in c.value for c in at.caption)
    at.slider(key="step").set_value(1).run()  # the crank alone: no coincident point
    assert not any(words in c.value for c in at.caption)


@pytest.mark.parametrize("lang, tab, chosen", [("en", "Complex-number method", "chosen"),
                                               ("sr", "Metoda kompleksnog broja", "izabrano"),
                                               ("sr-cyrl", "Метода комплексног броја", "изабрано")])
def test_the_complex_number_tab_solves_each_loop_by_squaring_and_adding(lang, tab, chosen):
    at = page(PAGE, lang=lang, scene="analitika-2.1", tab=tab)
    assert not at.exception
    equations = [read(x.value, lang) for x in at.latex]
    assert any(r"\cos\varphi_{4}" in e and r"\sin\varphi_{4}" in e for e in equations)  # A cos + B sin = C
    assert any(f"{chosen}: " in e and "275.13" in e for e in equations)  # the drawn root of φ₄
    assert any(r"s_{56}^2" in e for e in equations)  # the RPR group's quadratic in the slide


def test_a_class_iii_group_in_the_complex_number_tab_points_to_newton():
    at = plan_page(scene="zbirka-4.1", tab="Complex-number method")
    assert not at.exception
    assert any("Newton" in i.value for i in at.info)


@pytest.mark.parametrize("lang, words", [("en", "Final contour of point"),
                                         ("sr", "Završna kontura tačke"),
                                         ("sr-cyrl", "Завршна контура тачке")])
def test_the_complex_number_tab_ends_with_the_final_contour_of_a_coupler_point(lang, words):
    """E of the four-bar is no joint: its contour from the origin through the crank, with
    |v_E| the same digits as the graphical plan's reading."""
    tab = {"en": "Complex-number method", "sr": "Metoda kompleksnog broja",
           "sr-cyrl": "Метода комплексног броја"}[lang]
    at = page(PAGE, lang=lang, scene="four-bar-crank-rocker", tab=tab)
    assert not at.exception
    assert any(words in m.value and "E" in m.value for m in at.markdown)
    lines = [read(x.value, lang) for x in at.latex]
    assert any(r"\vec v_{E} = 0.1\,i\omega_{2}" in line for line in lines)
    motion = solve(load_preset("four-bar-crank-rocker"))
    assert any(f"|v_{{E}}| = {abs(motion.points['E'].v[0]):.5g}" in line for line in lines)


@pytest.mark.parametrize("lang", ["en", "sr", "sr-cyrl"])
def test_the_class_iii_plans_step_through_s_to_the_exact_velocities(lang):
    """Task 4.3 step by step: B first, then the special point S, and the last step (D) reads
    the solver's relative velocity v_DE in the language's own number format."""
    at = page(PAGE, lang=lang, scene="zbirka-4.3", step=1)
    assert not at.exception and not at.error
    assert at.latex[0].value.strip("$\n") == r"\vec v_{B} = \vec v_{BA}"
    last = at.slider(key="step").max
    at.slider(key="step").set_value(2).run()
    assert at.latex[0].value.strip("$\n").startswith(r"\vec v_{S} = ")
    at.slider(key="step").set_value(last).run()
    assert at.latex[0].value.strip("$\n").startswith(r"\vec v_{D} = \vec v_{E} + \vec v_{DE}")
    motion = solve(load_preset("zbirka-4.3"))
    v_de = abs(motion.points["D"].v[0] - motion.points["E"].v[0])
    table = at.dataframe[0].value
    expected = f"{v_de:.4g} m/s".replace(".", "," if lang.startswith("sr") else ".")
    assert expected in table.iloc[:, -1].tolist()
