"""Projector mode: big type, thick lines, high contrast, no sidebar; ``?present=1`` in the URL."""

from __future__ import annotations

import streamlit as st

from figures.style import NORMAL, PROJECTOR, Look
from mechanisms.typed import Refused
from ui.i18n import t
from ui.numbers import link_note
from ui.url import linked, said_of_link

SWITCH = {"1": True, "true": True, "0": False, "false": False}  # what ``?present=`` may say

CSS = """
<style>
html { font-size: 21px; }
[data-testid="stSidebar"], [data-testid="stSidebarCollapsedControl"],
[data-testid="stToolbar"] { display: none; }
.stApp, [data-testid="stHeader"] { background: #ffffff; color: #000000; }
[data-testid="stMainBlockContainer"] { max-width: 100%; padding: 0.5rem 1.5rem; }
.stApp p, .stApp label, .stApp li { color: #000000; font-weight: 500; }
</style>
"""


def presenting() -> bool:
    return bool(st.session_state.get("present"))


def look() -> Look:
    return PROJECTOR if presenting() else NORMAL


def _sync_url() -> None:
    if st.session_state.get("present"):
        st.query_params["present"] = "1"
    else:
        st.query_params.pop("present", None)


def projector_switch() -> None:
    """The switch (sidebar normally, top of the page while presenting)."""
    linked("present")
    if "present" not in st.session_state:
        given = st.query_params.get("present")
        st.session_state["present"] = SWITCH.get(given, False)
        if given is not None and given not in SWITCH:  # said beside the switch, page as usual
            said_of_link("present", Refused("unknown", given), False)
            st.query_params.pop("present", None)
    where = st if presenting() else st.sidebar
    if presenting():
        st.html(CSS)
    where.toggle(t("app.projector"), key="present", on_change=_sync_url)
    link_note("present", t("app.projector"), presenting(), where)
