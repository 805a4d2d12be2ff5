"""Chapter 1 page as a user drives it (AppTest): the numbers in the figures follow the inputs."""

import math
import re

import numpy as np
import pytest

from mechanisms import load_preset
from solvers import solve
from solvers.paths import cycle_values

from .test_pages import chart, decode, page, traces


def positions(at, point: str) -> np.ndarray:
    (trace,) = traces(chart(at, "paths"), f"positions of {point}")
    z = np.asarray(decode(trace["x"]), float) + 1j * np.asarray(decode(trace["y"]), float)
    return z[[bool(label) for label in trace["text"]]]  # the path's closing point has none


def fourbar(**state):
    return page("pages/trajectories.py", lang="en", scene="four-bar-crank-rocker", points=["A", "E"],
                **state)


def test_twelve_numbered_positions_follow_the_sense_of_rotation():
    at = fourbar()
    a = positions(at, "A")
    assert len(a) == 12
    assert np.angle(a[1] / a[0]) == pytest.approx(math.radians(30))  # ω₂ > 0: counter-clockwise
    at.slider(key="omega").set_value(-10.0).run()
    a = positions(at, "A")
    assert np.angle(a[1] / a[0]) == pytest.approx(math.radians(-30))
    (metric,) = [m for m in at.metric if m.label.startswith("Time per cycle")]
    assert metric.value == f"{2 * math.pi / 10:.4g} s"


def test_a_longer_crank_draws_a_bigger_crank_circle():
    at = fourbar()
    assert np.abs(positions(at, "A")) == pytest.approx(np.full(12, 0.1))
    at.slider(key="L2").set_value(0.12).run()
    assert not at.exception
    assert np.abs(positions(at, "A")) == pytest.approx(np.full(12, 0.12))


def test_the_resolution_table_follows_the_lengths_and_times_each_mechanism_once():
    """A length changes the drawn paths' error (the crank pin's circle: r(1 − cos 15°) at 12
    positions) but not the solve times, measured once for the mechanism as loaded."""
    at = fourbar(accuracy_open=True)

    def table():
        frame = at.dataframe[0].value
        return frame["solve time [ms]"].tolist(), frame["largest chord deviation [mm]"].tolist()

    times, errors = table()
    at.slider(key="L2").set_value(0.12).run()
    new_times, new_errors = table()
    assert new_times == times
    assert float(new_errors[0]) > float(errors[0])
    assert float(new_errors[0]) >= 1e3 * 0.12 * (1 - math.cos(math.pi / 12)) * 0.999


def test_a_rockers_swing_angle_is_shown_with_its_limit_positions():
    at = fourbar()
    (metric,) = [m for m in at.metric if m.label == "Swing angle of member 4"]
    low, high = (float(v) for v in re.findall(r"(-?[\d.]+)°", metric.delta))
    assert 0 < high - low < 180
    assert float(metric.value.rstrip("°")) == pytest.approx(high - low, abs=0.1)


def test_the_tedder_advances_by_its_travel_each_cycle_and_closes_relative_to_the_machine():
    at = page("pages/trajectories.py", lang="en", scene="zbirka-1.3", res=360, tab="In the field")
    at.slider(key="vR").set_value(4.0).run()
    assert not at.exception
    (field,) = traces(chart(at, "field"), "path of E in the field")
    x, y = np.asarray(decode(field["x"]), float), np.asarray(decode(field["y"]), float)
    omega_b = 4.0 / 0.32 * 0.09 / 0.03
    tc = 2 * math.pi / omega_b
    assert x[360] - x[0] == pytest.approx(4.0 * tc)  # one cycle of travel along +x
    assert y[360] == pytest.approx(y[0])  # the relative path closes after one cycle
    labels = {m.label: m.value for m in at.metric}
    assert labels["ω_b = ω₂ — crank"] == f"{omega_b:.4g} s⁻¹"


def test_a_mechanism_with_a_dead_zone_warns_and_rocks():
    at = page("pages/trajectories.py", lang="en", scene="analitika-2.1", tab="Animation")
    assert not at.exception
    assert "cannot pass" in at.warning[0].value
    assert any("rocks" in m.value or "limit position" in m.value for m in at.info)


def test_the_speed_accuracy_section_is_filled_only_while_open():
    """Closed (as a page opens), a length step measures no path errors and sends no table;
    the paths' CSV stays under the chart."""
    at = fourbar()
    assert not at.dataframe
    assert [e.label for e in at.expander if e.label == "Speed and accuracy"]
    paths = [b for b in at.get("download_button") if b.proto.label.startswith("Download the paths")]
    assert len(paths) == 1
    at.session_state["accuracy_open"] = True
    at.run()
    assert len(at.dataframe) == 1


def test_the_speed_accuracy_table_covers_every_resolution():
    at = fourbar(accuracy_open=True)
    table = at.dataframe[0].value
    assert list(table.iloc[:, 0]) == [12, 72, 360, 3600]
    deviation = [float(v) for v in table.iloc[:, 2]]
    assert deviation == sorted(deviation, reverse=True)


def test_serbian_page_uses_the_decimal_comma():
    at = page("pages/trajectories.py", lang="sr", scene="four-bar-crank-rocker")
    (metric,) = [m for m in at.metric if m.label.startswith("Vreme jednog ciklusa")]
    assert metric.value == "0,6283 s"


def test_animation_frames_carry_only_the_moving_traces_and_never_jump():
    at = page("pages/trajectories.py", lang="en", scene="analitika-2.1", res=360, points=["M"],
              tab="Animation")
    spec = chart(at, "animation")
    frames = spec["frames"]
    assert 10 < len(frames) <= 120
    moving = frames[0]["traces"]
    assert 0 not in moving  # the still, faint path is not resent
    assert all(f["traces"] == moving and len(f["data"]) == len(moving) for f in frames)
    angles = np.radians([float(s["label"]) for s in spec["layout"]["sliders"][0]["steps"]])
    jumps = np.abs(np.angle(np.exp(1j * np.diff(angles))))
    # 289 feasible positions rock there and back (576 frames), shown every 5th: 5° steps at most,
    # also where the motion turns back at the limits
    assert jumps.max() <= math.radians(5.01)


def test_the_construction_numbers_the_crank_pin_and_draws_the_compass_circles():
    at = page("pages/trajectories.py", lang="en", scene="zbirka-1.1")
    spec = chart(at, "paths")
    assert traces(spec, "positions of B") and traces(spec, "positions of K")
    (circles,) = traces(spec, "compass circles")
    x, y = np.asarray(decode(circles["x"]), float), np.asarray(decode(circles["y"]), float)
    first, second = np.split(x + 1j * y, np.flatnonzero(np.isnan(x))[:2])[:2]
    radii = sorted([np.nanmean(np.abs(first - 0)), np.nanmean(np.abs(second[1:] - 0.2))])
    assert radii == pytest.approx([0.06, 0.16], abs=1e-3)  # crank AB about A, rocker DC about D


def test_the_construction_shows_the_mechanism_in_pencil_in_each_position_it_reaches():
    """One grey line trace holds every member of every copy (a member with three points is a
    closed outline of four), a gap after each; the frame's pivots are drawn once, bold."""
    at = page("pages/trajectories.py", lang="en", scene="analitika-2.1")
    figure = chart(at, "paths")
    faint = [tr for tr in figure["data"] if tr.get("opacity") == 0.18]
    pencil = faint[0]
    assert pencil["mode"] == "lines" and "marker" not in pencil
    scene = load_preset("analitika-2.1")
    motion = solve(scene, cycle_values(scene, 12))
    per_copy = sum(len(m.points) + (len(m.points) > 2) + 1 for m in scene.members.values())
    assert len(decode(pencil["x"])) == per_copy * int(motion.feasible.sum())
    assert motion.feasible.sum() < 12  # this four-bar cannot pass a range: fewer copies
    (frame,) = traces(figure, "1 frame")
    assert frame["opacity"] == 1.0
