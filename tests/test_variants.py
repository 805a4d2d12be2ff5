"""Exam variants: deterministic, every one a good exercise, keys equal to independent
computations, codes that round-trip and refuse damage, bad input refused with a reason."""

import cmath
import json
import math
import re

import numpy as np
import pytest

from exams.codes import CHECK_LETTERS, Settings, code, parse
from exams.variants import MAX_COUNT, VariantError, as_json, from_code, generate, task
from exams.variation import givens
from mechanisms import SceneError, load_preset
from reports.values import exact_values
from exams import variants
from solvers.balancing import balance
from solvers.diagnostics import solve_instant
from solvers.kinematics import solve
from solvers.structure import decompose

from .test_cli import run


@pytest.fixture(scope="module")
def set_3_1():
    return generate(Settings("zbirka-3.1", 42), 12)


def test_the_same_settings_give_the_same_variants_and_another_seed_others(set_3_1):
    again = generate(Settings("zbirka-3.1", 42), 12)
    assert json.dumps(as_json(again)) == json.dumps(as_json(set_3_1))
    other = generate(Settings("zbirka-3.1", 43), 12)
    assert [v.given for v in other.variants] != [v.given for v in set_3_1.variants]
    assert len({tuple(x for _, x in v.given) for v in set_3_1.variants}) == 12  # all differ


def test_the_json_of_the_command_line_is_the_same_bytes_twice():
    first = run("variants", "zbirka-3.1", "--count", "3", "--seed", "7", "--json")
    second = run("variants", "zbirka-3.1", "--count", "3", "--seed", "7", "--json")
    assert first.returncode == 0, first.stderr
    assert first.stdout == second.stdout
    data = json.loads(first.stdout)
    assert [v["code"] for v in data["variants"]] == [code(Settings("zbirka-3.1", 7), i) for i in (1, 2, 3)]
    assert data["variants"][0]["asked"] == list(load_preset("zbirka-3.1").book)
    assert set(data["variants"][0]["key"]) > set(load_preset("zbirka-3.1").book)  # + self-check


def test_given_values_are_rounded_as_printed_and_within_the_spread(set_3_1):
    for v in set_3_1.variants:
        for g, value in v.given:
            lo, hi = g.bounds(20)
            assert lo - g.step / 2 <= value <= hi + g.step / 2, (g.label, value)
            assert abs(value / g.step - round(value / g.step)) < 1e-6, (g.label, value, g.step)
    angles = [value for v in set_3_1.variants for g, value in v.given if g.label == "φ₂"]
    assert all(float(a).is_integer() for a in angles)


def _rrr_orientation(scene, motion) -> dict[str, float]:
    """Sign of the triangle outer–inner–outer of every RRR dyad: the dyad's branch."""
    out = {}
    for group in decompose(scene).groups:
        if group.kind == "RRR":
            a, b, c = (motion.points[p.point].z[0] for p in group.pairs)
            out[group.name] = np.sign(((b - a).conjugate() * (c - b)).imag)
    return out


@pytest.mark.parametrize("pid", ["zbirka-2.1", "zbirka-3.1", "zbirka-5.1"])
def test_every_variant_is_a_good_exercise(pid):
    original = load_preset(pid)
    found = generate(Settings(pid, 5), 8)
    before = _rrr_orientation(original, solve_instant(original, None))
    structure = [(g.kind, g.members) for g in decompose(original).groups]
    turns = solve(original, np.linspace(0, 2 * math.pi, 360, endpoint=False), order=0).feasible.all()
    for v in found.variants:
        motion = solve_instant(v.scene, None)  # assembles (raises otherwise)
        assert motion.condition[0] <= max(variants.CONDITION, variants.OWN * task(pid).condition)
        assert [(g.kind, g.members) for g in decompose(v.scene).groups] == structure
        assert _rrr_orientation(v.scene, motion) == before, v.code
        if turns:
            cycle = solve(v.scene, np.linspace(0, 2 * math.pi, 720, endpoint=False), order=0)
            assert cycle.feasible.all(), v.code


def test_keys_are_the_solvers_values_for_every_asked_quantity(set_3_1):
    for v in set_3_1.variants:
        exact = exact_values(v.scene)
        assert [a.key for a in v.key if a.asked] == list(load_preset("zbirka-3.1").book)
        assert all(a.value == exact[a.key] for a in v.key)
        extra = {a.key for a in v.key if not a.asked}  # what the plans page's self-check grades
        assert {"points.B.v", "points.B.a", "points.C.a"} <= extra | set(load_preset("zbirka-3.1").book)
        assert not any(k.startswith(("points.A.", "points.D.", "members.2.")) for k in extra)
        assert {a.unit for a in v.key} <= {"m/s", "m/s²", "s⁻¹", "s⁻²"}


def test_keys_equal_an_independent_computation_by_finite_differences(set_3_1):
    """v_E and ω₃ of each variant from positions at φ₂ ± h, never from the velocity solver."""
    for v in set_3_1.variants[:4]:
        scene = v.scene
        h = 1e-6
        at = scene.driver.at + np.array([-h, h])
        motion = solve(scene, at, order=0)
        dt = 2 * h / abs(scene.driver.speed)
        key = {a.key: a.value for a in v.key}
        e = motion.points["E"].z
        assert key["points.E.v"] == pytest.approx(abs(e[1] - e[0]) / dt, rel=1e-6)
        angle = motion.members[3].angle
        assert key["members.3.omega"] == pytest.approx(
            math.copysign(1, scene.driver.speed) * (angle[1] - angle[0]) / (2 * h) * abs(scene.driver.speed),
            rel=1e-6)


def test_a_variant_of_a_fitted_task_travels_as_a_link():
    from mechanisms.link import decode, encode

    v = generate(Settings("zbirka-2.4", 2), 2).variants[1]
    assert v.scene.fit is None and not v.scene.book
    assert decode(encode(v.scene)).frame == v.scene.frame


def test_gear_variants_mesh_with_whole_teeth():
    for pid in ("zbirka-6.1", "zbirka-6.10"):
        found = generate(Settings(pid, 3), 6)
        for v in found.variants:
            train = v.scene
            for mesh in train.meshes:
                a, b = (train.members[m] for m in mesh.members)
                ra, rb = mesh.radii
                if not mesh.bevel:
                    distance = abs(ra - rb) if mesh.internal is not None else ra + rb
                    assert abs(a.axis - b.axis) == pytest.approx(distance, abs=1e-12), (v.code, mesh)
            assert {a.key for a in v.key if a.asked} == set(load_preset(pid).book)  # ratios too
            if pid == "zbirka-6.10":  # given by teeth: every radius a whole number of teeth
                for mesh in train.meshes:
                    assert all(abs(r / 0.002 - round(r / 0.002)) < 1e-9 for r in mesh.radii)
                    assert all(round(r / 0.002) >= 10 for r in mesh.radii)


def test_rotor_variants_balance_with_corrections_that_matter():
    for v in generate(Settings("zbirka-7.1", 11), 8).variants:
        rotor = v.scene
        found = balance(rotor)
        assert all(f.mass > 0 for f in found.corrections.values())
        force = sum(m.mass * m.radius * cmath.exp(1j * m.angle) for m in rotor.masses)
        force += sum(f.mass * f.radius * cmath.exp(1j * f.angle) for f in found.corrections.values())
        assert abs(force) < 1e-9
        key = {a.key: a.value for a in v.key}
        assert key["corrections.I.mass"] == pytest.approx(found.corrections["I"].mass)


def test_the_code_round_trips_and_opens_the_same_variant(set_3_1):
    v = set_3_1.variants[6]
    assert re.fullmatch(r"3\.1-S42-07[A-Z]", v.code)
    assert parse(v.code) == (Settings("zbirka-3.1", 42), 7)
    assert parse(v.code.lower()) == (Settings("zbirka-3.1", 42), 7)
    opened = from_code(v.code)
    assert opened.scene == v.scene and opened.key == v.key
    held = Settings("analitika-2.1", 9, 15, frozenset({0, 5}))
    assert parse(code(held, 3)) == (held, 3)


def test_damaged_and_unknown_codes_say_so(set_3_1):
    good = set_3_1.variants[0].code
    damaged = good.replace("S42", "S43")
    with pytest.raises(SceneError, match="damaged"):
        parse(damaged)
    for text in ("", "hello", "3.1-42-07", "3.1-S42-7"):
        with pytest.raises(SceneError, match="expected something like"):
            parse(text)
    wrong_letter = good[:-1] + next(c for c in CHECK_LETTERS if c != good[-1])
    with pytest.raises(SceneError, match="damaged"):
        parse(wrong_letter)
    unknown = code(Settings("zbirka-9.9", 1), 1)
    with pytest.raises(SceneError, match="no preset named"):
        from_code(unknown)
    too_far = code(Settings("zbirka-3.1", 42), 250)
    with pytest.raises(VariantError, match="count must be"):
        from_code(too_far)


def test_bad_requests_are_refused_with_the_reason(monkeypatch):
    with pytest.raises(VariantError, match="count must be 1"):
        generate(Settings("zbirka-3.1", 1), 201)
    with pytest.raises(VariantError, match="prints no answers"):
        generate(Settings("zbirka-1.1", 1), 3)
    everything = frozenset(range(len(task("zbirka-3.1").givens)))
    held = generate(Settings("zbirka-3.1", 1, held=everything), 3)
    assert len(held.variants) == 1 and "same numbers" in str(held.shortfall)
    monkeypatch.setattr(variants, "CONDITION", 0.0)
    monkeypatch.setattr(variants, "OWN", 0.5)
    monkeypatch.setattr(variants, "TRIES", 3)
    with pytest.raises(VariantError, match="near a dead centre"):
        generate(Settings("zbirka-2.2", 1), 2)


def test_givens_leave_structure_and_zeros_alone():
    import tomllib

    from mechanisms.loader import PRESETS

    doc = tomllib.loads((PRESETS / "zbirka-3.1.toml").read_text(encoding="utf-8"))
    labels = [g.label for g in givens(doc)]
    assert labels == ["x_A", "y_A", "AB", "BE", "DC", "φ₂", "ω₂"]  # D = (0, 0), ε₂ = 0 stay


def test_the_command_line_writes_sheets_and_key_and_refuses_bad_counts(tmp_path):
    sheets, key = tmp_path / "s.html", tmp_path / "k.csv"
    out = run("variants", "zbirka-7.1", "--count", "2", "--sheets", str(sheets), "--key", str(key),
              "--language", "en")
    assert out.returncode == 0, out.stderr
    assert sheets.read_text().count('class="sheet"') == 2
    assert key.read_text().splitlines()[0] == "code,quantity,value,unit,tolerance,asked"
    assert len(key.read_text().splitlines()) == 1 + 2 * 4
    bad = run("variants", "zbirka-3.1", "--count", "500")
    assert bad.returncode == 2 and f"'500' is more than {MAX_COUNT}" in bad.stderr
    hold = run("variants", "zbirka-3.1", "--hold", "XY")
    assert hold.returncode == 2 and "x_A" in hold.stderr
