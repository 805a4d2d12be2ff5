"""The builder's tables as ``st.data_editor`` takes and gives them: a frame with one dtype a
column in, plain rows (blank cells None) out.

Built column by column: pandas' conversions of whole frames (``to_numeric`` per column in,
``astype(object).where(...).to_dict`` out) cost 3–5 ms a table on every rerun of the
builder, where these take 0.4–0.5 ms (measured on the four-bar template's members).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from mechanisms.sketch import COLUMNS

TEXT_COLUMNS = {"point", "label", "first", "second", "through", "type", "form", "side"}


def frame_of(table: str, rows: list[dict]) -> pd.DataFrame:
    """The editor's input: numbers as floats (blank or not a number: NaN, so the loader
    names what is wrong), ticks as bools (blank: False), text as objects (as the editor
    has always been given it; pandas 3 would infer its own string dtype)."""
    def column_of(name: str):
        values = [row.get(name) for row in rows]
        if name == "follows_member":
            return np.array([not _blank_cell(v) and bool(v) for v in values], dtype=bool)
        if name in TEXT_COLUMNS:
            return pd.Series(values, dtype=object)
        return np.array([_float(v) for v in values], dtype=float)

    return pd.DataFrame({name: column_of(name) for name in COLUMNS[table]})


def _float(value) -> float:
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def rows_of(frame: pd.DataFrame) -> list[dict]:
    """The editor's result as rows of plain values, blank cells None."""
    columns = {name: [None if _blank_cell(v) else v for v in frame[name].tolist()]
               for name in frame.columns}
    return [dict(zip(columns, values)) for values in zip(*columns.values())]


def _blank_cell(value) -> bool:
    return value is None or value is pd.NA or (isinstance(value, float) and math.isnan(value))
