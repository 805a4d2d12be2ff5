"""One validator of a scene (issue 68): a table on a page becomes a scene only as the loader
would read it from a file. Every editable cell of the rotor's and the gears' tables, given
a negative, a zero, a huge and a text value through the link, is used exactly when the
loader takes the scene it makes and refused in words (the page keeping its own table)
when the loader does not — decided here by the loader itself, on the scene written as the
download writes it. The refusal names the table, the row as numbered and the column as
headed, and a page never holds a scene the loader refuses."""

from __future__ import annotations

import math

import pytest

from mechanisms import SceneError, load_preset
from mechanisms.gears import Mesh
from mechanisms.loader import as_loaded
from mechanisms.rotor import Mass

from .test_pages import linked

BAD = ["-0.5", "0", "1e300", "abc"]


def rotor_rows(scene) -> list[list[str]]:
    return [[f"{m.mass:.10g}", f"{m.radius * 1e3:.10g}", f"{math.degrees(m.angle):.10g}",
             f"{m.x * 1e3:.10g}"] for m in scene.masses]


def rotor_with(scene, rows):
    return scene.with_(masses=tuple(Mass(float(m), float(r) / 1e3, math.radians(float(a)), float(x) / 1e3)
                                    for m, r, a, x in rows))


def gear_rows(scene) -> list[list[str]]:
    return [[str(m.members[0]), str(m.members[1]), f"{m.radii[0]:.10g}", f"{m.radii[1]:.10g}",
             "1" if m.internal else "0"] for m in scene.meshes]


def gears_with(scene, rows):
    def ring(a, b, ra, rb, ticked):
        return (a if ra > rb else b) if ticked else None
    return scene.with_(meshes=tuple(
        Mesh((int(a), int(b)), (float(ra), float(rb)), ring(int(a), int(b), float(ra), float(rb), float(t) != 0), old.bevel)
        for (a, b, ra, rb, t), old in zip(rows, scene.meshes)))


TABLES = {  # page, scene, link key, rows, scene from rows, editable columns and their headers
    "masses": ("pages/rotor_balancing.py", "zbirka-7.1", rotor_rows, rotor_with,
               {0: "m [kg]", 1: "r [mm]", 2: "φ [°]", 3: "x [mm]"}),
    "meshes": ("pages/planetary_gears.py", "zbirka-6.1", gear_rows, gears_with,
               {2: "R_a [m]", 3: "R_b [m]"}),
}


def loader_takes(scene, make, rows) -> bool:
    try:
        values = [[float(v) for v in row] for row in rows]
    except ValueError:
        return False
    if not all(math.isfinite(v) and abs(v) <= 1e9 for row in values for v in row):
        return False
    try:
        as_loaded(make(scene, rows))
    except SceneError:
        return False
    return True


CASES = [(key, column, value) for key, spec in TABLES.items() for column in spec[4] for value in BAD]


@pytest.mark.parametrize("key, column, value", CASES)
def test_a_table_cell_is_used_exactly_when_the_loader_takes_its_scene(key, column, value):
    path, preset, rows_of, make, headers = TABLES[key]
    scene = load_preset(preset)
    rows = rows_of(scene)
    rows[1][column] = value
    text = ";".join(",".join(row) for row in rows)
    at = linked(path, scene=preset, lang="en", **{key: text})
    assert not at.exception
    said = [w.value for w in at.warning if "link's table" in w.value]
    if loader_takes(scene, make, rows):
        assert not said, said
        assert at.query_params[key] == text  # used as given
    else:
        assert said, (key, column, value)
        assert key not in at.query_params  # the page's own table, its link short again
        if value != "abc" and value != "1e300":  # (a number the loader refuses: at its cell)
            assert f"row 2 · {headers[column]}" in said[0], said[0]


def test_a_loader_refusal_maps_to_the_row_and_column_of_the_table():
    """The cell of each loader rule the tables can break, for the editor's own path."""
    import pandas as pd

    from ui.editor_tables import _loader_cell

    scene = load_preset("zbirka-6.1")
    table = pd.DataFrame([[float(v) for v in row] for row in gear_rows(scene)],
                         columns=["a", "b", "R_a [m]", "R_b [m]", "ring"])
    table.loc[2, "R_b [m]"] = 0.0
    cell = _loader_cell(lambda rows: as_loaded(gears_with(scene, rows.to_numpy().tolist())), table,
                        {"radii[0]": "R_a [m]", "radii[1]": "R_b [m]"})
    assert cell is not None and cell[:2] == (2, "R_b [m]")


GIVEN = [(key, column) for key, spec in TABLES.items() for column in spec[4]] + [("meshes", 4)]


@pytest.mark.parametrize("key, column", GIVEN)
def test_book_vs_exact_notices_every_table_cell_that_differs_from_the_book(key, column):
    """Each cell a student can change (the ring included: task 6.1's mesh 3–4 without its
    ring was compared with the book as if the book erred) is named in the book's notice,
    and the book's printed values are not set beside the changed task's."""
    path, preset, rows_of, make, _ = TABLES[key]
    scene = load_preset(preset)
    rows = rows_of(scene)
    rows[0][column] = "0" if column == 4 else f"{float(rows[0][column]) * 1.5 + 1:.10g}"
    at = linked(path, scene=preset, lang="en", **{key: ";".join(",".join(r) for r in rows)})
    assert not at.exception
    notice = [i.value for i in at.info if "differs:" in i.value]
    assert notice and "the book's task" in notice[0], [i.value for i in at.info]
    if column == 4:
        assert "a ring in mesh" in notice[0]
