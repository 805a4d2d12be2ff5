"""Every visible string in Serbian (Latin), English, and Serbian Cyrillic.

The strings live in one table per language (``locales/sr.toml``, ``locales/en.toml``);
Cyrillic is generated from the Latin Serbian table with ``cyrtranslit``. Course notation
inside a string (point letters, U_L, F_pq, v_R …) is wrapped in ⟨ ⟩ so that it stays in
Latin letters (the brackets never reach the screen); units in [square brackets] and
{placeholders} stay as they are too. Values are formatted in after
transliteration, with the language's decimal separator (the book writes 0,25 m).
"""

from __future__ import annotations

import re
import threading
import tomllib
from collections.abc import Callable
from functools import cache
from pathlib import Path
from typing import TypeVar

import cyrtranslit
import streamlit as st

from mechanisms.messages import KEEP, Text, text_of
from mechanisms.typed import comma_is_decimal
from ui.url import url_choice

T = TypeVar("T")

LOCALES = Path(__file__).resolve().parents[1] / "locales"
LANGUAGES = {"sr": "Srpski (latinica)", "en": "English", "sr-cyrl": "Српски (ћирилица)"}
LATIN = re.compile(r"(⟨[^⟩]*⟩|\{[^}]*\}|\[[^\]]*\])")  # spans transliteration leaves alone


@cache
def table(language: str) -> dict[str, str]:
    """The strings of one language (Cyrillic made from the Latin Serbian table)."""
    if language == "sr-cyrl":
        return {k: _to_cyrillic(v) for k, v in table("sr").items()}
    with open(LOCALES / f"{language}.toml", "rb") as f:
        return tomllib.load(f)


@cache
def _strings(language: str) -> dict[str, str]:
    """The strings of one language as a page shows them (the ⟨⟩ that keep notation Latin
    taken off): once, where taking them off at each of a run's hundred ``t()`` was 4 % of
    the plans page's rerun."""
    return {k: KEEP.sub(r"\1", v) for k, v in table(language).items()}


@cache
def member_labels(language: str) -> dict[str, str]:
    """The presets' member labels in one language, keyed by the English label in the file
    (``locales/labels.toml``; Cyrillic made from the Latin)."""
    if language == "en":
        return {}
    if language == "sr-cyrl":
        return {k: _to_cyrillic(v) for k, v in member_labels("sr").items()}
    with open(LOCALES / "labels.toml", "rb") as f:
        return tomllib.load(f)


def _to_cyrillic(text: str, latin: re.Pattern = LATIN) -> str:
    """Serbian Latin to Cyrillic, but for the spans ``latin`` matches (one capture group)."""
    parts = latin.split(text)  # even indices: prose, odd: spans kept in Latin
    return "".join(cyrtranslit.to_cyrillic(p, "sr") if i % 2 == 0 else p
                   for i, p in enumerate(parts))


_RUN = threading.local()  # the language of the script run on this thread (language_picker)


def current() -> str:
    """The page's language. Read from the session once per run, by ``language_picker``: a
    page asks about a hundred times a run, and each session-state read costs about 50 µs
    (a tenth of a rerun, measured with py-spy; docs/performance.md)."""
    return getattr(_RUN, "language", None) or st.session_state.get("lang") or default_language()


def decimal_comma(language: str | None = None) -> bool:
    """Whether the page writes its numbers with a decimal comma (Serbian: 0,25): the one
    rule of every number shown — texts, tables, charts, and the sliders' values, which the
    page's head rewrites in the mark ``language_picker`` names."""
    return comma_is_decimal(language or current())


def run_language() -> None:
    """Remember the session's language for the rest of this run (a fragment's run, which
    does not pass through ``language_picker``)."""
    _RUN.language = None  # an earlier run's, on this thread
    _RUN.language = current()


def kept_language(make: Callable[[], T]) -> Callable[[], T]:
    """``make`` for later, in this run's language: a download's data is made when it is
    clicked, on a thread with no page run, where ``current()`` would fall back to English."""
    language = current()

    def made() -> T:
        before = getattr(_RUN, "language", None)
        _RUN.language = language
        try:
            return make()
        finally:
            _RUN.language = before
    return made


def default_language() -> str:
    locale = (getattr(st.context, "locale", None) or "").lower()
    if locale.startswith("sr") and "cyrl" in locale:
        return "sr-cyrl"
    return "sr" if locale.startswith(("sr", "bs", "hr", "me")) else "en"


def t(key: str, language: str | None = None, **values) -> str:
    """The string ``key`` in the current language, with ``values`` formatted in. A value
    named ``member_label`` is a scene's member label: shown in the language's words where
    the labels table has them (an uploaded scene's own labels stay as written)."""
    language = language or current()
    text = _strings(language)[key]
    if not values:
        return text
    if "member_label" in values:
        values["member_label"] = label_of(values["member_label"], language)
    return text.format(**{k: num(v, language=language) if isinstance(v, float) else v
                          for k, v in values.items()})


def counted(key: str, n: int, language: str | None = None) -> str:
    """``n`` and a noun in the form the language wants after that number: the string ``key``
    holds three forms, "one|few|many" (Serbian: 1 student, 2 studenta, 5 studenata; 21
    student, 12 studenata), English using the first for 1 and the last otherwise."""
    language = language or current()
    forms = t(key, language).split("|")
    if language.startswith("sr"):
        form = 0 if n % 10 == 1 and n % 100 != 11 else 1 if 2 <= n % 10 <= 4 and not 12 <= n % 100 <= 14 else 2
    else:
        form = 0 if n == 1 else 2
    return forms[form].format(n=n)


def label_of(label: str, language: str | None = None) -> str:
    """A scene's member label in the language's words where the labels table has them (an
    uploaded scene's own labels stay as written)."""
    return KEEP.sub(r"\1", member_labels(language or current()).get(label, label))


def message(said: BaseException | Text | str, language: str | None = None) -> str:
    """An error, or a solver's sentence (``mechanisms.messages.Text``), in the reader's
    language; an error raised with a plain string shows that string."""
    language = language or current()
    if isinstance(said, BaseException):
        said = text_of(said)
    if not isinstance(said, Text):
        return str(said)
    return said.render(lambda key: _strings(language)[key],
                       comma=decimal_comma(language))


DECIMAL = re.compile(r"(?<=\d)\.(?=\d)")


def decimals(text: str, language: str | None = None) -> str:
    """Numbers already written in a text (a benchmark's cell) with the language's decimal
    sign. Only for texts that hold no identifiers such as task numbers (2.1)."""
    return DECIMAL.sub(",", text) if decimal_comma(language) else text


def latex(text: str, language: str | None = None) -> str:
    """A LaTeX equation with the language's decimal sign: Serbian's comma written ``{,}``,
    which LaTeX sets as a decimal sign, not as punctuation followed by a space."""
    return DECIMAL.sub("{,}", text) if decimal_comma(language) else text


def sci(value: float, digits: int = 1, language: str | None = None) -> str:
    """A small number in scientific notation (a residual, an error: 3,6e-16 in Serbian)."""
    return decimals(f"{value:.{digits}e}", language)


def num(value: float, digits: int = 4, language: str | None = None) -> str:
    """A number with ``digits`` significant digits and the language's decimal separator (a
    value that rounds to zero prints as 0, not −0)."""
    text = f"{value:.{digits}g}"
    if float(text) == 0:
        text = "0"
    return text.replace(".", ",") if decimal_comma(language) else text


def language_picker() -> str:
    """The language choice in the sidebar, kept in the URL as ``?lang=``; the run's language
    from here on (a session's reruns share one script thread, and each run passes here
    before its page)."""
    _RUN.language = None
    _RUN.language = url_choice(_marked_box, "Language · Jezik · Језик", list(LANGUAGES),
                               "lang", default=default_language(), format_func=LANGUAGES.get,
                               label_visibility="collapsed")
    kept = st.session_state.get("_link_refused_lang")
    if kept is not None and kept[1] == _RUN.language:  # ?lang=xx: said until another is picked
        st.sidebar.warning(t("link.refused", why=t(f"num.{kept[0].reason}", field="lang",
                                                   text=f"`{kept[0].text}`")), icon=":material/link_off:")
    return _RUN.language


def _marked_box(label: str, options: list[str], key: str, **kwargs) -> str:
    """The language box, in a container named by the decimal mark of the language it shows
    (``decimal_``comma or point): the page's head (scripts/page_head.py) writes the sliders'
    values in that mark, on every page, with a chart or without. No element of its own: a
    style element (``st.html``) brought Streamlit's HTML scripts, 12 kB, into every first
    paint."""
    mark = "comma" if decimal_comma(st.session_state[key]) else "point"
    return st.sidebar.container(key=f"decimal_{mark}").selectbox(label, options, key=key, **kwargs)


def in_language(english: str, serbian: str, language: str | None = None) -> str:
    """A text a scene gives in two languages, in the reader's (default the current one): the
    Serbian one (notation in ⟨⟩ kept Latin) for sr and sr-cyrl where there is one."""
    language = language or current()
    if not language.startswith("sr") or not serbian:
        return english
    return KEEP.sub(r"\1", _to_cyrillic(serbian) if language == "sr-cyrl" else serbian)


def _in_language(scene, field: str, language: str | None = None) -> str:
    """A scene's text field (``title``, ``note``, ``source``) in the language."""
    return in_language(getattr(scene, field), getattr(scene, f"{field}_sr", ""), language)


def title_of(scene, language: str | None = None) -> str:
    return _in_language(scene, "title", language)


def note_of(scene) -> str:
    return _in_language(scene, "note")


def source_of(scene) -> str:
    return _in_language(scene, "source")


def scaled_title(title: str, scale: float, unit: str) -> str:
    """A drawing's title with its scale, as the book writes it: "… — scale 1 cm = 10 N"."""
    return f"{title} — {t('fig.scale', scale=num(scale, 4), unit=unit)}"
