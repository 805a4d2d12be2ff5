"""The method pages of ``docs/`` inside the app: the app is where a student reads them, and
it serves no files of its own, so each page opens its method's page in an expander."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import streamlit as st

from ui.i18n import t

DOCS = Path(__file__).resolve().parents[1] / "docs"


@cache
def _text(name: str) -> str:
    return (DOCS / f"{name}.md").read_text(encoding="utf-8")


def method_doc(name: str) -> None:
    """``docs/<name>.md`` (written in English) in a closed expander named after the file."""
    with st.expander(t("app.method_doc", file=f"docs/{name}.md")):
        st.markdown(_text(name))
