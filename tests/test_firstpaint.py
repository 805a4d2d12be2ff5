"""A fresh visit's first run sends the chart and leaves out what can wait; the rerun its
paint starts sends the whole page (ui/firstpaint.py). The browser side: test_browser.py."""

import pytest
from streamlit.testing.v1 import AppTest

from ui.firstpaint import RAN

from .test_pages import ROOT, charts


def first_run(path: str, **params) -> AppTest:
    """The session's very first run, on page ``path`` (as a link with ``params`` opens it)."""
    at = AppTest.from_file(str(ROOT / "app.py"), default_timeout=60)
    at.session_state["lang"] = "en"
    at.query_params.update(params)
    at.run()  # AppTest reaches a page after a run of app.py (the home page) ...
    at.session_state[RAN] = False  # ... as if that run had been this page's ...
    at.switch_page(path).run()  # ... and runs the page's file alone
    return at


def rerun(at: AppTest) -> None:
    """The rerun the chart's "painted" trigger starts, after app.py marked the first done."""
    at.session_state[RAN] = True
    at.run()


def test_app_py_marks_the_first_run_done():
    at = AppTest.from_file(str(ROOT / "app.py"), default_timeout=60)
    at.run()
    assert at.session_state[RAN] is True


@pytest.mark.parametrize("path, tables", [("pages/trajectories.py", 1),
                                          ("pages/velocity_plans.py", 2),
                                          ("pages/kinetostatics.py", 2)])
def test_the_first_run_sends_the_chart_and_the_rerun_after_it_the_tables(path, tables):
    at = first_run(path)
    assert not at.exception
    assert charts(at) and all(c["first"] for c in charts(at).values())  # each reports its paint
    assert len(at.dataframe) == 0 and len(at.get("download_button")) == 0
    rerun(at)
    assert not at.exception
    assert not any(c["first"] for c in charts(at).values())
    assert len(at.dataframe) == tables and len(at.get("download_button")) > tables


def test_a_first_run_without_a_chart_leaves_nothing_out():
    """The rotor of a static balancing opens on its moment polygon's tab, which a static
    rotor does not draw: no chart would bring the rest, so nothing waits."""
    at = first_run("pages/rotor_balancing.py", mode="static")
    assert not charts(at)
    whole = len(at.dataframe)
    assert whole >= 2  # the masses (an input) and the corrections
    rerun(at)
    assert len(at.dataframe) == whole and not charts(at)
