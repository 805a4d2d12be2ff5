"""The class view's figures, for a projector: one bar per step of each student's first try
by diagnosis (the step where the class falls stands out from the back of the room); the
class's latest answers to one step as a cloud of tips over the exact construction; and, for
a step that asks a number, how the class's values spread around the right one."""

from __future__ import annotations

import math

import numpy as np

from methods.practice import DIAGNOSES, Step

from .arrows import arrow_traces
from .linkage import Text, scatter
from .plans import html
from .practice import sheet
from .raw import RawFigure
from .style import AXIS, NORMAL, Look, plane_layout

COLOURS = {"ok": "#2ca02c", "sense": "#ff7f0e", "direction": "#9467bd", "length": "#17becf",
           "scale": "#bcbd22", "missing-term": "#d62728", "wrong": "#8c564b", "none": "#c7c7c7"}
HIDDEN = "#7f7f7f"  # a step whose results the lecturer has not revealed: only who reached it
RIGHT = "#1f77b4"


def _bar(name: str, labels: list[str], values: list[int], colour: str, look: Look) -> dict:
    return dict(type="bar", orientation="h", name=name, y=labels, x=values,
                marker=dict(color=colour), text=[v or "" for v in values],
                textposition="inside", insidetextanchor="middle", textangle=0,
                textfont=dict(size=look.font), hovertemplate="%{y}: %{x}<extra>" + name + "</extra>")


def step_bars(steps: list[Step], first_tries: list[dict[str, int]], shown: list[bool],
              title: str, t: Text, look: Look = NORMAL) -> RawFigure:
    """One horizontal bar per step, top to bottom in the construction's order: each student's
    first try (``first_tries``: diagnosis → students, a step's), split by diagnosis where
    ``shown``, one grey bar of how many reached it elsewhere (revealed by the lecturer later)."""
    labels = [f"{i + 1}. {html(s.symbol)}" for i, s in enumerate(steps)]
    reached = [sum(tries.values()) for tries in first_tries]
    fig = RawFigure()
    for diagnosis in DIAGNOSES:
        values = [tries.get(diagnosis, 0) if on else 0 for tries, on in zip(first_tries, shown)]
        if any(values):
            fig.add_raw([_bar(t(f"class.diagnosis_{diagnosis}"), labels, values,
                              COLOURS[diagnosis], look)])
    hidden = [n if not on else 0 for n, on in zip(reached, shown)]
    if any(hidden) or not fig.legend_names():  # (an empty class still lists its steps)
        fig.add_raw([_bar(t("class.hidden"), labels, hidden, HIDDEN, look)])
    most = max(reached + [1])
    fig.merge_layout(dict(
        title=dict(text=title, font=dict(size=look.font + 4)), barmode="stack",
        height=max(look.height // 2, 160 + (look.font + 14) * len(steps)),
        font=dict(size=look.font, color="black"), plot_bgcolor="white",
        margin=dict(l=10 * look.font, r=20, t=3 * look.font + 20, b=4 * look.font + 40),
        legend=dict(orientation="h", yref="container", yanchor="bottom", y=0.0, traceorder="normal"),
        xaxis=dict(title=dict(text=t("class.axis_students")), range=[0, most * 1.02],
                   dtick=max(1, math.ceil(most / 10)), **AXIS),
        yaxis=dict(autorange="reversed", **{k: v for k, v in AXIS.items() if k != "showgrid"}),
        dragmode=False))
    return fig


def cloud(steps: list[Step], index: int, tips: list[tuple[complex, str]], right: bool,
          title: str, t: Text, look: Look = NORMAL) -> RawFigure:
    """The class's latest answers to step ``index`` on its sheet (the exact earlier steps
    drawn): each a tip (for an arrow, the tail plus the answer; for a point, the point), in
    SI, coloured by diagnosis; with ``right`` the exact arrow or point too."""
    step = steps[index]
    scale = step.scale or 1.0
    fig = RawFigure()
    start = sheet(fig, steps, index, t, look)
    base = step.tail / scale if step.kind == "vector" else 0j
    if right:
        head = base + complex(step.expected) / scale
        if step.kind == "vector":
            fig.add_raw(arrow_traces([(start, head, RIGHT)], 2.4 * look.line))
        fig.add_raw([scatter(x=[head.real], y=[head.imag], mode="markers",
                             name=t("class.right"), hoverinfo="skip",
                             marker=dict(size=14 * look.line, symbol="star-open", color=RIGHT,
                                         line=dict(width=2 * look.line)))])
    for diagnosis in DIAGNOSES:
        here = [base + z / scale for z, d in tips if d == diagnosis]
        if here:
            fig.add_raw([scatter(x=[z.real for z in here], y=[z.imag for z in here], mode="markers",
                                 name=f"{t(f'class.diagnosis_{diagnosis}')} ({len(here)})",
                                 hoverinfo="skip", marker=dict(
                                     size=9 * look.line, color=COLOURS[diagnosis], opacity=0.75,
                                     line=dict(width=look.line, color="white")))])
    plane_layout(fig, title, look, x_title="x [cm]", y_title="y [cm]")
    fig.merge_layout(dict(uirevision=f"cloud-{step.id}"))  # the lecturer's zoom survives a tick
    return fig


def spread(step: Step, values: list[tuple[float, str]], right: bool, title: str, t: Text,
           unit: tuple[str, float] = ("", 1.0), look: Look = NORMAL) -> RawFigure:
    """A step asking a number: the class's latest values in 20 bins (stacked by diagnosis),
    the exact value marked with ``right``. ``unit``: the unit shown and its size in SI."""
    name, factor = unit
    shown = [(v / factor, d) for v, d in values]
    exact = float(np.real(step.expected)) / factor
    everything = [v for v, _ in shown] + ([exact] if right or not shown else [])
    low, high = min(everything), max(everything)
    if high - low < 1e-12 * max(abs(high), 1.0):
        low, high = low - 1.0, high + 1.0
    edges = np.linspace(low, high, 21)
    centres, width = (edges[:-1] + edges[1:]) / 2, edges[1] - edges[0]
    fig = RawFigure()
    for diagnosis in DIAGNOSES:
        here = [v for v, d in shown if d == diagnosis]
        if here:
            heights = np.histogram(here, edges)[0]
            fig.add_raw([dict(type="bar", x=centres.tolist(), y=heights.tolist(), width=width,
                              name=f"{t(f'class.diagnosis_{diagnosis}')} ({len(here)})",
                              marker=dict(color=COLOURS[diagnosis]), hoverinfo="skip")])
    shapes = []
    if right:
        shapes.append(dict(type="line", xref="x", yref="paper", x0=exact, x1=exact, y0=0, y1=1,
                           line=dict(color=RIGHT, width=3 * look.line, dash="dash")))
    fig.merge_layout(dict(
        title=dict(text=title, font=dict(size=look.font + 4)), barmode="stack", height=look.height // 2 + 120,
        font=dict(size=look.font, color="black"), plot_bgcolor="white", shapes=shapes,
        margin=dict(l=6 * look.font, r=20, t=3 * look.font + 20, b=5 * look.font + 40),
        legend=dict(orientation="h", yref="container", yanchor="bottom", y=0.0),
        xaxis=dict(title=dict(text=f"{html(step.symbol)} [{name or step.unit}]"), **AXIS),
        yaxis=dict(title=dict(text=t("class.axis_students")), dtick=1, **AXIS),
        uirevision=f"spread-{step.id}", dragmode=False))
    return fig
