"""The complex-number (vector-loop) method written out as the course writes it.

For every Assur group the kinematics core closes one vector loop (``loops.build_loop``).
This module states that loop, its first and second derivatives (the course's equations
B and C) and the unknowns each yields, as LaTeX, and collects the solved values — so a
page can show the analytical method beside the graphical plan it must agree with.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from mechanisms.schema import FRAME, Scene
from solvers.kinematics import Motion
from solvers.loops import DyadLoop, Leg, build_loop
from solvers.structure import Group


@dataclass(frozen=True)
class LoopEquations:
    group: str  # "II(3,4)"
    kind: str  # "RRR", …
    position: str  # LaTeX: the loop
    velocity: str  # LaTeX: equation B
    acceleration: str  # LaTeX: equation C
    unknowns: tuple[str, ...]  # LaTeX symbols: φ₃, s₅₆, …


def _angle(ref: int) -> str:
    return "0" if ref == FRAME else f"\\varphi_{{{ref}}}"


def _direction(leg: Leg) -> tuple[float, str]:
    """|local| and e^{i(φ + α)} of a leg, folding α = 0 and 180° into the sign."""
    length, alpha = abs(leg.local), math.degrees(math.atan2(leg.local.imag, leg.local.real))
    phi = _angle(leg.ref)
    if abs(alpha) < 1e-9:
        return length, f"e^{{i{phi}}}" if leg.ref != FRAME else ""
    if abs(abs(alpha) - 180) < 1e-9:
        return -length, f"e^{{i{phi}}}" if leg.ref != FRAME else ""
    shift = f"{alpha:+.2f}^\\circ"
    return length, f"e^{{i({phi} {shift})}}" if leg.ref != FRAME else f"e^{{i({shift})}}"


def _slide(name: str) -> str:
    return f"s_{{{name.replace('-', '')}}}"


def legs_latex(legs, level: int) -> str:
    """A chain of legs (a loop, or a final contour), differentiated ``level`` times."""
    out = []
    for leg in legs:
        length, e = _direction(leg)
        sign = "-" if length < 0 else "+"
        size = f"{abs(length):.4g}"
        w, eps = f"\\omega_{{{leg.ref}}}", f"\\varepsilon_{{{leg.ref}}}"
        moving = leg.ref != FRAME
        if leg.slide:
            s = _slide(leg.slide)
            body = [s, f"(\\dot {s} + i{w}{s})",
                    f"(\\ddot {s} - {w}^2 {s} + i(2\\dot {s}{w} + {eps}{s}))"][level]
            if not moving:
                body = [s, f"\\dot {s}", f"\\ddot {s}"][level]
            out.append(f"{sign} {body}\\,{e}")
            continue
        if level and not moving:
            continue
        factor = ["", f"i{w}\\,", f"(i{eps} - {w}^2)\\,"][level]
        out.append(f"{sign} {size}\\,{factor}{e}")
    text = " ".join(out) if out else "0"
    return text[2:] if text.startswith("+ ") else text


def equations(scene: Scene, group: Group) -> LoopEquations:
    loop = build_loop(scene, group)
    (m0, c0), (m1, c1) = loop.start, loop.end
    names = []
    for member, local in ((m0, c0), (m1, c1)):
        letter = next(k for k, z in scene.points_of(member).items() if z == local)
        names.append(letter)
    a, b = names
    rhs = [f"\\vec r_{{{b}}} - \\vec r_{{{a}}}", f"\\vec v_{{{b}}} - \\vec v_{{{a}}}",
           f"\\vec a_{{{b}}} - \\vec a_{{{a}}}"]
    texts = [f"{legs_latex(loop.legs, k)} = {rhs[k]}" for k in range(3)]
    unknowns = tuple([f"\\varphi_{{{m}}}" for m in loop.free] + [_slide(p) for p in loop.slides])
    return LoopEquations(group.label(), group.kind, *texts, unknowns)


def solved_values(motion: Motion, i: int = 0) -> list[dict]:
    """The values the loops yield at position ``i``: per member φ, ω, ε; per slide s, ṡ, s̈
    (SI units, angles in degrees)."""
    rows = []
    for n, mm in sorted(motion.members.items()):
        rows.append({"kind": "member", "name": str(n), "position": math.degrees(mm.angle[i]) % 360,
                     "rate": float(mm.omega[i]), "acceleration": float(mm.epsilon[i])})
    for name, s in motion.sliders.items():
        rows.append({"kind": "slide", "name": name, "position": float(s.s[i]),
                     "rate": float(s.v[i]), "acceleration": float(s.a[i])})
    return rows


WORDS = {"or": "or", "chosen": "chosen", "drawn": "the drawn branch",
         "other": "is the other assembly"}  # the page passes its own language's words


def derivation(motion: Motion, group: Group, i: int = 0, words: dict[str, str] = WORDS) -> list[str]:
    """The position equation solved the way the complex-number method writes it, with the
    numbers at position ``i`` (LaTeX lines): the loop projected on x and y, one unknown
    eliminated by squaring and adding (two angles: A·cos φ + B·sin φ = C; an angle and a
    slide: a quadratic in the slide; two slides: a linear system), both roots, and the one
    the mechanism is assembled in, which is the branch the drawing shows."""
    scene = motion.scene
    loop = build_loop(scene, group)
    angle = {m: float(motion.members[m].angle[i]) for m in motion.members}
    angle[FRAME] = 0.0
    (m0, c0), (m1, c1) = loop.start, loop.end
    rhs = _world(motion, m1, c1, i) - _world(motion, m0, c0, i)
    lines = [_projection(loop, "x", rhs.real), _projection(loop, "y", rhs.imag)]
    free, slides = loop.free, loop.slides
    legs = loop.legs
    known = sum(leg.local * cmath.exp(1j * angle[leg.ref]) for leg in legs
                if leg.ref not in free and not leg.slide)
    d = rhs - known  # what the unknown legs must make up
    if len(free) == 2:
        j, k = free
        a_j = sum(leg.local for leg in legs if leg.ref == j and not leg.slide)
        a_k = sum(leg.local for leg in legs if leg.ref == k and not leg.slide)
        w = d * a_k.conjugate()
        c = (abs(d) ** 2 + abs(a_k) ** 2 - abs(a_j) ** 2) / 2
        lines.append(f"{w.real:.5g}\\cos\\varphi_{{{k}}} {w.imag:+.5g}\\sin\\varphi_{{{k}}} = {c:.5g}")
        base, spread = math.atan2(w.imag, w.real), math.acos(max(-1.0, min(1.0, c / abs(w))))
        roots = [math.degrees(base + r * spread) % 360 for r in (1, -1)]
        lines += _roots(f"\\varphi_{{{k}}}", roots, math.degrees(angle[k]) % 360, "°", words)
        return lines
    if len(free) == 1 and len(slides) == 1:
        (j,), slide_leg = free, next(leg for leg in legs if leg.slide)
        a = sum(leg.local for leg in legs if leg.ref == j and not leg.slide)
        s = _slide(slide_leg.slide)
        if slide_leg.ref == j:  # the slide turns with the unknown angle: |a + s·u| = |d|
            u = slide_leg.local
            b, c = 2 * (a * u.conjugate()).real, abs(a) ** 2 - abs(d) ** 2
            lines.append(f"|{_c(a)} + {s}\\,{_c(u)}|^2 = |{_c(d)}|^2")
        else:  # the slide's direction is known: |a| = |d − s·v|
            v = slide_leg.local * cmath.exp(1j * angle[slide_leg.ref])
            b, c = -2 * (d * v.conjugate()).real, abs(d) ** 2 - abs(a) ** 2
            lines.append(f"|{_c(d)} - {s}\\,{_c(v)}|^2 = {abs(a):.5g}^2")
        lines.append(f"{s}^2 {b:+.5g}\\,{s} {c:+.5g} = 0")
        disc = b * b - 4 * c
        roots = [(-b + r * math.sqrt(max(disc, 0.0))) / 2 for r in (1, -1)]
        lines += _roots(s, roots, float(motion.sliders[slide_leg.slide].s[i]), "m", words)
        return lines
    # two slides: s₁·v₁ + s₂·v₂ = d, solved by Cramer's rule
    v1, v2 = (leg.local * cmath.exp(1j * angle[leg.ref]) for leg in legs if leg.slide)
    det = (v1.conjugate() * v2).imag
    s1, s2 = (_slide(name) for name in slides)
    lines.append(f"{s1} = \\frac{{d \\times v_2}}{{v_1 \\times v_2}} = {(d.conjugate() * v2).imag / det:.5g}"
                 f",\\quad {s2} = \\frac{{v_1 \\times d}}{{v_1 \\times v_2}} = {(v1.conjugate() * d).imag / det:.5g}")
    return lines


def _world(motion: Motion, member: int, local: complex, i: int) -> complex:
    """Where a member's point is at position i (the loop's start and end points)."""
    scene = motion.scene
    name = next(k for k, z in scene.points_of(member).items() if z == local)
    return complex(motion.points[name].z[i])


def _projection(loop: DyadLoop, axis: str, value: float) -> str:
    trig = "\\cos" if axis == "x" else "\\sin"
    out = []
    for leg in loop.legs:
        length, alpha = abs(leg.local), math.degrees(cmath.phase(leg.local))
        phi = _angle(leg.ref) if leg.ref != FRAME else ""
        arg = (f"{phi} {alpha:+.2f}^\\circ" if abs(alpha) > 1e-9 else phi) if phi else f"{alpha:.2f}^\\circ"
        factor = f"{_slide(leg.slide)}\\," if leg.slide else f"{length:.4g}\\,"
        if leg.slide and abs(length - 1) > 1e-12:
            factor = f"{length:.4g}{_slide(leg.slide)}\\,"
        out.append(f"{factor}{trig}({arg})")
    return f"{axis}:\\ " + " + ".join(out) + f" = {value:.5g}"


def _c(z: complex) -> str:
    return f"({z.real:.4g} {z.imag:+.4g}i)"


def _roots(symbol: str, roots: list[float], chosen: float, unit: str, words: dict) -> list[str]:
    """Both roots, and which one the mechanism takes (the other is the mirror assembly)."""
    near = min(range(2), key=lambda r: abs(_wrap(roots[r] - chosen, unit)))
    other = 1 - near
    return [f"{symbol} = {roots[0]:.5g}\\,\\text{{{unit}}}\\ \\text{{{words['or']}}}\\ "
            f"{roots[1]:.5g}\\,\\text{{{unit}}}",
            f"\\text{{{words['chosen']}: }}{symbol} = {roots[near]:.5g}\\,\\text{{{unit}}}"
            f"\\ (\\text{{{words['drawn']}; }}{roots[other]:.5g}\\,\\text{{{unit} {words['other']}}})"]


def _wrap(x: float, unit: str) -> float:
    return (x + 180) % 360 - 180 if unit == "°" else x
