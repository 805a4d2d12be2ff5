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
from collections.abc import Callable, Iterable, Mapping, Sequence

import numpy as np
import pandas as pd
import streamlit as st

from mechanisms import SceneError
from mechanisms.messages import Text, text_of
from mechanisms.reader import key_parts
from mechanisms.sketch import COLUMNS
from ui.i18n import current, message, t
from ui.numbers import Refused, check, literal, refusal, shown
from ui.url import refuse_table, table_refused, table_to_url, url_drop, url_table

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
        return check(value, language)
    except Refused:
        return value


def refused(rows: list[dict], language: str,
            required: Callable[[dict], Iterable[str]] = lambda row: ()) -> list[tuple[int, str, Refused]]:
    """The one rule of every table a person types in: a row left wholly empty is a new row
    not yet filled (left out, not refused); any other row is whole or refused at its cells —
    each number cell holding a text that is not one number, and each of the row's
    ``required`` cells left empty: (row, column, why)."""
    found = []
    for i, row in enumerate(rows):
        if _unfilled(row):
            continue
        needed = set(required(row))  # once a row: asked a cell at a time, it was most of a
        for name, value in row.items():  # builder rerun's checking (bench/pages.py)
            if is_number_column(name) and isinstance(value, str) and value.strip():
                try:
                    check(value, language)  # (one number, within the loader's bounds)
                except Refused as why:
                    found.append((i, name, why))
            elif name in needed and _empty(value):
                found.append((i, name, Refused("empty", "")))
    return found


def _empty(value) -> bool:
    """A cell with nothing in it: blank, or only spaces."""
    return _blank_cell(value) or (isinstance(value, str) and not value.strip())


def _unfilled(row: dict) -> bool:
    """A new row not yet filled: every cell empty (a tick not ticked)."""
    return all(_empty(v) or v is False for v in row.values())


def marks(rows: list[dict], language: str, label: Mapping[str, str],
          required: Callable[[dict], Iterable[str]] = lambda row: ()) -> list[str]:
    """One cell a row for the table's ⚠ column: the refused columns of that row, by name."""
    by_row: dict[int, list[str]] = {}
    for i, name, _ in refused(rows, language, required):
        by_row.setdefault(i, []).append(label[name])
    return [", ".join(by_row.get(i, [])) for i in range(len(rows))]


def _blank_cell(value) -> bool:
    return value is None or value is pd.NA or (isinstance(value, float) and math.isnan(value))


def linked_table(key: str, default: pd.DataFrame, scene: str, *, name: str,
                 rows_fixed: bool = True, column_config: dict | None = None,
                 loader: Callable[[pd.DataFrame], None] | None = None,
                 fields: Mapping[str, str] | None = None) -> pd.DataFrame:
    """The table ``typed_table``'s editor starts from: the link's (ui.url.url_table), or the
    scene's own where the loader refuses the link's (said by the editor, at its cell). A
    page reads it alone where its editor waits for the first chart's paint (ui/firstpaint.py):
    on a fresh visit nothing is typed yet, so the editor would give exactly this."""
    start = url_table(key, default, scene, rows_fixed)
    if loader is not None and start is not default and (
            cell := _loader_cell(loader, start, fields or {})) is not None:
        start = refuse_table(key, default, scene,
                             _at_cell(name, cell, headers(start, column_config)))
    return start


def typed_table(key: str, default: pd.DataFrame, scene: str, numbers: Sequence[str], *,
                name: str, rows_fixed: bool = True, column_config: dict | None = None,
                loader: Callable[[pd.DataFrame], None] | None = None,
                fields: Mapping[str, str] | None = None, **editor) -> pd.DataFrame:
    """An editor of a table of numbers kept in the link (ui.url.url_table): the ``numbers``
    columns typed as text and read by ui.numbers, every row whole or refused by the one
    rule (``refused``: every cell not disabled is needed). A refused cell is named above the
    table ("``name`` · row 2 · m [kg]: type a number") and marked in its row (the ⚠ column);
    the page goes on with the last table that read whole, so no result and no link changes.
    When a cell is refused or mended the editor starts again from exactly what was typed
    (with the marks where they are now), and when the language changes from that last whole
    table, written the new language's way.

    ``loader`` holds a table that reads whole to the rules a scene file is held to (it
    raises the loader's SceneError for the scene the table makes): a refusal is said at its
    cell — ``fields`` maps the loader's field (``mass``, ``radii[1]``) to the column — and
    the table is not taken, so no scene the loader refuses is solved, drawn or written."""
    language = current()
    start = linked_table(key, default, scene, name=name, rows_fixed=rows_fixed,
                         column_config=column_config, loader=loader, fields=fields)
    link_said = st.container()  # a refused link table, said while the table is the scene's own
    memo = st.session_state.get(f"_{key}_typed")
    if memo is None or memo["scene"] != scene:
        memo = {"scene": scene, "language": language, "text": _written(start, numbers, language),
                "good": start, "version": 0, "marks": []}
    elif memo["language"] != language:
        memo = {**memo, "language": language, "text": _written(memo["good"], numbers, language),
                "version": memo["version"] + 1, "marks": []}
    config = {c: st.column_config.TextColumn(c) for c in numbers} | (column_config or {})
    data = marked(memo["text"].copy(), memo["marks"], config)
    place = st.container()
    resets = st.session_state.get(f"_{key}_resets", 0)  # (*As in the book*: a new editor)
    edited = st.data_editor(data, key=f"{key}-{scene}-{language}-{memo['version']}-{resets}",
                            column_config=config, hide_index=True, **editor)
    edited = edited.drop(columns=MARK, errors="ignore").reset_index(drop=True)
    needed = [c for c in edited.columns if c not in set(editor.get("disabled") or ())]
    rows = [dict(zip(edited.columns, values)) for values in edited.itertuples(index=False)]
    problems = refused(rows, language, lambda row: needed)
    headed = headers(edited, config)
    for i, column, why in problems:
        place.error(refusal(f"{name} · {t('table.row', row=i + 1)} · {headed[column]}", why),
                    icon=":material/error:")
    now = marks(rows, language, headed, lambda row: needed)
    if not problems:
        candidate = _read(rows, numbers, language, default)
        cell = _loader_cell(loader, candidate, fields or {}) if loader else None
        if cell is None:
            memo["good"] = candidate
        else:  # the loader's refusal, at its cell (and in the row's ⚠ mark)
            place.error(_at_cell(name, cell, headed), icon=":material/error:")
            now = [headed.get(cell[1], cell[1]) if r == cell[0] else "" for r in range(len(rows))]
    if now != memo["marks"] and (any(now) or any(memo["marks"])):
        memo.update(text=edited, marks=now, version=memo["version"] + 1)
        st.session_state[f"_{key}_typed"] = memo
        st.rerun()  # the editor again from what was typed, the marks where they are now
    st.session_state[f"_{key}_typed"] = memo
    if (text := table_refused(key)) is not None:
        if memo["good"].equals(start):
            said = (t("link.table_refused_why", text=literal(text[0]), why=text[1])
                    if isinstance(text, tuple) else t("link.table_refused", text=literal(text)))
            link_said.warning(said, icon=":material/link_off:")
        else:
            table_refused(key, kept=False)
    table_to_url(key, memo["good"], default)
    return memo["good"]


def headers(table: pd.DataFrame, config: dict | None) -> dict[str, str]:
    """Each column's header as the table shows it (its config's label, else its name)."""
    return {c: ((config or {}).get(c) or {}).get("label") or c for c in table.columns}


def _at_cell(name: str, cell: tuple[int, str, Text | str], headed: Mapping[str, str]) -> str:
    """A loader's refusal said at its cell: "Masses · row 1 · m [kg]: must be >= 0 …"."""
    row, column, rule = cell
    return f"{name} · {t('table.row', row=row + 1)} · {headed.get(column, column)}: {message(rule)}"


def _loader_cell(loader: Callable[[pd.DataFrame], None], table: pd.DataFrame,
                 fields: Mapping[str, str]) -> tuple[int, str, Text | str] | None:
    """Where the loader refuses the scene ``table`` makes: (row, column, why), or None."""
    try:
        loader(table)
    except SceneError as exc:
        said = text_of(exc)
        if not isinstance(said, Text) or said.key != "scene.at":
            return 0, "", said
        parts = key_parts(str(said.values.get("key", "")))  # ("masses", 1, "radii", 0)
        if len(parts) < 2 or not isinstance(parts[1], int):
            return 0, "", said.values["rule"]
        field = next((p for p in parts[2:] if isinstance(p, str)), "")
        index = next((p for p in parts[3:] if isinstance(p, int)), None)
        column = fields.get(f"{field}[{index}]") or fields.get(field, field)
        rule = said.values["rule"]
        if isinstance(rule, Text) and "value" in rule.values and column in table.columns \
                and parts[1] < len(table):  # what was typed, in the column's unit (mm, not m)
            rule = Text(rule.key, **{**rule.values, "value": float(table.iloc[parts[1]][column])})
        return parts[1], column, rule
    return None


def forget_table(key: str) -> None:
    """The table ``key`` back to its scene's own rows at the next run (*As in the book*):
    what was typed, kept and put in the link, all dropped."""
    for name in (f"_{key}_typed", f"_{key}_start", f"_{key}_link_refused"):
        st.session_state.pop(name, None)
    # a new editor: the old one's edits live in the browser, which sends them again
    st.session_state[f"_{key}_resets"] = st.session_state.get(f"_{key}_resets", 0) + 1
    url_drop(key)


def restart_table(key: str, scene: str, table: pd.DataFrame) -> None:
    """The table ``key`` starts again from ``table`` at the next run (a row added by a click
    on a chart): as ``forget_table``, but from these rows, not the scene's own."""
    forget_table(key)
    st.session_state[f"_{key}_start"] = (scene, table)


MARK = "⚠"  # the column that names a row's refused cells
REFUSED_CELL = "background-color: #fde8e8; color: #a4000f; font-weight: 600"


def marked(frame: pd.DataFrame, marks_: list[str], config: dict):
    """The editor's data with a red ⚠ column naming each row's refused cells (``config``
    gets the column), or ``frame`` itself where nothing is refused."""
    if not any(marks_):
        return frame
    frame.insert(0, MARK, marks_)
    config[MARK] = st.column_config.TextColumn(MARK, disabled=True)
    return frame.style.map(lambda v: REFUSED_CELL if v else "", subset=[MARK])


def _written(table: pd.DataFrame, numbers: Sequence[str], language: str) -> pd.DataFrame:
    """A table of numbers as the editor shows it: the ``numbers`` columns as text written
    in ``language`` with every digit."""
    text = table.astype({c: object for c in numbers}).reset_index(drop=True)
    for c in numbers:
        text[c] = [_text(v, language) for v in table[c]]
    return text


def _read(rows: list[dict], numbers: Sequence[str], language: str,
          default: pd.DataFrame) -> pd.DataFrame:
    """The rows of a table that read whole, as numbers; rows left wholly empty left out."""
    kept = [row for row in rows if not _unfilled(row)]
    table = pd.DataFrame([{c: _number(v, language) if c in numbers else v for c, v in row.items()}
                          for row in kept], columns=list(default.columns))
    return table.astype(default.dtypes)


def _number(value, language: str) -> float:
    """A cell of a table of numbers: blank is NaN (the row is left out), text is parsed."""
    if _blank_cell(value) or (isinstance(value, str) and not value.strip()):
        return math.nan
    return check(value, language) if isinstance(value, str) else float(value)
