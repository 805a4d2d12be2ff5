"""How big a scene may be: far above any mechanism of the course, far below what would keep a
server process busy. Counted on the parsed file before anything else is checked, so that an
oversized upload or link is refused in milliseconds (docs/scene-format.md, "Limits").

The course's largest scenes: a linkage of 7 moving members and 10 pairs, a gear train of 12
members and 7 meshes, a rotor of 3 masses (docs/scene-format.md lists each limit beside them).
"""

from __future__ import annotations

from typing import Any

from .messages import Text

# (top-level key, what it lists: the sentence ``scene.lists.<what>``, most allowed) per kind
# of scene
LINKAGE = (("members", "moving_members", 20), ("pairs", "pairs", 30), ("frame", "frame", 30),
           ("forces", "forces", 40), ("moments", "moments", 20), ("guess", "guess", 200))
POINTS = 200  # every point of every member, extra points included
GEARS = (("members", "members", 40), ("meshes", "meshes", 60), ("shafts", "shafts", 40),
         ("fixed", "fixed", 40), ("inputs", "inputs", 40), ("points", "points", 100))
ROTOR = (("masses", "masses", 100),)
BOOK = 300  # printed values quoted from the book


def count(raw: dict, limits, fail) -> None:
    """Refuse a table with more entries than its limit (``fail(key, rule)`` makes the error)."""
    for key, what, most in (*limits, ("book", "book", BOOK)):
        value: Any = raw.get(key)
        if isinstance(value, (list, dict)) and len(value) > most:
            raise fail(key, "too_many", count=len(value), what=Text(f"scene.lists.{what}"),
                       most=most)


def count_points(raw: dict, fail) -> None:
    """All points of all members together (extra points are free to add one by one)."""
    members = raw.get("members")
    if not isinstance(members, dict):
        return
    total = sum(len(spec.get("extra", {})) + len(spec.get("points", []))
                for spec in members.values() if isinstance(spec, dict)
                and isinstance(spec.get("extra", {}), dict) and isinstance(spec.get("points", []), list))
    if total > POINTS:
        raise fail("members", "too_many_points", count=total, most=POINTS)
