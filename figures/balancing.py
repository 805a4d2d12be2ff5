"""Chapter 7 figures: the end view and the rotor in 3D (the U and V polygons: figures.polygon).

Vectors are complex numbers z + i·y (the book's axes: z to the right, y up), so a vector
at angle φ points at φ from the z-axis, counter-clockwise.
"""

from __future__ import annotations

import numpy as np

from .linkage import Text, scatter
from .polygon import CLOSING, KNOWN, arrows
from .raw import RawFigure
from .style import NORMAL, Look, path_colour, plane_layout


def end_view_figure(masses: list[tuple[str, complex]], corrections: list[tuple[str, complex]],
                    title: str, t: Text, look: Look = NORMAL) -> RawFigure:
    """Radius vectors r·e^{iφ} of the masses and corrections, seen along the rotor's axis (mm)."""
    fig = RawFigure()
    radius = max(abs(v) for _, v in masses + corrections) * 1e3
    circle = radius * np.exp(1j * np.linspace(0, 2 * np.pi, 120))
    fig.add_raw([scatter(x=circle.real, y=circle.imag, mode="lines", showlegend=False,
                         hoverinfo="skip", line=dict(color="#cccccc", dash="dot"))])
    items = [(n, v * 1e3, KNOWN) for n, v in masses] + [(n, v * 1e3, CLOSING) for n, v in corrections]
    arrows(fig, [0j] * len(items), [v for _, v, _ in items], [c for *_, c in items],
            [n for n, *_ in items], look)
    fig.add_raw([scatter(x=[0], y=[0], mode="markers", showlegend=False,
                         marker=dict(size=8 * look.line, color="black"))])
    plane_layout(fig, title, look, x_title="z [mm]", y_title="y [mm]")
    lim = 1.15 * radius
    fig.merge_layout(dict(showlegend=False, xaxis=dict(range=[-lim, lim]),
                          yaxis=dict(range=[-lim, lim])))
    return fig


def side_view_figure(masses: list[tuple[str, complex, float]], planes: dict[str, float],
                     t: Text, look: Look = NORMAL) -> RawFigure:
    """The rotor seen from the side (looking along z, mm): its axis, the correction planes
    across it (dashed, named), and each mass's arm as it shows there, r·sin φ tall at its
    axial position x. ``masses`` are (name, r·e^{iφ}, x). A still drawing's second view
    (a Moodle question's), where the page turns the rotor in 3D."""
    fig = RawFigure()
    xs = [x * 1e3 for *_, x in masses] + [x * 1e3 for x in planes.values()]
    radius = max(abs(v) for _, v, _ in masses) * 1e3
    span = max(max(xs) - min(xs), 1.0)
    traces = [scatter(x=[min(xs) - 0.1 * span, max(xs) + 0.1 * span], y=[0, 0], mode="lines",
                      line=dict(color="black", width=3 * look.line, dash="dashdot"))]
    for i, (plane, x) in enumerate(planes.items()):
        traces.append(scatter(x=[x * 1e3, x * 1e3], y=[-1.1 * radius, 1.1 * radius],
                              mode="lines+text", text=["", t("rotor.fig_plane", plane=plane)],
                              textposition="top center",
                              line=dict(color=path_colour(i + 2), width=2 * look.line, dash="dash"),
                              textfont=dict(size=look.font, color=path_colour(i + 2))))
    for name, v, x in masses:
        tip = v.imag * 1e3
        traces.append(scatter(x=[x * 1e3, x * 1e3], y=[0, tip], mode="lines+markers+text",
                              text=["", name], textposition="top right" if tip >= 0 else "bottom right",
                              line=dict(color=KNOWN, width=2 * look.line),
                              marker=dict(size=[0, 8 * look.line], color=KNOWN),
                              textfont=dict(size=look.font + 1, color=KNOWN)))
    fig.add_raw(traces)
    plane_layout(fig, "", look, x_title="x [mm]", y_title="y [mm]", equal=False)
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
    for group, colour in ((masses, KNOWN), (corrections, CLOSING)):
        for name, mass, v, x in group:
            v = v * 1e3
            fig.add_raw([dict(type="scatter3d", x=[x * 1e3, x * 1e3], y=[0, v.real], z=[0, v.imag],
                              mode="lines+markers+text", text=["", name], showlegend=False,
                              line=dict(color=colour, width=4 * look.line),
                              marker=dict(size=[0, 6 + 14 * mass / biggest], color=colour))])
    fig.merge_layout(dict(title=dict(text=title), height=look.height, font=dict(size=look.font),
                          margin=dict(l=0, r=0, t=50, b=0),
                          scene=dict(xaxis=dict(title=dict(text="x [mm]")),
                                     yaxis=dict(title=dict(text="z [mm]")),
                                     zaxis=dict(title=dict(text="y [mm]")), aspectmode="data")))
    return fig
