"""A choice widget whose value lives in the URL as its plain code (``?lang=sr``, ``?scene=zbirka-1.3``).

Streamlit's own ``bind="query-params"`` keeps a choice's *displayed label* in the URL, which
would put translated text and long titles in shared links, and a link would break when
the language changes. These choices keep the option itself instead. Tables (a data
editor's rows) travel as compact rows of numbers.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator, Sequence
from typing import NoReturn

import pandas as pd
import streamlit as st

from mechanisms.reader import LARGEST
from mechanisms.typed import Refused, parse


PENDING = "_link_pending"  # this run's changes to the link, while a run gathers them


def _pending() -> dict[str, str]:
    """This run's gathered changes (none outside ``link_sent``)."""
    return st.session_state.get(PENDING) or {}


def url_set(key: str, text: str) -> None:
    """``?key=text`` in the page's link, when it changes. Inside ``link_sent`` (every run of
    the app) the run's changes go to the browser together as it ends: written one by one,
    each was a message the browser handled on its own — 14 on a fresh kinetostatics page,
    about 20 ms of chromium's time before its first chart (issue 83). Outside it (a page's
    script run alone, as AppTest runs one) a change is written at once."""
    pending = st.session_state.get(PENDING)
    if pending is None:
        if st.query_params.get(key) != text:
            st.query_params[key] = text
    elif pending.get(key, st.query_params.get(key)) != text:
        pending[key] = text


def url_value(key: str, default: str | None = None) -> str | None:
    """The link's value of ``key`` as this run leaves it: its gathered change, if any."""
    pending = _pending()
    return pending[key] if key in pending else st.query_params.get(key, default)


def url_drop(key: str) -> None:
    """``?key=`` out of the page's link, with any change the run had gathered for it (else
    the run's end would put it back)."""
    _pending().pop(key, None)
    st.query_params.pop(key, None)


def url_replace(values: dict[str, str]) -> None:
    """The page's whole link replaced by ``values``: what the run had gathered goes with the
    old one."""
    _pending().clear()
    st.query_params.from_dict(values)


def _send() -> None:
    """The gathered changes, in one message."""
    pending = _pending()
    changed = {k: v for k, v in pending.items() if st.query_params.get(k) != v}
    pending.clear()
    if changed:
        st.query_params.update(changed)


@contextlib.contextmanager
def link_sent() -> Iterator[None]:
    """Around a whole run (app.py) or a fragment's run (ui.fragments): the link's changes
    gathered, and sent in one message as the run ends, or fails. A fragment that a whole
    run calls gathers into the run's changes. A run that stops must stop through ``stop``
    (after a stop Streamlit sends nothing more); one that reruns writes its link again."""
    if PENDING in st.session_state:
        yield
        return
    st.session_state[PENDING] = {}
    try:
        yield
    except Exception:  # (an error, said by ui.boundary; not a stop or a rerun)
        _send()
        raise
    else:
        _send()
    finally:
        st.session_state.pop(PENDING, None)


def stop() -> NoReturn:
    """``st.stop()``, with the link's changes sent first: once a stop is asked for, Streamlit
    raises at the next message instead of sending it, so ``link_sent`` could not."""
    _send()
    st.stop()


LINK_KEYS = "_link_keys"  # session: every key this page reads from its link


def linked(key: str) -> None:
    """Note that the page reads ``key`` from its link: one list of what a page's links may
    carry, which tests/test_hostile_links.py opens with hostile values, key by key."""
    st.session_state.setdefault(LINK_KEYS, set()).add(key)


def link_value(key: str) -> str | None:
    """The link's one value of ``key`` (None when it gives none). A key the link gives more
    than once is refused (``Refused`` "repeated"), never its last value taken."""
    given = st.query_params.get_all(key)
    if len(given) > 1:
        raise Refused("repeated", " & ".join(given))
    return given[0] if given else None


def said_of_link(key: str, refused: Refused, value) -> None:
    """Remember that the link's value of ``key`` was refused, to be said while the widget
    holds the value the page used instead (``ui.numbers.link_note``, every run: a page's next
    run would drop a note made once; this module speaks no language)."""
    st.session_state[f"_link_refused_{key}"] = (refused, value)


def url_choice(widget: Callable, label: str, options: Sequence[str], key: str,
               default: str | None = None, **kwargs) -> str:
    """``widget`` (st.selectbox, st.radio, …) seeded from ``?key=`` and writing it back. A
    link's value that is not one of ``options`` (or given twice) gives way to ``default``,
    and is kept to be said (``ui.numbers.link_option``)."""
    linked(key)
    default = link_default(key, options[0]) if default is None else default  # (seed's, if seeded)
    if key not in st.session_state or st.session_state[key] not in options:
        st.session_state[key] = default
        try:
            wanted = link_value(key)
            if wanted is not None and wanted not in options:
                raise Refused("unknown", wanted)
            if wanted is not None:
                st.session_state[key] = wanted
        except Refused as refused:
            said_of_link(key, refused, default)
    value = widget(label, options, key=key, **kwargs)
    url_set(key, value)
    return value


def url_toggle(label: str, key: str, **kwargs) -> bool:
    """A switch kept in the URL as ``?key=true|false``. Not Streamlit's own binding: a
    bound switch set back to its default from a button (the book's "As in the book") kept
    the URL's old value and so its old state. Any other link value is kept to be said
    (``ui.numbers.link_switch``)."""
    linked(key)
    if key not in st.session_state and key in st.query_params:
        try:
            wanted = link_value(key)
            if wanted not in ("true", "false"):
                raise Refused("unknown", wanted or "")
            st.session_state[key] = wanted == "true"
        except Refused as refused:
            said_of_link(key, refused, kwargs.get("value", False))
    value = st.toggle(label, key=key, **kwargs)
    url_set(key, "true" if value else "false")
    return value


def seed(defaults: dict[str, object], scene: str) -> None:
    """Give the page's widgets their values for ``scene``, before they are drawn.

    On the first run a value may come from the link (``?omega=5``) and is kept; when the
    user picks another scene, every widget takes that scene's default, so a link never
    carries one scene's lengths into another. Widgets are then created without ``value=``.
    """
    previous = st.session_state.get("_seeded_for")
    st.session_state["_seeded_for"] = scene
    changed = previous is not None and previous != scene
    fallback = st.session_state.setdefault(LINK_DEFAULTS, {})
    for key, value in defaults.items():
        if changed or (key not in st.session_state and key not in st.query_params):
            st.session_state[key] = value
        fallback[key] = value  # what a refused value of the link gives way to


LINK_DEFAULTS = "_link_defaults"


def link_default(key: str, value=None):
    """The page's own value of ``key`` (``seed``'s), for a link whose value was refused."""
    return st.session_state.get(LINK_DEFAULTS, {}).get(key, value)


def url_table(key: str, default: pd.DataFrame, scene: str, rows_fixed: bool = True) -> pd.DataFrame:
    """The table an ``st.data_editor`` starts from: the one in the link (``?key=1,2;3,4`` —
    rows of numbers, columns as in ``default``) when the page opens and it fits, else
    ``default``. It is then kept until the scene changes, because the editor stores its
    edits relative to it."""
    linked(key)
    memo = f"_{key}_start"
    first = memo not in st.session_state
    if first or st.session_state[memo][0] != scene:
        start = default
        text = st.query_params.get(key) if first else None
        st.session_state.pop(f"_{key}_link_refused", None)  # (another scene: its own table)
        if text:
            try:
                rows = [[parse(v, "en") for v in row.split(",")] for row in text.split(";")]
                if any(len(row) != len(default.columns) for row in rows):
                    raise ValueError(text)
                table = pd.DataFrame(rows, columns=default.columns).astype(default.dtypes)
                if not table.map(lambda v: abs(v) <= LARGEST).all().all() or (
                        rows_fixed and len(table) != len(default)):
                    raise ValueError(text)
                start = table
            except (Refused, ValueError, TypeError):  # a hand-edited link: the scene's own table, said
                st.session_state[f"_{key}_link_refused"] = text
        st.session_state[memo] = (scene, start)
    return st.session_state[memo][1]


def refuse_table(key: str, default: pd.DataFrame, scene: str, why: str) -> pd.DataFrame:
    """The link's table for ``key`` refused after all (the scene it makes breaks a scene
    file's rules, ``why``): the scene's own table from now on, the link's text and why kept
    to be said."""
    st.session_state[f"_{key}_link_refused"] = (st.query_params.get(key, ""), why)
    st.session_state[f"_{key}_start"] = (scene, default)
    return default


def table_refused(key: str, kept: bool = True) -> str | tuple[str, str] | None:
    """The link's text for the table ``key`` when it was refused (and why, when the loader
    refused the scene it made): said by the page on every run while the table is still the
    scene's own, forgotten (``kept=False``) once edited."""
    if not kept:
        return st.session_state.pop(f"_{key}_link_refused", None)
    return st.session_state.get(f"_{key}_link_refused")


def table_to_url(key: str, table: pd.DataFrame, default: pd.DataFrame) -> None:
    """Put the edited table into the link, or take it out when it is the scene's own."""
    rows = table.dropna()
    if rows.shape == default.shape and (rows.to_numpy(dtype=float) == default.to_numpy(dtype=float)).all():
        url_drop(key)
        return
    url_set(key, ";".join(",".join(f"{float(v):.10g}" for v in row)
                          for row in rows.itertuples(index=False)))
