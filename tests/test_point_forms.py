"""A member's extra point by two distances and a side, or by a length and an angle
(mechanisms.point_forms): the same mechanism as [along, left] through a file and a link, the
author's form kept, and triangles that cannot close refused with the member and the point."""

from __future__ import annotations

import copy
import math

import numpy as np
import pytest

from mechanisms import SceneError, parse_scene, preset_ids
from mechanisms.link import decode, encode
from mechanisms.loader import build_document, build_scene, load_scene, preset_document
from mechanisms.point_forms import every_form, from_distances, written
from mechanisms.sketch import document, drag, driver_values, tables, template, template_ids
from mechanisms.writer import to_text
from solvers.diagnostics import sweep_values
from solvers.kinematics import solve


def _with_extras(doc: dict) -> bool:
    return any(spec.get("extra") for spec in doc.get("members", {}).values())


LINKAGE_DOCS = [(f"preset:{p}", preset_document(p)) for p in preset_ids("linkage")]
LINKAGE_DOCS += [(f"template:{n}", template(n)) for n in template_ids()]
TERNARY = [(name, doc) for name, doc in LINKAGE_DOCS if _with_extras(doc)]


def _offsets(doc: dict) -> dict:
    """The document with every extra point as [along, left] (a template may give a form)."""
    scene = build_document(doc)
    out = copy.deepcopy(doc)
    for number, spec in out.get("members", {}).items():
        for name in spec.get("extra", {}):
            z = scene.members[int(number)].points[name]
            spec["extra"][name] = [z.real, z.imag]
    return out


def _rewritten(doc: dict, form: str) -> dict:
    """Every extra point in ``form`` (distances only where the member has two points), with
    the numbers a sheet would print: computed from the offsets, to 12 digits."""
    out = _offsets(doc)
    for spec in out.get("members", {}).values():
        length = spec.get("length") if len(spec.get("points", [])) == 2 else None
        for name, (along, left) in spec.get("extra", {}).items():
            spec["extra"][name] = written(form, complex(along, left), length)
    return out


def _same_motion(a, b) -> float:
    """The largest difference of any point's position, velocity or acceleration over a cycle,
    relative to the mechanism's size and rates."""
    at = sweep_values(a, 72)
    ma, mb = solve(a, at), solve(b, at)
    worst = 0.0
    for name, p in ma.points.items():
        q = mb.points[name]
        for x, y in ((p.z, q.z), (p.v, q.v), (p.a, q.a)):
            x, y = np.broadcast_to(x, at.shape), np.broadcast_to(y, at.shape)
            both = np.isfinite(x) & np.isfinite(y)
            assert np.array_equal(np.isfinite(x), np.isfinite(y)), name
            scale = max(1.0, float(np.nanmax(np.abs(x))))
            worst = max(worst, float(np.max(np.abs(x[both] - y[both]), initial=0.0)) / scale)
    return worst


def test_the_rewritten_scenes_are_the_linkages_with_ternary_members():
    names = {n for n, _ in TERNARY}
    assert {"template:watt-six-bar", "template:stephenson-six-bar", "template:class-iii"} <= names
    assert sum(n.startswith("preset:") for n in names) >= 5


@pytest.mark.parametrize("form", ["distances", "polar"])
@pytest.mark.parametrize("name, doc", TERNARY, ids=[n for n, _ in TERNARY])
def test_a_point_by_distances_or_polar_solves_to_the_same_motion_through_a_file_and_a_link(
        name, doc, form, tmp_path):
    original = build_document(_offsets(doc), source=name)
    rewritten = build_document(_rewritten(doc, form), source=name)
    forms = {f for m in rewritten.members.values() for f in m.forms.values()}
    assert form in forms  # the rewrite took
    path = tmp_path / "scene.toml"
    path.write_text(to_text(rewritten))
    from_file, from_link = load_scene(path), decode(encode(rewritten))
    for scene in (from_file, from_link):
        assert {f for m in scene.members.values() for f in m.forms.values()} == forms
        assert _same_motion(original, scene) < 1e-9


def test_the_writer_keeps_the_authors_form_and_numbers():
    doc = template("watt-six-bar")
    text = to_text(build_scene(doc))
    assert 'E = { distances = [0.16, 0.12], side = "right" }' in text
    doc["members"]["4"]["extra"]["E"] = {"polar": [0.15, -30.0]}
    text = to_text(build_scene(doc))
    assert "E = { polar = [0.15, -30.0] }" in text
    assert parse_scene(text).members[4].points == build_scene(doc).members[4].points


def test_the_law_of_cosines_and_the_side():
    left = from_distances(0.12, 0.2, "left", 0.22)  # DC, DB with DB's member 0.22 long
    assert abs(abs(left) - 0.12) < 1e-15 and abs(abs(left - 0.22) - 0.2) < 1e-15
    assert left.imag > 0 and from_distances(0.12, 0.2, "right", 0.22) == left.conjugate()
    flat = from_distances(0.1, 0.2, "left", 0.3)  # 0.1 + 0.2 is not 0.3 in floats: flat all the same
    assert flat.imag == 0 and flat.real == pytest.approx(0.1, abs=1e-16)
    point = every_form(complex(0.1, 0.1), 0.2)
    assert point["d1"] == pytest.approx(math.hypot(0.1, 0.1)) and point["side"] == "left"
    assert point["r"] == pytest.approx(math.hypot(0.1, 0.1)) and point["theta"] == pytest.approx(45)


BAD = [
    ({"distances": [0.05, 0.1], "side": "left"}, "cannot close a triangle"),  # d1 + d2 < 0.25
    ({"distances": [0.5, 0.1], "side": "left"}, "cannot close a triangle"),  # 0.5 > 0.1 + 0.25
    ({"distances": [0.0, 0.3], "side": "left"}, "must both be > 0"),
    ({"distances": [-0.2, 0.1], "side": "left"}, "must both be > 0"),
    ({"distances": [0.2, 0.1], "side": "above"}, "side must be \"left\" or \"right\""),
    ({"distances": [0.2, 0.1]}, "side is missing"),
    ({"polar": [0.0, 30.0]}, "must be > 0"),
    ({"polar": [0.1]}, "must be a pair of numbers"),
    ({"polr": [0.1, 30.0]}, "must be [along, left]"),
]


@pytest.mark.parametrize("value, rule", BAD, ids=[r for _, r in BAD])
def test_a_point_that_cannot_be_placed_is_refused_naming_member_and_point(value, rule):
    doc = template("watt-six-bar")
    doc["members"]["4"]["extra"]["E"] = value
    with pytest.raises(SceneError) as file_error:
        build_scene(doc, source="sheet.toml")
    assert "members.4.extra.E" in str(file_error.value) and rule in str(file_error.value)
    if "cannot close" in rule or "> 0" in rule:
        assert "point E of member 4" in str(file_error.value)
    rows = tables(doc)  # the builder's table: the same message, and the row as typed
    typed = next(r for r in rows["extra"] if r["point"] == "E")
    again = document(rows, driver_values(doc), doc)
    shaped = not rule.startswith("must be")  # a table row holds two numbers, a file anything
    assert again["members"]["4"]["extra"]["E"] == value or not shaped
    with pytest.raises(SceneError) as table_error:
        build_scene(again, source="sheet.toml")
    assert str(table_error.value) == str(file_error.value) or not shaped
    if "distances" in value:
        assert (typed["d1"], typed["d2"]) == tuple(value["distances"])


def test_a_link_with_a_triangle_that_cannot_close_is_refused():
    doc = template("watt-six-bar")
    good = encode(build_scene(doc))
    text = to_text(build_scene(doc)).replace("distances = [0.16, 0.12]", "distances = [0.06, 0.12]")
    from mechanisms.link import _DICTIONARY  # the link's own packing, with a bad triangle
    import base64
    import zlib
    packer = zlib.compressobj(9, zlib.DEFLATED, -15, zdict=_DICTIONARY)
    bad = good[0] + base64.urlsafe_b64encode(
        packer.compress(text.encode()) + packer.flush()).decode().rstrip("=")
    with pytest.raises(SceneError, match=r"point E of member 4.*cannot close a triangle"):
        decode(bad)


def test_the_builder_rows_show_every_form_and_take_the_chosen_one():
    doc = template("watt-six-bar")
    row = next(r for r in tables(doc)["extra"] if r["point"] == "E")
    assert row["form"] == "distances" and (row["d1"], row["d2"], row["side"]) == (0.16, 0.12, "right")
    z = build_scene(doc).members[4].points["E"]
    assert (row["along"], row["left"]) == pytest.approx((z.real, z.imag), abs=1e-12)
    assert row["r"] == pytest.approx(abs(z)) and row["theta"] == pytest.approx(math.degrees(np.angle(z)))
    rows = tables(doc)
    e = next(r for r in rows["extra"] if r["point"] == "E")
    e.update(form="polar")
    again = build_scene(document(rows, driver_values(doc), doc))
    assert again.members[4].forms == {"E": "polar"}
    assert abs(again.members[4].points["E"] - z) < 1e-11


def test_a_drag_keeps_the_form_the_row_uses():
    doc = template("watt-six-bar")
    scene = build_scene(doc)
    motion = solve(scene, np.radians([doc["driver"]["at"]]), order=0)
    positions = {n: complex(p.z[0]) for n, p in motion.points.items()}
    rotations = {m: complex(mm.rot[0]) for m, mm in motion.members.items()}
    moved = drag(doc, positions, rotations, "E", positions["E"] + 0.01)
    value = moved["members"]["4"]["extra"]["E"]
    assert set(value) == {"distances", "side"}
    new = build_scene(moved)
    local = (positions["E"] + 0.01 - positions["D"]) / rotations[4]
    assert abs(new.members[4].points["E"] - local) < 1e-11


def test_a_variant_varies_the_sides_or_the_length_and_angle_the_task_gives():
    from exams.variation import apply, givens
    doc = template("watt-six-bar")
    found = {g.path: g for g in givens(doc)}
    sides = [p for p in found if p[:4] == ("members", "4", "extra", "E")]
    assert sides == [("members", "4", "extra", "E", "distances", 0),
                     ("members", "4", "extra", "E", "distances", 1)]
    assert [found[p].label for p in sides] == ["DE", "BE"]
    new, _ = apply(doc, list(found.values()), [g.value * 1.05 for g in found.values()])
    assert new["members"]["4"]["extra"]["E"] == {"distances": [0.16 * 1.05, 0.12 * 1.05],
                                                 "side": "right"}
    doc["members"]["4"]["extra"]["E"] = {"polar": [0.15, -30.0]}
    kinds = [(g.label, g.kind) for g in givens(doc) if g.path[:4] == ("members", "4", "extra", "E")]
    assert kinds == [("DE", "length"), ("∠E4", "angle")]
