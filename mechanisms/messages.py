"""Messages in the reader's language: an error keeps the key of its sentence in
``locales/*.toml`` and the values to fill in, not a finished English sentence, so that a page
renders it in Serbian (Latin or Cyrillic) or English and the command line in English.

A value may itself be a ``Text`` (a reason inside a sentence); floats are written with the
language's decimal separator, lists with "; " between numbers where the comma is decimal.
"""

from __future__ import annotations

import math
import re
import tomllib
from functools import cache
from pathlib import Path
from typing import Callable

LOCALES = Path(__file__).resolve().parents[1] / "locales"
KEEP = re.compile(r"⟨([^⟩]*)⟩")


class Text:
    """A sentence by its key, with the values to fill in (``str()`` gives it in English)."""

    __slots__ = ("key", "values")

    def __init__(self, key: str, /, **values):
        self.key = key
        self.values = values

    def render(self, lookup: Callable[[str], str], comma: bool = False) -> str:
        """The sentence from ``lookup(key)`` (notation marks already dropped or not), with
        its values written for a decimal ``comma`` or point."""
        return lookup(self.key).format(**{name: value_text(v, lookup, comma)
                                          for name, v in self.values.items()})

    def __str__(self) -> str:
        return self.render(english)

    def __repr__(self) -> str:
        return f"Text({self.key!r}, {self.values!r})"

    def __eq__(self, other) -> bool:  # equal sentences count as one (why variants failed)
        return isinstance(other, Text) and repr(self) == repr(other)

    def __hash__(self) -> int:
        return hash(repr(self))


class Joined(Text):
    """Several values in one place of a sentence, "; " between them (in Serbian a comma is
    the decimal sign)."""

    def __init__(self, items):
        super().__init__("", items=list(items))

    def render(self, lookup: Callable[[str], str], comma: bool = False) -> str:
        return "; ".join(value_text(v, lookup, comma) for v in self.values["items"])


def value_text(value, lookup: Callable[[str], str], comma: bool) -> str:
    """One value as a sentence shows it."""
    if isinstance(value, Text):
        return value.render(lookup, comma)
    if isinstance(value, bool) or value is None:
        return repr(value).lower() if isinstance(value, bool) else "—"
    if isinstance(value, int):
        return f"{value:,}".replace(",", "\u202f") if comma else f"{value:,}"
    if isinstance(value, float):
        return decimal(value, comma)
    if isinstance(value, (list, tuple)):
        return "[" + ("; " if comma else ", ").join(value_text(v, lookup, comma) for v in value) + "]"
    if isinstance(value, str):
        return value
    return repr(value)


def given(value):
    """A value a file gave, as a message quotes it: a string in quotes (so that an empty or
    spaced one shows), anything else as it is."""
    return repr(value) if isinstance(value, str) else value


def decimal(value: float, comma: bool, digits: int = 6) -> str:
    """``value`` to ``digits`` significant digits, with a decimal comma when asked."""
    if not math.isfinite(value):
        return str(value)
    text = f"{value:.{digits}g}"
    return text.replace(".", ",") if comma else text


@cache
def strings(language: str = "en") -> dict[str, str]:
    """The strings table of ``language`` ("en" or "sr", Latin) as written, notation marks
    included: for what below the pages writes in a chosen language (the Moodle export)."""
    with open(LOCALES / f"{language}.toml", "rb") as f:
        return tomllib.load(f)


def english(key: str) -> str:
    """The English sentence of ``key`` (notation marks dropped): the command line's language."""
    return KEEP.sub(r"\1", strings("en")[key])


def text_of(error: BaseException) -> Text | str:
    """What an error says: its ``Text`` when it was raised with one, else its English."""
    first = error.args[0] if error.args else ""
    return first if isinstance(first, Text) else str(error)
