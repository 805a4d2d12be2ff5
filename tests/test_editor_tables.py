"""The builder's tables in and out of the data editor (ui/editor_tables.py), checked against
pandas' whole-frame conversions that they replaced."""

import math

import pandas as pd
import pytest

from mechanisms.sketch import COLUMNS, TABLES, tables, template, template_ids
from ui.editor_tables import TEXT_COLUMNS, frame_of, rows_of

ODD_MEMBER = {"member": "x", "label": None, "first": "A", "second": None, "length": "abc",
              "mass": None, "centre_along": 2, "centre_left": None, "gyration": None}


def pandas_frame(table: str, rows: list[dict]) -> pd.DataFrame:
    frame = pd.DataFrame(rows, columns=list(COLUMNS[table]))
    for name in COLUMNS[table]:
        if name == "follows_member":
            frame[name] = frame[name].fillna(False).astype(bool)
        elif name in TEXT_COLUMNS:
            frame[name] = frame[name].astype(object)
        else:
            frame[name] = pd.to_numeric(frame[name], errors="coerce").astype(float)
    return frame


def pandas_rows(frame: pd.DataFrame) -> list[dict]:
    return frame.astype(object).where(frame.notna(), None).to_dict("records")


@pytest.mark.parametrize("name", template_ids())
def test_every_template_table_goes_in_and_out_as_pandas_would(name):
    rows = tables(template(name))
    rows["members"] = rows["members"] + [ODD_MEMBER]
    for table in TABLES:
        ours, theirs = frame_of(table, rows[table]), pandas_frame(table, rows[table])
        assert list(ours.columns) == list(COLUMNS[table])
        assert list(ours.dtypes) == list(theirs.dtypes)
        back = rows_of(ours)
        assert back == pandas_rows(theirs)
        assert [type(v) for r in back for v in r.values()] == \
            [type(v) for r in pandas_rows(theirs) for v in r.values()]


def test_blank_and_wrong_cells():
    frame = frame_of("members", [ODD_MEMBER])
    assert math.isnan(frame["member"][0]) and math.isnan(frame["length"][0])  # not numbers
    assert frame["centre_along"][0] == 2.0
    (row,) = rows_of(frame)
    assert row["length"] is None and row["second"] is None and row["first"] == "A"
    edited = pd.DataFrame({"a": pd.array([1, None], dtype="Int64"), "b": [None, "B"]})
    assert rows_of(edited) == [{"a": 1, "b": None}, {"a": None, "b": "B"}]  # pd.NA is blank too


def test_ticks_blank_is_false():
    rows = [{"follows_member": None}, {"follows_member": float("nan")}, {"follows_member": True}]
    assert frame_of("forces", rows)["follows_member"].tolist() == [False, False, True]
