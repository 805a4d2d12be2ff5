"""A number as a person types it, read by one rule (the pages through ui/numbers.py, the
command line's ``check``): on a Serbian page "0,35" and "0.35" are both 0.35; on an English
one the point is the decimal sign and a comma is refused (it could separate thousands);
anything that is not one finite number is refused, with why (``Refused.reason``, a
``num.<reason>`` string key)."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from .reader import LARGEST

NUMBER = re.compile(r"[+\-\u2212]?(?:[0-9]+(?:[.,][0-9]*)?|[.,][0-9]+)(?:[eE][+\-\u2212]?[0-9]+)?")


@dataclass(frozen=True)
class Refused(ValueError):
    """Why a typed text is not taken: ``reason`` is a ``num.<reason>`` string key."""

    reason: str
    text: str
    limit: float | None = None


def comma_is_decimal(language: str) -> bool:
    return language.startswith("sr")


def parse(text: str, language: str, *, integer: bool = False) -> float:
    """The one number ``text`` says in ``language``, or :class:`Refused`."""
    typed = text.strip()
    if not typed:
        raise Refused("empty", text)
    if NUMBER.fullmatch(typed) is None:
        raise Refused("not_number", text)
    if "," in typed and not comma_is_decimal(language):
        raise Refused("comma", text)
    value = float(typed.replace(",", ".").replace("\u2212", "-"))
    if not math.isfinite(value):
        raise Refused("not_number", text)
    if integer and not value.is_integer():
        raise Refused("integer", text)
    return value


def check(text: str, language: str, *, minimum: float | None = None,
          maximum: float | None = None, integer: bool = False) -> float:
    """``parse`` and the field's range: a value outside it is refused, not clamped. Every
    range lies within the scene loader's (±``LARGEST``): no solver or scale is handed a
    number whose square overflows (ω = 1e154 on the rotor page was an OverflowError)."""
    value = parse(text, language, integer=integer)
    minimum = -LARGEST if minimum is None else max(minimum, -LARGEST)
    maximum = LARGEST if maximum is None else min(maximum, LARGEST)
    if value < minimum:
        raise Refused("below", text, minimum)
    if value > maximum:
        raise Refused("above", text, maximum)
    return value
