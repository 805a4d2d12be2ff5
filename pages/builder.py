"""Build a mechanism: from a template, a preset or a file; by dragging on the drawing and typing
in tables; checked live; then studied on every chapter page through its link."""

from __future__ import annotations

import streamlit as st
from streamlit.delta_generator import DeltaGenerator

from figures.builder import builder_figure
from mechanisms import SceneError
from mechanisms.link import PARAMETER, encode
from mechanisms.loader import build_scene
from mechanisms.messages import text_of
from mechanisms.schema import Scene
from mechanisms.sketch import (
    COLUMNS,
    TABLES,
    document,
    driver_values,
    required,
    tables,
    template,
    template_ids,
)
from solvers.diagnostics import Unsolvable, format_ranges
from solvers.structure import StructureError, decompose, degrees_of_freedom, loose_joints
from ui import builder
from ui.cache import preset
from ui.chapters import BUILDER, CHAPTERS
from ui.editor_tables import MARK, frame_of, marked, marks, refused, rows_of
from ui.export import chart
from ui.firstpaint import hold, rerun_whole, waiting
from ui.fragments import fragment
from ui.i18n import current, latex, message, t, title_of
from ui.numbers import number_field, refusal
from ui.present import look
from ui.scenes import preset_titles, read_upload, scene_download

LINKAGE_PAGES = [c for c in CHAPTERS if c.file in (
    "pages/trajectories.py", "pages/velocity_plans.py", "pages/assur_groups.py",
    "pages/kinetostatics.py")]
LABELS = {"point": "build.col_point", "x": "build.col_x", "y": "build.col_y",
          "member": "build.col_member", "label": "build.col_label", "first": "build.col_first",
          "second": "build.col_second", "length": "build.col_length", "mass": "build.col_mass",
          "centre_along": "build.col_centre_along", "centre_left": "build.col_centre_left",
          "gyration": "build.col_gyration", "along": "build.col_along", "left": "build.col_left",
          "form": "build.col_form", "d1": "build.col_d1", "d2": "build.col_d2",
          "side": "build.col_side", "r": "build.col_r", "theta": "build.col_theta",
          "type": "build.col_type", "p": "build.col_p", "q": "build.col_q",
          "through": "build.col_through", "angle": "build.col_angle",
          "slider_angle": "build.col_slider_angle", "magnitude": "build.col_magnitude",
          "follows_member": "build.col_follows_member", "value": "build.col_value"}
TABS = {"frame": ("build.tab_frame", "build.hint_frame"),
        "members": ("build.tab_members", "build.hint_members"),
        "extra": ("build.tab_extra", "build.hint_extra"),
        "pairs": ("build.tab_pairs", "build.hint_pairs"),
        "forces": ("build.tab_forces", "build.hint_forces"),
        "moments": ("build.tab_moments", "build.hint_moments")}
DRIVERS = {"rotating": ("build.driver_rotating", ("build.phi", "build.omega", "build.epsilon")),
           "linear": ("build.driver_linear", ("build.s", "build.v", "build.a"))}
CLICKS = {"nothing": "build.click_nothing", "frame": "build.click_frame"}
FORM_LABELS = {"offset": "build.form_offset", "distances": "build.form_distances",
               "polar": "build.form_polar"}
SIDE_LABELS = {"left": "build.side_left", "right": "build.side_right"}
TYPE_LABELS = {"revolute": "build.type_revolute", "prismatic": "build.type_prismatic",
               "circular": "build.type_circular"}
UNITS = {"x": "m", "y": "m", "length": "m", "mass": "kg", "centre_along": "m",
         "centre_left": "m", "gyration": "m", "along": "m", "left": "m", "angle": "°",
         "d1": "m", "d2": "m", "r": "m", "theta": "°",
         "slider_angle": "°", "magnitude": "N", "value": "N·m"}


def column_label(name: str) -> str:
    label = t(LABELS[name])
    return f"{label} [{UNITS[name]}]" if name in UNITS else label


def column(name: str):
    label = column_label(name)
    if name == "type":
        return st.column_config.SelectboxColumn(label, options=list(TYPE_LABELS),
                                                format_func=lambda k: t(TYPE_LABELS[k]))
    if name == "form":
        return st.column_config.SelectboxColumn(label, options=list(FORM_LABELS), default="offset",
                                                format_func=lambda f: t(FORM_LABELS[f]))
    if name == "side":
        return st.column_config.SelectboxColumn(label, options=list(SIDE_LABELS),
                                                format_func=lambda s: t(SIDE_LABELS[s]))
    if name == "follows_member":
        return st.column_config.CheckboxColumn(label)
    if name in ("member", "p", "q"):
        return st.column_config.NumberColumn(label, min_value=1, step=1, format="%d")
    return st.column_config.TextColumn(label)  # numbers too: read by ui.numbers, not the browser


def needs(name: str):
    """The cells a filled row of the table ``name`` must have (mechanisms.sketch.required)."""
    return lambda row: required(name, row)


def refusals(name: str, rows: list[dict]) -> list[str]:
    """What a table holds that is not one number, each in words: the table, the row, the
    column and the text as typed."""
    return [refusal(f"{t(TABS[name][0])} · {t('table.row', row=i + 1)} · {column_label(col)}", why)
            for i, col, why in refused(rows, current(), needs(name))]


def edited_tables(doc: dict) -> dict[str, list[dict]]:
    """The six tables as the user has edited them. Only the open tab's table is sent to the
    browser (six editors doubled the rerun: 49 → 22 ms with one); switching tabs first folds
    the edits into the tables' document (ui.builder.fold). A refused cell is marked in its
    row (the ⚠ column) and named above the table, where the student types. On a fresh
    visit the open tab's editor too waits for the drawing's paint (ui/firstpaint.py): its
    grid script held the drawing back by an eighth, and nothing is typed in it yet."""
    rows = tables(doc)
    out: dict = {}
    tabs = st.tabs([t(TABS[n][0]) for n in TABLES], key="build_tab", on_change=builder.fold)
    language = current()
    left_out = hold()
    for tab, name in zip(tabs, TABLES):
        if not tab.open or left_out:
            out[name] = rows[name]
            continue
        with tab:
            st.caption(t(TABS[name][1]))
            frame, config = frame_of(name, rows[name], language), {c: column(c) for c in COLUMNS[name]}
            for said in refusals(name, rows[name]):
                st.error(said, icon=":material/error:")
            data = marked(frame, marks(rows[name], language,
                                       {c: column_label(c) for c in COLUMNS[name]}, needs(name)),
                          config)
            edited = st.data_editor(
                data, key=f"build_{builder.version()}_{name}", num_rows="dynamic",
                hide_index=True, placeholder="—", column_config=config)
            out[name] = rows_of(edited.drop(columns=MARK, errors="ignore"), language)
    return out


def driver_inputs(values: dict) -> dict:
    """The driving member 2: how it moves, and φ₂, ω₂, ε₂ (or s, v, a) in one row."""
    key = f"build_{builder.version()}_driver"
    kinds = list(DRIVERS)
    kind = st.radio(t("build.driver_type"), kinds, index=kinds.index(values["type"]),
                    format_func=lambda k: t(DRIVERS[k][0]), horizontal=True, key=f"{key}_type")
    names = DRIVERS[kind][1]
    row = st.container(horizontal=True, vertical_alignment="bottom")  # one block, not four (columns)
    return {"type": kind, **{field: number_field(t(label), f"{key}_{field}", float(values[field]),
                                                 where=row)
                             for field, label in zip(("at", "speed", "accel"), names)}}


def start_controls() -> None:
    # the labels made once a run from the titles kept per language (asking each preset's
    # cached scene for its title, fifty times a run, was an eighth of the page's rerun)
    titles = preset_titles("linkage", current())
    labels = {f"template:{n}": t("build.template", name=title_of(builder.template_scene(n)))
              for n in template_ids()}
    labels.update({f"preset:{p}": t("build.preset", name=title) for p, title in titles.items()})

    def begin() -> None:
        kind, name = st.session_state["build_start"].split(":", 1)
        if kind == "template":
            builder.start(template(name))
            st.session_state.pop("build_message", None)
        else:
            builder.start_from(preset(name))

    left, right = st.columns([3, 1], vertical_alignment="bottom")
    left.selectbox(t("build.start_from"), list(labels), format_func=labels.get, key="build_start")
    right.button(t("build.start"), on_click=begin, icon=":material/restart_alt:", width="stretch")
    with st.expander(t("build.upload_title")):
        st.file_uploader(t("scene.upload"), type=["toml"], key="build_upload", on_change=upload)


def upload() -> None:
    file = st.session_state.get("build_upload")
    if file is None:
        return
    try:
        scene = read_upload(file, "linkage")
    except SceneError as exc:
        st.session_state["build_message"] = text_of(exc)
        return
    builder.start_from(scene)


def checks(doc: dict, scene: Scene | None, problem: str | None,
           solved: builder.Drawing | None, last_doc: dict | None) -> None:
    """What a student needs to hear while building, in words."""
    n, p5 = len(doc.get("members", {})), len(doc.get("pairs", []))
    w = 3 * n - 2 * p5 if scene is None else degrees_of_freedom(scene)
    st.latex(latex(rf"W = 3n - 2p_5 - p_4 = 3\cdot{n} - 2\cdot{p5} - 0 = {w}"))
    if w > 1:
        st.warning(t("build.too_free", extra=w - 1))
    elif w < 1:
        st.warning(t("build.too_stiff", extra=1 - w))
    if problem:
        st.error(problem)
    if scene is None:
        return
    for point, member in loose_joints(scene):
        st.warning(t("build.loose", point=point, member=member))
    try:
        structure = decompose(scene)
    except StructureError:
        return  # the message is the problem above
    st.success(t("build.formula", formula=structure.formula))
    for zone in solved.zones if solved is not None else []:
        where = message(format_ranges(scene, zone.ranges))
        st.info(t("build.dead_zone", group=zone.group, kind=zone.kind, where=where))
    if solved is not None and not problem:
        assemblies(structure, solved, last_doc)


def assemblies(structure, solved: builder.Drawing, doc: dict) -> None:
    """Each group that closes more than one way: where it is drawn, where the other closure
    would put it, and one click to put it there."""
    found = builder.group_closures(solved.scene)
    for group in structure.groups:
        if len(found.get(group.name, [])) < 2:
            continue
        words = builder.closure_words(solved.scene, group.name, found[group.name])
        side = words.pop("side")
        text = t("build.closures_side" if side else "build.closures", group=group.label(),
                 count=len(found[group.name]), **words,
                 **({"side": t(SIDE_LABELS[side])} if side else {}))
        st.info(text)
        st.button(t("build.flip"), key=f"build_flip_{group.name}", help=t("build.flip_help"),
                  on_click=builder.flip, args=(doc, solved, group.name),
                  icon=":material/flip:")


def study(scene: Scene) -> None:
    st.header(t("build.study"))
    row = st.container(horizontal=True)  # one block, not five (columns): 1.8 → 0.4 ms a rerun
    for chapter in LINKAGE_PAGES:
        if row.button(t(chapter.title), icon=chapter.icon, key=f"open_{chapter.file}", width="stretch"):
            builder.open_on(chapter.file, scene)
    text = encode(scene)
    st.caption(t("build.link_caption", chars=len(text)))
    st.code(f"{PARAMETER}={text}", language=None, wrap_lines=True)
    scene_download(scene)


st.title(f"{BUILDER.icon} {t(BUILDER.title)}")
st.caption(t("build.intro"))
builder.from_link()
start_controls()
if st.session_state.get("build_message"):
    st.error(message(st.session_state["build_message"]))


@fragment
def workbench() -> None:
    """The tables: a cell reruns them and what they drive (``driven``), not app.py and the
    start controls above (an eighth of the builder's rerun). Starting anew or uploading runs
    the whole page."""
    base = builder.base()
    with st.container(key="build_bench"):  # on a phone: the drawing held over the tables
        drawing_col, tables_col = st.columns([3, 2], gap="large")
    with tables_col, st.container(key="build_tables"):
        driver_place = st.container()  # above the tables: written by driven()
        edited = edited_tables(base)
    driven(base, edited, drawing_col, driver_place)


def _texts(found: dict[str, list]) -> list[tuple]:
    return [(name, i, column, why.text) for name, cells in found.items() for i, column, why in cells]


@fragment
def driven(base: dict, edited: dict[str, list[dict]], drawing_col: DeltaGenerator,
           driver_place: DeltaGenerator) -> None:
    """The driver's row, the drawing, the checks and the links: φ₂ typed or a drag reruns
    these alone, not the tables' editor and tabs (a fifth of the rerun), which then come
    with the tables as the last run of ``workbench`` left them. A button here that gives the
    tables a new document (a group's other assembly) reruns the page, tables first."""
    if builder.base() != base:
        st.rerun(scope="app")
    with driver_place:
        driver = driver_inputs(driver_values(base))
    doc = document(edited, driver, base)
    builder.remember(doc)
    now = {name: refused(rows, current(), needs(name)) for name, rows in edited.items()}
    shown = tables(base)
    if (_texts(now) != _texts({n: refused(r, current(), needs(n)) for n, r in shown.items()})
            or (edited["extra"] != shown["extra"] and builder.stale_forms(edited["extra"], doc))):
        builder.replace(doc)  # the tables again: the ⚠ marks where they are now, a point's
        st.rerun()  # other forms computed from what was just typed in one of them

    scene, problem, solved = None, None, None
    if any(now.values()):
        problem = t("build.refused_cells", count=sum(map(len, now.values())))
    else:
        try:
            scene = build_scene(doc, source=t("build.tables"))
            solved = builder.drawing(scene)
            st.session_state["build_last"] = doc, solved
        except (SceneError, StructureError, Unsolvable) as exc:
            problem = message(builder.in_tables(exc, doc))
    last_doc, last = st.session_state.get("build_last", (None, None))

    with drawing_col:
        if last is not None:
            mode = st.radio(t("build.click_adds"), ["nothing", "frame", *map(str, last.scene.members)],
                            format_func=lambda m: t(CLICKS[m]) if m in CLICKS
                            else t("build.click_member", member=m), horizontal=True, key="build_click")
            with st.container(key="build_sheet"):
                result = chart(builder_figure(last.scene, last.positions, last.rotations,
                                              last.paths, t("build.drawing"), t, look(),
                                              builder.revision()),
                               f"{last.scene.id}-drawing", "build_fig", editable=True)
            if problem:  # a drag now would drop what the tables hold: mend them first
                st.caption(t("build.last_valid"))
            event = builder.moved(result.drag)
            if event is not None:
                if problem:
                    builder.refuse_drag()
                else:
                    builder.drop(last_doc, last, *event)
                st.rerun()
            if result.joint and not problem and (group := builder.group_of_joint(
                    last.scene, str(result.joint.get("point")))):
                builder.flip(last_doc, last, group)
                st.rerun()
            if result.click and mode != "nothing" and not problem:
                builder.click(last_doc, last, 1 if mode == "frame" else int(mode),
                              complex(result.click["x"], result.click["y"]), result.click["pixel"])
                st.rerun()
        if st.session_state.get("build_flip_error"):
            st.error(t("build.flip_failed", group=st.session_state.pop("build_flip_error")))
        if st.session_state.get("build_drag_error"):
            point, to, why = st.session_state.pop("build_drag_error")
            st.error(t("build.drag_failed", point=point, x=to.real, y=to.imag, why=message(why)))
        rerun_whole()  # (no drawing: no paint will bring the editor left out)
        if not waiting():  # on a fresh visit, after the drawing is painted (ui/firstpaint.py)
            checks(doc, scene, problem, solved, last_doc)

    if scene is not None and problem is None and not waiting():
        study(scene)


workbench()
