"""The tables in and out of the data editor (ui/editor_tables.py): number cells are text
written and read the page's way, so a round trip changes no number and a text that is not
one number is kept, to be refused by name; every row is whole or refused at its cells."""

import math
import tomllib

import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechanisms import load_preset, preset_ids
from mechanisms.schema import Scene
from mechanisms.sketch import COLUMNS, TABLES, required, tables, template, template_ids
from mechanisms.writer import to_toml
from ui.editor_tables import frame_of, is_number_column, marks, refused, rows_of
from ui.i18n import LANGUAGES
from ui.numbers import parse

ODD_MEMBER = {"member": "x", "label": None, "first": "A", "second": None, "length": "abc",
              "mass": None, "centre_along": 2, "centre_left": None, "gyration": None}


@pytest.mark.parametrize("language", LANGUAGES)
@pytest.mark.parametrize("name", template_ids())
def test_every_template_table_goes_in_and_out_unchanged(name, language):
    rows = tables(template(name))
    for table in TABLES:
        frame = frame_of(table, rows[table], language)
        assert list(frame.columns) == list(COLUMNS[table])
        back = rows_of(frame, language)
        want = [{k: (float(v) if is_number_column(k) and v is not None else v) for k, v in r.items()}
                for r in rows[table]]
        assert back == [{k: (None if v is None else v) for k, v in r.items()} for r in want]


def test_serbian_cells_show_a_decimal_comma_and_read_both_signs():
    rows = [{"point": "A", "x": 0.35, "y": -1.25}]
    frame = frame_of("frame", rows, "sr")
    assert frame["x"][0] == "0,35" and frame["y"][0] == "-1,25"
    frame.loc[0, "x"], frame.loc[0, "y"] = "10,5", "0.4"
    assert rows_of(frame, "sr") == [{"point": "A", "x": 10.5, "y": 0.4}]
    assert frame_of("frame", rows, "en")["x"][0] == "0.35"


def test_blank_and_wrong_cells():
    frame = frame_of("members", [ODD_MEMBER], "en")
    assert math.isnan(frame["member"][0]) and frame["length"][0] == "abc"  # kept as typed
    assert frame["centre_along"][0] == "2"
    (row,) = rows_of(frame, "en")
    assert row["length"] == "abc" and row["second"] is None and row["first"] == "A"
    assert row["centre_along"] == 2.0
    edited = pd.DataFrame({"member": pd.array([1, None], dtype="Int64"), "label": [None, "B"]})
    assert rows_of(edited, "en") == [{"member": 1, "label": None},
                                     {"member": None, "label": "B"}]  # pd.NA is blank too


@pytest.mark.parametrize("text", ["0,3,5", "abc", "1.2.3"])
def test_a_refused_cell_is_found_and_marked_in_its_row(text):
    rows = [{"point": "A", "x": 0.1, "y": 0.0}, {"point": "B", "x": text, "y": "0,2"}]
    rows = rows_of(frame_of("frame", rows, "sr"), "sr")
    assert rows[1]["x"] == text and rows[1]["y"] == 0.2
    ((row, column, why),) = refused(rows, "sr")
    assert (row, column, why.text) == (1, "x", text)
    assert marks(rows, "sr", {"x": "x [m]", "y": "y [m]"}) == ["", "x [m]"]


def test_a_comma_in_an_english_table_is_refused_not_read():
    rows = rows_of(pd.DataFrame({"point": ["A"], "x": ["0,35"], "y": ["0"]}), "en")
    assert rows[0]["x"] == "0,35"
    assert refused(rows, "en")[0][2].reason == "comma"


def test_ticks_blank_is_false():
    rows = [{"follows_member": None}, {"follows_member": float("nan")}, {"follows_member": True}]
    assert frame_of("forces", rows, "en")["follows_member"].tolist() == [False, False, True]


def test_a_point_typed_in_one_form_makes_its_checking_cells_stale():
    """The builder redraws the points' table when a point is typed as two distances while
    its along/left cells still say where it was (ui.builder.stale_forms), and not for a row
    being typed (it would be lost)."""
    from mechanisms.sketch import document, driver_values
    from ui.builder import stale_forms

    doc = template("four-bar")
    rows = tables(doc)
    assert not stale_forms(rows["extra"], doc)  # as the tables show it: nothing stale
    row = dict(rows["extra"][0], form="distances", d1=0.2, d2=0.3, side="left")
    edited = {**rows, "extra": [row]}
    typed = document(edited, driver_values(doc), doc)
    assert stale_forms([row], typed)  # along and left still say the old place
    assert not stale_forms([row, {"member": None, "point": None}], typed)  # a row being typed


def test_a_row_is_whole_or_refused_at_its_empty_needed_cell_and_an_empty_row_is_left_out():
    """The one rule (issue 61): clearing task 7.1's first mass once dropped the whole row
    and silently changed the correction; a cleared frame coordinate or member length reached
    the loader as an internal key."""
    rows = [{"m": "0,2", "r": None, "x": "1"}, {"m": None, "r": " ", "x": None},
            {"m": "abc", "r": "2", "x": "  "}]
    found = [(i, c, why.reason) for i, c, why in refused(rows, "sr", lambda row: ("m", "r", "x"))]
    assert found == [(0, "r", "empty"), (2, "m", "not_number"), (2, "x", "empty")]
    frame = [{"point": "A", "x": None, "y": 0.0}]
    assert [(c, w.reason) for _, c, w in refused(frame, "en", lambda row: required("frame", row))] \
        == [("x", "empty")]
    member = {"member": 3, "label": None, "first": "B", "second": "C", "length": None,
              "mass": None, "centre_along": None, "centre_left": None, "gyration": None}
    assert [c for _, c, _ in refused([member], "en", lambda row: required("members", row))] == ["length"]
    one_point = {**member, "second": None}
    assert refused([one_point], "en", lambda row: required("members", row)) == []


CELL = st.one_of(st.none(), st.just(""), st.just("  "), st.text(max_size=8),
                 st.floats(allow_nan=True, allow_infinity=True).map(str),
                 st.floats(allow_nan=False, allow_infinity=False).map(lambda v: f"{v:.6g}".replace(".", ",")))


@given(st.lists(st.fixed_dictionaries({"a": CELL, "b": CELL, "c": CELL}), max_size=6),
       st.sampled_from(["sr", "en"]))
@settings(max_examples=300, deadline=None)
def test_any_table_of_text_cells_reads_whole_or_names_each_refused_cell(rows, language):
    """Never raises; a table with no refusal reads every kept row as finite numbers, and a
    refused one names a row and column that hold what it says."""
    found = refused(rows, language, lambda row: ("a", "b", "c"))
    for i, column, why in found:
        cell = rows[i][column]
        assert (why.reason == "empty" and (cell is None or not cell.strip())) or cell == why.text
    if not found:
        for row in rows:
            cells = [row[c] for c in "abc"]
            if all(v is None or not v.strip() for v in cells):
                continue  # a new row not yet filled: left out
            assert all(math.isfinite(parse(v, language)) for v in cells)


def test_every_template_and_task_reads_whole_under_the_rule():
    """The rule asks no cell a real mechanism leaves empty (a one-point member's length, a
    revolute pair's line)."""
    docs = [template(name) for name in template_ids()]
    docs += [tomllib.loads(to_toml(scene)) for scene in map(load_preset, preset_ids())
             if isinstance(scene, Scene)]
    for doc in docs:
        rows = tables(doc)
        for name in TABLES:
            read = rows_of(frame_of(name, rows[name], "en"), "en")
            assert refused(read, "en", lambda row, name=name: required(name, row)) == [], name
