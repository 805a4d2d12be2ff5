"""The method pages of ``docs/`` inside the app: the app is where a student reads them, and
it serves no files of its own, so each page opens its method's page in an expander.

Each method page has a Serbian version in ``docs/sr/`` written for the course's students;
the Cyrillic page is made from it, with code, course notation in ⟨ ⟩ and link targets kept
in Latin letters (as ``ui.i18n`` does for the strings)."""

from __future__ import annotations

import re
from functools import cache
from pathlib import Path

import streamlit as st

from ui.i18n import KEEP, _to_cyrillic, current, t

DOCS = Path(__file__).resolve().parents[1] / "docs"
LATIN = re.compile(r"(`[^`]*`|⟨[^⟩]*⟩|\]\([^)]*\))")  # code, notation, a link's target


def path_of(name: str, language: str) -> str:
    """The method page a reader of ``language`` gets, relative to the project."""
    return f"docs/sr/{name}.md" if language.startswith("sr") else f"docs/{name}.md"


@cache
def text_of(name: str, language: str) -> str:
    """The method page ``name`` in ``language``, ready for ``st.markdown``."""
    text = (DOCS.parent / path_of(name, language)).read_text(encoding="utf-8")
    if language == "sr-cyrl":
        text = _to_cyrillic(text, LATIN)
    return KEEP.sub(r"\1", text)


def title_of(name: str, language: str) -> str:
    """The method page's title (its first heading), as a reader names it — not its file."""
    text = text_of(name, language)
    return next((line[2:].strip() for line in text.splitlines() if line.startswith("# ")), name)


def method_doc(name: str) -> None:
    """The method page in the reader's language, in a closed expander named after its title."""
    language = current()
    with st.expander(t("app.method_doc", title=title_of(name, language))):
        st.markdown(text_of(name, language))
