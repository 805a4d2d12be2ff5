"""Gear trains: hand-derived trains, the book's tasks, scaling, and the degenerate cases."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mechanisms import load_preset, parse_document, preset_ids
from mechanisms.gears import GearTrain, Input, Mesh
from methods.gear_steps import stage_latex
from solvers.gears import TrainError, solve_train


def epicyclic(sun=0.05, ring=0.15, omega=10.0, fixed=(4,)) -> GearTrain:
    planet = (ring - sun) / 2
    return parse_document(f"""
kind = "gears"
meshes = [ {{ members = [2, 3], radii = [{sun}, {planet}] }},
           {{ members = [3, 4], radii = [{planet}, {ring}], internal = 4 }} ]
fixed = {list(fixed)}
inputs = [ {{ member = 2, omega = {omega} }} ]
[members.2]
[members.3]
carrier = 5
axis = {sun + planet}
[members.4]
[members.5]
""")


def test_sun_driven_epicyclic_with_a_fixed_ring():
    """ω_carrier = ω_sun·R_sun/(R_sun + R_ring), written out by hand."""
    solution = solve_train(epicyclic(0.05, 0.15, 10.0))
    assert solution.status == "solved" and solution.dof == 1
    assert solution.omega[5] == pytest.approx(10.0 * 0.05 / (0.05 + 0.15))
    # the planet: seen from the carrier, sun and planet roll like fixed-axis gears
    assert solution.omega[3] - solution.omega[5] == pytest.approx(-(10.0 - 2.5) * 0.05 / 0.05)


def test_a_differential_with_equal_side_gears_averages_them():
    """ω_case = (ω_L + ω_R)/2 for the plane equivalent of a bevel differential."""
    train = load_preset("zbirka-6.10")
    turning = train.with_(shafts=(), inputs=(Input(9, 12.0), Input(11, 8.0)))
    solution = solve_train(turning)
    assert solution.status == "solved" and solution.dof == 2
    assert solution.omega[3] == pytest.approx((12.0 + 8.0) / 2)


@settings(max_examples=60, deadline=None)
@given(st.floats(0.01, 1.0), st.floats(1.2, 10.0), st.floats(-100, 100), st.floats(1e-3, 1e3))
def test_ratios_do_not_change_when_every_radius_is_scaled(sun, factor, omega, k):
    train = epicyclic(sun, sun * factor, omega)
    scaled = train.with_(meshes=tuple(Mesh(m.members, (k * m.radii[0], k * m.radii[1]), m.internal)
                                      for m in train.meshes))
    a, b = solve_train(train), solve_train(scaled)
    for member in (3, 5):
        assert b.omega[member] == pytest.approx(a.omega[member], rel=1e-9, abs=1e-9)


def test_a_planet_that_only_translates_has_an_infinite_ratio():
    solution = solve_train(load_preset("zbirka-6.4"))
    assert solution.omega[3] == 0.0
    assert solution.ratio(4, 3) == math.inf
    assert solution.omega[2] == pytest.approx(22.5)  # (0 − 10)/(ω₂ − 10) = −0.16/0.2


def test_a_ratio_of_exactly_one_and_a_carrier_driven_train():
    assert solve_train(load_preset("zbirka-6.8")).ratio(2, 3) == pytest.approx(1.0, abs=1e-12)  # one body
    fixed_sun = epicyclic(0.05, 0.15, 10.0).with_(inputs=(Input(5, 7.0),), fixed=(2,))
    assert solve_train(fixed_sun).omega[4] == pytest.approx(7.0 * (0.05 + 0.15) / 0.15)


def test_huge_tooth_ratios_stay_exact():
    train = epicyclic(1e-3, 1e3, 1.0)
    assert solve_train(train).omega[5] == pytest.approx(1e-3 / (1e-3 + 1e3), rel=1e-9)


def test_a_missing_input_names_the_undetermined_members():
    solution = solve_train(epicyclic().with_(inputs=()))
    assert solution.status == "under" and set(solution.undetermined) == {2, 3, 5}
    assert "1 degree(s) of freedom but 0 input(s)" in str(solution.message)


def test_contradicting_inputs_are_said_to_be_so():
    train = epicyclic().with_(inputs=(Input(2, 10.0), Input(5, 3.0)))
    solution = solve_train(train)
    assert solution.status == "over" and "contradict" in str(solution.message)


def test_a_mesh_between_planets_of_different_carriers_is_refused():
    train = epicyclic()
    members = dict(train.members)
    members[6] = members[3].__class__(6, carrier=2, axis=0.1)
    bad = train.with_(members=members, meshes=train.meshes + (Mesh((3, 6), (0.05, 0.05)),))
    with pytest.raises(TrainError, match="different carriers"):
        solve_train(bad)


@pytest.mark.parametrize("pid", preset_ids("gears"))
def test_every_book_train_solves_and_matches_the_book_within_its_rounding(pid):
    train = load_preset(pid)
    solution = solve_train(train)
    assert solution.status == "solved"
    assert solution.dof == len(train.inputs)
    for key, printed in train.book.items():
        if key.startswith("members."):
            exact = solution.omega[int(key.split(".")[1])]
            if key in train.book_notes:
                continue
            assert exact == pytest.approx(printed, rel=0.03, abs=0.05), key


def test_an_input_on_a_fixed_member_is_refused():
    from mechanisms import SceneError

    with pytest.raises(SceneError, match="fixed: it cannot be driven"):
        parse_document('kind = "gears"\nfixed = [2]\ninputs = [ { member = 2, omega = 1.0 } ]\n'
                       "[members.2]\n")


def test_radii_that_do_not_fit_the_axes_are_pointed_out():
    from solvers.gears import geometry_notes

    assert all(not geometry_notes(load_preset(pid)) for pid in preset_ids("gears"))
    train = epicyclic(0.05, 0.15)
    wrong = train.with_(meshes=(Mesh((2, 3), (0.08, 0.05)),) + train.meshes[1:])
    (note,) = geometry_notes(wrong)
    assert "mesh 2–3" in str(note) and "0.13" in str(note)


@pytest.mark.parametrize("pid", preset_ids("gears"))
def test_every_willis_relation_holds_for_the_solved_speeds(pid):
    from solvers.gears import willis_table

    solution = solve_train(load_preset(pid))
    for w in willis_table(solution.train):
        solved = w.check(solution.omega)
        if not math.isnan(solved):
            assert solved == pytest.approx(w.ratio, rel=1e-9), (w.a, w.b)


def test_task_6_1_stage_by_stage_gives_each_carriers_willis_ratio_from_the_radii():
    """The book's stages: seen from carrier 2, ring 4 to sun 5 is −R5/R4; seen from carrier
    13, ring 10 to sun 12 is −R12/R10; the fixed-axes chain 6…10 is R7/R6·(−R9/R8)·(−R10/R9)
    with 7 and 8 on one shaft. Each equals the same ratio from the solved speeds."""
    from solvers.gears import stages

    solution = solve_train(load_preset("zbirka-6.1"))
    found = {s.carrier: s for s in stages(solution)}
    assert found[2].ends == (4, 5) and found[2].ratio == pytest.approx(-0.18 / 0.64)
    assert found[13].ends == (10, 12) and found[13].ratio == pytest.approx(-0.14 / 0.5)
    assert found[None].ends == (6, 10)
    assert found[None].ratio == pytest.approx(0.135 / 1.01 * (-0.094 / 0.09) * (-0.6 / 0.094))
    for stage in found.values():
        assert stage.solved == pytest.approx(stage.ratio, rel=1e-9)
        c = 0.0 if stage.carrier is None else solution.omega[stage.carrier]
        assert stage.relative == {m: pytest.approx(solution.omega[m] - c) for m in stage.members}
    assert r"i^{2}_{4,5}" in stage_latex(found[2]) and "-0.28125" in stage_latex(found[2])
