"""Chapter 1 — point paths: the 12-step construction, smooth paths, animation, and the hay tedder."""

from __future__ import annotations

import time

import numpy as np
import pandas as pd
import streamlit as st

from figures.trajectories import animation_figure, construction_figure, field_figure
from mechanisms.schema import Scene, Travel
from solvers.diagnostics import dead_zones, format_range
from solvers.paths import (animation_order, cycle_time, cycle_values, field_path, loops_backward,
                           path_length, resolution_table, strokes)
from ui.cache import BY_REPR, solved
from ui.chapters import page_title
from ui.export import chart, csv_button
from ui.i18n import num, t
from ui.present import look
from ui.scenes import scene_download, scene_picker

RESOLUTIONS = (12, 72, 360, 3600)
MAX_FRAMES = 120

page_title("pages/trajectories.py")


@st.cache_data(max_entries=64, hash_funcs=BY_REPR)
def accuracy(scene: Scene, points: tuple[str, ...]) -> list[dict]:
    return resolution_table(scene, list(points), RESOLUTIONS)


controls, main = st.columns([1, 3], gap="large")


def travel_sliders(base: Travel) -> Travel:
    """v_R and the chain drive of task 1.3 (defaults from the scene)."""
    return Travel(
        speed=st.slider(t("traj.v_R"), 0.5, 8.0, base.speed, 0.1, key="vR", bind="query-params"),
        wheel_radius=st.slider(t("traj.R_t"), 0.15, 0.6, base.wheel_radius, 0.01, key="Rt",
                               bind="query-params"),
        sprocket_wheel=st.slider(t("traj.R_a"), 0.02, 0.2, base.sprocket_wheel, 0.005, key="Ra",
                                 bind="query-params"),
        sprocket_crank=st.slider(t("traj.R_b"), 0.02, 0.2, base.sprocket_crank, 0.005, key="Rb",
                                 bind="query-params"),
        angle=base.angle)


def length_sliders(scene: Scene) -> dict[int, float]:
    """One slider per link, from a quarter to twice its length in the scene."""
    out = {}
    for number, length in scene.lengths.items():
        member = scene.members[number]
        label = t("traj.length", link="".join(member.axis), member=number)
        out[number] = st.slider(label, round(length / 4, 4), round(length * 2, 4), length,
                                step=round(length / 100, 5), format="%.4f", key=f"L{number}",
                                bind="query-params")
    return out


with controls:
    base = scene_picker()
    steps = st.select_slider(t("traj.resolution"), RESOLUTIONS, value=360, key="res",
                             bind="query-params")
    views = {"steps": "traj.view_steps", "smooth": "traj.view_smooth"}
    view = st.radio(t("traj.view"), list(views), key="view", bind="query-params",
                    format_func=lambda v: t(views[v]), horizontal=True)
    movable = [p for p in base.point_names if p not in base.frame]
    points = st.multiselect(t("traj.points"), movable, default=movable[-1:], key="points",
                            bind="query-params") or movable[-1:]
    if base.travel:
        travel = travel_sliders(base.travel)
        scene = base.with_(travel=travel)
    else:
        omega = st.slider(t("traj.omega"), -50.0, 50.0, float(base.driver.speed), 0.5,
                          key="omega", bind="query-params")
        scene = base.with_(speed=omega)
    with st.expander(t("traj.lengths")):
        scene = scene.with_(lengths=length_sliders(scene))
    scene_download(scene)

started = time.perf_counter()
construction = solved(scene, tuple(cycle_values(scene, 12)))
fine = solved(scene, tuple(cycle_values(scene, steps)), order=1)
solve_ms = (time.perf_counter() - started) * 1e3

with main:
    for zone in dead_zones(scene):
        where = "; ".join(format_range(scene, lo, hi) for lo, hi in zone.ranges)
        st.warning(t("traj.dead_zone", group=zone.group, where=where))
    tabs = [t("traj.tab_paths"), t("traj.tab_animation")] + ([t("traj.tab_field")] if scene.travel else [])
    tab_paths, tab_anim, *tab_field = st.tabs(tabs)
    with tab_paths:
        started = time.perf_counter()
        fig = construction_figure(construction, fine if view == "smooth" else None, points,
                                  scene.title, t, look())
        figure_ms = (time.perf_counter() - started) * 1e3
        chart(fig, f"{scene.id}-paths", key="paths")
    with tab_anim:
        order = animation_order(fine.feasible)
        frames = order[::-(-len(order) // MAX_FRAMES)]  # at most MAX_FRAMES frames
        if not fine.feasible.all():
            st.info(t("traj.rocking"))
        chart(animation_figure(fine, frames, points, scene.title, t, look()),
              f"{scene.id}-animation", key="animation")
    if tab_field:
        with tab_field[0]:
            cycles = st.slider(t("traj.cycles"), 1, 6, 3, key="cycles", bind="query-params")
            point = points[-1]
            times, field = field_path(fine, scene.travel, point, cycles)
            chart(field_figure(times, field, fine.points[point].z, point, steps,
                               t("traj.field_title", point=point), t, look()),
                  f"{scene.id}-field", key="field")
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

with controls:
    st.metric(t("traj.time_per_cycle"), f"{num(cycle_time(scene))} s")
    for name in points:
        st.metric(t("traj.path_length", point=name), f"{num(path_length(fine.points[name].z))} m")
    for name, stroke in strokes(fine).items():
        st.metric(t("traj.stroke", pair=name), f"{num(stroke)} m")

with main:
    st.subheader(t("traj.accuracy_title"))
    rows = [{t("traj.col_positions"): r["positions"], t("traj.col_solve"): num(r["solve_ms"], 3),
             t("traj.col_deviation"): num(r["deviation_m"] * 1e3, 3),
             t("traj.col_current"): "◀" if r["positions"] == steps else ""}
            for r in accuracy(scene, tuple(points))]
    st.dataframe(pd.DataFrame(rows), hide_index=True)
    st.caption(t("traj.timing", solve=num(solve_ms, 3), figure=num(figure_ms, 3), steps=steps))
    table = pd.DataFrame({"phi2_deg": np.degrees(fine.at)})
    for name in points:
        table[f"{name}_x_m"] = fine.points[name].x
        table[f"{name}_y_m"] = fine.points[name].y
    csv_button(table, f"{scene.id}-paths.csv", key="csv")
