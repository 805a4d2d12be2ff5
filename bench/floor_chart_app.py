"""What every page of the app pays before its own content, for bench/browser.py's
navigation → first chart: Streamlit's front end, the app's sidebar (language, projector
mode) and navigation (every page listed), and one small chart drawn by ui/plot.py with the
bundle the pages use. A page can open no faster than this.

With ``?floor=slider``, the floor of bench/browser.py's slider → figure instead: one length
slider in a fragment redrawing the trajectories page's first figure (its default scene, the
12 positions), and nothing else on the page."""

import sys
from pathlib import Path

import streamlit as st

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from figures.raw import RawFigure  # noqa: E402
from figures.trajectories import construction_figure  # noqa: E402
from solvers.paths import numbered_points  # noqa: E402
from ui.cache import cycle, preset  # noqa: E402
from ui.chapters import BUILDER, CHAPTERS, VARIANTS  # noqa: E402
from ui.i18n import language_picker, t, title_of  # noqa: E402
from ui.plot import plot, publish_chart_js, publish_plotly_js  # noqa: E402
from ui.present import look, projector_switch  # noqa: E402
from ui.scenes import length_slider, preset_ids  # noqa: E402

LABELS = {"svg": "SVG", "png": "PNG", "fullscreen": "full screen"}


def page() -> None:
    if st.query_params.get("floor") == "slider":
        st.fragment(slider_floor)()
        return
    fig = RawFigure()
    fig.add_raw([{"type": "scatter", "x": [0, 1, 2], "y": [0, 1, 0]}])
    plot(fig, "floor", "floor", LABELS)


def slider_floor() -> None:
    """Member 2's length, as the trajectories page offers it, and that page's figure."""
    scene = preset(preset_ids("linkage")[0])
    value = length_slider(scene, 2, value=scene.lengths[2])
    moved = scene.with_(lengths={**scene.lengths, 2: value})
    last = [p for p in scene.point_names if p not in scene.frame][-1]  # the page's default
    plot(construction_figure(cycle(moved, 12), None, numbered_points(scene, [last]),
                             title_of(scene), t, look()), "floor", "floor", LABELS)


for publish in (publish_plotly_js, publish_chart_js):  # Streamlit serves static/ beside the script
    publish(Path(__file__).parent / "static")
st.set_page_config(page_title="floor", layout="wide")
language_picker()
projector_switch()
names = [Path(c.file).stem for c in (*CHAPTERS, BUILDER, VARIANTS)] + ["textbook_check"]
st.navigation([st.Page(page, title=name, url_path=name, default=name == "trajectories")
               for name in names]).run()
