"""The book-vs-exact table, shared by the textbook check page and the chapter pages."""

from __future__ import annotations

import pandas as pd
import streamlit as st

from solvers.textbook import BookRow, check
from ui.export import show_table
from ui.i18n import num, t

VERDICTS = {"agrees": "check.agrees", "close": "check.close", "differs": "check.differs",
            "layout": "check.layout", "missing": "check.missing"}


def book_table(rows: list[BookRow]) -> pd.DataFrame:
    return pd.DataFrame([{
        t("check.col_quantity"): r.key, t("check.col_book"): num(r.book, 6),
        t("check.col_exact"): "—" if r.exact is None else num(r.exact, 6),
        t("check.col_difference"): "—" if r.difference is None else num(r.difference, 3),
        t("check.col_verdict"): t(VERDICTS[r.verdict]), t("check.col_note"): r.note}
        for r in rows])


def book_section(scene, base) -> None:
    """Book vs exact on a chapter page: only for the scene as loaded (the printed values
    belong to its own data), with its CSV."""
    st.subheader(t("plans.book_title"))
    if scene == base:
        show_table(book_table(check(scene)), f"{scene.id}-book.csv", "csv_book")
    else:
        st.info(t("plans.book_changed"))
