"""Textbook check: every value a preset quotes from the book, beside the exact value."""

from __future__ import annotations

import pandas as pd
import streamlit as st

from mechanisms import load_preset, preset_ids
from mechanisms.messages import Text, text_of
from reports.textbook import BookRow, check
from solvers.diagnostics import Unsolvable
from ui.book import COUNTED, VERDICTS, book_table, coverage_table, fit_summary, tasks_table
from ui.cache import page_cache
from ui.chapters import page_for
from ui.export import csv_button, dataframe
from ui.i18n import message, t, title_of


@page_cache(st.cache_data(max_entries=4))
def all_checks() -> dict[str, list[BookRow] | Text]:
    """Every preset that quotes the book: its rows, or why it cannot be solved."""
    out: dict[str, list[BookRow] | Text] = {}
    for pid in preset_ids():
        scene = load_preset(pid)
        if scene.book:
            try:
                out[pid] = check(scene)
            except Unsolvable as exc:
                out[pid] = text_of(exc)
    return out


def order(pid: str) -> tuple:
    """By chapter and task: analitika-2.1 sits with chapter 2."""
    number = pid.split("-")[-1]
    return tuple(int(p) for p in number.split(".") if p.isdigit()), pid


st.title(f":material/fact_check: {t('check.title')}")
st.write(t("check.intro"))
checks = all_checks()
everything = [row for rows in checks.values() if isinstance(rows, list) for row in rows]
cols = st.columns(len(COUNTED))
for col, verdict in zip(cols, COUNTED):
    col.metric(t(VERDICTS[verdict]), sum(r.verdict == verdict for r in everything))

st.header(t("check.coverage_title"))
dataframe(coverage_table(checks), hide_index=True)
box = st.expander(t("check.tasks_title"), key="tasks_open", on_change="rerun")
if box.open:  # filled only while open
    with box:
        dataframe(tasks_table(), hide_index=True)

table = []
for pid in sorted(checks, key=order):
    scene = load_preset(pid)
    st.header(f"{pid} — {title_of(scene)}")
    st.page_link(page_for(pid), label=t("check.open"), icon=":material/open_in_new:",
                 query_params={"scene": pid})
    rows = checks[pid]
    if not isinstance(rows, list):
        st.error(message(rows))
        continue
    fit_summary(scene, rows)
    dataframe(book_table(rows), hide_index=True)
    table += [dict(preset=pid, key=r.key, book=r.book, exact=r.exact, verdict=r.verdict,
                   note=r.note) for r in rows]
csv_button(pd.DataFrame(table), "textbook-check.csv", key="csv")
