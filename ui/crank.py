"""The crank angle in the browser (issue 21): a page's figures at every few degrees of φ₂,
sent once per geometry, so that the chart element (ui/plot.js) redraws them locally while a
student scrubs or plays φ₂, with no rerun until the slider is released. The same control
moves one of a page's sliders (``slider_control``: a link's length, the hay tedder's travel)
on the trajectories page (issue 38): there a rerun is 1.5–2.5 times Streamlit's own floor in
the browser, which alone is about 150 ms.

Each frame carries only what differs from the first one: the traces that moved and the
layout keys that changed (a title with the angle, the letters). A position the mechanism
cannot reach is sent as null and shown as such.

The page's own sliders that a chart can follow (issue 83): while one of them has the
keyboard's focus (``NEAR``, told by the browser), each run sends with the chart its figures
one step either side of the slider's value (``Crank.near``), so that an arrow key redraws
the chart at once from them, and the run's own figure replaces that drawing when it comes.
A rerun alone is 1.6–2.2 times the floor's slider in the browser (docs/performance.md).
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import NamedTuple

import streamlit as st
from plotly.io.json import to_json_plotly

from figures.raw import RawFigure
from mechanisms.schema import Scene
from mechanisms.typed import Refused
from ui.numbers import link_note
from ui.url import linked, said_of_link, url_drop, url_set

STEP_DEG = 5.0  # 72 frames a turn: smooth to scrub, small enough to send
FRAMES = 36  # about this many frames along a slider's range (a link's length: every 5th step)
LIVE = "crank_live"  # session key: the student asked for the frames (see live())
NEAR = "crank_near"  # session key: the page's slider (its key) the keyboard is on (see follow())
PHI = (0.0, 360.0, 0.5)  # degrees: the ends and step of a page's φ₂ slider (ui.scenes)
OMEGA = (-50.0, 50.0, 0.5)  # rad/s: the ends and step of its ω₂ slider (ui.scenes.driver_speed)


@dataclass(frozen=True)
class Crank:
    """A chart's own control of φ₂ (or of another quantity, ``key``): the frame values, the
    one showing, the group of charts that move together, and the frames themselves (JSON)
    once the student has asked for them by touching the control — ordinary reruns do not pay
    for 72 figures.

    ``key``: the session key and URL parameter the control sets when let go; ``unit`` is
    shown after the value and ``step`` names what a step button adds; ``unreachable`` is the
    string (its key) that says why a gap in the frames is one. ``choices``: other quantities
    the control can move instead, (key, name) each, offered in a list beside it; picking one
    asks for its frames."""

    values: tuple[float, ...]
    index: int
    group: str
    frames: str | None = None  # {"base", "frames"} from crank_frames
    label: str = "φ₂"
    key: str = "at"
    unit: str = "°"
    step: str = f"{STEP_DEG:g}°"
    choices: tuple[tuple[str, str], ...] = ()
    wraps: bool = True  # a step past the last value comes round to the first (not a length)
    unreachable: str = "fig.unreachable"
    follows: tuple[str, ...] = ()  # the page's sliders (keys) whose neighbours it can send
    near: str | None = None  # {"key", "values", "frames"}: see near_frames()

    def json(self) -> str:
        return (f'{{"values": {json.dumps(list(self.values))}, "index": {self.index}, '
                f'"group": {json.dumps(self.group)}, "label": {json.dumps(self.label)}, '
                f'"key": {json.dumps(self.key)}, "unit": {json.dumps(self.unit)}, '
                f'"step": {json.dumps(self.step)}, "choices": {json.dumps(self.choices)}, '
                f'"wraps": {json.dumps(self.wraps)}, "follows": {json.dumps(self.follows)}, '
                f'"near": {self.near or "null"}, '
                f'"turn": {self.frames or "null"}}}')


def turn(task: float | None = None, step_deg: float = STEP_DEG) -> tuple[float, ...]:
    """The frame angles of a whole turn, in degrees, with the task's own instant among them
    (task 5.1 is drawn at φ₂ = 50.29°): scrubbing comes back to the figure the book solved."""
    grid = [k * step_deg for k in range(int(round(360.0 / step_deg)))]
    if task is not None and min(_apart(g, task) for g in grid) > 1e-6:
        grid = sorted(grid + [round(task % 360.0, 6)])  # 50.2857°, not 50.285700000000006°
    return tuple(grid)


def task_turn(base: Scene) -> tuple[float, ...]:
    """The frame angles for a page on the task ``base``: its own instant among them when its
    driver turns (a linear driver's stroke gets no frames: see cranks)."""
    return turn(math.degrees(base.driver.at) if base.driver.kind == "rotating" else None)


def nearest(values: tuple[float, ...], degrees: float) -> int:
    """The frame closest to ``degrees`` around the turn."""
    return min(range(len(values)), key=lambda k: _apart(values[k], degrees))


def _apart(a: float, b: float) -> float:
    """How far apart two angles (degrees) are around the turn: 0 … 180."""
    return abs((a - b + 180.0) % 360.0 - 180.0)


def along(lo: float, hi: float, step: float, value: float) -> tuple[float, ...]:
    """The frame values along a slider's range ``lo`` … ``hi``, ``step`` apart, with the
    slider's own ``value`` among them (a student may have set it between two frames)."""
    grid = [round(lo + k * step, 6) for k in range(int((hi - lo) / step + 1e-9) + 1)]
    if min(abs(g - value) for g in grid) > 1e-9:
        grid = sorted(grid + [value])
    return tuple(grid)


class Ranged(NamedTuple):
    """A page's slider that a chart's own control can move: its symbol on the chart, its name
    in the control's list, its range and step, its unit and the value the page shows."""

    label: str
    name: str
    lo: float
    hi: float
    step: float
    unit: str
    value: float


def slider_control(sliders: dict[str, Ranged], remembered: str, group: str, asked: bool | str,
                   frames: Callable[[str, tuple[float, ...]], str | None],
                   unreachable: str, label: str) -> Crank:
    """A chart's own control of one of the page's ``sliders`` (by their keys): the one last
    picked in its list (the first at first), kept in the session and in the link as
    ``remembered`` (``?chart_length=L3``), so a reload or a shared link moves the same one;
    at about ``FRAMES`` values along its range, the page's value among them, with their
    frames (``frames(key, values)``, a page's cached crank_frames) when the student asked
    (``asked``: live()). Letting go sets that slider (ui.export.chart). A link's choice
    that is none of them is said under ``label`` (what the control picks)."""
    first = next(iter(sliders))
    if asked in sliders:
        st.session_state[remembered] = asked
    linked(remembered)
    given = st.query_params.get(remembered)
    if remembered not in st.session_state and given is not None and given not in sliders:
        said_of_link(remembered, Refused("unknown", given), first)  # (``label``: said below)
    key = st.session_state.get(remembered, given)
    key = st.session_state[remembered] = key if key in sliders else first
    link_note(remembered, label, key)
    if key == first:
        url_drop(remembered)
    else:
        url_set(remembered, key)
    shown = sliders[key]
    stride = max(1, round((shown.hi - shown.lo) / shown.step / FRAMES)) * shown.step
    values = along(shown.lo, shown.hi, stride, shown.value)
    on = keyboard_on(tuple(sliders))
    close = None if on is None else near_frames(
        on, sliders[on], frames(on, (sliders[on].value, *sides(sliders[on]))))
    return Crank(values, min(range(len(values)), key=lambda k: abs(values[k] - shown.value)),
                 group, frames(key, values) if asked else None, label=shown.label, key=key,
                 unit=shown.unit, step=f"{round(stride, 6):g}{shown.unit}", wraps=False,
                 unreachable=unreachable,
                 choices=tuple((k, slider.name) for k, slider in sliders.items()),
                 follows=tuple(sliders), near=close)


def crank_frames(draw: Callable[[int, float], dict[str, RawFigure] | None],
                 values: tuple[float, ...], unit: Callable[[float], float] = math.radians
                 ) -> dict[str, str]:
    """``draw(k, φ₂ in rad)`` gives a page's figures at frame k, by name (None where the
    mechanism cannot be drawn); per name, the JSON of its frames, each a patch on the first.
    ``unit`` turns a value into what ``draw`` takes (``float`` for a length in metres).
    Numbers are rounded to 5 significant digits (a tenth of a millimetre on a drawing)."""
    drawn = [draw(k, unit(v)) for k, v in enumerate(values)]
    names = next((list(d) for d in drawn if d), [])
    out = {}
    for name in names:
        specs = [None if d is None else _rounded(json.loads(to_json_plotly(d[name].raw_dict())))
                 for d in drawn]
        base = next(s for s in specs if s is not None)
        varying = {k for s in specs if s is not None for k, v in s["layout"].items()
                   if base["layout"].get(k) != v}
        frames = [None if s is None else _patch(base, s, varying) for s in specs]
        out[name] = json.dumps({"base": base, "frames": frames}, separators=(",", ":"))
    return out


def cranks(scene: Scene, names: tuple[str, ...], group: str, values: tuple[float, ...],
           frames: Callable[[Scene, tuple[float, ...]], dict[str, str]], asked: bool,
           follows: tuple[str, ...] = ("at", "omega")) -> dict[str, Crank]:
    """The named charts' own φ₂ controls at the frame angles ``values`` (task_turn), moving
    together as ``group``, on the angle the page shows; with their frames when the student
    asked (``frames(scene, values)``: a page's cached crank_frames of ``scene`` at those
    angles, in degrees), and the figures one step of the page's φ₂ or ω₂ slider (of those
    the charts ``follows``) either side while the keyboard is on it. None for a linear
    driver, whose stroke is no turn."""
    if scene.driver.kind != "rotating":
        return {}
    sent = frames(scene, values) if asked else {}
    at = st.session_state["at"]
    on = keyboard_on(follows)
    close: dict[str, str | None] = {}
    if on == "at":
        phi = Ranged("φ₂", "φ₂", *PHI, "°", at)
        around = frames(scene, (at, *sides(phi)))
        close = {name: near_frames("at", phi, around.get(name)) for name in names}
    elif on == "omega":
        omega = Ranged("ω₂", "ω₂", *OMEGA, " s⁻¹", scene.driver.speed)
        drawn = [frames(scene.with_(speed=w), (at,)) for w in (omega.value, *sides(omega))]
        close = {name: near_figures("omega", omega, [d.get(name) for d in drawn])
                 for name in names}
    shown = nearest(values, at)
    return {name: Crank(values, shown, group, sent.get(name), follows=follows,
                        near=close.get(name)) for name in names}


def sides(shown: Ranged) -> tuple[float, ...]:
    """What one arrow key sets from the slider's value: a step down and a step up, each
    within the slider's range."""
    steps = (round(shown.value - shown.step, 9), round(shown.value + shown.step, 9))
    return tuple(v for v in steps if shown.lo - 1e-9 <= v <= shown.hi + 1e-9)


def near_frames(key: str, shown: Ranged, sent: str | None) -> str | None:
    """A chart's figures one step of the slider ``key`` either side of its value, from
    ``sent`` (crank_frames at the value, then at ``sides(shown)``): each a patch on the
    figure at the value itself, the one the run draws, which the browser holds. None where
    that figure cannot be drawn."""
    if sent is None:
        return None
    turn = json.loads(sent)
    if turn["frames"][0] is None:
        return None
    return _near(key, shown, turn["frames"][1:])


def near_figures(key: str, shown: Ranged, sent: list[str | None]) -> str | None:
    """As near_frames, from a chart's figure drawn apart at the value and at each of
    ``sides(shown)`` (each crank_frames of one frame: a quantity that is no frame of a
    page's turn, as ω₂)."""
    figures = [None if s is None else json.loads(s) for s in sent]
    figures = [None if f is None or f["frames"][0] is None else f["base"] for f in figures]
    base = figures[0]
    if base is None:
        return None
    varying = {k for f in figures[1:] if f for k, v in f["layout"].items()
               if base["layout"].get(k) != v}
    return _near(key, shown, [None if f is None else _patch(base, f, varying)
                              for f in figures[1:]])


def _near(key: str, shown: Ranged, patches: list[dict | None]) -> str:
    """What the browser is sent of a slider's neighbours (ui/plot.js): the slider, the
    values one arrow key sets (``sides``), and the chart's patch at each."""
    return json.dumps({"key": key, "values": list(sides(shown)), "frames": patches},
                      separators=(",", ":"))


def keyboard_on(keys: tuple[str, ...]) -> str | None:
    """Which of the sliders ``keys`` the keyboard is on, as the browser last said (a chart's
    trigger "near", see follow), or None."""
    key = st.session_state.get(NEAR)
    return key if key in keys else None


def follow(key: str | None) -> None:
    """The browser says that the keyboard is on the page's slider ``key`` (a chart's
    ``follows``), or on none of them (None): the runs that follow send its neighbours."""
    if key:
        st.session_state[NEAR] = key
    else:
        st.session_state.pop(NEAR, None)


def _rounded(value):
    if isinstance(value, float):
        return float(f"{value:.5g}")
    if isinstance(value, list):
        return [_rounded(v) for v in value]
    if isinstance(value, dict):
        return {k: _rounded(v) for k, v in value.items()}
    return value


def _patch(base: dict, spec: dict, varying: set[str]) -> dict:
    """What turns ``base`` into ``spec``: the changed properties of each changed trace, by
    index; when the number of traces differs (S gone to infinity, say), every trace, each
    one the first frame also has as its index there (the Assur page's path of S, 4 kB, was
    sent whole in every such frame); and every layout key that changes anywhere in the turn
    (the chart lays them over the figure it showed first, drawn at another angle)."""
    patch: dict = {}
    if len(spec["data"]) != len(base["data"]):
        patch["all"] = [next((j for j, old in enumerate(base["data"]) if old == tr), tr)
                        for tr in spec["data"]]
    else:
        changed = {str(i): {k: v for k, v in tr.items() if old.get(k) != v}
                   for i, (tr, old) in enumerate(zip(spec["data"], base["data"])) if tr != old}
        if changed:
            patch["data"] = changed
    layout = {k: spec["layout"][k] for k in varying if k in spec["layout"]}
    if layout:
        patch["layout"] = layout
    return patch


def live() -> bool | str:
    """Whether this run answers a touch of a chart's φ₂ control (the frames are sent then),
    read once a run: any other rerun, a geometry change among them, sends none. A control
    with choices says which one the student picked (its key)."""
    return st.session_state.pop(LIVE, False)
