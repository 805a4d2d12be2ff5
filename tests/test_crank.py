"""The crank frames the browser scrubs (ui/crank.py): each patch rebuilds its frame."""

import json
import math

from figures.raw import RawFigure
from ui.crank import Crank, crank_frames, nearest, turn


def drawing(angle: float) -> dict[str, RawFigure] | None:
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
    data = patch.get("all") or [{**tr, **patch.get("data", {}).get(str(i), {})}
                                for i, tr in enumerate(base["data"])]
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


def test_the_control_travels_without_frames_until_asked():
    control = json.loads(Crank(turn(), 3, "plans").json())
    assert control["turn"] is None and control["index"] == 3 and control["group"] == "plans"
    assert control["label"] == "φ₂"
    assert json.loads(Crank(turn(), 0, "plans", '{"base": 1}').json())["turn"] == {"base": 1}
