"""Synthesis: the precision points a coupler point must pass → a four-bar, found by
solvers.synthesis, re-solved by the kinematics core, opened in the builder by its link.

Thin: the table and fields are read by the one number reader, the task by its loader
(mechanisms.synthesis), the search by the solver; the page only wires them and draws."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import streamlit as st

from figures.synthesis import found_figure, synthesis_figure, three_positions_figure
from mechanisms import SceneError, parse_scene, preset_ids
from mechanisms.link import PARAMETER, encode
from mechanisms.messages import value_text
from mechanisms.reader import Reader
from mechanisms.synthesis import SynthesisTask, build_task
from solvers import Motion, solve
from solvers.paths import cycle_values
from methods import practice_steps
from methods.practice_steps import THREE_APART
from methods.scales import plan_scales
from methods.three_positions import construction, of_scene
from solvers.synthesis import DEFAULT_SECONDS, Result, SynthesisError, synthesize
from ui import practice
from ui.cache import preset
from ui.chapters import SYNTHESIS
from ui.editor_tables import restart_table, typed_table
from ui.export import chart
from ui.i18n import decimal_comma, message, num, t, title_of
from ui.numbers import link_option, number_field, refused_fields
from ui.scenes import link_choice

UNIT = "m"
COLUMNS = (f"x [{UNIT}]", f"y [{UNIT}]")
EXAMPLES = {"tine": "syn.example_tine", "own": "syn.example_own"}
TIMINGS = {"free": "syn.timing_free", "steps": "syn.timing_steps"}
BUDGETS = (3_000, 10_000, 30_000, 100_000, 300_000)  # fast … accurate (bench/synthesis.py)
TINE_STEPS = 12  # the book's compass construction: twelve positions of the crank
TURN_FRAMES = 72  # the found four-bar's animation: a frame every 5°


@st.cache_resource(show_spinner=False)
def tine_points() -> pd.DataFrame:
    """Task 1.3's tine tip E at the twelve crank positions of the compass construction,
    relative to the machine (the scene's own solve: no travel added)."""
    scene = preset("zbirka-1.3")
    e = solve(scene, cycle_values(scene, TINE_STEPS), order=0, points=["E"]).points["E"].z
    return pd.DataFrame({COLUMNS[0]: np.round(e.real, 4), COLUMNS[1]: np.round(e.imag, 4)})


def own_points() -> pd.DataFrame:
    return pd.DataFrame({COLUMNS[0]: [0.0, 0.1, 0.2, 0.1], COLUMNS[1]: [0.0, 0.08, 0.0, -0.05]})


@st.cache_resource(max_entries=8, show_spinner=False)
def turning(scene_text: str) -> Motion:
    """The found four-bar over a whole turn, every 5° (the animation's frames)."""
    scene = parse_scene(scene_text, source="synthesis")
    return solve(scene, cycle_values(scene, TURN_FRAMES), order=0)


def counted(n: int) -> str:
    """A count as the page's language groups its digits (a narrow space in Serbian, where
    the comma is the decimal sign)."""
    return value_text(n, t, decimal_comma())


def task_of(points: pd.DataFrame, timing: str, step: float, max_length: float,
            box: float) -> SynthesisTask:
    """The task the fields make, read by the task file's own reader (one set of rules)."""
    raw = {"points": points[list(COLUMNS)].to_numpy(dtype=float).tolist(), "timing": timing,
           "max_length": max_length, "box": box, "title": t("syn.title")}
    if timing == "steps":
        raw["crank_steps"] = [step] * (len(points) - 1)
    return build_task(raw, Reader(t("syn.points")))


def searched(task: SynthesisTask, budget: int) -> Result:
    """The search, its progress shown as it goes."""
    bar = st.progress(0.0, text=t("syn.searching", share=0, best="—"))

    def told(share: float, best: float) -> None:
        bar.progress(share, text=t("syn.searching", share=round(100 * share), best=num(best, 3)))

    try:
        return synthesize(task, seed=1, budget=budget, seconds=DEFAULT_SECONDS, progress=told)
    finally:
        bar.empty()


def path_part() -> None:
    """Precision points → a four-bar, found, re-solved, drawn and linked."""
    st.write(t("syn.intro"))
    example = link_option(st.selectbox, t("syn.example"), list(EXAMPLES), "example",
                         format_func=lambda e: t(EXAMPLES[e]))
    default = tine_points() if example == "tine" else own_points()
    left, right = st.columns([2, 3])
    with left:
        st.markdown(f"**{t('syn.points')}**")
        points = typed_table("points", default, example, COLUMNS, name=t("syn.points"),
                             rows_fixed=False, num_rows="dynamic", width="stretch")
        timing = link_option(st.radio, t("syn.timing"), list(TIMINGS), "timing", horizontal=True,
                            format_func=lambda k: t(TIMINGS[k]),
                            default="steps" if example == "tine" else "free")
        step = 360.0 / TINE_STEPS
        if timing == "steps":
            step = number_field(t("syn.step"), "syn_step", step, minimum=-359.0, maximum=359.0,
                                url=True)
        spread = float(np.ptp(points[list(COLUMNS)].to_numpy(), axis=0).max()) if len(points) else 1.0
        c1, c2 = st.columns(2)
        max_length = number_field(t("syn.max_length", unit=UNIT), f"syn_max_{example}",
                                  round(4 * spread, 2) or 1.0, minimum=1e-6, where=c1, url=True)
        box = number_field(t("syn.box", unit=UNIT), f"syn_box_{example}", round(3 * spread, 2) or 1.0,
                           minimum=1e-6, where=c2, url=True)
        speed = st.select_slider(t("syn.speed"), options=list(range(len(BUDGETS))), value=3,
                                 format_func=lambda i: counted(BUDGETS[i]),
                                 key="syn_speed",
                                 help=t("syn.speed_help", budget=f"{counted(BUDGETS[0])} … {counted(BUDGETS[-1])}",
                                        seconds=num(DEFAULT_SECONDS)))
        fields = {"syn_step": t("syn.step"), f"syn_max_{example}": t("syn.max_length", unit=UNIT),
                  f"syn_box_{example}": t("syn.box", unit=UNIT)}
        refused = refused_fields(fields)
        try:
            task = task_of(points, timing, step, max_length, box)
            problem = refused
        except SceneError as exc:
            task, problem = None, message(exc)
        find = st.button(t("syn.find"), type="primary", icon=":material/travel_explore:",
                         disabled=task is None or refused is not None, help=problem, width="stretch")
        if problem and not refused:
            st.error(problem, icon=":material/error:")
        if find and task is not None:
            try:
                st.session_state["syn_result"] = (task, searched(task, BUDGETS[speed]))
            except SynthesisError as exc:
                st.session_state.pop("syn_result", None)
                st.error(t("syn.none", reason=str(exc)), icon=":material/error:")

    kept = st.session_state.get("syn_result")
    result = kept[1] if kept is not None else None
    with right:
        shown_points = [complex(x, y) for x, y in points[list(COLUMNS)].to_numpy(dtype=float)]
        if result is not None and kept[0] == task:
            figure = found_figure(turning(result.scene_toml), shown_points, result.positions["M"], t)
        else:
            figure = synthesis_figure(shown_points, t, unit=UNIT)
        drawn = chart(figure, "synthesis", "synthesis_chart", editable=True)
        st.caption(t("syn.click"))
        if drawn is not None and drawn.click:
            added = pd.concat([points, pd.DataFrame({COLUMNS[0]: [round(drawn.click["x"], 4)],
                                                     COLUMNS[1]: [round(drawn.click["y"], 4)]})],
                              ignore_index=True)
            restart_table("points", example, added)
            st.rerun()

    if result is not None:
        if kept[0] != task:
            st.warning(t("syn.stale"), icon=":material/history:")
        link = result.linkage
        st.success(t("syn.found", seconds=num(result.seconds, 2), evaluations=counted(result.evaluations),
                     objective=num(result.objective, 4), largest=num(float(np.max(result.errors)), 3),
                     unit=UNIT), icon=":material/check_circle:")
        st.write(t("syn.lengths", frame=num(link.frame, 4), crank=num(link.crank, 4),
                   coupler=num(link.coupler, 4), rocker=num(link.rocker, 4), unit=UNIT,
                   along=num(link.point.real, 4), left=num(link.point.imag, 4)))
        st.dataframe(pd.DataFrame({
            t("syn.col_point"): range(1, len(result.errors) + 1),
            t("syn.col_phi"): [num(math.fmod(a, 360.0), 2) for a in result.crank_deg],
            t("syn.col_error", unit=UNIT): [num(float(e), 3) for e in result.errors]}),
            hide_index=True)
        text = encode(result.scene)
        b1, b2 = st.columns(2)
        b1.page_link("pages/builder.py", label=t("syn.open_builder"), icon=":material/draw:",
                     query_params={PARAMETER: text})
        b2.page_link("pages/trajectories.py", label=t("syn.open_trajectories"),
                     icon=":material/timeline:", query_params={PARAMETER: text, "scene": link_choice(text)})
        if example == "tine":
            st.caption(t("syn.tine_note"))


@st.cache_resource(show_spinner=False)
def four_bars() -> list[str]:
    """The presets whose three coupler positions the construction takes (four-bars)."""
    ids = []
    for pid in preset_ids("linkage"):
        try:
            of_scene(preset(pid), [math.degrees(preset(pid).driver.at)])
            ids.append(pid)
        except SceneError:
            pass
    return ids


def three_part() -> None:
    """Three positions of a course four-bar's coupler → its pivots, step by step, practised."""
    st.subheader(t("three.title"))
    st.write(t("three.intro"))
    options = four_bars()
    pid = link_option(st.selectbox, t("three.scene"), options, "three_scene",
                      default="zbirka-1.3", format_func=lambda p: f"{p} — {title_of(preset(p))}")
    scene = preset(pid)
    first = math.degrees(scene.driver.at) % 360
    row = st.container(horizontal=True)
    angles = [number_field(f"φ₂,{i + 1} [°]", f"three_at_{pid}_{i}", first + d, where=row,
                           help=t("three.angles"))
              for i, d in enumerate(THREE_APART)]
    try:
        a, b = of_scene(scene, angles)
        stages = construction(a, b)
    except SceneError as exc:
        st.error(message(exc), icon=":material/error:")
        return
    upto = st.slider(t("three.step"), 1, len(stages), len(stages), key=f"three_step_{pid}")
    stage = stages[upto - 1]
    st.info(t(stage.key, **{k: num(v, 4) if isinstance(v, float) else v
                            for k, v in stage.values.items()}), icon=":material/edit:")
    chart(three_positions_figure(a, b, stages, upto, t), f"three-positions-{pid}", "three_chart")
    if practice.toggle("pr_three"):
        practice.panel(practice_steps.three(stages, plan_scales(scene, None)["L"]), "pr_three",
                       t("practice.sheet_compass"))


st.title(f"{SYNTHESIS.icon} {t(SYNTHESIS.title)}")
practice.class_only("pr_three")  # a seated student: the class's practice alone
MODES = {"path": "three.mode_path", "three": "three.mode_three"}
mode = link_option(st.radio, t("three.mode"), list(MODES), "mode", horizontal=True,
                   format_func=lambda m: t(MODES[m]))
if mode == "three":
    three_part()
else:
    path_part()
