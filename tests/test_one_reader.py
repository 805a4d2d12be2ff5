"""One reader for every link (issue 68): each parameter a page writes into its own link —
found by opening the page and reading its link, not from a list — is read back by the
app's one parser, whatever widget shows it. Written with a decimal comma (as the app's own
fields take it) it is used exactly; given twice, or not one of a choice's options, it is
refused in words that stay on the page while the page shows its own value."""

from __future__ import annotations

import math

import pytest

from ui.numbers import literal

from .test_hostile_links import PAGES, _opened

CHAPTERS = list(PAGES)  # (every page, the home and the class page included)
NO_NUMBERS = ("app.py", "pages/class.py", "pages/textbook_check.py", "pages/builder.py",
              "pages/variants.py")
KINDS = ("slider", "select_slider", "text_input", "radio", "selectbox", "toggle")


def values(at) -> dict[str, object]:
    """Every keyed widget's value on the page."""
    found = {}
    for kind in KINDS:
        for widget in getattr(at, kind):
            if widget.key:
                found[widget.key] = widget.value
    return found


def own(path: str):
    """The page's own link: what it writes, and each widget Streamlit binds to the link
    (its ``query_param_key``), at its own value."""
    at = _opened(path, {})
    assert not at.exception, path
    link = dict(at.query_params.items())
    for kind in KINDS:
        for widget in getattr(at, kind):
            bound = getattr(widget.proto, "query_param_key", "")
            if bound and bound not in link and isinstance(widget.value, (int, float)):
                link[bound] = str(widget.value)
    return link, values(at)


def number(text: str) -> float | None:
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) and "e" not in text.lower() else None


def comma(text: str) -> str:
    return text.replace(".", ",") if "." in text else f"{text},0"


@pytest.mark.parametrize("path", CHAPTERS)
def test_a_link_s_numbers_with_a_decimal_comma_are_used_exactly(path):
    link, shown = own(path)
    numeric = {k: v for k, v in link.items() if number(v) is not None and k in shown}
    if path in NO_NUMBERS:
        assert not numeric  # (their links carry a language, a scene or a code: no number)
        return
    assert numeric, path
    at = _opened(path, {**link, **{k: comma(v) for k, v in numeric.items()}})
    at.run()  # (the first paint's rerun: what was said must still be there)
    now = values(at)
    for key, text in numeric.items():
        assert float(now[key]) == pytest.approx(float(text), rel=1e-12), (path, key, text, now[key])
    said = " ".join(w.value for w in at.warning)
    assert not any(comma(v) in said for v in numeric.values()), said[:300]


@pytest.mark.parametrize("path", CHAPTERS)
def test_a_key_given_twice_or_an_unknown_choice_is_said_and_stays_said(path):
    link, shown = own(path)
    keys = [k for k in link if k in shown and k != "lang"]
    query = {k: [link[k], link[k]] for k in keys}
    at = _opened(path, query)
    at.run()
    said = " ".join(w.value for w in at.warning)
    for key in keys:
        assert literal(f"{link[key]} & {link[key]}") in said, (path, key, said[:400])
    assert not at.exception


@pytest.mark.parametrize("value", ["abc", "1e400", "", "\u22121e12", "zzz"])
@pytest.mark.parametrize("path", CHAPTERS)
def test_every_link_value_is_used_exactly_or_said_and_stays_said(path, value):
    """Text, huge, empty and Unicode-minus values in every parameter of a page's own link at
    once: each parameter's widget then holds the value exactly as the app's parser reads it,
    or the page says the value in words — still after the first paint's rerun."""
    from mechanisms.typed import Refused, parse

    link, shown = own(path)
    keys = [k for k in link if k in shown and k != "lang"]
    at = _opened(path, {**link, **{k: value for k in keys}})
    at.run()
    assert not at.exception
    notes = [w.value for w in at.warning if "This link's value was not used" in w.value
             and (not value or literal(value) in w.value)]  # one per refused key
    now = values(at)
    try:
        number = parse(value, "sr")
    except Refused:
        number = None
    refused = []
    for key in keys:
        used = now.get(key)
        exact = (number is not None and isinstance(used, (int, float)) and not isinstance(used, bool)
                 and float(used) == number) or used == value
        if not exact:
            refused.append(key)
    assert len(notes) >= len(refused), (path, value, refused, notes)
