"""Kinetostatics: reactions, inertia loads and the driving torque against independent checks."""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest
from hypothesis import assume, given, strategies as st

from cli import main
from mechanisms import load_preset
from mechanisms.schema import Force, Moment, Scene
from reports.textbook import check
from solvers.kinetostatics import analyse, free_body

from . import scenes
from .test_properties import SETTINGS, angle, mechanisms

CYCLE = np.linspace(0, 2 * np.pi, 37)


def loaded(scene: Scene, masses: dict[int, float], rho: float = 0.05, gravity: float = 9.81,
           forces=(), moments=()) -> Scene:
    members = {n: dataclasses.replace(m, mass=masses.get(n, 0.0), gyration=rho)
               for n, m in scene.members.items()}
    return dataclasses.replace(scene, members=members, gravity=gravity, forces=tuple(forces),
                               moments=tuple(moments))


def cross(a: complex, b: complex) -> float:
    return a.real * b.imag - a.imag * b.real


@pytest.mark.parametrize("omega", [10.0, -3.0])
def test_static_slider_crank_matches_the_closed_form(omega):
    """Massless links, a horizontal force F on the slider: the motor's power balances F's,
    M_p·ω₂ = −F·v_B, so M_p = −F·v_Bx/ω₂."""
    force = 120.0
    scene = scenes.slider_crank(guide_deg=0.0, omega=omega)
    scene = dataclasses.replace(scene, forces=(Force(4, "B", force, 0.0),))
    k = analyse(scene, CYCLE)
    vx = k.motion.points["B"].vx
    ok = np.isfinite(k.driving)
    assert ok.sum() > 30
    np.testing.assert_allclose(k.driving[ok], (-force * vx / omega)[ok], atol=1e-9 * force)
    # the slider's guide carries the rod's vertical push: F_14 normal to x, F_34 along the rod
    rod = k.motion.points["B"].z - k.motion.points["A"].z
    f34 = k.reactions[(3, 4)].force
    assert np.allclose(np.imag(np.conj(rod) * f34)[ok], 0.0, atol=1e-9 * force)
    assert np.allclose(k.reactions[(1, 4)].force.real[ok], 0.0, atol=1e-9 * force)


def test_a_mechanism_at_rest_still_has_a_driving_torque():
    """ω₂ = 0: the power balance and the lever use virtual velocities and still agree."""
    scene = scenes.fourbar(omega=0.0)
    scene = loaded(scene, {3: 2.0, 4: 1.5}, forces=[Force(3, "E", 40.0, 1.0)])
    k = analyse(scene, CYCLE)
    ok = np.isfinite(k.driving)
    assert np.abs(k.driving[ok]).max() > 1.0
    assert np.nanmax(k.disagreement) < 1e-9
    assert np.allclose(k.power[ok], 0.0)


@SETTINGS
@given(mechanisms(), angle, st.floats(0.1, 5), st.floats(0.1, 5), st.floats(0.01, 0.2),
       st.floats(-200, 200), st.floats(0, 360), st.floats(-20, 20), st.booleans())
def test_three_driving_torques_agree(scene, phi, m3, m4, rho, force, direction, moment, follows):
    last = max(scene.members)
    point = next(iter(scene.members[last].points))
    scene = loaded(scene, {3: m3, last: m4}, rho,
                   forces=[Force(last, point, force, math.radians(direction), follows)],
                   moments=[Moment(3, moment)])
    k = analyse(scene, phi)
    assume(bool(k.motion.feasible[0]) and k.motion.condition[0] < 1e3)
    assert k.disagreement[0] < 1e-9
    assert abs(k.power_residual[0]) <= 1e-9 * max(k.scale[0] * abs(scene.driver.speed), 1e-12)


def test_loads_that_do_no_work_agree_to_round_off_not_to_a_ratio_of_zeros():
    """A slotted crank whose column passes through the crank's pivot: the slider stands still
    at O, every load's power is ~0 and the three M_p are ~1e-40 N·m; their disagreement is
    measured against the loads' moments (this divided 1e-40 by 1e-40 and failed at random)."""
    scene = loaded(scenes.slotted_crank(1.0, 0.5, 0.0, 1e-18), {3: 1.0, 4: 1.0}, 0.125)
    k = analyse(scene, math.radians(1.0))
    assert abs(k.driving[0]) < 1e-12 and k.scale[0] < 1e-12
    assert k.disagreement[0] < 1e-9


def equilibrium(k, member: int, i: int) -> tuple[complex, float]:
    """Σ F and Σ M about the origin of everything acting on one member, from the result's
    parts: the loads and the reactions F_pq with q = member."""
    total_f, total_m = 0j, 0.0
    for ld in k.loads:
        if ld.member == member:
            total_f += ld.force[i]
            total_m += cross(ld.point[i], ld.force[i])
    total_m += sum(float(c.value[i]) for c in k.couples if c.member == member)
    for r in k.on_member(member):
        total_f += r.force[i]
        total_m += cross(r.point[i], r.force[i]) + float(r.couple[i])
    if member == 2:
        total_m += float(k.driving[i])
    return total_f, total_m


@pytest.mark.parametrize("preset", ["predavanja-kinetostatika", "zbirka-2.5", "triad-full-turn",
                                    "tangent-slotted-crank"])
def test_every_member_is_in_equilibrium_and_reactions_are_action_and_reaction(preset):
    scene = load_preset(preset)
    scene = loaded(scene, {n: 0.5 + 0.2 * n for n in scene.members},
                   forces=[*scene.forces, Force(3, next(iter(scene.members[3].points)), 30.0, 2.0)])
    k = analyse(scene, CYCLE)
    for (p, q), r in k.reactions.items():
        back = k.reactions[(q, p)]
        np.testing.assert_array_equal(r.force, -back.force)
        np.testing.assert_array_equal(r.couple, -back.couple)
    for i in np.flatnonzero(np.isfinite(k.driving)):
        for member in scene.members:
            f, m = equilibrium(k, member, i)
            assert abs(f) < 1e-9 * k.scale[i] + 1e-9 and abs(m) < 1e-9 * k.scale[i] + 1e-9
    assert np.nanmax(k.disagreement) < 1e-9


def test_huygens_centre_carries_the_inertia_couple():
    """−m·a_B at S plus −m·a_SB at K has the same resultant and the same moment about any point
    as −m·a_S at S plus the couple −J·ε; for a rocker about a fixed B all of it acts at K."""
    scene = loaded(scenes.fourbar(), {2: 1.0, 3: 2.0, 4: 1.5}, rho=0.07, gravity=0.0)
    k = analyse(scene, CYCLE)
    probe = 0.3 - 0.2j
    for n, inert in k.inertia.items():
        assert np.allclose(inert.base_force + inert.relative_force, inert.force)
        direct = cross_arr(inert.centre - probe, inert.force) + inert.moment
        huygens = (cross_arr(inert.centre - probe, inert.base_force)
                   + cross_arr(inert.huygens - probe, inert.relative_force))
        np.testing.assert_allclose(huygens, direct, atol=1e-9 * np.abs(direct).max())
    rocker = k.inertia[4]  # D is on the frame: a_B = 0
    assert np.allclose(rocker.base_force, 0.0)
    bs = abs(rocker.centre - rocker.base)
    np.testing.assert_allclose(abs(rocker.huygens - rocker.base), bs + 0.07 ** 2 / bs)


def cross_arr(a, b):
    return a.real * b.imag - a.imag * b.real


def test_a_linear_driver_gets_a_driving_force():
    scene = load_preset("analitika-2.2")
    scene = loaded(scene, {3: 1.0, 4: 0.8, 6: 0.5}, forces=[Force(6, "M", 25.0, 0.5)])
    k = analyse(scene, scene.driver.at + np.linspace(-0.02, 0.02, 9))
    assert k.crank_force is None
    assert np.isfinite(k.driving).all()
    assert np.nanmax(k.disagreement) < 1e-9
    np.testing.assert_allclose(k.power, k.driving * scene.driver.speed)


def test_force_polygons_close_and_draw_known_forces_first():
    k = analyse(load_preset("predavanja-kinetostatika"))
    for members in [(5, 6), (3, 4), (2,)]:
        actions = free_body(k, members, 0)
        assert abs(sum(a.force for a in actions)) < 1e-9 * max(abs(a.force) for a in actions)
        known = [a.known for a in actions]
        assert known == sorted(known, reverse=True) and known[0]
    names = [a.name for a in free_body(k, (5, 6), 0)]
    assert names == ["F_5", "F_45", "F_16"]


def test_the_lecture_example_by_its_own_moment_equations():
    """The lecture's steps, written here from the solved positions: member 6 is a two-force
    member, so F_65 lies along MC and ΣM_B(5) gives |F_65| = F_5·h_5B/h_65B."""
    scene = load_preset("predavanja-kinetostatika")
    k = analyse(scene)
    z = {n: complex(p.z[0]) for n, p in k.motion.points.items()}
    mc = (z["C"] - z["M"]) / abs(z["C"] - z["M"])
    h65 = abs(cross(z["M"] - z["B"], mc))
    h5 = abs((z["E"] - z["B"]).imag)  # F_5 is horizontal
    assert abs(k.reactions[(6, 5)].magnitude[0] - 100.0 * h5 / h65) < 1e-9
    verdicts = {row.key: row.verdict for row in check(scene)}
    assert verdicts["reactions.6-5.magnitude"] == "agrees"
    assert verdicts["driving.torque"] in {"agrees", "close"}


def test_cli_forces_json():
    import contextlib
    import io

    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        assert main(["forces", "predavanja-kinetostatika", "--at", "200", "--json"]) == 0
    data = json.loads(out.getvalue())
    k = analyse(load_preset("predavanja-kinetostatika"), math.radians(200))
    r = data["reactions"]
    assert r["4-5"]["x"] == pytest.approx(-r["5-4"]["x"])
    assert r["4-5"]["magnitude"] == pytest.approx(float(k.reactions[(4, 5)].magnitude[0]))
    assert "offset" in r["4-3"]  # the block slides in the rocker's slot
    d = data["driving"]
    assert d["torque"] == pytest.approx(d["torque_zhukovsky"], rel=1e-9)
    assert d["torque"] == pytest.approx(d["torque_power_balance"], rel=1e-9)
    assert d["power"] == pytest.approx(d["torque"] * 10.0)
    assert data["inertia"] == {}  # the lecture leaves inertia out: no masses


def test_cli_forces_of_a_rotor_is_a_clear_error(capsys):
    assert main(["forces", "zbirka-7.1"]) == 2
    assert "not a linkage" in capsys.readouterr().err


def test_a_change_point_is_labelled_not_a_wrong_number():
    """A parallelogram four-bar folds flat at φ₂ = 0: there neither its motion nor the
    coupler-rocker dyad's reactions are determined (NaN, with condition ∞ on both); next to
    it the reactions grow as 1/δ while the three driving torques stay finite and agree."""
    scene = scenes.fourbar(r2=0.1, r3=0.4, r4=0.1, dx=0.4, dy=0.0)
    scene = dataclasses.replace(scene, forces=(Force(4, "B", 10.0, 1.0),))
    k = analyse(scene, np.array([0.0, 1e-6, 1e-3]))
    assert np.isnan(k.reactions[(3, 4)].force[0]) and np.isinf(k.condition["3-4"][0])
    assert np.isinf(k.motion.condition[0]) and np.isnan(k.driving_lever[0])
    assert np.isfinite(k.driving[1:]).all() and abs(k.driving[1] - k.driving[2]) < 1e-2
    grow = k.reactions[(3, 4)].magnitude[1] / k.reactions[(3, 4)].magnitude[2]
    assert 900 < grow < 1100
    assert k.disagreement[1] < 1e-6 and k.disagreement[2] < 1e-9


def test_the_printed_force_polygon_is_at_true_scale():
    """Each arrow of the SVG is |F|/U_F centimetres long and the polygon closes."""
    import re

    from figures.polygon import polygon_svg

    k = analyse(load_preset("predavanja-kinetostatika"))
    actions = free_body(k, (5, 6), 0)
    svg = polygon_svg([(a.name, a.force) for a in actions if a.known],
                      [(a.name, a.force) for a in actions if not a.known], 10.0, "test")
    lines = [tuple(map(float, m)) for m in re.findall(
        r'<line x1="([\d.]+)" y1="([\d.]+)" x2="([\d.]+)" y2="([\d.]+)" stroke="#(?!ddd)', svg)]
    assert [math.hypot(x2 - x1, y2 - y1) for x1, y1, x2, y2 in lines] == pytest.approx(
        [abs(a.force) / 10.0 for a in actions], abs=1e-3)
    assert lines[0][:2] == pytest.approx(lines[-1][2:], abs=1e-3)
    assert re.search(r'width="[\d.]+cm"', svg)


def test_a_coarse_cycle_misses_the_torque_peak():
    from solvers.diagnostics import torque_resolution

    seen = []
    rows = torque_resolution(load_preset("zbirka-5.4"), (12, 72, 360), progress=seen.append)
    assert [r["steps"] for r in rows] == [12, 72, 360] and rows[-1]["change"] == 0.0
    assert abs(rows[0]["change"]) > abs(rows[1]["change"]) > 0  # finer: closer to the peak
    assert seen == sorted(seen) and seen[0] == 0.0
