"""Where a mechanism cannot go, and where it nearly locks: masked and explained, never guessed."""

import math

import numpy as np
import pytest

from mechanisms import load_preset
from solvers import solve
from solvers.diagnostics import dead_zones, explain_open

from . import scenes


def test_task_2_1_cannot_pass_a_range_and_those_positions_are_masked():
    scene = load_preset("analitika-2.1")
    phi = np.radians(np.arange(0.0, 360.0, 0.5))
    motion = solve(scene, phi)
    blocked = np.degrees(phi[~motion.feasible])
    assert blocked.min() == pytest.approx(106.5, abs=0.5) and blocked.max() == pytest.approx(177.0, abs=0.5)
    assert np.isnan(motion.points["M"].x[~motion.feasible]).all()
    assert np.isfinite(motion.points["M"].x[motion.feasible]).all()
    (zone,) = dead_zones(scene)
    assert zone.group == "3-4" and len(zone.ranges) == 1


def test_the_explanation_names_group_condition_and_range():
    scene = load_preset("analitika-2.1")
    at = math.radians(140)
    (issue,) = solve(scene, at).issues
    text = str(explain_open(scene, at, issue))
    assert "II(3-4) RRR" in text and "cannot reach" in text
    assert "106.3°" in text and "177°" in text


def test_assembly_mode_is_kept_across_the_dead_zone():
    """The coupler stays on the same side of the diagonal AD before and after the dead zone."""
    scene = load_preset("analitika-2.1")
    phi = np.radians(np.arange(0.0, 360.0, 0.5))
    motion = solve(scene, phi, order=0)
    a, c, d = motion.points["A"].z, motion.points["C"].z, motion.points["D"].z
    side = np.sign(((c - a) * np.conj(d - a)).imag)[motion.feasible]
    assert (side == side[0]).all()
    # and the motion is continuous where it exists: no jumps between neighbouring positions
    steps = np.abs(np.diff(c))[motion.feasible[1:] & motion.feasible[:-1]]
    assert steps.max() < 0.05  # fast near the limits, but no jump to the other branch


def test_a_grashof_crank_rocker_runs_the_whole_turn():
    motion = solve(load_preset("four-bar-crank-rocker"), np.linspace(0, 2 * np.pi, 720))
    assert motion.feasible.all() and not motion.issues


def test_a_dead_centre_is_flagged_with_its_condition_number():
    """At φ₂ = 180° the distance AD = 0.5 m equals AB + BD: coupler and rocker in line."""
    scene = scenes.fourbar(r2=0.1, r3=0.3, r4=0.2, dx=0.4)
    motion = solve(scene, [math.pi, math.pi - 0.05, 1.0])
    assert motion.condition[2] < 10
    assert motion.condition[0] > 1e6
    (issue,) = [i for i in motion.issues if i.problem == "near-singular"]
    assert issue.group == "3-4" and issue.worst_condition > 1e6
    assert np.isfinite(motion.points["B"].z[0])


def test_parallel_guides_are_open_not_infinite():
    scene = scenes.slotted_crank(gx=0.2, column_deg=90.0)
    motion = solve(scene, [math.radians(89.0), math.radians(90.0)])
    assert list(motion.feasible) == [True, False]
    assert np.isnan(motion.points["B"].y[1])
