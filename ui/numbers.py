"""Every number a person types, read by one parser, in an input the app controls.

Streamlit's number box and a data editor's number cell read what is typed in the *browser's*
language: on a Serbian page in an English browser "0,35" became 35 and "3,1" became 31,
silently. So no number is typed into a widget that parses it in the browser. A number field
here is a text box whose text this module reads:

- on a Serbian page (Latin or Cyrillic) "0,35" and "0.35" both mean 0.35;
- on an English page the point is the decimal sign, and a comma is refused with a message
  (it could be a thousands separator: "1,000" must not silently become 1 or 1000);
- anything that is not one number ("0,3,5", "1.2.3", "abc", an empty box) is refused at its
  field, in words that name the field and repeat what was typed; the page goes on with the
  field's last good value, so nothing else changes.

A number is shown the way it is written in the page's language (a decimal comma in
Serbian), with every digit it holds, so that showing a value and reading it back never
changes it.
"""

from __future__ import annotations

import contextlib
import math
import re

import numpy as np
import streamlit as st
from streamlit.errors import StreamlitAPIException

from mechanisms.typed import NUMBER, Refused, check, comma_is_decimal, parse  # noqa: F401 (the pages' parser)
from ui.firstpaint import hold
from ui.i18n import current, t
from ui.url import link_default, link_value, linked, said_of_link, url_choice, url_set, url_toggle

REASONS = ("empty", "not_number", "comma", "integer", "below", "above", "repeated", "unknown")  # num.<reason>
SHOWN_MAX = 40  # characters of a typed text repeated in a message


def as_given(value: float) -> float:
    """A value a task gives, after a change of units: rounded to 12 significant digits, so
    that 120° made radians and back is 120 again, not 119,99999999999999. (For the page's
    own values only; what a person types keeps every digit.)"""
    return float(f"{float(value):.12g}")


def shown(value: float, language: str, *, integer: bool = False) -> str:
    """``value`` as a person writes it in ``language``, with every digit it holds (Python's
    shortest text that reads back as the same float)."""
    if integer:
        return str(int(value))
    text = repr(float(value))
    if text.endswith(".0"):
        text = text[:-2]
    return text.replace(".", ",") if comma_is_decimal(language) else text


def refusal(field: str, refused: Refused, language: str | None = None) -> str:
    """The refusal in words: the field, what was typed (as typed, cut and shown literally)
    and why."""
    language = language or current()
    limit = written(refused.limit, language) if refused.limit is not None else ""
    return t(f"num.{refused.reason}", language, field=field, text=literal(refused.text),
             limit=limit)


def written(value: float, language: str) -> str:
    """A limit as people write it: every digit, no exponent (0,000000001, not 1e-09)."""
    text = np.format_float_positional(value, trim="-")
    return text.replace(".", ",") if comma_is_decimal(language) else text


def literal(text: str) -> str:
    """A typed text shown exactly as typed inside a Markdown message: a code span (markup,
    dollars and stars stay text), cut to ``SHOWN_MAX`` characters, control characters
    dropped."""
    text = "".join(c for c in text if c.isprintable())
    if len(text) > SHOWN_MAX:
        text = text[:SHOWN_MAX] + "…"
    if not text:
        return "“”"
    fence = "`" * (max((len(run) for run in re.findall(r"`+", text)), default=0) + 1)
    return f"{fence} {text} {fence}"


def _memo(key: str) -> str:
    return f"_num_{key}"


def number_field(label: str, key: str, value: float | None = None, *,
                 minimum: float | None = None, maximum: float | None = None,
                 integer: bool = False, optional: bool = False, url: bool = False,
                 where=None, help: str | None = None,
                 label_visibility: str = "visible", wait: bool = False) -> float | None:
    """A text box for one number, read by :func:`parse` in the page's language.

    ``value`` is the field's first value (a page that seeds its widgets through
    ``ui.url.seed`` puts a float under ``key`` instead; it is written out here). ``url``
    keeps the value in the link as ``?key=`` with a decimal point, whatever the language.
    ``optional``: an answer box, where an empty box is ``None`` (not given yet), and so is
    a refused text. Otherwise a text that is refused shows its message under the field and
    the field's last good value is returned, so the rest of the page stays as it was.
    ``wait``: a secondary field, left out of a page's first run while it holds the page's
    seeded value (``ui.firstpaint.hold``).
    """
    where = where if where is not None else st
    if url:
        linked(key)
    language = current()
    state = st.session_state
    memo = state.get(_memo(key))  # (language, text shown, value) of the last good reading
    given = state.get(key)
    if isinstance(given, (int, float)) and not isinstance(given, bool):  # seeded by the page
        if wait and hold():  # (ui.url.seed, not from the link: the value the widget shows)
            return float(given)
        value, given = float(given), None
    elif given is None and url and key in st.query_params:
        try:  # read as a typed value is, range and all (either decimal sign)
            value = check(link_value(key) or "", "sr", minimum=minimum, maximum=maximum,
                          integer=integer)
        except Refused as refused:  # a hand-edited link: the page's own value, said
            value = link_default(key, value)
            said_of_link(key, refused, value)
    if given is None:
        text = "" if value is None else shown(value, language, integer=integer)
        state[key] = text
        memo = (language, text, value)
    elif memo is not None and memo[0] != language and memo[1] == given:
        text = "" if memo[2] is None else shown(memo[2], language, integer=integer)
        state[key] = text  # the language changed: the same value, written its new way
        memo = (language, text, memo[2])
    box = where.container(key=f"num_{'pos' if minimum is not None and minimum >= 0 else 'any'}_{key}")
    typed = box.text_input(label, key=key, help=help, autocomplete="off",
                           label_visibility=label_visibility)
    result = memo[2] if memo is not None else value
    if memo is not None and typed == memo[1]:
        result = memo[2]  # the value shown, with every bit it had
    elif optional and not typed.strip():
        result = None
        memo = (language, typed, None)
    else:
        try:
            result = check(typed, language, minimum=minimum, maximum=maximum, integer=integer)
            memo = (language, typed, result)
        except Refused as refused:
            box.error(refusal(label, refused), icon=":material/error:")
            if optional:
                result = None  # an answer: a refused one is no answer, not the last one
    link_note(key, label, result, box)
    state[_memo(key)] = memo
    if url and result is not None:
        url_set(key, f"{result:.15g}")
    return result


def bound_link(key: str, label: str, low: float | None = None, high: float | None = None,
               options: list | None = None, *, integer: bool | None = None) -> None:
    """Before a widget Streamlit binds to the link (``bind="query-params"``: φ₂, ω₂, a
    step): the link's value is read here, by the app's one parser, and handed to the widget
    as its value with the link rewritten in the plain form Streamlit's binding reads
    ("1,5" and "−3" would put a slider at its minimum). A value that is not one number in
    ``[low, high]`` (or not one of ``options``), or a key the link gives twice, is said in
    words and dropped, and the page's own value is used."""
    linked(key)
    read = f"_link_read_{key}"  # the link is read when the page opens, not after
    given = key in st.query_params and not st.session_state.get(read)
    st.session_state[read] = True  # (later runs: the widget's value, the link written from it)
    if given:
        if integer is None:
            integer = all(isinstance(v, int) for v in (options or [low, high]) if v is not None)
        try:
            text = link_value(key) or ""
            value = check(text, "sr", minimum=low, maximum=high, integer=integer)
            if options is not None:
                value = next((o for o in options if math.isclose(o, value, rel_tol=1e-9)), None)
                if value is None:
                    raise Refused("unknown", text)
            used = int(value) if integer else float(value)
            st.session_state[key] = used
            with contextlib.suppress(StreamlitAPIException):  # (bound already: it writes it)
                st.query_params[key] = str(used) if integer else f"{used:.15g}"
        except Refused as refused:
            st.query_params.pop(key, None)
            if (own := link_default(key)) is not None:
                st.session_state[key] = inside(own, low, high, options)
            said_of_link(key, refused, st.session_state.get(key))
    link_note(key, label, st.session_state.get(key))


def bound_choices(key: str, label: str, options) -> None:
    """Before a multiselect Streamlit binds to the link: the link's values that are none of
    ``options`` are said in words (Streamlit drops them without a word and keeps the rest,
    or shows the page's own choice when none is left). Said under the widget by
    ``link_note`` for as long as it holds what the page chose instead."""
    linked(key)
    read = f"_link_read_{key}"
    if key in st.query_params and not st.session_state.get(read):
        unknown = [v for v in st.query_params.get_all(key) if v not in options]
        if unknown:
            said_of_link(key, Refused("unknown", ", ".join(unknown)), None)
    st.session_state[read] = True


def inside(value, low: float | None, high: float | None, options: list | None = None):
    """``value`` within the widget's bounds of this scene: the nearest option, or clamped
    to [low, high]. A page's own value may lie beyond them (the Assur page seeds "every
    group", 99, and its slider ends at this scene's number of groups): a refused link must
    not hand the widget a value it then refuses."""
    if options:
        return min(options, key=lambda o: abs(o - value))
    if low is not None and value < low:
        return low
    if high is not None and value > high:
        return high
    return value


def link_switch(label: str, key: str, **kwargs) -> bool:
    """A switch kept in the link (``url_toggle``), a link's value that is not true or false
    said in words while the switch is as the page has it."""
    value = url_toggle(label, key, **kwargs)
    link_note(key, label, value)
    return value


def link_option(widget, label: str, options, key: str, default: str | None = None, **kwargs) -> str:
    """A choice kept in the link (``url_choice``), with a link's unknown value said in words
    for as long as the page shows its own instead."""
    value = url_choice(widget, label, options, key, default, **kwargs)
    link_note(key, label, value)
    return value


def link_note(key: str, label: str, value, where=None) -> None:
    """Say a refused link value of ``key`` while the field still holds the page's own."""
    kept = st.session_state.get(f"_link_refused_{key}")
    if kept is None:
        return
    if kept[1] is None and value is not None:  # (the widget's own first value, taken now)
        kept = st.session_state[f"_link_refused_{key}"] = (kept[0], value)
    if kept[1] != value:  # the person has set the field since: the link is behind them
        del st.session_state[f"_link_refused_{key}"]
        return
    (where or st).warning(t("link.refused", why=refusal(label, kept[0])), icon=":material/link_off:")


def bound_slider(label: str, low, high, *, key: str, where=None, wait: bool = False, **options):
    """``st.slider`` kept in the link (``bind="query-params"``), its link value read first
    by ``bound_link``. ``wait``: a secondary control, left out of a page's first run when
    its value is known without it (``ui.firstpaint.hold``)."""
    bound_link(key, label, low, high)
    if wait and key in st.session_state and hold():
        return st.session_state[key]  # (the link's, or the page's seeded value: the widget's)
    return slider(label, low, high, key=key, where=where, bind="query-params", **options)


def slider(label: str, low, high, *, where=None, **options):
    """``st.slider`` whose first value, when not given, is ``low`` said outright — the one
    Streamlit would take. Left unsaid, Streamlit reads every key of the session state to
    learn whether the slider is a range (``filtered_state``): about 0.3 ms a slider, a
    tenth of a trajectories rerun with its five. (``low`` stays the default a link bound
    to the slider leaves out, as before.)"""
    return (where or st).slider(label, low, high, value=options.pop("value", low), **options)


def bound_select_slider(label: str, options: list, *, key: str, value=None, wait: bool = False,
                        **kwargs):
    """``st.select_slider`` kept in the link, its link value read first by ``bound_link``;
    ``value`` is its first value, ``wait`` as for ``bound_slider``."""
    bound_link(key, label, options=list(options))
    if wait and hold():  # (the link's, or the page's seeded value, else the first: the widget's)
        return st.session_state.get(key, options[0] if value is None else value)
    if value is not None:
        kwargs["value"] = value
    return st.select_slider(label, options, key=key, bind="query-params", **kwargs)


def is_refused(key: str) -> bool:
    """Whether the number field ``key`` now shows a text it refused (the page goes on with
    its last good value, but a form must not start anything from it)."""
    memo = st.session_state.get(_memo(key))
    return memo is not None and st.session_state.get(key) != memo[1]


def refused_fields(fields: dict[str, str]) -> str | None:
    """Why a form cannot start anything yet — its number fields (key → label) that show a
    refused text — or None: the one rule of every button that starts something (a class,
    variants, a synthesis), said as the disabled button's help."""
    refused = [label for key, label in fields.items() if is_refused(key)]
    return t("num.fix_first", fields="; ".join(refused)) if refused else None


def last_value(key: str) -> float | None:
    """A number field's value as it last read (for code that needs it before the field is
    drawn in this run)."""
    memo = st.session_state.get(_memo(key))
    if memo is not None:
        return memo[2]
    given = st.session_state.get(key)
    return float(given) if isinstance(given, (int, float)) else None
