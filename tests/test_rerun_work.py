"""What a rerun no longer redoes (issues 38 and 70): tables handed to Streamlit as Arrow made
from their rows, page caches applied once, a cache asked once for the same arguments,
frozen figures serialised once."""

from __future__ import annotations

import pandas as pd
import plotly.io as pio
import pytest
from streamlit.testing.v1 import AppTest

from figures.linkage import scatter
from figures.raw import RawFigure
from ui.cache import page_cache, same_call


def shown(rows, language: str = "en") -> pd.DataFrame:
    """``rows`` drawn by ui.export.dataframe on a page in ``language``, read back as shown."""
    def page(rows, language):
        import streamlit as st

        from ui.export import dataframe
        st.session_state["lang"] = language
        dataframe(rows, hide_index=True)

    at = AppTest.from_function(page, args=(rows, language))
    at.run()
    assert not at.exception, [e.message for e in at.exception]
    return at.dataframe[0].value


def test_rows_become_columns_in_order_with_a_dash_where_a_row_leaves_a_cell_out():
    table = shown([{"F_pq": "F_12", "x [N]": "3.5"},
                   {"F_pq": "F_23", "x [N]": "1.25", "h [m]": "0.02"}])
    assert list(table.columns) == ["F_pq", "x [N]", "h [m]"]
    assert table["h [m]"].tolist() == ["—", "0.02"]
    assert table["F_pq"].tolist() == ["F_12", "F_23"]


def test_numbers_stay_numbers_and_a_mixed_column_is_shown_as_text():
    table = shown([{"n": 1, "value": 0.5, "mixed": 2.5}, {"n": 2, "value": 1.5, "mixed": "—"}])
    assert table["n"].tolist() == [1, 2]
    assert table["value"].tolist() == [0.5, 1.5]
    assert table["mixed"].tolist() == ["2.5", "—"]


def test_a_dataframe_is_shown_as_its_rows_are():
    frame = pd.DataFrame({"a": [1.0, 2.0], "b": ["x", "y"]})
    assert shown(frame).equals(shown(frame.to_dict("records")))


def test_a_serbian_table_writes_its_numbers_with_a_decimal_comma():
    table = shown([{"član": 2, "ω [s⁻¹]": 10.5}, {"član": 3, "ω [s⁻¹]": -2.25}], "sr")
    assert table["ω [s⁻¹]"].tolist() == ["10,5", "-2,25"]
    assert table["član"].tolist() == [2, 3]  # whole numbers have no decimal mark to change


def test_a_page_cache_is_applied_once_per_code_and_anew_for_new_code():
    applied = []

    def decorator(func):
        applied.append(func)
        return lambda *args: ("cached", func(*args))

    def define(offset: int):
        @page_cache(decorator)
        def add(x: int) -> int:  # the same code on every call of define, as a page's rerun
            return x + offset
        return add

    first, second = define(1), define(2)
    assert first is second and len(applied) == 1
    assert first(1) == ("cached", 2)  # the first definition's (a page's constants are the same)

    namespace: dict = {}
    exec("def add(x):\n    return x - 1", namespace)  # an edited page: new code
    assert page_cache(decorator)(namespace["add"])(1) == ("cached", 0) and len(applied) == 2
    exec(compile("def add(x):\n    return x - 1", "<string>", "exec"), again := {})
    assert page_cache(decorator)(again["add"]) is page_cache(decorator)(namespace["add"])
    assert len(applied) == 2  # the same page compiled again: the same wrapper, none added


def test_the_same_call_again_is_answered_without_asking_the_cache_and_an_equal_one_asks():
    asked = []

    @same_call
    def solved(scene, tol=1e-9):
        asked.append((scene, tol))
        if scene[0] == "bad":
            raise ValueError("unsolvable")
        return [scene]

    def made(at: str = "30"):  # a new object each time, as each run makes its scene
        return ("four-bar", float(at))

    scene = made()
    first = solved(scene)
    assert solved(scene) is first and len(asked) == 1    # the same object: not asked
    assert solved(made()) == first and len(asked) == 2   # equal, another object: asked
    assert solved(made("31")) != first and len(asked) == 3
    tol = float("1e-6")
    assert solved(scene, tol=tol) and solved(scene, tol) and len(asked) == 5  # other arguments
    bad = ("bad", float("0"))
    for _ in range(2):  # an exception is not kept: asked again, raised again
        with pytest.raises(ValueError):
            solved(bad)
    assert len(asked) == 7


def test_a_frozen_figure_keeps_the_json_it_was_frozen_with():
    fig = RawFigure()
    fig.add_raw([scatter(x=[0, 1], y=[1, 2], mode="lines", name="path")])
    assert fig.json() == pio.to_json(fig, validate=False)
    frozen = fig.freeze().json()
    assert frozen == pio.to_json(fig, validate=False)
    fig.add_raw([scatter(x=[2], y=[3], mode="markers", name="later")])  # (a frozen figure is not
    assert fig.json() == frozen != pio.to_json(fig, validate=False)     # changed: shown as frozen)


def test_no_page_shows_a_bare_expression_so_the_server_compiles_without_magic():
    """The server turns Streamlit's magic off (.streamlit/config.toml: a page compiled five
    times faster); a bare expression in a page would then silently show nothing."""
    import ast
    import tomllib
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    config = tomllib.loads((root / ".streamlit" / "config.toml").read_text(encoding="utf-8"))
    assert config["runner"]["magicEnabled"] is False
    shown = []
    for path in [root / "app.py", *sorted((root / "pages").glob("*.py"))]:
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            body = getattr(node, "body", None)
            for i, statement in enumerate(body if isinstance(body, list) else []):
                docstring = i == 0 and isinstance(getattr(statement, "value", None), ast.Constant)
                if (isinstance(statement, ast.Expr) and not docstring
                        and not isinstance(statement.value, (ast.Call, ast.Await))):
                    shown.append(f"{path.name}:{statement.lineno}")
    assert not shown


def test_every_slider_says_its_first_value_so_streamlit_reads_no_session_state_for_it():
    """A slider without ``value`` makes Streamlit read every key of the session state to
    learn whether it is a range (0.3 ms a slider): every slider of the app's own code says
    its first value, or is made by ``ui.numbers.slider``, which says ``low``."""
    import ast
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    unsaid, seen = [], 0
    for path in [root / "app.py", *root.glob("ui/*.py"), *root.glob("pages/*.py")]:
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                    and node.func.attr == "slider"):
                seen += 1
                if len(node.args) < 4 and not any(k.arg == "value" for k in node.keywords):
                    unsaid.append(f"{path.relative_to(root)}:{node.lineno}")
    assert seen >= 3 and not unsaid, unsaid


def test_a_slider_made_by_the_helper_starts_and_links_as_streamlits_own_would():
    """``ui.numbers.slider`` says ``low`` as the first value: the one Streamlit takes when
    none is given, and the default a bound link leaves out — and a value the session holds
    still wins, moved or not."""
    def page():
        import streamlit as st

        from ui.numbers import slider
        st.session_state["shown"] = (slider("fresh", 2.0, 9.0, key="fresh"),
                                     st.slider("own", 2.0, 9.0, key="own"),
                                     slider("held", 2.0, 9.0, key="held"))

    at = AppTest.from_function(page)
    at.session_state["held"] = 4.5
    at.run()
    assert not at.exception, [e.message for e in at.exception]
    assert at.session_state["shown"] == (2.0, 2.0, 4.5)
    fresh, own = at.slider(key="fresh").proto, at.slider(key="own").proto
    assert list(fresh.default) == list(own.default) == [2.0]  # (the link leaves this out)
    at.slider(key="fresh").set_value(3.0).run()
    assert at.session_state["shown"] == (3.0, 2.0, 4.5)

