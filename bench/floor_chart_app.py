"""What every page of the app pays before its own content, for bench/browser.py's
navigation → first chart: Streamlit's front end, the app's sidebar (language, projector
mode) and navigation (every page listed), and one small chart drawn by ui/plot.py with the
bundle the pages use. A page can open no faster than this."""

import sys
from pathlib import Path

import streamlit as st

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from figures.raw import RawFigure  # noqa: E402
from ui.chapters import BUILDER, CHAPTERS, VARIANTS  # noqa: E402
from ui.i18n import language_picker  # noqa: E402
from ui.plot import plot, publish_plotly_js  # noqa: E402
from ui.present import projector_switch  # noqa: E402


def page() -> None:
    fig = RawFigure()
    fig.add_raw([{"type": "scatter", "x": [0, 1, 2], "y": [0, 1, 0]}])
    plot(fig, "floor", "floor", {"svg": "SVG", "png": "PNG", "fullscreen": "full screen"})


publish_plotly_js(Path(__file__).parent / "static")  # Streamlit serves static/ beside the script
st.set_page_config(page_title="floor", layout="wide")
language_picker()
projector_switch()
names = [Path(c.file).stem for c in (*CHAPTERS, BUILDER, VARIANTS)] + ["textbook_check"]
st.navigation([st.Page(page, title=name, url_path=name, default=name == "trajectories")
               for name in names]).run()
