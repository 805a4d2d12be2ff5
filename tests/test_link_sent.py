"""A run's changes to the link go to the browser in one message as the run ends
(ui.url.link_sent): written one by one, each was a message the browser handled on its own
(issue 83). None may be lost on the way: not by a stop, an error, or a fragment the run
calls."""

import ast
from pathlib import Path

import pytest
from streamlit.testing.v1 import AppTest

ROOT = Path(__file__).resolve().parents[1]


def gathered():
    import streamlit as st

    from ui.url import link_sent, stop, url_set, url_value

    with link_sent():
        url_set("a", "1")
        st.session_state["seen_a"] = st.query_params.get("a")  # not sent yet ...
        st.session_state["meant_a"] = url_value("a")  # ... but what the run means
        with link_sent():  # a fragment the run calls: its changes join the run's
            url_set("b", "2")
        st.session_state["seen_b"] = st.query_params.get("b")
        url_set("c", "3")
        if st.session_state.get("end") == "stop":
            stop()
        if st.session_state.get("end") == "error":
            raise ValueError("a page's error")
        url_set("d", "4")


@pytest.mark.parametrize("end, sent", [
    (None, {"a": "1", "b": "2", "c": "3", "d": "4"}),
    ("stop", {"a": "1", "b": "2", "c": "3"}),  # (a plain st.stop() sent nothing at all)
    ("error", {"a": "1", "b": "2", "c": "3"})])
def test_a_run_s_changes_are_sent_together_as_it_ends_and_none_is_lost(end, sent):
    at = AppTest.from_function(gathered)
    at.session_state["end"] = end
    at.run()
    assert at.session_state["seen_a"] is None and at.session_state["seen_b"] is None
    assert at.session_state["meant_a"] == "1"
    assert dict(at.query_params.items()) == sent


def dropped():
    import streamlit as st

    from ui.url import link_sent, url_drop, url_replace, url_set

    with link_sent():
        url_set("a", "1")
        url_set("b", "2")
        url_drop("a")  # taken out after its change was gathered: not put back at the end
        if st.session_state.get("replace"):
            url_replace({"class": "X"})  # the whole link replaced: b goes with it


@pytest.mark.parametrize("replace, sent", [(False, {"b": "2"}), (True, {"class": "X"})])
def test_a_key_taken_out_or_a_link_replaced_is_not_put_back_as_the_run_ends(replace, sent):
    at = AppTest.from_function(dropped)
    at.session_state["replace"] = replace
    at.run()
    assert dict(at.query_params.items()) == sent


def alone():
    import streamlit as st

    from ui.url import url_set

    url_set("a", "1")  # a page's script run alone (AppTest): written at once
    st.session_state["seen_a"] = st.query_params.get("a")


def test_outside_a_gathered_run_a_change_is_written_at_once():
    at = AppTest.from_function(alone).run()
    assert at.session_state["seen_a"] == "1" and at.query_params["a"] == "1"


def test_every_page_stops_through_the_stop_that_sends_the_link():
    """``st.stop()`` itself would drop the run's link changes (Streamlit sends nothing after a
    stop is asked for): every stop of the app's own code goes through ``ui.url.stop``."""
    plain = []
    for path in [ROOT / "app.py", *ROOT.glob("ui/*.py"), *ROOT.glob("pages/*.py")]:
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                    and node.func.attr == "stop" and isinstance(node.func.value, ast.Name)
                    and node.func.value.id == "st"):
                plain.append(f"{path.relative_to(ROOT)}:{node.lineno}")
    assert len(plain) == 1 and plain[0].startswith("ui/url.py:"), plain
