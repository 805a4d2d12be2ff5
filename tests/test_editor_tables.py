"""The builder's tables in and out of the data editor (ui/editor_tables.py): number cells
are text written and read the page's way, so a round trip changes no number and a text that
is not one number is kept, to be refused by name."""

import math

import pandas as pd
import pytest

from mechanisms.sketch import COLUMNS, TABLES, tables, template, template_ids
from ui.editor_tables import frame_of, is_number_column, marks, refused, rows_of
from ui.i18n import LANGUAGES

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
