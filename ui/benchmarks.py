"""Each page's rows of the benchmarks, quoted from docs/performance.md.

The benchmarks (``bench/*.py --write``) write their tables there between marker comments,
so that file is the one record of what was measured; a page reads its own rows back
instead of repeating the measurements on every rerun.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import pandas as pd
import streamlit as st

from ui.export import show_table
from ui.i18n import decimals, t

DOC = Path(__file__).resolve().parents[1] / "docs/performance.md"
# a chapter's benchmark: its title and its columns ("a; b; c") in the page's language
CHAPTER_TABLES = {"kinematics": ("bench.table_kinematics", "bench.cols_kinematics"),
                  "kinetostatics": ("bench.table_kinetostatics", "bench.cols_kinetostatics"),
                  "peers": ("bench.table_peers", "bench.cols_peers"),
                  "differences": ("bench.table_differences", "bench.cols_differences"),
                  "newton": ("bench.table_newton", "bench.cols_newton"),
                  "graphical": ("bench.table_graphical", "bench.cols_graphical")}
CAPTION = re.compile(r"Measured (\S+) on (\S+), Python ([^,:]+)(?:, median of (\d+) runs)?")


@dataclass(frozen=True)
class Measured:
    """One benchmark table: when and how it was measured, and its rows."""
    caption: str  # "Measured 2026-11-22 on x86_64, Python 3.11.7, median of 12 runs:"
    table: pd.DataFrame


def parse(text: str, name: str) -> Measured | None:
    """The table between the two ``<!-- {name} table -->`` markers, None when absent."""
    parts = text.split(f"<!-- {name} table -->")
    if len(parts) < 3:
        return None
    lines = [line.strip() for line in parts[1].strip().splitlines()]
    caption = next((line for line in lines if line.startswith("Measured")), "")
    rows = [[cell.strip().replace("\\|", "|") for cell in re.split(r"(?<!\\)\|", line)[1:-1]]
            for line in lines if line.startswith("|")]
    if len(rows) < 2:
        return None
    header = rows[0]
    body = [r for r in rows[2:] if len(r) == len(header) and r != header  # a second table's
            and not all(set(c) <= set("-:") for c in r)]                  # header is no row
    return Measured(caption, pd.DataFrame(body, columns=header))


@st.cache_resource(max_entries=8, show_spinner=False)  # shared and never mutated: no copy per rerun
def _read(name: str, stamp: float) -> Measured | None:
    """``stamp`` (the file's mtime) is only part of the cache key: a new file, a new read."""
    return parse(DOC.read_text(encoding="utf-8"), name)


def measured(name: str) -> Measured | None:
    """A benchmark's table as last written (read again when the file changes)."""
    try:
        return _read(name, DOC.stat().st_mtime)
    except OSError:
        return None


# what a peer's call computes, as the benchmark writes it in a row's name
ROW_WORDS = {"(positions)": "bench.row_positions", "(pos + vel + acc)": "bench.row_all"}


def _words(cell: str) -> str:
    for english, key in ROW_WORDS.items():
        cell = cell.replace(english, t(key))
    return cell


def page_row(name: str, page: str) -> list[str] | None:
    """A page's row of the ``pages`` or ``browser`` benchmark (its cells after the name)."""
    found = measured(name)
    if found is None:
        return None
    own = found.table[found.table.iloc[:, 0] == page]
    return list(own.iloc[0, 1:]) if len(own) else None


def speed_panel(page: str, scene_id: str, chapter_tables: tuple[str, ...] = ()) -> None:
    """What the benchmarks measured for this page (its rerun on the server, slider → figure
    in a browser) and for this scene in the chapter's own benchmarks. Filled only while
    open: a closed panel costs the rerun nothing."""
    panel = st.expander(t("bench.title"), key="bench", on_change="rerun")
    if not panel.open:
        return
    with panel:
        st.caption(t("bench.hint"))
        cols = st.columns(3)
        server, browser = page_row("pages", page), page_row("browser", page)
        if server:
            cols[0].metric(t("bench.rerun"), f"{decimals(server[0])} ms")
            cols[1].metric(t("bench.sent"), f"{decimals(server[1])} kB")
        if browser:
            cols[2].metric(t("bench.browser"), f"{decimals(browser[0])} ms")
        for name in chapter_tables:
            found = measured(name)
            if found is None:
                continue
            title, columns = CHAPTER_TABLES[name]
            table = found.table
            if table.columns[0] == "scene":  # a table per scene: this scene's rows if measured
                own = table[table["scene"] == scene_id]
                if len(own) == 0:
                    st.caption(t("bench.other_scenes"))
                table = own if len(own) else table
            # decimal comma in the numbers (not in the ids of the first column), and the
            # first column's words in the page's language
            table = pd.concat([table.iloc[:, :1].map(_words), table.iloc[:, 1:].map(decimals)],
                              axis=1)
            names = t(columns).split("; ")
            st.markdown(f"**{t(title)}**")
            show_table(table.set_axis(names if len(names) == table.shape[1] else table.columns,
                                      axis=1), f"benchmark-{name}.csv", f"csv_bench_{name}")
            when = CAPTION.match(found.caption)
            if when:
                st.caption(t("bench.when", date=when[1], machine=when[2], python=when[3])
                           + (" " + t("bench.runs", runs=when[4]) if when[4] else ""))
