"""A mechanism as a student lays it out: tables of numbers and points drawn at one instant.

The builder page keeps a scene *document* — the very table the TOML loader reads
(``tomllib.loads`` of a scene file) — and edits it two ways:

* **tables** (``tables`` / ``document``): frame points, members, extra points, pairs,
  loads and the driver as rows of plain values, the way ``st.data_editor`` shows them;
* **drawing** (``drag``): a point moved on the figure changes the lengths and offsets of
  the members that carry it, so that the mechanism, re-solved, passes through it.

Either way the document becomes a ``Scene`` only through ``loader.build_scene``, the same
validation as a file. Every drawn position is written to ``[guess]``, so the solver takes
the assembly of every Assur group that is closest to the drawing: no ±1 signs.
"""

from __future__ import annotations

import cmath
import copy
import math
import tomllib
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from .point_forms import FORMS, FormError, every_form, form_of, local_point, written
from .schema import DRIVER, FRAME, Scene
from .writer import to_toml

TEMPLATES = Path(__file__).parent / "templates"
TABLES = ("frame", "members", "extra", "pairs", "forces", "moments")
COLUMNS = {
    "frame": ("point", "x", "y"),
    "members": ("member", "label", "first", "second", "length", "mass", "centre_along",
                "centre_left", "gyration"),
    "extra": ("member", "point", "form", "along", "left", "d1", "d2", "side", "r", "theta"),
    "pairs": ("type", "p", "q", "point", "through", "angle", "slider_angle"),
    "forces": ("member", "point", "magnitude", "angle", "follows_member", "label"),
    "moments": ("member", "value"),
}
FORM_COLUMNS = {"offset": ("along", "left"), "distances": ("d1", "d2", "side"),
                "polar": ("r", "theta")}  # a point's form is typed in these; the rest show it
DRIVER_KEYS = ("type", "at", "speed", "accel")  # at: ° or m; speed: rad/s or m/s
KEEP = ("id", "title", "title_sr", "source", "source_sr", "note", "note_sr", "gravity",
        "scales", "special")  # what the tables do not show, carried over unchanged


ORDER = ("four-bar", "slider-crank", "slotted-lever", "inverted-slider-crank", "watt-six-bar",
         "stephenson-six-bar", "class-iii", "linear-drive")  # simplest first


def template_ids() -> list[str]:
    """The templates, simplest first (any file not named in ORDER after them)."""
    found = {p.stem for p in TEMPLATES.glob("*.toml")}
    return [n for n in ORDER if n in found] + sorted(found - set(ORDER))


def template(name: str) -> dict:
    """A template's document (the four-bar, the slider-crank, …)."""
    with open(TEMPLATES / f"{name}.toml", "rb") as f:
        return tomllib.load(f)


def from_scene(scene: Scene, positions: Mapping[str, complex]) -> dict:
    """A scene's document to start building from, drawn at ``positions`` (its instant): the
    book's printed values stay behind (they belong to the task, not to a changed mechanism),
    and the drawing replaces the ±1 signs."""
    doc = tomllib.loads(to_toml(scene))
    for key in ("book", "book_notes", "book_notes_sr", "book_slips", "layout_assumed", "fit",
                "assembly", "travel"):
        doc.pop(key, None)
    doc["guess"] = drawn(doc, positions)
    return doc


def _blank(value: Any) -> bool:
    return value is None or (isinstance(value, float) and math.isnan(value)) or value == ""


def _num(value: Any) -> Any:
    """A cell's number as the loader wants it (a float, or the cell as typed to be refused)."""
    if isinstance(value, bool):
        return value
    if isinstance(value, (int, float)):
        return float(value)
    return value


def _int(value: Any) -> Any:
    if isinstance(value, float) and value.is_integer():
        return int(value)
    return value


def required(table: str, row: Mapping[str, Any]) -> tuple[str, ...]:
    """The cells a filled row of ``table`` must have (``document`` would skip the row, or
    the loader name an internal key, without them): a frame point's name, x and y; a
    member's number and, with two points, its length; a point's member, name and cells in
    the form it is given in; a pair's type, members and point (a sliding pair's line too);
    a force's member, point, size and angle; a moment's member and value.
    (ui.editor_tables refuses a row with one of them blank, at that cell.)"""
    if table == "frame":
        return ("point", "x", "y")
    if table == "members":
        two = not (_blank(row.get("first")) or _blank(row.get("second")))
        return ("member", "length") if two else ("member",)
    if table == "extra":
        form = FORM_COLUMNS.get(row.get("form") or "offset", ())
        return ("member", "point", *(c for c in form if c != "side"))
    if table == "pairs":
        return ("type", "p", "q", "point") + (("through",) if row.get("type") == "prismatic" else ())
    if table == "forces":
        return ("member", "point", "magnitude", "angle")
    if table == "moments":
        return ("member", "value")
    return ()


def tables(doc: dict) -> dict[str, list[dict]]:
    """The document as rows of plain values, one list per table (blank cells are None)."""
    out: dict[str, list[dict]] = {name: [] for name in TABLES}
    for name, xy in doc.get("frame", {}).items():
        out["frame"].append({"point": name, "x": xy[0], "y": xy[1]})
    for number, spec in doc.get("members", {}).items():
        axis = list(spec.get("points", [])) + [None, None]
        centre = spec.get("centre") or [None, None]
        out["members"].append({
            "member": int(number), "label": spec.get("label", ""), "first": axis[0],
            "second": axis[1], "length": spec.get("length"), "mass": spec.get("mass"),
            "centre_along": centre[0], "centre_left": centre[1], "gyration": spec.get("gyration")})
        for name, value in spec.get("extra", {}).items():
            out["extra"].append(_extra_row(int(number), name, value, spec))
    for p in doc.get("pairs", []):
        if p.get("type") == "prismatic":
            out["pairs"].append({"type": "prismatic", "p": p.get("guide"), "q": p.get("slider"),
                                 "point": p.get("point"), "through": p.get("through"),
                                 "angle": p.get("angle", 0.0),
                                 "slider_angle": p.get("slider_angle", 0.0)})
        elif p.get("type") == "circular":  # "through" holds the slot's centre
            out["pairs"].append({"type": "circular", "p": p.get("guide"), "q": p.get("slider"),
                                 "point": p.get("point"), "through": p.get("centre"),
                                 "angle": None, "slider_angle": None})
        else:
            p_, q_ = (list(p.get("members", [])) + [None, None])[:2]
            out["pairs"].append({"type": "revolute", "p": p_, "q": q_, "point": p.get("point"),
                                 "through": None, "angle": None, "slider_angle": None})
    for f in doc.get("forces", []):
        out["forces"].append({k: f.get(k) for k in COLUMNS["forces"]})
    for m in doc.get("moments", []):
        out["moments"].append({k: m.get(k) for k in COLUMNS["moments"]})
    return out


def driver_values(doc: dict) -> dict:
    d = doc.get("driver", {})
    linear = d.get("type") == "linear"
    return {"type": d.get("type", "rotating"), "at": d.get("at", 0.0),
            "speed": d.get("velocity" if linear else "omega", 0.0),
            "accel": d.get("acceleration" if linear else "epsilon", 0.0)}


def document(rows: Mapping[str, list[dict]], driver: Mapping[str, Any], base: dict) -> dict:
    """The document the tables and the driver say, with what they do not show kept from
    ``base`` (titles, scales, the drawn positions). Blank rows are skipped; a half-filled row
    is kept as it is, so that the loader names what is missing."""
    doc = {k: copy.deepcopy(base[k]) for k in KEEP if k in base}
    doc["frame"] = {str(r["point"]): [_num(r["x"]), _num(r["y"])]
                    for r in rows["frame"] if not _blank(r.get("point"))}
    members: dict[str, dict] = {}
    for r in rows["members"]:
        if _blank(r.get("member")):
            continue
        spec: dict[str, Any] = {"points": [str(r[k]) for k in ("first", "second")
                                           if not _blank(r.get(k))]}
        if not _blank(r.get("label")):
            spec["label"] = str(r["label"])
        for key in ("length", "mass", "gyration"):
            if not _blank(r.get(key)):
                spec[key] = _num(r[key])
        if not (_blank(r.get("centre_along")) and _blank(r.get("centre_left"))):
            spec["centre"] = [_num(0.0 if _blank(r.get(k)) else r[k])
                              for k in ("centre_along", "centre_left")]
        members[str(_int(r["member"]))] = spec
    for r in rows["extra"]:
        if _blank(r.get("member")) or _blank(r.get("point")):
            continue
        spec = members.setdefault(str(_int(r["member"])), {})
        spec.setdefault("extra", {})[str(r["point"])] = _extra_value(r)
    doc["members"] = members
    doc["pairs"] = [_pair(r) for r in rows["pairs"] if not _blank(r.get("type"))]
    doc["forces"] = [{k: (_int(r[k]) if k == "member" else _num(r[k])) for k in COLUMNS["forces"]
                      if not _blank(r.get(k))} for r in rows["forces"] if not _blank(r.get("member"))]
    doc["moments"] = [{k: (_int(r[k]) if k == "member" else _num(r[k])) for k in COLUMNS["moments"]
                       if not _blank(r.get(k))} for r in rows["moments"] if not _blank(r.get("member"))]
    linear = driver["type"] == "linear"
    doc["driver"] = {"type": driver["type"], "at": _num(driver["at"]),
                     ("velocity" if linear else "omega"): _num(driver["speed"]),
                     ("acceleration" if linear else "epsilon"): _num(driver["accel"])}
    doc["guess"] = {k: v for k, v in base.get("guess", {}).items()
                    if any(k in _points_of(s) for s in members.values())}
    return doc


def _extra_row(member: int, name: str, value: Any, spec: dict) -> dict:
    """A member's point as a row: its form's cells as written, the other forms' cells
    computed from them (blank where the point cannot be placed yet)."""
    form = form_of(value)
    row = {"member": member, "point": name, "form": form if form in FORMS else "offset",
           **{k: None for k in COLUMNS["extra"][3:]}}
    length = _length(spec)
    try:
        row.update(every_form(local_point(value, length), length))
    except (FormError, TypeError, ValueError):
        pass
    if form == "distances":
        (row["d1"], row["d2"]), row["side"] = _two(value.get("distances")), value.get("side")
    elif form == "polar":
        row["r"], row["theta"] = _two(value.get("polar"))
    elif isinstance(value, list):
        row["along"], row["left"] = _two(value)
    return row


def _length(spec: dict) -> Any:
    """A member's length as its row holds it, None for a one-point member (no second point
    to measure a triangle's side from)."""
    return spec.get("length") if len(spec.get("points", [])) == 2 else None


def _two(value: Any) -> tuple[Any, Any]:
    return tuple(value) if isinstance(value, list) and len(value) == 2 else (None, None)


def _extra_value(r: Mapping[str, Any]) -> Any:
    """A point row as the document writes it, in the row's form (blank numbers are 0 in the
    offset form, and left blank in the others, for the loader to name)."""
    form = r.get("form") if r.get("form") in FORMS else "offset"
    if form == "distances":
        value = {"distances": [_num(r.get("d1")), _num(r.get("d2"))]}
        return value if _blank(r.get("side")) else {**value, "side": str(r["side"])}
    if form == "polar":
        return {"polar": [_num(r.get("r")), _num(r.get("theta"))]}
    return [_num(0.0 if _blank(r.get(k)) else r[k]) for k in ("along", "left")]


def _pair(r: Mapping[str, Any]) -> dict:
    if r["type"] == "prismatic":
        pair = {"type": "prismatic", "guide": _int(r.get("p")), "slider": _int(r.get("q")),
                "point": r.get("point"), "through": r.get("through"),
                "angle": _num(0.0 if _blank(r.get("angle")) else r["angle"]),
                "slider_angle": _num(0.0 if _blank(r.get("slider_angle")) else r["slider_angle"])}
    elif r["type"] == "circular":
        pair = {"type": "circular", "guide": _int(r.get("p")), "slider": _int(r.get("q")),
                "point": r.get("point"), "centre": r.get("through")}
    else:
        pair = {"type": r["type"], "members": [_int(r.get("p")), _int(r.get("q"))],
                "point": r.get("point")}
    return {k: v for k, v in pair.items() if not _blank(v)}


def _points_of(spec: dict) -> list[str]:
    return list(spec.get("points", [])) + list(spec.get("extra", {}))


def drawn(doc: dict, positions: Mapping[str, complex]) -> dict[str, list[float]]:
    """``[guess]``: where the drawing puts every point of a moving member, rounded to a
    ten-thousandth of the mechanism's size (enough to tell two assemblies apart, and it
    keeps a link short)."""
    names = {p for spec in doc.get("members", {}).values() for p in _points_of(spec)}
    names -= set(doc.get("frame", {}))
    size = max((abs(z) for z in positions.values()), default=1.0) or 1.0
    digits = max(0, 4 - math.floor(math.log10(size)))
    return {n: [round(positions[n].real, digits), round(positions[n].imag, digits)]
            for n in sorted(names) if n in positions}


def _angle(z: complex) -> float:
    return math.atan2(z.imag, z.real)


def drag(doc: dict, positions: Mapping[str, complex], rotations: Mapping[int, complex],
         point: str, to: complex) -> dict:
    """The document after point ``point`` is moved to ``to`` on the drawing.

    ``positions`` and ``rotations`` (e^{iθ} per member) are the drawing as solved. A frame
    point moves; a member whose axis ends at the point takes the new length and direction;
    every other point stays where it is drawn, its offsets on its member recomputed (the
    way a figure is laid out to scale), and a centre of mass scales with the length. Guide
    lines keep their direction in the drawing. The driver's position follows the crank (or
    the slider), and every point's drawn place goes to ``[guess]``, so the re-solved
    mechanism passes through ``to`` (a slider's point: its foot on the guide).
    """
    doc = copy.deepcopy(doc)
    to = _onto_frame_guides(doc, positions, point, to)
    new = dict(positions)
    new[point] = to
    if point in doc.get("frame", {}):
        doc["frame"][point] = [to.real, to.imag]
    turn: dict[int, complex] = {FRAME: 1 + 0j}  # each member's new rotation
    for key, spec in doc.get("members", {}).items():
        number, axis = int(key), spec.get("points", [])
        turn[number] = rotations.get(number, 1 + 0j)
        if len(axis) == 2 and point in axis:
            a, b = (new[p] for p in axis)
            now = b - a  # zero when dragged onto its other end: the loader says why not
            factor = abs(now) / spec["length"]
            spec["length"] = abs(now)
            turn[number] = cmath.exp(1j * _angle(now)) if now else turn[number]
            for name in spec.get("extra", {}):  # stays where it is drawn (unless dragged)
                _move_extra(spec, name, (new[name] - a) / turn[number])
            if "centre" in spec:  # a mass property: follows the length, as with a slider
                spec["centre"] = [c * factor for c in spec["centre"]]
        elif point in spec.get("extra", {}) and axis and axis[0] in new:
            _move_extra(spec, point, (to - new[axis[0]]) / turn[number])
    for pair in doc.get("pairs", []):
        if pair.get("type") == "prismatic":
            g, s = pair["guide"], pair["slider"]
            line = cmath.exp(1j * math.radians(pair.get("angle", 0.0))) * rotations.get(g, 1 + 0j)
            pair["angle"] = math.degrees(_angle(line / turn.get(g, 1 + 0j)))
            if s in turn and len(doc["members"][str(s)].get("points", [])) == 2:
                pair["slider_angle"] = math.degrees(_angle(line / turn[s]))
    _driver_follows(doc, new, turn)
    doc["guess"] = drawn(doc, new)
    return doc


def _move_extra(spec: dict, name: str, local: complex) -> None:
    """A member's point at a new local place, written in the form its row uses."""
    old = spec["extra"][name]
    form = form_of(old)
    if form in ("distances", "polar"):
        spec["extra"][name] = written(form, local, _length(spec), old.get("side", "left"))
    else:
        spec["extra"][name] = [local.real, local.imag]


def _onto_frame_guides(doc: dict, positions: Mapping[str, complex], point: str,
                       to: complex) -> complex:
    """A slider's point dragged off a fixed guide goes to its foot on the guide (a moving
    guide turns to meet it instead)."""
    for pair in doc.get("pairs", []):
        if pair.get("type") == "prismatic" and pair.get("guide") == FRAME and pair.get("point") == point:
            line = cmath.exp(1j * math.radians(pair.get("angle", 0.0)))
            base = positions[pair["through"]]
            to = base + ((to - base) / line).real * line
    return to


def _driver_follows(doc: dict, new: Mapping[str, complex], turn: Mapping[int, complex]) -> None:
    driver = doc.get("driver", {})
    axis = doc["members"][str(DRIVER)].get("points", [])
    if driver.get("type") == "rotating" and len(axis) == 2:
        driver["at"] = math.degrees(_angle(new[axis[1]] - new[axis[0]])) % 360.0
    elif driver.get("type") == "linear":
        pair = next(p for p in doc["pairs"] if p.get("type") == "prismatic"
                    and p.get("guide") == FRAME and p.get("slider") == DRIVER)
        line = cmath.exp(1j * math.radians(pair.get("angle", 0.0)))
        driver["at"] = ((new[pair["point"]] - new[pair["through"]]) / line).real


def snap(z: complex, pixel: float) -> complex:
    """A place put with the mouse, on the roundest grid the eye can aim at: steps of 1, 2 or 5
    times a power of ten, at least three screen pixels (``pixel``: metres per pixel). On a
    half-metre drawing 500 pixels wide that is 5 mm; zoomed in, 1 mm."""
    wanted = 3 * max(pixel, 1e-12)
    power = 10.0 ** math.floor(math.log10(wanted))
    step = next(k * power for k in (1, 2, 5, 10) if k * power >= wanted)
    digits = max(0, 1 - math.floor(math.log10(step)))  # 60 × 0.005 is 0.30000000000000004

    def on_grid(v: float) -> float:
        return round(round(v / step) * step, digits) + 0.0  # no −0

    return complex(on_grid(z.real), on_grid(z.imag))


def free_letter(doc: dict) -> str:
    """The first capital letter no point of the document uses (then A1, B1, …)."""
    used = set(doc.get("frame", {})) | {p for s in doc.get("members", {}).values()
                                        for p in _points_of(s)}
    for suffix in ("", *map(str, range(1, 100))):
        for letter in "ABCDEFGHIJKLMNOPQRSTUVWXYZ":
            if letter + suffix not in used:
                return letter + suffix
    raise ValueError("no free point name")  # unreachable below 2,600 points


def add_point(doc: dict, positions: Mapping[str, complex], rotations: Mapping[int, complex],
              member: int, at: complex) -> dict:
    """The document with a new point where the user clicked: a frame point (member 1), or a
    point of a moving member (its offsets from where the member is drawn)."""
    doc = copy.deepcopy(doc)
    name = free_letter(doc)
    if member == FRAME:
        doc.setdefault("frame", {})[name] = [at.real, at.imag]
    else:
        spec = doc["members"][str(member)]
        local = (at - positions[spec["points"][0]]) / rotations[member]
        spec.setdefault("extra", {})[name] = [local.real, local.imag]
    return doc
