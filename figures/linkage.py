"""The mechanism drawn at one instant, with the paths of its points over the cycle."""

from __future__ import annotations

import cmath

import numpy as np
import plotly.graph_objects as go

from mechanisms.schema import FRAME, Scene
from solvers.kinematics import Motion

from .style import FRAME_COLOUR, PATH_COLOUR, member_colour, plane_layout


def _xy(points: list[complex]) -> tuple[list[float], list[float]]:
    return [p.real for p in points], [p.imag for p in points]


def mechanism_traces(scene: Scene, positions: dict[str, complex],
                     rotations: dict[int, complex]) -> list[go.Scatter]:
    """Members as lines (a ternary member as a closed outline), pivots, sliders and guides."""
    traces = []
    for number, member in scene.members.items():
        pts = [positions[p] for p in member.points if p in positions]
        if len(pts) > 2:
            pts = pts + pts[:1]
        x, y = _xy(pts)
        traces.append(go.Scatter(
            x=x, y=y, mode="lines+markers", name=f"{number} {member.label}".strip(),
            line=dict(color=member_colour(number), width=4), marker=dict(size=7),
            hoverinfo="name"))
    for pair in scene.pairs:
        if pair.kind != "prismatic" or pair.members[0] not in rotations:
            continue
        guide, slider = pair.members
        at = positions.get(pair.point)
        if at is None:
            continue
        direction = cmath.exp(1j * pair.angle) * rotations[guide]
        ends = [at - 0.6 * _scale(scene) * direction, at + 0.6 * _scale(scene) * direction]
        x, y = _xy(ends)
        traces.append(go.Scatter(x=x, y=y, mode="lines", showlegend=False, hoverinfo="skip",
                                 line=dict(color=member_colour(guide) if guide != FRAME
                                           else FRAME_COLOUR, width=1.5, dash="dot")))
        traces.append(go.Scatter(x=[at.real], y=[at.imag], mode="markers", showlegend=False,
                                 hoverinfo="skip", marker=dict(symbol="square", size=14,
                                                               color="rgba(0,0,0,0)",
                                                               line=dict(color=member_colour(slider), width=2))))
    fixed = [positions[p] for p in scene.frame if p in positions]
    x, y = _xy(fixed)
    traces.append(go.Scatter(x=x, y=y, mode="markers", name="1 frame",
                             marker=dict(symbol="triangle-up", size=14, color=FRAME_COLOUR)))
    names = sorted(positions)
    x, y = _xy([positions[n] for n in names])
    traces.append(go.Scatter(x=x, y=y, mode="text", text=names, textposition="top right",
                             showlegend=False, hoverinfo="skip", textfont=dict(size=14)))
    return traces


def _scale(scene: Scene) -> float:
    """A typical length of the scene (for drawing guide lines)."""
    lengths = list(scene.lengths.values()) or [1.0]
    return float(np.median(lengths))


def instant_figure(cycle: Motion, now: Motion, paths: list[str], title: str) -> go.Figure:
    """The mechanism at the instant ``now`` (first position), over the paths of ``cycle``.

    Where the mechanism cannot be, the paths have gaps; an instant that cannot be
    reached draws the paths alone.
    """
    fig = go.Figure()
    for name in paths:
        p = cycle.points[name]
        fig.add_trace(go.Scatter(x=p.x, y=p.y, mode="lines", name=f"path of {name}",
                                 line=dict(color=PATH_COLOUR, width=1.5), hoverinfo="skip"))
    if now.feasible[0]:
        positions = {n: complex(p.z[0]) for n, p in now.points.items()}
        rot = {m: cmath.exp(1j * float(mm.angle[0])) for m, mm in now.members.items()}
        rot[FRAME] = 1 + 0j
        for trace in mechanism_traces(now.scene, positions, rot):
            fig.add_trace(trace)
    return plane_layout(fig, title)
