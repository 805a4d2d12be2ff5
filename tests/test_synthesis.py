"""Path synthesis (solvers/synthesis.py, docs/synthesis.md): a four-bar's own coupler points
give that four-bar's error back (~0) in every timing mode; every answer keeps the task's rules
and is the kinematics core's own re-solve; bad tasks are refused in one line naming the field."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from mechanisms import load_scene, parse_scene
from mechanisms.synthesis import SynthesisTask, parse_task
from solvers import solve
from solvers.synthesis import keeps_rules, synthesize

from .test_cli import run

ROOT = Path(__file__).resolve().parents[1]
TEMPLATE = ROOT / "mechanisms" / "templates" / "four-bar.toml"
ANGLES = np.radians([20.0, 75.0, 130.0, 190.0, 250.0, 310.0])  # φ₂ from +x (the frame line)


def template_points() -> np.ndarray:
    """The builder's four-bar template's coupler point M, solved by the app itself."""
    return solve(load_scene(TEMPLATE), ANGLES, order=0).points["M"].z


def _task(**fields) -> SynthesisTask:
    m = template_points()
    base = dict(points=tuple(complex(z) for z in m), max_length=1.0, box=1.0)
    return SynthesisTask(**{**base, **fields})


TASKS = {
    "angles, O and the frame line fixed": dict(timing="angles", crank_angles=tuple(np.degrees(ANGLES)),
                                               crank_pivot=0j, frame_angle=0.0),
    "angles, O and the frame line free": dict(timing="angles", crank_angles=tuple(np.degrees(ANGLES))),
    "steps": dict(timing="steps", crank_steps=tuple(np.degrees(np.diff(ANGLES)))),
    "free": dict(timing="free"),
}


@pytest.mark.parametrize("name", list(TASKS))
def test_a_four_bars_own_coupler_points_give_an_error_of_about_zero(name):
    task = _task(**TASKS[name])
    result = synthesize(task, seed=1, budget=60_000, seconds=60)
    size = np.max(np.abs(np.array(task.points)))
    assert result.objective < 1e-10 * size ** 2 * len(task.points), result.objective
    assert keeps_rules(result.linkage, task)
    # the answer is the kinematics core's: the scene, loaded anew, passes the points
    again = solve(parse_scene(result.scene_toml), np.radians(result.crank_deg), order=0)
    assert np.allclose(again.points["M"].z, task.points, atol=1e-6 * size)


def test_where_the_timing_is_given_the_template_itself_comes_back():
    """O, the frame line and the crank's angles fixed: the shape is determined by the
    points, so the search must find the template's very links."""
    template = load_scene(TEMPLATE)
    result = synthesize(_task(**TASKS["angles, O and the frame line fixed"]), seed=3,
                        budget=60_000, seconds=60)
    link = result.linkage
    assert math.isclose(link.crank, template.members[2].length, rel_tol=1e-6)
    assert math.isclose(link.coupler, template.members[3].length, rel_tol=1e-6)
    assert math.isclose(link.rocker, template.members[4].length, rel_tol=1e-6)
    assert abs(link.D - template.frame["D"]) < 1e-6
    assert abs(link.point - template.members[3].points["M"]) < 1e-6


@settings(max_examples=12, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(points=st.lists(st.tuples(st.floats(-5, 5), st.floats(-5, 5)), min_size=3, max_size=7,
                       unique=True),
       timing=st.sampled_from(["free", "steps", "angles"]),
       fixed=st.booleans(), seed=st.integers(1, 10_000))
def test_every_answer_keeps_the_rules_and_is_the_solvers_own(points, timing, fixed, seed):
    pts = [complex(x, y) for x, y in points]
    if max(abs(p - q) for p in pts for q in pts) < 0.5:
        return
    n = len(pts)
    extra = {}
    if timing == "angles":
        extra["crank_angles"] = tuple(float(a) for a in np.linspace(0, 300, n))
    if timing == "steps":
        extra["crank_steps"] = (40.0,) * (n - 1)
    if fixed:
        extra.update(crank_pivot=0j, frame_angle=15.0)
    task = SynthesisTask(points=tuple(pts), timing=timing, max_length=20.0, min_length=0.2,
                         box=10.0, **extra)
    result = synthesize(task, seed=seed, budget=3_000, seconds=60)
    link = result.linkage
    assert keeps_rules(link, task)
    lengths = sorted([link.frame, link.crank, link.coupler, link.rocker])
    assert link.crank == lengths[0] and lengths[0] + lengths[3] < lengths[1] + lengths[2]
    assert all(0.2 <= r <= 20 for r in lengths)
    for p in (link.O, link.D):  # (D = O + OD·e^{iθ}: a float's last digit)
        assert abs(p.real) <= 10 * (1 + 1e-15) and abs(p.imag) <= 10 * (1 + 1e-15)
    # one branch over the whole turn: the loaded scene closes at every position, and the
    # objective is the re-solved one
    scene = parse_scene(result.scene_toml)
    turn = solve(scene, np.linspace(0, 2 * np.pi, 721), order=0)
    assert turn.feasible.all()
    at = solve(scene, np.radians(result.crank_deg), order=0).points["M"].z
    assert math.isclose(result.objective, float(np.sum(np.abs(at - np.array(pts)) ** 2)),
                        rel_tol=1e-9, abs_tol=1e-12)


BAD = {
    "two points": ("points = [[0, 0], [1, 1]]", "points"),
    "NaN": ("points = [[0, 0], [1, 1], [2, nan]]", "points[2]"),
    "infinity": ("points = [[0, 0], [1, inf], [2, 0]]", "points[1]"),
    "a timing list of the wrong length": (
        'points = [[0, 0], [1, 1], [2, 0]]\ntiming = "angles"\ncrank_angles = [0, 10]', "crank_angles"),
    "steps missing": ('points = [[0, 0], [1, 1], [2, 0]]\ntiming = "steps"', "crank_steps"),
    "bounds that leave no four-bar": (
        "points = [[0, 0], [1, 1], [2, 0]]\nmin_length = 5\nmax_length = 4", "min_length"),
    "a pivot outside the box": (
        "points = [[0, 0], [1, 1], [2, 0]]\ncrank_pivot = [9, 0]\nbox = 5", "crank_pivot"),
    "an unknown key": ("points = [[0, 0], [1, 1], [2, 0]]\nspeed = 3", "speed"),
    "an unknown timing": ('points = [[0, 0], [1, 1], [2, 0]]\ntiming = "fast"', "timing"),
    "not TOML": ("points = [[0, 0]", "TOML"),
}


@pytest.mark.parametrize("name", list(BAD))
def test_a_bad_task_exits_2_with_one_line_naming_the_field(name, tmp_path):
    text, field = BAD[name]
    path = tmp_path / "task.toml"
    path.write_text(text)
    done = run("synthesize", str(path))
    assert done.returncode == 2, done.stderr
    assert done.stdout == "" and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert field in done.stderr and "Traceback" not in done.stderr


@pytest.mark.parametrize("args", [["missing.toml"], ["."], ["{task}", "--budget", "0"],
                                  ["{task}", "--seconds", "nan"]])
def test_a_bad_file_or_number_on_the_command_line_exits_2(args, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    task = tmp_path / "task.toml"
    task.write_text("points = [[0, 0], [1, 1], [2, 0]]")
    done = run("synthesize", *[a.format(task=task) for a in args])
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr


def test_the_json_answer_is_what_solve_prints_for_its_scene(tmp_path):
    task = tmp_path / "task.toml"
    task.write_text('points = [[3, 3], [2.759, 3.363], [2.372, 3.663]]\ntiming = "angles"\n'
                    "crank_angles = [30, 45, 60]\ncrank_pivot = [0, 0]\nframe_angle = 0\n"
                    "max_length = 50\nbox = 50\n")
    done = subprocess.run([sys.executable, "-m", "solvers", "synthesize", str(task), "--json",
                           "--budget", "20000"], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert done.returncode == 0, done.stderr
    data = json.loads(done.stdout)
    assert {"objective", "evaluations", "seconds", "mechanism", "positions", "scene"} <= set(data)
    assert set(data["mechanism"]) >= {"O", "D", "crank", "coupler", "rocker"}
    scene = tmp_path / "found.toml"
    scene.write_text(data["scene"])
    total = 0.0
    for position, target in zip(data["positions"], [(3, 3), (2.759, 3.363), (2.372, 3.663)]):
        solved = json.loads(run("solve", str(scene), "--at",
                                 repr(position["crank_angle_deg"]), "--json").stdout)
        for name in ("A", "B", "M"):
            p = solved["points"][name]
            assert np.allclose([p["x"], p["y"]], position[name], atol=1e-9)
        total += (solved["points"]["M"]["x"] - target[0]) ** 2 + (solved["points"]["M"]["y"] - target[1]) ** 2
    assert math.isclose(total, data["objective"], rel_tol=1e-6, abs_tol=1e-15)
    assert data["mechanism"]["O"] == [0.0, 0.0]
    assert [round(p["crank_angle_deg"], 9) for p in data["positions"]] == [30, 45, 60]


def test_the_text_answer_has_units_and_each_points_error(tmp_path):
    task = tmp_path / "task.toml"
    task.write_text("points = [[0, 0], [1, 1], [2, 0], [1, -1]]\n")
    done = run("synthesize", str(task), "--budget", "5000")
    assert done.returncode == 0, done.stderr
    assert "error" in done.stdout and "φ₂ °" in done.stdout and done.stdout.count("\n") > 8


def test_the_same_seed_gives_the_same_four_bar():
    task = parse_task("points = [[0, 0], [1, 1], [2, 0], [1, -1]]\n")
    a, b = (synthesize(task, seed=7, budget=5_000, seconds=60) for _ in range(2))
    assert a.scene_toml == b.scene_toml
