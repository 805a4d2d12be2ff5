"""Rotor scenes (chapter 7): unbalanced masses and the two correction planes.

Angles are measured as the book measures them: a mass at radius r and angle φ has
y = r·sin φ and z = r·cos φ. SI units inside (kg, m, rad); degrees in the file.
Format: docs/scene-format.md, section "Rotors".
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field

from . import limits
from .messages import given
from .reader import Reader, SceneError, identity

PLANES = ("I", "II")
QUANTITIES = ("mass", "radius", "angle")
TOP_KEYS = {"id", "kind", "title", "title_sr", "source", "note", "note_sr", "source_sr", "omega", "mode", "planes",
            "masses", "corrections", "bearings", "book", "book_notes",
            "book_notes_sr"}


@dataclass(frozen=True)
class Mass:
    mass: float  # kg
    radius: float  # m
    angle: float  # rad
    x: float  # axial position, m


@dataclass(frozen=True)
class Correction:
    """The known quantities of one correction (None = unknown, to be found)."""

    mass: float | None = None
    radius: float | None = None
    angle: float | None = None

    @property
    def unknowns(self) -> tuple[str, ...]:
        return tuple(q for q in QUANTITIES if getattr(self, q) is None)


@dataclass(frozen=True)
class Rotor:
    id: str
    title: str
    source: str
    note: str
    masses: tuple[Mass, ...]
    planes: dict[str, float]  # axial positions of the correction planes I and II, m
    corrections: dict[str, Correction]
    mode: str = "dynamic"  # or "static": one correction plane (I)
    omega: float | None = None  # rad/s, for the bearing forces
    bearings: dict[str, float] = field(default_factory=dict)  # axial positions A, B, m
    book: dict[str, float] = field(default_factory=dict)
    book_notes: dict[str, str] = field(default_factory=dict)
    book_notes_sr: dict[str, str] = field(default_factory=dict)  # the same in Serbian
    title_sr: str = ""  # the title in Serbian (Latin); Cyrillic is made from it
    note_sr: str = ""  # the note and the source in Serbian (Latin), likewise
    source_sr: str = ""

    def with_(self, **changes) -> Rotor:
        return dataclasses.replace(self, **changes)


def parse_rotor(raw: dict, source: str, default_id: str) -> Rotor:
    r = Reader(source)
    r.check_keys(raw, TOP_KEYS, "")
    limits.count(raw, limits.ROTOR, r.fail)
    mode = r.text(raw, "mode", "", default="dynamic")
    if mode not in ("dynamic", "static"):
        raise r.fail("mode", "rotor_mode", value=given(mode))
    planes_needed = PLANES if mode == "dynamic" else PLANES[:1]
    planes = r.check_keys(raw.get("planes", {}), set(PLANES), "planes")
    positions = {p: r.number(planes, p, "planes") for p in planes_needed}
    specs = raw.get("masses")
    if not isinstance(specs, list) or not specs:
        raise r.fail("masses", "masses_missing")
    masses = []
    for i, spec in enumerate(specs):
        where = f"masses[{i}]"
        spec = r.check_keys(spec, {"mass", "radius", "angle", "x"}, where)
        masses.append(Mass(r.number(spec, "mass", where, non_negative=True),
                           r.number(spec, "radius", where, non_negative=True),
                           math.radians(r.number(spec, "angle", where)),
                           r.number(spec, "x", where, default=0.0)))
    table = r.check_keys(raw.get("corrections", {}), set(PLANES), "corrections")
    corrections = {}
    for plane in planes_needed:
        where = f"corrections.{plane}"
        spec = r.check_keys(table.get(plane, {}), set(QUANTITIES), where)
        known = {q: r.number(spec, q, where, positive=q != "angle") for q in QUANTITIES if q in spec}
        if "angle" in known:
            known["angle"] = math.radians(known["angle"])
        corrections[plane] = Correction(**known)
        if len(corrections[plane].unknowns) != 2:
            raise r.fail(where, "one_unknown_pair", given=", ".join(sorted(spec)) or "—")
    bearings = r.check_keys(raw.get("bearings", {}), {"A", "B"}, "bearings")
    omega = raw.get("omega")
    return Rotor(
        **identity(raw, r, default_id),
        masses=tuple(masses), planes=positions, corrections=corrections, mode=mode,
        omega=None if omega is None else r.number(raw, "omega", "", positive=True),
        bearings={k: r.number(bearings, k, "bearings") for k in bearings},
    )


__all__ = ["Correction", "Mass", "Rotor", "SceneError", "parse_rotor", "PLANES"]
