"""Chapter 7 figures: the U and V polygons drawn to scale, the end view, the rotor in 3D.

Vectors are complex numbers z + i·y (the book's axes: z to the right, y up), so a vector
at angle φ points at φ from the z-axis, counter-clockwise.
"""

from __future__ import annotations

import numpy as np

from .linkage import Text, scatter
from .raw import RawFigure
from .style import NORMAL, Look, path_colour, plane_layout

KNOWN = "#1f77b4"
CORRECTION = "#d62728"


def _arrows(fig: RawFigure, starts: list[complex], ends: list[complex], colours: list[str],
            labels: list[str], look: Look) -> None:
    """Arrows as layout annotations (a handful per figure), labelled at their middles."""
    for a, b, colour, label in zip(starts, ends, colours, labels):
        fig.add_annotation(x=b.real, y=b.imag, ax=a.real, ay=a.imag, xref="x", yref="y",
                           axref="x", ayref="y", showarrow=True, arrowhead=3, arrowsize=1.2,
                           arrowwidth=2 * look.line, arrowcolor=colour, text="")
        mid = (a + b) / 2
        fig.add_annotation(x=mid.real, y=mid.imag, text=label, showarrow=False,
                           font=dict(size=look.font + 1, color=colour), xshift=10, yshift=10)


def polygon_figure(known: list[tuple[str, complex]], corrections: list[tuple[str, complex]],
                   scale: float, unit: str, title: str, t: Text, look: Look = NORMAL) -> RawFigure:
    """A closed vector polygon drawn head to tail, in centimetres of drawing at ``scale``
    (``unit`` per cm): the known vectors first, then the corrections that close it."""
    vectors = known + corrections
    points = np.concatenate([[0j], np.cumsum([v for _, v in vectors])]) / scale
    fig = RawFigure()
    fig.add_raw([scatter(x=points.real, y=points.imag, mode="markers+text", showlegend=False,
                         text=[str(i + 1) if i < len(vectors) else "" for i in range(len(points))],
                         textposition="bottom left", hoverinfo="skip",
                         marker=dict(size=5 * look.line, color="black"))])
    colours = [KNOWN] * len(known) + [CORRECTION] * len(corrections)
    _arrows(fig, list(points[:-1]), list(points[1:]), colours,
            [f"{name}" for name, _ in vectors], look)
    fig.add_raw([scatter(x=[None], y=[None], mode="lines", name=t("rotor.fig_known"),
                         line=dict(color=KNOWN, width=3)),
                 scatter(x=[None], y=[None], mode="lines", name=t("rotor.fig_corrections"),
                         line=dict(color=CORRECTION, width=3))])
    plane_layout(fig, f"{title} — {t('rotor.fig_scale', scale=f'{scale:.4g}', unit=unit)}", look,
                 x_title="z [cm]", y_title="y [cm]")
    pad = 0.1 * max(np.ptp(points.real), np.ptp(points.imag), 1.0)
    fig.update_xaxes(range=[points.real.min() - pad, points.real.max() + pad], dtick=1)
    fig.update_yaxes(range=[points.imag.min() - pad, points.imag.max() + pad], dtick=1)
    return fig


def end_view_figure(masses: list[tuple[str, complex]], corrections: list[tuple[str, complex]],
                    title: str, t: Text, look: Look = NORMAL) -> RawFigure:
    """Radius vectors r·e^{iφ} of the masses and corrections, seen along the rotor's axis (mm)."""
    fig = RawFigure()
    radius = max(abs(v) for _, v in masses + corrections) * 1e3
    circle = radius * np.exp(1j * np.linspace(0, 2 * np.pi, 120))
    fig.add_raw([scatter(x=circle.real, y=circle.imag, mode="lines", showlegend=False,
                         hoverinfo="skip", line=dict(color="#cccccc", dash="dot"))])
    items = [(n, v * 1e3, KNOWN) for n, v in masses] + [(n, v * 1e3, CORRECTION) for n, v in corrections]
    _arrows(fig, [0j] * len(items), [v for _, v, _ in items], [c for *_, c in items],
            [n for n, *_ in items], look)
    fig.add_raw([scatter(x=[0], y=[0], mode="markers", showlegend=False,
                         marker=dict(size=8 * look.line, color="black"))])
    plane_layout(fig, title, look, x_title="z [mm]", y_title="y [mm]")
    fig.update_layout(showlegend=False)
    lim = 1.15 * radius
    fig.update_xaxes(range=[-lim, lim])
    fig.update_yaxes(range=[-lim, lim])
    return fig


def rotor_3d_figure(masses: list[tuple[str, float, complex, float]],
                    corrections: list[tuple[str, float, complex, float]], planes: dict[str, float],
                    title: str, t: Text, look: Look = NORMAL) -> RawFigure:
    """The rotor's axis with each mass on its arm at its axial position (all in mm);
    ``masses`` are (name, mass, r·e^{iφ}, x). Marker size grows with the mass."""
    fig = RawFigure()
    xs = [x for *_, x in masses + corrections] + list(planes.values())
    lo, hi = min(xs) * 1e3, max(xs) * 1e3
    span = max(hi - lo, 1.0)
    fig.add_raw([dict(type="scatter3d", x=[lo - 0.1 * span, hi + 0.1 * span], y=[0, 0], z=[0, 0],
                      mode="lines", name=t("rotor.fig_axis"),
                      line=dict(color="black", width=6 * look.line))])
    radius = max(abs(v) for _, _, v, _ in masses + corrections) * 1e3
    ring = radius * np.exp(1j * np.linspace(0, 2 * np.pi, 60))
    for i, (plane, x) in enumerate(planes.items()):
        fig.add_raw([dict(type="scatter3d", x=np.full(60, x * 1e3), y=ring.real, z=ring.imag,
                          mode="lines", name=t("rotor.fig_plane", plane=plane),
                          line=dict(color=path_colour(i + 2), width=3, dash="dash"))])
    biggest = max(m for _, m, _, _ in masses + corrections) or 1.0
    for group, colour in ((masses, KNOWN), (corrections, CORRECTION)):
        for name, mass, v, x in group:
            v = v * 1e3
            fig.add_raw([dict(type="scatter3d", x=[x * 1e3, x * 1e3], y=[0, v.real], z=[0, v.imag],
                              mode="lines+markers+text", text=["", name], showlegend=False,
                              line=dict(color=colour, width=4 * look.line),
                              marker=dict(size=[0, 6 + 14 * mass / biggest], color=colour))])
    fig.update_layout(title=title, height=look.height, font=dict(size=look.font),
                      margin=dict(l=0, r=0, t=50, b=0),
                      scene=dict(xaxis_title="x [mm]", yaxis_title="z [mm]", zaxis_title="y [mm]",
                                 aspectmode="data"))
    return fig
