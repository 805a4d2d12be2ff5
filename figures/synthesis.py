"""The synthesis page's drawing: the points asked for, and the found four-bar's coupler curve
through them, the linkage drawn at the first point, each point joined to where the coupler
point really passes (the re-solved positions)."""

from __future__ import annotations

import numpy as np

from .linkage import Text, scatter
from .raw import RawFigure
from .style import NORMAL, Look, plane_layout

ASKED = "#d62728"
CURVE = "#1f77b4"
LINKS = "#333333"


def synthesis_figure(points: list[complex], t: Text, *, curve: np.ndarray | None = None,
                     pivots: tuple[complex, complex] | None = None,
                     joints: tuple[complex, complex, complex] | None = None,
                     reached: np.ndarray | None = None, unit: str = "m",
                     look: Look = NORMAL) -> RawFigure:
    """``points`` numbered in order; with a found four-bar: its coupler ``curve`` over the
    whole turn, its ``pivots`` (O, D) and ``joints`` (A, B, M) at the first point, and the
    positions ``reached`` at each point (joined to their targets when they miss)."""
    fig = RawFigure()
    z = np.array(points, dtype=complex)
    traces = []
    if curve is not None:
        loop = np.append(curve, curve[:1])
        traces.append(scatter(x=loop.real, y=loop.imag, mode="lines", name=t("syn.curve"),
                              line=dict(color=CURVE, width=2 * look.line)))
    if pivots is not None and joints is not None:
        o, d = pivots
        a, b, m = joints
        traces.append(scatter(x=[o.real, a.real, b.real, d.real], y=[o.imag, a.imag, b.imag, d.imag],
                              mode="lines+markers+text", name=t("syn.linkage"),
                              text=["O", "A", "B", "D"], textposition="top left",
                              line=dict(color=LINKS, width=3 * look.line),
                              marker=dict(size=7 * look.line, color=LINKS)))
        traces.append(scatter(x=[a.real, m.real, b.real], y=[a.imag, m.imag, b.imag], mode="lines",
                              fill="toself", fillcolor="rgba(51,51,51,0.12)", showlegend=False,
                              hoverinfo="skip", line=dict(color=LINKS, width=1.5 * look.line)))
    if reached is not None:
        gaps = [v for p, q in zip(z, reached) for v in (p, q, np.nan)]
        gaps = np.array(gaps, dtype=complex)
        traces.append(scatter(x=gaps.real, y=gaps.imag, mode="lines", showlegend=False,
                              hoverinfo="skip", line=dict(color=ASKED, width=1)))
    traces.append(scatter(x=z.real, y=z.imag, mode="markers+text", name=t("syn.points"),
                          text=[str(i + 1) for i in range(len(z))], textposition="bottom right",
                          marker=dict(size=9 * look.line, color=ASKED, symbol="circle-open",
                                      line=dict(width=2))))
    fig.add_raw(traces)
    plane_layout(fig, t("syn.chart_title"), look, x_title=f"x [{unit}]", y_title=f"y [{unit}]")
    return fig
