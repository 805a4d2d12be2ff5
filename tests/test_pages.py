"""Every page renders without an exception (Streamlit AppTest), and the first page reacts."""

import base64
from pathlib import Path

import numpy as np
import pytest
from streamlit.testing.v1 import AppTest

from pages.chapters import CHAPTERS

ROOT = Path(__file__).resolve().parents[1]


def page(path: str) -> AppTest:
    at = AppTest.from_file(str(ROOT / path), default_timeout=30)
    return at.run()


def figure_arrays(at: AppTest) -> list:
    """The x arrays of every trace of the first Plotly chart (Plotly ≥ 6 packs them as bdata)."""
    import json

    spec = json.loads(at.get("plotly_chart")[0].proto.spec)
    out = []
    for trace in spec["data"]:
        x = trace.get("x")
        if isinstance(x, dict):
            x = np.frombuffer(base64.b64decode(x["bdata"]), dtype=x["dtype"])
        out.append(np.asarray(x, dtype=float))
    return out


def test_home_lists_every_chapter():
    at = page("app.py")
    assert not at.exception
    text = " ".join(m.value for m in at.markdown)
    for chapter in CHAPTERS:
        assert chapter.summary.split(".")[0] in text


@pytest.mark.parametrize("chapter", CHAPTERS, ids=lambda c: c.file)
def test_every_chapter_page_renders(chapter):
    at = page(chapter.file)
    assert not at.exception
    assert at.title[0].value.endswith(chapter.title)
    if not chapter.ready:
        assert "Coming soon" in at.info[0].value


def test_moving_the_crank_moves_the_drawn_mechanism():
    at = page("pages/trajectories.py")
    at.selectbox(key="scene").set_value("four-bar-crank-rocker").run()
    before = figure_arrays(at)
    at.slider(key="phi").set_value(120.0).run()
    after = figure_arrays(at)
    assert not at.exception
    assert len(before) == len(after)
    moved = [not np.allclose(a, b, equal_nan=True) for a, b in zip(before, after)]
    assert any(moved)  # the members moved
    assert not moved[0]  # the path stays: it is the whole cycle


def test_a_position_the_crank_cannot_reach_is_explained_on_the_page():
    at = page("pages/trajectories.py")
    at.selectbox(key="scene").set_value("analitika-2.1").run()
    at.slider(key="phi").set_value(140.0).run()
    assert not at.exception
    assert "cannot pass" in at.warning[0].value
