"""The command line as a user runs it: ``python -m solvers …``.

Each test runs ``cli.main`` — what ``python -m solvers`` hands over to (solvers/__main__.py)
— in this process, with its output captured and an argparse exit taken as the exit code: a
fresh interpreter per call cost 1.5–2 s of imports, most of this file's time.
``test_python_m_solvers_is_the_same_command_line`` runs the real entry point in its own
process, as a user's shell does."""

import contextlib
import io
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

from cli import main

from .test_reference_tasks import fourbar_2_1

ROOT = Path(__file__).resolve().parents[1]


def run(*args: str) -> subprocess.CompletedProcess:
    """``python -m solvers *args`` from the project's folder: its exit code and output."""
    out, err = io.StringIO(), io.StringIO()
    here = os.getcwd()
    os.chdir(ROOT)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            try:
                code = main(list(args))
            except SystemExit as exc:  # argparse's own refusals and --help
                code = exc.code if isinstance(exc.code, int) else 2
    finally:
        os.chdir(here)
    return subprocess.CompletedProcess(["python", "-m", "solvers", *args], code,
                                       out.getvalue(), err.getvalue())


def test_python_m_solvers_is_the_same_command_line():
    done = subprocess.run([sys.executable, "-m", "solvers", "solve", "analitika-2.1", "--json"],
                          cwd=ROOT, capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout) == json.loads(run("solve", "analitika-2.1", "--json").stdout)
    bad = subprocess.run([sys.executable, "-m", "solvers", "solve", "no-such-scene"], cwd=ROOT,
                         capture_output=True, text=True, timeout=60)
    assert bad.returncode == 2 and bad.stderr.startswith("error:") and "Traceback" not in bad.stderr


def test_solve_json_has_exactly_the_documented_layout_and_exact_values():
    out = run("solve", "analitika-2.1", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert list(data) == ["scene", "at", "points", "members", "sliders"]
    assert data["scene"] == "analitika-2.1" and data["at"] == 55.0
    assert set(data["points"]) == {"O", "A", "B", "C", "D", "E", "M"}
    assert set(data["points"]["M"]) == {"x", "y", "vx", "vy", "ax", "ay", "v", "a"}
    m = data["points"]["M"]
    assert m["v"] == pytest.approx(math.hypot(m["vx"], m["vy"]))
    assert set(data["members"]["4"]) == {"angle_deg", "omega", "epsilon"}
    assert set(data["sliders"]["5-6"]) == {"s", "v", "a", "coriolis"}
    ref = fourbar_2_1(math.radians(55))
    assert data["members"]["4"]["omega"] == pytest.approx(ref["w4"], rel=1e-10)
    assert data["members"]["3"]["angle_deg"] == pytest.approx(math.degrees(ref["phi3"]) % 360, abs=1e-9)


def test_solve_task_2_2_at_the_books_instant():
    out = run("solve", "analitika-2.2", "--json")
    data = json.loads(out.stdout)
    assert data["at"] == 0.17
    assert data["points"]["A"]["vy"] == pytest.approx(3.0)
    assert data["sliders"]["1-2"]["v"] == pytest.approx(3.0)
    assert data["members"]["3"]["angle_deg"] == pytest.approx(349.6, abs=0.1)  # not the book's 195.22


def test_a_position_the_crank_cannot_reach_fails_with_the_reason():
    out = run("solve", "analitika-2.1", "--at", "140")
    assert out.returncode == 3
    assert out.stdout == ""
    assert "cannot close at φ₂ = 140°" in out.stderr and "cannot pass" in out.stderr
    assert "Traceback" not in out.stderr


def test_bad_scene_file_and_unknown_preset_exit_2_without_traceback(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('[frame]\nO = [0, 0]\n[members.3]\npoints = ["A", "B"]\nlength = -0.2\n')
    out = run("solve", str(bad))
    assert out.returncode == 2 and "bad.toml: members.3.length must be > 0, got -0.2" in out.stderr
    missing = run("solve", "no-such-preset")
    assert missing.returncode == 2 and "known presets" in missing.stderr
    assert "Traceback" not in out.stderr + missing.stderr


def test_list_and_structure():
    out = run("list")
    assert "analitika-2.1" in out.stdout and "Four-bar" in out.stdout
    data = json.loads(run("structure", "analitika-2.2", "--json").stdout)
    assert data["dof"] == 1 and data["formula"] == "I(1,2) → II(3,4) → II(5,6)"
    assert [g["kind"] for g in data["groups"]] == ["RPR", "RRP"]


def test_text_output_has_units():
    out = run("solve", "slider-crank", "--at", "90")
    assert out.returncode == 0
    assert "vx m/s" in out.stdout and "ε rad/s²" in out.stdout


def test_bench_prints_the_ratio_and_the_error():
    out = run("bench", "four-bar-crank-rocker", "--steps", "360", "--repeat", "5")
    assert out.returncode == 0, out.stderr
    assert "ratio mehanizmi / baseline" in out.stdout
    error = float(out.stdout.split("angles ")[1].split(" rad")[0])
    assert error < 1e-12


def test_the_hay_tedder_adds_its_travel_block():
    data = json.loads(run("solve", "zbirka-1.3", "--json").stdout)
    travel = data["travel"]
    assert set(travel) == {"wheel_omega", "crank_omega", "cycle_time", "step_time", "step_distance"}
    assert travel["wheel_omega"] == pytest.approx(3.0 / 0.32)
    assert travel["crank_omega"] == pytest.approx(28.125)
    assert travel["step_distance"] == pytest.approx(3.0 * 2 * math.pi / 28.125 / 12)
    assert data["members"]["2"]["omega"] == pytest.approx(28.125)


def test_rotor_json_has_the_corrections_and_the_residual():
    out = run("solve", "zbirka-7.1", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    assert list(data) == ["scene", "kind", "corrections", "residual"]
    assert data["kind"] == "rotor" and set(data["corrections"]) == {"I", "II"}
    assert set(data["corrections"]["I"]) == {"mass", "radius", "angle_deg"}
    assert data["corrections"]["I"]["radius"] == 0.2
    assert data["residual"]["force"] < 1e-12 and data["residual"]["moment"] < 1e-12


def test_an_unbalanceable_rotor_file_exits_3_with_the_reason(tmp_path):
    bad = tmp_path / "flat.toml"
    bad.write_text('kind = "rotor"\n[planes]\nI = 0.1\nII = 0.1\n[[masses]]\nmass = 0.1\n'
                   'radius = 0.1\nangle = 0\nx = 0.3\n[corrections.I]\nradius = 0.1\n'
                   '[corrections.II]\nradius = 0.1\n')
    out = run("solve", str(bad))
    assert out.returncode == 3 and "same axial position" in out.stderr


def test_gear_train_json():
    data = json.loads(run("solve", "zbirka-6.4", "--json").stdout)
    assert list(data)[:5] == ["scene", "kind", "members", "ratios", "dof"]
    assert data["kind"] == "gears" and data["dof"] == 1
    assert data["members"]["3"]["omega"] == 0.0
    assert data["ratios"]["4-3"] == "inf"
    out = run("solve", "zbirka-6.5", "--json")
    ring = -8.0 * 0.05 / 0.45  # pinion 2 inside ring 3
    k = 0.356 / 0.182  # Willis: (ω₇ − ω₆)/(ω₄ − ω₆) = −R₄/R₇
    assert json.loads(out.stdout)["members"]["6"]["omega"] == pytest.approx((12.0 + k * ring) / (1 + k))


def test_plan_json_gives_images_and_components_that_close():
    out = run("plan", "analitika-2.1", "--json")
    assert out.returncode == 0, out.stderr
    data = json.loads(out.stdout)
    solved = json.loads(run("solve", "analitika-2.1", "--json").stdout)
    for name, p in solved["points"].items():
        assert data["points"][name]["velocity_image"] == pytest.approx([p["vx"], p["vy"]], abs=1e-12)
        assert data["points"][name]["acceleration_image"] == pytest.approx([p["ax"], p["ay"]], abs=1e-12)
    kinds = {c["kind"] for s in data["acceleration"]["steps"] for c in s["components"]}
    assert {"normal", "tangential", "coriolis", "sliding"} <= kinds
    images = {k.lower(): v["acceleration_image"] for k, v in data["points"].items()}
    images |= data["acceleration"]["construction_points"] | {"p": [0.0, 0.0], "e5": None}
    for step in data["acceleration"]["steps"]:
        for c in step["components"]:
            if images.get(c["from"]) and images.get(c["to"]):
                assert [images[c["to"]][0] - images[c["from"]][0],
                        images[c["to"]][1] - images[c["from"]][1]] == pytest.approx([c["x"], c["y"]], abs=1e-9)


def test_plan_of_a_gear_train_is_refused_with_exit_2():
    out = run("plan", "zbirka-6.1")
    assert out.returncode == 2 and "not a linkage" in out.stderr and "Traceback" not in out.stderr


def test_link_prints_a_parameter_that_solve_plan_structure_and_forces_accept():
    out = run("link", "zbirka-2.1")
    assert out.returncode == 0, out.stderr
    value = out.stdout.strip()
    assert value.startswith("s=1") and len(value) < 2000
    for command in ("solve", "plan", "structure", "forces"):
        by_link = run(command, "--link", f"http://localhost:8501/velocity_plans?lang=sr&{value}", "--json")
        by_name = run(command, "zbirka-2.1", "--json")
        assert by_link.returncode == 0, by_link.stderr
        assert json.loads(by_link.stdout) == json.loads(by_name.stdout), command


def test_a_damaged_link_on_the_command_line_is_a_clear_error():
    out = run("solve", "--link", "s=1notascene")
    assert out.returncode == 2 and "link: the parameter is damaged" in out.stderr
    both = run("solve", "zbirka-2.1", "--link", "s=1abc")
    assert both.returncode == 2 and "not both" in both.stderr


def test_a_gear_trains_stages_come_with_stages_json():
    data = json.loads(run("solve", "zbirka-6.1", "--stages", "--json").stdout)
    carriers = [s["carrier"] for s in data["stages"]]
    assert carriers == [2, None, 13]
    stage = data["stages"][0]
    assert stage["ends"] == [4, 5] and stage["ratio"] == pytest.approx(-0.28125)
    assert stage["relative"]["4"] == pytest.approx(-data["members"]["2"]["omega"])  # ring 4 is fixed
    assert "stages" not in json.loads(run("solve", "zbirka-6.1", "--json").stdout)
    text = run("solve", "zbirka-6.1", "--stages").stdout
    assert "stage, carrier 13" in text and "i10,12 = -0.28 from the radii" in text
    order = data["order"]  # every member once, in the book's order, with the system's speeds
    assert [s["member"] for s in order][:4] == [2, 4, 6, 7]
    assert {str(s["member"]): pytest.approx(s["omega"]) for s in order} == \
        {m: w["omega"] for m, w in data["members"].items()}
    assert f"ω12 = {data['members']['12']['omega']:.6g}  (stage, carrier 13)" in text


def test_a_locked_differential_prints_its_stage_without_a_ratio_of_speeds():
    text = run("solve", "zbirka-6.10", "--stages").stdout
    assert "i9,11 = -1 from the radii, 0/0 from the speeds" in text


@pytest.mark.parametrize("args", [("solve", "zbirka-3.1", "--at", "1,5"),
                                  ("variants", "zbirka-3.1", "--count", "1.5"),
                                  ("practice", "zbirka-3.1", "--method", "bogus"),
                                  ("synthesize", "task.toml", "--budget", "abc"), ("bogus",)])
def test_the_command_lines_own_refusals_are_one_line_and_exit_2(args):
    out = run(*args)
    assert out.returncode == 2 and out.stdout == ""
    assert len(out.stderr.strip().splitlines()) == 1 and out.stderr.startswith("error: ")
    assert "--help" in out.stderr and "usage:" not in out.stderr


EDGES = {  # (arguments, what the one line must say); {d}: a folder, {big}/{binary}: files
    "a folder for the sheets": (("variants", "zbirka-3.1", "--sheets", "{d}"), "is a folder"),
    "a folder for Moodle": (("variants", "zbirka-3.1", "--moodle", "{d}"), "is a folder"),
    "a key in a missing folder": (("variants", "zbirka-3.1", "--key", "{d}/missing/k.csv"),
                                  "does not exist"),
    "negative steps": (("bench", "zbirka-3.1", "--steps", "-5"), "'-5' is less than 1"),
    "no steps": (("bench", "zbirka-3.1", "--steps", "0"), "'0' is less than 1"),
    "a negative repeat": (("bench", "zbirka-3.1", "--repeat", "-1"), "'-1' is less than 1"),
    **{f"solve at {v}": (("solve", "zbirka-3.1", "--at", v), "not one number")
       for v in ("nan", "inf", "1e999")},
    **{f"{c} at nan": ((c, "zbirka-3.1", *m, "--at", "nan"), "not one number")
       for c, m in (("plan", ()), ("forces", ()), ("practice", ("--method", "plans")))},
    "solve at -1e308": (("solve", "zbirka-3.1", "--at", "-1e308"), "less than -1000000000"),
    "solve beyond a turn": (("solve", "zbirka-3.1", "--at", "-1000"), "outside this scene's range"),
    "a slider beyond its range": (("solve", "analitika-2.2", "--at", "50"), "outside this scene's range"),
    "a class at nan": (("class", "create", "zbirka-3.1", "--method", "plans", "--at", "nan"),
                       "not one number"),
    "a class beyond a turn": (("class", "create", "zbirka-3.1", "--method", "plans", "--at", "720"),
                              "outside this scene's range"),
    "a binary answers file": (("practice", "zbirka-3.1", "--method", "plans", "--answers", "{binary}"),
                              "is not text in UTF-8"),
    "a huge answers file": (("practice", "zbirka-3.1", "--method", "plans", "--answers", "{big}"),
                            "at most 1000 kB"),
    "an answers folder": (("practice", "zbirka-3.1", "--method", "plans", "--answers", "{d}"),
                          "is a folder"),
}


@pytest.mark.parametrize("name", list(EDGES))
def test_every_command_at_its_edges_says_one_line_and_exits_2(name, tmp_path):
    """Issue 85's table: a wrong file or number is the user's to fix (exit 2, one line that
    names what was given), never a traceback, never a run at a position nobody meant."""
    args, said = EDGES[name]
    (tmp_path / "binary.json").write_bytes(b"\x80\x81{}")
    (tmp_path / "big.json").write_text('{"answers": {}, "pad": "' + "x" * 1_100_000 + '"}')
    where = {"d": str(tmp_path), "big": str(tmp_path / "big.json"),
             "binary": str(tmp_path / "binary.json")}
    out = run(*(a.format(**where) for a in args))
    assert out.returncode == 2 and out.stdout == "", (out.returncode, out.stdout[:200])
    assert len(out.stderr.strip().splitlines()) == 1 and out.stderr.startswith("error: "), out.stderr
    assert said in out.stderr and "Traceback" not in out.stderr
    assert not list(tmp_path.glob("*.html")) and not list(tmp_path.glob("*.xml"))
