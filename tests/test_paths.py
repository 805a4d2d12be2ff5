"""Chapter 1 solvers: positions per cycle, drawing accuracy, path metrics, animation order, travel."""

import math

import numpy as np
import pytest

from mechanisms import load_preset
from mechanisms.schema import Travel
from solvers import solve
from solvers.paths import (animation_order, chord_deviation, cycle_time, cycle_values, field_path,
                           loops_backward, path_errors, path_length, solve_times,
                           strokes)

from . import scenes


def test_positions_start_at_the_scenes_instant_and_follow_the_rotation():
    scene = load_preset("analitika-2.1")  # φ₂ = 55°, ω₂ < 0 (clockwise)
    values = np.degrees(cycle_values(scene, 12))
    assert values[0] == pytest.approx(55.0)
    assert values[1] == pytest.approx(55.0 - 30.0)


@pytest.mark.parametrize("steps", [12, 72, 360, 3600])
def test_chord_deviation_of_the_crank_circle_is_its_sagitta(steps):
    """A point on a circle of radius r, drawn from N positions: r·(1 − cos(π/N))."""
    scene = scenes.fourbar(r2=0.1)
    deviation = chord_deviation(scene, steps, ["A"])["A"]
    assert deviation == pytest.approx(0.1 * (1 - math.cos(math.pi / steps)), rel=1e-3)


def test_finer_resolution_draws_closer_to_the_exact_path():
    scene = load_preset("zbirka-1.3")
    deviation = [chord_deviation(scene, n, ["E"])["E"] for n in (12, 72, 360, 3600)]
    assert deviation == sorted(deviation, reverse=True)
    assert deviation[0] / deviation[1] == pytest.approx(36, rel=0.5)  # second order: (72/12)²


def test_path_length_and_stroke_against_hand_values():
    crank = scenes.fourbar(r2=0.1)
    motion = solve(crank, cycle_values(crank, 3600), order=0)
    assert path_length(motion.points["A"].z) == pytest.approx(2 * math.pi * 0.1, rel=1e-6)
    slider = load_preset("slider-crank")  # central: stroke = 2·OA
    motion = solve(slider, cycle_values(slider, 3600), order=0)
    assert strokes(motion)["1-4"] == pytest.approx(0.2, rel=1e-6)
    assert cycle_time(slider) == pytest.approx(2 * math.pi / 20.0)


def test_animation_runs_round_a_full_turn():
    assert list(animation_order(np.ones(5, bool))) == [0, 1, 2, 3, 4]


def test_animation_rocks_between_the_limits_without_jumping():
    feasible = np.array([True] * 4 + [False] * 3 + [True] * 3)  # an arc 7, 8, 9, 0, 1, 2, 3
    order = animation_order(feasible, start=1)
    assert order[0] == 1 and feasible[order].all()
    steps = np.abs(np.diff(order))
    assert set(steps) <= {1, 9}  # neighbours, or 9 ↔ 0 across the seam of the cycle
    assert {3, 7} <= set(order)  # it reaches both limits


def test_travel_numbers_of_task_1_3():
    """The book's chain: ω_t = v_R/R_t, ω_b = ω_t·R_a/R_b, t_c = 2π/ω_b, 12 steps."""
    travel = Travel(speed=3.0, wheel_radius=0.32, sprocket_wheel=0.09, sprocket_crank=0.03)
    assert travel.wheel_omega == pytest.approx(3.0 / 0.32)
    assert travel.crank_omega == pytest.approx(3.0 / 0.32 * 0.09 / 0.03)
    assert travel.cycle_time == pytest.approx(2 * math.pi / 28.125)
    assert travel.step_time() == pytest.approx(0.22340214 / 12, rel=1e-6)
    assert travel.step_distance() == pytest.approx(3.0 * 0.22340214 / 12, rel=1e-6)
    scene = load_preset("zbirka-1.3")
    assert scene.driver.speed == pytest.approx(28.125)


def test_field_path_advances_by_the_travel_of_one_cycle():
    scene = load_preset("zbirka-1.3")
    motion = solve(scene, cycle_values(scene, 360), order=1)
    times, field = field_path(motion, scene.travel, "E", cycles=3)
    tc = scene.travel.cycle_time
    assert times[360] == pytest.approx(tc)
    assert field[360] - field[0] == pytest.approx(3.0 * tc)
    assert field[720] - field[360] == pytest.approx(3.0 * tc)


def test_a_point_loops_back_exactly_when_it_outruns_the_machine():
    """The crank pin: speed r·ω along the travel at its lowest point, against v_R."""
    crank = scenes.fourbar(r2=0.1, omega=20.0)  # r·ω = 2 m/s
    motion = solve(crank, cycle_values(crank, 3600), order=1)
    slow = Travel(speed=1.5, wheel_radius=0.3, sprocket_wheel=0.1, sprocket_crank=0.1)
    fast = Travel(speed=2.5, wheel_radius=0.3, sprocket_wheel=0.1, sprocket_crank=0.1)
    assert loops_backward(motion, slow, "A") == (True, pytest.approx(-0.5, abs=1e-5))
    assert loops_backward(motion, fast, "A") == (False, pytest.approx(0.5, abs=1e-5))


def test_the_tedder_tine_makes_a_true_trochoid_at_the_books_speed():
    scene = load_preset("zbirka-1.3")
    motion = solve(scene, cycle_values(scene, 360), order=1)
    loops, slowest = loops_backward(motion, scene.travel, "E")
    assert loops and slowest < 0


def test_solve_times_and_path_errors_per_resolution():
    scene = scenes.fourbar(r2=0.1)
    times = solve_times(scene, repeat=1)
    errors = path_errors(scene, ["A"])
    assert list(times) == list(errors) == [12, 72, 360, 3600]
    assert all(ms > 0 for ms in times.values())
    # the crank pin's path is a circle: a chord of 30° misses it by r(1 − cos 15°)
    assert errors[12] == pytest.approx(0.1 * (1 - math.cos(math.pi / 12)), rel=1e-3)
    assert errors[72] == pytest.approx(0.1 * (1 - math.cos(math.pi / 72)), rel=1e-3)


def test_a_rockers_limit_positions_are_its_extreme_angles():
    """Crank-rocker: the rocker's limits are where crank and coupler are in line (law of cosines)."""
    from solvers.paths import swings

    scene = load_preset("four-bar-crank-rocker")  # OA 0.1, AB 0.35, DB 0.3, OD 0.4
    motion = solve(scene, cycle_values(scene, 3600), order=0)
    low, high = swings(motion)[4]

    def rocker_angle(reach):  # angle of D→B when |OB| = reach, B above the x-axis
        cos_o = (0.4**2 + reach**2 - 0.3**2) / (2 * 0.4 * reach)
        b = reach * complex(cos_o, math.sqrt(1 - cos_o**2))
        return math.degrees(np.angle(b - 0.4))

    limits = sorted([rocker_angle(0.35 + 0.1), rocker_angle(0.35 - 0.1)])
    assert low == pytest.approx(limits[0], abs=0.05) and high == pytest.approx(limits[1], abs=0.05)
    assert 2 not in swings(motion)  # the crank turns fully
