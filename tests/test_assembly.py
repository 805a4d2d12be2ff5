"""Every way an Assur group closes at the drawn instant (solvers.assembly), and the builder's
one-click "other assembly": every length kept, the group drawn in its mirror closure, and the
solver following it (AppTest)."""

from __future__ import annotations

import pytest

from mechanisms.loader import build_scene
from mechanisms.sketch import drawn, template
from solvers import StructureError, decompose
from solvers.assembly import closures
from solvers.diagnostics import solve_instant
from ui.i18n import t

from .test_builder_page import PAGE, drawn as drawn_on_page, start
from .test_pages import charts, page


def _instant(scene):
    motion = solve_instant(scene, None)
    return motion, {n: complex(p.z[0]) for n, p in motion.points.items()}


@pytest.mark.parametrize("name", ["four-bar", "slider-crank", "slotted-lever", "watt-six-bar",
                                  "stephenson-six-bar", "class-iii"])
def test_each_group_closes_two_ways_and_the_drawn_one_comes_first(name):
    scene = build_scene(template(name))
    motion, places = _instant(scene)
    for group in decompose(scene).groups:
        found = closures(scene, group.name)
        assert len(found) >= 2, group.name
        assert max(abs(found[0][n] - places[n]) for n in found[0]) < 1e-9
        assert max(abs(found[1][n] - places[n]) for n in found[1]) > 1e-3


@pytest.mark.parametrize("name, group", [("watt-six-bar", "5-6"), ("four-bar", "3-4"),
                                         ("class-iii", "3-4-5-6")])
def test_drawing_a_group_in_its_other_closure_moves_the_solver_there_with_every_length(name, group):
    doc = template(name)
    scene = build_scene(doc)
    motion, places = _instant(scene)
    other = closures(scene, group)[1]
    flipped_doc = {**doc, "guess": drawn(doc, {**places, **other})}
    flipped = build_scene(flipped_doc)
    assert flipped.lengths == scene.lengths
    new_motion, new_places = _instant(flipped)
    assert max(abs(new_places[n] - other[n]) for n in other) < 1e-9
    members = next(g for g in decompose(scene).groups if g.name == group).members
    omegas = [(motion.members[m].omega[0], new_motion.members[m].omega[0]) for m in members]
    assert any(abs(a - b) > 1e-3 * max(abs(a), abs(b), 1.0) for a, b in omegas)
    assert closures(flipped, group)[1] == pytest.approx(places, abs=1e-9) or all(
        abs(closures(flipped, group)[1][n] - places[n]) < 1e-9 for n in other)


def test_an_unknown_group_is_refused():
    with pytest.raises(StructureError, match="no Assur group"):
        closures(build_scene(template("four-bar")), "7-8")


def test_a_group_that_cannot_close_has_no_closure():
    doc = template("four-bar")
    scene = build_scene(doc)
    group = decompose(scene).groups[0]
    longer = build_scene({**doc, "driver": {**doc["driver"]}}).with_(
        lengths={3: 0.01, 4: 0.01})  # the coupler and rocker cannot reach
    assert closures(longer, group.name) == []


def test_the_builder_says_where_the_other_assembly_is_and_flips_by_one_click():
    at = start("template:watt-six-bar")
    before = drawn_on_page(at)
    info = [i.value for i in at.info if "5-6" in i.value or "(5,6)" in i.value]
    assert info and "F" in info[0] and t("build.side_left", "en") in info[0] + t("build.side_right", "en")
    button = next(b for b in at.button if b.key == "build_flip_5-6")
    button.click().run()
    assert not at.exception and not at.error, [e.value for e in at.error]
    after = drawn_on_page(at)
    scene = build_scene(template("watt-six-bar"))
    other = closures(scene, "5-6")[1]
    assert abs(after["F"] - other["F"]) < 1e-3  # drawn where the other closure puts F
    assert abs(after["B"] - before["B"]) < 1e-3  # the first group stays as it was
    assert charts(at)["build_fig"]["editable"] is True


def test_the_builder_in_serbian_says_it_in_serbian():
    at = page(PAGE, lang="sr")  # a first visit opens the four-bar template
    text = " ".join(i.value for i in at.info)
    assert "drugi sklop" in text and "(0,4087; 0,2999) m" in text
    assert t("build.flip", "sr") in [b.label for b in at.button]
