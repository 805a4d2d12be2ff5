"""Chapter 6 figures: the train in half-section and the Kutzbach velocity diagram ("velocida").

Both share the vertical axis: the distance y from the central axis (m). In the velocity
diagram every member is one straight line v(y) = ω·y + (ω_carrier − ω)·y_axis; meshing
members share the pitch point's velocity, so their lines cross there. Angular velocities are
read with a pole at distance H below the axis: the ray parallel to a member's line meets
the axis at v = ω·H.
"""

from __future__ import annotations

from mechanisms.gears import GearTrain
from solvers.gears import TrainSolution

from .linkage import Text, scatter
from .raw import RawFigure
from .style import NORMAL, Look, member_colour, plane_layout


def rims(train: GearTrain) -> dict[int, list[float]]:
    """The pitch radii each member shows in its meshes."""
    out: dict[int, list[float]] = {m: [] for m in train.members}
    for mesh in train.meshes:
        for m, r in zip(mesh.members, mesh.radii):
            out[m].append(r)
    return out


def axial_positions(train: GearTrain) -> dict[int, float]:
    """Given x, or members laid out left to right in order (shafts side by side)."""
    spread = max([m.axis for m in train.members.values()] + [r for rs in rims(train).values() for r in rs])
    step = 0.25 * spread
    return {n: (m.x if m.x is not None else i * step) for i, (n, m) in enumerate(train.members.items())}


def contact(train: GearTrain, mesh) -> float:
    """Radius y of the pitch point of a mesh in the half-section."""
    (a, b), (ra, rb) = mesh.members, mesh.radii
    if mesh.internal == a:  # let a be the gear with outer teeth
        a, b, ra, rb = b, a, rb, ra
    ya, yb = train.members[a].axis, train.members[b].axis
    if mesh.internal is None:
        return ya + ra if yb > ya or (yb == ya and ra < rb) else ya - ra
    return ya + ra if ya >= yb else ya - ra


def member_name(train: GearTrain, n: int, t: Text) -> str:
    """Member ``n`` as every surface names it ("4 ring — fixed"): whether it is fixed is said
    from the train's ``fixed``, never written into a label as well."""
    name = t("fig.member", number=n, member_label=train.members[n].label).strip()
    return name + (f" — {t('gears.fixed')}" if n in train.fixed else "")


def schematic_figure(train: GearTrain, title: str, t: Text, look: Look = NORMAL) -> RawFigure:
    """Half-section to scale: each member's rims as bars about its axis, carriers as arms."""
    fig = RawFigure()
    x = axial_positions(train)
    rim = rims(train)
    traces = [scatter(x=[min(x.values()) - 0.1, max(x.values()) + 0.1], y=[0, 0], mode="lines",
                      name=t("gears.central_axis"), line=dict(color="black", dash="dashdot"))]
    for n, m in train.members.items():
        colour = member_colour(n)
        reach = max(rim[n], default=0.0)
        for r in rim[n]:
            traces.append(scatter(x=[x[n], x[n]], y=[m.axis - r, m.axis + r], mode="lines",
                                  showlegend=False, hoverinfo="skip",
                                  line=dict(color=colour, width=6 * look.line)))
        if m.carrier is not None:  # the arm from the carrier's hub out to the planet's axis
            c = m.carrier
            traces.append(scatter(x=[x[c], x[c], x[n]], y=[0, m.axis, m.axis], mode="lines",
                                  showlegend=False, hoverinfo="skip",
                                  line=dict(color=member_colour(c), width=3 * look.line)))
        traces.append(scatter(x=[x[n]], y=[m.axis + reach], mode="markers+text", text=[str(n)],
                              textposition="top center", name=member_name(train, n, t),
                              marker=dict(color=colour, size=8 * look.line),
                              # the number over the tallest rim stays whole above the plot's edge
                              cliponaxis=False, textfont=dict(size=look.font + 2, color=colour)))
    for shaft in train.shafts:
        xs = [x[m] for m in shaft]
        axis = train.members[shaft[0]].axis
        traces.append(scatter(x=[min(xs), max(xs)], y=[axis, axis], mode="lines", showlegend=False,
                              hoverinfo="skip", line=dict(color="#777777", width=2 * look.line)))
    fig.add_raw(traces)
    plane_layout(fig, title, look, x_title=t("gears.axial"), y_title=t("gears.radius"))
    return fig


def velocity_figure(solution: TrainSolution, pole: float, title: str, t: Text,
                    look: Look = NORMAL) -> RawFigure:
    """Kutzbach's diagram: each member's velocity line, the pitch points, and the rays from a
    pole ``pole`` metres below the axis whose intercepts give ω·H."""
    train = solution.train
    rim = rims(train)
    fig = RawFigure()
    traces = []
    for n, m in train.members.items():
        if n not in solution.omega:
            continue
        carried = [p.axis for p in train.members.values() if p.carrier == n]
        if m.axis == 0:  # a central member: from the axis out to its rims and planets
            ys = [0.0, max(rim[n] + carried, default=0.0)]
        else:
            reach = max(rim[n], default=0.0)
            ys = [m.axis - reach, m.axis + reach]
        vs = [solution.velocity(n, y) for y in ys]
        traces.append(scatter(x=vs, y=ys, mode="lines", name=t("fig.omega_line", member=n,
                                                                 omega=float(solution.omega[n])),
                              line=dict(color=member_colour(n), width=2.5 * look.line)))
        traces.append(scatter(x=[0, solution.omega[n] * pole], y=[-pole, 0], mode="lines+text",
                              text=["", str(n)], textposition="top center", showlegend=False,
                              hoverinfo="skip", textfont=dict(color=member_colour(n)),
                              line=dict(color=member_colour(n), width=1 * look.line, dash="dot")))
    xs, ys, labels = [], [], []
    for mesh in train.meshes:
        y = contact(train, mesh)
        a = mesh.members[0]
        if a in solution.omega:
            xs.append(solution.velocity(a, y))
            ys.append(y)
            labels.append(f"{mesh.members[0]}–{mesh.members[1]}")
    traces.append(scatter(x=xs, y=ys, mode="markers+text", text=labels, textposition="middle right",
                          name=t("gears.pitch_points"), marker=dict(size=9 * look.line, color="black")))
    traces.append(scatter(x=[0], y=[-pole], mode="markers+text", text=["P"], textposition="bottom center",
                          name=t("gears.pole"), marker=dict(size=8, color="black", symbol="x")))
    fig.add_raw(traces)
    # velocities and radii have different units: no equal scaling
    plane_layout(fig, title, look, x_title="v [m/s]", y_title=t("gears.radius"), equal=False)
    return fig
