"""Chapter 4 — structure: degrees of freedom, the driver and the Assur groups, special points S."""

from __future__ import annotations

import numpy as np
import streamlit as st

from figures.assur import structure_figure
from figures.raw import RawFigure
from figures.style import Look
from mechanisms.schema import Scene
from solvers.diagnostics import (
    TOLERANCES,
    Unsolvable,
    format_ranges,
    newton_accuracy,
    newton_iterations,
    sweep_values,
)
from solvers.kinematics import Motion, solve
from solvers.structure import StructureError, decompose, degrees_of_freedom
from ui.benchmarks import speed_panel
from ui.cache import BY_REPR, instant, page_cache, same_call
from ui.chapters import page_title
from ui.crank import crank_frames, cranks, task_turn
from ui.docs import method_doc
from ui.export import Rows, chart, show_table
from ui.firstpaint import hold, rerun_whole, waiting
from ui.fragments import Places, at_position, fragment
from ui.i18n import current as current_language, latex, message, num, sci, t, title_of
from ui.layout import page_columns
from ui.numbers import bound_select_slider, bound_slider, number_field
from ui.present import look
from ui.progress import measured
from ui.scenes import driver_start, scene_picker
from ui.selfcheck import Quantity, answer_box, computed
from ui.url import seed, stop

page_title("pages/assur_groups.py")
CYCLE = 360


@same_call
@page_cache(st.cache_resource(max_entries=32, show_spinner=False, hash_funcs=BY_REPR))
def cycle(scene: Scene, tol: float) -> Motion:
    """A survey of the driver (``CYCLE`` positions)."""
    return solve(scene, sweep_values(scene, CYCLE), tol=tol)


@page_cache(st.cache_resource(max_entries=8, show_spinner=False, hash_funcs=BY_REPR))
def turn_frames(scene: Scene, values: tuple[float, ...], tol: float, upto: int, language: str,
                look_: Look) -> dict[str, str]:
    """The structure drawing at the angles ``values`` (ui.crank.task_turn: every 5° of φ₂
    and the task's instant), from one solution of the turn, over the page's own survey
    (``cycle``: the scene comes at its preset instant, as there)."""
    motion = solve(scene, np.radians(values), tol=tol)
    survey = cycle(scene, tol)

    def draw(i: int, _: float) -> dict[str, RawFigure] | None:
        if not motion.feasible[i]:
            return None
        return {"structure": structure_figure(motion, i, upto, t("assur.fig_title"), t, look(),
                                              survey)}

    return crank_frames(draw, values)


def counts(scene: Scene) -> None:
    n, p5, dof = len(scene.members), len(scene.pairs), degrees_of_freedom(scene)
    cols = st.columns(4)
    cols[0].metric(t("assur.n"), n)
    cols[1].metric(t("assur.p5"), p5)
    cols[2].metric(t("assur.p4"), 0)
    cols[3].metric(t("assur.dof"), dof)
    st.latex(latex(rf"W = 3n - 2p_5 - p_4 = 3\cdot{n} - 2\cdot{p5} - 0 = {dof}"))


def groups_table(structure) -> Rows:
    return [{t("assur.col_group"): g.label(), t("assur.col_class"): g.cls,
             t("assur.col_kind"): g.kind, t("assur.col_order"): g.order,
             t("assur.col_members"): ", ".join(map(str, g.members))}
            for g in structure.groups]


def special_table(motion: Motion, index: int) -> Rows:
    rows = []
    for name, p in motion.special.items():
        z = complex(p.z[index])
        if not np.isfinite(z):
            rows.append({t("assur.col_point"): name, "x [m]": t("assur.at_infinity")})
            continue
        rows.append({t("assur.col_point"): name, "x [m]": num(z.real, 4), "y [m]": num(z.imag, 4),
                     "v [m/s]": num(abs(p.v[index]), 4), "a [m/s²]": num(abs(p.a[index]), 4)})
    return rows


def newton_table(scene: Scene, tol: float) -> None:
    """Newton's method at this instant for each class III group, iterate by iterate, from the
    pose a chosen step earlier: the residual falls quadratically once it is near, and a start
    too far away wanders (which is why the solver marches along the cycle in small steps)."""
    rotating = scene.driver.kind == "rotating"
    st.caption(t("assur.iterations_hint"))
    back = number_field(t("assur.iterations_back_deg" if rotating else "assur.iterations_back_mm"),
                        "back", minimum=0.0, maximum=180.0 if rotating else 1000.0, url=True)
    offset = np.radians(back) if rotating else back / 1000.0
    for name, iterates in newton_iterations(scene, offset, tol).items():
        if not iterates:
            st.warning(t("assur.iterations_unreachable", group=name))
            continue
        rows = [{"k": k, t("assur.col_residual"): sci(it.residual, 2),
                 t("assur.col_correction"): sci(it.correction, 2),
                 **{f"θ{m} [°]": num(round(float(np.degrees(a)), 9) + 0.0, 8)
                    for m, a in it.angles.items()}}
                for k, it in enumerate(iterates)]
        show_table(rows, f"{scene.id}-newton-{name}.csv", f"csv_iterations_{name}")
        last = iterates[-1].residual
        if last <= tol * 10 or last < 1e-12:
            st.caption(t("assur.iterations_done", group=name, count=len(iterates) - 1,
                         residual=sci(last, 1)))
        else:
            st.warning(t("assur.iterations_failed", group=name, count=len(iterates) - 1))


def about_the_survey(base: Scene, scene: Scene, current: Motion, survey: Motion, tol: float) -> None:
    """Under the drawing: the special points' table, Newton's accuracy and iterations."""
    if survey.special:
        st.header(t("assur.special"))
        st.caption(t("assur.special_hint"))
        table = special_table(current, 0)
        show_table(table, f"{scene.id}-special-points.csv", "special_csv")
    if survey.newton:  # the two panels are filled only while open: closed, a rerun skips
        # Newton's iterations (a third of the page's rerun) and the accuracy table
        accuracy = st.expander(t("assur.accuracy"), key="newton_accuracy", on_change="rerun")
        iterations = st.expander(t("assur.iterations"), key="newton_iterations",
                                 on_change="rerun")
    if survey.newton and accuracy.open:
        with accuracy:
            st.caption(t("assur.accuracy_hint"))
            report = next(iter(current.newton.values()))
            st.write(t("assur.instant_newton", iterations=int(report.iterations[0]),
                       residual=sci(report.residual[0], 1)))
            table = measured(base, "newton", lambda done: newton_accuracy(
                base, sweep_values(base, CYCLE), progress=done), t("app.measuring"))
            rows = [{t("assur.col_tol"): sci(r['tol'], 0),
                     t("assur.col_iter"): f"{num(r['iterations_mean'], 2)} / {r['iterations_max']}",
                     t("assur.col_ms"): num(r["solve_ms"], 1),
                     t("assur.col_error"): sci(r['error_m'], 1)}
                    for r in table]
            show_table(rows, f"{base.id}-newton-tolerance.csv", "csv_newton")
    if survey.newton and iterations.open:
        with iterations:
            newton_table(scene, tol)
    if survey.newton:
        method_doc("complex-number")


def self_check(scene: Scene, structure, current: Motion) -> list[Quantity]:
    """What a student can check: W, the number of groups, each special point at the instant."""
    quantities = [computed("W", float(degrees_of_freedom(scene)), ""),
                  computed(t("assur.self_groups"), float(len(structure.groups)), "")]
    for name, p in current.special.items():
        z = complex(p.z[0])
        if np.isfinite(z):
            quantities += [computed(f"x_{name} [m]", z.real, "m"), computed(f"y_{name} [m]", z.imag, "m"),
                           computed(f"v_{name} [m/s]", float(abs(p.v[0])), "m/s")]
    return quantities


controls, main = page_columns()
with controls:
    base = scene_picker(default="zbirka-4.1")
    seed({"at": driver_start(base), "tol": 1e-10, "upto": 99, "back": 5.0},
         st.session_state["scene"])
    position = st.container()  # φ₂ (or s): drawn by the fragment below
    tolerances = [*TOLERANCES[:3], 1e-10, TOLERANCES[3]]
    tol = bound_select_slider(t("assur.tol"), tolerances, key="tol",
                              format_func=lambda v: sci(v, 0))
    below = st.container()  # the scene's download, then the answer box

with main:  # the structure, which φ₂ does not change
    st.caption(title_of(base))
    if not hold():  # on a fresh visit, after the drawing (ui/firstpaint.py)
        counts(base)
    try:
        structure = decompose(base)
    except StructureError as exc:
        rerun_whole()  # (no drawing follows to bring the counts)
        st.error(t("assur.no_structure", reason=message(exc)))
        stop()
    st.markdown(t("assur.formula", formula=structure.formula))
    groups_place = st.container()
    groups = len(structure.groups)
    upto = groups
    if groups > 1:
        st.session_state["upto"] = min(st.session_state.get("upto", groups), groups)
        upto = bound_slider(t("assur.upto"), 1, groups, key="upto")


@fragment
def at_the_instant(base: Scene, tol: float, upto: int) -> None:
    """Everything that depends on φ₂, which moving φ₂ (or the drawing's own φ₂ control)
    reruns alone: not app.py, the scene picker, the tolerance and the structure above,
    which rerun the page and this with it. Its places outside are written on every run (a
    fragment may only write where it wrote in the page's last full run)."""
    scene, asked, answer_slot = at_position(Places(position, below), base)
    with groups_place:  # written on every run, filled when the table is shown
        groups_slot = st.container()
    try:
        current, problem = instant(scene, tol), None
    except (Unsolvable, StructureError) as exc:
        current, problem = None, exc
    if problem or not hold():  # on a fresh visit, after the drawing (ui/firstpaint.py)
        with groups_slot:
            show_table(groups_table(structure), f"{scene.id}-groups.csv", "csv_groups")
    if problem:
        rerun_whole()  # (no drawing follows to bring what the first run left out)
        st.error(t("plans.unsolvable", reason=message(problem)))
        return
    surveyed = scene.with_(at=base.driver.at)  # per geometry: φ₂ does not survey again
    survey = cycle(surveyed, tol)
    values = task_turn(base)
    frames = cranks(scene, ("structure",), "structure", values, lambda _, angles: turn_frames(
        surveyed, angles, tol, upto, current_language(), look()), asked,
        follows=("at",))  # (the structure has no speed, and the page no ω₂)
    chart(structure_figure(current, 0, upto, t("assur.fig_title"), t, look(), survey),
          f"{scene.id}-structure", key="structure", crank=frames.get("structure"))
    for issue in survey.issues:
        ranges = message(format_ranges(scene, issue.ranges))
        key = "assur.open" if issue.problem == "open" else "assur.near_singular"
        st.warning(t(key, group=issue.group, ranges=ranges))
    if waiting():
        return
    about_the_survey(base, scene, current, survey, tol)
    with answer_slot:
        answer_box(self_check(scene, structure, current), key="self")


with main:  # the fragment's own place: what it writes here needs no block of its own
    at_the_instant(base, tol, upto)
    if not waiting():  # (φ₂ does not change it: outside the fragment, its runs do not send it)
        speed_panel("assur_groups", base.id, ("newton",))
