"""Read and validate linkage scene files (TOML, standard library ``tomllib``).

Scene files are data only: they are parsed, never executed. Every rule broken is
reported with the file, the key and the rule, e.g.
``four-bar.toml: members.3.length must be > 0, got -0.2``.
The format is documented in ``docs/scene-format.md``.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import re
import tomllib
from pathlib import Path
from typing import Any

from . import limits
from .formula import formula_keys
from .messages import Text, given, text_of
from .point_forms import FormError, form_of, from_distances, from_polar
from .reader import Reader, SceneError, identity
from .schema import DRIVER, FRAME, Driver, Fit, Force, Member, Moment, Pair, Scene, Travel

PRESETS = Path(__file__).parent / "presets"
MAX_BYTES = 100_000  # the largest preset is 4 kB; refused before parsing (800 kB took 0.25 s)

TOP_KEYS = {"id", "kind", "title", "title_sr", "source", "note", "note_sr", "source_sr", "gravity", "inertia", "pairs", "frame",
            "driver", "members", "assembly", "forces", "moments", "book", "travel", "book_notes", "book_notes_sr",
            "scales", "guess", "special", "layout_assumed", "fit", "book_slips"}
FIT_KEYS = {"unknowns", "start", "used", "residual", "chose"}
SCALE_KEYS = {"L", "v", "a", "F"}
TRAVEL_KEYS = {"speed", "wheel_radius", "sprocket_wheel", "sprocket_crank", "angle"}
MEMBER_KEYS = {"points", "length", "extra", "mass", "centre", "gyration", "label"}
PAIR_KEYS = {"type", "members", "point", "name", "guide", "slider", "through", "angle", "centre",
             "slider_angle"}
DRIVER_KEYS = {"member", "type", "at", "omega", "epsilon", "velocity", "acceleration"}
FORCE_KEYS = {"member", "point", "magnitude", "angle", "follows_member", "label"}
MOMENT_KEYS = {"member", "value"}


def load_scene(path: str | Path):
    """Load a scene of any kind (linkage, rotor, …) from a TOML file."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise SceneError(Text("scene.unreadable", source=str(path), reason=exc.strerror or "")) from None
    return parse_document(data, source=path.name, default_id=path.stem)


def load_preset(preset_id: str):
    """Load a preset by its id (``analitika-2.1``, ``zbirka-1.3``, ``zbirka-7.1``, …)."""
    return load_scene(_preset_path(preset_id))


def preset_document(preset_id: str) -> dict:
    """A preset's TOML table as its file writes it (teeth stay teeth): what a variant or a fit
    changes numbers in before ``build_document`` makes it a scene again."""
    path = _preset_path(preset_id)
    return read_toml(path.read_bytes(), path.name)


def _preset_path(preset_id: str) -> Path:
    path = PRESETS / f"{preset_id}.toml"
    if not path.is_file():
        known = ", ".join(preset_ids())
        raise SceneError(Text("scene.no_preset", name=preset_id, known=known))
    return path


def preset_ids(kind: str | None = None) -> list[str]:
    """Preset ids, optionally only those of one kind ("linkage", "rotor", …)."""
    return list(_preset_ids(kind))


@functools.cache
def _preset_ids(kind: str | None) -> tuple[str, ...]:
    """Read once: the presets ship with the code (every page's scene box asks on each rerun)."""
    ids = sorted(p.stem for p in PRESETS.glob("*.toml"))
    return tuple(i for i in ids if kind is None or _kind_of(PRESETS / f"{i}.toml") == kind)


def _kind_of(path: Path) -> str:
    for line in path.read_text(encoding="utf-8").splitlines():
        if line.startswith("kind"):
            return line.split("=", 1)[1].strip().strip('"')
        if line.startswith("["):
            break
    return "linkage"


def load_any(name: str):
    """A preset id or a path to a TOML file, as the command line accepts."""
    if name.endswith(".toml") or "/" in name:
        return load_scene(name)
    return load_preset(name)


def parse_document(data: bytes | str, source: str = "<scene>", default_id: str = "scene"):
    """Parse any scene kind: the top-level ``kind`` key chooses the schema."""
    return build_document(read_toml(data, source), source, default_id)


def build_document(raw: dict, source: str = "<scene>", default_id: str = "scene"):
    """A scene of any kind from its TOML table (a file's, or one made in code: a variant's)."""
    kind = raw.get("kind", "linkage")
    if kind == "rotor":
        from .rotor import parse_rotor

        return parse_rotor(raw, source, default_id)
    if kind == "gears":
        from .gears import parse_gears

        return parse_gears(raw, source, default_id)
    return _build(raw, Reader(source), default_id)


def as_loaded(scene, source: str = "<table>"):
    """``scene`` (made from a page's table) held to the rules a scene file is: written as
    the download writes it and read back by the loader, which raises its SceneError where
    the file would be refused. So a table is checked by the one validator, and no scene
    the loader refuses is solved, drawn or written."""
    from .writer import to_text

    return parse_document(to_text(scene), source, scene.id)


def parse_scene(data: bytes | str, source: str = "<scene>", default_id: str = "scene") -> Scene:
    """Parse and validate a linkage scene (bytes from an upload or a file)."""
    return _build(read_toml(data, source), Reader(source), default_id)


def build_scene(raw: dict, source: str = "builder", default_id: str = "my-mechanism") -> Scene:
    """Validate a scene document made elsewhere (the builder's tables): the table a TOML file
    parses to, checked by the same rules with the same messages."""
    return _build(raw, Reader(source), default_id)


def read_toml(data: bytes | str, source: str) -> dict:
    """Bytes → TOML table, refusing what is too big, not UTF-8 or not TOML."""
    if isinstance(data, str):
        data = data.encode("utf-8")
    if len(data) > MAX_BYTES:
        raise SceneError(Text("scene.file_too_big", source=source, size=len(data), most=MAX_BYTES))
    try:
        text = data.decode("utf-8-sig")  # Windows Notepad starts UTF-8 with a byte-order mark
    except UnicodeDecodeError as exc:
        raise SceneError(Text("scene.not_utf8", source=source, byte=exc.start)) from None
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(_toml_error(exc, source)) from None
    except RecursionError:
        raise SceneError(Text("scene.too_deep", source=source)) from None
    return raw


# the TOML parser's reasons (Python 3.11's tomllib), by how they start, in the reader's words
TOML_REASONS = {"Cannot overwrite a value": "overwrite", "Cannot declare": "twice",
                "Cannot mutate immutable namespace": "twice", "Cannot redefine namespace": "twice",
                "Duplicate inline table key": "twice", "Unterminated string": "unterminated",
                "Unclosed array": "unclosed_array", "Unclosed inline table": "unclosed_table",
                "Invalid value": "value", "Invalid statement": "statement",
                "Expected '=' after a key": "equals", "Invalid initial character for a key part": "key",
                "Illegal character": "character", "Found invalid character": "character",
                "Expected ']]'": "brackets", "Expected ']'": "bracket", "Expected newline": "newline",
                "Unescaped '\\'": "escape", "Invalid hex value": "escape",
                "Escaped character is not": "escape", "Invalid date or datetime": "date",
                "Expected": "expected"}


def _toml_error(exc: tomllib.TOMLDecodeError, source: str) -> Text:
    """The parser's message as a sentence in the reader's language, its place kept."""
    message = str(exc)
    place = re.search(r" \(at (?:line (\d+), column (\d+)|end of document)\)$", message)
    reason = message[:place.start()] if place else message
    known = next((key for start, key in TOML_REASONS.items() if reason.startswith(start)), None)
    said = Text(f"toml.{known or 'other'}")
    where = ("" if place is None else Text("toml.end") if place[1] is None
             else Text("toml.at", line=int(place[1]), column=int(place[2])))
    return Text("scene.not_toml", source=source, where=where, reason=said)


def _build(raw: dict, r: Reader, default_id: str) -> Scene:
    r.check_keys(raw, TOP_KEYS, "")
    limits.count(raw, limits.LINKAGE, r.fail)
    limits.count_points(raw, r.fail)
    kind = r.text(raw, "kind", "", default="linkage")
    if kind != "linkage":
        raise r.fail("kind", "not_linkage", kind=given(kind))
    frame = _frame(raw, r)
    members = _members(raw, r)
    pairs = _pairs(raw, r, frame, members)
    driver = _driver(raw, r, members, pairs)
    scene = Scene(
        **identity(raw, r, default_id),
        frame=frame,
        members=members,
        pairs=pairs,
        driver=driver,
        assembly=_assembly(raw, r, members),
        forces=_forces(raw, r, members, frame),
        moments=_moments(raw, r, members),
        gravity=r.number(raw, "gravity", "", default=0.0, non_negative=True),
        inertia=_flag(raw, r, "inertia", default=True),
        scales=_scales(raw, r),
        guess=_guess(raw, r),
        special=_special(raw, r, members),
        layout_assumed=_flag(raw, r, "layout_assumed"),
    )
    if "fit" in raw:
        scene = dataclasses.replace(scene, fit=_fit(raw, r, scene.book))
    if "book_slips" in raw:
        scene = dataclasses.replace(scene, book_slips=_slips(raw, r, scene.book))
    if scene.guess:
        scene = dataclasses.replace(scene, guess_at=driver.at)
    if "travel" in raw:
        scene = scene.with_(travel=_travel(raw, r, driver))
    _check_every_member_is_joined(scene, r)
    _check_shared_points_are_joints(scene, r)
    return scene


def _frame(raw: dict, r: Reader) -> dict[str, complex]:
    table = raw.get("frame")
    if table is None:
        raise r.fail("frame", "frame_missing")
    if not isinstance(table, dict) or not table:
        raise r.fail("frame", "frame_table")
    frame = {name: r.vector(v, f"frame.{name}") for name, v in table.items()}
    names = list(frame)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if frame[a] == frame[b]:
                raise r.fail(f"frame.{b}", "pivots_coincide", other=f"frame.{a}")
    return frame


def _members(raw: dict, r: Reader) -> dict[int, Member]:
    table = raw.get("members")
    if not isinstance(table, dict) or not table:
        raise r.fail("members", "members_missing")
    members = {}
    for key, spec in table.items():
        where = f"members.{key}"
        if not key.isdigit() or int(key) < 2:
            raise r.fail(where, "member_number")
        spec = r.check_keys(spec, MEMBER_KEYS, where)
        members[int(key)] = _member(int(key), spec, r, where)
    if DRIVER not in members:
        raise r.fail("members.2", "driver_missing")
    return dict(sorted(members.items()))


def _member(number: int, spec: dict, r: Reader, where: str) -> Member:
    axis = spec.get("points")
    if (not isinstance(axis, list) or not 1 <= len(axis) <= 2
            or not all(isinstance(p, str) and p for p in axis) or len(set(axis)) != len(axis)):
        raise r.fail(f"{where}.points", "point_letters", value=given(axis))
    points = {axis[0]: 0j}
    if len(axis) == 2:
        points[axis[1]] = complex(r.number(spec, "length", where, positive=True))
    elif "length" in spec:
        raise r.fail(f"{where}.length", "one_point_length")
    extra = spec.get("extra", {})
    if not isinstance(extra, dict):
        raise r.fail(f"{where}.extra", "extra_table")
    forms = {}
    for name, value in extra.items():
        length = points[axis[1]].real if len(axis) == 2 else None
        z = _extra_point(value, r, f"{where}.extra.{name}", length, Text("scene.point_of_member", point=name,
                                                                    member=number))
        if isinstance(value, dict):
            forms[name] = form_of(value)
        if name in points:
            raise r.fail(f"{where}.extra.{name}", "repeats_point")
        for other, w in points.items():
            if z == w:
                raise r.fail(f"{where}.extra.{name}", "point_coincides", other=other)
        points[name] = z
    centre = spec.get("centre")
    return Member(
        number=number,
        points=points,
        axis=tuple(axis),
        mass=r.number(spec, "mass", where, default=0.0, non_negative=True),
        centre=None if centre is None else r.vector(centre, f"{where}.centre"),
        gyration=r.number(spec, "gyration", where, default=0.0, non_negative=True),
        label=r.text(spec, "label", where, default=""),
        forms=forms,
    )


def _extra_point(value: Any, r: Reader, where: str, length: float | None, who: str) -> complex:
    """A member's extra point in any of its forms (mechanisms.point_forms): the shape of the
    value checked here, with the file's messages; the geometry (a triangle that closes) there."""
    if not isinstance(value, dict):
        return r.vector(value, where)
    form = form_of(value)
    try:
        if form == "distances":
            r.check_keys(value, {"distances", "side"}, where)
            d = r.vector(value["distances"], f"{where}.distances")
            return from_distances(d.real, d.imag, r.text(value, "side", where), length)
        if form == "polar":
            r.check_keys(value, {"polar"}, where)
            p = r.vector(value["polar"], f"{where}.polar")
            return from_polar(p.real, p.imag)
    except FormError as exc:
        raise r.fail(where, "point_form", who=who, reason=text_of(exc)) from None
    raise r.fail(where, "point_form", who=who, reason=Text("form.unknown", value=given(value)))


def _member_ref(value: Any, r: Reader, where: str, members: dict[int, Member]) -> int:
    if isinstance(value, bool) or not isinstance(value, int):
        raise r.fail(where, "not_member_number", value=given(value))
    if value != 1 and value not in members:
        raise r.fail(where, "no_member", member=value)
    return value


def _point_ref(value: Any, member: int, r: Reader, where: str, frame: dict,
               members: dict[int, Member]) -> str:
    own = frame if member == FRAME else members[member].points
    if not isinstance(value, str) or value not in own:
        raise r.fail(where, "not_point_of", member=member, points=", ".join(own), value=given(value))
    return value


def _pairs(raw: dict, r: Reader, frame: dict, members: dict[int, Member]) -> tuple[Pair, ...]:
    specs = raw.get("pairs")
    if not isinstance(specs, list) or not specs:
        raise r.fail("pairs", "pairs_missing")
    pairs = []
    for i, spec in enumerate(specs):
        where = f"pairs[{i}]"
        spec = r.check_keys(spec, PAIR_KEYS, where)
        kind = spec.get("type")
        if kind == "revolute":
            ms = spec.get("members")
            if not isinstance(ms, list) or len(ms) != 2:
                raise r.fail(f"{where}.members", "two_members", value=given(ms))
            a, b = (_member_ref(m, r, f"{where}.members", members) for m in ms)
            if a == b:
                raise r.fail(f"{where}.members", "same_member")
            point = spec.get("point")
            for m in (a, b):
                _point_ref(point, m, r, f"{where}.point", frame, members)
            taken = {q.name for q in pairs}
            auto = point if point not in taken else f"{point}:{a}-{b}"
            pair = Pair("revolute", (a, b), point, name=r.text(spec, "name", where, default=auto))
        elif kind == "prismatic":
            guide = _member_ref(spec.get("guide"), r, f"{where}.guide", members)
            slider = _member_ref(spec.get("slider"), r, f"{where}.slider", members)
            if guide == slider:
                raise r.fail(f"{where}.slider", "slider_is_guide")
            pair = Pair(
                "prismatic", (guide, slider),
                point=_point_ref(spec.get("point"), slider, r, f"{where}.point", frame, members),
                through=_point_ref(spec.get("through"), guide, r, f"{where}.through", frame, members),
                angle=math.radians(r.number(spec, "angle", where, default=0.0)),
                slider_angle=math.radians(r.number(spec, "slider_angle", where, default=0.0)),
                name=r.text(spec, "name", where, default=f"{guide}-{slider}"),
            )
        elif kind == "circular":
            pair = _circular(spec, r, where, frame, members)
        else:
            raise r.fail(f"{where}.type", "pair_type", value=given(kind))
        pairs.append(pair)
    names = [p.name for p in pairs]
    for i, name in enumerate(names):
        if name in names[:i]:
            raise r.fail(f"pairs[{i}].name", "pair_name", name=name)
    return tuple(pairs)


def _circular(spec: dict, r: Reader, where: str, frame: dict, members: dict[int, Member]) -> Pair:
    """A block in a circular slot of the guide member: the block carries the slot's centre
    as a point (its distance from the block's point is the radius), shared with the guide."""
    guide = _member_ref(spec.get("guide"), r, f"{where}.guide", members)
    slider = _member_ref(spec.get("slider"), r, f"{where}.slider", members)
    if slider == FRAME or guide == slider:
        raise r.fail(f"{where}.slider", "slot_slider")
    point = _point_ref(spec.get("point"), slider, r, f"{where}.point", frame, members)
    centre = spec.get("centre")
    for m in (guide, slider):
        _point_ref(centre, m, r, f"{where}.centre", frame, members)
    if centre == point:
        raise r.fail(f"{where}.centre", "slot_centre")
    return Pair("revolute", (guide, slider), centre, on_slot=point,
                name=r.text(spec, "name", where, default=f"{guide}-{slider}"))


def _driver(raw: dict, r: Reader, members: dict[int, Member], pairs: tuple[Pair, ...]) -> Driver:
    spec = r.check_keys(raw.get("driver"), DRIVER_KEYS, "driver") if "driver" in raw else None
    if spec is None:
        raise r.fail("driver", "no_driver")
    member = spec.get("member", DRIVER)
    if member != DRIVER:
        raise r.fail("driver.member", "driver_member", value=given(member))
    kind = spec.get("type")
    if kind == "rotating":
        pair = next((p for p in pairs if p.kind == "revolute" and set(p.members) == {1, 2}), None)
        if pair is None:
            raise r.fail("driver.type", "no_crank_pair")
        if members[DRIVER].points[pair.point] != 0:
            raise r.fail("members.2.points", "crank_start", point=pair.point)
        return Driver("rotating", DRIVER, pair.name,
                      at=math.radians(r.number(spec, "at", "driver", default=0.0)),
                      speed=r.number(spec, "omega", "driver"),
                      accel=r.number(spec, "epsilon", "driver", default=0.0))
    if kind == "linear":
        pair = next((p for p in pairs if p.kind == "prismatic" and p.members == (1, 2)), None)
        if pair is None:
            raise r.fail("driver.type", "no_slide_pair")
        return Driver("linear", DRIVER, pair.name,
                      at=r.number(spec, "at", "driver", default=0.0),
                      speed=r.number(spec, "velocity", "driver"),
                      accel=r.number(spec, "acceleration", "driver", default=0.0))
    raise r.fail("driver.type", "driver_type", value=given(kind))


def _assembly(raw: dict, r: Reader, members: dict[int, Member]) -> dict[tuple[int, int], int]:
    table = raw.get("assembly", {})
    if not isinstance(table, dict):
        raise r.fail("assembly", "assembly_table")
    out = {}
    for key, value in table.items():
        parts = key.split("-")
        if len(parts) != 2 or not all(p.isdigit() and int(p) in members for p in parts):
            raise r.fail(f"assembly.{key}", "assembly_key")
        if value not in (1, -1) or isinstance(value, bool):
            raise r.fail(f"assembly.{key}", "assembly_sign", value=given(value))
        out[tuple(sorted(int(p) for p in parts))] = value
    return out


def _tables(raw: dict, r: Reader, name: str, allowed: set[str]):
    """(where, spec) for each table of the array ``[[name]]``, keys checked."""
    specs = raw.get(name, [])
    if not isinstance(specs, list):
        raise r.fail(name, "array_of_tables", name=name)
    for i, spec in enumerate(specs):
        where = f"{name}[{i}]"
        yield where, r.check_keys(spec, allowed, where)


def _flag(table: dict, r: Reader, name: str, where: str = "", default: bool = False) -> bool:
    value = table.get(name, default)
    if not isinstance(value, bool):
        raise r.fail(f"{where}.{name}" if where else name, "not_flag", value=given(value))
    return value


def _forces(raw: dict, r: Reader, members: dict[int, Member], frame: dict) -> tuple[Force, ...]:
    forces = []
    for where, spec in _tables(raw, r, "forces", FORCE_KEYS):
        member = _member_ref(spec.get("member"), r, f"{where}.member", members)
        follows = _flag(spec, r, "follows_member", where)
        point = _point_ref(spec.get("point"), member, r, f"{where}.point", frame, members)
        forces.append(Force(member, point, r.number(spec, "magnitude", where),
                            math.radians(r.number(spec, "angle", where, default=0.0)), follows,
                            r.text(spec, "label", where, default="")))
    return tuple(forces)


def _moments(raw: dict, r: Reader, members: dict[int, Member]) -> tuple[Moment, ...]:
    return tuple(Moment(_member_ref(spec.get("member"), r, f"{where}.member", members),
                        r.number(spec, "value", where))
                 for where, spec in _tables(raw, r, "moments", MOMENT_KEYS))


def _scales(raw: dict, r: Reader) -> dict[str, float]:
    """The book's drawing scales: how much one centimetre of the drawing stands for."""
    spec = r.check_keys(raw.get("scales", {}), SCALE_KEYS, "scales")
    return {k: r.number(spec, k, "scales", positive=True) for k in spec}


def _fit(raw: dict, r: Reader, book: dict[str, float]) -> Fit:
    spec = r.check_keys(raw["fit"], FIT_KEYS, "fit")
    unknowns, start, used = (spec.get(k) for k in ("unknowns", "start", "used"))
    if not (isinstance(unknowns, list) and unknowns and all(isinstance(u, str) for u in unknowns)):
        raise r.fail("fit.unknowns", "fit_unknowns")
    if not (isinstance(start, list) and len(start) == len(unknowns)):
        raise r.fail("fit.start", "fit_start", count=len(unknowns))
    if not (isinstance(used, list) and used and all(isinstance(k, str) and k in book for k in used)):
        raise r.fail("fit.used", "fit_used")
    chose = spec.get("chose", [])
    if not (isinstance(chose, list)
            and all(isinstance(k, str) and k in book and k not in used for k in chose)):
        raise r.fail("fit.chose", "fit_chose")
    return Fit(tuple(unknowns), tuple(r.number({"v": v}, "v", "fit.start") for v in start),
               tuple(used), r.number(spec, "residual", "fit", non_negative=True), tuple(chose))


def _slips(raw: dict, r: Reader, book: dict[str, float]) -> dict[str, str]:
    table = raw["book_slips"]
    if not isinstance(table, dict):
        raise r.fail("book_slips", "slips_table")
    for key, formula in table.items():
        if key not in book:
            raise r.fail(f"book_slips.{key}", "slip_key")
        try:
            formula_keys(r.text(table, key, "book_slips"))
        except ValueError as error:
            raise r.fail(f"book_slips.{key}", text_of(error)) from None
    return dict(table)


def _guess(raw: dict, r: Reader) -> dict[str, complex]:
    table = raw.get("guess", {})
    if not isinstance(table, dict):
        raise r.fail("guess", "guess_table")
    return {name: r.vector(v, f"guess.{name}") for name, v in table.items()}


def _special(raw: dict, r: Reader, members: dict[int, Member]) -> dict[str, tuple[int, int]]:
    table = raw.get("special", {})
    if not isinstance(table, dict):
        raise r.fail("special", "special_table")
    out = {}
    for name, value in table.items():
        if (not isinstance(value, list) or len(value) != 2 or len(set(map(str, value))) != 2
                or not all(isinstance(m, int) and not isinstance(m, bool) and m in members
                           for m in value)):
            raise r.fail(f"special.{name}", "special_point", value=given(value))
        out[name] = (value[0], value[1])
    return out


def _travel(raw: dict, r: Reader, driver: Driver) -> Travel:
    spec = r.check_keys(raw["travel"], TRAVEL_KEYS, "travel")
    if driver.kind != "rotating":
        raise r.fail("travel", "travel_driver")
    return Travel(*(r.number(spec, k, "travel", positive=True)
                    for k in ("speed", "wheel_radius", "sprocket_wheel", "sprocket_crank")),
                  angle=math.radians(r.number(spec, "angle", "travel", default=0.0)))


def _check_shared_points_are_joints(scene: Scene, r: Reader) -> None:
    """A letter on several members names one place: those members must be pinned there."""
    owners: dict[str, list[int]] = {}
    for number in [1, *scene.members]:
        for name in scene.points_of(number):
            owners.setdefault(name, []).append(number)
    for name, members in owners.items():
        group = {members[0]}
        grown = True
        while grown:
            grown = False
            for p in scene.pairs:
                if p.kind == "revolute" and p.point == name and len(group & set(p.members)) == 1:
                    group |= set(p.members)
                    grown = True
        loose = [m for m in members if m not in group]
        if loose:
            raise r.fail(f"members.{loose[0]}.points", "loose_letter", point=name, member=members[0])


def _check_every_member_is_joined(scene: Scene, r: Reader) -> None:
    for number in scene.members:
        if not any(number in p.members for p in scene.pairs):
            raise r.fail(f"members.{number}", "not_joined")
        if len(scene.members[number].axis) == 1 and not any(
                p.kind == "prismatic" and number in p.members for p in scene.pairs):
            raise r.fail(f"members.{number}.points", "one_point_member")
