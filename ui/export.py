"""Downloads: tables as CSV, figures as SVG or PNG (drawn by the browser, no server work)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pandas as pd
import pyarrow as pa
import streamlit as st

from figures.raw import RawFigure
from ui.crank import LIVE, Crank
from ui.i18n import current, decimal_comma, num, t
from ui.plot import plot

Rows = list[dict[str, Any]]  # a table as its rows, each {column: value}
Table = Rows | pd.DataFrame


def csv_button(table: Table | Callable[[], Table], filename: str, key: str,
               label: str | None = None) -> None:
    """The table as CSV, made and written only when the button is pressed (not on every
    rerun): ``table`` may be the function that makes it. ``label``: for a table the page
    does not show (the button's own words say what it holds)."""
    def data() -> bytes:
        made = table() if callable(table) else table
        return pd.DataFrame(made).to_csv(index=False).encode("utf-8")

    st.download_button(label or t("export.csv"), data, filename, mime="text/csv", key=key,
                       on_click="ignore", icon=":material/download:")


def chart(fig: RawFigure, filename: str, key: str, editable: bool = False,
          crank: Crank | None = None, handle: str | None = None, focus: str | None = None):
    """A Plotly chart whose toolbar saves it as SVG (to print) or PNG, and shows it full screen.
    Redrawn in place between reruns (ui.plot), in the figure's own look (figures.raw.house).
    ``editable``: its shapes drag and its paper clicks (ui.plot.plot), read from the result.
    ``crank``: its own φ₂ control (ui.crank); letting go of it sets the page's φ₂ (``at``),
    or the quantity the control moves (``crank.key``). ``handle`` and ``focus``: a shape
    moved by finger and what to scroll to (ui.plot.plot).
    On a Serbian page its numbers have a decimal comma (Plotly's ``separators``)."""
    labels = {"svg": t("export.save_svg"), "png": t("export.save_png"),
              "fullscreen": t("export.fullscreen")}
    if crank is not None:
        labels.update(play=t("fig.play"), pause=t("fig.pause"), choice=t("fig.choice"),
                      unreachable=t(crank.unreachable))
    return plot(fig, key, filename, labels, editable, crank,
                None if crank is None else _turned(crank.key),
                separators=",." if decimal_comma() else None, locale=current(),
                handle=handle, focus=focus)


def _turned(key: str) -> Callable[[float | None, bool | str], None]:
    """What a chart's own control does before the rerun it starts."""
    def turned(value: float | None, asked: bool | str) -> None:
        """The student touched the control or picked one of its choices (None), or let go of
        it at ``value``: the rerun that follows sends the frames (of the choice ``asked``
        names), and takes the quantity ``key`` from the control."""
        st.session_state[LIVE] = asked
        if value is not None:
            st.session_state[key] = value
    return turned


def print_button(svg: Callable[[], str], filename: str, key: str) -> None:
    """A drawing at true scale, as SVG to print at 100 %: ``svg`` draws it when the button
    is pressed (drawing both plans' SVG took 4 ms of every rerun of the plans page)."""
    st.download_button(t("export.print"), lambda: svg().encode("utf-8"), filename,
                       mime="image/svg+xml", key=key, on_click="ignore", icon=":material/print:")


def show_table(table: Table, filename: str, key: str) -> None:
    """A table on the page with its CSV download under it."""
    dataframe(table, hide_index=True)
    csv_button(table, filename, key)


def dataframe(table: Table, **options) -> None:
    """``st.dataframe`` of a table, handed to Streamlit as an Arrow table made column by
    column from its rows. Streamlit's own conversion of a pandas DataFrame cost 2–3 ms a
    table on every rerun, a fifth of it building the DataFrame (docs/performance.md); this
    costs about 0.2 ms.

    In the page's language: on a Serbian page every number is written with a decimal
    comma, as text aligned right like a number. The CSV download keeps the numbers and
    their decimal point."""
    if isinstance(table, pd.DataFrame):
        cells = {name: table[name].tolist() for name in table.columns}
    else:
        names = dict.fromkeys(name for row in table for name in row)
        cells = {name: [row.get(name) for row in table] for name in names}
    serbian = decimal_comma()
    columns = []
    for name, values in cells.items():
        if serbian and values and all(isinstance(v, float) or v is None for v in values):
            values = [_cell(v) for v in values]
            options["column_config"] = {name: st.column_config.Column(alignment="right"),
                                        **options.get("column_config", {})}
        columns.append(_column(values))
    st.dataframe(pa.Table.from_arrays(columns, names=[str(n) for n in cells]), **options)


def _column(values: list) -> pa.Array:
    """One column: its values as they are when Arrow can hold them in one type (numbers,
    text), else each as text; a cell a row left out as "—", a NaN as an empty cell."""
    if None in values and not all(v is None for v in values):
        values = ["—" if v is None else v for v in values]
    if all(isinstance(v, str) for v in values):  # (no NaN to find: 9 µs, where the search took 75)
        return pa.array(values, type=pa.string())
    try:
        return pa.array(values, from_pandas=True)
    except (pa.ArrowInvalid, pa.ArrowTypeError):
        return pa.array([str(v) for v in values])


def _cell(value: float | None) -> str:
    """A float as Serbian writes it; a missing value as "—"."""
    return "—" if value is None or value != value else num(value, 6)
