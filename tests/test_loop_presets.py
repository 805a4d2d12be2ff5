"""The complex-number seed's loop set-up exercises (its tasks 2.3–2.7): each preset's view
writes the task's two contours, with the unknowns the task solves each contour for."""

import numpy as np
import pytest

from mechanisms import load_preset
from methods.analytic import equations
from solvers.diagnostics import solve_instant
from solvers.kinematics import solve

# per task: for contour I and contour II, (the dyad, the angle the task solves for)
CONTOURS = {
    "analitika-2.3": [((3, 4), r"\varphi_{3}"), ((5, 6), r"\varphi_{5}")],
    "analitika-2.4": [((3, 4), r"\varphi_{3}"), ((5, 6), r"\varphi_{5}")],
    "analitika-2.5": [((3, 4), r"\varphi_{4}"), ((6, 7), r"\varphi_{6}")],
    "analitika-2.6": [((3, 4), r"\varphi_{4}"), ((6, 7), r"\varphi_{6}")],
    "analitika-2.7": [((3, 4), r"\varphi_{4}"), ((5, 6), r"\varphi_{5}")],
}


@pytest.mark.parametrize("pid", CONTOURS)
def test_each_contour_is_a_dyad_solved_for_the_tasks_angle_and_one_slide(pid):
    scene = load_preset(pid)
    assert scene.layout_assumed and not scene.book  # no numbers in the task: nothing to judge
    groups = solve_instant(scene, None).structure.groups
    assert [g.members for g in groups] == [members for members, _ in CONTOURS[pid]]
    for group, (_, angle) in zip(groups, CONTOURS[pid]):
        eq = equations(scene, group)
        assert eq.unknowns[0] == angle and eq.unknowns[1].startswith("s_")
        assert angle in eq.position and eq.unknowns[1] in eq.position


@pytest.mark.parametrize("pid", CONTOURS)
def test_the_assumed_dimensions_assemble_over_the_whole_motion(pid):
    scene = load_preset(pid)
    if scene.driver.kind == "rotating":
        at = np.radians(np.arange(0.0, 360.0, 1.0))
    else:  # the driving slider's stroke around its drawn position
        at = np.linspace(scene.driver.at - 0.1, scene.driver.at + 0.1, 201)
    assert solve(scene, at).feasible.all()


def test_a_slotted_levers_angle_is_the_unknown_not_its_blocks():
    """Task 2.5 solves contour I for φ₄, the slotted lever's angle; the block at A follows."""
    scene = load_preset("analitika-2.5")
    group = solve_instant(scene, None).structure.groups[0]
    eq = equations(scene, group)
    assert r"\varphi_{3}" not in eq.position and r"\varphi_{4}" in eq.position
