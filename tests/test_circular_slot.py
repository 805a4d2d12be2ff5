"""A block in a circular slot (task 2.3): it moves as a link to the slot's centre, and the
relative motion along the arc — its speed, the normal part v²/R and the Coriolis part — is
reported and drawn as the slot's."""

import dataclasses

import numpy as np
import pytest

from figures.linkage import mechanism_traces, pose
from mechanisms import SceneError, load_preset, parse_document
from mechanisms.writer import to_text
from reports.values import exact_values
from solvers.diagnostics import solve_instant
from solvers.kinematics import solve

STEP = 1e-5  # rad of the crank, for the finite differences


def test_the_slot_reads_back_as_written():
    scene = load_preset("zbirka-2.3")
    slot = next(p for p in scene.pairs if p.on_slot)
    assert (slot.members, slot.point, slot.on_slot) == ((4, 3), "H", "B")
    text = to_text(scene)
    assert 'type = "circular"' in text
    assert parse_document(text) == dataclasses.replace(scene, id="zbirka-2.3")


def test_the_block_stays_on_the_arc_and_its_relative_motion_is_the_arcs():
    scene = load_preset("zbirka-2.3")
    at = scene.driver.at + np.array([-STEP, 0.0, STEP])
    m = solve(scene, at, order=2)
    radius = np.abs(m.points["B"].z - m.points["H"].z)
    assert np.allclose(radius, 0.65, atol=1e-12)
    slot = m.sliders["4-3"]
    omega2 = scene.driver.speed
    v = (slot.s[2] - slot.s[0]) / (2 * STEP) * omega2  # ds/dt by central differences
    a = (slot.s[2] - 2 * slot.s[1] + slot.s[0]) / STEP ** 2 * omega2 ** 2
    assert slot.v[1] == pytest.approx(v, rel=1e-6)
    assert slot.a[1] == pytest.approx(a, rel=1e-4)
    assert abs(slot.normal[1]) == pytest.approx(slot.v[1] ** 2 / 0.65, rel=1e-12)
    towards_centre = (m.points["H"].z[1] - m.points["B"].z[1]) / 0.65
    assert slot.normal[1] / abs(slot.normal[1]) == pytest.approx(towards_centre, abs=1e-12)
    omega4 = m.members[4].omega[1]
    assert abs(slot.coriolis[1]) == pytest.approx(2 * abs(omega4 * slot.v[1]), rel=1e-12)


def test_the_block_in_the_slot_is_the_books_relative_acceleration():
    """a_B (crank) = a_B4 (the rocker's point under B) + Coriolis + normal + tangential."""
    scene = load_preset("zbirka-2.3")
    m = solve_instant(scene, None)
    slot, rocker = m.sliders["4-3"], m.members[4]
    b, c = m.points["B"].z[0], m.points["C"].z[0]
    a_b4 = (1j * rocker.epsilon[0] - rocker.omega[0] ** 2) * (b - c)  # C is fixed
    tangent = 1j * (b - m.points["H"].z[0]) / 0.65
    total = a_b4 + slot.coriolis[0] + slot.normal[0] + slot.a[0] * tangent
    assert total == pytest.approx(m.points["B"].a[0], abs=1e-9)


def test_the_json_gives_the_slots_normal_part():
    values = exact_values(load_preset("zbirka-2.3"))
    assert values["sliders.4-3.v"] == pytest.approx(1.75, rel=0.01)
    assert "sliders.6-5.s" in values


def test_the_slot_is_drawn_as_an_arc_and_the_block_without_its_link():
    scene = load_preset("zbirka-2.3")
    m = solve_instant(scene, None)
    traces = mechanism_traces(scene, *pose(m, 0), t=lambda key, **v: key)
    block = next(tr for tr in traces if tr.get("name", "").startswith("fig.member"))  # any member
    assert block
    guides = next(tr for tr in traces if tr.get("line", {}).get("dash") == "dot")
    xs = np.array([x for x in guides["x"] if x is not None], dtype=float)
    ys = np.array([y for y in guides["y"] if y is not None], dtype=float)
    centre = m.points["H"].z[0]
    on_circle = np.isclose(np.abs(xs + 1j * ys - centre), 0.65, atol=1e-9)
    assert on_circle.sum() >= 25
    members = [tr for tr in traces if tr.get("mode") == "lines+markers"]
    block3 = members[list(scene.members).index(3)]
    assert len(block3["x"]) == 1  # the block alone, not a line to the centre


@pytest.mark.parametrize("change, message", [
    ('centre = "H"', 'centre = "B"'),
    ('centre = "H"', 'centre = "Q"'),
])
def test_a_wrong_slot_is_refused_with_the_reason(change, message):
    text = to_text(load_preset("zbirka-2.3"))
    with pytest.raises(SceneError, match="centre"):
        parse_document(text.replace(change, message))


def test_the_plans_cross_the_slot_the_books_way():
    """v_B₄ = v_B + v_B₄B (⊥ B₄H) = v_C + v_B₄C, and a_B₄ = a_B + a^k + a^n (v²/R) + a^t."""
    from methods.plans import build

    scene = load_preset("zbirka-2.3")
    m = solve(scene, [scene.driver.at], order=2)
    plans = build(m)
    step = next(s for s in plans.acceleration.steps if s.target == "b4")
    arrows = {a.kind: a for start, side in step.sides if start == "b" for a in side}
    b, h, c = (m.points[p].z[0] for p in "BHC")
    w4, e4 = m.members[4].omega[0], m.members[4].epsilon[0]
    assert plans.velocity.images["b4"] == pytest.approx(1j * w4 * (b - c), abs=1e-12)
    assert plans.acceleration.images["b4"] == pytest.approx((1j * e4 - w4 ** 2) * (b - c), abs=1e-9)
    v_rel = plans.velocity.images["b4"] - plans.velocity.images["b"]
    assert abs(arrows["coriolis"].value) == pytest.approx(2 * abs(w4) * abs(v_rel), rel=1e-12)
    assert abs(arrows["normal"].value) == pytest.approx(abs(v_rel) ** 2 / 0.65, rel=1e-12)
    assert (arrows["tangential"].value * (b - h).conjugate()).real == pytest.approx(0, abs=1e-9)
    assert plans.acceleration.closure() < 1e-9
