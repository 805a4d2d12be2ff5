"""Every page renders without an exception (Streamlit AppTest), in every language."""

import base64
import json
from pathlib import Path

import numpy as np
import plotly.graph_objects as go
import pytest
from streamlit.testing.v1 import AppTest

from ui.chapters import CHAPTERS
from ui.i18n import LANGUAGES, t
from ui.numbers import shown

ROOT = Path(__file__).resolve().parents[1]


def page(path: str, **state) -> AppTest:
    """Page ``path`` run as AppTest runs a page (its script, with ``state`` preset), or
    ``app.py``'s home page. The page's run is the test's first: a run of the home page
    before each (65–100 ms, three times the page's own) was paid by a thousand tests."""
    at = AppTest.from_file(str(ROOT / "app.py"), default_timeout=60)
    for key, value in state.items():
        at.session_state[key] = value
    if path != "app.py":
        at.switch_page(path)
    at.run()
    return at


def typed(at: AppTest, key: str, value: float, language: str = "en"):
    """A number typed into a number field (a text box ui.numbers reads) the way a person
    writes it in ``language``; ``.run()`` it."""
    return at.text_input(key=key).input(shown(value, language))


def decode(value):
    """Plotly ≥ 6 packs arrays as {"dtype", "bdata"}; plain lists stay lists."""
    if isinstance(value, dict) and "bdata" in value:
        return np.frombuffer(base64.b64decode(value["bdata"]), dtype=value["dtype"])
    return value


def charts(at: AppTest) -> dict[str, dict]:
    """Every chart on the page (ui.plot), by key: what the browser is sent to draw, with the
    figure under "figure"."""
    return {element.proto.id.rsplit("-", 1)[-1]: json.loads(element.proto.bytes)
            for element in at.get("bidi_component")
            if element.proto.component_name == "mehanizmi_plot"}


def chart(at: AppTest, key: str) -> dict:
    """The figure of chart ``key``."""
    return charts(at)[key]["figure"]


def arrows(spec: dict) -> list[tuple[float, float, float, float]]:
    """(tail x, tail y, head x, head y) of every arrow a figure draws (figures.arrows)."""
    drawn = []
    for tr in spec["data"]:
        if tr.get("marker", {}).get("symbol") == "arrow":
            x, y = tr["x"], tr["y"]
            drawn += [(x[i], y[i], x[i + 1], y[i + 1]) for i in range(0, len(x), 3)]
    return drawn


def texts(spec: dict) -> list[str]:
    """Every text a figure writes beside its points (labels of arrows, points, corners)."""
    return [text for tr in spec["data"] if "text" in tr.get("mode", "") for text in tr["text"]]


def traces(spec: dict, name_start: str) -> list[dict]:
    return [tr for tr in spec["data"] if str(tr.get("name", "")).startswith(name_start)]


def test_home_lists_every_chapter():
    at = page("app.py")
    assert not at.exception
    text = " ".join(m.value for m in at.markdown)
    for chapter in CHAPTERS:
        assert t(chapter.summary, language="en").split(".")[0] in text


@pytest.mark.parametrize("language", list(LANGUAGES))
@pytest.mark.parametrize("chapter", CHAPTERS, ids=lambda c: c.file)
def test_every_chapter_page_renders_in_every_language(chapter, language):
    at = page(chapter.file, lang=language)
    assert not at.exception
    assert at.title[0].value.endswith(t(chapter.title, language=language))


def test_every_preset_that_quotes_the_book_is_on_the_textbook_check_page():
    from mechanisms import load_preset, preset_ids

    at = page("pages/textbook_check.py", lang="en")
    assert not at.exception
    headings = " ".join(h.value for h in at.header)
    quoting = [pid for pid in preset_ids() if load_preset(pid).book]
    assert len(quoting) >= 9
    for pid in quoting:
        assert pid in headings
    rows = sum(len(d.value) for d in at.dataframe if "quantity" in d.value.columns)  # not coverage
    assert rows == sum(len(load_preset(pid).book) for pid in quoting)


def linked(path: str, **params) -> AppTest:
    """Open a page from a shared link: ``params`` are the link's query parameters."""
    at = AppTest.from_file(str(ROOT / path), default_timeout=60)
    at.query_params.update({k: str(v) for k, v in params.items()})
    at.run()
    return at


EDITORS = {"pages/planetary_gears.py": 1, "pages/rotor_balancing.py": 1}  # input tables
OPENED = {"pages/trajectories.py": {"accuracy_open": True}}  # its table's section, shut at first


@pytest.mark.parametrize("chapter", CHAPTERS, ids=lambda c: c.file)
def test_every_table_has_its_csv_download(chapter):
    at = page(chapter.file, lang="en", **OPENED.get(chapter.file, {}))
    csv = [b for b in at.get("download_button") if b.proto.label == t("export.csv", "en")]
    assert len(csv) >= len(at.dataframe) - EDITORS.get(chapter.file, 0) > 0


@pytest.mark.parametrize("chapter", CHAPTERS, ids=lambda c: c.file)
def test_every_chart_is_drawn_in_place_in_the_house_style(chapter):
    """Charts go through ui.plot (Plotly.react into a div kept between reruns), never
    st.plotly_chart, whose theme and remounts cost the browser most of a redraw
    (docs/performance.md); each figure carries its own font and title style instead."""
    at = page(chapter.file, lang="en")
    assert not at.get("plotly_chart")
    drawn = charts(at)
    assert drawn
    for body in drawn.values():
        go.Figure(body["figure"])  # Plotly's schema: figures are built unvalidated (figures/raw.py)
        layout = body["figure"]["layout"]
        assert "Source Sans" in layout["font"]["family"] and layout["title"]["x"] == 0.0
        assert body["src"].endswith(".js") and body["filename"]
        crank = {"play", "pause", "unreachable", "choice"} if body["crank"] else set()  # its own φ₂
        assert set(body["labels"]) == {"svg", "png", "fullscreen"} | crank


@pytest.mark.parametrize("chapter", CHAPTERS, ids=lambda c: c.file)
def test_closed_panels_cost_a_rerun_nothing(chapter):
    """The scene's note and upload, and the answer check, are filled only while open: closed,
    a rerun sends none of their elements to the browser."""
    closed = page(chapter.file, lang="en")
    assert not closed.get("file_uploader") and not [w for w in closed.text_input if w.key == "self_value"]
    opened = page(chapter.file, lang="en", about=True, self_open=True)
    assert opened.get("file_uploader") and [w for w in opened.text_input if w.key == "self_value"]


@pytest.mark.parametrize("path, query, doc", [
    ("pages/trajectories.py", {"view": "compass"}, "compass.md"),
    ("pages/velocity_plans.py", {"scene": "zbirka-4.1"}, "triad-plans.md"),
    ("pages/kinetostatics.py", {"tab": "Step by step"}, "graphical-kinetostatics.md"),
    ("pages/kinetostatics.py", {"tab": "Zhukovsky's lever"}, "reduced-mechanism.md"),
    ("pages/planetary_gears.py", {"willis_open": True}, "willis.md"),
    ("pages/assur_groups.py", {"scene": "triad-full-turn"}, "complex-number.md"),
])
def test_each_method_links_its_page_of_the_docs(path, query, doc):
    """Each step-by-step method opens its docs page in the app, the page's text itself."""
    at = page(path, lang="en", **query)
    assert not at.exception
    first = (Path(__file__).resolve().parents[1] / "docs" / doc).read_text().splitlines()[0]
    expander = next(e for e in at.expander if first.removeprefix("# ") in e.label)  # its title
    assert any(first in m.value for m in expander.markdown)
