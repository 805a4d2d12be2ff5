"""Degrees of freedom and Assur decomposition, and the explanations when it fails."""

import pytest

from mechanisms import load_preset, parse_scene
from solvers import StructureError, decompose, solve

from .test_loader import fourbar_text

EXPECTED = {
    "analitika-2.1": ("I(1,2) → II(3,4) → II(5,6)", ["RRR", "RPR"]),
    "analitika-2.2": ("I(1,2) → II(3,4) → II(5,6)", ["RPR", "RRP"]),
    "four-bar-crank-rocker": ("I(1,2) → II(3,4)", ["RRR"]),
    "slider-crank": ("I(1,2) → II(3,4)", ["RRP"]),
    "scotch-yoke": ("I(1,2) → II(3,4)", ["RPP"]),
    "tangent-slotted-crank": ("I(1,2) → II(3,4)", ["PRP"]),
}


@pytest.mark.parametrize("pid", sorted(EXPECTED))
def test_presets_decompose_into_the_expected_groups(pid):
    st = decompose(load_preset(pid))
    formula, kinds = EXPECTED[pid]
    assert st.dof == 1 and st.formula == formula
    assert [g.kind for g in st.groups] == kinds


def test_dof_counts_members_and_pairs():
    st = decompose(load_preset("analitika-2.1"))
    assert (st.moving_members, st.lower_pairs, st.higher_pairs) == (5, 7, 0)
    assert st.dof == 3 * 5 - 2 * 7


def test_an_extra_link_makes_a_structure_that_cannot_move():
    text = fourbar_text().replace('[members.4]', '[members.5]\npoints = ["A", "D"]\nlength = 0.38\n\n[members.4]')
    text = text.replace('pairs = [', 'pairs = [\n  { type = "revolute", members = [5, 2], point = "A" },\n'
                                     '  { type = "revolute", members = [5, 1], point = "D" },')
    with pytest.raises(StructureError, match=r"W = 3·4 − 2·6 = 0.*over-constrained"):
        decompose(parse_scene(text))


def test_a_dangling_member_is_named():
    text = fourbar_text().replace('{ type = "revolute", members = [4, 1], point = "D" },', "")
    text = text.replace('points = ["D", "B"]', 'points = ["Q", "B"]')
    with pytest.raises(StructureError, match=r"W = 3·3 − 2·3 = 3.*Member\(s\) 4 are joined by a single pair"):
        decompose(parse_scene(text))


TRIAD = """
pairs = [
  { type = "revolute", members = [1, 2], point = "O" },
  { type = "revolute", members = [2, 3], point = "A" },
  { type = "revolute", members = [3, 4], point = "B" },
  { type = "revolute", members = [4, 5], point = "C" },
  { type = "revolute", members = [4, 6], point = "E" },
  { type = "revolute", members = [5, 1], point = "F" },
  { type = "revolute", members = [6, 1], point = "G" },
]
[frame]
O = [0.0, 0.0]
F = [0.5, 0.3]
G = [0.6, -0.2]
[driver]
type = "rotating"
omega = 5.0
[members.2]
points = ["O", "A"]
length = 0.1
[members.3]
points = ["A", "B"]
length = 0.4
[members.4]
points = ["B", "C"]
length = 0.3
extra = { E = [0.1, -0.2] }
[members.5]
points = ["F", "C"]
length = 0.25
[members.6]
points = ["G", "E"]
length = 0.3
"""


def test_a_class_three_group_is_recognised_and_assembled_without_a_sketch():
    scene = parse_scene(TRIAD)  # no [guess]: Newton's first converged start is taken
    st = decompose(scene)
    assert [(g.cls, g.members[0], sorted(g.members)) for g in st.groups] == [(3, 4, [3, 4, 5, 6])]
    assert st.formula == "I(1,2) → III(3,4,5,6)"
    m = solve(scene)
    assert m.feasible.all()
    assert abs(m.points["C"].z[0] - scene.frame["F"]) == pytest.approx(0.25, abs=1e-9)
    assert abs(m.points["E"].z[0] - scene.frame["G"]) == pytest.approx(0.3, abs=1e-9)
