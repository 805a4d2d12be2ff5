"""A gear train by hand, one unknown speed per equation (methods.gear_steps), against the
linear system of solvers.gears."""

import math

import pytest

from mechanisms import load_preset, parse_document, preset_ids
from methods.gear_steps import speed_steps, stage_latex, total_ratio
from solvers.gears import solve_train, stages


@pytest.mark.parametrize("pid", preset_ids("gears"))
def test_the_hand_order_reaches_every_member_with_the_systems_speeds(pid):
    """Every train of the collection is solved with the book's kinds of equation (no member
    left to the linear system), and each speed carried through them is the system's."""
    solution = solve_train(load_preset(pid))
    steps = speed_steps(solution)
    assert sorted(s.member for s in steps) == sorted(solution.omega)
    assert not [s for s in steps if s.kind == "system"]
    for s in steps:
        assert s.omega == pytest.approx(solution.omega[s.member], rel=1e-12, abs=1e-12)
        assert s.latex.count(r"\begin{gathered}") == s.latex.count(r"\end{gathered}")


def test_a_member_at_rest_reads_zero_in_its_equation():
    """Task 6.4: seen from carrier 4, gear 3 comes out at round-off size; it is written as
    0 inside the equation, which stays whole."""
    by = {s.member: s for s in speed_steps(solve_train(load_preset("zbirka-6.4")))}
    assert by[3].omega == 0.0 and by[3].latex.endswith(r"= 0\end{gathered}")


def test_task_6_1_follows_the_books_order():
    """Task 6.1's analytic solution: ω6 = ω2 (one body), the fixed-axes chain 7, 8, 9, 10 gear
    by gear, then carrier 2's stage gives the sun 5, 13 turns with 5, carrier 13's stage gives
    12, and the planets 3 and 11 come last."""
    steps = speed_steps(solve_train(load_preset("zbirka-6.1")))
    assert [(s.member, s.kind) for s in steps] == [
        (2, "input"), (4, "fixed"), (6, "shaft"), (7, "mesh"), (8, "shaft"), (9, "mesh"),
        (10, "mesh"), (5, "stage"), (13, "shaft"), (12, "stage"), (3, "mesh"), (11, "mesh")]
    by = {s.member: s for s in steps}
    assert by[2].latex == r"\omega_{2} = \frac{v}{R} = \frac{1}{0.41} = 2.439"
    assert by[5].carrier == 2 and r"i^{2}_{4,5}" in by[5].latex
    assert by[12].carrier == 13 and by[12].latex.endswith(f"= {by[12].omega:.5g}\\end{{gathered}}")
    omega = {s.member: s.omega for s in steps}
    assert total_ratio(steps, 6, 12).endswith(f"= {omega[6] / omega[12]:.5g}")
    assert total_ratio(steps, 2, 4) is None  # member 4 stands still: no finite ratio


def test_a_differential_driving_straight_turns_its_side_gears_with_the_case():
    """Task 6.10: the side gears 9 and 11 share a shaft, so carrier 3's stage
    (ω9 − ω3)/(ω11 − ω3) = −1 can only hold with ω9 = ω3; the stage's ratio stays the radii's
    −1 (the shaft is no path between the central gears), and 0/0 is not printed as a ratio."""
    solution = solve_train(load_preset("zbirka-6.10"))
    by = {s.member: s for s in speed_steps(solution)}
    assert by[9].kind == "stage" and by[9].omega == pytest.approx(solution.omega[3], rel=1e-12)
    stage = next(s for s in stages(solution) if s.carrier == 3)
    assert stage.ratio == pytest.approx(-1.0) and math.isnan(stage.solved)
    assert "nan" not in stage_latex(stage)
    assert r"\text{iz poluprečnika: } {-1}" in stage_latex(stage, "iz poluprečnika")


def test_stages_that_need_each_other_are_solved_together():
    """Two coupled stages (ring 3 = carrier 6, carrier 5 = ring 7, sun 8 fixed, sun 2
    driven): each stage's equation has two unknowns, so no single equation starts the chain
    and the rest comes from the linear system, still equal to it."""
    train = parse_document("""
kind = "gears"
meshes = [ { members = [2, 4], radii = [0.05, 0.05] },
           { members = [4, 3], radii = [0.05, 0.15], internal = 3 },
           { members = [8, 9], radii = [0.05, 0.05] },
           { members = [9, 7], radii = [0.05, 0.15], internal = 7 } ]
shafts = [[3, 6], [5, 7]]
fixed = [8]
inputs = [ { member = 2, omega = 10.0 } ]
[members.2]
[members.3]
[members.4]
carrier = 5
axis = 0.1
[members.5]
[members.6]
[members.7]
[members.8]
[members.9]
carrier = 6
axis = 0.1
""")
    solution = solve_train(train)
    assert solution.status == "solved"
    steps = speed_steps(solution)
    assert {s.kind for s in steps} >= {"input", "fixed", "system"}
    for s in steps:
        assert s.omega == pytest.approx(solution.omega[s.member], rel=1e-12, abs=1e-12)
