"""Tables typed in ``st.data_editor``: the builder's (a frame with one dtype a column in,
plain rows, blank cells None, out) and the small tables of numbers on the gear and rotor
pages (``typed_table``).

A number cell is a *text* cell read by the app's parser (ui/numbers.py), not the editor's
number cell: that one reads what is typed in the browser's language, so "0,35" became 35 on
a Serbian page in an English browser. In, a number is written the page's way (0,35 in
Serbian) with every digit it holds; out, the text is read back (0,35 and 0.35 alike on a
Serbian page). A text that is not one number stays in its row as typed, so that the page
refuses it by name and the student can mend it (``refused``).

Built column by column: pandas' conversions of whole frames (``to_numeric`` per column in,
``astype(object).where(...).to_dict`` out) cost 3–5 ms a table on every rerun of the
builder, where these take 0.4–0.5 ms (measured on the four-bar template's members).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np
import pandas as pd
import streamlit as st

from mechanisms.sketch import COLUMNS
from ui.i18n import current, t
from ui.numbers import Refused, literal, parse, refusal, shown
from ui.url import table_refused, table_to_url, url_table

TEXT_COLUMNS = {"point", "label", "first", "second", "through", "type", "form", "side"}
WHOLE_COLUMNS = {"member", "p", "q"}  # member numbers: the editor's own whole-number cells
TICK_COLUMNS = {"follows_member"}


def is_number_column(name: str) -> bool:
    return name not in TEXT_COLUMNS | WHOLE_COLUMNS | TICK_COLUMNS


def frame_of(table: str, rows: list[dict], language: str) -> pd.DataFrame:
    """The editor's input: number cells as text written in ``language`` (a text kept as
    typed where it was refused), member numbers as floats (blank or not a number: NaN, so
    the loader names what is wrong), ticks as bools (blank: False), text as objects (pandas
    3 would infer its own string dtype)."""
    def column_of(name: str):
        values = [row.get(name) for row in rows]
        if name in TICK_COLUMNS:
            return np.array([not _blank_cell(v) and bool(v) for v in values], dtype=bool)
        if name in TEXT_COLUMNS:
            return pd.Series(values, dtype=object)
        if name in WHOLE_COLUMNS:
            return np.array([_float(v) for v in values], dtype=float)
        return pd.Series([_text(v, language) for v in values], dtype=object)

    return pd.DataFrame({name: column_of(name) for name in COLUMNS[table]})


def _text(value, language: str) -> str | None:
    if _blank_cell(value):
        return None
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return shown(float(value), language)
    return str(value)


def _float(value) -> float:
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def rows_of(frame: pd.DataFrame, language: str) -> list[dict]:
    """The editor's result as rows of plain values, blank cells None, number cells read in
    ``language`` (a text that is not one number kept as typed)."""
    columns = {name: [_cell(name, v, language) for v in frame[name].tolist()]
               for name in frame.columns}
    return [dict(zip(columns, values)) for values in zip(*columns.values())]


def _cell(name: str, value, language: str):
    if _blank_cell(value):
        return None
    if not is_number_column(name) or not isinstance(value, str):
        return value
    if not value.strip():
        return None
    try:
        return parse(value, language)
    except Refused:
        return value


def refused(rows: list[dict], language: str) -> list[tuple[int, str, Refused]]:
    """The number cells that hold a text which is not one number: (row, column, why)."""
    found = []
    for i, row in enumerate(rows):
        for name, value in row.items():
            if is_number_column(name) and isinstance(value, str):
                try:
                    parse(value, language)
                except Refused as why:
                    found.append((i, name, why))
    return found


def marks(rows: list[dict], language: str, label: Mapping[str, str]) -> list[str]:
    """One cell a row for the table's ⚠ column: the refused columns of that row, by name."""
    by_row: dict[int, list[str]] = {}
    for i, name, _ in refused(rows, language):
        by_row.setdefault(i, []).append(label[name])
    return [", ".join(by_row.get(i, [])) for i in range(len(rows))]


def _blank_cell(value) -> bool:
    return value is None or value is pd.NA or (isinstance(value, float) and math.isnan(value))


def typed_table(key: str, default: pd.DataFrame, scene: str, numbers: Sequence[str], *,
                rows_fixed: bool = True, column_config: dict | None = None,
                **editor) -> pd.DataFrame:
    """An editor of a table of numbers kept in the link (ui.url.url_table): the ``numbers``
    columns typed as text and read by ui.numbers. A cell that is not one number is named
    above the table and keeps its text; the page goes on with the last table that read
    whole. The editor starts again from that table when the language changes, so that its
    cells are written the new language's way and no edit is lost."""
    language = current()
    start = url_table(key, default, scene, rows_fixed)
    if (text := table_refused(key)) is not None:
        st.warning(t("link.table_refused", text=literal(text)), icon=":material/link_off:")
    memo = st.session_state.get(f"_{key}_typed")
    if memo is None or memo["scene"] != scene:
        memo = {"scene": scene, "language": language, "start": start, "good": start}
    elif memo["language"] != language:
        memo = {**memo, "language": language, "start": memo["good"]}
    text = memo["start"].astype({c: object for c in numbers})
    for c in numbers:
        text[c] = [_text(v, language) for v in memo["start"][c]]
    place = st.container()
    config = {c: st.column_config.TextColumn(c) for c in numbers} | (column_config or {})
    edited = st.data_editor(text, key=f"{key}-{scene}-{language}", column_config=config, **editor)
    table, problems = edited.copy(), []
    for c in numbers:
        values = []
        for i, v in enumerate(edited[c].tolist()):
            try:
                values.append(_number(v, language))
            except Refused as why:
                problems.append(refusal(f"{t('table.row', row=i + 1)} · {c}", why))
                values.append(math.nan)
        table[c] = np.array(values, dtype=float)
    for said in problems:
        place.error(said, icon=":material/error:")
    if not problems:
        memo["good"] = table
    st.session_state[f"_{key}_typed"] = memo
    table_to_url(key, memo["good"], default)
    return memo["good"]


def _number(value, language: str) -> float:
    """A cell of a table of numbers: blank is NaN (the row is left out), text is parsed."""
    if _blank_cell(value) or (isinstance(value, str) and not value.strip()):
        return math.nan
    return parse(value, language) if isinstance(value, str) else float(value)
