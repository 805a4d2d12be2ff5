"""The mechanism builder's core: links (?s=), the branch taken from the drawing, and the
sketch (tables ↔ document, drags, clicks) — all without a browser."""

import base64
import math
import zlib

import numpy as np
import pytest

from mechanisms import SceneError, load_preset, preset_ids
from mechanisms.link import MAX_CHARS, _DICTIONARY, decode, encode, parameter, to_text
from mechanisms.loader import build_scene
from mechanisms.sketch import (add_point, document, drag, drawn, driver_values, free_letter,
                               from_scene, snap, tables, template, template_ids)
from solvers import solve
from solvers.diagnostics import solve_instant, sweep_values
from solvers.structure import decompose, loose_joints

from .scenes import fourbar, rocking_guide, scotch_yoke, slider_crank, slotted_crank

LINKAGES = preset_ids("linkage")


def pose(scene):
    motion = solve_instant(scene, None)
    return ({n: complex(p.z[0]) for n, p in motion.points.items()},
            {m: complex(mm.rot[0]) for m, mm in motion.members.items()})


def packed(text: bytes) -> str:
    """A link parameter made by hand (as an attacker or a broken mail client would)."""
    c = zlib.compressobj(9, zlib.DEFLATED, -15, zdict=_DICTIONARY)
    return "1" + base64.urlsafe_b64encode(c.compress(text) + c.flush()).decode().rstrip("=")


# --- links ---------------------------------------------------------------------------

@pytest.mark.parametrize("pid", preset_ids())
def test_every_preset_travels_in_a_link_unchanged(pid):
    scene = load_preset(pid)
    value = encode(scene)
    assert set(value) <= set("0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz-_")
    assert to_text(decode(value)) == to_text(scene)


def test_a_link_is_read_from_a_whole_url_an_s_parameter_or_the_value_alone():
    value = encode(load_preset("zbirka-2.1"))
    for text in (value, f"s={value}", f"https://host/velocity_plans?lang=sr&s={value}&at=30",
                 f"  http://localhost:8501/trajectories?s={value}\n"):
        assert parameter(text) == value
    with pytest.raises(SceneError, match="no s= parameter"):
        decode("https://host/velocity_plans?lang=sr")


def eight_members() -> dict:
    """The Watt six-bar with one more dyad on its second rocker: eight members with the frame,
    every moving member with a mass, a centre and a radius of gyration, a force and a moment."""
    doc = template("watt-six-bar")
    doc["frame"]["J"] = [0.8, 0.1]
    doc["members"]["6"]["extra"] = {"K": [0.1, 0.0]}
    doc["members"]["7"] = {"points": ["K", "H"], "length": 0.2}
    doc["members"]["8"] = {"points": ["J", "H"], "length": 0.2}
    doc["pairs"] += [{"type": "revolute", "members": [6, 7], "point": "K"},
                     {"type": "revolute", "members": [7, 8], "point": "H"},
                     {"type": "revolute", "members": [8, 1], "point": "J"}]
    for spec in doc["members"].values():
        spec.update(mass=1.25, gyration=0.0731, centre=[0.05, 0.01])
    doc["forces"] = [{"member": 8, "point": "H", "magnitude": 150.0, "angle": 270.0}]
    doc["moments"] = [{"member": 4, "value": -12.5}]
    scene = build_scene(doc)
    doc["guess"] = drawn(doc, pose(scene)[0])
    return doc


def test_an_eight_member_mechanism_with_masses_travels_in_under_2000_characters():
    scene = build_scene(eight_members())
    assert len(scene.members) == 7 and set(scene.guess) == {"A", "B", "E", "F", "K", "H"}
    value = encode(scene)
    assert len(value) < 2000
    assert to_text(decode(value)) == to_text(scene)


@pytest.mark.parametrize("text, rule", [
    ("1" + "A" * 40, "damaged"),
    ("1Zm9v!!", "damaged"),
    ("2abc", "unknown format"),
    ("", "unknown format"),
    ("1" + "x" * MAX_CHARS, "at most 8,000"),
])
def test_a_bad_link_says_what_is_wrong(text, rule):
    with pytest.raises(SceneError, match=rule):
        decode(text)


def test_a_cut_link_says_it_is_cut():
    value = encode(load_preset("zbirka-2.1"))
    with pytest.raises(SceneError, match="cut short"):
        decode(value[: len(value) // 2])


def test_a_link_that_inflates_past_the_upload_limit_is_refused_without_inflating_it_all():
    bomb = packed(b"#" * 3_000_000)
    assert len(bomb) < MAX_CHARS  # small on the wire
    with pytest.raises(SceneError, match="over 100,000 bytes"):
        decode(bomb)


def test_a_link_to_an_invalid_scene_gets_the_loaders_message():
    text = to_text(load_preset("zbirka-2.1")).replace("length = 0.41", "length = -0.41")
    with pytest.raises(SceneError, match=r"link: members.3.length must be > 0"):
        decode(packed(text.encode()))


@pytest.mark.parametrize("name", template_ids())
def test_a_built_scene_downloads_and_uploads_again_unchanged(name):
    from mechanisms import parse_scene

    scene = build_scene(template(name))
    assert to_text(parse_scene(to_text(scene))) == to_text(scene)


# --- the branch is the one drawn -------------------------------------------------------

@pytest.mark.parametrize("make", [fourbar, slider_crank, rocking_guide], ids=["RRR", "RRP", "RPR"])
@pytest.mark.parametrize("branch", [1, -1])
def test_drawn_points_choose_the_dyads_assembly_over_the_whole_cycle(make, branch):
    signed = make(branch=branch)
    at = sweep_values(signed, 72)
    expected = solve(signed, at)
    positions, _ = pose(signed)
    unsigned = build_scene(from_scene(signed, positions))
    assert not unsigned.assembly and unsigned.guess
    got = solve(unsigned, at)
    for name, point in expected.points.items():
        ok = np.isfinite(point.z)
        assert np.allclose(got.points[name].z[ok], point.z[ok], atol=1e-12), name
        assert np.allclose(got.points[name].a[ok], point.a[ok], atol=1e-9), name


@pytest.mark.parametrize("make", [slotted_crank, scotch_yoke], ids=["PRP", "RPP"])
def test_drawn_points_leave_the_single_assembly_dyads_alone(make):
    scene = make()
    positions, _ = pose(scene)
    rebuilt, expected = pose(build_scene(from_scene(scene, positions)))[0], positions
    assert all(abs(rebuilt[n] - z) < 1e-12 for n, z in expected.items())


def test_an_explicit_assembly_sign_still_wins_over_the_drawing():
    up, down = fourbar(branch=1), fourbar(branch=-1)
    doc = from_scene(up, pose(up)[0])
    doc["assembly"] = {"3-4": -1}
    assert pose(build_scene(doc))[0]["B"] == pytest.approx(pose(down)[0]["B"], abs=1e-12)


@pytest.mark.parametrize("pid", LINKAGES)
def test_every_linkage_preset_rebuilt_from_its_drawing_is_the_same_mechanism(pid):
    """Presets carry ±1 signs (and class III [guess] points); the builder replaces the signs by
    the drawn positions: every point lands where the preset puts it."""
    scene = load_preset(pid)
    positions, _ = pose(scene)
    rebuilt, _ = pose(build_scene(from_scene(scene, positions)))
    for name, z in positions.items():
        assert abs(rebuilt[name] - z) < 1e-9 * max(1.0, abs(z)), name


def test_the_triads_assembly_is_the_drawn_one():
    scene = build_scene(template("class-iii"))
    positions, _ = pose(scene)
    doc = template("class-iii")
    doc["guess"] = drawn(doc, positions)
    again, _ = pose(build_scene(doc))
    assert max(abs(again[n] - positions[n]) for n in positions) < 1e-9
    assert decompose(scene).groups[0].cls == 3


# --- the sketch: tables, drags, clicks -----------------------------------------------------

@pytest.mark.parametrize("name", template_ids())
def test_the_tables_say_the_whole_document(name):
    doc = template(name)
    again = document(tables(doc), driver_values(doc), doc)
    assert to_text(build_scene(again)) == to_text(build_scene(doc))


def test_a_half_filled_row_is_kept_and_the_loader_names_what_is_missing():
    doc = template("four-bar")
    rows = tables(doc)
    rows["members"].append({"member": 5.0, "label": None, "first": "B", "second": "K",
                            "length": None, "mass": None, "centre_along": None,
                            "centre_left": None, "gyration": None})
    half = document(rows, driver_values(doc), doc)
    assert half["members"]["5"] == {"points": ["B", "K"]}
    with pytest.raises(SceneError, match="members.5.length is missing"):
        build_scene(half)


def test_a_typed_value_outside_the_loaders_range_gets_the_loaders_message():
    doc = template("four-bar")
    rows = tables(doc)
    rows["members"][1]["length"] = -0.35
    with pytest.raises(SceneError, match=r"members.3.length must be > 0, got -0.35"):
        build_scene(document(rows, driver_values(doc), doc), source="the tables")


@pytest.mark.parametrize("name", template_ids())
def test_a_dragged_joint_is_where_the_resolved_mechanism_passes(name):
    doc = template(name)
    scene = build_scene(doc)
    positions, rotations = pose(scene)
    doc["guess"] = drawn(doc, positions)
    sliding = {p.point for p in scene.pairs if p.kind == "prismatic" and p.members[0] == 1}
    for point, z in positions.items():
        if point in sliding:
            continue  # a slider on a frame guide goes to its foot on the guide (below)
        to = z + 0.01 + 0.004j
        moved, _ = pose(build_scene(drag(doc, positions, rotations, point, to)))
        assert abs(moved[point] - to) < 1e-9, point
        still = [n for n in positions if n != point and n in scene.frame]
        assert all(moved[n] == positions[n] for n in still)


def test_a_slider_dragged_off_its_guide_lands_on_the_guide():
    doc = template("slider-crank")
    positions, rotations = pose(build_scene(doc))
    moved, _ = pose(build_scene(drag(doc, positions, rotations, "B", positions["B"] - 0.05 + 0.02j)))
    assert moved["B"] == pytest.approx(positions["B"] - 0.05, abs=1e-9)


def test_dragging_the_crank_pin_sets_the_crank_length_and_phi2():
    doc = template("four-bar")
    positions, rotations = pose(build_scene(doc))
    new = drag(doc, positions, rotations, "A", 0.06 + 0.08j)
    assert new["members"]["2"]["length"] == pytest.approx(0.1)
    assert new["driver"]["at"] == pytest.approx(math.degrees(math.atan2(0.08, 0.06)))
    assert new["guess"]["A"] == [0.06, 0.08]


def test_dragging_a_pivot_moves_the_frame_and_keeps_the_other_joints():
    doc = template("four-bar")
    positions, rotations = pose(build_scene(doc))
    new = drag(doc, positions, rotations, "D", 0.3 + 0j)
    assert new["frame"]["D"] == [0.3, 0.0]
    moved, _ = pose(build_scene(new))
    assert moved["B"] == pytest.approx(positions["B"], abs=1e-9)
    assert new["members"]["4"]["length"] == pytest.approx(abs(positions["B"] - 0.3))


def test_snap_puts_a_mouse_place_on_the_roundest_grid_of_at_least_three_pixels():
    assert snap(0.30137 + 0.24861j, 0.0012) == pytest.approx(0.300 + 0.250j, abs=1e-15)  # 5 mm
    assert snap(0.30137 + 0.24861j, 0.0002) == pytest.approx(0.301 + 0.249j, abs=1e-15)  # 1 mm
    assert snap(0.30137 + 0.24861j, 0.0005) == pytest.approx(0.302 + 0.248j, abs=1e-15)  # 2 mm
    assert snap(12.34 + 0j, 0.02) == pytest.approx(12.3 + 0j)


def test_a_click_adds_a_frame_point_or_a_point_of_a_member():
    doc = template("four-bar")
    positions, rotations = pose(build_scene(doc))
    assert free_letter(doc) == "C"
    with_frame = add_point(doc, positions, rotations, 1, 0.1 - 0.1j)
    assert with_frame["frame"]["C"] == [0.1, -0.1]
    with_point = add_point(doc, positions, rotations, 3, 0.2 + 0.2j)
    on_coupler, _ = pose(build_scene(with_point))
    assert on_coupler["C"] == pytest.approx(0.2 + 0.2j, abs=1e-12)


def test_unconnected_joints_are_named():
    doc = template("four-bar")
    doc["frame"]["E"] = [0.5, 0.5]
    doc["pairs"] = doc["pairs"][:3] + [{"type": "revolute", "members": [4, 1], "point": "D"}]
    assert loose_joints(build_scene(doc)) == [("E", 1)]
    doc["members"]["4"]["points"] = ["D", "K"]
    doc["members"]["4"]["extra"] = {"B": [0.2, 0.05]}
    assert ("K", 4) in loose_joints(build_scene(doc))


def test_a_joint_dragged_onto_the_other_end_of_its_member_is_refused_with_the_rule():
    doc = template("four-bar")
    positions, rotations = pose(build_scene(doc))
    with pytest.raises(SceneError, match="members.2.length must be > 0"):
        build_scene(drag(doc, positions, rotations, "A", 0j))


def _mutations():
    """A refusal of each of the builder's tables, and of the driver (issue 68: the messages
    said "frame.D", "members.2.mass", "pairs[0].members navodi član 25")."""
    def change(path, value):
        def made(doc):
            target = doc
            for part in path[:-1]:
                target = target[part]
            target[path[-1]] = value
        return made
    return {"frame emptied": change(("frame",), {}),
            "a frame point": change(("frame", "D"), "x"),
            "a member's mass": change(("members", "2", "mass"), -1),
            "a member's length": change(("members", "3", "length"), "x"),
            "a pair's members": change(("pairs", 0, "members"), [1, 25]),
            "a pair's kind": change(("pairs", 1, "type"), "weld"),
            "a member's point": change(("members", "3", "extra"), {"M": "x"}),
            "a force": change(("forces",), [{"member": 3, "point": "B", "magnitude": "x", "angle": 0}]),
            "a moment": change(("moments",), [{"member": 9, "value": 1.0}]),
            "the driver": change(("driver", "type"), "x")}


@pytest.mark.parametrize("name", list(_mutations()))
@pytest.mark.parametrize("language", ["en", "sr"])
def test_a_refusal_of_the_tables_names_the_table_row_and_column_never_a_file_key(name, language):
    import copy
    import re

    from mechanisms.sketch import template
    from ui.builder import in_tables
    from ui.i18n import message, t

    doc = copy.deepcopy(template("four-bar"))
    _mutations()[name](doc)
    with pytest.raises(SceneError) as refused:
        build_scene(doc, source="tables")
    said = message(in_tables(refused.value, doc), language)
    assert not re.search(r"\b(frame|members|pairs|forces|moments|driver|extra)\b[.\[]|\[\d+\]", said), said
    tabs = [t(f"build.tab_{n}", language) for n in ("frame", "members", "extra", "pairs", "forces", "moments")]
    assert any(tab in said for tab in tabs) or t("build.driver_type", language) in said, said
    if "row" in said or "red " in said:
        assert not re.search(r"(row|red) 0\b", said), said  # rows as numbered on screen, from 1
