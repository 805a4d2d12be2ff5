"""Chapter 5 — kinetostatics: joint reactions F_pq, inertia loads, the driving torque and power
over the cycle, with force polygons and Zhukovsky's lever."""

from __future__ import annotations

import math

import numpy as np
import streamlit as st

from figures.kinetostatics import cycle_figure, forces_figure, html, lever_figure
from figures.polygon import polygon_figure, polygon_svg
from figures.raw import RawFigure
from figures.style import Look
from mechanisms.schema import Scene
from methods import practice_steps
from methods.force_steps import equation, steps as force_steps
from methods.lever_steps import construction as lever_construction, latex as lever_latex
from methods.scales import polygon_scale
from reports.values import has_loads
from solvers.diagnostics import Unsolvable, format_ranges, sweep_values, torque_resolution
from solvers.kinetostatics import Action, Kinetostatics, analyse, free_body
from solvers.structure import StructureError
from ui import practice
from ui.benchmarks import speed_panel
from ui.book import book_section
from ui.cache import BY_REPR, instant, page_cache, same_call
from ui.chapters import page_title
from ui.crank import crank_frames, cranks, task_turn
from ui.docs import method_doc
from ui.export import Rows, chart, print_button, show_table
from ui.firstpaint import rerun_whole, waiting
from ui.fragments import Places, at_position, fragment
from ui.i18n import current, latex, message, num, scaled_title, sci, t, title_of
from ui.layout import page_columns
from ui.numbers import bound_select_slider, bound_slider, last_value, link_switch, number_field
from ui.present import look
from ui.progress import measured
from ui.scenes import driver_speed, driver_start, scene_picker
from ui.selfcheck import answer_box, named
from ui.url import seed, stop

page_title("pages/kinetostatics.py")
practice.class_only("pr_forces", "pr_lever")  # a seated student: the class's practice alone
RESOLUTIONS = (12, 72, 360, 3600)


@page_cache(st.cache_resource(max_entries=32, hash_funcs=BY_REPR))
def over_cycle(scene: Scene, steps: int, inertia: bool) -> Kinetostatics:
    """``steps`` positions over the cycle. Called with the scene at its preset instant, so
    that moving φ₂ does not analyse the cycle again (only the marker moves)."""
    return analyse(scene, sweep_values(scene, steps), inertia=inertia)


@same_call
@page_cache(st.cache_resource(max_entries=64, show_spinner=False, hash_funcs=BY_REPR))
def at_instant(scene: Scene, inertia: bool) -> Kinetostatics:
    """The scene's own instant alone (the same numbers as that position of a survey), from
    its cached kinematics: the page solves that instant first, to explain a failure."""
    return analyse(scene, inertia=inertia, motion=instant(scene))


def defaults(base: Scene) -> dict[str, object]:
    values: dict[str, object] = {
        "at": driver_start(base),
        "omega": float(base.driver.speed), "inertia": base.inertia, "gravity": base.gravity > 0,
        "steps": 360, "UF": base.scales.get("F", 0.0), "fstep": 1}
    for n, m in base.members.items():
        values[f"m{n}"], values[f"rho{n}"] = float(m.mass), float(m.gyration)
    for i, f in enumerate(base.forces):
        values[f"F{i}"], values[f"Fa{i}"] = float(f.magnitude), math.degrees(f.angle)
    for i, mo in enumerate(base.moments):
        values[f"M{i}"] = float(mo.value)
    return values


def task_values(base: Scene) -> dict[str, object]:
    """The widgets' values that pose the book's task: position, speed, switches and loads
    (not the scales, the resolution or the step shown)."""
    return {k: v for k, v in defaults(base).items() if k not in ("steps", "UF", "fstep")}


def load_inputs(base: Scene, scene: Scene) -> Scene:
    """Masses, radii of gyration, forces and moments, all kept in the link. Their fields sit
    in a shut expander: a fresh visit sends them after the chart's paint (thirteen text
    boxes of the default scene: ui.firstpaint), unless the link set them."""
    def field(label: str, key: str, **options) -> float:
        return number_field(label, key, url=True, wait=True, **options)

    inertia = link_switch(t("forces.inertia"), "inertia")
    gravity = link_switch(t("forces.gravity"), "gravity")
    with st.expander(t("forces.loads"), expanded=False):
        forces, angles = [], []
        for i, f in enumerate(base.forces):
            left, right = st.columns([3, 2])
            forces.append(field(t("forces.force_input", name=f.label or f"F_{f.member}",
                                  point=f.point), f"F{i}", where=left))
            degrees = field(
                t("forces.force_angle_follows" if f.follows_member else "forces.force_angle"),
                f"Fa{i}", where=right)  # the file's angle exactly, unless changed
            angles.append(f.angle if degrees == math.degrees(f.angle) else math.radians(degrees))
        moments = [field(t("forces.moment_input", member=mo.member), f"M{i}")
                   for i, mo in enumerate(base.moments)]
        masses, rhos = {}, {}
        for n in base.members:
            left, right = st.columns(2)
            masses[n] = field(t("forces.mass", member=n), f"m{n}", minimum=0.0, where=left)
            rhos[n] = field(t("forces.rho", member=n), f"rho{n}", minimum=0.0, where=right)
    return scene.with_loads(masses=masses, gyrations=rhos, forces=forces, angles=angles,
                            moments=moments, inertia=inertia,
                            gravity=(base.gravity or 9.81) if gravity else 0.0)


def reactions_table(k: Kinetostatics, i: int) -> Rows:
    rows = []
    for (p, q), r in sorted(k.reactions.items()):
        if p > q:
            continue
        f = complex(r.force[i])
        row = {"F_pq": f"F_{p}{q}", t("forces.col_pair"): f"{r.pair.letter} {r.pair.point}",
               "x [N]": num(f.real, 4), "y [N]": num(f.imag, 4), "|F| [N]": num(abs(f), 4),
               t("forces.col_angle"): num(math.degrees(math.atan2(f.imag, f.real)) % 360, 4)}
        if r.pair.kind == "prismatic":
            row["h [m]"] = num(float(r.offset[i]), 4)
        rows.append(row)
    return rows  # h belongs to sliding pairs only: "—" in the others' rows


def inertia_table(k: Kinetostatics, i: int) -> Rows:
    rows = []
    for n, inert in sorted(k.inertia.items()):
        K = None if inert.huygens is None else complex(inert.huygens[i])
        rows.append({t("forces.col_member"): n, "|F_i| [N]": num(abs(inert.force[i]), 4),
                     "M_i [N·m]": num(float(inert.moment[i]), 4),
                     "S [m]": f"({num(inert.centre[i].real, 4)}; {num(inert.centre[i].imag, 4)})",
                     "K [m]": "—" if K is None else f"({num(K.real, 4)}; {num(K.imag, 4)})",
                     t("forces.col_huygens_moment"): num(float(inert.huygens_moment[i]), 4)})
    return rows


def driving_metrics(k: Kinetostatics, i: int) -> None:
    unit, symbol = ("N·m", "M_p") if k.rotating else ("N", "F_p")
    cols = st.columns(4)
    # units beside the names: four values with their units did not fit a column and were cut
    cols[0].metric(f"{t('forces.by_groups', symbol=symbol)} [{unit}]", num(k.driving[i], 5))
    cols[1].metric(f"{t('forces.by_lever', symbol=symbol)} [{unit}]", num(k.driving_lever[i], 5))
    cols[2].metric(f"{t('forces.by_power', symbol=symbol)} [{unit}]", num(k.driving_power[i], 5))
    cols[3].metric(f"{t('forces.power')} [W]", num(k.power[i], 5))
    st.caption(t("forces.agreement", spread=sci(k.disagreement[i], 1),
                 residual=sci(k.power_residual[i], 1)))
    if k.crank_force is not None:
        st.caption(t("forces.crank_force", value=num(k.crank_force[i], 4)))


def group_name(group: str) -> str:
    return t("forces.driver") if group == "driver" else t("forces.group_label", members=group)


def construction_steps(k: Kinetostatics, now: int) -> None:
    """The graphical method one equation at a time: a step slider (forwards and backwards),
    the equation with its numbers, and the free body or the polygon drawn to the scale U_F."""
    construction = force_steps(k, now)
    count = len(construction.steps)
    st.write(t("forces.steps_intro"))
    st.session_state["fstep"] = min(max(int(st.session_state.get("fstep", 1)), 1), count)
    number = bound_slider(t("forces.step"), 1, count, key="fstep")
    step = construction.steps[number - 1]
    members = ", ".join(str(m) for m in sorted(step.members))
    what = {"moment": t("forces.step_moment", members=members, point=step.about),
            "polygon": t("forces.step_polygon", members=members),
            "together": t("forces.step_together", members=members)}[step.kind]
    if step.about == "S" and len(step.members) > 1:
        what = t("forces.step_special", members=members)
    st.markdown(f"**{number}/{count} · {group_name(step.group)}** — {what}")
    for line in equation(step):
        st.latex(latex(line))
    st.caption(t("forces.step_units"))
    if step.kind == "polygon":
        known = [(html(term.name), term.force) for term in step.terms]
        closing = [(html(name), force) for name, force in step.closing]
        uf = last_value("UF") or polygon_scale(f for _, f in known + closing)
        chart(polygon_figure(known, closing, uf, scaled_title(t("forces.polygon_title"), uf, "N"),
                             (t("forces.legend_known"), t("forces.legend_closing")), look()),
              f"{k.motion.scene.id}-step-{number}", key="fig_step")
    elif step.kind == "moment":
        marks = {step.about: step.at} if step.at is not None else None
        chart(forces_figure(k, now, step.forces(), t("forces.free_body_title"), t, look(),
                            members=step.members, marks=marks),
              f"{k.motion.scene.id}-step-{number}", key="fig_step")
    method_doc("graphical-kinetostatics")
    if number == count:
        unit, symbol = ("N·m", "M_p") if k.rotating else ("N", "F_p")
        st.success(t("forces.steps_done", symbol=symbol, value=num(construction.driving, 5),
                     unit=unit, solver=num(float(k.driving[now]), 5)))


def book_lever(k: Kinetostatics, now: int) -> None:
    """The reduced mechanism as tasks 5.3–5.4 write it: the unlettered points placed by
    proportion, the moments about the pole, F_p and M_p against the group-by-group value."""
    st.header(t("forces.lever_book"))
    st.caption(t("forces.lever_book_hint"))
    lever = lever_construction(k, now)
    proportions, moments = lever_latex(lever, k.rotating)
    for line in proportions + moments:
        st.latex(latex(line))
    if k.rotating:
        st.success(t("forces.lever_compare", symbol="M_p", lever=num(lever.torque, 5),
                     groups=num(float(k.driving[now]), 5), unit="N·m"))
    else:
        st.success(t("forces.lever_compare", symbol="F_p", lever=num(lever.balancing, 5),
                     groups=num(float(k.driving[now]), 5), unit="N"))


def loads_figure(k: Kinetostatics, i: int, at_label: str) -> RawFigure:
    """The mechanism at position ``i`` with every load and inertia force."""
    loads = [(ld.name, complex(ld.point[i]), complex(ld.force[i])) for ld in k.loads]
    return forces_figure(k, i, loads, t("forces.loads_title", at=at_label), t, look())


def polygon_figures(k: Kinetostatics, i: int, members: tuple[int, ...], actions: list[Action],
                    uf: float) -> dict[str, RawFigure]:
    """A group's free body (its ``actions`` at position ``i``) and its force polygon to the
    scale ``uf``."""
    known = [(html(a.name), a.force) for a in actions if a.known]
    closing = [(html(a.name), a.force) for a in actions if not a.known]
    return {"free_body": forces_figure(k, i, [(a.name, a.point, a.force) for a in actions],
                                       t("forces.free_body_title"), t, look(), members=members),
            "polygon": polygon_figure(known, closing, uf,
                                      scaled_title(t("forces.polygon_title"), uf, "N"),
                                      (t("forces.legend_known"), t("forces.legend_closing")),
                                      look())}


@page_cache(st.cache_resource(max_entries=8, show_spinner=False, hash_funcs=BY_REPR))
def turn_frames(scene: Scene, values: tuple[float, ...], inertia: bool,
                members: tuple[int, ...] | None, uf: float, language: str,
                look_: Look) -> dict[str, str]:
    """The loads (``members`` None) or a group's free body and polygon (to ``uf``, or a scale
    that fits each position when 0) at the angles ``values`` (ui.crank.task_turn: every 5°
    of φ₂ and the task's instant), from one analysis of the turn; the scene comes at
    φ₂ = 0."""
    k = analyse(scene, np.radians(values), inertia=inertia)

    def draw(i: int, _: float) -> dict[str, RawFigure] | None:
        if not (k.motion.feasible[i] and np.isfinite(k.driving[i])):
            return None
        if members is None:
            return {"loads": loads_figure(k, i, f"{num(values[i], 4)}°")}
        actions = free_body(k, members, i)
        return polygon_figures(k, i, members, actions, uf or polygon_scale(a.force for a in actions))

    return crank_frames(draw, values)


def load_tables(k: Kinetostatics, now: int) -> None:
    """Under the loads: the joint reactions, and the inertia loads when they count."""
    st.header(t("forces.reactions"))
    st.caption(t("forces.reactions_hint"))
    show_table(reactions_table(k, now), f"{k.motion.scene.id}-reactions.csv", "csv_reactions")
    if k.inertia:
        st.header(t("forces.inertia_title"))
        st.caption(t("forces.inertia_hint"))
        show_table(inertia_table(k, now), f"{k.motion.scene.id}-inertia.csv", "csv_inertia")


def polygons_tab(k: Kinetostatics, now: int, scene: Scene, values: tuple[float, ...],
             asked: bool) -> None:
    """One group's free body and force polygon at this instant, at the scale asked (0: one
    that fits), with its φ₂ frames, print and table."""
    groups = {g.name: g.members for g in k.motion.structure.groups}
    groups["driver"] = (2,)
    names = list(k.order)
    choice = st.selectbox(t("forces.group"), names, key="group",
                          format_func=lambda n: t("forces.driver") if n == "driver"
                          else t("forces.group_label", members=n))
    asked_uf = number_field(t("forces.UF"), "UF", minimum=0.0,
                            url=True)  # 0: a scale that fits each position
    actions = free_body(k, groups[choice], now)
    uf = asked_uf or polygon_scale(a.force for a in actions)
    figures = polygon_figures(k, now, groups[choice], actions, uf)
    frames = cranks(scene, ("free_body", "polygon"), "forces", values,
                    lambda shown, angles: turn_frames(
                        shown.with_(at=0.0), angles, st.session_state["inertia"], groups[choice],
                        asked_uf, current(), look()), asked)
    chart(figures["free_body"], f"{scene.id}-free-body-{choice}", key="fig_free_body",
          crank=frames.get("free_body"))
    chart(figures["polygon"], f"{scene.id}-polygon-{choice}", key="fig_polygon",
          crank=frames.get("polygon"))
    caption = t("forces.svg_caption", scene=scene.id, group=choice, scale=num(uf, 4))
    print_button(lambda: polygon_svg([(a.name, a.force) for a in actions if a.known],
                                     [(a.name, a.force) for a in actions if not a.known], uf,
                                     caption),
                 f"{scene.id}-polygon-{choice}.svg", key="svg_polygon")
    polygon = [{t("forces.col_force"): a.name, "|F| [N]": num(abs(a.force), 4),
                t("forces.col_plan"): num(abs(a.force) / uf, 3),
                t("forces.col_angle"): num(math.degrees(math.atan2(
                    a.force.imag, a.force.real)) % 360, 4)} for a in actions]
    show_table(polygon, f"{scene.id}-polygon-{choice}.csv", "csv_polygon")


def cycle_tab(scene: Scene, base: Scene, steps: int, rotating: bool) -> None:
    """The driving torque, power and reactions over the cycle (analysed once per geometry;
    φ₂ moves the marker), and what the cycle's resolution costs."""
    c = over_cycle(scene.with_(at=base.driver.at), steps, st.session_state["inertia"])
    x = c.motion.at
    x = np.degrees(x) if rotating else x
    symbol = "M_p [N·m]" if rotating else "F_p [N]"
    chart(cycle_figure(x, [(symbol, c.driving, "y"), ("P [W]", c.power, "y2")],
                       st.session_state["at"], t("forces.cycle_title"),
                       t("plans.phi") if rotating else t("plans.s"), look()),
          f"{scene.id}-torque", key="fig_cycle")
    power = c.power
    feasible = np.isfinite(power)
    peak = float(np.nanmax(np.abs(power), initial=0))
    # the mean over a cycle of loads that do no net work is zero up to rounding: show 0
    mean = float(np.mean(power[feasible])) if feasible.any() else math.nan
    mean = 0.0 if abs(mean) <= 1e-9 * peak else mean
    cols = st.columns(3)
    cols[0].metric(t("forces.mean_power"), f"{num(mean, 4)} W" if feasible.any() else "—")
    cols[1].metric(t("forces.peak_power"), f"{num(peak, 4)} W")
    name, unit = ("M_p", "N·m") if rotating else ("F_p", "N")
    cols[2].metric(t("forces.peak_driving", symbol=name),
                   f"{num(np.nanmax(np.abs(c.driving), initial=0), 4)} {unit}")
    if not feasible.all():
        st.caption(t("forces.part_cycle", share=num(100 * feasible.mean(), 3)))
    for issue in c.motion.issues:
        ranges = message(format_ranges(scene, issue.ranges))
        if issue.problem == "near-singular":
            st.warning(t("forces.dead_point", group=issue.group, ranges=ranges))
    pairs = [(f"|F_{p}{q}|", r.magnitude, "y") for (p, q), r in sorted(c.reactions.items())
             if p < q]
    chart(cycle_figure(x, pairs, st.session_state["at"], t("forces.reactions_cycle"),
                       t("plans.phi") if rotating else t("plans.s"), look(), y_title="|F| [N]"),
          f"{scene.id}-reactions-cycle", key="fig_reactions_cycle")
    with st.expander(t("forces.resolution")):
        st.caption(t("forces.resolution_hint"))
        inertia = st.session_state["inertia"]
        table = measured(scene, "resolution", lambda done: torque_resolution(scene, RESOLUTIONS, inertia, done),
                         t("app.measuring"), variant=inertia)
        rows = [{t("forces.col_steps"): r["steps"], t("assur.col_ms"): num(r["ms"], 3),
                 t("forces.col_peak"): num(r["peak"], 6),
                 t("forces.col_change"): f"{num(r['change'], 3)} %"}
                for r in table]
        show_table(rows, f"{scene.id}-resolution.csv", "csv_resolution")


controls, main = page_columns()
with controls:
    base = scene_picker(default="predavanja-kinetostatika")
    seed(defaults(base), st.session_state["scene"])
    position = st.container()  # φ₂ (or s): drawn by the fragment below
    loaded = load_inputs(base, driver_speed(base, wait=True))
    steps = bound_select_slider(t("forces.steps"), RESOLUTIONS, key="steps", wait=True)
    below = st.container()  # the scene's download, then the answer box


@fragment
def at_the_instant(loaded: Scene, steps: int) -> None:
    """Everything that depends on φ₂, which moving φ₂ reruns alone (not the scene picker and
    the fifteen or so load inputs above, a quarter of the page's rerun): its slider, the
    charts, tables and answers at that instant, the cycle's tab (its marker). A load, ω₂ or
    the scene rerun the page, and this with it."""
    scene, asked, answer_slot = at_position(Places(position, below), loaded)

    st.caption(title_of(scene))
    if not has_loads(scene):
        st.info(t("forces.no_loads"))
    try:
        instant(scene)  # raises with the reason when the mechanism cannot be in this position
        k = at_instant(scene, st.session_state["inertia"])
    except (Unsolvable, StructureError) as exc:
        rerun_whole()  # (no chart follows to bring the controls a first run holds back)
        st.error(t("plans.unsolvable", reason=message(exc)))
        stop()
    now = 0  # k holds the instant only
    if not np.isfinite(k.driving[now]):
        st.warning(t("forces.singular"))
    results = st.container()  # the driving torque: filled below, unless the student practises
    tabs = st.tabs([t("forces.tab_loads"), t("forces.tab_polygons"), t("forces.tab_steps"),
                    t("forces.tab_lever"), t("forces.tab_cycle")], key="tab", on_change="rerun")


    rotating = scene.driver.kind == "rotating"
    values = task_turn(base)  # the φ₂ frames' angles, the task's instant among them
    at_label = f"{num(st.session_state['at'], 4)}{'°' if rotating else ' m'}"
    if tabs[0].open:
        with tabs[0]:
            frames = cranks(scene, ("loads",), "forces", values,
                            lambda shown, angles: turn_frames(
                                shown.with_(at=0.0), angles, st.session_state["inertia"], None,
                                0.0, current(), look()), asked)
            chart(loads_figure(k, now, at_label), f"{scene.id}-loads", key="fig_loads",
                  crank=frames.get("loads"))
        if not waiting():  # on a fresh visit, after the chart is painted (ui/firstpaint.py)
            with tabs[0]:
                load_tables(k, now)

    if tabs[1].open:
        with tabs[1]:
            polygons_tab(k, now, scene, values, asked)

    practising = False
    if tabs[2].open:
        with tabs[2]:
            practising = practice.toggle("pr_forces")
            if practising:
                uf = last_value("UF") or polygon_scale(
                    complex(r.force[now]) for r in k.reactions.values())
                practice.panel(practice_steps.forces(k, now, uf), "pr_forces",
                               t("practice.sheet_forces"))
            else:
                construction_steps(k, now)

    if tabs[3].open:
        with tabs[3]:
            st.write(t("forces.lever_intro"))
            practising = practice.toggle("pr_lever")
            if practising:
                practice.panel(practice_steps.lever(k, now), "pr_lever", "", drawable=False)
            else:
                chart(lever_figure(k, now, t("forces.lever_title"), t, look()), f"{scene.id}-lever",
                      key="fig_lever")
                speed = scene.driver.speed or 1.0
                lever = [{t("forces.col_force"): f.name, "|F| [N]": num(abs(f.force[now]), 4),
                          t("forces.col_moment"): num(float(f.moment[now]) * speed, 4)}
                         for f in k.lever if abs(f.force[now]) > 0]
                show_table(lever, f"{scene.id}-lever.csv", "csv_lever")
                book_lever(k, now)
                method_doc("reduced-mechanism")

    if not practising and not waiting():  # (what the construction ends with; after the paint)
        with results:
            driving_metrics(k, now)

    if tabs[4].open:
        with tabs[4]:
            cycle_tab(scene, base, steps, rotating)

    if not waiting():
        if scene.book:
            book_section(scene, base, task_values(base))
        with answer_slot:  # M_p or F_p, P, |F_pq|, parts (exams.judged), as the page counts inertia
            answer_box(lambda: named(scene.with_loads(inertia=st.session_state["inertia"]), base), key="self")


with main:  # the fragment's own place: what it writes here needs no block of its own
    at_the_instant(loaded, steps)
    if not waiting():  # (φ₂ does not change it: outside the fragment, its runs do not send it)
        speed_panel("kinetostatics", loaded.id, ("kinetostatics",))
