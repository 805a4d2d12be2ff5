"""Chapters 2–3 — velocity and acceleration plans, step by step, beside the complex-number method."""

from __future__ import annotations

import math

import streamlit as st

from figures.plans import KIND_KEYS, layout_plan, mechanism_figure, plain, plan_figure, plan_svg
from figures.raw import RawFigure
from figures.style import Look
from mechanisms.schema import Scene
from methods import practice_steps
from methods.analytic import derivation, equations, solved_values
from methods.contour import contour, free_points, latex as contour_latex
from methods.plans import Plans, build, describe, readings
from methods.scales import plan_scales
from solvers.diagnostics import Unsolvable, solve_instant
from solvers.kinematics import Motion
from solvers.structure import StructureError
from ui import practice
from ui.benchmarks import speed_panel
from ui.book import book_section
from ui.cache import BY_REPR, instant, page_cache, same_call
from ui.chapters import page_title
from ui.crank import crank_frames, cranks, task_turn
from ui.docs import method_doc
from ui.export import Rows, chart, print_button, show_table
from ui.firstpaint import hold, waiting
from ui.fragments import Places, at_position, fragment
from ui.i18n import current, latex, message, num, sci, t, title_of
from ui.layout import page_columns
from ui.numbers import bound_slider, number_field
from ui.present import look
from ui.scenes import driver_speed, driver_start, scene_picker
from ui.selfcheck import answer_box, named
from ui.url import seed

SVG_CAPTIONS = {"v": "plans.svg_caption_v", "a": "plans.svg_caption_a"}

page_title("pages/velocity_plans.py")
practice.class_only("pr_plans")  # a seated student: the class's practice alone


def root_words() -> dict[str, str]:
    """The words of a chosen root, in the page's language."""
    return {"or": t("plans.root_or"), "chosen": t("plans.root_chosen"),
            "drawn": t("plans.root_drawn"), "other": t("plans.root_other")}


@same_call
@page_cache(st.cache_resource(max_entries=64, show_spinner=False, hash_funcs=BY_REPR))
def solved_plans(scene: Scene) -> Plans:
    """Both plans at the scene's instant."""
    return build(instant(scene))


def auto_scales(scene: Scene) -> dict[str, float]:
    """The book's scales when the preset has them, else round ones that fit a 12 cm plan."""
    try:
        return plan_scales(scene, solved_plans(scene))
    except (Unsolvable, StructureError):
        return plan_scales(scene, None)


def defaults(base: Scene) -> dict[str, object]:
    values: dict[str, object] = {"at": driver_start(base),
                                 "omega": float(base.driver.speed), "prec": 0.5}
    scales = auto_scales(base)
    values.update(UL=scales["L"], Uv=scales["v"], Ua=scales["a"])
    return values


def scale_inputs() -> dict[str, float]:
    with st.expander(t("plans.scales"), expanded=True):
        st.caption(t("plans.scales_hint"))
        labels = {"L": "plans.UL", "v": "plans.Uv", "a": "plans.Ua"}
        scales = {k: number_field(t(label), f"U{k}", minimum=1e-9, url=True)
                  for k, label in labels.items()}
        precision = bound_slider(t("plans.precision"), 0.1, 2.0, step=0.1, key="prec")
    return {"L": scales["L"], "v": scales["v"], "a": scales["a"], "precision_cm": precision / 10}


def plan_figures(scene: Scene, plans: Plans, scales: dict[str, float], index: int,
                 motion: Motion | None = None) -> dict[str, RawFigure]:
    """Both plans up to step ``index`` and the mechanism, at the scene's instant."""
    out = {key: plan_figure(layout_plan(plan, scales[key], index),
                            t(title, scale=num(scales[key], 4)), t, look())
           for plan, key, title in ((plans.velocity, "v", "plans.velocity_title"),
                                    (plans.acceleration, "a", "plans.acceleration_title"))}
    at = num(math.degrees(scene.driver.at) % 360, 4)
    out["mech"] = mechanism_figure(motion or instant(scene), plans,
                                   t("plans.mechanism_title", at=at), t, look())
    return out


@page_cache(st.cache_resource(max_entries=8, show_spinner=False, hash_funcs=BY_REPR))
def turn_frames(scene: Scene, values: tuple[float, ...], scales: dict[str, float], index: int,
                language: str, look_: Look) -> dict[str, str]:
    """The three figures at the angles ``values`` (ui.crank.task_turn: every 5° of φ₂ and
    the task's instant), once per geometry, scales and step: the scene comes at φ₂ = 0,
    so the angle the page shows is not part of the key."""
    def draw(_: int, angle: float) -> dict[str, RawFigure] | None:
        at = scene.with_(at=angle)
        try:
            motion = solve_instant(at, None)
            return plan_figures(at, build(motion), scales, index, motion)
        except (Unsolvable, StructureError):
            return None

    return crank_frames(draw, values)


def step_table(plans: Plans, scene: Scene, scales: dict[str, float], index: int) -> Rows:
    """The vectors of one step in both plans: name, kind, direction, plan length, value."""
    rows = []
    for plan, key, unit in ((plans.velocity, "v", "m/s"), (plans.acceleration, "a", "m/s²")):
        for _, side in plan.steps[index].sides:
            for a in side:
                rows.append({t("plans.col_vector"): plain(a.symbol), t("plans.col_kind"): t(KIND_KEYS[a.kind]),
                             t("plans.col_direction"): describe(a.rule, scene),
                             t("plans.col_plan"): num(abs(a.value) / scales[key], 3),
                             t("plans.col_value"): f"{num(abs(a.value), 4)} {unit}"})
    return rows


def member_table(plans: Plans) -> Rows:
    """ω and ε of every member, with its sense of rotation."""
    return [{t("plans.col_member"): n, t("plans.col_omega"): num(w, 5),
             t("plans.col_epsilon"): num(e, 5),
             t("plans.col_sense"): t("plans.ccw" if w > 0 else "plans.cw" if w < 0 else "plans.still")}
            for n, (w, e) in sorted(plans.members.items())]


def plans_tab(scene: Scene, base: Scene, plans: Plans, scales: dict[str, float], step: int,
              asked: bool) -> None:
    """The step's equations, both plans and the mechanism, the step's and members' tables."""
    steps = plans.velocity.steps
    index = step - 1
    later = hold()  # on a fresh visit the charts below come first (ui/firstpaint.py)
    if not later:
        st.latex(latex(steps[index].latex))
        st.latex(latex(plans.acceleration.steps[index].latex))
        if any(a.kind == "coriolis" for _, side in plans.acceleration.steps[index].sides for a in side):
            st.caption(t("plans.extension", point=steps[index].target.upper()))
        if any(g.cls == 3 for g in instant(scene).structure.groups):
            method_doc("triad-plans")
    figures = plan_figures(scene, plans, scales, index)
    values = task_turn(base)
    frames = cranks(scene, ("v", "a", "mech"), "plans", values,
                    lambda shown, angles: turn_frames(shown.with_(at=0.0), angles, scales, index,
                                                      current(), look()), asked)
    left, right = st.columns(2)
    for column, plan, key in ((left, plans.velocity, "v"), (right, plans.acceleration, "a")):
        with column:
            chart(figures[key], f"{scene.id}-{plan.quantity}-plan", key=f"fig_{key}",
                  crank=frames.get(key))
            if not later:
                caption = t(SVG_CAPTIONS[key], scene=scene.id, scale=num(scales[key], 4))
                print_button(lambda plan=plan, key=key, caption=caption: plan_svg(
                                 layout_plan(plan, scales[key]), caption),
                             f"{scene.id}-{plan.quantity}-plan.svg", key=f"svg_{key}")
    if not later:
        show_table(step_table(plans, scene, scales, index), f"{scene.id}-step-{step}.csv",
                   "csv_step")
        show_table(member_table(plans), f"{scene.id}-members.csv", "csv_members")
    chart(figures["mech"], f"{scene.id}-mechanism", key="fig_mech", crank=frames.get("mech"))


def loops_tab(scene: Scene, plans: Plans) -> None:
    """The complex-number method, group by group, and its values beside the plans'."""
    st.write(t("plans.analytic_intro"))
    for group in instant(scene).structure.groups:
        if group.cls == 3:  # no closed form: Newton's method on the Assur groups page
            st.info(t("plans.triad_loops", group=group.label()))
            st.page_link("pages/assur_groups.py", label=t("plans.to_assur"))
            continue
        eq = equations(scene, group)
        st.markdown(f"**{eq.group} · {eq.kind}** — {t('plans.unknowns')}: "
                    + ", ".join(f"${u}$" for u in eq.unknowns))
        st.latex(latex(eq.position))
        st.caption(t("plans.derivation"))
        for line in derivation(instant(scene), group, words=root_words()):
            st.latex(latex(line))
        st.latex(latex(r"\text{B:}\ " + eq.velocity))
        st.latex(latex(r"\text{C:}\ " + eq.acceleration))
    for name in free_points(scene):
        chain = contour(scene, name)
        if chain is not None:
            st.markdown(t("plans.final_contour", point=name))
            for line in contour_latex(instant(scene), chain):
                st.latex(latex(line))
    units = {"member": ("°", "s⁻¹", "s⁻²"), "slide": ("m", "m/s", "m/s²")}
    names = {"member": "plans.row_member", "slide": "plans.row_slide"}
    rows = [{t("plans.col_quantity"): t(names[r["kind"]], name=r["name"]),
             t("plans.col_position"): f"{num(r['position'], 6)} {units[r['kind']][0]}",
             t("plans.col_rate"): f"{num(r['rate'], 6)} {units[r['kind']][1]}",
             t("plans.col_acc"): f"{num(r['acceleration'], 6)} {units[r['kind']][2]}"}
            for r in solved_values(instant(scene))]
    show_table(rows, f"{scene.id}-analytic.csv", "csv_analytic")
    st.success(t("plans.agreement", v=sci(plans.velocity.closure(), 1),
                 a=sci(plans.acceleration.closure(), 1)))
    method_doc("complex-number")


def accuracy_tab(scene: Scene, base: Scene, values: list, precision_cm: float) -> None:
    """What reading each vector off a drawing to the chosen precision misses."""
    st.write(t("plans.accuracy_intro", precision=num(precision_cm * 10, 2)))
    table = [{t("plans.col_vector"): plain(r.symbol),
              t("plans.col_value"): f"{num(r.exact, 5)} {r.unit}",
              t("plans.col_plan"): "—" if r.plan_cm is None else num(r.plan_cm, 3),
              t("plans.col_uncertainty"): f"± {num(r.uncertainty, 2)} {r.unit}",
              t("plans.col_relative"): f"{num(100 * r.uncertainty / r.exact, 2)} %"
              if r.exact else "—"} for r in values]
    show_table(table, f"{scene.id}-readings.csv", "csv_readings")
    if scene.book:
        book_section(scene, base, {k: v for k, v in defaults(base).items() if k in ("at", "omega")})


controls, main = page_columns()
with controls:
    base = scene_picker()
    seed(defaults(base), st.session_state["scene"])
    position = st.container()  # φ₂ (or s): drawn by the fragment below
    driven = driver_speed(base, wait=True)
    scales = scale_inputs()
    below = st.container()  # the scene's download, then the answer box


@fragment
def at_the_instant(driven: Scene, scales: dict[str, float]) -> None:
    """Everything that depends on φ₂, which moving φ₂ (or the step, or a chart's own φ₂
    control) reruns alone: not app.py, the scene picker, ω₂ and the scales (a fifth of the
    page's rerun). Any of those reruns the page, and this with it. It runs in the main
    column; a fragment may only write outside it where it wrote in the page's last full run,
    so the answer box's place is written on every run (ui/firstpaint.py leaves the box out
    of a first run)."""
    scene, asked, answer_slot = at_position(Places(position, below), driven)
    try:
        plans = solved_plans(scene)
    except Unsolvable as exc:
        st.error(t("plans.unsolvable", reason=message(exc)))
        return
    except StructureError:  # a class III group without its special point S at this instant
        group = next(g for g in instant(scene).structure.groups if g.cls == 3)
        st.info(t("plans.not_drawn", group=group.label()))
        st.page_link("pages/assur_groups.py", label=t("plans.to_assur"))
        return

    steps = plans.velocity.steps
    st.caption(title_of(scene))
    if st.session_state.get("step", 0) > len(steps):
        st.session_state["step"] = len(steps)
    step = len(steps)
    if len(steps) > 1:  # a crank alone has one step and nothing to step through
        step = bound_slider(t("plans.step"), 1, len(steps), value=len(steps), key="step")
    tab_plans, tab_loops, tab_accuracy = st.tabs(
        [t("plans.tab_plans"), t("plans.tab_analytic"), t("plans.tab_accuracy")],
        key="tab", on_change="rerun")
    if tab_plans.open:
        with tab_plans:
            if practice.toggle("pr_plans"):
                practice.panel(practice_steps.plans(plans, scales), "pr_plans",
                               t("practice.sheet_plans"))
            else:
                plans_tab(scene, base, plans, scales, step, asked)
    if tab_loops.open:
        with tab_loops:
            loops_tab(scene, plans)
    if tab_accuracy.open:  # (its readings made only for it)
        with tab_accuracy:
            accuracy_tab(scene, base, readings(plans, scales, scales["precision_cm"]),
                         scales["precision_cm"])
    if not waiting():
        with answer_slot:  # signed ω, ε and the task's tolerances (exams.judged)
            answer_box(lambda: named(scene, base), key="self")


with main:  # the fragment's own place: what it writes here needs no block of its own
    at_the_instant(driven, scales)
    if not waiting():  # (φ₂ does not change it: outside the fragment, its runs do not send it)
        speed_panel("velocity_plans", base.id, ("kinematics", "graphical"))
