"""The crank frames the browser scrubs (ui/crank.py): each patch rebuilds its frame, and on
every page with them the frame at the page's angle is the figure the page draws there; the
neighbours a page's slider sends while the keyboard is on it are the figures the page draws
one step either side."""

import json
import math

import pytest
from streamlit.testing.v1 import AppTest

from figures.raw import RawFigure
from mechanisms import load_preset
from tests.test_pages import ROOT, charts, decode, page
from ui.crank import (LIVE, NEAR, PHI, Crank, Ranged, along, crank_frames, nearest, sides,
                      task_turn, turn)


def drawing(_: int, angle: float) -> dict[str, RawFigure] | None:
    """A pin on a unit circle, a still frame line and a title with the angle; nothing drawn
    between 90° and 180° (as where a mechanism cannot be assembled)."""
    if math.radians(90) < angle < math.radians(180):
        return None
    fig = RawFigure()
    fig.add_raw([{"type": "scatter", "x": [0.0, 1.0], "y": [0.0, 0.0], "mode": "lines"},
                 {"type": "scatter", "x": [math.cos(angle)], "y": [math.sin(angle)], "mode": "markers"}])
    fig.merge_layout({"title": {"text": f"{math.degrees(angle):.0f}°"}, "showlegend": False})
    return {"pin": fig}


def rebuilt(turn_json: dict, k: int) -> dict | None:
    """What ui/plot.js draws for frame k, in Python."""
    patch = turn_json["frames"][k]
    if patch is None:
        return None
    base = turn_json["base"]
    if "all" in patch:
        data = [base["data"][tr] if isinstance(tr, int) else tr for tr in patch["all"]]
    else:
        data = [{**tr, **patch.get("data", {}).get(str(i), {})} for i, tr in enumerate(base["data"])]
    return {"data": data, "layout": {**base["layout"], **patch.get("layout", {})}}


def test_every_patch_rebuilds_its_frame_and_sends_only_what_moves():
    values = turn()
    sent = json.loads(crank_frames(drawing, values)["pin"])
    for k, v in enumerate(values):
        frame = rebuilt(sent, k)
        if 90 < v < 180:
            assert frame is None
            continue
        assert frame["data"][1]["x"][0] == float(f"{math.cos(math.radians(v)):.5g}")
        assert frame["layout"]["title"]["text"] == f"{v:.0f}°"
    assert all("0" not in p.get("data", {}) for p in sent["frames"] if p)  # the still line: once
    assert all(set(p["data"]["1"]) == {"x", "y"} for p in sent["frames"][1:] if p)  # what moved
    assert all("showlegend" not in p.get("layout", {}) for p in sent["frames"] if p)


def test_the_slider_starts_at_the_frame_nearest_the_page_s_angle_around_the_turn():
    values = turn()
    assert len(values) == 72 and values[1] == 5.0
    assert nearest(values, 358.0) == 0 and nearest(values, 12.4) == 2 and nearest(values, 181.0) == 36


def test_the_task_s_own_instant_is_one_of_the_frames():
    values = turn(50.2857)  # task 5.1's φ₂: off the 5° grid, so a frame of its own
    assert len(values) == 73 and values[nearest(values, 50.2857)] == 50.2857
    assert list(values) == sorted(values)
    assert turn(60.0) == turn() and turn(-10.0) == turn()  # on the grid: nothing added
    assert task_turn(load_preset("zbirka-5.1")) == values  # from radians, shown as written
    assert task_turn(load_preset("analitika-2.2")) == turn()  # a slider's s is no angle


def test_the_control_travels_without_frames_until_asked():
    control = json.loads(Crank(turn(), 3, "plans").json())
    assert control["turn"] is None and control["index"] == 3 and control["group"] == "plans"
    assert control["label"] == "φ₂"
    assert json.loads(Crank(turn(), 0, "plans", '{"base": 1}').json())["turn"] == {"base": 1}


# --- the pages' frames (AppTest): the frame at the page's angle is what the page draws there

PAGES = [("pages/velocity_plans.py", {}, ("fig_v", "fig_a", "fig_mech")),
         ("pages/kinetostatics.py", {}, ("fig_loads",)),
         ("pages/kinetostatics.py", {"tab": "Force polygons"}, ("fig_free_body", "fig_polygon")),
         ("pages/assur_groups.py", {"scene": "triad-full-turn"}, ("structure",))]


def numbers(trace: dict) -> list[float | None]:
    """A trace's x and y as plain numbers, a gap (null or NaN) as None, as Plotly reads them."""
    out = []
    for axis in ("x", "y"):
        values = decode(trace.get(axis, []))
        out += [None if v is None or not math.isfinite(float(v)) else float(v) for v in values]
    return out


def same_drawing(frame: dict, figure: dict) -> None:
    assert len(frame["data"]) == len(figure["data"])
    for sent, drawn in zip(frame["data"], figure["data"]):
        got, want = numbers(sent), numbers(drawn)
        assert len(got) == len(want)
        for g, w in zip(got, want):
            assert (g is None) == (w is None)
            if g is not None:
                assert g == pytest.approx(w, rel=1e-4, abs=1e-4 * max(1.0, abs(w)))
    assert frame["layout"].get("title") == figure["layout"].get("title")


@pytest.mark.parametrize("path, state, keys", PAGES)
def test_the_frames_drawn_at_the_page_s_angle_are_the_page_s_figures(path, state, keys):
    at = page(path, lang="en", at=40.0, **state)
    assert not at.exception
    assert all(charts(at)[key]["crank"]["turn"] is None for key in keys)  # not asked: none sent
    at.session_state[LIVE] = True  # what touching a chart's φ₂ control sets (ui.export)
    at.run()
    sent = charts(at)
    for key in keys:
        control = sent[key]["crank"]  # every 5°, and the task's own instant where off that grid
        k40 = control["values"].index(40.0)
        assert control["index"] == k40 and len(control["turn"]["frames"]) == len(control["values"])
        same_drawing(rebuilt(control["turn"], k40), sent[key]["figure"])
    at.session_state["at"] = 200.0  # the page follows the control's release: no stale frame
    at.session_state[LIVE] = True
    at.run()
    moved = charts(at)
    for key in keys:
        control = moved[key]["crank"]
        k200, k40 = control["values"].index(200.0), control["values"].index(40.0)
        assert control["index"] == k200
        same_drawing(rebuilt(control["turn"], k200), moved[key]["figure"])
        assert rebuilt(control["turn"], k40) == rebuilt(sent[key]["crank"]["turn"], k40)


def test_a_new_scene_brings_its_own_frames():
    at = page("pages/kinetostatics.py", lang="en", at=40.0)
    at.session_state[LIVE] = True
    at.run()
    before = charts(at)["fig_loads"]["crank"]["turn"]
    at.session_state["scene"] = "zbirka-5.1"
    at.session_state[LIVE] = True
    at.run()
    after = charts(at)["fig_loads"]
    assert after["crank"]["turn"] != before
    k = after["crank"]["index"]  # the task's own φ₂ = 50.29°, a frame of its own
    assert after["crank"]["values"][k] == pytest.approx(50.2857)
    same_drawing(rebuilt(after["crank"]["turn"], k), after["figure"])


def test_a_length_s_frames_run_along_its_slider_with_the_shown_length_among_them():
    assert along(0.025, 0.2, 0.005, 0.1) == tuple(round(0.025 + 0.005 * k, 6) for k in range(36))
    off = along(0.025, 0.2, 0.005, 0.101)  # set between two frames with the page's slider
    assert len(off) == 37 and 0.101 in off and list(off) == sorted(off)


# --- the page's own slider with the keyboard on it: its neighbours come with the chart

def test_an_arrow_key_s_neighbours_stay_within_the_slider_s_range():
    phi = Ranged("φ₂", "φ₂", *PHI, "°", 40.0)
    assert sides(phi) == (39.5, 40.5)
    assert sides(phi._replace(value=0.0)) == (0.5,) and sides(phi._replace(value=360.0)) == (359.5,)
    length = Ranged("AB", "AB", 0.0875, 0.7, 0.0035, " m", 0.35)
    assert sides(length) == (0.3465, 0.3535)  # on the slider's grid, not 0.34650000000000003


def near_rebuilt(spec: dict, k: int) -> dict | None:
    """What ui/plot.js draws for the slider's neighbour k: its patch over the chart's figure."""
    return rebuilt({"base": spec["figure"], "frames": spec["crank"]["near"]["frames"]}, k)


def neighbours_drawn(at: AppTest, key: str, keys: tuple[str, ...], value: float) -> None:
    """With the keyboard on slider ``key`` at ``value``, each chart of ``keys`` is sent its
    figures one step either side, and each is what the page draws when the slider gets there
    (which is then sent its own neighbours)."""
    at.session_state[key] = value
    at.session_state[NEAR] = key  # what the slider's focus in the browser says (ui.crank.follow)
    at.run()
    sent = charts(at)
    for chart_key in keys:
        assert key in sent[chart_key]["crank"]["follows"]
        assert sent[chart_key]["crank"]["near"]["key"] == key
    values = sent[keys[0]]["crank"]["near"]["values"]
    assert len(values) == 2 and values[0] < value < values[1]
    for k, moved_to in enumerate(values):
        at.session_state[key] = moved_to
        at.run()
        moved = charts(at)
        for chart_key in keys:
            same_drawing(near_rebuilt(sent[chart_key], k), moved[chart_key]["figure"])
            assert moved[chart_key]["crank"]["near"]["values"][int(not k)] == pytest.approx(value)
        assert any(moved[c]["figure"] != sent[c]["figure"] for c in keys)  # (ω₂: not the linkage)
    del at.session_state[NEAR]  # the keyboard left the page's sliders: no run sends them
    at.run()
    assert all(charts(at)[chart_key]["crank"]["near"] is None for chart_key in keys)


@pytest.mark.parametrize("path, state, keys", PAGES)
def test_phi2_s_neighbours_are_the_page_s_figures_a_step_either_side(path, state, keys):
    at = page(path, lang="en", at=40.0, **state)
    assert all(charts(at)[key]["crank"]["near"] is None for key in keys)  # not asked: none
    speed = "assur" not in path  # (the Assur page has no ω₂ slider, its structure no speed)
    assert all(("omega" in charts(at)[key]["crank"]["follows"]) == speed for key in keys)
    neighbours_drawn(at, "at", keys, 40.0)


@pytest.mark.parametrize("path, state, keys", [
    ("pages/velocity_plans.py", {}, ("fig_v", "fig_a", "fig_mech")),
    ("pages/kinetostatics.py", {"scene": "zbirka-5.3"}, ("fig_loads",)),  # with inertia
    ("pages/kinetostatics.py", {"scene": "zbirka-5.3", "tab": "Force polygons"},
     ("fig_free_body", "fig_polygon"))])
def test_omega2_s_neighbours_are_the_page_s_figures_a_step_either_side(path, state, keys):
    """The plans, and the loads where members have inertia, grow with ω₂ at the same φ₂
    (the Assur page has no ω₂)."""
    at = page(path, lang="en", at=40.0, **state)
    assert all("omega" in charts(at)[key]["crank"]["follows"] for key in keys)
    neighbours_drawn(at, "omega", keys, 12.0)


@pytest.mark.parametrize("scene, state, chart_key, keys", [
    ("four-bar-crank-rocker", {}, "paths", ("L2", "L3", "L4")),
    ("zbirka-1.3", {"tab": "In the field"}, "field", ("Rt", "Ra", "Rb"))])
def test_every_slider_a_trajectories_chart_follows_sends_its_neighbours(scene, state, chart_key,
                                                                         keys):
    at = page("pages/trajectories.py", lang="en", scene=scene, **state)
    assert tuple(charts(at)[chart_key]["crank"]["follows"]) == keys
    for key in keys:
        neighbours_drawn(at, key, (chart_key,), at.session_state[key])


# --- the trajectories page: the chart's own control of a link's length

def test_the_length_frames_drawn_at_the_page_s_length_are_the_page_s_figure():
    at = page("pages/trajectories.py", lang="en", scene="four-bar-crank-rocker")
    control = charts(at)["paths"]["crank"]
    assert control["turn"] is None and control["key"] == "L2" and not control["wraps"]
    assert [key for key, _ in control["choices"]] == ["L2", "L3", "L4"]
    at.session_state[LIVE] = "L3"  # what picking member 3 in the control's list sets
    at.run()
    sent = charts(at)["paths"]
    control = sent["crank"]
    assert control["key"] == "L3" and control["label"] == "AB" and control["unit"] == " m"
    k = control["index"]
    assert control["values"][k] == 0.35 and len(control["turn"]["frames"]) == 36
    same_drawing(rebuilt(control["turn"], k), sent["figure"])
    at.session_state["L3"] = control["values"][k + 4]  # let go four frames on: the page follows
    at.session_state[LIVE] = True
    at.run()
    moved = charts(at)["paths"]
    assert moved["crank"]["key"] == "L3" and moved["crank"]["index"] == k + 4
    same_drawing(rebuilt(moved["crank"]["turn"], k + 4), moved["figure"])
    assert moved["crank"]["turn"] == control["turn"]  # the same frames: the shown length is no key
    assert moved["figure"] != sent["figure"]
    at.run()  # any other rerun sends no frames, and the list keeps the length picked
    assert charts(at)["paths"]["crank"]["turn"] is None
    assert charts(at)["paths"]["crank"]["key"] == "L3"


def test_the_tedder_s_travel_moves_on_the_field_chart_and_its_frames_are_the_page_s_figure():
    at = page("pages/trajectories.py", lang="en", scene="zbirka-1.3", tab="In the field", Rt=0.4)
    control = charts(at)["field"]["crank"]
    assert control["turn"] is None and control["key"] == "Rt" and control["unit"] == " m"
    assert [key for key, _ in control["choices"]] == ["Rt", "Ra", "Rb"]  # v_R moves no path
    assert control["values"][control["index"]] == 0.4 and control["step"] == "0.01 m"
    at.session_state[LIVE] = "Ra"  # picking R_a, the sprocket on the wheel's shaft, in the list
    at.run()
    sent = charts(at)["field"]
    control = sent["crank"]
    assert control["key"] == "Ra" and control["label"] == "R_a" and control["unit"] == " m"
    k = control["index"]
    assert len(control["turn"]["frames"]) == len(control["values"]) == 37
    same_drawing(rebuilt(control["turn"], k), sent["figure"])
    at.session_state["Ra"] = control["values"][k + 6]  # let go: the drive turns the crank faster
    at.session_state[LIVE] = True
    at.run()
    moved = charts(at)["field"]
    assert moved["crank"]["index"] == k + 6 and moved["crank"]["turn"] == control["turn"]
    same_drawing(rebuilt(moved["crank"]["turn"], k + 6), moved["figure"])
    assert moved["figure"] != sent["figure"]
    assert at.slider(key="Ra").value == control["values"][k + 6]  # the page's slider follows


def test_the_link_picked_in_the_chart_s_list_is_kept_in_the_page_s_link():
    at = page("pages/trajectories.py", lang="en", scene="four-bar-crank-rocker")
    assert "chart_length" not in at.query_params  # member 2's, the first: nothing to say
    at.session_state[LIVE] = "L4"
    at.run()
    assert at.query_params["chart_length"] == "L4"
    opened = AppTest.from_file(str(ROOT / "app.py"), default_timeout=60)  # the link, reloaded
    opened.query_params.update(lang="en", scene="four-bar-crank-rocker", chart_length="L4")
    opened.run()
    opened.switch_page("pages/trajectories.py").run()
    assert charts(opened)["paths"]["crank"]["key"] == "L4"
    opened.session_state[LIVE] = "L2"
    opened.run()
    assert "chart_length" not in opened.query_params


def test_a_length_no_position_can_be_built_with_is_a_gap_and_the_page_says_why():
    at = page("pages/trajectories.py", lang="en", scene="triad-full-turn")
    at.session_state[LIVE] = "L3"
    at.run()
    control = charts(at)["paths"]["crank"]
    frames = control["turn"]["frames"]
    assert frames[0] is None and frames[control["index"]] is not None  # a triad that cannot close
    why = charts(at)["paths"]["labels"]["unreachable"]  # the gap's tooltip names the length
    assert why.startswith("The mechanism cannot be assembled with this length")
    at.session_state["L3"] = control["values"][0]  # let go there
    at.run()
    assert not at.exception
    assert "cannot be assembled" in at.error[0].value and "III(3,4,5,6)" in at.error[0].value
