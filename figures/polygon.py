"""Closed vector polygons drawn to scale, head to tail, as the book draws them: the U and V
polygons of rotor balancing (chapter 7) and the force polygons of kinetostatics (chapter 5)."""

from __future__ import annotations

import numpy as np

from .arrows import arrow_traces, label_trace, name_by_colour
from .linkage import scatter
from .paper import PaperArrow, PaperLabel, subscripts, true_scale_svg
from .raw import RawFigure
from .style import NORMAL, Look, plane_layout

KNOWN = "#1f77b4"
CLOSING = "#d62728"


def arrows(fig: RawFigure, starts: list[complex], ends: list[complex], colours: list[str],
           labels: list[str], look: Look, names: dict[str, str] | None = None) -> None:
    """Arrows (see figures.arrows), each labelled at its middle in its own colour; with
    ``names`` (colour → name) the legend names the colours."""
    traces = arrow_traces(zip(starts, ends, colours), 2 * look.line)
    if names:
        name_by_colour(traces, names)
    fig.add_raw(traces)
    fig.add_raw([label_trace([(complex(a) + complex(b)) / 2 for a, b in zip(starts, ends)],
                             labels, colours, look.font + 1)])


def polygon_figure(known: list[tuple[str, complex]], closing: list[tuple[str, complex]],
                   scale: float, title: str, legend: tuple[str, str], look: Look = NORMAL,
                   axes: tuple[str, str] = ("x", "y")) -> RawFigure:
    """The vectors head to tail in centimetres of drawing at ``scale`` (units per cm): the
    known ones first (numbered corners as in the book), then those that close the polygon.
    ``legend`` names the two colours; ``axes`` the drawing's axes."""
    vectors = known + closing
    points = corners(vectors, scale)
    fig = RawFigure()
    fig.add_raw([scatter(x=points.real, y=points.imag, mode="markers+text", showlegend=False,
                         text=[str(i + 1) if i < len(vectors) else "" for i in range(len(points))],
                         textposition="bottom left", hoverinfo="skip",
                         marker=dict(size=5 * look.line, color="black"))])
    colours = [KNOWN] * len(known) + [CLOSING] * len(closing)
    arrows(fig, list(points[:-1]), list(points[1:]), colours, [name for name, _ in vectors], look,
           {KNOWN: legend[0], CLOSING: legend[1]})
    plane_layout(fig, title, look, x_title=f"{axes[0]} [cm]", y_title=f"{axes[1]} [cm]")
    pad = 0.1 * max(np.ptp(points.real), np.ptp(points.imag), 1.0)
    fig.merge_layout(dict(
        xaxis=dict(range=[points.real.min() - pad, points.real.max() + pad], dtick=1),
        yaxis=dict(range=[points.imag.min() - pad, points.imag.max() + pad], dtick=1)))
    return fig


def corners(vectors: list[tuple[str, complex]], scale: float) -> np.ndarray:
    """The polygon's corners in cm: 0, then each vector added head to tail."""
    return np.concatenate([[0j], np.cumsum([v for _, v in vectors])]) / scale


def polygon_svg(known: list[tuple[str, complex]], closing: list[tuple[str, complex]],
                scale: float, caption: str) -> str:
    """The polygon at true scale for printing (names plain, F_45 style)."""
    vectors = known + closing
    points = corners(vectors, scale)
    colours = [KNOWN] * len(known) + [CLOSING] * len(closing)
    arrows = [PaperArrow(a, b, c) for a, b, c in zip(points[:-1], points[1:], colours)]
    labels = [PaperLabel(f"{i + 1}", z) for i, z in enumerate(points[:-1])]
    labels += [PaperLabel(subscripts(name), (a + b) / 2) for (name, _), a, b
               in zip(vectors, points[:-1], points[1:])]
    return true_scale_svg(arrows, labels, caption)
