"""What the solver plans once per scene (issue 21, item 4) must never change an answer: each
point is read where some member carries it, constants are shared read-only, and a changed
scene gets a plan of its own."""

from __future__ import annotations

import math

import numpy as np
import pytest

from mechanisms import load_preset, preset_ids
from mechanisms.schema import FRAME
from solvers.kinematics import solve

CYCLE = np.linspace(0.0, 2 * math.pi, 37)


def linkages() -> list[str]:
    return [pid for pid in preset_ids() if not pid.startswith(("gears", "rotor", "zbirka-6", "zbirka-7"))]


@pytest.mark.parametrize("pid", linkages())
def test_a_point_is_where_every_member_that_carries_it_puts_it(pid):
    scene = load_preset(pid)
    at = CYCLE if scene.driver.kind == "rotating" else scene.driver.at + np.linspace(-1e-3, 1e-3, 5)
    motion = solve(scene, at, order=0)
    size = max(abs(z) for m in scene.members.values() for z in m.points.values())
    checked = 0
    for number, body in motion.bodies.items():
        for name, local in scene.points_of(number).items():
            ok = motion.feasible & np.isfinite(motion.points[name].z)
            gap = np.abs(body.position(local) - motion.points[name].z)[ok]
            assert np.all(gap <= 1e-9 * size), (name, number, float(np.max(gap, initial=0)))
            checked += 1
    assert checked > len(scene.frame)


def test_frame_points_are_the_frames_own_at_every_resolution_and_read_only():
    scene = load_preset("four-bar-crank-rocker")
    for n in (12, 360, 12):
        motion = solve(scene, np.linspace(0, 2 * math.pi, n), order=2)
        for name, z in scene.frame.items():
            point = motion.points[name]
            assert point.z.shape == (n,) and np.all(point.z == z) and np.all(point.v == 0)
            with pytest.raises(ValueError):
                point.z[0] = 1.0


def test_a_changed_scene_is_solved_with_its_own_plan():
    scene = load_preset("four-bar-crank-rocker")
    before = solve(scene, CYCLE, order=0).points["B"].z
    longer = scene.with_(lengths={3: 0.4})
    after = solve(longer, CYCLE, order=0)
    a, b = after.points["A"].z, after.points["B"].z
    assert np.allclose(np.abs(b - a), 0.4, rtol=0, atol=1e-14)
    assert np.max(np.abs(after.points["B"].z - before)) > 1e-3
    assert np.array_equal(solve(scene, CYCLE, order=0).points["B"].z, before)


def test_points_asked_for_alone_are_the_same_as_in_the_whole_solve():
    scene = load_preset("zbirka-2.2")
    whole = solve(scene, CYCLE, order=2)
    for name in scene.point_names:
        if name in scene.frame:
            continue
        alone = solve(scene, CYCLE, order=2, points=[name]).points[name]
        assert np.array_equal(alone.z, whole.points[name].z, equal_nan=True)
        assert np.array_equal(alone.a, whole.points[name].a, equal_nan=True)
    assert FRAME in whole.bodies


def test_the_crank_s_turn_is_kept_by_the_angles_values_not_by_the_array():
    """solvers.kinematics._TURNS: the same angles again reuse e^{iφ₂} (read-only); the same
    array changed in place is new angles, and is solved as such."""
    scene = load_preset("four-bar-crank-rocker")
    at = np.linspace(0.0, 2 * math.pi, 360, endpoint=False)
    first = solve(scene, at, order=0).members[2].rot
    again = solve(scene, at.copy(), order=0).members[2].rot
    assert again is first and not first.flags.writeable
    assert np.allclose(first, np.exp(1j * at), atol=1e-15, rtol=0)
    at += 0.25  # in place: the same object, other angles
    moved = solve(scene, at, order=0)
    assert np.allclose(moved.members[2].rot, np.exp(1j * at), atol=1e-15, rtol=0)
    assert np.allclose(moved.points["B"].z, solve(scene, at.copy(), order=0).points["B"].z)


def test_the_same_bytes_in_another_shape_are_not_the_same_turn():
    """A kept turn is found by the angles' shape and type as well as their bytes."""
    from solvers.kinematics import _turn

    at = np.linspace(0.0, 2 * math.pi, 12, endpoint=False)
    assert _turn(at).shape == (12,)
    assert _turn(at.reshape(3, 4)).shape == (3, 4)
    assert _turn(at[:1]).shape == (1,) and _turn(np.float64(at[0]).reshape(())).shape == ()
