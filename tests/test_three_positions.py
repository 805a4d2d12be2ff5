"""The three-position construction (methods/three_positions.py): the pivots found where the
perpendicular bisectors cross are the four-bar's own, for every four-bar of the course; a
position given as a point and the coupler's angle gives the same; positions that leave no
pivot are refused in words; practice judges the construction's answers; the page draws it
step by step."""

from __future__ import annotations

import cmath
import math

import pytest

from mechanisms import SceneError, load_preset, preset_ids
from methods.practice import grade
from methods.practice_steps import THREE_APART, steps_for
from methods.three_positions import bisector, construction, crossing, joints, of_scene
from ui.chapters import SYNTHESIS

from .test_pages import chart, page

FOUR_BARS = ["four-bar-crank-rocker", "zbirka-1.1", "zbirka-1.3", "zbirka-5.4"]


def _positions(pid: str):
    scene = load_preset(pid)
    first = math.degrees(scene.driver.at)
    return scene, of_scene(scene, [first + d for d in THREE_APART])


def test_every_four_bar_of_the_course_is_found_and_only_those():
    found = []
    for pid in preset_ids("linkage"):
        try:
            _positions(pid)
            found.append(pid)
        except SceneError:
            pass
    assert found == FOUR_BARS


@pytest.mark.parametrize("pid", FOUR_BARS)
def test_the_bisectors_cross_at_the_four_bars_own_pivots(pid):
    scene, (a, b) = _positions(pid)
    stages = construction(a, b)
    found = {k: v for stage in stages for k, v in stage.found.items()}
    crank_pivot = scene.members[2].axis[0]
    rocker_pivot = next(p for p in scene.members[4].axis if p in scene.frame)
    size = max(abs(z) for z in scene.frame.values()) + scene.members[3].length
    assert abs(found["O"] - scene.frame[crank_pivot]) < 1e-12 * size
    assert abs(found["D"] - scene.frame[rocker_pivot]) < 1e-9 * size
    links = stages[-1].values
    assert links["crank"] == pytest.approx(scene.members[2].length, rel=1e-9)
    assert links["coupler"] == pytest.approx(scene.members[3].length, rel=1e-9)
    assert links["rocker"] == pytest.approx(scene.members[4].length, rel=1e-9)
    # every stage's bisector holds points as far from both ends of its chord
    for stage in stages:
        for line in stage.lines:
            far = line.middle + 3.7 * line.direction
            assert abs(far - line.ends[0]) == pytest.approx(abs(far - line.ends[1]), rel=1e-12)


def test_a_position_as_a_point_and_the_couplers_angle_gives_the_same_pivots():
    scene, (a, b) = _positions("zbirka-1.3")
    # the coupler's point E and its angle at each position; A and B in the coupler's frame
    e = [p + 0.68 / 0.3 * (q - p) for p, q in zip(a, b)]
    angle = [cmath.phase(q - p) for p, q in zip(a, b)]
    local_a, local_b = -0.68 + 0j, -0.38 + 0j  # (E lies 0.68 m along C→B: A = C, B = B)
    again = [joints(m, th, local_a, local_b) for m, th in zip(e, angle)]
    stages = construction([p for p, _ in again], [q for _, q in again])
    assert abs(stages[2].found["O"] - scene.frame["D"]) < 1e-12
    assert abs(stages[5].found["D"] - scene.frame["A"]) < 1e-9


def test_positions_that_leave_no_pivot_are_refused_in_words():
    with pytest.raises(SceneError, match="one line"):
        crossing(bisector(0j, 1 + 0j), bisector(1 + 0j, 2 + 0j), "O")
    with pytest.raises(SceneError, match="same place"):
        bisector(1 + 1j, 1 + 1j)
    with pytest.raises(SceneError, match="needs a four-bar"):
        of_scene(load_preset("zbirka-3.1"), [0, 40, 80])


def test_practice_judges_the_constructions_answers():
    steps = steps_for(load_preset("four-bar-crank-rocker"), "three")
    assert [s.id for s in steps] == ["three.O", "three.D", "three.crank", "three.rocker", "three.frame"]
    for step in steps:
        assert grade(step, step.expected).diagnosis == "ok"
        off = step.expected + (3 * step.tolerance if step.kind == "scalar" else 3j * step.tolerance)
        assert grade(step, off).diagnosis != "ok"


def test_the_page_draws_the_construction_step_by_step_and_practises_it():
    at = page(SYNTHESIS.file)
    at.radio(key="mode").set_value("three").run()
    assert not at.exception and not at.error
    step = at.slider(key="three_step_zbirka-1.3")
    assert step.value == step.max == 7
    whole = chart(at, "three_chart")
    assert sum(tr.get("name") == "perpendicular bisector" for tr in whole["data"]) == 4
    step.set_value(1).run()
    first = chart(at, "three_chart")
    assert sum(tr.get("name") == "perpendicular bisector" for tr in first["data"]) == 1
    assert "Join A1 and A2" in at.info[0].body
    before = len(at.text_input)
    at.toggle(key="pr_three_on").set_value(True).run()
    assert not at.exception
    assert len(at.text_input) > before  # the first step's answer boxes (O: x and y)
