"""The builder's drawing: the mechanism at its drawn instant, every point a circle the user
drags (a Plotly shape named after the point), and the paths the moving points trace over
the cycle, so that a dragged pivot shows at once what it does to the motion."""

from __future__ import annotations

import numpy as np

from mechanisms.schema import Scene

from .linkage import Text, gapped_xy, mechanism_traces, scatter
from .raw import RawFigure
from .style import FRAME_COLOUR, NORMAL, Look, plane_layout

HANDLE = 0.025  # a handle's radius, as a fraction of the drawing's extent
PATH_COLOUR = "#9e9e9e"


def extent(positions: dict[str, complex]) -> float:
    """The drawing's size: the diagonal of the box around its points."""
    z = np.array(list(positions.values()))
    return float(np.hypot(np.ptp(z.real), np.ptp(z.imag))) or 1.0


def builder_figure(scene: Scene, positions: dict[str, complex], rotations: dict[int, complex],
                   paths: dict[str, np.ndarray], title: str, t: Text, look: Look = NORMAL,
                   revision: str = "") -> RawFigure:
    """Members, frame, sliders and letters (``figures.linkage``), grey paths over the cycle
    (NaN where the mechanism cannot go), and one draggable circle per point.

    The zoom is kept between redraws (``uirevision``), but a dragged circle must go where
    the solved mechanism puts it: ``revision`` (new for every new drawing) tells Plotly not
    to keep the user's own shape edits (``editrevision``)."""
    fig = RawFigure()
    if paths:
        fig.add_raw([scatter(**gapped_xy(paths.values()), mode="lines", name=t("build.paths"),
                             hoverinfo="skip",
                             line=dict(color=PATH_COLOUR, width=1 * look.line, dash="dot"))])
    fig.add_raw(mechanism_traces(scene, positions, rotations, t, look))
    r = HANDLE * extent(positions)
    shapes = [dict(type="circle", name=name, xref="x", yref="y", x0=z.real - r, x1=z.real + r,
                   y0=z.imag - r, y1=z.imag + r, line=dict(color=FRAME_COLOUR if name in scene.frame
                                                           else "#1f77b4", width=1.5 * look.line),
                   fillcolor="rgba(31, 119, 180, 0.12)")
              for name, z in sorted(positions.items())]
    plane_layout(fig, title, look)
    fig.merge_layout(dict(shapes=shapes, dragmode="pan", uirevision="builder",
                          editrevision=revision))
    return fig
