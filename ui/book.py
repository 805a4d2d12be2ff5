"""The book-vs-exact table, shared by the textbook check page and the chapter pages."""

from __future__ import annotations

import pandas as pd

from solvers.textbook import BookRow
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
