"""Velocity and acceleration plans drawn as a student draws them: in centimetres at a scale.

``layout_plan`` turns a plan (``methods.plans``) and a scale U (units per cm) into drawn
arrows and labels up to a step of the construction; ``plan_figure`` shows that in Plotly
and ``plan_svg`` writes it as an SVG whose centimetre is a centimetre on paper.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache

from methods.plans import POLE, Arrow, Plan, Plans
from solvers.kinematics import Motion

from .arrows import arrow_traces, name_by_colour
from .linkage import Text, mechanism_traces, pose, scatter
from .paper import PaperArrow, PaperLabel, bounds, true_scale_svg
from .raw import RawFigure
from .style import AXIS, LEGEND, NARROW, NORMAL, Look, margins, plane_layout

SUPERSCRIPT = {"n": "ⁿ", "t": "ᵗ", "k": "ᵏ", "r": "ʳ"}
KIND_COLOURS = {"absolute": "#222222", "relative": "#1f5fbf", "normal": "#2a9d3a",
                "tangential": "#e07b00", "sliding": "#8e44ad", "coriolis": "#d62728"}
KIND_KEYS = {"absolute": "plans.kind_absolute", "relative": "plans.kind_relative",
             "normal": "plans.kind_normal", "tangential": "plans.kind_tangential",
             "sliding": "plans.kind_sliding", "coriolis": "plans.kind_coriolis"}


@dataclass(frozen=True)
class Drawn:
    arrow: Arrow
    tail: complex  # cm on the plan
    head: complex
    current: bool  # belongs to the highlighted step


@dataclass(frozen=True)
class PlanDrawing:
    arrows: list[Drawn]
    labels: dict[str, complex]  # image label → cm
    scale: float  # units per cm
    unit: str


TEX = {"\\omega": "ω", "\\varepsilon": "ε", "\\cdot": "·"}  # LaTeX commands as plain characters


@lru_cache(maxsize=1024)  # a plan names the same few vectors in every rerun
def _parts(symbol: str) -> tuple[str, str, str]:
    """``a^n_{C_{4}B}`` → ("a", "n", "C4B"); ``b4`` → ("b", "", "4"); ``\\omega_{4}`` → ("ω", "", "4")."""
    for tex, letter in TEX.items():
        symbol = symbol.replace(tex, letter)
    m = re.fullmatch(r"(\w)(?:\^(\w))?(?:_\{(.*)\})?", symbol) or re.fullmatch(r"(\D)()(\d+)", symbol)
    if m is None:
        return symbol, "", ""
    return m[1], m[2] or "", re.sub(r"[_{}]", "", m[3] or "")


def html(symbol: str) -> str:
    """``a^n_{C_{4}B}`` → ``a<sup>n</sup><sub>C4B</sub>``; ``b4`` → ``b<sub>4</sub>``."""
    base, sup, sub = _parts(symbol)
    return base + (f"<sup>{sup}</sup>" if sup else "") + (f"<sub>{sub}</sub>" if sub else "")


def plain(symbol: str) -> str:
    """``a^n_{C_{4}B}`` → ``aⁿ_C4B``, for tables and widgets."""
    base, sup, sub = _parts(symbol)
    return base + SUPERSCRIPT.get(sup, sup) + (f"_{sub}" if sub else "")


def mechanism_figure(motion: Motion, plans: Plans, title: str, t: Text,
                     look: Look = NORMAL) -> RawFigure:
    """The mechanism at the plans' instant, with the coincident points (B₄) marked."""
    fig = RawFigure()
    positions, rotations = pose(motion, 0)
    fig.add_raw(mechanism_traces(motion.scene, positions, rotations, t, look))
    extra = {k: z for k, z in plans.positions.items() if k not in positions}
    fig.add_raw([scatter(x=[z.real for z in extra.values()], y=[z.imag for z in extra.values()],
                         mode="text", text=[html(k.lower()).upper() for k in extra],
                         textposition="bottom left", showlegend=False, hoverinfo="skip",
                         textfont=dict(size=look.font))])
    return plane_layout(fig, title, look)


def layout_plan(plan: Plan, scale: float, upto: int | None = None) -> PlanDrawing:
    """Arrows of steps 0…``upto`` (all when None) in cm, the last step marked current;
    absolute vectors from the pole to every image reached so far."""
    steps = plan.steps if upto is None else plan.steps[:upto + 1]
    last = len(steps) - 1
    cm = {k: v / scale for k, v in plan.images.items()}
    q = plan.quantity[0]
    arrows: list[Drawn] = []
    labels = {POLE: 0j}
    for index, step in enumerate(steps):
        current = upto is not None and index == last
        for _, side in step.sides:
            for a in side:
                arrows.append(Drawn(a, cm[a.tail], cm[a.head], current))
                labels[a.tail], labels[a.head] = cm[a.tail], cm[a.head]
        target = step.target
        absolute = Arrow("absolute", POLE, target, plan.images[target], f"{q}_{{{target.upper()}}}", ())
        arrows.append(Drawn(absolute, 0j, cm[target], current))
        labels[target] = cm[target]
    unit = "m/s" if plan.quantity == "velocity" else "m/s²"
    return PlanDrawing(arrows, labels, scale, unit)


def _merged(labels: dict[str, complex]) -> dict[tuple[str, ...], complex]:
    """Images that coincide (the pole and the fixed points) share one label: P ≡ o ≡ d."""
    groups: dict[tuple[float, float], list[str]] = {}
    for name, z in labels.items():
        groups.setdefault((round(z.real, 6), round(z.imag, 6)), []).append(name)
    return {tuple(sorted(names, key=lambda n: n != POLE)): complex(*xy) for xy, names in groups.items()}


def _visible(d: Drawn) -> bool:
    return abs(d.head - d.tail) > 1e-9


def plan_figure(drawing: PlanDrawing, title: str, t: Text, look: Look = NORMAL) -> RawFigure:
    """The plan on a 1-cm grid, arrows coloured by kind (legend), labels like the book's,
    and a hover on each arrow with its length on the plan and its value."""
    fig = RawFigure()
    visible = [d for d in drawing.arrows if _visible(d)]
    faded = any(d.current for d in visible)
    arrows = []
    for current in (False, True):  # the highlighted step drawn last, on top
        group = [(d.tail, d.head, KIND_COLOURS[d.arrow.kind]) for d in visible if d.current == current]
        arrows += arrow_traces(group, (3.0 if current else 1.8) * look.line,
                               opacity=0.45 if faded and not current else 1.0)
    kinds = {kind: t(key) for kind, key in KIND_KEYS.items()}  # once, not once an arrow
    name_by_colour(arrows, {colour: kinds[kind] for kind, colour in KIND_COLOURS.items()})
    fig.add_raw(arrows)
    hover_x, hover_y, hover_text = [], [], []
    for d in visible:
        mid = (d.head + d.tail) / 2
        length = abs(d.head - d.tail)
        hover_x.append(mid.real)
        hover_y.append(mid.imag)
        hover_text.append(t("plans.hover", name=html(d.arrow.symbol), cm=round(float(length), 2),
                            value=float(length * drawing.scale), unit=drawing.unit,
                            kind=kinds[d.arrow.kind]))
    traces = [scatter(x=hover_x, y=hover_y, mode="markers", hoverinfo="text",
                      hovertext=hover_text, showlegend=False,
                      marker=dict(size=10 * look.line, color="rgba(0,0,0,0)"))]
    pole = "P<sub>v</sub>" if drawing.unit == "m/s" else "P<sub>a</sub>"
    places = _merged(drawing.labels)
    traces.append(scatter(
        x=[z.real for z in places.values()], y=[z.imag for z in places.values()],
        mode="markers+text", text=[" ≡ ".join(pole if n == POLE else html(n) for n in names)
                                   for names in places],
        textposition="top right", hoverinfo="skip", showlegend=False,
        textfont=dict(size=look.font + 2), marker=dict(size=5 * look.line, color="black")))
    fig.add_raw(traces)
    corners = list(drawing.labels.values())
    x0, x1, y0, y1 = bounds(corners)
    span = max(x1 - x0, y1 - y0)
    if span > 20:  # labels are drawn at a fixed font size: leave them room on a long plan
        x0, x1, y0, y1 = bounds(corners, pad=span / 20)
    grid = dict(AXIS)
    if span <= 125:
        grid["dtick"] = 1 if span <= 25 else 5
    fig.merge_layout(dict(
        title=dict(text=title, font=dict(size=look.font + 4)), height=look.height,
        margin=margins(fig, look.font, NARROW), plot_bgcolor="white",
        font=dict(size=look.font, color="black"),
        legend=LEGEND,
        xaxis=dict(range=[x0, x1], title=dict(text="[cm]"), **grid),
        yaxis=dict(range=[y0, y1], title=dict(text="[cm]"), scaleanchor="x", scaleratio=1, **grid)))
    return fig


def plan_svg(drawing: PlanDrawing, caption: str) -> str:
    """The whole plan as SVG at true scale (see figures.paper)."""
    arrows = [PaperArrow(d.tail, d.head, KIND_COLOURS[d.arrow.kind])
              for d in drawing.arrows if _visible(d)]
    labels = [PaperLabel(" ≡ ".join("P" if n == POLE else re.sub(
        r"(\d+)$", r'<tspan font-size="0.2" baseline-shift="sub">\1</tspan>', n) for n in names), z)
              for names, z in _merged(drawing.labels).items()]
    return true_scale_svg(arrows, labels, caption)
