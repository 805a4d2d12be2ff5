"""Downloads: tables as CSV, figures as SVG or PNG (drawn by the browser, no server work)."""

from __future__ import annotations

import pandas as pd
import streamlit as st

from figures.raw import RawFigure
from ui.crank import LIVE, Crank
from ui.i18n import current, num, t
from ui.plot import plot


def csv_button(table: pd.DataFrame, filename: str, key: str) -> None:
    """The table as CSV, written only when the button is pressed (not on every rerun)."""
    st.download_button(t("export.csv"), lambda: table.to_csv(index=False).encode("utf-8"),
                       filename, mime="text/csv", key=key, on_click="ignore",
                       icon=":material/download:")


def chart(fig: RawFigure, filename: str, key: str, editable: bool = False,
          crank: Crank | None = None):
    """A Plotly chart whose toolbar saves it as SVG (to print) or PNG, and shows it full screen.
    Redrawn in place between reruns (ui.plot), in the figure's own look (figures.raw.HOUSE).
    ``editable``: its shapes drag and its paper clicks (ui.plot.plot), read from the result.
    ``crank``: its own φ₂ control (ui.crank); letting go of it sets the page's φ₂ (``at``).
    On a Serbian page its numbers have a decimal comma (Plotly's ``separators``)."""
    labels = {"svg": t("export.save_svg"), "png": t("export.save_png"),
              "fullscreen": t("export.fullscreen")}
    if crank is not None:
        labels.update(play=t("fig.play"), pause=t("fig.pause"), unreachable=t("fig.unreachable"))
    return plot(fig, key, filename, labels, editable, crank, None if crank is None else _turned,
                separators=",." if current().startswith("sr") else None)


def _turned(degrees: float | None) -> None:
    """The student touched a chart's φ₂ control (None) or let go of it at ``degrees``: the
    rerun that follows sends the frames, and takes φ₂ from the control."""
    st.session_state[LIVE] = True
    if degrees is not None:
        st.session_state["at"] = degrees


def print_button(svg: str, filename: str, key: str) -> None:
    """A drawing at true scale, as SVG to print at 100 %."""
    st.download_button(t("export.print"), svg.encode("utf-8"), filename, mime="image/svg+xml",
                       key=key, on_click="ignore", icon=":material/print:")


def show_table(table: pd.DataFrame, filename: str, key: str) -> None:
    """A table on the page with its CSV download under it."""
    dataframe(table, hide_index=True)
    csv_button(table, filename, key)


def dataframe(table: pd.DataFrame, **options) -> None:
    """``st.dataframe`` in the page's language: on a Serbian page every number is written
    with a decimal comma, as text aligned right like a number (a pandas Styler would keep
    the values numbers but costs 7 ms a table on every rerun, ten times this). The CSV
    download keeps the numbers and their decimal point."""
    if current().startswith("sr"):
        numbers = [c for c in table.columns if pd.api.types.is_float_dtype(table[c])]
        options["column_config"] = {**{c: st.column_config.Column(alignment="right")
                                       for c in numbers}, **options.get("column_config", {})}
        table = table.map(_cell)
    st.dataframe(table, **options)


def _cell(value):
    """A float as Serbian writes it; anything else as it is."""
    if isinstance(value, float):
        return "—" if value != value else num(value, 6)
    return value
