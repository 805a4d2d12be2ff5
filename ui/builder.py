"""The builder page's state: the scene document its tables start from, and what was drawn.

``st.data_editor`` keeps a user's edits *relative to* the table it was first given, so the
tables start from a stored document (``build_doc``) under keys that carry a version; a
drag, a click or a new start replaces the document and bumps the version (fresh tables),
while typing leaves both alone. The document the tables show now is saved every rerun
(``build_now``), so that leaving the page and coming back loses nothing.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping

import numpy as np
import streamlit as st

from mechanisms import Scene, SceneError
from mechanisms.link import PARAMETER, decode, encode
from mechanisms.loader import build_scene
from mechanisms.messages import Text, text_of
from mechanisms.reader import key_parts
from mechanisms.sketch import add_point, drag, drawn, from_scene, snap, tables, template
from solvers.assembly import closures
from solvers.diagnostics import Unsolvable, dead_zones, solve_instant, sweep_values
from solvers.kinematics import GroupIssue, solve
from solvers.structure import StructureError, decompose
from ui.cache import BY_REPR
from ui.editor_tables import is_number_column
from ui.i18n import label_of
from ui.scenes import link_choice

START = "four-bar"


@dataclasses.dataclass(frozen=True)
class Drawing:
    """A scene that solves at its instant, as drawn: every point's place, every member's
    e^{iθ}, the moving points' paths over the cycle and where a group cannot close."""

    scene: Scene
    positions: dict[str, complex]
    rotations: dict[int, complex]
    paths: dict[str, np.ndarray]
    zones: list[GroupIssue]


@st.cache_resource(max_entries=32, show_spinner=False, hash_funcs=BY_REPR)
def drawing(scene: Scene) -> Drawing:
    """Solve the scene at its instant (Unsolvable or StructureError say why not)."""
    motion = solve_instant(scene, None)
    positions = {n: complex(p.z[0]) for n, p in motion.points.items()}
    rotations = {m: complex(mm.rot[0]) for m, mm in motion.members.items()}
    cycle = solve(scene, sweep_values(scene, 180), order=0)
    paths = {n: p.z for n, p in cycle.points.items() if n not in scene.frame}
    return Drawing(scene, positions, rotations, paths, dead_zones(scene, motion.structure, 720))


def version() -> int:
    return st.session_state.setdefault("build_version", 0)


def revision() -> str:
    """Changes with every new drawing and every drag, refused ones too (figures.builder)."""
    return f"{version()}-{st.session_state.get('build_drops', 0)}"


def base() -> dict:
    """The document the tables start from (the four-bar template on a first visit)."""
    if "build_doc" not in st.session_state:
        start(template(START))
    now = st.session_state.get("build_now")
    tables = f"build_{version()}_"  # the tables' keys (once: asked per key, 0.5 ms a rerun)
    if now is not None and now != st.session_state["build_doc"] and not any(
            key.startswith(tables) for key in st.session_state):
        replace(now)  # back on the page: the tables left as they were
    return st.session_state["build_doc"]


def replace(doc: dict) -> None:
    """New tables from ``doc`` (after a drag, a click, a start)."""
    st.session_state["build_doc"] = doc
    st.session_state["build_now"] = doc
    st.session_state["build_version"] = version() + 1


def start(doc: dict) -> None:
    """Start from a document, its points drawn where it solves (so that every group keeps
    the assembly it shows); one that does not solve starts as it is, to be mended."""
    doc = in_words(doc)
    try:
        solved = drawing(build_scene(doc, source=doc.get("id", "builder")))
        doc = {**doc, "guess": drawn(doc, solved.positions)}
    except (SceneError, StructureError, Unsolvable):
        pass
    doc.pop("assembly", None)
    replace(doc)


# a loader key's field → the builder table's column it is typed in (build.col_<column>)
FIELD_COLUMNS = {"points": "first", "centre": "centre_along", "members": "p", "guide": "p",
                 "slider": "q", "mass": "mass", "length": "length", "gyration": "gyration",
                 "label": "label", "point": "point", "through": "through", "angle": "angle",
                 "slider_angle": "slider_angle", "type": "type", "magnitude": "magnitude",
                 "member": "member", "value": "value", "follows_member": "follows_member"}
TABLES = ("frame", "members", "pairs", "forces", "moments")  # the builder's tabs, by the loader's keys


def in_tables(said: BaseException | Text | str, doc: Mapping) -> Text | str:
    """A loader's refusal of the tables told at the cell the student typed it in — the
    table as its tab is named, the row as numbered on screen, the column as headed — not by
    the file's key (`frame.D`, `members.2.mass`, `pairs[0].members`)."""
    said = text_of(said) if isinstance(said, BaseException) else said
    if not isinstance(said, Text) or said.key != "scene.at":
        return said
    key = str(said.values.get("key", ""))
    if key == "driver" or key.startswith("driver."):  # (the driver's own fields, above the tables)
        return Text("build.at", where=Text("build.driver_type"), rule=said.values["rule"])
    parts = key_parts(key)  # ("members", "2", "mass"), ("pairs", 0, "members")
    if not parts or parts[0] not in TABLES:
        return said
    table, which = parts[0], parts[1] if len(parts) > 1 else None
    fields = [f for f in parts[2:] if isinstance(f, str)]
    if table == "members" and fields[:1] == ["extra"] and len(fields) > 1:  # a member's point
        table, row = "extra", _row_of(doc, "extra", (which, fields[1]))
        fields = fields[2:]
    else:
        row = which + 1 if isinstance(which, int) else _row_of(doc, table, which)
    column = next((FIELD_COLUMNS[f] for f in fields if f in FIELD_COLUMNS), None)
    rule = said.values["rule"]
    if isinstance(rule, Text) and rule.key in ("scene.frame_table", "scene.frame_missing"):
        rule = Text("build.frame_empty")  # (the file's "O = [0, 0]" is no help in a table)
    where = Text("build.where", table=Text(f"build.tab_{table}"))
    if row is not None:
        where = Text("build.where_row", table=Text(f"build.tab_{table}"), row=row)
    if row is not None and column is not None:
        where = Text("build.where_cell", table=Text(f"build.tab_{table}"), row=row,
                     column=Text(f"build.col_{column}"))
    return Text("build.at", where=where, rule=rule)


def _row_of(doc: Mapping, table: str, name) -> int | None:
    """The row (from 1, as shown) of a frame point, a member or a member's point."""
    if table == "frame":
        names = list(doc.get("frame", {}))
    elif table == "members":
        names = [str(n) for n in doc.get("members", {})]
    elif table == "extra":
        names = [(str(n), p) for n, spec in doc.get("members", {}).items()
                 for p in spec.get("extra", {})]
    else:
        return None
    return names.index(name) + 1 if name in names else None


def start_from(scene: Scene) -> None:
    """Start from a scene (a preset, an uploaded file), drawn where it solves; one that does
    not solve at its instant still fills the tables, with the reason shown."""
    try:
        positions = drawing(scene).positions
        st.session_state.pop("build_message", None)
    except (StructureError, Unsolvable) as exc:
        positions = {}
        st.session_state["build_message"] = text_of(exc)
    replace(in_words(from_scene(scene, positions)))


def from_link() -> None:
    """A scene carried by the page's link (``?s=``, as the synthesis page's *Open in the
    builder* sends one) starts the tables, once per link; the link is then taken out of the
    address, since the tables are what the page shows from there on. A damaged link, or one
    of a gear train or a rotor, is said in words and the tables stay as they were."""
    text = st.query_params.get(PARAMETER)
    if not text:
        return
    st.query_params.pop(PARAMETER, None)
    try:
        scene = decode(text)
        if not isinstance(scene, Scene):
            raise SceneError(Text("build.link_not_linkage"))
    except SceneError as exc:
        st.session_state["build_message"] = text_of(exc)
        return
    start_from(scene)


def in_words(doc: dict) -> dict:
    """The members' labels in the reader's language (a template's "crank" is "krivaja" in
    the Serbian tables, and in the file the student saves)."""
    members = {number: {**spec, "label": label_of(spec["label"])} if spec.get("label") else spec
               for number, spec in doc.get("members", {}).items()}
    return {**doc, "members": members}


def fold() -> None:
    """Before another tab's table is shown: the tables start again from what they say now
    (a closed tab's editor is gone, and its edits must not be)."""
    replace(st.session_state.get("build_now", base()))


def remember(doc: dict) -> None:
    st.session_state["build_now"] = doc


def open_on(page: str, scene: Scene) -> None:
    """Show the built scene on a chapter page, carried by the link (``?s=``)."""
    text = encode(scene)
    st.session_state["linked_text"] = text
    st.session_state["scene"] = link_choice(text)
    st.switch_page(page, query_params={PARAMETER: text, "scene": link_choice(text)})


def moved(drag: Mapping | None) -> tuple[str, complex, float] | None:
    """A drag event from the drawing as (point, place, metres per pixel), or None."""
    if not drag or "point" not in drag:
        return None
    return str(drag["point"]), complex(float(drag["x"]), float(drag["y"])), float(drag["pixel"])


@st.cache_resource(max_entries=16, show_spinner=False)
def template_scene(name: str) -> Scene:
    return build_scene(template(name), source=f"{name}.toml")


def _solves(doc: dict) -> Text | str | None:
    """Why the document does not solve at its instant, or None."""
    try:
        drawing(build_scene(doc))
    except (SceneError, StructureError, Unsolvable) as exc:
        return in_tables(exc, doc)
    return None


def drop(doc: dict, last: Drawing, point: str, to: complex, pixel: float) -> None:
    """A point dragged to ``to`` (snapped to what ``pixel`` m per pixel lets the eye aim at):
    new lengths and offsets, or, where the mechanism cannot be drawn that way, the reason
    and the last valid drawing kept."""
    to = snap(to, pixel)
    refuse_drag()  # a new revision first: if the drag is refused, the circle goes back
    new = drag(doc, last.positions, last.rotations, point, to)
    problem = _solves(new)
    if problem is None:
        replace(new)
    else:
        st.session_state["build_drag_error"] = (point, to, problem)


def refuse_drag() -> None:
    """A new drawing revision (figures.builder): the dragged circle returns to its place."""
    st.session_state["build_drops"] = st.session_state.get("build_drops", 0) + 1


def click(doc: dict, last: Drawing, member: int, at: complex, pixel: float) -> None:
    replace(add_point(doc, last.positions, last.rotations, member, snap(at, pixel)))


@st.cache_resource(max_entries=32, show_spinner=False, hash_funcs=BY_REPR)
def group_closures(scene: Scene) -> dict[str, list[dict[str, complex]]]:
    """Every Assur group's closures at the drawn instant, the drawn one first
    (solvers.assembly); a class III group's search takes ~0.1 s, so it is kept."""
    return {g.name: closures(scene, g.name) for g in decompose(scene).groups}


def group_of_joint(scene: Scene, point: str) -> str | None:
    """The Assur group a double-clicked joint moves with: the group whose closures differ
    at that point (its inner joint, or a point of its members)."""
    for name, found in group_closures(scene).items():
        if len(found) > 1 and point in found[0] and abs(found[0][point] - found[1][point]) > 0:
            return name
    return None


def flip(doc: dict, last: Drawing, group: str) -> None:
    """The group drawn in its next closure: its points' drawn places (``[guess]``) move there
    and every length stays, so the solver takes that assembly; the groups after it keep the
    side they are drawn on."""
    found = group_closures(last.scene).get(group, [])
    if len(found) < 2:
        st.session_state["build_flip_error"] = group
        return
    new = {**doc, "guess": drawn(doc, {**last.positions, **found[1]})}
    problem = _solves(new)
    if problem is None:
        replace(new)
    else:
        st.session_state["build_flip_error"] = group


def closure_words(scene: Scene, group: str, found: list[dict[str, complex]]) -> dict:
    """What a student compares with the sheet's figure: the point that moves most between
    the drawn closure and the other one, where each puts it, and for an RRR dyad on which
    side of the line between its outer joints it is drawn."""
    drawn_at, other = found[0], found[1]
    point = max(drawn_at, key=lambda n: abs(drawn_at[n] - other[n]))
    words = {"point": point, "x": drawn_at[point].real, "y": drawn_at[point].imag,
             "x2": other[point].real, "y2": other[point].imag, "side": None}
    g = next(g for g in decompose(scene).groups if g.name == group)
    if g.kind == "RRR":
        p, q = g.pairs[0].point, g.pairs[2].point
        c = g.pairs[1].point
        a, b = drawn_at.get(p), drawn_at.get(q)
        if a is not None and b is not None:
            turn = ((drawn_at[c] - a) / (b - a)).imag
            words.update(point=c, x=drawn_at[c].real, y=drawn_at[c].imag, x2=other[c].real,
                         y2=other[c].imag, side="left" if turn > 0 else "right", line=f"{p}→{q}")
    return words


def stale_forms(rows: list[dict], doc: dict) -> bool:
    """A member's point typed in one form (two distances, say) while its other forms' cells,
    shown for checking, still say where it was. Only when every row is whole: a row being
    typed is not in the document yet, and new tables would lose it."""
    if any(r.get("member") is None or not r.get("point") for r in rows):
        return False
    fresh = {(r["member"], r["point"]): r for r in tables(doc)["extra"]}
    return any(fresh.get((r["member"], r["point"]), r).get(c) != r.get(c)
               for r in rows for c in r if is_number_column(c))
