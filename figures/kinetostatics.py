"""Chapter 5 figures: the mechanism with its loads, Zhukovsky's lever (the velocity plan turned
90° with the forces at their images) and the driving torque and power over the cycle."""

from __future__ import annotations

import re

import numpy as np

from solvers.kinetostatics import Kinetostatics

from .linkage import Text, mechanism_traces, pose, scatter, typical_length
from .polygon import arrows
from .raw import RawFigure
from .style import (
    AXIS,
    LEGEND,
    NORMAL,
    TICKS,
    Look,
    margins,
    member_colour,
    path_colour,
    plane_layout,
)

LOAD_COLOURS = {"external": "#d62728", "inertia": "#ff7f0e", "weight": "#7f7f7f",
                "reaction": "#1f77b4"}
LEGEND_KEYS = {"external": "forces.legend_external", "inertia": "forces.legend_inertia",
               "weight": "forces.legend_weight", "reaction": "forces.legend_reaction"}


REACTION = re.compile(r"F_\d\d(\^[tn])?")  # F_45, and its parts F_45^t, F_45^n


def _kind(name: str) -> str:
    """What a force is, from the course's name: F_i3 inertia, G_3 weight, F_45 (two member
    numbers, or a part of it) a reaction, anything else an external load."""
    if name.startswith(("F_i", "M_i")):
        return "inertia"
    if name.startswith("G_"):
        return "weight"
    return "reaction" if REACTION.fullmatch(name) else "external"


def html(name: str) -> str:
    """F_i3 → F<sub>i3</sub>; F_i3^K → F<sub>i3</sub><sup>K</sup>."""
    base, _, sup = name.partition("^")
    head, _, sub = base.partition("_")
    text = f"{head}<sub>{sub}</sub>" if sub else head
    return text + (f"<sup>{sup}</sup>" if sup else "")


def forces_figure(k: Kinetostatics, index: int, forces: list[tuple[str, complex, complex]],
                  title: str, t: Text, look: Look = NORMAL,
                  members: tuple[int, ...] | None = None,
                  marks: dict[str, complex] | None = None) -> RawFigure:
    """The mechanism (or only ``members``: a free body) at one position, with each force
    (name, point of action, force) as an arrow from its point; the longest arrow is a third
    of a typical link, and each label gives the value. ``marks`` are named points (the point
    a moment equation is taken about)."""
    motion = k.motion
    positions, rotations = pose(motion, index)
    if members is not None:
        own = {p for m in members for p in motion.scene.members[m].points}
        positions = {p: z for p, z in positions.items() if p in own}
        rotations = {m: r for m, r in rotations.items() if m in members}
    fig = RawFigure()
    traces = mechanism_traces(motion.scene, positions, rotations, t, look)
    fig.add_raw([tr for tr in traces if len(tr["x"])])  # members off the free body: no points
    biggest = max((abs(f) for *_, f in forces), default=0.0)
    reach = 0.35 * typical_length(motion.scene)
    if biggest > 0:
        arrows(fig, [p for _, p, _ in forces], [p + f / biggest * reach for _, p, f in forces],
               [LOAD_COLOURS[_kind(n)] for n, *_ in forces],
               [t("fig.force_value", name=html(n), value=float(abs(f))) for n, _, f in forces], look,
               {colour: t(LEGEND_KEYS[kind]) for kind, colour in LOAD_COLOURS.items()})
    for name, z in (marks or {}).items():
        fig.add_raw([scatter(x=[z.real], y=[z.imag], mode="markers+text", text=[name],
                             textposition="bottom right", showlegend=False, hoverinfo="skip",
                             marker=dict(size=11 * look.line, color="black", symbol="circle-x-open"),
                             textfont=dict(size=look.font + 2))])
    return plane_layout(fig, title, look)


def lever_figure(k: Kinetostatics, index: int, title: str, t: Text, look: Look = NORMAL
                 ) -> RawFigure:
    """Zhukovsky's lever: the images of the points (velocity plan at ω₂, turned 90°), the
    members between them, every force at the image of its point and its lever arm about the
    pole (dashed, the foot of the perpendicular)."""
    motion = k.motion
    speed = motion.scene.driver.speed or 1.0
    images = {n.lower(): complex(1j * p.v[index]) for n, p in motion.points.items()}
    fig = RawFigure()
    for number, member in motion.scene.members.items():
        pts = [images[p.lower()] for p in member.points if p.lower() in images]
        if len(pts) > 2:
            pts = pts + pts[:1]
        fig.add_raw([scatter(x=[z.real for z in pts], y=[z.imag for z in pts], mode="lines",
                             line=dict(color=member_colour(number), width=2 * look.line),
                             name=f"{number}", showlegend=False, hoverinfo="skip")])
    names = sorted(images)
    fig.add_raw([scatter(x=[images[n].real for n in names], y=[images[n].imag for n in names],
                         mode="markers+text", text=names, textposition="top right",
                         showlegend=False, hoverinfo="skip",
                         marker=dict(size=5 * look.line, color="black"),
                         textfont=dict(size=look.font + 1)),
                 scatter(x=[0], y=[0], mode="markers+text", text=["P"], showlegend=False,
                         textposition="bottom left", hoverinfo="skip",
                         marker=dict(size=9 * look.line, color="black", symbol="x"))])
    forces = [(f.name, complex(f.image[index]) * speed, complex(f.force[index])) for f in k.lever]
    forces = [(n, p, f) for n, p, f in forces if abs(f) > 0]
    reach = 0.3 * max([abs(z) for z in images.values()] + [1e-12])
    biggest = max((abs(f) for *_, f in forces), default=1.0)
    arrows(fig, [p for _, p, _ in forces], [p + f / biggest * reach for _, p, f in forces],
           [LOAD_COLOURS[_kind(n)] for n, *_ in forces], [html(n) for n, *_ in forces], look)
    feet_x: list = []
    feet_y: list = []
    for _, p, f in forces:  # the foot of the perpendicular from the pole to the force's line
        d = f / abs(f)
        foot = p - (np.conj(d) * p).real * d
        feet_x += [0.0, foot.real, None]
        feet_y += [0.0, foot.imag, None]
    fig.add_raw([scatter(x=feet_x, y=feet_y, mode="lines", name=t("forces.lever_arms"),
                         line=dict(color="#444444", width=1 * look.line, dash="dash"),
                         hoverinfo="skip")])
    return plane_layout(fig, title, look, x_title=t("forces.lever_x"), y_title=t("forces.lever_y"))


def cycle_figure(x: np.ndarray, series: list[tuple[str, np.ndarray, str]], marker: float,
                 title: str, x_title: str, look: Look = NORMAL, y_title: str | None = None
                 ) -> RawFigure:
    """Curves over the cycle, each on the left (y) or right (y2, only when a curve uses it)
    axis, with the chosen instant marked by a vertical line."""
    fig = RawFigure()
    for i, (name, values, axis) in enumerate(series):
        fig.add_raw([scatter(x=x, y=values, mode="lines", name=name, yaxis=axis,
                             line=dict(color=path_colour(i), width=(3.5 - i) * look.line,
                                       dash="dash" if i else "solid"))])
    fig.merge_layout(dict(
        shapes=[dict(type="line", xref="x", yref="y domain", x0=marker, x1=marker, y0=0, y1=1,
                     line=dict(color="black", dash="dot", width=1.5 * look.line))],
        title=dict(text=title, font=dict(size=look.font + 4)), height=int(look.height * 0.7),
        font=dict(size=look.font, color="black"), plot_bgcolor="white",
        margin=dict(margins(fig, look.font), r=int(4.5 * look.font + 2)),  # y2 on the right
        legend=LEGEND,
        xaxis=dict(AXIS, title=dict(text=x_title)),
        yaxis=dict(AXIS, title=dict(text=y_title or series[0][0]), mirror=False, zeroline=True,
                   zerolinecolor="#999999")))
    if any(axis == "y2" for *_, axis in series):
        fig.merge_layout(dict(yaxis2=dict(title=dict(text=series[-1][0]), overlaying="y",
                                          side="right", showgrid=False, **TICKS)))
    return fig
