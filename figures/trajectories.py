"""Chapter 1 figures: the 12-step construction, smooth paths, the animation, the field path."""

from __future__ import annotations

import numpy as np

from mechanisms.schema import FRAME, Scene
from solvers.kinematics import Motion

from .linkage import (Text, gapped, gapped_xy, mechanism_traces, packed, pose, scatter,
                      unpacked)
from .raw import RawFigure
from .style import FRAME_COLOUR, NORMAL, Look, margins, path_colour, plane_layout

TRAIL = 40  # frames a trail lasts
SUBSCRIPTS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def numbered(point: str, k: int) -> str:
    """B₁, B₂, … as the book numbers the positions."""
    return f"{point}{str(k).translate(SUBSCRIPTS)}"


def _closed(z: np.ndarray) -> np.ndarray:
    return np.append(z, z[:1])


def construction_figure(steps: Motion, smooth: Motion | None, points: list[str], title: str,
                        t: Text, look: Look = NORMAL) -> RawFigure:
    """The compass circles, the mechanism faint in each of the 12 positions, the chosen points
    numbered 1…12, and their paths: through the 12 positions as on paper, or (``smooth``)
    at a fine resolution."""
    fig = RawFigure()
    scene = steps.scene
    fig.add_raw(compass_circles(scene, t, look))
    fig.add_raw(pencil_copies(steps, t, look))
    for i, name in enumerate(points):
        colour = path_colour(i)
        z = steps.points[name].z
        marks = dict(text=[numbered(name, k + 1) for k in range(len(z))], textposition="top center",
                     textfont=dict(size=look.font, color=colour), hoverinfo="text",
                     marker=dict(size=7 * look.line, color=colour))
        line = dict(color=colour, width=2 * look.line)
        if smooth is None:  # the path through the 12 positions: one trace draws both
            closed = _closed(z)
            fig.add_raw([scatter(x=closed.real, y=closed.imag, mode="lines+markers+text",
                                 name=t("fig.positions_path", point=name), line=line,
                                 **{**marks, "text": marks["text"] + [""]})])
        else:
            path = _closed(smooth.points[name].z)
            fig.add_raw([scatter(x=path.real, y=path.imag, mode="lines", hoverinfo="skip",
                                 name=t("fig.path_of", point=name), line=line),
                         scatter(x=z.real, y=z.imag, mode="markers+text",
                                 name=t("fig.positions_of", point=name), **marks)])
    if steps.feasible[0]:
        positions, rotations = pose(steps, 0)
        fig.add_raw(mechanism_traces(scene, positions, rotations, t, look))
    return plane_layout(fig, title, look)


def pencil_copies(steps: Motion, t: Text, look: Look) -> list[dict]:
    """The mechanism faint in every position it reaches, in pencil grey as on paper: all its
    members as lines in one trace, its sliders' guides and blocks in one each. The frame's
    pivots do not move (the mechanism drawn in position 1 shows them), and the joints need
    no marks of their own. A browser draws a few traces much faster than 12 copies of eight,
    and lines faster than hundreds of markers."""
    scene = steps.scene
    copies = [mechanism_traces(scene, *pose(steps, k), t, look, opacity=0.18, legend=False,
                               letters=False, colour=lambda _: FRAME_COLOUR)
              for k in range(len(steps.at)) if steps.feasible[k]]
    if not copies:
        return []
    members = len(scene.members)
    pencil = _joined([trace for copy in copies for trace in copy[:members]])
    pencil.update(mode="lines", name=None, legendgroup=None, hoverinfo="skip")
    pencil.pop("marker")
    sliders = zip(*(copy[members:-1] for copy in copies))  # the frame's pivots come last
    return [pencil] + [_joined(list(same)) for same in sliders]


def _joined(traces: list[dict]) -> dict:
    """Traces of one kind as one trace, a gap between each."""
    trace = dict(traces[0])
    for axis in ("x", "y"):
        trace[axis] = packed(gapped(tr[axis] for tr in traces))
    return trace


def compass_circles(scene: Scene, t: Text, look: Look) -> list[dict]:
    """The circles a student draws with the compass: every point of a member pinned to the
    frame moves on a circle about that pivot (the crank circle, the rocker's arc)."""
    ring = np.exp(1j * np.linspace(0, 2 * np.pi, 121))
    circles = []
    for pair in scene.pairs:
        if pair.kind != "revolute" or FRAME not in pair.members:
            continue
        member = scene.members[pair.other(FRAME)]
        centre = scene.frame[pair.point]
        pivot = member.points[pair.point]
        for name, local in member.points.items():
            if name != pair.point:
                circles.append(centre + abs(local - pivot) * ring)
    return [scatter(**gapped_xy(circles), mode="lines", name=t("fig.compass"), hoverinfo="skip",
                    line=dict(color="#999999", width=1 * look.line, dash="dash"))]


def animation_figure(motion: Motion, order: np.ndarray, points: list[str], title: str, t: Text,
                     look: Look = NORMAL) -> RawFigure:
    """The mechanism moving through the positions ``order`` with the chosen points leaving
    trails. Each frame carries only the moving traces (the mechanism and the trails)."""
    scene = motion.scene
    fig = RawFigure()
    for i, name in enumerate(points):  # the whole path, faint and still
        z = motion.points[name].z
        fig.add_raw([scatter(x=z.real, y=z.imag, mode="lines", showlegend=False,
                                 hoverinfo="skip", opacity=0.25,
                                 line=dict(color=path_colour(i), width=1.5 * look.line))])

    def moving(step: int) -> list[dict]:
        k = order[step]
        positions, rotations = pose(motion, k)
        traces = []
        for i, name in enumerate(points):
            trail = motion.points[name].z[order[max(0, step - TRAIL):step + 1]]
            traces.append(scatter(x=trail.real, y=trail.imag, mode="lines",
                                     name=t("fig.trail_of", point=name), hoverinfo="skip",
                                     line=dict(color=path_colour(i), width=3 * look.line)))
        return traces + mechanism_traces(scene, positions, rotations, t, look)

    indices = fig.add_raw(moving(0))
    labels = np.degrees(motion.at[order]) % 360
    fig.add_frames([dict(data=moving(s), traces=indices, name=str(s)) for s in range(len(order))])
    x = np.concatenate([p.x for p in motion.points.values()])
    y = np.concatenate([p.y for p in motion.points.values()])
    _fixed_range(fig, x, y)
    fig.merge_layout(dict(
        updatemenus=_play_buttons(t, look, frame_ms=60, redraw=False),
        sliders=[dict(active=0, x=0.25, y=-0.08, len=0.75, yanchor="top", pad=dict(t=10),
                      currentvalue=dict(prefix="φ₂ = ", suffix="°", font=dict(size=look.font + 2)),
                      steps=[dict(label=f"{labels[s]:.0f}", method="animate",
                                  args=[[str(s)], dict(frame=dict(duration=0, redraw=False),
                                                       mode="immediate")])
                             for s in range(len(order))])]))
    plane_layout(fig, title, look)
    room = margins(fig, look.font)["b"] + 4 * look.font + 30  # the frame slider above the legend
    fig.merge_layout(dict(margin=dict(b=room)))
    return fig


def field_figure(times: np.ndarray, field: np.ndarray, relative: np.ndarray, point: str,
                 steps_per_cycle: int, title: str, t: Text, look: Look = NORMAL) -> RawFigure:
    """The point's path in the field (relative path + travel) over several cycles, with the
    12 numbered positions of each cycle; the relative loop is drawn at the start for scale."""
    fig = RawFigure()
    fig.add_raw([scatter(x=relative.real, y=relative.imag, mode="lines",
                             name=t("fig.relative_path", point=point), hoverinfo="skip",
                             line=dict(color="#999999", width=1.5 * look.line, dash="dot"))])
    fig.add_raw([scatter(x=field.real, y=field.imag, mode="lines",
                             name=t("fig.field_path", point=point),
                             line=dict(color=path_colour(0), width=2.5 * look.line),
                             customdata=times, hovertemplate="t = %{customdata:.4f} s<extra></extra>")])
    marks = np.arange(0, len(field), max(1, steps_per_cycle // 12))
    fig.add_raw([scatter(
        x=field.real[marks], y=field.imag[marks], mode="markers+text",
        name=t("fig.positions_of", point=point),
        text=[numbered(point, (i % 12) + 1) for i in range(len(marks))], textposition="top center",
        textfont=dict(size=look.font - 2), marker=dict(size=6 * look.line, color=path_colour(1)))])
    return plane_layout(fig, title, look)


def compass_figure(scene: Scene, steps: list, texts: list[str], title: str, t: Text,
                   look: Look = NORMAL) -> RawFigure:
    """The compass construction (``methods.compass``) one step per animation frame, with a
    step slider and a play button that run in the browser: the arcs drawn so far in pencil,
    this step's arcs in colour, the points found so far with their numbers, and at the end
    each path through its 12 points. Each frame's title says what the step draws."""
    fig = RawFigure()
    pivots = list(scene.frame.values())
    fig.add_raw([scatter(x=[z.real for z in pivots], y=[z.imag for z in pivots], mode="markers+text",
                         text=list(scene.frame), textposition="bottom center", name=t("fig.frame"),
                         hoverinfo="skip", marker=dict(symbol="triangle-up", size=14 * look.line,
                                                       color=FRAME_COLOUR))])
    near = _arc_targets(steps)

    def drawn(upto: int) -> list[dict]:
        old, new, found, paths = [], [], {}, []
        for s, step in enumerate(steps[:upto + 1]):
            for k, (centre, radius) in enumerate(step.arcs):
                arc = _arc(centre, radius, near.get((s, k)), full=step.what == "crank")
                (new if s == upto else old).append(arc)
            found.update(step.found)
            if step.what == "path":
                paths.append(_closed(np.array(list(step.found.values()))))
        pencil = dict(color="#999999", width=1 * look.line)
        return [scatter(**gapped_xy(old), mode="lines", hoverinfo="skip", name=t("fig.compass"),
                        line=pencil),
                scatter(**gapped_xy(new), mode="lines", hoverinfo="skip", showlegend=False,
                        line=dict(color=path_colour(1), width=2.5 * look.line)),
                scatter(**gapped_xy(paths), mode="lines", hoverinfo="skip", showlegend=False,
                        line=dict(color=path_colour(0), width=2 * look.line, shape="spline")),
                scatter(x=[z.real for z in found.values()], y=[z.imag for z in found.values()],
                        mode="markers+text", text=list(found), textposition="top center",
                        hoverinfo="text", showlegend=False, textfont=dict(size=look.font),
                        marker=dict(size=6 * look.line, color=path_colour(0)))]

    last = len(steps) - 1
    whole = drawn(last)
    indices = fig.add_raw(whole)
    fig.add_frames([dict(data=drawn(s), traces=indices, name=str(s),
                         layout=dict(title=dict(text=texts[s]))) for s in range(len(steps))])
    x = np.concatenate([unpacked(trace["x"]) for trace in whole] + [[z.real for z in pivots]])
    y = np.concatenate([unpacked(trace["y"]) for trace in whole] + [[z.imag for z in pivots]])
    _fixed_range(fig, x, y)  # every arc and point stays in the frame
    jump = dict(frame=dict(duration=0, redraw=True), mode="immediate")
    fig.merge_layout(dict(
        updatemenus=_play_buttons(t, look, frame_ms=700, redraw=True),
        sliders=[dict(active=last, x=0.36, y=-0.08, len=0.64, yanchor="top", pad=dict(t=10),
                      currentvalue=dict(prefix=t("fig.step") + " ", font=dict(size=look.font + 2)),
                      steps=[dict(label=str(s + 1), method="animate", args=[[str(s)], jump])
                             for s in range(len(steps))])]))
    plane_layout(fig, texts[last], look)
    room = margins(fig, look.font)["b"] + 4 * look.font + 30
    fig.merge_layout(dict(margin=dict(b=room)))
    return fig


def _fixed_range(fig: RawFigure, x: np.ndarray, y: np.ndarray) -> None:
    """Axes fixed around every drawn coordinate (NaN ignored), 5 % to spare: frames of an
    animation must not rescale the picture."""
    pad = 0.05 * max(np.nanmax(x) - np.nanmin(x), np.nanmax(y) - np.nanmin(y), 1e-9)
    fig.merge_layout(dict(
        xaxis=dict(range=[float(np.nanmin(x) - pad), float(np.nanmax(x) + pad)], autorange=False),
        yaxis=dict(range=[float(np.nanmin(y) - pad), float(np.nanmax(y) + pad)], autorange=False)))


def _play_buttons(t: Text, look: Look, frame_ms: int, redraw: bool) -> list[dict]:
    """▶ and ■ under the figure: play the frames from the current one, ``frame_ms`` each."""
    play = dict(frame=dict(duration=frame_ms, redraw=redraw), transition=dict(duration=0),
                fromcurrent=True, mode="immediate")
    pause = dict(frame=dict(duration=0, redraw=False), mode="immediate")
    return [dict(type="buttons", direction="left", x=0.0, y=-0.08, xanchor="left",
                 yanchor="top", showactive=False, font=dict(size=look.font + 2),
                 pad=dict(t=10, r=10),
                 buttons=[dict(label="▶ " + t("fig.play"), method="animate", args=[None, play]),
                          dict(label="■ " + t("fig.pause"), method="animate",
                               args=[[None], pause])])]


def _arc_targets(steps: list) -> dict[tuple[int, int], complex]:
    """Where each arc of an "arc" step will be crossed: the point its group's next "meet"
    step finds (a student draws the arc only near there)."""
    out = {}
    for s, step in enumerate(steps):
        if step.what in ("arc", "meet"):
            meet = step if step.what == "meet" else next(m for m in steps[s + 1:] if m.what == "meet")
            for k in range(len(step.arcs)):
                out[(s, k)] = next(iter(meet.found.values()))
    return out


def _arc(centre: complex, radius: float, near: complex | None, full: bool = False) -> np.ndarray:
    if full or near is None:
        return centre + radius * np.exp(1j * np.linspace(0, 2 * np.pi, 121))
    mid = np.angle(near - centre)
    return centre + radius * np.exp(1j * (mid + np.linspace(-0.35, 0.35, 25)))
