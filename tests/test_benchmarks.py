"""Pages quote their benchmark rows from docs/performance.md (ui/benchmarks.py)."""

import re

import pytest

from ui.benchmarks import DOC, parse

from .test_pages import page

SAMPLE = """prose
<!-- pages table -->
Measured 2026-01-02 on x86_64, Python 3.11.7, median of 12 runs:

| page | rerun, ms | figures sent, kB |
|---|---:|---:|
| trajectories | 41 | 25 |
| velocity\\|plans | 48 | 27 |
<!-- pages table -->
more prose"""


def test_a_marked_table_is_read_with_its_caption_and_escaped_bars():
    found = parse(SAMPLE, "pages")
    assert found.caption.startswith("Measured 2026-01-02")
    assert list(found.table.columns) == ["page", "rerun, ms", "figures sent, kB"]
    assert list(found.table["page"]) == ["trajectories", "velocity|plans"]
    assert found.table.iloc[0, 1] == "41"


def test_a_missing_or_unclosed_table_is_none():
    assert parse(SAMPLE, "browser") is None
    assert parse(SAMPLE.rsplit("<!-- pages table -->", 1)[0], "pages") is None


def documented(name: str, page_name: str) -> str:
    """The page's number in a benchmark table, read from the document independently."""
    block = DOC.read_text(encoding="utf-8").split(f"<!-- {name} table -->")[1]
    return re.search(rf"^\| {page_name} \| ([^|]+) \|", block, re.M)[1].strip()


@pytest.mark.parametrize("path, name", [("pages/trajectories.py", "trajectories"),
                                        ("pages/planetary_gears.py", "planetary_gears")])
def test_each_page_quotes_its_own_rerun_time(path, name):
    at = page(path, lang="en", bench=True)  # the panel open
    assert not at.exception
    shown = {m.label: m.value for m in at.metric}
    assert shown["Rerun on the server"] == f"{documented('pages', name)} ms"


def test_a_closed_panel_computes_nothing():
    at = page("pages/planetary_gears.py", lang="en")
    assert "Rerun on the server" not in [m.label for m in at.metric]


def test_the_kinetostatics_page_shows_its_scenes_rows_in_serbian():
    at = page("pages/kinetostatics.py", lang="sr", bench=True)
    assert not at.exception
    table = next(d.value for d in at.dataframe if "položaja" in d.value.columns)
    assert set(table.iloc[:, 0]) == {"predavanja-kinetostatika"}
    assert list(table.iloc[:, 1]) == ["12", "72", "360", "3600"]
    assert all("," in cell and "." not in cell for cell in table.iloc[:, 2])  # decimal comma


@pytest.mark.parametrize("path, scene, column", [
    ("pages/assur_groups.py", "triad-full-turn", "time [ms] (360 positions)"),
    ("pages/velocity_plans.py", "zbirka-2.1", "values read")])
def test_a_chapter_page_quotes_its_own_accuracy_rows(path, scene, column):
    """The Assur page quotes Newton's tolerance rows of its scene, the plans page the
    graphical method's row at the book's scales."""
    at = page(path, lang="en", scene=scene, bench=True)
    assert not at.exception
    (table,) = [d.value for d in at.dataframe if column in d.value.columns]
    assert set(table["scene"]) == {scene}
