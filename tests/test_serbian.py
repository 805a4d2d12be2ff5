"""Serbian throughout: every page rendered in Serbian (Latin) and in Cyrillic with each of its
tabs, every expander and every practice switch opened, plus the failing cases a student
meets (a damaged link, a scene that cannot close, a negative length typed in the builder, a
variant code out of range), shows no English sentence and no number with a decimal point.

What is read: every text element (markdown, captions, LaTeX, headers, metrics, messages),
every label (widgets, tabs, expanders, buttons), the tables as shown (a Serbian table's
display values) and the charts' own texts (titles, legends, labels). A chart's ticks and
hover numbers are the browser's (Plotly's ``separators``: tests/test_phone.py reads them);
its toolbar's tooltips are Plotly's, in the locale the chart names (read here: the page's
language, whose words are checked). The number boxes' texts (ui/numbers.py) are read too.
A slider's own number is Streamlit's, rewritten in the browser (tests/test_phone.py and
tests/test_links_browser.py read it; docs/i18n.md). The practice CSV's header and diagnosis words are read as well.
"""

from __future__ import annotations

import io
import json
import re
from pathlib import Path

import pyarrow as pa
import pytest
from streamlit.testing.v1 import AppTest

from ui.i18n import t

ROOT = Path(__file__).resolve().parents[1]
# English words a Serbian sentence never holds (whole words, any case): a sentence in English
# has some of them
ENGLISH = {"the", "and", "of", "with", "which", "from", "must", "this", "that", "are", "is",
           "be", "by", "for", "into", "when", "where", "its", "has", "have", "would", "than",
           "cannot", "does", "not", "only", "each", "every", "or", "at", "it", "an", "as", "in",
           "if", "you", "your", "can", "will", "there", "then", "here", "press", "shows", "see",
           "click", "step", "points", "member", "group", "scale", "drawn", "read"}
WORD = re.compile(r"[^\W\d_]+")
# an identifier is no number: a task (zadatak 2.1, zadaci 1.1–1.3), a preset (zbirka-2.1), a
# code (3.1-S42-07K), a version (3.11.7), a file (docs/sr/x.md)
TASKS = re.compile(r"(?i)(zadat\w*|zadac\w*|задат\w*|задац\w*|zbirk\w*|збирк\w*|task\w*)"
                   r"\s+\d+\.\d+(\s*[–-]\s*\d+\.\d+)?")
POINT = re.compile(r"(?<![\w.\-–/])\d+\.\d+(?:e[+-]?\d+)?(?![\w.\-–/])")
# columns of identifiers: a task's number (2.1), a result's key (points.M.x)
IDENTIFIERS = {t("check.col_task", language=lang) for lang in ("sr", "sr-cyrl")}
SKIP = re.compile(r"`[^`]*`|https?://\S+|\S+\.(?:md|py|toml|csv|svg|html)\b"
                  r"|\b[a-z]\w*(?:\.[\w-]+)+|\b\w+_\w+")  # a result's key, a file's key


def run(path: str, language: str, query: dict | None = None, **state) -> AppTest:
    """The page in ``language``, with ``state`` preset and ``query`` in its link."""
    at = AppTest.from_file(str(ROOT / "app.py"), default_timeout=120)
    at.session_state["lang"] = language
    for key, value in state.items():
        at.session_state[key] = value
    for key, value in (query or {}).items():
        at.query_params[key] = value
    at.run()
    if path != "app.py":
        at.switch_page(path).run()
    assert not at.exception, [e.message for e in at.exception]
    return at


def _table(element) -> list[str]:
    """A table's cells as the reader sees them (a Styler's display values when there is one;
    the app writes a Serbian table's numbers as text, ui.export.dataframe)."""
    data = element.proto.arrow_data
    raw = data.styler.display_values if data.HasField("styler") else data.data
    if not raw:
        return []
    frame = pa.ipc.open_stream(io.BytesIO(raw)).read_all().to_pandas()
    config = json.loads(element.proto.columns or "{}")  # the labels a column is shown with
    names = {str(c): (config.get(str(c)) or {}).get("label") or str(c) for c in frame.columns}
    for c in frame.columns:  # a choice's cell shows the choice's label
        options = (config.get(str(c)) or {}).get("type_config", {}).get("options") or []
        shown = {o["value"]: o["label"] for o in options if isinstance(o, dict) and "label" in o}
        if shown:
            frame[c] = frame[c].map(lambda v: shown.get(v, v))
    tasks = [c for c in frame.columns if names[str(c)] in IDENTIFIERS]
    cells = frame.drop(columns=tasks).to_numpy().ravel()
    return list(names.values()) + [str(v) for v in cells if isinstance(v, str)]


def _chart(element, language: str) -> list[str]:
    """What a chart writes: titles, legend names, texts beside points, annotations; and
    whether its toolbar speaks ``language``."""
    whole = json.loads(element.proto.bytes)
    spec = whole.get("figure", {})
    out = [] if whole.get("locale") == language else [f"the toolbar in {whole.get('locale')}"]

    def title(node) -> None:
        if isinstance(node, dict):
            text = node.get("text") if isinstance(node.get("text"), str) else None
            if text:
                out.append(text)
            for key, value in node.items():
                if key in ("title", "xaxis", "yaxis", "xaxis2", "yaxis2", "legend"):
                    title(value)
        elif isinstance(node, str):
            out.append(node)

    title(spec.get("layout", {}))
    for annotation in spec.get("layout", {}).get("annotations", []):
        out.append(str(annotation.get("text", "")))
    for trace in spec.get("data", []):
        out.append(str(trace.get("name", "")))
        text = trace.get("text")
        out += [str(x) for x in text] if isinstance(text, list) else [str(text or "")]
    for frame in spec.get("frames", [])[:1]:
        for trace in frame.get("data", []):
            text = trace.get("text")
            out += [str(x) for x in text] if isinstance(text, list) else []
    return out


def shown(at: AppTest) -> list[str]:
    """Every text the page shows."""
    out = []
    for node in _walk(at._tree):
        kind = getattr(node, "type", "")
        proto = getattr(node, "proto", None)
        if kind == "dataframe":
            out += _table(node)
        elif kind == "bidi_component" and proto is not None and proto.component_name == "mehanizmi_plot":
            out += _chart(node, at.session_state["lang"])
        for attribute in ("value", "label", "body", "help", "placeholder"):
            value = getattr(proto, attribute, None) if proto is not None else None
            if isinstance(value, str) and value:
                out.append(value)
        if kind in ("metric",):
            out += [proto.body, proto.delta]
        if kind == "text_input":  # a number box as typed (ui/numbers.py)
            out.append(node.value or "")
        if kind == "radio" or kind == "selectbox":
            out += list(getattr(node, "options", []))
    return out


def _walk(node):
    yield node
    for child in getattr(node, "children", {}).values():
        yield from _walk(child)


def keyed(at: AppTest, kind: str) -> dict[str, list[str]]:
    """The keyed tab groups (key → labels) or expanders (key → [label]) of the page."""
    out = {}
    for node in _walk(at._tree):
        if getattr(node, "type", "") == kind:
            ident = node.proto.id if kind == "tab_container" else node.proto.id
            key = ident.rsplit("-", 1)[-1] if ident.startswith("$$ID-") else None
            if key:
                out[key] = [c.label for c in node.children.values()] if kind == "tab_container" \
                    else [node.label]
    return out


# on a Cyrillic page no word of three Latin letters or more is left, except units and the
# names of programs
LATIN = re.compile(r"\b[a-z]{3,}\b")
NAMES = {"rad", "pylinkage", "mechanism", "sin", "cos", "tan", "arccos", "atan", "latinica"}
CODE = re.compile(r"\\(?:begin|end)\{\w+\}|\\[A-Za-z]+|<[^>]*>|:material/\S*"
                  r"|\b\w+(?:-\w+)+")  # LaTeX, HTML, icons, ids


def english_in(text: str, language: str) -> list[str]:
    prose = CODE.sub(" ", SKIP.sub(" ", text))
    words = {w for w in WORD.findall(prose) if w.lower() in ENGLISH and not w.isupper()}
    if language == "sr-cyrl":
        words |= set(LATIN.findall(prose)) - NAMES
    return sorted(words)


def points_in(text: str) -> list[str]:
    return POINT.findall(TASKS.sub(" ", SKIP.sub(" ", text)))


def problems(texts: list[str], language: str = "sr") -> list[tuple[str, str]]:
    """(text, what is wrong) for each shown text with an English word or a decimal point."""
    found = []
    for text in texts:
        if text.startswith("<style>"):  # the page's CSS, never shown
            continue
        english, points = english_in(text, language), points_in(text)
        if english or points:
            found.append((text[:160], f"English {english}" if english else f"point {points}"))
    return found


def opened(at: AppTest) -> dict:
    """The state that opens every keyed expander and turns on every practice switch."""
    return ({key: True for key in keyed(at, "expander")}
            | {w.key: True for w in at.toggle if w.key and w.key.startswith("pr_")})


def explore(path: str, language: str, **state) -> list[str]:
    """The page with every keyed expander open and every practice switch on, then again for
    each tab of each keyed tab group: every text shown on the way."""
    first = run(path, language, **state)
    base = {**state, **opened(first)}
    texts, seen, todo = shown(first), set(), [None]
    while todo:
        tab = todo.pop(0)
        at = run(path, language, **base, **(dict([tab]) if tab else {}))
        more = opened(at)
        if set(more) - set(base):  # a tab with expanders or switches of its own
            at = run(path, language, **{**base, **more}, **(dict([tab]) if tab else {}))
        texts += shown(at)
        for key, labels in keyed(at, "tab_container").items():
            todo += [(key, label) for label in labels if (key, label) not in seen]
            seen |= {(key, label) for label in labels}
    return texts


PAGES = [("pages/trajectories.py", {}), ("pages/trajectories.py", {"view": "compass"}),
         ("pages/velocity_plans.py", {}), ("pages/velocity_plans.py", {"scene": "zbirka-4.1"}),
         ("pages/assur_groups.py", {}), ("pages/assur_groups.py", {"scene": "triad-full-turn"}),
         ("pages/kinetostatics.py", {}), ("pages/planetary_gears.py", {}),
         ("pages/rotor_balancing.py", {}), ("pages/builder.py", {}), ("pages/variants.py", {}),
         ("pages/textbook_check.py", {}), ("pages/class.py", {}), ("app.py", {})]


@pytest.mark.parametrize("language", ["sr", "sr-cyrl"])
@pytest.mark.parametrize("path, state", [
    pytest.param(p, s, id="-".join([Path(p).stem, *map(str, s.values())])) for p, s in PAGES])
def test_every_page_reads_serbian_with_everything_open(path, state, language):
    texts = explore(path, language, **state)
    assert len(texts) > 20
    assert not problems(texts, language), problems(texts, language)


def _open_linkage() -> str:
    """A four-bar whose coupler is too short to close at its own instant (a link to it)."""
    from mechanisms.link import encode
    from mechanisms.loader import build_document
    from mechanisms.sketch import template

    doc = template("four-bar")
    doc["members"]["3"]["length"] = 0.05
    return encode(build_document(doc, source="link"))


def _far_seed() -> str:
    """A variant code whose check letter is right but whose seed is past the largest."""
    from exams.codes import MAX_SEED, Settings, code
    return code(Settings("zbirka-2.1", MAX_SEED + 1), 1)


@pytest.mark.parametrize("language", ["sr", "sr-cyrl"])
@pytest.mark.parametrize("case", ["damaged link", "cut link", "cannot close", "negative length",
                                  "seed out of range", "bad check letter"])
def test_every_failing_case_says_why_in_serbian(case, language):
    from mechanisms import load_preset
    from mechanisms.link import encode
    from mechanisms.sketch import template

    if case == "negative length":
        doc = template("four-bar")
        doc["members"]["3"]["length"] = -0.2
        at = run("pages/builder.py", language, build_doc=doc)
        wanted = "0,2"  # the value typed, written the Serbian way
    else:
        query = {"damaged link": {"s": "1garbage"},
                 "cut link": {"s": encode(load_preset("zbirka-2.1"))[:-30]},
                 "cannot close": {"s": _open_linkage()},
                 "seed out of range": {"v": _far_seed()},
                 "bad check letter": {"v": "2.1-S42-07Q"}}[case]
        at = run("pages/velocity_plans.py", language, query)
        wanted = {"cannot close": "°", "seed out of range": "1000000000"}.get(case, "")
    errors = [e.value for e in at.error]
    assert errors, case
    assert not problems(errors, language), problems(errors, language)
    assert any(wanted in e.replace("\u202f", "") for e in errors), errors


def test_the_reader_finds_english_words_and_decimal_points():
    """The checks above can fail: an English reason, a number with a point, a Latin word on a
    Cyrillic page are found; task numbers, keys, files, notation and LaTeX are not."""
    assert problems(["grupa ne može da se zatvori: the two links cannot reach each other"])
    assert problems(["ω₃ = 7.84 s⁻¹"])
    assert problems(["група не може да се затвори: veza je oštećena"], "sr-cyrl")
    assert not problems(["Задатак 2.1: ⟨v_B⟩ = 7,84 m/s (задаци 1.1–1.3, zbirka-2.3, "
                         "points.M.x, docs/sr/willis.md)", "F_23^t \\frac{1}{2}"], "sr-cyrl")


@pytest.mark.parametrize("language", ["sr", "sr-cyrl"])
def test_the_toolbar_and_the_practice_csv_speak_serbian(language, monkeypatch):
    from cli.practice import steps_for
    from mechanisms import load_preset
    from methods.progress import Progress
    from ui import i18n
    from ui.plot import plotly_locales
    from ui.practice import answers_table

    words = plotly_locales()[language]["dictionary"]
    assert words["Reset axes"] != "Reset axes" and not problems(list(words.values()), language)
    monkeypatch.setattr(i18n._RUN, "language", language, raising=False)
    steps = steps_for(load_preset("zbirka-3.1"), "plans")
    progress = Progress.start()
    progress.give(steps[0], -steps[0].expected)  # a reversed arrow, then right
    progress.give(steps[0], steps[0].expected)
    table = answers_table(steps, progress)
    said = [*table.columns, *table.iloc[:, 6], *table.iloc[:, 7]]
    assert not problems([str(w) for w in said], language), problems(said, language)
    assert table.iloc[0, 6] == " | ".join(t(f"practice.word_{d}", language)
                                          for d in ("sense", "ok"))
    assert "." in table.iloc[0, 3] or "e" in table.iloc[0, 3]  # numbers keep a decimal point


def test_the_decimal_mark_is_one_rule_for_every_surface_that_writes_a_number():
    """``ui.i18n.decimal_comma`` decides the mark of every number the app writes: the texts
    (``num``, ``decimals``, ``latex``, ``sci``, a solver's sentence), a table's cells, a
    chart's ``separators``, and the mark the language box's container gives the page's
    head for its sliders. No module decides it again: every ``startswith("sr")`` left in the app picks
    words, not a decimal mark, and is named here."""
    import ast

    from mechanisms.messages import Text
    from ui.i18n import decimal_comma, decimals, latex, message, num, sci

    for language, mark in (("sr", ","), ("sr-cyrl", ","), ("en", ".")):
        assert decimal_comma(language) is (mark == ",")
        assert num(0.25, language=language) == f"0{mark}25"
        assert decimals("U_v = 0.5 m/s", language) == f"U_v = 0{mark}5 m/s"
        assert latex("0.5", language) == ("0{,}5" if mark == "," else "0.5")
        assert sci(3.6e-16, language=language) == f"3{mark}6e-16"
        assert f"0{mark}5" in message(Text("num.below", field="x", text="-1", limit=0.5),
                                      language)

    def page(language):
        import streamlit as st

        from figures.raw import RawFigure
        from ui.export import chart, dataframe
        from ui.i18n import language_picker
        st.session_state["lang"] = language
        language_picker()
        dataframe([{"x [m]": 0.25}], hide_index=True)
        fig = RawFigure()
        fig.add_raw([{"type": "scatter", "x": [0, 1], "y": [0, 1]}])
        chart(fig, "f", key="f")

    for language, mark in (("sr", ","), ("en", ".")):
        at = AppTest.from_function(page, args=(language,))
        at.run()
        assert not at.exception, [e.message for e in at.exception]
        boxes = {b.proto.id for b in at.sidebar.children.values()}
        assert any(f"decimal_{'comma' if mark == ',' else 'point'}" in box for box in boxes), boxes
        assert at.dataframe[0].value["x [m]"].tolist() == [0.25 if mark == "." else "0,25"]
        spec = json.loads(at.get("bidi_component")[0].proto.bytes)
        assert spec["separators"] == (",." if mark == "," else None)

    words = {("ui/i18n.py", "default_language"), ("ui/i18n.py", "counted"),
             ("ui/i18n.py", "in_language"), ("ui/docs.py", "path_of"),
             ("mechanisms/typed.py", "comma_is_decimal")}
    found = set()

    def visit(node, where: str, path) -> None:  # each call under its innermost function
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            where = node.name
        if (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)
                and node.func.attr == "startswith" and node.args
                and "sr" in ast.unparse(node.args[0])):
            found.add((path.relative_to(ROOT).as_posix(), where))
        for child in ast.iter_child_nodes(node):
            visit(child, where, path)

    for path in [ROOT / "app.py", *ROOT.glob("ui/*.py"), *ROOT.glob("pages/*.py"),
                 ROOT / "mechanisms" / "typed.py"]:
        visit(ast.parse(path.read_text(encoding="utf-8")), "<module>", path)
    assert found == words
