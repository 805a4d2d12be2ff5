"""Drawings at true scale as SVG: one centimetre of the drawing is one centimetre of paper
when printed at 100 %, on a 1-cm grid with the scale written under it — so a student can
lay the print over a hand drawing. Used for the velocity/acceleration plans and for the
force and balancing polygons."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class PaperArrow:
    tail: complex  # cm
    head: complex
    colour: str


@dataclass(frozen=True)
class PaperLabel:
    text: str  # SVG text content (already escaped; may hold <tspan>s)
    at: complex  # cm


def bounds(points: list[complex], pad: float = 1.0) -> tuple[float, float, float, float]:
    """x0, x1, y0, y1 in cm around the points, with room on the right for labels."""
    xs = [p.real for p in points] or [0.0]
    ys = [p.imag for p in points] or [0.0]
    return min(xs) - pad, max(xs) + 2.5 * pad, min(ys) - pad, max(ys) + pad


def true_scale_svg(arrows: list[PaperArrow], labels: list[PaperLabel], caption: str) -> str:
    x0, x1, y0, y1 = bounds([a.tail for a in arrows] + [a.head for a in arrows]
                            + [lb.at for lb in labels])
    w, h = x1 - x0, y1 - y0 + 1.0  # one extra cm for the caption

    def xy(z: complex) -> tuple[float, float]:
        return z.real - x0, y1 - z.imag

    colours = sorted({a.colour for a in arrows})
    marker = {c: f"m{i}" for i, c in enumerate(colours)}
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:.3f}cm" height="{h:.3f}cm" '
           f'viewBox="0 0 {w:.3f} {h:.3f}" font-family="sans-serif">',
           '<defs>' + "".join(
               f'<marker id="{marker[c]}" viewBox="0 0 10 10" refX="10" refY="5" '
               f'markerWidth="0.35" markerHeight="0.35" markerUnits="userSpaceOnUse" '
               f'orient="auto"><path d="M0,0 L10,5 L0,10 z" fill="{c}"/></marker>'
               for c in colours) + '</defs>']
    for gx in range(int(w) + 1):
        out.append(f'<line x1="{gx}" y1="0" x2="{gx}" y2="{h - 1:.3f}" stroke="#ddd" stroke-width="0.01"/>')
    for gy in range(int(h - 1) + 1):
        out.append(f'<line x1="0" y1="{gy}" x2="{w:.3f}" y2="{gy}" stroke="#ddd" stroke-width="0.01"/>')
    for a in arrows:
        (ax, ay), (bx, by) = xy(a.tail), xy(a.head)
        out.append(f'<line x1="{ax:.4f}" y1="{ay:.4f}" x2="{bx:.4f}" y2="{by:.4f}" '
                   f'stroke="{a.colour}" stroke-width="0.03" marker-end="url(#{marker[a.colour]})"/>')
    for lb in labels:
        px, py = xy(lb.at)
        out.append(f'<circle cx="{px:.4f}" cy="{py:.4f}" r="0.04"/>'
                   f'<text x="{px + 0.08:.4f}" y="{py - 0.08:.4f}" font-size="0.3">{lb.text}</text>')
    out.append(f'<text x="0.2" y="{h - 0.35:.3f}" font-size="0.3">{escape(caption)}</text></svg>')
    return "\n".join(out)


def escape(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def subscripts(text: str) -> str:
    """F_45 → F<tspan …>45</tspan>: the course's indices, as SVG text."""
    head, _, sub = escape(text).partition("_")
    return head + (f'<tspan font-size="0.2" baseline-shift="sub">{sub}</tspan>' if sub else "")
