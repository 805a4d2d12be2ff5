"""Gear-train scenes (chapter 6): members, meshes, shafts, carriers, fixed members and inputs.

A member is anything that turns about an axis: a gear, a carrier (arm), a ring, a wheel.
A planet's axis is carried by its carrier at ``axis`` from the central axis; a member
without a carrier turns about a fixed axis (``axis`` = its distance from the central axis,
0 for the central members). Each mesh names its two members, the pitch radius of each at
that mesh (a member may have several toothed rims) and which of them, if any, is a ring
with internal teeth. A bevel pair is drawn as its plane equivalent (``bevel = true``): the
sense of the second gear is chosen with ``internal`` as for spur gears, and its axes are
not checked against the radii. SI units (m, rad/s); format in docs/scene-format.md, "Gear trains".
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field

from . import limits
from .messages import Text, given
from .reader import Reader, SceneError, identity

TOP_KEYS = {"id", "kind", "title", "title_sr", "source", "note", "note_sr", "source_sr", "members", "meshes", "shafts",
            "fixed", "inputs", "points", "book", "book_notes",
            "book_notes_sr"}
MEMBER_KEYS = {"label", "carrier", "axis", "x"}
MESH_KEYS = {"members", "radii", "teeth", "module", "internal", "bevel"}
INPUT_KEYS = {"member", "omega", "velocity", "radius"}


@dataclass(frozen=True)
class GearMember:
    number: int
    label: str = ""
    carrier: int | None = None  # the carrier that holds this member's axis (a planet)
    axis: float = 0.0  # distance of the axis from the central axis, m
    x: float | None = None  # axial position for the drawing, m (None: laid out in order)


@dataclass(frozen=True)
class Mesh:
    members: tuple[int, int]
    radii: tuple[float, float]  # pitch radii at this mesh, m
    internal: int | None = None  # the member whose teeth are internal (a ring), if any
    bevel: bool = False  # bevel gears: axes at an angle, so no centre distance to check


@dataclass(frozen=True)
class Input:
    member: int
    omega: float  # rad/s (a velocity given at a radius is converted: ω = v/r)
    velocity: float | None = None  # as given, m/s
    radius: float | None = None  # m


@dataclass(frozen=True)
class GearTrain:
    id: str
    title: str
    source: str
    note: str
    members: dict[int, GearMember]
    meshes: tuple[Mesh, ...]
    shafts: tuple[tuple[int, ...], ...] = ()
    fixed: tuple[int, ...] = ()
    inputs: tuple[Input, ...] = ()
    points: dict[str, tuple[int, float]] = field(default_factory=dict)  # name → (member, radius)
    book: dict[str, float] = field(default_factory=dict)
    book_notes: dict[str, str] = field(default_factory=dict)
    book_notes_sr: dict[str, str] = field(default_factory=dict)  # the same in Serbian
    title_sr: str = ""  # the title in Serbian (Latin); Cyrillic is made from it
    note_sr: str = ""  # the note and the source in Serbian (Latin), likewise
    source_sr: str = ""

    def with_(self, **changes) -> GearTrain:
        return dataclasses.replace(self, **changes)


def _array(r: Reader, value, where: str, what: str) -> list:
    """``value`` as a list; ``what`` names the ``scene.array.`` sentence of its items."""
    if not isinstance(value, list):
        raise r.fail(where, "array_of", what=Text(f"scene.array.{what}"), value=given(value))
    return value


def _check_carriers(members: dict[int, GearMember], r: Reader) -> None:
    """A carrier cannot be carried, through any chain, by a member it carries (or by itself):
    following carriers from any member must end at one on a fixed axis."""
    for start in members.values():
        seen = [start.number]
        carrier = start.carrier
        while carrier is not None:
            if carrier in seen:
                chain = " → ".join(map(str, [*seen[seen.index(carrier):], carrier]))
                raise r.fail(f"members.{start.number}.carrier", "carrier_cycle", chain=chain)
            seen.append(carrier)
            carrier = members[carrier].carrier


def parse_gears(raw: dict, source: str, default_id: str) -> GearTrain:
    r = Reader(source)
    r.check_keys(raw, TOP_KEYS, "")
    limits.count(raw, limits.GEARS, r.fail)
    table = raw.get("members")
    if not isinstance(table, dict) or not table:
        raise r.fail("members", "gear_members_missing")
    members = {}
    for key, spec in table.items():
        where = f"members.{key}"
        if not key.isdigit() or int(key) < 1:
            raise r.fail(where, "gear_number")
        spec = r.check_keys(spec, MEMBER_KEYS, where)
        carrier = spec.get("carrier")
        members[int(key)] = GearMember(
            int(key), r.text(spec, "label", where, default=""),
            None if carrier is None else r.integer(spec, "carrier", where),
            r.number(spec, "axis", where, default=0.0, non_negative=True),
            spec.get("x") if spec.get("x") is None else r.number(spec, "x", where))
    known = set(members)

    def member(value, where: str) -> int:
        if isinstance(value, bool) or not isinstance(value, int) or value not in known:
            raise r.fail(where, "one_of_members", known=sorted(known), value=given(value))
        return value

    for m in members.values():
        if m.carrier is not None:
            member(m.carrier, f"members.{m.number}.carrier")
            if m.axis <= 0:
                raise r.fail(f"members.{m.number}.axis", "planet_axis")
    _check_carriers(members, r)
    meshes = []
    for i, spec in enumerate(_array(r, raw.get("meshes", []), "meshes", "meshes")):
        where = f"meshes[{i}]"
        spec = r.check_keys(spec, MESH_KEYS, where)
        pair = spec.get("members")
        if not isinstance(pair, list) or len(pair) != 2:
            raise r.fail(f"{where}.members", "two_members", value=given(pair))
        a, b = (member(m, f"{where}.members") for m in pair)
        if "radii" in spec:
            radii = spec["radii"]
            if not isinstance(radii, list) or len(radii) != 2:
                raise r.fail(f"{where}.radii", "two_radii")
            radii = tuple(r.number({f"radii[{k}]": v}, f"radii[{k}]", where, positive=True)
                          for k, v in enumerate(radii))
        elif "teeth" in spec:
            module = r.number(spec, "module", where, default=0.001, positive=True)
            teeth = spec["teeth"]
            if not isinstance(teeth, list) or len(teeth) != 2 or not all(
                    isinstance(z, int) and not isinstance(z, bool) and z > 0 for z in teeth):
                raise r.fail(f"{where}.teeth", "two_teeth", value=given(teeth))
            radii = tuple(module * z / 2 for z in teeth)
        else:
            raise r.fail(where, "mesh_size")
        internal = spec.get("internal")
        if internal is not None:
            internal = member(internal, f"{where}.internal")
            if internal not in (a, b):
                raise r.fail(f"{where}.internal", "internal_member")
        bevel = spec.get("bevel", False)
        if not isinstance(bevel, bool):
            raise r.fail(f"{where}.bevel", "not_flag", value=given(bevel))
        meshes.append(Mesh((a, b), radii, internal, bevel))
    shafts = tuple(tuple(member(m, f"shafts[{i}]")
                         for m in _array(r, group, f"shafts[{i}]", "members"))
                   for i, group in enumerate(_array(r, raw.get("shafts", []), "shafts",
                                                    "shafts")))
    fixed = tuple(member(m, "fixed") for m in _array(r, raw.get("fixed", []), "fixed",
                                                       "members"))
    inputs = []
    for i, spec in enumerate(_array(r, raw.get("inputs", []), "inputs", "inputs")):
        where = f"inputs[{i}]"
        spec = r.check_keys(spec, INPUT_KEYS, where)
        m = member(spec.get("member"), f"{where}.member")
        if m in fixed:
            raise r.fail(f"{where}.member", "fixed_input", member=m)
        if "omega" in spec:
            inputs.append(Input(m, r.number(spec, "omega", where)))
        else:
            v = r.number(spec, "velocity", where)
            radius = r.number(spec, "radius", where, positive=True)
            inputs.append(Input(m, v / radius, v, radius))
    points = {}
    table = raw.get("points", {})
    if not isinstance(table, dict):
        raise r.fail("points", "gear_points", value=given(table))
    for name, value in table.items():
        if not (isinstance(value, list) and len(value) == 2):
            raise r.fail(f"points.{name}", "gear_point")
        points[name] = (member(value[0], f"points.{name}"),
                        r.number({"r": value[1]}, "r", f"points.{name}", non_negative=True))
    return GearTrain(
        **identity(raw, r, default_id),
        members=dict(sorted(members.items())), meshes=tuple(meshes), shafts=shafts, fixed=fixed,
        inputs=tuple(inputs), points=points)


__all__ = ["GearMember", "GearTrain", "Input", "Mesh", "SceneError", "parse_gears"]
