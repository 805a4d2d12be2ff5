"""Arrows drawn as scatter traces: the shaft as a line, the head as Plotly's ``arrow``
marker turned along the shaft (``angleref="previous"``), its tip on the head point.

Plotly's annotation arrows cost a DOM group and an SVG path measurement each, on every
redraw: the plans page (30 arrows) spent most of its browser redraw there. One trace per
colour draws the same arrows as one path and one set of markers.
"""

from __future__ import annotations

from collections.abc import Iterable

from .linkage import scatter

HEAD = 5.0  # head size per unit of line width, in px


def arrow_traces(arrows: Iterable[tuple[complex, complex, str]], width: float,
                 opacity: float = 1.0) -> list[dict]:
    """One trace per colour for arrows (tail, head, colour); zero-length arrows have no
    direction and are left out."""
    by_colour: dict[str, tuple[list, list, list]] = {}
    for tail, head, colour in arrows:
        tail, head = complex(tail), complex(head)
        if abs(head - tail) <= 1e-12 * max(abs(head), abs(tail), 1e-300):
            continue
        xs, ys, sizes = by_colour.setdefault(colour, ([], [], []))
        xs += [tail.real, head.real, None]
        ys += [tail.imag, head.imag, None]
        sizes += [0, HEAD * width + 4, 0]
    return [scatter(x=xs, y=ys, mode="lines+markers", showlegend=False, hoverinfo="skip",
                    opacity=opacity, line=dict(color=colour, width=width),
                    marker=dict(symbol="arrow", angleref="previous", size=sizes, color=colour,
                                opacity=1.0, line=dict(width=0)))
            for colour, (xs, ys, sizes) in by_colour.items()]


def name_by_colour(traces: list[dict], names: dict[str, str]) -> None:
    """Legend entries from the arrow traces themselves, one per colour drawn, named and
    ordered as in ``names`` (colour → name): the entry takes the look of the last trace of
    its colour (drawn on top), and all of a colour's arrows hide together. An empty trace
    per entry cost the browser a whole trace on every redraw."""
    order = list(names)
    named = set()
    for trace in reversed(traces):
        colour = trace["line"]["color"]
        trace.update(name=names[colour], legendgroup=colour, showlegend=colour not in named,
                     legendrank=order.index(colour))
        named.add(colour)


def label_trace(places: list[complex], labels: list[str], colours: list[str],
                size: float) -> dict:
    """Labels beside points (an arrow's middle), each in its arrow's colour."""
    return scatter(x=[z.real for z in places], y=[z.imag for z in places], mode="text",
                   text=labels, textposition="top right", showlegend=False, hoverinfo="skip",
                   textfont=dict(size=size, color=colours))
