"""The complex-number (vector-loop) method written out as the course writes it.

For every Assur group the kinematics core closes one vector loop (``loops.build_loop``).
This module states that loop, its first and second derivatives (the course's equations
B and C) and the unknowns each yields, as LaTeX, and collects the solved values — so a
page can show the analytical method beside the graphical plan it must agree with.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from mechanisms.schema import FRAME, Scene

from .kinematics import Motion
from .loops import DyadLoop, Leg, build_loop
from .structure import Group


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


def _terms(loop: DyadLoop, level: int) -> str:
    """The legs of the loop, differentiated ``level`` times."""
    out = []
    for leg in loop.legs:
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
    texts = [f"{_terms(loop, k)} = {rhs[k]}" for k in range(3)]
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
