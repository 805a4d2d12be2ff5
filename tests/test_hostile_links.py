"""No link shows a traceback (issues 60 and 61): every page opened with hostile values in
every parameter its own link carries — found by opening the page and reading the link it
writes, not from a list — and in the parameters any page reads (a scene, a shared scene,
a variant code, a language, a class and student, a table). Each value is taken, or refused
in words with the page's own value kept; none raises (the suite lets exceptions through
the error boundary, so an exception element here is a bug)."""

from __future__ import annotations

import pytest

from streamlit.testing.v1 import AppTest

from .test_pages import ROOT

PAGES = ["app.py", "pages/trajectories.py", "pages/velocity_plans.py", "pages/assur_groups.py",
         "pages/kinetostatics.py", "pages/planetary_gears.py", "pages/rotor_balancing.py",
         "pages/builder.py", "pages/synthesis.py", "pages/variants.py", "pages/textbook_check.py",
         "pages/class.py"]
VALUES = ["abc", "nan", "-inf", "1e400", "", "0", "-1", "1,,2", "1;2;x", "'\"<b>&%00", "９",
          "1" * 300]
EVERY_PAGE = [{"scene": "../../etc/passwd"}, {"scene": "zbirka-9.99"}, {"s": "%%%%"},
              {"s": "A" * 4000}, {"s": "eJzLSM3JyQcABiwCFQ"}, {"v": "3.1-S42-ZZZZZ"},
              {"v": "x" * 300}, {"lang": "xx"}, {"class": "ZZZZZZ", "student": "nope"},
              {"join": "<script>"}, {"class": "ABC", "key": "x"}, {"present": "maybe"},
              {"masses": "1,,2;3"}, {"meshes": "nan,1;2"}, {"masses": "inf,1,2,3"}]


def _opened(path: str, query: dict[str, str]):
    """The page opened fresh from a link with ``query`` (a first run, as a phone opens it),
    through app.py (its language, its pages)."""
    at = AppTest.from_file(str(ROOT / "app.py"), default_timeout=60)
    at.query_params.update(query)
    at.run()
    if path != "app.py":
        at.switch_page(path).run()
    return at


def _own_link(path: str) -> list[str]:
    """The parameters a page writes into its own link when it is opened."""
    at = _opened(path, {})
    assert not at.exception, path
    return list(at.query_params)


@pytest.mark.sweep
@pytest.mark.parametrize("path", PAGES)
def test_every_parameter_of_a_page_s_own_link_with_hostile_values(path):
    keys = _own_link(path)
    for value in VALUES:
        at = _opened(path, {key: value for key in keys})
        assert not at.exception, (path, value, at.exception[0].message if at.exception else "")


@pytest.mark.sweep
@pytest.mark.parametrize("path", PAGES)
def test_the_parameters_any_page_reads_with_hostile_values(path):
    for query in EVERY_PAGE:
        at = _opened(path, query)
        assert not at.exception, (path, query, at.exception[0].message if at.exception else "")


def test_a_refused_link_value_is_said_at_its_field_and_the_page_s_own_is_used():
    """/velocity_plans?Uv=abc once showed a traceback; ?Uv=-1 was taken past the field's
    minimum; ?masses=inf,… crashed the rotor page."""
    own = _opened("pages/velocity_plans.py", {}).text_input(key="Uv").value
    for value in ("abc", "-1", "1e400"):
        at = _opened("pages/velocity_plans.py", {"Uv": value})
        said = [w.value for w in at.warning if "U_v" in w.value]
        assert len(said) == 1 and value in said[0], (value, [w.value for w in at.warning])
        assert at.text_input(key="Uv").value == own  # the task's own U_v
    at = _opened("pages/rotor_balancing.py", {"masses": "inf,1,2,3"})
    assert any("inf,1,2,3" in w.value for w in at.warning) and not at.exception


def test_the_crawl_reaches_every_page_s_own_parameters():
    keys = {path: set(_own_link(path)) for path in ("pages/velocity_plans.py",
                                                    "pages/rotor_balancing.py")}
    assert {"scene", "UL", "Uv", "Ua"} <= keys["pages/velocity_plans.py"]
    assert {"xI", "valueI", "omega"} <= keys["pages/rotor_balancing.py"]
