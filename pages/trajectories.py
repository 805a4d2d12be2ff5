"""Chapter 1 — point paths: the 12-step construction, smooth paths, animation, and the hay tedder."""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np
import pandas as pd
import streamlit as st

from figures.raw import RawFigure
from figures.style import Look
from figures.trajectories import animation_figure, compass_figure, construction_figure, field_figure
from mechanisms.schema import Scene, Travel
from methods import practice_steps
from methods.compass import construction as compass_steps
from methods.scales import plan_scales
from solvers import solve
from solvers.diagnostics import Unsolvable, dead_zones, format_ranges
from solvers.kinematics import GroupIssue, Motion
from solvers.paths import (
    animation_order,
    cycle_time,
    cycle_values,
    field_path,
    loops_backward,
    numbered_points,
    path_errors,
    path_length,
    solve_times,
    strokes,
    swings,
)
from solvers.structure import StructureError
from ui import practice
from ui.benchmarks import speed_panel
from ui.book import book_section
from ui.cache import BY_REPR, cycle, page_cache
from ui.chapters import page_title
from ui.crank import Crank, Ranged, crank_frames, live, slider_control
from ui.docs import method_doc
from ui.export import chart, csv_button, show_table
from ui.firstpaint import waiting
from ui.fragments import fragment
from ui.i18n import current, message, num, t, title_of
from ui.layout import page_columns
from ui.numbers import (bound_choices, bound_select_slider, bound_slider, link_note,
                        link_option)
from ui.present import look
from ui.scenes import length_range, length_slider, scene_download, scene_picker
from ui.selfcheck import answer_box, computed, named
from ui.url import seed

RESOLUTIONS = (12, 72, 360, 3600)
MAX_FRAMES = 120
SMOOTH_FRAMES = 360  # the finest paths a chart's control has frames of (3600 would send 5 MB)
CHART_LENGTH = "chart_length"  # session: the length the paths chart's control moves ("L3")
CHART_TRAVEL = "chart_travel"  # session: what of the travel the field chart's control moves
# the hay tedder's travel (task 1.3), slider by slider: its label, Travel's field, range, unit
TRAVEL = {"vR": ("traj.v_R", "speed", 0.5, 8.0, 0.1, " m/s"),
          "Rt": ("traj.R_t", "wheel_radius", 0.15, 0.6, 0.01, " m"),
          "Ra": ("traj.R_a", "sprocket_wheel", 0.02, 0.2, 0.005, " m"),
          "Rb": ("traj.R_b", "sprocket_crank", 0.02, 0.2, 0.005, " m")}

page_title("pages/trajectories.py")
practice.class_only("pr_compass")  # a seated student: the class's practice alone


@page_cache(st.cache_data(max_entries=16, show_spinner=False, hash_funcs=BY_REPR))
def _solve_times(base: Scene) -> dict[int, float]:
    return solve_times(base, RESOLUTIONS)


@page_cache(st.cache_data(max_entries=64, show_spinner=False, hash_funcs=BY_REPR))
def _path_errors(scene: Scene, points: tuple[str, ...]) -> dict[int, float]:
    return path_errors(scene, list(points), RESOLUTIONS)


def accuracy(base: Scene, scene: Scene, points: tuple[str, ...]) -> list[dict]:
    """The resolution table: solve times measured once per mechanism as loaded (lengths do
    not change them), path errors once per geometry (ω₂ changes neither)."""
    times = _solve_times(base.with_(speed=1.0))
    errors = _path_errors(scene.with_(speed=1.0), points)
    return [{"positions": n, "solve_ms": times[n], "deviation_m": errors[n]} for n in RESOLUTIONS]


@page_cache(st.cache_resource(max_entries=16, show_spinner=False, hash_funcs=BY_REPR))
def animation(scene: Scene, steps: int, points: tuple[str, ...], language: str, look_: Look):
    """The animation figure (the costliest to build); shared, never mutated."""
    fine = cycle(scene, steps, order=1)
    order = animation_order(fine.feasible)
    frames = order[::-(-len(order) // MAX_FRAMES)]  # at most MAX_FRAMES frames
    return animation_figure(fine, frames, list(points), title_of(scene), t, look_).freeze()


@page_cache(st.cache_resource(max_entries=32, show_spinner=False, hash_funcs=BY_REPR))
def zones(scene: Scene) -> list[GroupIssue]:
    """Where the mechanism cannot be assembled, once per geometry (a survey of the cycle)."""
    return dead_zones(scene)


@page_cache(st.cache_resource(max_entries=32, show_spinner=False, hash_funcs=BY_REPR))
def paths_figure(scene: Scene, smooth: int | None, numbered: tuple[str, ...], language: str,
                 look_: Look):
    """The 12-step construction with the paths through it, or ``smooth`` (a resolution)
    for smooth ones; shared, never mutated. Only the sense of ω₂ changes the drawing, so a
    scene comes with ω₂ = ±1: a rerun that changes no geometry builds nothing (it built this
    figure on every rerun, a seventh of the page's time)."""
    fine = None if smooth is None else cycle(scene, smooth, order=1)
    return construction_figure(cycle(scene, 12), fine, list(numbered), title_of(scene), t,
                               look_).freeze()


@page_cache(st.cache_resource(max_entries=8, show_spinner=False, hash_funcs=BY_REPR))
def length_frames(scene: Scene, number: int, values: tuple[float, ...], smooth: int | None,
                  numbered: tuple[str, ...], language: str, look_: Look) -> str | None:
    """The paths figure with member ``number`` at each length of ``values`` (the chart's own
    length control), once per geometry of the other members: ``scene`` has that member at
    its length as loaded, so the length the page shows is not part of the key."""
    def draw(_: int, length: float) -> dict[str, RawFigure] | None:
        at = scene.with_(lengths={number: length})
        try:
            steps = solve(at, cycle_values(at, 12))
            fine = None if smooth is None else solve(at, cycle_values(at, smooth), order=1)
        except (Unsolvable, StructureError):  # a class III group that cannot close at all
            return None
        if not steps.feasible.any():
            return None
        return {"paths": construction_figure(steps, fine, list(numbered), title_of(at), t, look_)}

    return crank_frames(draw, values, unit=float).get("paths")


def length_control(base: Scene, scene: Scene, smooth: int | None, numbered: tuple[str, ...],
                   asked: bool | str) -> Crank | None:
    """The paths chart's own control of a link's length (``ui.crank.slider_control``), the
    one last picked in its list, member 2's at first: a length moves in the browser as φ₂
    does on the plans page, where a rerun took 300 ms to redraw. None for a scene without a
    link length."""
    if not base.lengths:
        return None
    links = {n: "".join(base.members[n].axis) for n in base.lengths}
    sliders = {f"L{n}": Ranged(links[n], t("traj.chart_length", link=links[n], member=n),
                               *length_range(length), " m", scene.lengths[n])
               for n, length in base.lengths.items()}

    def frames(key: str, values: tuple[float, ...]) -> str | None:
        number = int(key[1:])
        others = {n: v for n, v in scene.lengths.items() if n != number}
        return length_frames(base.with_(lengths=others, speed=scene.driver.speed), number,
                             values, smooth, numbered, current(), look())

    return slider_control(sliders, CHART_LENGTH, "lengths", asked, frames, "fig.unbuildable",
                          t("traj.chart_length_pick"))


@page_cache(st.cache_resource(max_entries=8, show_spinner=False, hash_funcs=BY_REPR))
def travel_frames(scene: Scene, field: str, values: tuple[float, ...], steps: int, cycles: int,
                  point: str, language: str, look_: Look) -> str | None:
    """The field chart with the travel's ``field`` at each of ``values``, once per geometry
    and the rest of the travel: ``scene`` has that field at a fixed value, so the one the
    page shows is not part of the key. The linkage is solved once: the travel changes only
    ω₂, so only the times at which the point passes its positions."""
    positions = solve(scene, cycle_values(scene, steps))

    def draw(_: int, value: float) -> dict[str, RawFigure]:
        at = scene.with_(travel=replace(scene.travel, **{field: value}))
        times, path = field_path(replace(positions, scene=at), at.travel, point, cycles)
        return {"field": field_figure(times, path, positions.points[point].z, point, steps,
                                      t("traj.field_title", point=point), t, look_)}

    return crank_frames(draw, values, unit=float).get("field")


def travel_control(scene: Scene, steps: int, cycles: int, point: str,
                   asked: bool | str) -> Crank:
    """The field chart's own control of the chain drive (``ui.crank.slider_control``), R_t
    at first: the tine's loops open and close in the browser as the drive's ratio moves. Not
    v_R: the crank is driven from the ground wheel, so the machine travels 2π·R_t·R_b/R_a a
    crank turn at any speed, and v_R changes only the times, not the path."""
    def words(label: str) -> tuple[str, str]:  # "⟨v_R⟩ — travel speed … [m/s]": v_R, its name
        text = t(label)
        return text.split(" — ")[0], text.rsplit(" [", 1)[0]

    sliders = {key: Ranged(*words(label), lo, hi, step, unit, getattr(scene.travel, field))
               for key, (label, field, lo, hi, step, unit) in TRAVEL.items() if key != "vR"}

    def frames(key: str, values: tuple[float, ...]) -> str | None:
        field = TRAVEL[key][1]
        fixed = scene.with_(travel=replace(scene.travel, **{field: sliders[key].lo}))
        return travel_frames(fixed, field, values, steps, cycles, point, current(), look())

    return slider_control(sliders, CHART_TRAVEL, "travel", asked, frames, "fig.unreachable",
                          t("traj.chart_travel_pick"))


controls, main = page_columns()


COMPASS = {"crank": "compass.crank", "arc": "compass.arc", "meet": "compass.meet",
           "group": "compass.group", "offset": "compass.offset", "path": "compass.path"}


def compass_texts(steps: list) -> list[str]:
    """What each step of the compass construction draws, in the page's language."""
    def words(step) -> str:
        values = {k: num(v, 4) if isinstance(v, float) else v for k, v in step.values.items()}
        return t(COMPASS[step.what], **values)
    return [t("compass.step", k=k + 1, n=len(steps), text=words(s)) for k, s in enumerate(steps)]


def defaults(base: Scene) -> dict[str, object]:
    """Every scene-dependent widget's value in the scene as loaded."""
    values: dict[str, object] = {f"L{n}": length for n, length in base.lengths.items()}
    values["points"] = [p for p in base.point_names if p not in base.frame][-1:]
    if base.travel:
        tr = base.travel
        values.update(vR=tr.speed, Rt=tr.wheel_radius, Ra=tr.sprocket_wheel, Rb=tr.sprocket_crank)
    else:
        values["omega"] = float(base.driver.speed)
    return values


def travel_sliders(base: Travel) -> Travel:
    """v_R and the chain drive of task 1.3, kept in the URL."""
    return Travel(**{field: bound_slider(t(label), lo, hi, step=step, key=key)
                     for key, (label, field, lo, hi, step, _) in TRAVEL.items()},
                  angle=base.angle)


def length_sliders(base: Scene) -> dict[int, float]:
    """One slider per link (``ui.scenes.length_slider``), kept in the URL."""
    return {number: length_slider(base, number, bind="query-params") for number in base.lengths}


def paths_tab(base: Scene, scene: Scene, construction: Motion, steps: int, view: str,
              points: list[str], asked: bool | str) -> float:
    """The 12 positions and the paths with the chart's own length control (or the compass
    construction, or practising it); the ms it took to build the figure. ``asked``: the
    control was touched (``ui.crank.live``)."""
    started = time.perf_counter()
    numbered = tuple(numbered_points(scene, points))
    control = None
    if view == "compass":
        steps_drawn = compass_steps(construction, points)
        fig = compass_figure(scene, steps_drawn, compass_texts(steps_drawn), title_of(scene), t,
                             look())
    else:
        sensed = scene.with_(speed=1.0 if scene.driver.speed >= 0 else -1.0)
        smooth = steps if view == "smooth" else None
        fig = paths_figure(sensed, smooth, numbered, current(), look())
        if smooth is None or smooth <= SMOOTH_FRAMES:
            control = length_control(base, sensed, smooth, numbered, asked)
    figure_ms = (time.perf_counter() - started) * 1e3
    if view == "compass" and practice.toggle("pr_compass"):
        practice.panel(practice_steps.compass(construction, plan_scales(scene, None)["L"]),
                       "pr_compass", t("practice.sheet_compass"))
    else:
        chart(fig, f"{scene.id}-paths", key="paths", crank=control)
    if view == "compass":
        method_doc("compass")
    return figure_ms


def field_tab(scene: Scene, fine: Motion, steps: int, point: str, asked: bool | str) -> None:
    """The tine's path in the field (the linkage and the travel) with the chart's own control
    of the travel, and the drive's figures."""
    cycles = bound_slider(t("traj.cycles"), 1, 6, value=3, key="cycles")
    times, field = field_path(fine, scene.travel, point, cycles)
    control = travel_control(scene, steps, cycles, point, asked) if steps <= SMOOTH_FRAMES else None
    chart(field_figure(times, field, fine.points[point].z, point, steps,
                       t("traj.field_title", point=point), t, look()),
          f"{scene.id}-field", key="field", crank=control)
    tr = scene.travel
    loops, slowest = loops_backward(fine, tr, point)
    cols = st.columns(3)
    cols[0].metric(t("traj.omega_t"), f"{num(tr.wheel_omega)} s⁻¹")
    cols[1].metric(t("traj.omega_b"), f"{num(tr.crank_omega)} s⁻¹")
    cols[2].metric(t("traj.cycle_time"), f"{num(tr.cycle_time)} s")
    cols = st.columns(3)
    cols[0].metric(t("traj.step_time"), f"{num(tr.step_time())} s")
    cols[1].metric(t("traj.step_distance"), f"{num(tr.step_distance())} m")
    cols[2].metric(t("traj.travel_per_cycle"), f"{num(tr.speed * tr.cycle_time)} m")
    st.write(t("traj.loops_yes" if loops else "traj.loops_no", point=point,
               speed=num(slowest, 3)))


def readouts(scene: Scene, fine: Motion, points: list[str]) -> None:
    """Beside the controls: the answer box, the cycle time, path lengths, strokes, swings."""
    lengths = {p: path_length(fine.points[p].z) for p in points}
    answers = [computed(t("traj.time_per_cycle"), cycle_time(scene), "s")]
    answers += [computed(t("traj.path_length", point=p), length, "m") for p, length in lengths.items()]
    # the hay tedder's travel as the task asks it (exams.judged: travel.*, as ``check`` names them)
    answer_box(lambda: answers + (named(scene, scene, lambda key: key.startswith("travel."))
                                  if scene.travel else []), key="self")
    st.metric(t("traj.time_per_cycle"), f"{num(cycle_time(scene))} s")
    for name in points:
        st.metric(t("traj.path_length", point=name), f"{num(lengths[name])} m")
    for name, stroke in strokes(fine).items():
        st.metric(t("traj.stroke", pair=name), f"{num(stroke)} m")
    for number, (low, high) in swings(fine).items():
        # the limits under the angle, in small type: "101.4° … 147.3°" is too wide for the column
        st.metric(t("traj.swing", member=number), f"{num(high - low, 4)}°",
                  f"{num(low, 4)}° … {num(high, 4)}°", delta_color="off", delta_arrow="off",
                  delta_description=t("traj.limits"))


def paths_table(fine: Motion, points: list[str]) -> pd.DataFrame:
    """The drawn points' paths over the cycle, for the CSV download (made when pressed)."""
    table = pd.DataFrame({"phi2_deg": np.degrees(fine.at)})
    for name in points:
        table[f"{name}_x_m"] = fine.points[name].x
        table[f"{name}_y_m"] = fine.points[name].y
    return table


def resolution_table(base: Scene, scene: Scene, fine: Motion, points: list[str], steps: int,
                     timings: tuple[float, float]) -> None:
    """Under the chart: the paths as CSV; what each resolution costs and misses, in a section
    filled only while open (with it, each new length measured the paths' errors at four
    resolutions and sent the table: a sixth of the step's rerun and its heaviest element in
    the browser). ``timings``: this run's solve and figure, ms."""
    csv_button(lambda: paths_table(fine, points), f"{scene.id}-paths.csv", key="csv",
               label=t("traj.csv_paths"))
    section = st.expander(t("traj.accuracy_title"), key="accuracy_open", on_change="rerun")
    if section.open:
        with section:
            rows = [{t("traj.col_positions"): r["positions"],
                     t("traj.col_solve"): num(r["solve_ms"], 3),
                     t("traj.col_deviation"): num(r["deviation_m"] * 1e3, 3),
                     t("traj.col_current"): "◀" if r["positions"] == steps else ""}
                    for r in accuracy(base, scene, tuple(points))]
            show_table(rows, f"{scene.id}-resolution.csv", "csv_resolution")
            st.caption(t("traj.timing", solve=num(timings[0], 3), figure=num(timings[1], 3),
                         steps=steps))


with controls:
    base = scene_picker()
    seed(defaults(base), st.session_state["scene"])
    steps = bound_select_slider(t("traj.resolution"), RESOLUTIONS, key="res", value=360,
                                wait=True)
    views = {"steps": "traj.view_steps", "smooth": "traj.view_smooth", "compass": "traj.view_compass"}
    view = link_option(st.radio, t("traj.view"), list(views), "view",
                      format_func=lambda v: t(views[v]), horizontal=True)
    movable = [p for p in base.point_names if p not in base.frame]
    bound_choices("points", t("traj.points"), movable)
    chosen = st.multiselect(t("traj.points"), movable, key="points", bind="query-params")
    link_note("points", t("traj.points"), chosen)
    points = chosen or movable[-1:]
    geometry = st.container()  # ω₂ (or the travel), the lengths, the readouts: the fragment's


@fragment
def drawn(base: Scene, steps: int, view: str, points: list[str]) -> None:
    """What ω₂ (or the travel) and the link lengths change, which moving them reruns alone:
    the solve, the chart, the readouts and the resolution table; not app.py, the scene
    picker, the resolution, the view and the points, which rerun the page and this with
    it. Its sliders are drawn on every run (Streamlit forgets a widget a run leaves out)."""
    asked = live()
    with geometry:
        if base.travel:
            scene = base.with_(travel=travel_sliders(base.travel))
        else:
            omega = bound_slider(t("traj.omega"), -50.0, 50.0, step=0.5, key="omega", wait=True)
            scene = base.with_(speed=omega)
        with st.expander(t("traj.lengths")):
            scene = scene.with_(lengths=length_sliders(base))
        scene_download(scene)

    started = time.perf_counter()
    try:
        construction = cycle(scene, 12)
        fine = cycle(scene, steps, order=1)
    except (Unsolvable, StructureError) as exc:  # lengths a class III group cannot close with
        st.error(t("traj.unbuildable", reason=message(exc)))
        return
    solve_ms = (time.perf_counter() - started) * 1e3

    for zone in zones(scene.with_(speed=1.0)):
        where = message(format_ranges(scene, zone.ranges))
        st.warning(t("traj.dead_zone", group=zone.group, where=where))
    tabs = [t("traj.tab_paths"), t("traj.tab_animation")]
    tabs += [t("traj.tab_field")] if scene.travel else []
    tab_paths, tab_anim, *tab_field = st.tabs(tabs, key="tab", on_change="rerun")
    figure_ms = 0.0
    if tab_paths.open:
        with tab_paths:
            figure_ms = paths_tab(base, scene, construction, steps, view, points, asked)
    if tab_anim.open:
        with tab_anim:
            if not fine.feasible.all():
                st.info(t("traj.rocking"))
            chart(animation(scene, steps, tuple(points), current(), look()),
                  f"{scene.id}-animation", key="animation")
    if tab_field and tab_field[0].open:
        with tab_field[0]:
            field_tab(scene, fine, steps, points[-1], asked)
    if not waiting():  # on a fresh visit, after the chart is painted (ui/firstpaint.py)
        with geometry:
            readouts(scene, fine, points)
        if base.book:  # task 1.3's travel: book vs exact, or what the student changed
            book_section(scene, base, {k: v for k, v in defaults(base).items() if k != "points"})
        resolution_table(base, scene, fine, points, steps, (solve_ms, figure_ms))


with main:  # the fragment's own place: what it writes here needs no block of its own
    drawn(base, steps, view, points)
    if not waiting():  # (ω₂ and the lengths do not change it: its runs do not send it)
        speed_panel("trajectories", base.id, ("kinematics", "differences", "peers"))
