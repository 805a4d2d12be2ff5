"""Hostile scene files: whatever a file holds, loading and solving it ends in a result or in
a SceneError / StructureError / Unsolvable whose message names the problem — never another
exception, never code run from the file (fuzzed with hypothesis)."""

from __future__ import annotations

import copy
import math
import tomllib

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from mechanisms import SceneError, parse_document, preset_ids
from mechanisms.gears import GearTrain
from mechanisms.loader import PRESETS as PRESET_DIR
from mechanisms.rotor import Rotor
from solvers.balancing import BalanceError, balance
from solvers.cli import main
from solvers.diagnostics import Unsolvable, solve_instant
from solvers.gears import TrainError, solve_train
from solvers.kinetostatics import SINGULAR, analyse
from solvers.structure import StructureError

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
    from mechanisms.loader import _build, _Reader
    from mechanisms.gears import parse_gears
    from mechanisms.rotor import parse_rotor

    kind = raw.get("kind", "linkage")
    if kind == "rotor":
        return parse_rotor(raw, "<fuzz>", "fuzz")
    if kind == "gears":
        return parse_gears(raw, "<fuzz>", "fuzz")
    return _build(raw, _Reader("<fuzz>"), "fuzz")


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
