"""Variant codes: a short text on a student's sheet that names one variant exactly.

``3.1-S42-07K`` is variant 7 of task 3.1 (preset ``zbirka-3.1``) made with seed 42 at the
default spread. A set made with another spread says so (``S42R15``), and one that held
some given values at the book's (``S42H5`` — a hexadecimal mask over the task's givens, in
their order). The last letter is a check: a mistyped digit gives a clear message instead
of somebody else's variant. Codes are read case-insensitively.
"""

from __future__ import annotations

import re
import zlib
from dataclasses import dataclass

from mechanisms.loader import SceneError
from mechanisms.messages import Text

DEFAULT_SPREAD = 20  # ± % around the book's values
CHECK_LETTERS = "ACDEFHJKLMNPRTUVWXY"  # no B/8, G/6, I/1, O/0, Q, S/5, Z/2 to confuse
MAX_SEED = 10**9
_SET = re.compile(r"S(\d{1,10})(?:R(\d{1,2}))?(?:H([0-9A-F]{1,16}))?")


@dataclass(frozen=True)
class Settings:
    """What makes a set of variants: the task (a preset id), the seed, the spread (± %) and
    the givens held at the book's values (their indices)."""

    task: str
    seed: int
    spread: int = DEFAULT_SPREAD
    held: frozenset[int] = frozenset()


def short(task: str) -> str:
    """zbirka-3.1 → 3.1, analitika-2.1 → A2.1, other presets as they are."""
    if task.startswith("zbirka-"):
        return task.removeprefix("zbirka-")
    if task.startswith("analitika-"):
        return "A" + task.removeprefix("analitika-")
    return task


def _long(text: str) -> str:
    text = text.lower()
    if re.fullmatch(r"\d+\.\d+", text):
        return f"zbirka-{text}"
    if re.fullmatch(r"a\d+\.\d+", text):
        return f"analitika-{text[1:]}"
    return text


def _check(body: str) -> str:
    return CHECK_LETTERS[zlib.crc32(body.upper().encode()) % len(CHECK_LETTERS)]


def code(settings: Settings, index: int) -> str:
    part = f"S{settings.seed}"
    if settings.spread != DEFAULT_SPREAD:
        part += f"R{settings.spread}"
    if settings.held:
        part += f"H{sum(1 << i for i in settings.held):X}"
    body = f"{short(settings.task)}-{part}-{index:02d}"
    return body + _check(body)


def parse(text: str) -> tuple[Settings, int]:
    """(settings, index) of a code; SceneError saying what is wrong with a damaged one."""
    cleaned = text.strip()
    parts = cleaned.split("-")
    if len(parts) < 3 or not cleaned.isascii():
        raise SceneError(Text("code.shape", code=text))
    task, settings, last = "-".join(parts[:-2]), parts[-2].upper(), parts[-1].upper()
    found = _SET.fullmatch(settings)
    number = re.fullmatch(r"(\d{1,3})([A-Z])", last)
    if not found or not number or not task:
        raise SceneError(Text("code.shape", code=text))
    body = cleaned[:-1]
    if _check(body) != number.group(2):
        raise SceneError(Text("code.check", code=text))
    seed, spread, mask = found.groups()
    if int(seed) > MAX_SEED:
        raise SceneError(Text("code.seed", code=text, most=MAX_SEED))
    held = frozenset(i for i in range(64) if mask and int(mask, 16) >> i & 1)
    return Settings(_long(task), int(seed), int(spread or DEFAULT_SPREAD), held), int(number.group(1))
