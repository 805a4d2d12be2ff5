"""The final contour of the complex-number method: a point that is no joint, from the origin
through the crank, differentiated twice (issue 23, item 5)."""

from __future__ import annotations

import numpy as np
import pytest

from mechanisms import load_preset
from mechanisms.loader import preset_ids
from methods.contour import contour, free_points, latex, values
from solvers.kinematics import solve


@pytest.mark.parametrize("pid", preset_ids("linkage"))
def test_the_final_contour_gives_the_solvers_position_velocity_and_acceleration(pid):
    scene = load_preset(pid)
    at = np.array([scene.driver.at, scene.driver.at + 0.1])
    motion = solve(scene, at)
    for name in free_points(scene):
        c = contour(scene, name)
        if c is None:  # reached only across a guide (the scotch yoke's slot point)
            continue
        for i in range(2):
            r, v, a = values(motion, c, i)
            p = motion.points[name]
            assert abs(r - p.z[i]) < 1e-12
            assert abs(v - p.v[i]) < 1e-12 * max(1.0, abs(p.v[i]))
            assert abs(a - p.a[i]) < 1e-12 * max(1.0, abs(p.a[i]))


def test_the_contour_goes_through_the_crank_as_the_seed_does():
    scene = load_preset("four-bar-crank-rocker")
    c = contour(scene, "E")
    crank_pin = next(p.point for p in scene.pairs if set(p.members) == {2, 3})
    assert c.joints[1] == crank_pin and [leg.ref for leg in c.legs] == [1, 2, 3]
    a_line, _, b_line, *_ = latex(solve(scene), c)
    assert r"\varphi_{2}" in a_line and r"\varphi_{3}" in a_line
    assert r"i\omega_{3}" in b_line
