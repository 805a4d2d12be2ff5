"""Hostile scene files: whatever a file holds, loading and solving it ends in a result or in
a SceneError / StructureError / Unsolvable whose message names the problem — never another
exception, never code run from the file (fuzzed with hypothesis)."""

from __future__ import annotations

import copy
import dataclasses
import json
import math
import tomllib

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from cli import main
from mechanisms import SceneError, parse_document, preset_ids
from mechanisms.gears import GearTrain
from mechanisms.loader import PRESETS as PRESET_DIR
from mechanisms.rotor import Rotor
from solvers.balancing import BalanceError, balance
from solvers.diagnostics import Unsolvable, solve_instant
from solvers.gears import TrainError, solve_train
from solvers.kinetostatics import SINGULAR, analyse
from solvers.structure import StructureError

from .scenes import chain, dyads, largest_allowed, rotor, train

PRESETS = {pid: (PRESET_DIR / f"{pid}.toml").read_text() for pid in preset_ids()}
EXPECTED = (SceneError, StructureError, Unsolvable, TrainError, BalanceError)
FUZZ = settings(max_examples=150, deadline=None, suppress_health_check=list(HealthCheck))

hostile_values = st.one_of(
    st.booleans(),  # TOML has no null st.integers(-10**30, 10**30), st.text(max_size=20),
    st.sampled_from([math.nan, math.inf, -math.inf, 0.0, -1.0, 1e308, 1e-308, 1e6]),
    st.lists(st.floats(allow_nan=True), max_size=4), st.dictionaries(st.text(max_size=5),
                                                                     st.integers(), max_size=3))


def paths(table, prefix=()):
    """Every (path, value) inside a parsed TOML table, lists included."""
    items = table.items() if isinstance(table, dict) else enumerate(table)
    for key, value in items:
        yield prefix + (key,), value
        if isinstance(value, (dict, list)):
            yield from paths(value, prefix + (key,))


def replaced(raw: dict, path: tuple, value) -> dict:
    out = copy.deepcopy(raw)
    target = out
    for key in path[:-1]:
        target = target[key]
    target[path[-1]] = value
    return out


def use(scene) -> None:
    """What a page does with a loaded scene: solve it (and its loads)."""
    if isinstance(scene, Rotor):
        balance(scene)
    elif isinstance(scene, GearTrain):
        solve_train(scene)
    else:
        motion = solve_instant(scene, None)  # raises Unsolvable where it cannot be
        assert all(np.isfinite(p.z[0]) for p in motion.points.values())
        k = analyse(scene, motion=motion)
        singular = (not np.isfinite(motion.condition[0])
                    or any(not c[0] <= SINGULAR for c in k.condition.values()))
        assert np.isfinite(k.driving[0]) or singular  # NaN only where it says why


def from_raw(raw: dict):
    """Load a scene from an already parsed table, through the same entry as a file."""
    from mechanisms.gears import parse_gears
    from mechanisms.loader import _build
    from mechanisms.reader import Reader
    from mechanisms.rotor import parse_rotor

    kind = raw.get("kind", "linkage")
    if kind == "rotor":
        return parse_rotor(raw, "<fuzz>", "fuzz")
    if kind == "gears":
        return parse_gears(raw, "<fuzz>", "fuzz")
    return _build(raw, Reader("<fuzz>"), "fuzz")


@FUZZ
@given(st.sampled_from(sorted(PRESETS)), st.data(), hostile_values)
def test_any_value_anywhere_is_a_clear_error_or_a_result(pid, data, value):
    raw = tomllib.loads(PRESETS[pid])
    path, _ = data.draw(st.sampled_from(list(paths(raw))))
    try:
        use(from_raw(replaced(raw, path, value)))
    except EXPECTED as exc:
        assert str(exc).strip()


@FUZZ
@given(st.sampled_from(sorted(PRESETS)), st.integers(0, 10**6), st.binary(max_size=8),
       st.integers(0, 40))
def test_damaged_bytes_are_a_clear_error_or_a_result(pid, at, junk, cut):
    """A file cut short, with bytes inserted (not UTF-8, a stray quote, a NUL)."""
    data = PRESETS[pid].encode()
    i = at % (len(data) + 1)
    damaged = data[:i] + junk + data[i + cut:]
    try:
        use(parse_document(damaged, source="upload.toml"))
    except EXPECTED as exc:
        assert str(exc).strip()


@pytest.mark.parametrize("text, words", [
    ("x = " + "[" * 5000 + "]" * 5000, "nested too deeply"),
    ("[" + ".".join(["a"] * 3000) + "]\nb = 1", "not a known key"),
    ('kind = ["rotor"]', "kind must be a string"),
    ("id = 'x'\n" + "note = '" + "a" * 2_000_000 + "'", "bytes"),
])
def test_absurd_files_are_refused_with_the_reason(text, words):
    with pytest.raises(SceneError, match=words):
        parse_document(text)


def test_nan_and_inf_lengths_name_their_key():
    text = PRESETS["zbirka-2.1"].replace("length = 0.41", "length = nan", 1)
    with pytest.raises(SceneError, match=r"members\.3\.length"):
        parse_document(text)
    text = PRESETS["zbirka-2.1"].replace("omega = 15.0", "omega = inf", 1)
    with pytest.raises(SceneError, match="omega"):
        parse_document(text)


def test_a_structure_that_cannot_move_or_moves_too_freely_is_explained():
    """A member joined back to the frame twice (a locked cycle), or left with two degrees
    of freedom: the structure says W and why it cannot decompose."""
    text = PRESETS["four-bar-crank-rocker"]
    locked = text.replace('pairs = [', 'pairs = [\n  { type = "revolute", members = [3, 1], point = "B" },', 1)
    for broken in (locked,):
        try:
            scene = parse_document(broken)
        except SceneError as exc:
            assert str(exc).strip()
            continue
        with pytest.raises((StructureError, Unsolvable), match=r"\S"):
            solve_instant(scene, None)


@pytest.mark.parametrize("command", ["solve", "forces", "plan", "structure"])
def test_the_cli_answers_a_broken_file_with_a_message_not_a_traceback(tmp_path, capsys, command):
    bad = tmp_path / "bad.toml"
    bad.write_bytes(b"\xff\xfe[members.2]\nlength = 'long'")
    assert main([command, str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.startswith("error:") and "Traceback" not in err


@pytest.mark.parametrize("pid", ["zbirka-2.5", "triad-full-turn", "zbirka-5.3", "zbirka-6.8",
                                 "zbirka-7.2"])
def test_every_number_set_to_an_extreme_is_a_clear_error_or_a_result(pid):
    """Each number of the file, one at a time, as 1e308, −1e308, 1e-300, 0 or −1: a
    result, or an error that names what is wrong (no overflow, no traceback)."""
    raw = tomllib.loads(PRESETS[pid])
    numeric = [path for path, value in paths(raw)
               if isinstance(value, (int, float)) and not isinstance(value, bool)]
    assert numeric
    for path in numeric:
        for value in (1e308, -1e308, 1e-300, 0.0, -1.0):
            try:
                use(from_raw(replaced(raw, path, value)))
            except EXPECTED as exc:
                assert str(exc).strip(), (path, value)


# --- bounded work per scene (issue: oversized scenes) ----------------------------------------

@pytest.mark.parametrize("text, limit", [
    (train(10_000), "file is 8[0-9,]+ bytes; a scene must be under 100,000 bytes"),
    (chain(6_000, pinned=True), "a scene must be under 100,000 bytes"),
    (chain(3_000), "a scene must be under 100,000 bytes"),
    (rotor(5_000), "a scene must be under 100,000 bytes"),
    (train(41), "members lists 41 members; a scene may have at most 40"),
    (train(300), "members lists 300 members"),
    (chain(21), "members lists 21 moving members; a scene may have at most 20"),
    (chain(400, pinned=True), "members lists 400 moving members"),
    (dyads(21), "members lists 43 moving members"),
    (rotor(101), "masses lists 101 unbalanced masses; a scene may have at most 100"),
])
def test_a_scene_past_a_limit_is_refused_by_naming_the_limit(text, limit):
    """Refused before anything is validated or solved (bench/hostile.py times it: ms): the
    big files by their size before parsing, the others by their counts after it."""
    with pytest.raises(SceneError, match=limit):
        parse_document(text)


def test_too_many_points_forces_or_printed_values_are_refused():
    raw = tomllib.loads(PRESETS["zbirka-2.1"])
    many = copy.deepcopy(raw)
    many["members"]["3"]["extra"] = {f"X{i}": [0.01 * i, 0.0] for i in range(300)}
    with pytest.raises(SceneError, match="hold 311 points; a scene may have at most 200"):
        from_raw(many)
    many = copy.deepcopy(raw)
    many["forces"] = [{"member": 3, "point": "B", "magnitude": 1.0}] * 41
    with pytest.raises(SceneError, match="forces lists 41 forces"):
        from_raw(many)
    many = copy.deepcopy(raw)
    many["book"] = {f"points.C.v{i}": 1.0 for i in range(301)}
    with pytest.raises(SceneError, match="book lists 301 printed values"):
        from_raw(many)


def test_the_largest_allowed_linkage_still_solves_and_its_page_shows_it():
    from streamlit.testing.v1 import AppTest

    from mechanisms.link import encode

    from .test_pages import ROOT

    scene = parse_document(largest_allowed())
    assert len(scene.members) == 19 and len(scene.pairs) == 28
    motion = solve_instant(scene, None)  # within the budget, or OverBudget would be raised
    for d in range(1, 10):
        assert abs(motion.points[f"C{d}"].z[0] - scene.guess[f"C{d}"]) < 1e-9
    at = AppTest.from_file(str(ROOT / "app.py"), default_timeout=60)
    at.session_state["lang"] = "en"
    at.query_params["s"] = encode(scene)
    at.run()
    at.switch_page("pages/velocity_plans.py").run()
    assert not at.exception and not at.error, [e.value for e in at.error]


def test_a_page_given_an_oversized_scene_in_a_link_says_the_limit_and_no_exception():
    import base64
    import zlib

    from streamlit.testing.v1 import AppTest

    from mechanisms.link import _DICTIONARY  # build the link by hand: encode needs a Scene

    from .test_pages import ROOT

    c = zlib.compressobj(9, zlib.DEFLATED, -15, zdict=_DICTIONARY)
    value = "1" + base64.urlsafe_b64encode(c.compress(chain(60).encode()) + c.flush()).decode()
    at = AppTest.from_file(str(ROOT / "app.py"), default_timeout=60)
    at.session_state["lang"] = "en"
    at.query_params["s"] = value.rstrip("=")
    at.run()
    at.switch_page("pages/trajectories.py").run()
    assert not at.exception
    assert "members lists 60 moving members; a scene may have at most 20" in at.error[0].value


def test_a_solve_past_its_time_budget_stops_with_a_reason(monkeypatch):
    from solvers import budget, decompose, solve
    from solvers.budget import OverBudget

    scene = parse_document(PRESETS["triad-full-turn"])
    monkeypatch.setattr(budget, "SECONDS", -1.0)  # every budget already spent
    for run in (lambda: solve(scene, np.linspace(0, 6, 36)), lambda: decompose(scene)):
        with pytest.raises(OverBudget, match="takes longer than -1 s"):
            run()
    assert issubclass(OverBudget, Unsolvable)  # pages and the CLI already say it in words


# --- gear trains that cannot exist; files from Windows ---------------------------------------

def test_a_cycle_of_carriers_is_refused():
    text = PRESETS["zbirka-6.8"].replace("[members.5]", "[members.5]\ncarrier = 4\naxis = 0.04", 1)
    with pytest.raises(SceneError, match=r"cycle of carriers \((4 → 5 → 4|5 → 4 → 5)\)"):
        parse_document(text)


def test_a_gear_member_numbered_0_is_refused():
    text = PRESETS["zbirka-6.8"].replace("[members.4]", "[members.0]", 1)
    with pytest.raises(SceneError, match=r"members\.0 must be numbered like the book's members"):
        parse_document(text)


def test_a_train_whose_input_is_at_rest_keeps_its_ratios_and_says_everything_is_at_rest():
    moving = parse_document(PRESETS["zbirka-6.8"])
    still = moving.with_(inputs=tuple(dataclasses.replace(i, omega=0.0) for i in moving.inputs))
    go, rest = solve_train(moving), solve_train(still)
    assert not any(rest.omega.values()) and "at rest" in str(rest.message)
    for a in moving.members:
        for b in moving.members:
            if a != b:
                assert rest.ratio(a, b) == pytest.approx(go.ratio(a, b), rel=1e-12)


def test_a_file_saved_with_a_byte_order_mark_loads():
    text = PRESETS["zbirka-2.1"]
    assert parse_document(("\ufeff" + text).encode("utf-8")) == parse_document(text)
    with pytest.raises(SceneError, match="not UTF-8"):
        parse_document(text.encode("utf-16"))


def test_the_cli_solves_a_train_at_rest_and_notes_why_everything_is_still(tmp_path, capsys):
    still = tmp_path / "still.toml"
    still.write_text(PRESETS["zbirka-6.8"].replace("omega = 100.0", "omega = 0.0", 1))
    assert parse_document(still.read_text()).inputs[0].omega == 0.0
    assert main(["solve", str(still), "--json"]) == 0
    out = capsys.readouterr()
    assert "note: the input is at rest" in out.err
    assert main(["solve", "zbirka-6.8", "--json"]) == 0
    moving = json.loads(capsys.readouterr().out)["ratios"]
    at_rest = json.loads(out.out)["ratios"]
    assert at_rest.keys() == moving.keys()
    for key, ratio in moving.items():  # ∞ only where a member is fixed, as when it moves
        assert at_rest[key] == ratio if ratio == "inf" else at_rest[key] == pytest.approx(ratio)
