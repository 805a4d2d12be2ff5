"""The floor bench/browser.py divides by (bench/floor_chart_app.py) runs, and its slider
floor offers and draws what the trajectories page does for member 2's length."""

import json
from pathlib import Path

from streamlit.testing.v1 import AppTest

from .test_pages import page

ROOT = Path(__file__).resolve().parents[1]


def figure(at: AppTest) -> dict:
    return json.loads(at.get("bidi_component")[0].proto.bytes)["figure"]


def test_the_slider_floor_is_the_trajectories_pages_length_slider_and_figure():
    floor = AppTest.from_file(str(ROOT / "bench" / "floor_chart_app.py"), default_timeout=60)
    floor.query_params["floor"] = "slider"
    floor.run()
    assert not floor.exception
    (slider,) = floor.slider
    app = page("pages/trajectories.py")
    ours = app.slider(key="L2")
    assert (slider.label, slider.min, slider.max, slider.step, slider.value) == \
        (ours.label, ours.min, ours.max, ours.step, ours.value)
    before = figure(floor)
    assert before["data"] == figure(app)["data"]
    slider.set_value(ours.value * 1.25).run()
    ours.set_value(ours.value * 1.25).run()
    assert not floor.exception and figure(floor)["data"] != before
    assert figure(floor)["data"] == figure(app)["data"]


def test_the_chart_floor_draws_one_small_chart_with_the_app_s_scripts_beside_it():
    at = AppTest.from_file(str(ROOT / "bench" / "floor_chart_app.py"), default_timeout=60)
    at.run()
    assert not at.exception and not at.slider and len(at.get("bidi_component")) == 1
    # its server serves bench/static/: the chart's script must be there under the app's name
    from ui.plot import publish_chart_js

    name = publish_chart_js().rsplit("/", 1)[1]
    assert (ROOT / "bench" / "static" / name).read_bytes() == (ROOT / "static" / name).read_bytes()
