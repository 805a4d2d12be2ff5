"""The mechanism drawn at one position: members, pivots, sliders with their guides, letters.

Every call returns the same number of traces in the same order for any position of a
scene, so animation frames can replace them one for one; a scene without sliders has no
guide or block traces. Traces are plain dicts.
"""

from __future__ import annotations

import base64
import cmath
from collections.abc import Callable, Iterable

import numpy as np
from _plotly_utils.utils import to_typed_array_spec

from mechanisms.schema import FRAME, Scene
from solvers.kinematics import Motion

from .style import FRAME_COLOUR, NORMAL, Look, member_colour

Text = Callable[..., str]  # the page's translator: t(key, **values)


def scatter(**properties) -> dict:
    """A scatter trace as a plain dict (see figures/raw.py for why not ``go.Scatter``), its
    coordinate arrays ``packed``."""
    for key in ("x", "y", "customdata"):
        if key in properties:
            properties[key] = packed(properties[key])
    return {"type": "scatter", **properties}


def packed(values):
    """A numpy array of more than 64 numbers as base64 float32 (Plotly's typed arrays): a
    quarter of the JSON text, encoded in microseconds, and seven digits is more than a
    screen shows. Anything else as it is."""
    if isinstance(values, np.ndarray) and values.size > 64:
        return to_typed_array_spec(values.astype(np.float32))
    return values


def unpacked(values) -> np.ndarray:
    """A trace's coordinates as floats, NaN for a gap: a list (``None`` for a gap), a numpy
    array, or Plotly's typed array (``packed``)."""
    if isinstance(values, dict) and "bdata" in values:
        return np.frombuffer(base64.b64decode(values["bdata"]), dtype=values["dtype"]).astype(float)
    return np.asarray(values, dtype=float)


def gapped(pieces: Iterable) -> np.ndarray:
    """Lines joined into one array, a NaN after each: Plotly's gap between them, as the
    ``None`` of a list, but the array can travel ``packed`` (the builder's paths as lists
    of ``None``-separated numbers were 22 of its chart's 26 kB every rerun)."""
    return np.concatenate([np.append(np.asarray(piece, dtype=float), np.nan) for piece in pieces]
                          or [np.empty(0)])


def gapped_xy(curves: Iterable[np.ndarray]) -> dict[str, np.ndarray]:
    """Curves in the complex plane as one trace's ``x`` and ``y``, ``gapped``."""
    curves = list(curves)
    return dict(x=gapped(c.real for c in curves), y=gapped(c.imag for c in curves))


def _xy(points: list[complex]) -> tuple[list[float], list[float]]:
    return [p.real for p in points], [p.imag for p in points]


def pose(motion: Motion, index: int) -> tuple[dict[str, complex], dict[int, complex]]:
    """Positions of the points and rotations e^{iθ} of the members at one position."""
    positions = {n: complex(p.z[index]) for n, p in motion.points.items()}
    rotations = {m: complex(mm.rot[index]) for m, mm in motion.members.items()}
    rotations[FRAME] = 1 + 0j
    return positions, rotations


def typical_length(scene: Scene) -> float:
    lengths = list(scene.lengths.values()) or [1.0]
    return float(np.median(lengths))


def mechanism_traces(scene: Scene, positions: dict[str, complex], rotations: dict[int, complex],
                     t: Text, look: Look = NORMAL, opacity: float = 1.0,
                     legend: bool = True, letters: bool = True,
                     colour: Callable[[int], str] = member_colour,
                     label: Callable[[int], str] | None = None) -> list[dict]:
    """Members as thick lines (a member with three or more points as a closed outline),
    frame pivots as triangles, sliders as squares on dotted guide lines (a circular slot's
    dotted arc), point letters.
    ``colour`` and ``label`` per member number default to the member's own."""
    traces = []
    blocks_in_slots = {pair.members[1]: pair.on_slot for pair in scene.pairs if pair.on_slot}
    for number, member in scene.members.items():
        # a block in a circular slot is drawn as the block, not as its link to the centre
        shown = [blocks_in_slots[number]] if number in blocks_in_slots else member.points
        pts = [positions[p] for p in shown if p in positions]
        if len(pts) > 2:
            pts = pts + pts[:1]
        x, y = _xy(pts)
        name = label(number) if label else t("fig.member", number=number,
                                               member_label=member.label).strip()
        traces.append(scatter(
            x=x, y=y, mode="lines+markers", name=name, legendgroup=name,
            showlegend=legend, opacity=opacity, hoverinfo="name",
            line=dict(color=colour(number), width=4 * look.line),
            marker=dict(size=7 * look.line)))
    guide_x: list = []
    guide_y: list = []
    blocks = []
    reach = 0.6 * typical_length(scene)
    sliding = [pair for pair in scene.pairs if pair.kind == "prismatic" or pair.on_slot]
    for pair in sliding:
        if pair.on_slot:  # the slot's arc about its centre, a quarter circle around the block
            centre, at = positions.get(pair.point), positions.get(pair.on_slot)
            if centre is None or at is None:
                continue
            arc = np.exp(1j * np.linspace(-np.pi / 4, np.pi / 4, 25))
            x, y = _xy(list(centre + (at - centre) * arc))
            guide_x += x + [None]
            guide_y += y + [None]
            blocks.append(at)
            continue
        at = positions.get(pair.point)
        rot = rotations.get(pair.members[0])
        if at is None or rot is None:
            continue
        direction = cmath.exp(1j * pair.angle) * rot
        x, y = _xy([at - reach * direction, at + reach * direction])
        guide_x += x + [None]
        guide_y += y + [None]
        blocks.append(at)
    if sliding:  # guides and blocks only where the scene has sliders: a trace costs the browser
        traces.append(scatter(x=guide_x, y=guide_y, mode="lines", showlegend=False,
                              hoverinfo="skip", opacity=opacity,
                              line=dict(color=FRAME_COLOUR, width=1.5 * look.line, dash="dot")))
        x, y = _xy(blocks)
        traces.append(scatter(x=x, y=y, mode="markers", showlegend=False, hoverinfo="skip",
                              opacity=opacity,
                              marker=dict(symbol="square-open", size=16 * look.line,
                                          color=FRAME_COLOUR, line=dict(width=2 * look.line))))
    x, y = _xy([positions[p] for p in scene.frame if p in positions])
    traces.append(scatter(x=x, y=y, mode="markers", name=t("fig.frame"), showlegend=legend,
                             opacity=opacity, hoverinfo="skip",
                             marker=dict(symbol="triangle-up", size=14 * look.line,
                                         color=FRAME_COLOUR)))
    if letters:
        names = sorted(positions)
        x, y = _xy([positions[n] for n in names])
        traces.append(scatter(x=x, y=y, mode="text", text=names, textposition="top right",
                              showlegend=False, hoverinfo="skip",
                              textfont=dict(size=look.font + 2, color="black")))
    return traces
