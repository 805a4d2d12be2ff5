"""Shared look of every figure: colours per member, fonts, equal axes in metres."""

from __future__ import annotations

import plotly.graph_objects as go

MEMBER_COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b",
                  "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"]
FRAME_COLOUR = "#444444"
PATH_COLOUR = "#888888"


def member_colour(number: int) -> str:
    return MEMBER_COLOURS[(number - 2) % len(MEMBER_COLOURS)]


def plane_layout(fig: go.Figure, title: str, height: int = 560) -> go.Figure:
    """Equal scaling on x and y (a linkage must not look sheared), metres on both axes."""
    fig.update_layout(
        title=title, height=height, margin=dict(l=10, r=10, t=50, b=80),
        plot_bgcolor="white", showlegend=True,
        legend=dict(orientation="h", yanchor="top", y=-0.12, xanchor="left", x=0.0),
    )
    fig.update_xaxes(title_text="x [m]", showgrid=True, gridcolor="#eeeeee", zeroline=False)
    fig.update_yaxes(title_text="y [m]", showgrid=True, gridcolor="#eeeeee", zeroline=False,
                     scaleanchor="x", scaleratio=1)
    return fig
