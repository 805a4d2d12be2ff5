"""The chapter 5 page as a user meets it (AppTest through app.py)."""

from __future__ import annotations

import pytest

from tests.test_pages import chart, decode, page, texts, typed

PAGE = "pages/kinetostatics.py"


def metrics(at) -> list[str]:
    return [m.value for m in at.metric]


def test_the_lecture_example_shows_three_equal_driving_torques():
    at = page(PAGE, lang="en")
    assert not at.exception and not at.error
    torque = metrics(at)[:3]
    assert torque[0] == torque[1] == torque[2] and torque[0].startswith("4.53")
    assert [m.label.rsplit(" ", 1)[-1] for m in at.metric] == ["[N·m]"] * 3 + ["[W]"]
    reactions = at.dataframe[0].value
    assert set(reactions["F_pq"]) == {"F_12", "F_14", "F_16", "F_23", "F_34", "F_45", "F_56"}
    sliding = reactions.iloc[:, 1].str.startswith("P")  # the pair's letter: R or P
    assert 0 < sliding.sum() < len(reactions)
    assert (reactions.loc[~sliding, "h [m]"] == "—").all()  # no offset shown as "None"
    assert (reactions.loc[sliding, "h [m]"] != "—").all()
    assert "F<sub>5</sub> = 100 N" in texts(chart(at, "fig_loads"))


def test_moving_the_crank_and_adding_inertia_change_the_torque():
    at = page(PAGE, lang="en")
    before = metrics(at)[0]
    at.slider(key="at").set_value(200.0).run()
    moved = metrics(at)[0]
    assert moved != before
    assert at.toggle(key="inertia").value is False  # the lecture's example leaves it out
    at.toggle(key="inertia").set_value(True).run()
    assert metrics(at)[0] == moved  # no member has a mass yet
    typed(at, "m5", 3.0)
    typed(at, "rho5", 0.1).run()
    assert not at.exception
    assert metrics(at)[0] != moved
    inertia = at.dataframe[1].value
    assert len(inertia) == 1  # member 5
    assert inertia.iloc[0, 2] == inertia.iloc[0, -1]  # M_i = moment of the K form about S
    at.toggle(key="inertia").set_value(False).run()
    assert metrics(at)[0] == moved  # a mass without inertia or weight changes nothing


@pytest.mark.parametrize("tab", [1, 2, 3, 4])
def test_every_tab_draws(tab):
    labels = ["Loads and reactions", "Force polygons", "Step by step", "Zhukovsky's lever",
              "Over the cycle"]
    at = page(PAGE, lang="en", tab=labels[tab])
    assert not at.exception and not at.error
    keys = {1: ["fig_free_body", "fig_polygon"], 2: ["fig_step"], 3: ["fig_lever"],
            4: ["fig_cycle", "fig_reactions_cycle"]}[tab]
    for key in keys:
        assert chart(at, key)["data"]


def test_the_cycle_curves_pass_through_the_instant_and_only_the_marker_follows_the_crank():
    at = page(PAGE, lang="en", tab="Over the cycle")
    at.slider(key="at").set_value(90.0).run()
    curves = chart(at, "fig_cycle")
    (torque, _) = curves["data"]
    at_90 = decode(torque["y"])[list(decode(torque["x"])).index(90.0)]
    assert float(metrics(at)[0].split()[0]) == pytest.approx(at_90, rel=1e-4)  # 5 digits shown
    at.slider(key="at").set_value(200.0).run()
    moved = chart(at, "fig_cycle")
    assert moved["data"] == curves["data"]
    assert [s["x0"] for s in moved["layout"]["shapes"]] == [200.0]


def test_the_polygon_follows_the_force_scale():
    at = page(PAGE, lang="en", tab="Force polygons")
    lengths = at.dataframe[0].value.iloc[:, 2].tolist()
    typed(at, "UF", 20.0).run()
    halved = at.dataframe[0].value.iloc[:, 2].tolist()
    assert [float(a) / 2 for a in lengths] == pytest.approx([float(b) for b in halved], abs=6e-3)


def test_a_scene_without_loads_says_so():
    at = page(PAGE, lang="en", scene="zbirka-2.1")
    assert not at.exception
    assert any("no loads" in i.value for i in at.info)


@pytest.mark.parametrize("lang", ["sr", "sr-cyrl"])
def test_the_page_speaks_serbian(lang):
    at = page(PAGE, lang=lang, scene="zbirka-4.2")
    assert not at.exception and not at.error


def test_check_my_answer_grades_the_driving_torque():
    at = page(PAGE, lang="en", self_open=True)
    box = at.selectbox(key="self_quantity")
    box.set_value(box.options.index("M_p [N·m]")).run()  # (the one table's order: exams.judged)
    at.text_input(key="self_value").input("4.535").run()  # M_p of the lecture example
    assert any(s.value.startswith("Right") for s in at.success)
    at.text_input(key="self_value").input("4.9").run()
    assert any("The sign is right, but the size is not" in w.value for w in at.warning)


def test_a_dead_point_of_a_class_iii_group_is_explained_over_the_cycle():
    at = page(PAGE, lang="en", scene="triad-full-turn", tab="Over the cycle", steps=3600, m4=1.0)
    assert not at.exception
    assert any("dead point" in w.value for w in at.warning)


def test_turning_the_load_changes_the_torque_as_the_power_says():
    """F_5 turned to point along −x reverses its power, so M_p changes sign when F_5 is the
    only load (M_4 set to zero)."""
    at = page(PAGE, lang="en", M0=0.0)
    ahead = float(at.metric[0].value.split()[0])
    typed(at, "Fa0", 180.0).run()
    assert not at.exception
    assert float(at.metric[0].value.split()[0]) == pytest.approx(-ahead, rel=1e-4)


def test_the_scene_note_reads_in_serbian_cyrillic_with_latin_notation():
    at = page(PAGE, lang="sr-cyrl", about=True)  # the scene's note is under "about"
    note = next(m.value for m in at.markdown if "F₅ = 100 N" in m.value)
    assert "Криваја" in note  # prose transliterated …
    assert "OA" in note and "⟨" not in note  # … notation kept as the course writes it


def test_loads_that_do_no_net_work_need_no_mean_power():
    """The lecture's loads (a constant force and a couple on an oscillating rocker) do no
    net work over a cycle: the mean driving power reads 0 W, not a rounding residue."""
    at = page(PAGE, lang="en", tab="Over the cycle")
    values = {m.label: m.value for m in at.metric}
    assert values["Mean driving power"] == "0 W"
    assert values["Peak |M_p|"].endswith("N·m")


STEPS_TAB = {"en": "Step by step", "sr": "Korak po korak", "sr-cyrl": "Корак по корак"}


@pytest.mark.parametrize("lang", ["en", "sr", "sr-cyrl"])
def test_the_graphical_method_steps_from_the_first_to_the_last_equation(lang):
    """Task 5.1 step by step: the first step is a moment equation of member 5 with its free
    body; a middle one a polygon drawn to scale; the last one ends in the solver's M_p. A step
    beyond the last (an old link) shows the last."""
    at = page(PAGE, lang=lang, scene="zbirka-5.1", tab=STEPS_TAB[lang], fstep=1)
    assert not at.exception and not at.error
    assert r"\sum M_{F}^{(5)}" in at.latex[0].value
    assert "F<sub>45</sub><sup>t</sup>" in " ".join(texts(chart(at, "fig_step")))
    at.slider(key="fstep").set_value(2).run()
    polygon = texts(chart(at, "fig_step"))
    assert {"F<sub>45</sub><sup>n</sup>", "F<sub>16</sub>", "G<sub>5</sub>"} <= set(polygon)
    last = page(PAGE, lang=lang, scene="zbirka-5.1", tab=STEPS_TAB[lang], fstep=99)
    assert not last.exception
    count = last.slider(key="fstep").max
    assert last.slider(key="fstep").value == count
    torque = metrics(last)[0]
    assert torque in last.success[0].value  # "M_p = … N·m", the group-by-group value


@pytest.mark.parametrize("lang, tab", [("en", "Zhukovsky's lever"), ("sr", "Redukovani mehanizam"),
                                       ("sr-cyrl", "Редуковани механизам")])
def test_the_lever_tab_writes_the_books_equation_and_agrees_with_the_groups(lang, tab):
    """Task 5.3: S and K placed by proportion, the moments about the pole, then M_p = F_p·AB
    next to the group-by-group value (the same digits)."""
    at = page(PAGE, lang=lang, scene="zbirka-5.3", tab=tab)
    assert not at.exception and not at.error
    lines = [x.value for x in at.latex]
    assert any(r"\frac{BK_{3}}{BC}" in line for line in lines)
    assert any(r"\sum M_P = F_p\cdot h_p" in line for line in lines)
    torque = metrics(at)[0]
    assert at.success[0].value.count(torque) == 2  # from the lever, and group by group
