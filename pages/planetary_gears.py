"""Chapter 6 — planetary and differential gear trains: Willis equations, velocity diagram."""

from __future__ import annotations

import pandas as pd
import streamlit as st

from figures.gears import member_name, schematic_figure, velocity_figure
from mechanisms.gears import GearTrain, Input, Mesh
from mechanisms.loader import as_loaded
from methods import practice_steps
from methods.gear_steps import speed_steps, stage_latex, total_ratio
from methods.scales import nice_scale
from solvers.gears import TrainError, geometry_notes, solve_train, stages, willis_table
from ui import practice
from ui.benchmarks import speed_panel
from ui.book import differs, train_changes
from ui.chapters import page_title
from ui.docs import method_doc
from ui.editor_tables import linked_table, typed_table
from ui.export import chart, show_table
from ui.firstpaint import hold, rerun_whole, waiting
from ui.fragments import fragment
from ui.i18n import latex, message, num, t
from ui.layout import page_columns
from ui.numbers import number_field
from ui.present import look
from ui.scenes import scene_download, scene_picker
from ui.selfcheck import answer_box, named
from ui.url import seed, stop

page_title("pages/planetary_gears.py")
practice.class_only("pr_willis")  # a seated student: the class's practice alone

# the caption under each step of methods.gear_steps: (kind, on fixed axes) → locale key
STEP_WORDS = {("input", True): "gears.kind_input", ("fixed", True): "gears.kind_fixed",
              ("shaft", True): "gears.kind_shaft", ("mesh", True): "gears.kind_mesh_fixed",
              ("mesh", False): "gears.kind_mesh_planet", ("stage", False): "gears.kind_stage",
              ("system", True): "gears.kind_system"}


def defaults(base: GearTrain) -> dict[str, object]:
    """Each input's ω (or peripheral v), and drawing scales that fit the train on ~8 cm."""
    reach = max(r for m in base.meshes for r in m.radii)
    fastest = max((abs(i.omega) for i in base.inputs), default=1.0) * reach
    values: dict[str, object] = {f"in{i.member}": i.omega if i.velocity is None else i.velocity
                                 for i in base.inputs}
    values.update(UL=nice_scale(reach / 8), Uv=nice_scale(fastest / 8), H=2.0)
    return values


def scale_inputs() -> tuple[float, float, float]:
    """U_L, U_v and the pole distance, in their place among the controls (drawn on every
    run, also one the train stops: Streamlit forgets a widget a run leaves out)."""
    with scales_place:
        return (number_field(t("gears.scale_length"), "UL", minimum=1e-6, url=True),
                number_field(t("gears.scale_velocity"), "Uv", minimum=1e-6, url=True),
                number_field(t("gears.pole_distance"), "H", minimum=0.1, url=True))


def meshes_table(base: GearTrain) -> pd.DataFrame:
    """The meshes as the table shows them: a ring (internal teeth) a yes/no cell — the ring
    is the larger gear of its mesh (the second where both are alike), as in every task."""
    return pd.DataFrame([{"a": m.members[0], "b": m.members[1], "R_a [m]": m.radii[0],
                          "R_b [m]": m.radii[1], "ring": m.internal is not None} for m in base.meshes])


def meshes_of(table: pd.DataFrame, base: GearTrain) -> tuple[Mesh, ...]:
    """The table's meshes (a ticked ring: its larger gear has the internal teeth)."""
    def ring(a: int, b: int, ra: float, rb: float, ticked: bool) -> int | None:
        return (a if ra > rb else b) if ticked else None
    return tuple(Mesh((int(r["a"]), int(r["b"])), (float(r["R_a [m]"]), float(r["R_b [m]"])),
                      ring(int(r["a"]), int(r["b"]), float(r["R_a [m]"]), float(r["R_b [m]"]),
                           bool(r["ring"])), old.bevel)
                 for (_, r), old in zip(table.iterrows(), base.meshes))


controls, main = page_columns()
with controls:
    base = scene_picker("gears")
    seed(defaults(base), st.session_state["scene"])
    inputs = []
    for inp in base.inputs:
        if inp.velocity is None:
            omega = number_field(t("gears.input_omega", member=inp.member), f"in{inp.member}",
                                 url=True)
            inputs.append(Input(inp.member, omega))
        else:
            v = number_field(t("gears.input_velocity", member=inp.member, radius=num(inp.radius)),
                             f"in{inp.member}", url=True)
            inputs.append(Input(inp.member, v / inp.radius, v, inp.radius))
    scales_place = st.container()  # U_L, U_v and the pole distance: drawn by the fragment below

with main:
    own = meshes_table(base)
    table_rules = {"name": t("gears.meshes_short"), "column_config": {
                       "ring": st.column_config.CheckboxColumn(t("gears.ring"), help=t("gears.ring_help"))},
                   "loader": lambda rows: as_loaded(base.with_(meshes=meshes_of(rows, base))),
                   "fields": {"radii[0]": "R_a [m]", "radii[1]": "R_b [m]", "internal": "ring"}}
    # a fresh visit: the meshes' editor (a grid script, the heaviest element here, and above
    # the charts) after the first chart's paint (ui/firstpaint.py); the link's table meanwhile
    if hold():
        table = linked_table("meshes", own, base.id, **table_rules)
    else:
        with st.container(key="later_meshes"):  # on a phone, after the charts (ui/layout.py)
            st.markdown(f"**{t('gears.meshes')}**")
            table = typed_table("meshes", own, base.id, ("R_a [m]", "R_b [m]"), width="stretch",
                                disabled=["a", "b"], **table_rules)
    meshes = meshes_of(table, base)
    train: GearTrain = base.with_(inputs=tuple(inputs), meshes=meshes)
    for note in geometry_notes(train):
        st.info(message(note))
    try:
        solution = solve_train(train)
    except TrainError as exc:
        rerun_whole()  # (no chart follows to bring the editor)
        st.error(message(exc))
        scale_inputs()
        stop()
    st.caption(t("gears.dof", dof=solution.dof, inputs=len(train.inputs)))
    if solution.status == "solved" and solution.message:
        st.info(message(solution.message))  # the input at rest: the ratios still hold
    if solution.status != "solved":
        st.error(message(solution.message))
        chart(schematic_figure(train, t("gears.schematic"), t, look()), f"{train.id}-train", key="train")
        scale_inputs()
        stop()


def intercepts(u_l: float, u_v: float, h: float) -> None:
    """Under the velocity diagram: its pole distance, U_ω and each member's intercept."""
    st.caption(t("gears.pole_note", H=num(h, 3)))
    u_omega = u_v / (h * u_l)
    st.markdown(t("gears.u_omega", value=num(u_omega, 4)))
    show_table([{t("gears.col_member"): m, t("gears.col_intercept"): num(w / u_omega, 4),
                 "ω = x·U_ω [s⁻¹]": num(w, 5)} for m, w in solution.omega.items()],
        f"{train.id}-intercepts.csv", "csv_intercepts")


def results() -> None:
    """Under the drawing: every ω with the book's, a ratio, the points' speeds, Willis's
    equations stage by stage, and the answer box."""
    rows = []
    changed = train_changes(train, base) if base.book else []  # the book's ω: the task's own
    for m, w in solution.omega.items():
        book = None if changed else train.book.get(f"members.{m}.omega")
        rows.append({t("gears.col_member"): member_name(train, m, t),
                     "ω [s⁻¹]": num(w, 5),
                     t("gears.col_book"): "" if book is None else num(book, 5)})
    show_table(rows, f"{train.id}-omega.csv", "csv")
    if changed:
        differs(changed, {k: v for k, v in defaults(base).items() if k.startswith("in")},
                ("meshes",))
    cols = st.columns(3)
    members = list(train.members)
    a = cols[0].selectbox(t("gears.ratio_from"), members, key="ra")
    b = cols[1].selectbox(t("gears.ratio_to"), members, index=len(members) - 1, key="rb")
    ratio = solution.ratio(a, b)
    cols[2].metric(f"i {a},{b} = ω{a}/ω{b}", t("gears.infinite") if ratio == float("inf") else num(ratio, 5))
    for name, (m, r) in train.points.items():
        st.metric(t("gears.point_velocity", point=name, member=m), f"{num(solution.velocity(m, r), 5)} m/s")
    # filled only while open: closed, a rerun skips its tables and LaTeX (most of the page's)
    willis = st.expander(t("gears.willis_title"), key="willis_open", on_change="rerun")
    if willis.open:
        with willis:
            show_table([{
                t("gears.col_mesh"): f"{w.a}–{w.b}",
                t("gears.col_carrier"): t("gears.frame") if w.carrier is None else str(w.carrier),
                t("gears.col_equation"): (f"(ω{w.a} − ω{w.carrier})/(ω{w.b} − ω{w.carrier})"
                                          if w.carrier is not None else f"ω{w.a}/ω{w.b}"),
                t("gears.col_radii"): num(w.ratio, 5),
                t("gears.col_solved"): num(w.check(solution.omega), 5)}
                for w in willis_table(train)], f"{train.id}-willis.csv", "csv_willis")
            st.markdown(f"**{t('gears.stages_title')}**")
            for stage in stages(solution):
                st.latex(latex(stage_latex(stage, t("gears.from_radii"))))
                st.caption(t("gears.stage_fixed") if stage.carrier is None
                           else t("gears.stage_carrier", carrier=stage.carrier))
            steps = speed_steps(solution)
            if steps:
                st.markdown(f"**{t('gears.chain_title')}**")
                for step in steps:
                    st.latex(latex(step.latex))
                    st.caption(t(STEP_WORDS[step.kind, step.carrier is None], carrier=step.carrier))
                total = total_ratio(steps, a, b)
                if total:
                    st.latex(latex(total))
                    st.caption(t("gears.total_ratio"))
            method_doc("willis")
    answer_box(lambda: named(solution.train, base), key="self")  # (exams.judged: signed ω, ratios)


with controls:
    scene_download(train)

with main:
    tab_train, tab_v = st.tabs([t("gears.schematic"), t("gears.velocity_diagram")], key="tab",
                               on_change="rerun")
    if tab_train.open:
        with tab_train:
            chart(schematic_figure(train, t("gears.schematic"), t, look()), f"{train.id}-train", key="train")


@fragment
def velocity_diagram() -> None:
    """The drawing's scales and the velocity diagram they draw (with its intercepts), which
    a scale reruns alone: not app.py, the scene, the inputs, the meshes' table, the
    solution, the schematic and the results. Any of those reruns the page, and this with
    it. The scales are drawn on every run (Streamlit forgets a widget a run leaves out)."""
    u_l, u_v, h = scale_inputs()
    if tab_v.open:
        with tab_v:
            pole = h * u_l  # the pole's distance below the axis, in metres of the drawing's scale
            chart(velocity_figure(solution, pole, t("gears.velocity_diagram"), t, look()),
                  f"{train.id}-velocities", key="velocities")
            if not waiting():
                intercepts(u_l, u_v, h)


velocity_diagram()

if not waiting():  # on a fresh visit, after the chart is painted (ui/firstpaint.py)
    with main:
        if practice.toggle("pr_willis"):
            practice.panel(practice_steps.willis(solution), "pr_willis", "", drawable=False)
        else:
            results()
        speed_panel("planetary_gears", train.id)
