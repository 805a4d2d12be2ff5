"""Printable sheets of a set of variants: one A4 page per student, then the lecturer's key.

Plain HTML with its own print style (the browser's "Print" makes the PDF) and the
mechanism drawn as SVG in real centimetres at the task's length scale U_L, so that a
student measures the drawing with a ruler as on the exam. Pure: it takes a solved set of
variants and returns text.
"""

from __future__ import annotations

import html
import math

from exams.variants import VariantSet, symbol
from methods.practice import printed_tolerance

WORDS = {
    "en": {"variant": "Variant", "name": "Name and index number", "given": "Given",
           "find": "Find", "drawing": "The mechanism at the asked instant, drawn at U_L = {u} m/cm",
           "check": "Check your answers: in Mehanizmi, type the code {code} into the self-check box.",
           "key": "Answer key", "quantity": "Quantity", "value": "Exact value", "unit": "Unit",
           "tolerance": "A drawing allows ±", "title": "Variants of {task} (seed {seed}, ± {spread} %)",
           "extra": "In grey: not asked by the task, but graded by the self-check of its page."},
    "sr": {"variant": "Varijanta", "name": "Ime, prezime i broj indeksa", "given": "Dato",
           "find": "Odrediti", "drawing": "Mehanizam u traženom položaju, nacrtan u razmeri U_L = {u} m/cm",
           "check": "Proverite rešenja: u aplikaciji Mehanizmi unesite kod {code} u polje za samoproveru.",
           "key": "Ključ rešenja", "quantity": "Veličina", "value": "Tačna vrednost", "unit": "Jedinica",
           "tolerance": "Crtež dozvoljava ±", "title": "Varijante zadatka {task} (seme {seed}, ± {spread} %)",
           "extra": "Sivo: zadatak to ne traži, ali ga ocenjuje samoprovera na stranici zadatka."},
}

STYLE = """
@page { size: A4; margin: 15mm; }
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 11pt; color: #000; }
.sheet { page-break-after: always; break-after: page; }
h1 { font-size: 15pt; margin: 0 0 4mm; } h2 { font-size: 12pt; margin: 5mm 0 2mm; }
.code { float: right; font: bold 14pt monospace; border: 1px solid #000; padding: 1mm 3mm; }
.name { border-bottom: 1px solid #000; height: 8mm; margin-bottom: 4mm; }
table { border-collapse: collapse; } td, th { border: 1px solid #888; padding: 1mm 3mm; text-align: left; }
td.n { text-align: right; font-variant-numeric: tabular-nums; }
.answer { width: 35mm; } .small { font-size: 9pt; color: #333; }
tr.extra td { color: #666; font-style: italic; }
.tasks { display: flex; gap: 10mm; align-items: flex-start; }
"""


def _n(value: float, digits: int = 6, language: str = "en") -> str:
    """A number as the language writes it (Serbian: a decimal comma)."""
    text = f"{value:.{digits}g}".replace("-", "−")
    return text.replace(".", ",") if language == "sr" else text


def _e(text: str) -> str:
    """Escaped for HTML, without the ⟨ ⟩ that mark formulas in the app's texts."""
    return html.escape(str(text).replace("⟨", "").replace("⟩", ""))


def drawing_svg(scene, drawn: dict[str, complex], scale: float) -> str:
    """The linkage at its instant as SVG in centimetres (1 cm = ``scale`` m): each member's
    points joined, frame pivots as triangles, guides of sliding pairs as dashed lines, and
    the points lettered."""
    if not drawn:
        return ""
    zs = list(drawn.values())
    pad = 0.08 * max(max(z.real for z in zs) - min(z.real for z in zs),
                     max(z.imag for z in zs) - min(z.imag for z in zs), scale)
    x0, x1 = min(z.real for z in zs) - pad, max(z.real for z in zs) + pad
    y0, y1 = min(z.imag for z in zs) - pad, max(z.imag for z in zs) + pad

    def xy(z: complex) -> tuple[float, float]:  # cm on the paper, y down
        return (z.real - x0) / scale, (y1 - z.imag) / scale

    width, height = (x1 - x0) / scale, (y1 - y0) / scale
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.2f}cm" height="{height:.2f}cm" '
           f'viewBox="0 0 {width:.3f} {height:.3f}">',
           '<g stroke="#000" stroke-width="0.03" fill="none" stroke-linecap="round">']
    for member in scene.members.values():
        names = [n for n in member.points if n in drawn]
        path = [xy(drawn[n]) for n in names]
        if len(path) >= 2:
            closed = len(path) >= 3
            points = " ".join(f"{x:.3f},{y:.3f}" for x, y in path)
            tag = "polygon" if closed else "polyline"
            out.append(f'<{tag} points="{points}" stroke-width="0.06"/>')
    for pair in scene.pairs:
        if pair.kind == "prismatic" and pair.through in drawn and pair.point in drawn:
            a, b = drawn[pair.through], drawn[pair.point]
            if abs(b - a) > 1e-9:
                d = (b - a) * 0.25
                (ax, ay), (bx, by) = xy(a - d), xy(b + d)
                out.append(f'<line x1="{ax:.3f}" y1="{ay:.3f}" x2="{bx:.3f}" y2="{by:.3f}" '
                           'stroke-dasharray="0.2 0.1"/>')
                cx, cy = xy(b)
                out.append(f'<rect x="{cx - 0.25:.3f}" y="{cy - 0.15:.3f}" width="0.5" height="0.3"/>')
    for name in scene.frame:
        if name in drawn:
            x, y = xy(drawn[name])
            out.append(f'<polygon points="{x:.3f},{y:.3f} {x - 0.25:.3f},{y + 0.4:.3f} '
                       f'{x + 0.25:.3f},{y + 0.4:.3f}"/>'
                       f'<line x1="{x - 0.4:.3f}" y1="{y + 0.4:.3f}" x2="{x + 0.4:.3f}" y2="{y + 0.4:.3f}"/>')
    out.append('</g><g fill="#fff" stroke="#000" stroke-width="0.03">')
    for name, z in drawn.items():
        x, y = xy(z)
        out.append(f'<circle cx="{x:.3f}" cy="{y:.3f}" r="0.08"/>')
    out.append('</g><g fill="#000" font-size="0.4">')
    for name, z in drawn.items():
        x, y = xy(z)
        out.append(f'<text x="{x + 0.15:.3f}" y="{y - 0.15:.3f}" font-size="0.4">{_e(name)}</text>')
    out.append("</g></svg>")
    return "\n".join(out)


def length_scale(scene, drawn: dict[str, complex]) -> float:
    """The task's U_L (m per cm), or for a scene without one a round scale (1, 2, 5 × 10ⁿ)
    that makes the drawing at most 12 cm wide."""
    if getattr(scene, "scales", {}).get("L"):
        return scene.scales["L"]
    size = max((abs(a - b) for a in drawn.values() for b in drawn.values()), default=1.0) or 1.0
    raw = size / 12
    power = 10 ** math.floor(math.log10(raw))
    return next(m * power for m in (1, 2, 5, 10) if m * power >= raw)


def sheets_html(found: VariantSet, title: str, language: str = "sr") -> str:
    """Every variant's sheet (A4, one per page) and then the lecturer's key, in one file."""
    w = WORDS[language]
    s = found.settings
    parts = [f'<!DOCTYPE html><html lang="{language}"><head><meta charset="utf-8">',
             f"<title>{_e(w['title'].format(task=s.task, seed=s.seed, spread=s.spread))}</title>",
             f"<style>{STYLE}</style></head><body>"]
    for v in found.variants:
        parts.append(f'<section class="sheet"><div class="code">{_e(v.code)}</div>')
        parts.append(f"<h1>{_e(title)} — {_e(w['variant'])} {v.index}</h1>")
        parts.append(f'<div class="small">{_e(w["name"])}</div><div class="name"></div>')
        parts.append(f"<div class=\"tasks\"><div><h2>{_e(w['given'])}</h2><table>")
        for g, value in v.given:
            parts.append(f'<tr><td>{_e(g.label)}</td><td class="n">{_e(_n(value, language=language))}</td>'
                         f"<td>{_e(g.unit)}</td></tr>")
        parts.append(f"</table></div><div><h2>{_e(w['find'])}</h2><table>")
        for a in v.key:
            if a.asked:
                parts.append(f'<tr><td>{_e(symbol(a.key))}</td><td class="answer"></td><td>{_e(a.unit)}</td></tr>')
        parts.append("</table></div></div>")
        if v.drawn:
            scale = length_scale(v.scene, v.drawn)
            parts.append(f"<h2>{_e(w['drawing'].format(u=_n(scale, language=language)))}</h2>")
            parts.append(drawing_svg(v.scene, v.drawn, scale))
        parts.append(f'<p class="small">{_e(w["check"].format(code=v.code))}</p></section>')
    parts.append(f"<section><h1>{_e(w['key'])}: "
                 f"{_e(w['title'].format(task=s.task, seed=s.seed, spread=s.spread))}</h1>"
                 f'<p class="small">{_e(w["extra"])}</p>')
    for v in found.variants:
        parts.append(f"<h2>{_e(v.code)}</h2><table><tr><th>{_e(w['quantity'])}</th>"
                     f"<th>{_e(w['value'])}</th><th>{_e(w['unit'])}</th><th>{_e(w['tolerance'])}</th></tr>")
        for a in v.key:
            tol = "" if a.tolerance is None else _n(printed_tolerance(a.tolerance), 3, language)
            row = "<tr>" if a.asked else '<tr class="extra">'
            parts.append(f'{row}<td>{_e(symbol(a.key))}</td><td class="n">{_e(_n(a.value, language=language))}</td>'
                         f'<td>{_e(a.unit)}</td><td class="n">{_e(tol)}</td></tr>')
        parts.append("</table>")
    parts.append("</section></body></html>")
    return "\n".join(parts)
