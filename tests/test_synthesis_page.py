"""The synthesis page (pages/synthesis.py) as a student uses it, in AppTest: the tine of task
1.3 fitted, points typed with a decimal comma on a Serbian page, a refused field that stops the
search with its reason, and the found four-bar's link that the builder opens."""

from __future__ import annotations

from pathlib import Path
from urllib.parse import parse_qs

import numpy as np
import pytest
from streamlit.testing.v1 import AppTest

from mechanisms.link import PARAMETER, decode
from ui.chapters import SYNTHESIS

from .test_pages import chart, page

ROOT = Path(__file__).resolve().parents[1]


def find_button(at: AppTest):
    return next(b for b in at.button if b.proto.type == "primary")


def page_links(at: AppTest) -> dict[str, str]:
    """Each page link's page and its query string."""
    found = {}

    def walk(node) -> None:
        for child in (node.children.values() if isinstance(getattr(node, "children", None), dict) else []):
            if getattr(child, "type", None) == "page_link":
                found[child.proto.page] = child.proto.query_string
            walk(child)

    walk(at.main)
    return found


@pytest.fixture(scope="module")
def found() -> AppTest:
    """The page with the tine's four-bar found (the default example, a search of seconds)."""
    at = page(SYNTHESIS.file)
    assert not at.exception
    find_button(at).click().run()
    assert not at.exception and not at.error
    return at


def test_the_tines_path_is_fitted_and_the_errors_shown_are_the_re_solved_ones(found):
    task, result = found.session_state["syn_result"]
    assert len(task.points) == 12 and task.timing == "steps"
    table = found.dataframe[-1].value
    assert len(table) == 12
    assert np.allclose(table.iloc[:, 2].astype(float), result.errors, rtol=5e-3, atol=1e-12)
    assert result.objective < 1e-3  # twelve points of a loop half a metre wide, within mm
    figure = chart(found, "synthesis_chart")  # the four-bar turning, a frame every 5°
    assert len(figure["frames"]) == 72 and "Precision points" in [tr.get("name") for tr in figure["data"]]


def test_the_found_four_bar_opens_in_the_builder(found):
    result = found.session_state["syn_result"][1]
    query = parse_qs(page_links(found)["builder"])
    text = query[PARAMETER][0]
    assert decode(text).members[2].length == pytest.approx(result.linkage.crank)
    builder = AppTest.from_file(str(ROOT / "app.py"), default_timeout=60)
    builder.run()
    builder.query_params[PARAMETER] = text
    builder.switch_page("pages/builder.py").run()
    assert not builder.exception
    doc = builder.session_state["build_doc"]
    assert doc["members"]["3"]["length"] == pytest.approx(result.linkage.coupler)
    assert doc["members"]["4"]["length"] == pytest.approx(result.linkage.rocker)


def test_points_typed_with_a_decimal_comma_on_a_serbian_page_are_read(monkeypatch):
    from ui import i18n

    # (AppTest writes a choice's label outside the script's run: in the page's language)
    monkeypatch.setattr(i18n._RUN, "language", "sr", raising=False)
    at = page(SYNTHESIS.file, lang="sr")
    at.selectbox(key="example").select_index(1).run()
    at.text_input(key="syn_max_own").input("0,5").run()
    assert not at.exception and not at.error
    find_button(at).click().run()
    assert at.session_state["syn_result"][0].max_length == 0.5
    assert "," in found_text(at)


def found_text(at: AppTest) -> str:
    return at.success[0].body


def test_a_refused_field_stops_the_search_and_says_why():
    at = page(SYNTHESIS.file)
    at.text_input(key="syn_max_tine").input("1,5").run()  # a comma on an English page
    assert at.error, "the field says its refusal"
    button = find_button(at)
    assert button.disabled and "Longest link" in button.proto.help
