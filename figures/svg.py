"""A page's 2-D figure as a still SVG drawing, for places that cannot run Plotly: a Moodle
question's picture (the rotor's end and side views, a gear train's half-section). The same
figure the page draws, so the question shows what the student will see in the app.

Only what those figures use is drawn: scatter traces' lines (solid, dashed, dotted),
markers (dots, and the arrowheads of figures.arrows), and text beside points (with the
course's <sub> and <sup> indices). Data units are drawn to one scale on both axes, the
figure ``width`` cm wide; sizes given in screen pixels become 1 px = 1/96 inch. (A page's
figure is drawn by Plotly in the browser; rendering it to SVG on the server would need a
headless browser, Kaleido, for what these few line drawings need.)
"""

from __future__ import annotations

import html
import math
import re

import numpy as np

from .linkage import unpacked
from .raw import RawFigure

PX = 2.54 / 96  # cm a CSS pixel
DASHES = {"dash": "0.25,0.15", "dot": "0.05,0.12", "dashdot": "0.3,0.12,0.05,0.12",
          "longdash": "0.5,0.15"}
_TAG = re.compile(r"<(/?)(sub|sup|b|i|br)\s*/?>|<[^>]*>", re.IGNORECASE)


def _values(array) -> list[float | None]:
    """A trace's coordinates: a list, a numpy array, or Plotly's typed array (base64)."""
    return [None if math.isnan(v) else v for v in unpacked(array).tolist()]


def _each(value, n: int) -> list:
    """A per-point property given once or as a list."""
    return list(value) if isinstance(value, (list, tuple, np.ndarray)) else [value] * n


def _text(markup: str, size: float) -> str:
    """Plotly's text markup as SVG text content: <sub>/<sup> as shifted tspans, the rest plain."""
    out, shift = [], None
    position = 0
    for match in _TAG.finditer(markup):
        out.append(html.escape(html.unescape(markup[position:match.start()]), quote=False))
        position = match.end()
        closing, tag = match.group(1), (match.group(2) or "").lower()
        if tag in ("sub", "sup") and not closing:
            shift = "sub" if tag == "sub" else "super"
            out.append(f'<tspan font-size="{0.7 * size:.3f}" baseline-shift="{shift}">')
        elif tag in ("sub", "sup") and shift:
            out.append("</tspan>")
            shift = None
    out.append(html.escape(html.unescape(markup[position:]), quote=False))
    return "".join(out) + ("</tspan>" if shift else "")


def figure_svg(fig: RawFigure, width: float = 12.0, caption: str = "",
               height: float | None = None, axes: bool = False) -> str:
    """``fig``'s scatter traces as an SVG drawing ``width`` cm wide (y up, as on the page),
    within the layout's axis ranges where it gives them, with ``caption`` under it; one
    scale on both axes, or ``height`` cm tall (a rotor's side view: a metre long, a
    tenth of that across). ``axes``: the lines x = 0 and y = 0, named by the layout's axis
    titles at their positive ends (the end view's z and y, from which φ is measured)."""
    traces = [tr for tr in fig.raw_dict()["data"]
              if tr.get("type", "scatter") == "scatter" and tr.get("visible", True) is True]
    points = [(x, y) for tr in traces for x, y in zip(_values(tr.get("x", [])), _values(tr.get("y", [])))
              if x is not None and y is not None]
    layout = fig.raw_dict()["layout"]
    xs, ys = [x for x, _ in points] or [0.0], [y for _, y in points] or [0.0]
    x0, x1 = layout.get("xaxis", {}).get("range") or (min(xs), max(xs))
    y0, y1 = layout.get("yaxis", {}).get("range") or (min(ys), max(ys))
    pad = 0.08 * max(x1 - x0, y1 - y0, 1e-12)
    x0, x1, y0, y1 = x0 - pad, x1 + pad, y0 - pad, y1 + pad
    k = width / (x1 - x0)  # cm a data unit
    ky = k if height is None else height / (y1 - y0)
    height = (y1 - y0) * ky
    room = 0.8 if caption else 0.0

    def xy(x: float, y: float) -> tuple[float, float]:
        return (x - x0) * k, (y1 - y) * ky

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.2f}cm" '
           f'height="{height + room:.2f}cm" viewBox="0 0 {width:.3f} {height + room:.3f}" '
           'font-family="sans-serif">', f'<rect width="{width:.3f}" height="{height + room:.3f}" fill="#fff"/>']
    if axes:
        names = [str(layout.get(a, {}).get("title", {}).get("text", "")) for a in ("xaxis", "yaxis")]
        (ax, ay), (bx, by), (ox, oy) = xy(x0, 0), xy(0, y1), xy(0, 0)
        out.append(f'<path d="M{ax:.3f},{ay:.3f}H{width:.3f}M{ox:.3f},{height:.3f}V{by:.3f}" '
                   f'stroke="#999" stroke-width="{PX:.3f}"/>'
                   f'<text x="{width - 0.1:.3f}" y="{oy - 0.15:.3f}" font-size="0.3" fill="#666" '
                   f'text-anchor="end">{_text(names[0], 0.3)}</text>'
                   f'<text x="{ox + 0.12:.3f}" y="{by + 0.35:.3f}" font-size="0.3" fill="#666">'
                   f'{_text(names[1], 0.3)}</text>')
    for tr in traces:
        out += _trace(tr, xy)
    if caption:
        out.append(f'<text x="0.2" y="{height + 0.5:.3f}" font-size="0.35">{_text(caption, 0.35)}</text>')
    out.append("</svg>")
    return "\n".join(out)


def _trace(tr: dict, xy) -> list[str]:
    """One scatter trace's lines, then its markers (arrowheads pointing from the point
    before), then its text."""
    xs, ys = _values(tr.get("x", [])), _values(tr.get("y", []))
    mode = str(tr.get("mode", "lines+markers"))
    line, marker = tr.get("line", {}) or {}, tr.get("marker", {}) or {}
    out = []
    if "lines" in mode:
        colour = line.get("color", "#000")
        dash = DASHES.get(str(line.get("dash", "")), "")
        run: list[str] = []
        for x, y in list(zip(xs, ys)) + [(None, None)]:
            if x is None or y is None:
                if len(run) > 1:
                    out.append(f'<polyline points="{" ".join(run)}" fill="none" stroke="{colour}" '
                               f'stroke-width="{line.get("width", 2) * PX:.3f}" stroke-linecap="round"'
                               + (f' stroke-dasharray="{dash}"' if dash else "") + "/>")
                run = []
            else:
                run.append("{:.3f},{:.3f}".format(*xy(x, y)))
    if "markers" in mode:
        sizes = _each(marker.get("size", 6), len(xs))
        colours = _each(marker.get("color", line.get("color", "#000")), len(xs))
        arrow = marker.get("symbol") == "arrow"
        for i, (x, y) in enumerate(zip(xs, ys)):
            if x is None or y is None or not sizes[i]:
                continue
            px, py = xy(x, y)
            r = sizes[i] * PX / 2
            if arrow and i > 0 and xs[i - 1] is not None:
                bx, by = xy(xs[i - 1], ys[i - 1])
                turn = math.atan2(py - by, px - bx)
                corners = [(px, py)] + [(px - 2 * r * math.cos(turn + s * 0.45),
                                         py - 2 * r * math.sin(turn + s * 0.45)) for s in (1, -1)]
                out.append(f'<polygon points="{" ".join(f"{a:.3f},{b:.3f}" for a, b in corners)}" '
                           f'fill="{colours[i]}"/>')
            elif not arrow:
                out.append(f'<circle cx="{px:.3f}" cy="{py:.3f}" r="{r:.3f}" fill="{colours[i]}"/>')
    if "text" in mode:
        font = tr.get("textfont", {}) or {}
        size = float(font.get("size", 12)) * PX
        colours = _each(font.get("color", "#000"), len(xs))
        where = str(tr.get("textposition", "middle center"))
        anchor = "start" if "right" in where else "end" if "left" in where else "middle"
        dx = {"start": 0.12, "end": -0.12, "middle": 0.0}[anchor]
        dy = -0.15 if "top" in where else size + 0.1 if "bottom" in where else size / 3
        for x, y, text, colour in zip(xs, ys, _each(tr.get("text", ""), len(xs)), colours):
            if x is None or y is None or not text:
                continue
            px, py = xy(x, y)
            out.append(f'<text x="{px + dx:.3f}" y="{py + dy:.3f}" font-size="{size:.3f}" '
                       f'text-anchor="{anchor}" fill="{colour}">{_text(str(text), size)}</text>')
    return out
