"""Property tests over random assemblable mechanisms of every dyad kind (hypothesis)."""

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from mechanisms.schema import Scene
from solvers import decompose, solve

from . import scenes
from .checks import closure_residual, size

length = st.floats(0.05, 1.0)
angle = st.floats(0.0, 2 * math.pi)
branch = st.sampled_from([1, -1])


@st.composite
def mechanisms(draw) -> Scene:
    """A random mechanism of a random dyad kind (whether it assembles is checked later)."""
    kind = draw(st.sampled_from(["RRR", "RRP", "RPR", "PRP", "RPP"]))
    if kind == "RRR":
        scene = scenes.fourbar(draw(length), draw(length), draw(length), draw(length),
                               draw(st.floats(-0.3, 0.3)), branch=draw(branch))
    elif kind == "RRP":
        scene = scenes.slider_crank(draw(length), draw(length), draw(st.floats(-0.2, 0.2)),
                                    draw(st.floats(-60, 60)), branch=draw(branch))
    elif kind == "RPR":
        scene = scenes.rocking_guide(draw(length), draw(st.floats(0.05, 0.5)),
                                     draw(st.floats(-0.5, 0.5)), draw(st.floats(-90, 90)),
                                     branch=draw(branch))
    elif kind == "PRP":
        scene = scenes.slotted_crank(draw(length), draw(st.floats(0.05, 0.5)),
                                     draw(st.floats(-0.5, 0.5)), draw(st.floats(0, 180)))
    else:
        scene = scenes.scotch_yoke(draw(length), draw(st.floats(20, 160)), draw(st.floats(-60, 60)),
                                   draw(st.floats(-0.2, 0.2)))
    assert [g.kind for g in decompose(scene).groups] == [kind]
    return scene


def assembled(scene: Scene, phi: float):
    """The motion at φ₂, or reject the example when it does not assemble or is near a dead centre."""
    motion = solve(scene, phi)
    assume(motion.feasible[0] and motion.condition[0] < 1e3)
    return motion


SETTINGS = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.filter_too_much])


@SETTINGS
@given(mechanisms(), angle)
def test_loop_closes(scene, phi):
    motion = assembled(scene, phi)
    assert closure_residual(scene, motion) <= 1e-12 * size(scene)


@SETTINGS
@given(mechanisms(), angle)
def test_velocities_and_accelerations_match_finite_differences(scene, phi):
    motion = assembled(scene, phi)
    h = 1e-5
    omega = scene.driver.speed
    around = solve(scene, [phi - h, phi + h])
    assume(around.feasible.all())
    for name, p in motion.points.items():
        q = around.points[name]
        v_fd = omega * (q.z[1] - q.z[0]) / (2 * h)
        a_fd = omega * (q.v[1] - q.v[0]) / (2 * h)
        cond = motion.condition[0]
        assert abs(p.v[0] - v_fd) <= 1e-6 * (abs(v_fd) + abs(omega) * size(scene)) * cond
        assert abs(p.a[0] - a_fd) <= 1e-5 * (abs(a_fd) + omega**2 * size(scene)) * cond**2


@SETTINGS
@given(mechanisms(), angle, st.floats(1e-3, 1e3))
def test_scaling_lengths_scales_velocities_and_accelerations(scene, phi, k):
    motion = assembled(scene, phi)
    scaled = dataclasses.replace(
        scene.with_(lengths={n: k * length for n, length in scene.lengths.items()}),
        frame={name: k * z for name, z in scene.frame.items()})
    big = solve(scaled, phi)
    for name, p in motion.points.items():
        q = big.points[name]
        tol = 1e-9 * k * size(scene) * motion.condition[0]
        assert abs(q.z[0] - k * p.z[0]) <= tol
        assert abs(q.v[0] - k * p.v[0]) <= tol * abs(scene.driver.speed)
        # near a limit position the accelerations are huge (1e8 m/s²): rounding is relative
        assert abs(q.a[0] - k * p.a[0]) <= (tol * scene.driver.speed ** 2 * motion.condition[0]
                                            + 1e-9 * abs(k * p.a[0]))


@SETTINGS
@given(mechanisms(), angle)
def test_reversing_the_crank_reverses_velocities_and_keeps_accelerations(scene, phi):
    motion = assembled(scene, phi)
    back = solve(scene.with_(speed=-scene.driver.speed), phi)
    for name, p in motion.points.items():
        q = back.points[name]
        tol = 1e-9 * size(scene) * scene.driver.speed ** 2 * motion.condition[0] ** 2
        assert abs(q.v[0] + p.v[0]) <= tol
        assert abs(q.a[0] - p.a[0]) <= tol


def test_finite_differences_converge_at_second_order():
    """Halving the step quarters the difference: the analytic velocity is the true limit."""
    scene = scenes.fourbar()
    phi = 0.7
    exact = solve(scene, phi).points["E"].v[0]
    errors = []
    for h in (2e-2, 1e-2, 5e-3):
        q = solve(scene, [phi - h, phi + h]).points["E"]
        errors.append(abs(scene.driver.speed * (q.z[1] - q.z[0]) / (2 * h) - exact))
    assert errors[0] / errors[1] == pytest.approx(4.0, rel=0.05)
    assert errors[1] / errors[2] == pytest.approx(4.0, rel=0.05)


def test_positions_only_and_requested_points_only():
    """Compute only what is asked: no velocities for positions, no groups M does not need."""
    from mechanisms import load_preset

    scene = load_preset("analitika-2.1")
    positions = solve(scene, np.radians([55.0, 60.0]), order=0)
    assert positions.points["M"].v is None and positions.members[3].omega is None
    only_c = solve(scene, np.radians([55.0]), points=["C"])
    assert set(only_c.transmission) == {"3-4"}
    assert "M" not in only_c.points and 5 not in only_c.members
    full = solve(scene, np.radians([55.0]))
    assert only_c.points["C"].z[0] == full.points["C"].z[0]
