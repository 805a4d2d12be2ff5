"""The synthesis page's drawings: the points asked for; the found four-bar turning with its
coupler point's trail through them, each point joined to where the coupler point really
passes (the re-solved positions); the three-position construction step by step."""

from __future__ import annotations

import numpy as np

from solvers.kinematics import Motion

from .linkage import Text, scatter
from .raw import RawFigure
from .style import NORMAL, Look, plane_layout
from .trajectories import animation_figure

ASKED = "#d62728"
CURVE = "#1f77b4"
LINKS = "#333333"


def synthesis_figure(points: list[complex], t: Text, *, unit: str = "m",
                     look: Look = NORMAL) -> RawFigure:
    """The points asked for, numbered in order (a click on the chart adds one)."""
    fig = RawFigure()
    z = np.array(points, dtype=complex)
    fig.add_raw([scatter(x=z.real, y=z.imag, mode="markers+text", name=t("syn.points"),
                         text=[str(i + 1) for i in range(len(z))], textposition="bottom right",
                         marker=dict(size=9 * look.line, color=ASKED, symbol="circle-open",
                                     line=dict(width=2)))])
    plane_layout(fig, t("syn.chart_title"), look, x_title=f"x [{unit}]", y_title=f"y [{unit}]")
    return fig


def found_figure(motion: Motion, points: list[complex], reached: np.ndarray, t: Text,
                 look: Look = NORMAL) -> RawFigure:
    """The found four-bar turning (the trajectories page's animation: play, pause, φ₂'s
    slider), its coupler point M leaving its trail through the asked points, each point
    joined to where M really passes (the re-solved positions)."""
    fig = animation_figure(motion, np.arange(len(motion.at)), ["M"], t("syn.chart_title"), t, look)
    z = np.array(points, dtype=complex)
    gaps = np.array([v for p, q in zip(z, reached) for v in (p, q, np.nan)], dtype=complex)
    fig.add_raw([scatter(x=gaps.real, y=gaps.imag, mode="lines", showlegend=False,
                         hoverinfo="skip", line=dict(color=ASKED, width=1)),
                 scatter(x=z.real, y=z.imag, mode="markers+text", name=t("syn.points"),
                         text=[str(i + 1) for i in range(len(z))], textposition="bottom right",
                         marker=dict(size=9 * look.line, color=ASKED, symbol="circle-open",
                                     line=dict(width=2)))])
    return fig


def three_positions_figure(a: list[complex], b: list[complex], stages: list, upto: int, t: Text,
                           look: Look = NORMAL) -> RawFigure:
    """The coupler's three positions A_iB_i, and the construction's stages 1 … ``upto``: the
    perpendicular bisectors drawn so far, the pivots found, the four-bar at the first position
    once every pivot is there."""
    fig = RawFigure()
    span = max(abs(p - q) for p in a + b for q in a + b) or 1.0
    traces = []
    for i, (p, q) in enumerate(zip(a, b)):
        traces.append(scatter(x=[p.real, q.real], y=[p.imag, q.imag], mode="lines+markers+text",
                              text=[f"A{i + 1}", f"B{i + 1}"], textposition="top center",
                              name=t("three.positions"), showlegend=i == 0, legendgroup="pos",
                              line=dict(color=CURVE, width=2 * look.line),
                              marker=dict(size=7 * look.line, color=CURVE)))
    shown = stages[:upto]
    lines = {line.ends: line for stage in shown for line in stage.lines}
    for k, line in enumerate(lines.values()):
        ends = [line.middle - span * line.direction, line.middle + span * line.direction]
        chord = line.ends
        traces.append(scatter(x=[chord[0].real, chord[1].real], y=[chord[0].imag, chord[1].imag],
                              mode="lines", showlegend=False, hoverinfo="skip",
                              line=dict(color="#999999", width=1, dash="dot")))
        traces.append(scatter(x=[e.real for e in ends], y=[e.imag for e in ends], mode="lines",
                              name=t("three.bisector"), showlegend=k == 0, legendgroup="bis",
                              line=dict(color=ASKED, width=1.5 * look.line, dash="dash")))
    found = {name: z for stage in shown for name, z in stage.found.items()}
    if found:
        traces.append(scatter(x=[z.real for z in found.values()], y=[z.imag for z in found.values()],
                              mode="markers+text", text=list(found), textposition="bottom left",
                              showlegend=False, marker=dict(size=11 * look.line, color=LINKS,
                                                            symbol="triangle-up")))
    if upto >= len(stages) and {"O", "D"} <= set(found):
        o, d = found["O"], found["D"]
        traces.append(scatter(x=[o.real, a[0].real, b[0].real, d.real],
                              y=[o.imag, a[0].imag, b[0].imag, d.imag], mode="lines",
                              name=t("syn.linkage"), line=dict(color=LINKS, width=3 * look.line)))
    fig.add_raw(traces)
    plane_layout(fig, t("three.chart_title"), look)
    seen = np.array(a + b + list(found.values()))
    middle, half = seen.mean(), 0.65 * max(np.ptp(seen.real), np.ptp(seen.imag), 1e-9)
    fig.merge_layout(dict(xaxis=dict(range=[middle.real - half, middle.real + half]),
                          yaxis=dict(range=[middle.imag - half, middle.imag + half])))
    return fig
