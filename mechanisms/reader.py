"""What every scene parser shares: typed access to parsed TOML whose messages name the key
(``four-bar.toml: members.3.length must be > 0, got -0.2``), the scene error, and the fields
every kind of scene has (id, titles, notes, the book's printed values).

Its own module so that the linkage loader and the gear and rotor parsers import it and not
each other.
"""

from __future__ import annotations

import difflib
import math
import re
from typing import Any

from .messages import Text, given

LARGEST = 1e9  # beyond this a number is a typo or an attack, and squares of it overflow


PART = re.compile(r"([^.\[\]]+)|\[(\d+)\]")


def key_parts(key: str) -> tuple[str | int, ...]:
    """The parts of a key the loader names in a refusal, by the one grammar every scene
    file has: a table's entry by name after a point, a list's by index in brackets —
    ``members.2.mass`` → ("members", "2", "mass"), ``masses[1].mass`` → ("masses", 1,
    "mass"), ``pairs[0].members[1]`` → ("pairs", 0, "members", 1). The builder's tables
    and the pages' small tables find their cell from these (one reader, one cell named)."""
    return tuple(int(index) if index else name for name, index in PART.findall(key))


class SceneError(ValueError):
    """A scene file breaks a rule; the message (a ``Text``) names the file, the key and the
    rule."""


class Reader:
    """Typed access to the parsed TOML with messages that name the key."""

    def __init__(self, source: str):
        self.source = source

    def fail(self, key: str, rule: str | Text, **values) -> SceneError:
        """The error for ``key``: ``rule`` is a ``Text`` or the name of a ``scene.`` sentence
        filled with ``values``."""
        if not isinstance(rule, Text):
            rule = Text(f"scene.{rule}", **values)
        return SceneError(Text("scene.at", source=self.source, key=key, rule=rule))

    def check_keys(self, table: Any, allowed: set[str], key: str) -> dict:
        if not isinstance(table, dict):
            raise self.fail(key, "not_table", kind=type(table).__name__)
        for name in table:
            if name not in allowed:
                near = difflib.get_close_matches(name, sorted(allowed), n=1)
                hint = Text("scene.did_you_mean", near=near[0]) if near else ""
                where = f"{key}.{name}" if key else name
                raise self.fail(where, "unknown_key", hint=hint)
        return table

    def number(self, table: dict, name: str, key: str, default: float | None = None,
               positive: bool = False, non_negative: bool = False) -> float:
        where = f"{key}.{name}" if key else name
        if name not in table:
            if default is None:
                raise self.fail(where, "missing")
            return default
        value = table[name]
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(where, "not_number", value=given(value))
        if not math.isfinite(value):
            raise self.fail(where, "not_finite", value=given(value))
        if abs(value) > LARGEST:
            raise self.fail(where, "too_large", value=float(value), largest=LARGEST)
        if positive and value <= 0:
            raise self.fail(where, "not_positive", value=given(value))
        if non_negative and value < 0:
            raise self.fail(where, "negative", value=given(value))
        return float(value)

    def text(self, table: dict, name: str, key: str, default: str | None = None) -> str:
        where = f"{key}.{name}" if key else name
        value = table.get(name, default)
        if value is None:
            raise self.fail(where, "missing")
        if not isinstance(value, str):
            raise self.fail(where, "not_string", value=given(value))
        return value

    def integer(self, table: dict, name: str, key: str) -> int:
        where = f"{key}.{name}" if key else name
        value = table.get(name)
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.fail(where, "not_member_number", value=given(value))
        return value

    def vector(self, value: Any, key: str) -> complex:
        ok = (isinstance(value, list) and len(value) == 2
              and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value))
        if not ok:
            raise self.fail(key, "not_vector", value=given(value))
        if not all(math.isfinite(v) and abs(v) <= LARGEST for v in value):
            raise self.fail(key, "vector_range", largest=LARGEST, value=given(value))
        return complex(value[0], value[1])


def identity(raw: dict, r: Reader, default_id: str) -> dict:
    """What every kind of scene has: id, titles, source, note, and the book's printed values
    with the reasons some of them differ, in English and Serbian (``[book]``, ``[book_notes]``,
    ``[book_notes_sr]``)."""
    book = raw.get("book", {})
    if not isinstance(book, dict):
        raise r.fail("book", "book_table")
    notes, notes_sr = raw.get("book_notes", {}), raw.get("book_notes_sr", {})
    for name, table in (("book_notes", notes), ("book_notes_sr", notes_sr)):
        if not isinstance(table, dict):
            raise r.fail(name, "notes_table")
    for key in notes_sr:
        if key not in notes:
            raise r.fail(f"book_notes_sr.{key}", "note_sr_key")
    return dict(id=r.text(raw, "id", "", default=default_id),
                title=r.text(raw, "title", "", default=default_id),
                title_sr=r.text(raw, "title_sr", "", default=""),
                source=r.text(raw, "source", "", default=""),
                note=r.text(raw, "note", "", default=""),
                note_sr=r.text(raw, "note_sr", "", default=""),
                source_sr=r.text(raw, "source_sr", "", default=""),
                book={k: r.number(book, k, "book") for k in book},
                book_notes={k: r.text(notes, k, "book_notes") for k in notes},
                book_notes_sr={k: r.text(notes_sr, k, "book_notes_sr") for k in notes_sr})
