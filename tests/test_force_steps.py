"""Kinetostatics step by step (issue 23, item 3): the book's equations one at a time end in the
batched solver's reactions and driving torque, in the book's order."""

from __future__ import annotations

import numpy as np
import pytest

from mechanisms import load_preset
from mechanisms.loader import preset_ids
from mechanisms.schema import Force
from methods.force_steps import _Body, _together, equation, steps
from methods.lever_steps import construction as lever_construction, latex as lever_latex
from solvers.kinetostatics import analyse

from .test_kinetostatics import loaded


def with_masses(pid: str):
    """A preset with a mass on every member (and its own loads): inertia and weights
    everywhere, so that every pair carries a reaction."""
    scene = load_preset(pid)
    return loaded(scene, {n: 1.0 + 0.3 * n for n in scene.members}, rho=0.04,
                  forces=scene.forces, moments=scene.moments)


def assert_same(k, construction):
    driving = float(k.driving.reshape(-1)[0])
    assert construction.driving == pytest.approx(driving, rel=1e-9, abs=1e-9)
    for key, r in k.reactions.items():
        force, _, couple = construction.reactions[key]
        exact = complex(r.force.reshape(-1)[0])
        assert abs(force - exact) <= 1e-9 * max(1.0, abs(exact)), key
        assert couple == pytest.approx(float(np.reshape(r.couple, -1)[0]), rel=1e-9, abs=1e-9)


@pytest.mark.parametrize("pid", preset_ids("linkage"))
def test_the_last_step_equals_the_solver_on_every_preset(pid):
    """Every reaction F_pq (and a guide's couple) and M_p or F_p, on every linkage preset
    with masses on all its members: dyads of all five kinds, triads, linear drivers."""
    k = analyse(with_masses(pid))
    construction = steps(k)
    assert_same(k, construction)
    assert all(s.kind != "together" for s in construction.steps)  # each step is the book's kind


def test_a_four_bar_goes_as_the_book_does():
    """RRR: the moments about the inner joint give both tangential parts, the group's polygon
    closes with the two normals, a member's polygon gives the inner reaction; then member 2."""
    k = analyse(with_masses("four-bar-crank-rocker"))
    construction = steps(k)
    kinds = [(s.kind, sorted(s.found)) for s in construction.steps]
    assert kinds == [("moment", ["F_23^t"]), ("moment", ["F_14^t"]),
                     ("polygon", ["F_14^n", "F_23^n"]), ("polygon", ["F_34"]),
                     ("moment", ["M_p"]), ("polygon", ["F_12"])]
    first = construction.steps[0]
    crank_pin = next(p.point for p in k.motion.scene.pairs if set(p.members) == {2, 3})
    outer = complex(k.motion.points[crank_pin].z[0])
    inner = complex(k.motion.points[first.about].z[0])
    assert first.at == inner and first.about != crank_pin
    assert abs(first.terms[-1].moment) == pytest.approx(abs(inner - outer))  # F_23^t's arm


def test_a_moment_equation_adds_up_to_zero_and_its_polygon_closes():
    """The numbers shown: Σ of the known moments plus the found one is zero; the polygon's
    sides (known, then closing) add up to nothing."""
    k = analyse(with_masses("zbirka-5.1"))
    for step in steps(k).steps:
        if step.kind == "moment":
            total = sum(t.moment * (1.0 if not t.unknown else 0.0) for t in step.terms)
            found = [t for t in step.terms if t.unknown]
            value = sum(t.moment * step.found[t.name][0] for t in found) if len(found) == 1 else 0
            if len(found) == 1:
                assert abs(total + value) < 1e-9 * max(1.0, abs(total))
        elif step.kind == "polygon":
            sides = [t.force for t in step.terms] + [f for _, f in step.closing]
            assert abs(sum(sides)) < 1e-9 * max(abs(f) for f in sides)


def test_a_class_iii_group_is_closed_through_its_assur_point():
    """Three normals are too many for one polygon: the moment of the whole group about S,
    where two of their lines meet, holds the third alone."""
    k = analyse(with_masses("triad-full-turn"))
    special = [s for s in steps(k).steps if s.about == "S"]
    assert len(special) == 1 and len(special[0].members) == 4
    lines = [t for t in special[0].terms if not t.unknown and t.name.endswith("^n")]
    assert not lines  # the normals met at S: none is known yet, none enters with an arm
    group = next(g for g in k.motion.structure.groups if g.cls == 3)
    assert set(special[0].members) == set(group.members)


def test_a_block_on_a_guide_is_found_from_two_moment_equations():
    """RPR: the force across the guide and its couple F·h from the block's moment about its
    pin and the guide's moment about its pivot, as task 5.2 finds F_34."""
    k = analyse(with_masses("zbirka-3.1"))
    first, second = steps(k).steps[:2]
    assert first.kind == second.kind == "moment" and not first.found
    assert sorted(second.found) == ["F_34", "F_34·h_34"]
    assert second.found["F_34·h_34"][1] == "N·m" and second.found["F_34"][1] == "N"


def test_a_linear_driver_ends_with_its_driving_force():
    scene = loaded(load_preset("analitika-2.2"), {3: 1.0, 4: 0.8, 6: 0.5},
                   forces=[Force(6, "M", 25.0, 0.5)])
    k = analyse(scene)
    construction = steps(k)
    assert_same(k, construction)
    assert "F_p" in construction.steps[-1].found or any("F_p" in s.found for s in construction.steps)


def test_solving_a_body_all_at_once_gives_the_same_reactions():
    """The fallback when no equation with one or two unknowns is left."""
    k = analyse(with_masses("four-bar-crank-rocker"))
    group = k.motion.structure.groups[0]
    body = _Body(k, 0, group.name, group.members, group.pairs, {})
    step = _together(body)
    assert step.kind == "together" and len(body.values) == len(body.unknowns)
    body.record()
    for (p, q), (force, _, _) in body.known.items():
        if (p, q) in k.reactions and {p, q} <= set(group.members):
            assert abs(force - complex(k.reactions[(p, q)].force[0])) < 1e-9 * abs(force)


def test_the_equations_read_as_latex_with_their_results():
    k = analyse(load_preset("zbirka-5.1"))
    step = steps(k).steps[0]
    symbols, numbers = equation(step)
    assert symbols.startswith(r"\sum M_{F}^{(5)}") and r"F_{45}^{t}\cdot h" in symbols
    value, unit = step.found["F_45^t"]
    assert numbers.endswith(rf"F_{{45}}^{{t}} = {value:.4g}\ \mathrm{{N}}")
    assert numbers.startswith("70")  # G_5 = 70 N (task 5.1), times its signed arm


@pytest.mark.parametrize("pid", preset_ids("linkage"))
def test_the_reduced_mechanism_the_books_way_gives_the_solvers_driving_torque(pid):
    """F_p at the crank pin's image from the moments about the pole, M_p = F_p·AB: equal to the
    group-by-group M_p (F_p itself for a linear driver) on every preset with masses."""
    k = analyse(with_masses(pid))
    lever = lever_construction(k)
    exact = float(k.driving[0])
    found = lever.torque if k.rotating else lever.balancing
    assert found == pytest.approx(exact, rel=1e-9, abs=1e-9 * max(1.0, abs(lever.balancing)))
    for image in lever.images:  # the image of a member is similar to the member
        ratio = image.side[1] / image.side[0]
        assert image.plan[0] == pytest.approx(image.real[0] * ratio, rel=1e-9, abs=1e-12)
        assert image.plan[1] == pytest.approx(image.real[1] * ratio, rel=1e-9, abs=1e-12)


def test_the_lever_places_s_and_k_by_proportion_along_the_member():
    """Task 5.3's members 3 and 6: S and K lie on the member's axis, so one proportion each
    (b⁰k⁰ = b⁰c⁰·BK/BC), and BK = BS + ρ²/BS."""
    k = analyse(load_preset("zbirka-5.3"))
    lever = lever_construction(k)
    placed = {im.point: im for im in lever.images}
    assert {"S_3", "K_3"} <= set(placed) and placed["K_3"].along
    bs, bk = placed["S_3"].real[0], placed["K_3"].real[0]
    rho = k.motion.scene.members[3].gyration
    assert bk == pytest.approx(bs + rho ** 2 / bs)
    proportions, moments = lever_latex(lever, rotating=True)
    assert any(r"\frac{BK_{3}}{BC}" in line for line in proportions)
    assert moments[-1].endswith(rf"M_p = F_p\cdot\overline{{AB}} = {lever.torque:.4g}\ \mathrm{{N\cdot m}}")
