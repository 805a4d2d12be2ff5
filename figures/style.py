"""Shared look of every figure: colours per member, fonts, equal axes in metres.

``Look`` carries what projector mode changes: bigger type, thicker lines, a taller figure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .raw import RawFigure

MEMBER_COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b",
                  "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"]
FRAME_COLOUR = "#444444"
PATH_COLOURS = ["#0b6e4f", "#c44900", "#6a4c93", "#1982c4", "#8a5a44", "#ff595e"]


@dataclass(frozen=True)
class Look:
    font: int = 14
    line: float = 1.0  # multiplies every line width and marker size
    height: int = 600


# under the figure, anchored to its bottom edge: placed relative to the plot area it would
# sit on the x-axis title whenever equal axes shrink that area
LEGEND = dict(orientation="h", yref="container", yanchor="bottom", y=0.0,
              xref="container", xanchor="left", x=0.0)
# every axis: tick labels may overflow the figure. The margins leave them room, and Plotly's
# default check (hide any that would) measures every label on every redraw, ~18 ms a chart
# (bench/browser.py)
TICKS = dict(ticklabeloverflow="allow")
# a drawing's axes: grid and a frame all round
AXIS = dict(showgrid=True, gridcolor="#e5e5e5", zeroline=False, showline=True,
            linecolor="black", mirror=True, **TICKS)
WIDE, NARROW = 740, 360  # px: a chart across the page's main column, and in half of it


def margins(fig: RawFigure, font: int, width: int = WIDE) -> dict:
    """Fixed margins with room for tick labels, axis titles and the legend's rows.

    Plotly's ``automargin`` would measure them instead, but every margin it pushes makes it
    draw the figure a second time (20–50 ms a figure in the browser). A horizontal legend
    wraps at its widest entry, so its rows follow from that entry and the chart's width."""
    names = fig.legend_names()
    rows = 0
    if names:
        widest = max(0.55 * font * len(name) + 50 for name in names)  # text, sample, gap
        rows = math.ceil(len(names) / max(1, int(width // widest)))
    return dict(l=int(4.5 * font + 2), r=10, t=int(2.5 * font + 25),
                b=int(2 * font + 30 + rows * (font + 11)))


NORMAL = Look()
PROJECTOR = Look(font=24, line=2.0, height=860)


def member_colour(number: int) -> str:
    return MEMBER_COLOURS[(number - 2) % len(MEMBER_COLOURS)]


def path_colour(index: int) -> str:
    return PATH_COLOURS[index % len(PATH_COLOURS)]


def plane_layout(fig: RawFigure, title: str, look: Look = NORMAL, x_title: str = "x [m]",
                 y_title: str = "y [m]", equal: bool = True) -> RawFigure:
    """Equal scaling on x and y (a linkage must not look sheared), metres on both axes."""
    layout = dict(
        title=dict(text=title, font=dict(size=look.font + 4)), height=look.height,
        margin=margins(fig, look.font), plot_bgcolor="white",
        font=dict(size=look.font, color="black"), showlegend=True,
        legend=LEGEND,
        xaxis=dict(title=dict(text=x_title), **AXIS),
        yaxis=dict(title=dict(text=y_title), **AXIS))
    if equal:
        layout["yaxis"].update(scaleanchor="x", scaleratio=1)
    fig.merge_layout(layout)
    return fig
