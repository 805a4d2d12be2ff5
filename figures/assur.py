"""Chapter 4 figure: the mechanism coloured by Assur group, added group by group, with the
special points S of class III groups, their construction lines and their paths."""

from __future__ import annotations

import numpy as np

from mechanisms.schema import DRIVER, FRAME
from solvers.kinematics import Motion, binary_line, special_pairs
from solvers.state import Body
from solvers.structure import Group, Structure

from .linkage import Text, mechanism_traces, pose, scatter
from .raw import RawFigure
from .style import NORMAL, Look, path_colour, plane_layout

S_COLOUR = "#b8860b"


def group_colours(structure: Structure) -> dict[int, str]:
    """One colour per Assur group (the driver keeps the first)."""
    colours = {DRIVER: path_colour(0)}
    for i, group in enumerate(structure.groups, start=1):
        colours.update(dict.fromkeys(group.members, path_colour(i)))
    return colours


def group_labels(structure: Structure, t: Text) -> dict[int, str]:
    labels = {DRIVER: t("assur.driver_label")}
    for group in structure.groups:
        labels.update(dict.fromkeys(group.members, f"{group.label()} {group.kind}"))
    return labels


def structure_figure(motion: Motion, index: int, upto: int, title: str, t: Text,
                     look: Look = NORMAL, survey: Motion | None = None) -> RawFigure:
    """The driver and the first ``upto`` groups at position ``index``; S where it is finite,
    on its path over ``survey`` (a sweep of the driver; ``motion`` itself when None)."""
    scene, structure = motion.scene, motion.structure
    shown = {FRAME, DRIVER} | {m for g in structure.groups[:upto] for m in g.members}
    positions, rotations = pose(motion, index)
    own = {p for m in shown - {FRAME} for p in scene.members[m].points} | set(scene.frame)
    positions = {p: z for p, z in positions.items() if p in own}
    rotations = {m: r for m, r in rotations.items() if m in shown}
    colours, labels = group_colours(structure), group_labels(structure, t)
    traces = mechanism_traces(scene, positions, rotations, t, look,
                              colour=lambda m: colours[m], label=lambda m: labels[m])
    seen = set()
    for trace in traces:  # one legend entry per group
        if trace.get("name") in seen:
            trace["showlegend"] = False
        seen.add(trace.get("name"))
    shown_groups = structure.groups[:upto]
    for name, (group, b1, b2) in special_pairs(scene, structure.groups).items():
        if group in shown_groups:
            traces += special_traces(motion, name, group, (b1, b2), index, t, look,
                                     survey or motion)
    fig = RawFigure()
    fig.add_raw(traces)
    return plane_layout(fig, title, look)


def special_traces(motion: Motion, name: str, group: Group, pair: tuple[int, int], index: int,
                   t: Text, look: Look, survey: Motion) -> list[dict]:
    """The path of special point ``name`` over ``survey``, its construction lines (from each
    binary member's joint along the member's line to S) and S itself at ``index``."""
    centre, reach = _extent(survey)
    path = survey.special[name].z
    with np.errstate(invalid="ignore"):
        path = np.where(np.abs(path - centre) < reach, path, np.nan)
    traces = [scatter(x=path.real, y=path.imag, mode="lines", name=t("assur.s_path", name=name),
                      hoverinfo="name", line=dict(color=S_COLOUR, width=1.5 * look.line,
                                                  dash="dash"))]
    s = complex(motion.special[name].z[index])
    if not np.isfinite(s) or abs(s - centre) >= reach:
        return traces
    bodies = {m: _body(motion, m, index) for m in [FRAME, *motion.members]}
    xs, ys = [], []
    for member in pair:
        line = binary_line(motion.scene, group, member, bodies)
        if line is not None:
            joint = complex(line[0])
            xs += [joint.real, s.real, None]
            ys += [joint.imag, s.imag, None]
    traces.append(scatter(x=xs, y=ys, mode="lines", showlegend=False, hoverinfo="skip",
                          line=dict(color=S_COLOUR, width=1.2 * look.line, dash="dot")))
    traces.append(scatter(x=[s.real], y=[s.imag], mode="markers+text", text=[name],
                          textposition="bottom right", name=name, hoverinfo="name",
                          marker=dict(symbol="x", size=12 * look.line, color=S_COLOUR),
                          textfont=dict(size=look.font + 2, color=S_COLOUR)))
    return traces


def _extent(survey: Motion) -> tuple[complex, float]:
    """The middle of the mechanism's points over ``survey``, and three mechanism sizes about
    it: how far S and its path are drawn. Near parallel lines S runs off toward infinity, and
    drawing that would shrink the mechanism to a dot. Taken over the whole survey, the
    clipped path is the same at every φ₂ (the browser's φ₂ frames send it once)."""
    points = np.concatenate([p.z for p in survey.points.values()])
    points = points[np.isfinite(points)]
    if not points.size:  # nothing assembles: nothing to draw S beside
        return 0j, 0.0
    centre = complex(points.mean())
    return centre, 3 * max(float(np.abs(points - centre).max()), 1e-9)


def _body(motion: Motion, member: int, index: int) -> Body:
    """A member at one position, placed by its first point (enough for ``binary_line``)."""
    points = motion.scene.points_of(member)
    first = next(iter(points))
    rot = complex(motion.members[member].rot[index]) if member != FRAME else 1 + 0j
    return Body(rot=rot, z=complex(motion.points[first].z[index]), ref=points[first])
