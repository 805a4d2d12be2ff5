"""Scene text for tests: small TOML builders for every dyad kind (random geometry from hypothesis)."""

from __future__ import annotations

import cmath
import math

from mechanisms import parse_scene


def fourbar(r2=0.1, r3=0.35, r4=0.3, dx=0.4, dy=0.0, omega=10.0, branch=1, ex=0.15, ey=0.1):
    """RRR: crank OA, coupler AB with point E, rocker DB."""
    return parse_scene(f"""
pairs = [
  {{ type = "revolute", members = [1, 2], point = "O" }},
  {{ type = "revolute", members = [2, 3], point = "A" }},
  {{ type = "revolute", members = [3, 4], point = "B" }},
  {{ type = "revolute", members = [4, 1], point = "D" }},
]
[frame]
O = [0.0, 0.0]
D = [{dx}, {dy}]
[driver]
type = "rotating"
omega = {omega}
[members.2]
points = ["O", "A"]
length = {r2}
[members.3]
points = ["A", "B"]
length = {r3}
extra = {{ E = [{ex}, {ey}] }}
[members.4]
points = ["D", "B"]
length = {r4}
[assembly]
"3-4" = {branch}
""")


def slider_crank(r2=0.1, r3=0.35, offset=0.02, guide_deg=10.0, omega=10.0, branch=1):
    """RRP: crank OA, rod AB, slider B on a frame guide through G at an angle."""
    return parse_scene(f"""
pairs = [
  {{ type = "revolute", members = [1, 2], point = "O" }},
  {{ type = "revolute", members = [2, 3], point = "A" }},
  {{ type = "revolute", members = [3, 4], point = "B" }},
  {{ type = "prismatic", guide = 1, slider = 4, point = "B", through = "G", angle = {guide_deg} }},
]
[frame]
O = [0.0, 0.0]
G = [-0.5, {offset}]
[driver]
type = "rotating"
omega = {omega}
[members.2]
points = ["O", "A"]
length = {r2}
[members.3]
points = ["A", "B"]
length = {r3}
extra = {{ E = [0.1, 0.05] }}
[members.4]
points = ["B", "K"]
length = 0.05
[assembly]
"3-4" = {branch}
""")


def rocking_guide(r2=0.1, px=0.3, py=0.05, lock_deg=0.0, omega=10.0, branch=1):
    """RPR: crank OA, block 3 on pin A sliding along rod 4, which turns about P."""
    return parse_scene(f"""
pairs = [
  {{ type = "revolute", members = [1, 2], point = "O" }},
  {{ type = "revolute", members = [2, 3], point = "A" }},
  {{ type = "prismatic", guide = 4, slider = 3, point = "A", through = "P", slider_angle = {lock_deg} }},
  {{ type = "revolute", members = [4, 1], point = "P" }},
]
[frame]
O = [0.0, 0.0]
P = [{px}, {py}]
[driver]
type = "rotating"
omega = {omega}
[members.2]
points = ["O", "A"]
length = {r2}
[members.3]
points = ["A"]
[members.4]
points = ["P", "T"]
length = 0.6
extra = {{ E = [0.2, 0.04] }}
[assembly]
"3-4" = {branch}
""")


def slotted_crank(r2=0.5, gx=0.2, gy=0.0, column_deg=90.0, omega=2.0):
    """PRP: block 3 in the crank's slot, pinned at B to slider 4 on a fixed column."""
    return parse_scene(f"""
pairs = [
  {{ type = "revolute", members = [1, 2], point = "O" }},
  {{ type = "prismatic", guide = 2, slider = 3, point = "B", through = "O" }},
  {{ type = "revolute", members = [3, 4], point = "B" }},
  {{ type = "prismatic", guide = 1, slider = 4, point = "B", through = "G", angle = {column_deg} }},
]
[frame]
O = [0.0, 0.0]
G = [{gx}, {gy}]
[driver]
type = "rotating"
omega = {omega}
[members.2]
points = ["O", "K"]
length = {r2}
[members.3]
points = ["B"]
[members.4]
points = ["B", "W"]
length = 0.05
""")


def scotch_yoke(r2=0.12, slot_deg=90.0, rail_deg=0.0, rail_y=0.0, omega=10.0):
    """RPP: block 3 on pin A in the slot of yoke 4, the yoke sliding on a frame rail."""
    return parse_scene(f"""
pairs = [
  {{ type = "revolute", members = [1, 2], point = "O" }},
  {{ type = "revolute", members = [2, 3], point = "A" }},
  {{ type = "prismatic", guide = 4, slider = 3, point = "A", through = "Y", angle = {slot_deg} }},
  {{ type = "prismatic", guide = 1, slider = 4, point = "Y", through = "R", angle = {rail_deg} }},
]
[frame]
O = [0.0, 0.0]
R = [-0.3, {rail_y}]
[driver]
type = "rotating"
omega = {omega}
[members.2]
points = ["O", "A"]
length = {r2}
[members.3]
points = ["A"]
[members.4]
points = ["Y", "Q"]
length = 0.25
""")


# --- oversized scenes (tests/test_hostile.py, bench/hostile.py): TOML text, not parsed ---

def chain(n: int, pinned: bool = False) -> str:
    """A linkage of ``n`` moving members: a crank, then members each pinned to the one before
    and to the frame (``pinned``: every member pinned to the frame only)."""
    out = ['pairs = [', '  { type = "revolute", members = [1, 2], point = "P0" },']
    for k in range(3, n + 2):
        if not pinned:
            out.append(f'  {{ type = "revolute", members = [{k - 1}, {k}], point = "Q{k}" }},')
        out.append(f'  {{ type = "revolute", members = [{k}, 1], point = "P{k}" }},')
    out += [']', '[frame]', 'P0 = [0.0, 0.0]']
    out += [f"P{k} = [{k * 0.1}, 0.5]" for k in range(3, n + 2)]
    out += ['[driver]', 'type = "rotating"', 'omega = 1.0', '[members.2]',
            'points = ["P0", "Q3"]' if not pinned else 'points = ["P0", "A"]', 'length = 0.1']
    for k in range(3, n + 2):
        ends = f'["Q{k}", "P{k}"]' if not pinned else f'["P{k}", "X{k}"]'
        extra = f'\nextra = {{ Q{k + 1} = [0.05, 0.01] }}' if not pinned and k < n + 1 else ""
        out += [f"[members.{k}]", f"points = {ends}", f"length = 0.2{extra}"]
    return "\n".join(out)


def train(n: int) -> str:
    out = ['kind = "gears"', "meshes = ["]
    out += [f"  {{ members = [{k}, {k + 1}], radii = [0.01, 0.02] }}," for k in range(1, n)]
    out += ["]", "fixed = []", "inputs = [ { member = 1, omega = 10.0 } ]"]
    out += [f"[members.{k}]\naxis = {0.03 * k}" for k in range(1, n + 1)]
    return "\n".join(out)


def rotor(n: int) -> str:
    out = ['kind = "rotor"', "[planes]", "I = 0.5", "II = 0.0"]
    out += ["[[masses]]\nmass = 0.1\nradius = 0.1\nangle = 30\nx = 0.2"] * n
    out += ["[corrections.I]", "radius = 0.2", "[corrections.II]", "radius = 0.2"]
    return "\n".join(out)


def dyads(count: int) -> str:
    """A crank and ``count`` dyads in series, each hung on the rocker of the one before,
    laid out where it closes (the drawn places go to [guess]): 1 + 2·count moving members."""
    a = 0.1 * cmath.exp(1j * math.pi / 3)
    out = ['pairs = [', '  { type = "revolute", members = [1, 2], point = "O" },']
    frame, members, guess, hang, on = ["O = [0.0, 0.0]"], ['[members.2]\npoints = ["O", "P1"]\n'
                                                            'length = 0.1'], [], a, 2
    for d in range(1, count + 1):
        j, k = 2 * d + 1, 2 * d + 2
        c = hang + 0.3 + 0.2j
        f = c + 0.1 - 0.25j
        u = (c - f) / abs(c - f)
        nxt = f + (0.15 + 0.05j) * u
        out += [f'  {{ type = "revolute", members = [{on}, {j}], point = "P{d}" }},',
                f'  {{ type = "revolute", members = [{j}, {k}], point = "C{d}" }},',
                f'  {{ type = "revolute", members = [{k}, 1], point = "F{d}" }},']
        frame.append(f"F{d} = [{f.real!r}, {f.imag!r}]")
        members += [f'[members.{j}]\npoints = ["P{d}", "C{d}"]\nlength = {abs(c - hang)!r}',
                    f'[members.{k}]\npoints = ["F{d}", "C{d}"]\nlength = {abs(c - f)!r}'
                    + (f"\nextra = {{ P{d + 1} = [0.15, 0.05] }}" if d < count else "")]
        guess.append(f"C{d} = [{c.real!r}, {c.imag!r}]")
        hang, on = nxt, k
    out += ["]", "[frame]", *frame, "[driver]", 'type = "rotating"', "at = 60.0", "omega = 10.0",
            *members, "[guess]", *guess]
    return "\n".join(out)


def largest_allowed() -> str:
    """19 moving members, 28 pairs (W = 1 needs an odd count: 20 members would not move)."""
    return dyads(9)
