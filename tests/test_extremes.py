"""Numerical stability at the extremes: each case either gives an accurate result, checked
against an independent reference (a closed form, a constraint the answer must satisfy, an
exact scaling law), or says precisely why it cannot — never NaN, inf or a wrong number
without a label."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from mechanisms import load_preset
from mechanisms.rotor import Correction, Mass, Rotor
from solvers.balancing import balance
from solvers.diagnostics import Unsolvable, solve_instant
from solvers.kinematics import solve
from solvers.kinetostatics import analyse

from . import scenes

CYCLE = np.linspace(0.0, 2 * math.pi, 73)
ROTATING = ["four-bar-crank-rocker", "slider-crank", "zbirka-2.1", "zbirka-2.2", "zbirka-2.5",
            "zbirka-3.1", "tangent-slotted-crank", "zbirka-4.1", "zbirka-4.3", "triad-full-turn",
            "predavanja-kinetostatika"]


def scaled(scene, k: float):
    """Every length of the scene times k: the frame, every member's points and centre."""
    members = {n: dataclasses.replace(m, points={p: k * z for p, z in m.points.items()},
                                      centre=None if m.centre is None else k * m.centre,
                                      gyration=k * m.gyration)
               for n, m in scene.members.items()}
    guess = {p: k * z for p, z in scene.guess.items()}
    return dataclasses.replace(scene, frame={p: k * z for p, z in scene.frame.items()},
                               members=members, guess=guess)


@pytest.mark.parametrize("pid", ROTATING)
@pytest.mark.parametrize("k", [1e-4, 1e4])
def test_a_scene_scaled_from_a_tenth_of_a_millimetre_to_ten_kilometres_scales_exactly(pid, k):
    """Positions, velocities and accelerations scale by k (ω₂ fixed), angles do not."""
    scene = load_preset(pid)
    base, big = solve(scene, CYCLE), solve(scaled(scene, k), CYCLE)
    # at the very edge of a range the group reaches, rounding decides whether it closes
    edge = np.convolve(np.diff(base.feasible.astype(int), prepend=base.feasible[0],
                               append=base.feasible[-1]) != 0, [1, 1], mode="valid") > 0
    assert np.array_equal(base.feasible[~edge], big.feasible[~edge])
    ok = base.feasible & big.feasible
    for name, p in base.points.items():
        q = big.points[name]
        for attr in ("z", "v", "a"):
            ref = k * getattr(p, attr)[ok]
            np.testing.assert_allclose(getattr(q, attr)[ok], ref,
                                       atol=1e-9 * k * max(1.0, float(np.max(np.abs(ref)) / k)))
    for n, m in base.members.items():
        np.testing.assert_allclose(big.members[n].omega[ok], m.omega[ok], rtol=1e-8, atol=1e-9)


def test_one_scene_with_links_from_1e_4_to_1e4_metres_closes_its_loop():
    """A 0.1 mm crank driving 10 km links: every constraint holds to rounding of the largest
    length, and the velocity and acceleration constraints hold as well."""
    scene = scenes.fourbar(r2=1e-4, r3=1e4, r4=1e4, dx=1e4, dy=0.0, ex=10.0, ey=5.0)
    motion = solve(scene, CYCLE)
    assert motion.feasible.all()
    z = {n: p.z for n, p in motion.points.items()}
    v = {n: p.v for n, p in motion.points.items()}
    a = {n: p.a for n, p in motion.points.items()}
    np.testing.assert_allclose(np.abs(z["B"] - z["A"]), 1e4, rtol=1e-14)
    np.testing.assert_allclose(np.abs(z["B"] - z["D"]), 1e4, rtol=1e-14)
    np.testing.assert_allclose(np.abs(z["A"] - z["O"]), 1e-4, rtol=1e-12)
    ab, db = z["B"] - z["A"], z["B"] - z["D"]
    # d/dt |AB|² = 0 and d²/dt² |AB|² = 0 (likewise for DB): velocity and acceleration checks
    dot = lambda p, q: (np.conj(p) * q).real  # noqa: E731
    scale_v = np.max(np.abs(v["A"])) * 1e4
    assert np.max(np.abs(dot(ab, v["B"] - v["A"]))) <= 1e-9 * scale_v
    assert np.max(np.abs(dot(db, v["B"]))) <= 1e-9 * scale_v
    scale_a = np.max(np.abs(a["A"])) * 1e4
    assert np.max(np.abs(dot(ab, a["B"] - a["A"]) + np.abs(v["B"] - v["A"]) ** 2)) <= 1e-9 * scale_a


@pytest.mark.parametrize("omega", [1e-3, 1e4])
def test_angular_velocity_from_1e_3_to_1e4(omega):
    """v ∝ ω₂ and a ∝ ω₂² (ε₂ = 0), exactly; the driving torque of the inertia loads ∝ ω₂²."""
    scene = load_preset("four-bar-crank-rocker")  # has masses
    ref = analyse(scene, CYCLE)
    fast = analyse(scene.with_(speed=omega), CYCLE)
    r = omega / scene.driver.speed
    for name, p in ref.motion.points.items():
        q = fast.motion.points[name]
        np.testing.assert_allclose(q.v, r * p.v, rtol=1e-12, atol=1e-15 * r)
        np.testing.assert_allclose(q.a, r * r * p.a, rtol=1e-12, atol=1e-15 * r * r)
    inertia_only = dataclasses.replace(scene, forces=(), moments=(), gravity=0.0)
    slow_k, fast_k = analyse(inertia_only, CYCLE), analyse(inertia_only.with_(speed=omega), CYCLE)
    np.testing.assert_allclose(fast_k.driving, r * r * slow_k.driving,
                               atol=1e-9 * r * r * np.max(np.abs(slow_k.driving)))
    assert fast_k.disagreement.max() < 1e-9


def test_a_change_point_mechanism_where_branches_meet_is_flagged():
    """s + l = p + q (1 + 3 = 2 + 2): once a turn the four links line up and the two
    assembly branches meet. There the condition number is huge and said to be; elsewhere
    the loop closes."""
    scene = scenes.fourbar(r2=1.0, r3=2.0, r4=2.0, dx=3.0, dy=0.0)
    phi = np.linspace(0.0, 2 * math.pi, 721)
    motion = solve(scene, phi)
    flagged = [i for i in motion.issues if i.problem == "near-singular"]
    assert flagged and flagged[0].worst_condition > 1e3
    assert any(lo <= math.pi <= hi for lo, hi in flagged[0].ranges)  # A, B, D in line at φ₂ = π
    ok = motion.feasible
    z = motion.points
    np.testing.assert_allclose(np.abs(z["B"].z - z["A"].z)[ok], 2.0, rtol=1e-9)


def test_a_crank_driven_exactly_onto_its_limit():
    """Non-Grashof four-bar: the crank reaches its limit where coupler and crank line up
    (|DA| = AB + BD). At that angle the position is exact and flagged singular; a hair past
    it the group cannot close, and the explanation names the group and the condition."""
    r2, r3, r4, dx = 0.3, 0.25, 0.3, 0.5
    limit = math.acos((r2 ** 2 + dx ** 2 - (r3 + r4) ** 2) / (2 * r2 * dx))  # law of cosines
    scene = scenes.fourbar(r2=r2, r3=r3, r4=r4, dx=dx, dy=0.0)
    motion = solve(scene, [limit * (1 - 1e-12)])
    assert motion.feasible[0]
    b = motion.points["B"].z[0]
    assert abs(abs(b - motion.points["A"].z[0]) - r3) < 1e-9
    assert abs(abs(b - dx) - r4) < 1e-9
    assert motion.condition[0] > 1e4
    with pytest.raises(Unsolvable, match=r"3-4.*cannot close|cannot reach"):
        solve_instant(scene.with_(at=limit * (1 + 1e-6)), None)


@pytest.mark.parametrize("delta", [1e-2, 1e-4, 1e-6])
def test_nearly_parallel_guides(delta):
    """Tangent slotted crank: the slider's line x = 0.2 and the slot along the crank are
    nearly parallel at φ₂ = 90° − δ. y_B = 0.2·tan φ₂ and v_B = 0.2·ω/cos² φ₂ hold there,
    the Coriolis part is 2·ω₂·v_rel, and the position is flagged near-singular as δ → 0."""
    scene = load_preset("tangent-slotted-crank")
    phi = math.pi / 2 - delta
    motion = solve(scene, [phi])
    omega = scene.driver.speed
    assert motion.points["B"].y[0] == pytest.approx(0.2 * math.tan(phi), rel=1e-9)
    assert motion.points["B"].vy[0] == pytest.approx(0.2 * omega / math.cos(phi) ** 2, rel=1e-8)
    slider = motion.sliders["slot"]  # block 3 in the slot along crank 2
    assert abs(slider.coriolis[0]) == pytest.approx(2 * abs(omega * slider.v[0]), rel=1e-9)
    if delta <= 1e-4:
        assert motion.condition[0] > 1e3 and any(i.problem == "near-singular" for i in motion.issues)


def test_a_special_point_at_infinity_is_labelled_not_a_number():
    """Where the two binary lines of a class III group are parallel, S is at infinity: NaN
    in the arrays, null in the JSON, never a huge finite number."""
    from reports.values import motion_json

    scene = load_preset("triad-full-turn")
    phi = np.linspace(0.0, 2 * math.pi, 3601)
    motion = solve(scene, phi)
    s = motion.special["S"].z
    finite = np.isfinite(s)
    reach = 100 * max(abs(z) for z in scene.frame.values())
    assert np.all(np.abs(s[finite]) < 1e6 * reach)  # near-parallel: far, but a number
    if not finite.all():
        at_inf = phi[~finite][0]
        assert motion_json(solve(scene, [at_inf]))["special_points"]["S"] is None


@pytest.mark.parametrize("masses", [(1e-6, 1e3, 0.5), (1e3, 1e-6, 1e-6)])
def test_a_rotor_with_masses_from_a_milligram_to_a_tonne(masses):
    """Masses spanning nine decades in one rotor: after correction the residual force and
    moment are at rounding level of the largest unbalance."""
    rotor = Rotor(id="r", title="r", source="", note="", mode="dynamic",
                  masses=tuple(Mass(m, 0.1 + 0.05 * i, 0.7 * i + 0.3, 0.1 * (i + 1))
                               for i, m in enumerate(masses)),
                  planes={"I": 0.0, "II": 0.5},
                  corrections={"I": Correction(radius=0.2), "II": Correction(radius=0.2)})
    result = balance(rotor)
    largest = max(m * (0.1 + 0.05 * i) for i, m in enumerate(masses))
    assert result.residual_force <= 1e-12 * largest
    assert result.residual_moment <= 1e-12 * largest
    assert all(math.isfinite(c.mass) and c.mass > 0 for c in result.corrections.values())


def test_a_dead_point_of_a_class_iii_group_is_flagged():
    """triad-full-turn's group passes a dead point near φ₂ = 271.7°: the solver names the
    group and the range, with the condition number."""
    scene = load_preset("triad-full-turn")
    motion = solve(scene, np.linspace(0.0, 2 * math.pi, 3601))
    (issue,) = [i for i in motion.issues if i.problem == "near-singular"]
    assert issue.group == "3-4-5-6" and issue.worst_condition > 1e3
    assert any(math.radians(271) <= lo <= math.radians(273) for lo, _ in issue.ranges)
