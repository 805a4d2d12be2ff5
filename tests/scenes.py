"""Scene text for tests: small TOML builders for every dyad kind (random geometry from hypothesis)."""

from __future__ import annotations

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
