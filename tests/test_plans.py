"""Velocity and acceleration plans (chapters 2–3): checked against quantities computed
independently here — finite differences of the solver's positions, and a rotating-guide
case derived by hand — never against the plan's own numbers."""

import cmath
import math
import re

import numpy as np
import pytest

from figures.plans import layout_plan, plan_svg
from mechanisms import load_preset, preset_ids
from mechanisms.schema import Scene
from methods.analytic import equations
from methods.plans import POLE, build, readings
from solvers.diagnostics import solve_instant
from solvers.kinematics import solve
from solvers.structure import StructureError, decompose

CLASS_III = {"zbirka-4.1", "zbirka-4.2", "zbirka-4.3", "triad-full-turn"}  # drawn through S
LINKAGES = list(preset_ids("linkage"))


@pytest.mark.parametrize("pid", sorted(CLASS_III))
def test_a_class_iii_plan_starts_from_the_special_point(pid):
    """S lies on the lines of two binary members, so from each one's pivot P the part
    v_S − v_P is square to PS, and a_S's tangential part too (the two normal parts, of the
    binary member and of the ternary one, come first); S's image is the solver's S."""
    scene = load_preset(pid)
    motion = solve(scene, [scene.driver.at], order=2)
    plans = build(motion)
    s = motion.special["S"]
    assert plans.velocity.images["s"] == pytest.approx(complex(s.v[0]), abs=1e-12)
    assert plans.acceleration.images["s"] == pytest.approx(complex(s.a[0]), abs=1e-9)
    first = next(step for step in plans.acceleration.steps if step.target == "s")
    assert first.group.startswith("III(") and len(first.sides) == 2
    for _, side in first.sides:
        last = side[-1]
        if last.kind == "tangential":
            pivot = motion.points[last.rule[1]].z[0]
            assert (last.value * np.conj(s.z[0] - pivot)).real == pytest.approx(0, abs=1e-9)
    assert plans.velocity.closure() < 1e-9 and plans.acceleration.closure() < 1e-9


def test_a_class_iii_group_without_its_special_point_is_refused_with_the_reason():
    motion = solve(load_preset("zbirka-4.1"), order=2)
    motion.special = {}  # as where the binary lines are parallel
    with pytest.raises(StructureError, match="special point S"):
        build(motion)


def plans_of(scene: Scene, at=None):
    return build(solve_instant(scene, at))


@pytest.mark.parametrize("pid", LINKAGES)
def test_every_polygon_of_both_plans_closes(pid):
    """Each equation's sides, added head to tail from their start images, reach the target."""
    plans = plans_of(load_preset(pid))
    for plan in (plans.velocity, plans.acceleration):
        size = max(abs(z) for z in plan.images.values())
        assert plan.closure() <= 1e-12 * size
        assert plan.steps, pid


@pytest.mark.parametrize("pid", ["analitika-2.1", "analitika-2.2", "zbirka-1.2", "scotch-yoke",
                                 "tangent-slotted-crank"])
def test_images_are_the_derivatives_of_the_positions(pid):
    """Velocity images against central differences of positions, acceleration images
    against second differences — including the coincident points (B₄) of the guides."""
    scene = load_preset(pid)
    plans = plans_of(scene)
    h = 1e-5 if scene.driver.kind == "rotating" else 1e-6
    at = scene.driver.at
    rate = scene.driver.speed
    around = [plans_of(scene.with_(at=at + k * h)) for k in (-1, 1)]
    for name in plans.positions:
        image = name.lower()
        if not (name.isalpha() and len(name) == 1):  # coincident: fixed to its member, not moving
            continue
        zm, zp = (p.positions[name] for p in around)
        fd_v = (zp - zm) / (2 * h) * rate
        fd_a = (zp - 2 * plans.positions[name] + zm) / h**2 * rate**2
        scale_v = max(abs(z) for z in plans.velocity.images.values())
        scale_a = max(abs(z) for z in plans.acceleration.images.values())
        assert abs(plans.velocity.images[image] - fd_v) < 1e-6 * scale_v, name
        assert abs(plans.acceleration.images[image] - fd_a) < 1e-3 * scale_a, name


def test_relative_parts_have_the_directions_the_book_draws():
    """v_XY ⊥ XY, aⁿ_XY along YX toward X with ω²·XY, aᵗ_XY ⊥ XY."""
    plans = plans_of(load_preset("analitika-2.1"))
    pos = {k.lower(): z for k, z in plans.positions.items()}
    for plan in (plans.velocity, plans.acceleration):
        for arrow in plan.arrows:
            if arrow.kind not in ("relative", "normal", "tangential") or not arrow.lever:
                continue
            x, y = arrow.rule[1:] if arrow.kind != "normal" else arrow.rule[:0:-1]
            xy = pos[y.lower()] - pos[x.lower()]
            w, _ = plans.members[arrow.member]
            if arrow.kind == "normal":
                assert arrow.value == pytest.approx(-w * w * xy, abs=1e-9)
            else:
                assert abs((arrow.value * xy.conjugate()).real) < 1e-9 * abs(arrow.value * xy) + 1e-12


def slotted_lever(phi2: float) -> Scene:
    """Crank OA = 0.1 m (ω₂ = 12 s⁻¹), slider 3 at A in a guide 4 turning about C = (0, −0.3)."""
    from mechanisms.loader import parse_scene

    return parse_scene(f"""
pairs = [
  {{ type = "revolute", members = [1, 2], point = "O" }},
  {{ type = "revolute", members = [2, 3], point = "A" }},
  {{ type = "prismatic", guide = 4, slider = 3, point = "A", through = "C" }},
  {{ type = "revolute", members = [4, 1], point = "C" }},
]
[frame]
O = [0.0, 0.0]
C = [0.0, -0.3]
[driver]
type = "rotating"
at = {phi2}
omega = 12.0
[members.2]
points = ["O", "A"]
length = 0.1
[members.3]
points = ["A"]
[members.4]
points = ["C", "D"]
length = 0.5
""")


@pytest.mark.parametrize("phi2", [0.0, 35.0, 90.0, 200.0, 300.0])
def test_coriolis_of_a_rotating_guide_matches_the_hand_derivation(phi2):
    """With r = CA, θ₄ = arg r: ṙ = Re(v_A·e^{−iθ₄}), ω₄ = Im(v_A·e^{−iθ₄})/|r|;
    Coriolis = 2·ω₄·ṙ, directed as the sliding velocity turned 90° in the sense of ω₄."""
    scene = slotted_lever(phi2)
    plans = plans_of(scene)
    a = 0.1 * cmath.exp(1j * math.radians(phi2))
    v_a = 1j * 12.0 * a
    r = a - (-0.3j)
    e = r / abs(r)
    rdot = (v_a * e.conjugate()).real
    omega4 = (v_a * e.conjugate()).imag / abs(r)
    # the plan walks from A (slider) to A₄ (guide): v_A₄A = iω₄·r − (ṙ·e + iω₄·r) = −ṙ·e
    expected = 2j * omega4 * (-rdot * e)
    coriolis = [x for x in plans.acceleration.arrows if x.kind == "coriolis"]
    assert len(coriolis) == 1
    assert coriolis[0].value == pytest.approx(expected, abs=1e-9)
    sliding = next(x for x in plans.velocity.arrows if x.kind == "sliding")
    assert sliding.value == pytest.approx(-rdot * e, abs=1e-9)
    assert plans.members[4][0] == pytest.approx(omega4, rel=1e-9)


def test_a_fixed_guide_has_no_coriolis_part_and_is_stated_as_a_direction():
    plans = plans_of(load_preset("slider-crank"))
    assert not [a for a in plans.acceleration.arrows if a.kind == "coriolis"]
    assert r"\parallel" in plans.velocity.steps[-1].latex


def test_equations_read_like_the_book():
    plans = plans_of(load_preset("four-bar-crank-rocker"))
    group = plans.velocity.steps[1].latex
    assert group.startswith(r"\vec v_{B} = \vec v_{A} + \vec v_{BA} = \vec v_{BD}")
    assert r"\vec a^n_{BA} + \vec a^t_{BA}" in plans.acceleration.steps[1].latex
    kinds = [s.group for s in plans.velocity.steps]
    assert kinds[0] == "driver" and kinds[1] == "II(3,4)" and "similarity" in kinds


def test_every_point_of_the_mechanism_gets_an_image():
    scene = load_preset("analitika-2.2")
    plans = plans_of(scene)
    for name in scene.point_names:
        assert name.lower() in plans.velocity.images


def test_readings_carry_the_drawing_error_at_the_scales():
    plans = plans_of(load_preset("analitika-2.1"))
    scales = {"L": 0.05, "v": 0.5, "a": 10.0}
    rows = readings(plans, scales, precision_cm=0.05)
    v_c = next(r for r in rows if r.symbol == "v_{C}")
    assert v_c.uncertainty == pytest.approx(0.05 * 0.5)
    assert v_c.plan_cm == pytest.approx(abs(plans.velocity.images["c"]) / 0.5)
    omega4 = next(r for r in rows if r.symbol == r"\omega_{4}")
    assert omega4.exact == pytest.approx(abs(plans.members[4][0]), rel=1e-9)
    finer = next(r for r in readings(plans, scales, 0.01) if r.symbol == r"\omega_{4}")
    assert finer.uncertainty == pytest.approx(omega4.uncertainty / 5)


def test_svg_prints_one_plan_centimetre_as_one_centimetre():
    plans = plans_of(load_preset("analitika-2.1"))
    scale = 0.5
    drawing = layout_plan(plans.velocity, scale)
    svg = plan_svg(drawing, "caption")
    width = float(re.search(r'width="([\d.]+)cm"', svg)[1])
    view = [float(x) for x in re.search(r'viewBox="([^"]+)"', svg)[1].split()]
    assert view[2] == pytest.approx(width, abs=1e-3)  # one user unit = one cm
    lines = re.findall(r'<line x1="([-\d.]+)" y1="([-\d.]+)" x2="([-\d.]+)" y2="([-\d.]+)" '
                       r'stroke="#1f5fbf"', svg)
    lengths = sorted(math.dist((float(a), float(b)), (float(c), float(d))) for a, b, c, d in lines)
    expected = sorted(abs(a.value) / scale for a in plans.velocity.arrows if a.kind == "relative")
    assert lengths == pytest.approx(expected, abs=1e-3)


def test_a_step_limits_the_drawing_and_marks_its_arrows():
    plans = plans_of(load_preset("analitika-2.1"))
    first = layout_plan(plans.velocity, 0.5, 0)
    full = layout_plan(plans.velocity, 0.5)
    assert len(first.arrows) < len(full.arrows)
    assert all(d.current for d in first.arrows)
    assert not any(d.current for d in full.arrows)
    assert set(first.labels) == {POLE, "o", "a"}


@pytest.mark.parametrize("pid,unknowns", [("four-bar-crank-rocker", [r"\varphi_{3}", r"\varphi_{4}"]),
                                          ("slider-crank", [r"\varphi_{3}", "s_{14}"])])
def test_each_loop_names_its_unknowns(pid, unknowns):
    scene = load_preset(pid)
    eq = equations(scene, decompose(scene).groups[0])
    assert list(eq.unknowns) == unknowns
    assert eq.velocity.count(r"\omega") >= 1 and "B" not in eq.position


def test_plans_follow_the_crank_angle():
    scene = load_preset("four-bar-crank-rocker")
    a = plans_of(scene, 30.0).velocity.images["b"]
    b = plans_of(scene, 60.0).velocity.images["b"]
    assert abs(a - b) > 1e-3


def test_plans_need_accelerations():
    with pytest.raises(ValueError, match="order=2"):
        build(solve(load_preset("slider-crank"), order=1))


def test_velocity_images_scale_with_omega_and_accelerations_with_its_square():
    scene = load_preset("analitika-2.1")
    base, fast = plans_of(scene), plans_of(scene.with_(speed=2 * scene.driver.speed))
    for k in base.velocity.images:
        assert fast.velocity.images[k] == pytest.approx(2 * base.velocity.images[k], abs=1e-12)
    for k in ("c", "m"):
        assert fast.acceleration.images[k] == pytest.approx(4 * base.acceleration.images[k])
    assert np.isfinite([abs(z) for z in fast.acceleration.images.values()]).all()


@pytest.mark.parametrize("pid", ["analitika-2.1", "analitika-2.2", "slider-crank", "zbirka-2.3",
                                 "analitika-2.5", "scotch-yoke"])
def test_the_squared_and_added_position_equation_has_the_solutions_root(pid):
    """Each group's derivation ends on two roots, and the chosen one is the solver's value (to
    the printed five digits)."""
    from methods.analytic import derivation

    scene = load_preset(pid)
    motion = solve(scene, [scene.driver.at], order=2)
    for group in motion.structure.groups:
        lines = derivation(motion, group)
        assert lines[0].startswith("x:") and lines[1].startswith("y:")
        if len(lines) == 3:  # two slides: Cramer's rule gives both
            values = [float(v) for v in re.findall(r"= (-?[\d.]+(?:e-?\d+)?)", lines[2])]
            exact = sorted(float(motion.sliders[p.name].s[0]) for p in group.pairs if p.kind == "prismatic")
            assert sorted(values) == pytest.approx(exact, rel=1e-4, abs=1e-6)
            continue
        chosen = float(re.search(r"= (-?[\d.]+(?:e-?\d+)?)\\,", lines[-1]).group(1))
        unknown = lines[-1].split("}", 1)[1]
        if "varphi" in lines[-1]:
            member = int(re.search(r"varphi_\{(\d+)\}", lines[-1]).group(1))
            assert chosen == pytest.approx(math.degrees(motion.members[member].angle[0]) % 360, abs=1e-2)
        else:
            name = next(p.name for p in group.pairs if p.kind == "prismatic"
                        and f"s_{{{p.name.replace('-', '')}}}" in unknown)
            assert chosen == pytest.approx(float(motion.sliders[name].s[0]), rel=1e-4)


def test_the_other_root_is_the_other_assembly():
    """Task 2.1 of the complex-number seed: the root not chosen is where the solver puts the
    rocker when the group is assembled the other way."""
    import dataclasses

    from methods.analytic import derivation

    scene = load_preset("analitika-2.1")
    motion = solve(scene, [scene.driver.at], order=2)
    group = motion.structure.groups[0]
    line = derivation(motion, group)[-2]  # φ₄ = … ° or … °
    roots = [float(x) for x in re.findall(r"(-?\d+(?:\.\d+)?)\\,\\text", line)]
    assert len(roots) == 2
    key = tuple(sorted(group.members))
    flipped = dataclasses.replace(scene, assembly={key: -scene.assembly.get(key, 1)}, guess={})
    other = solve(flipped, [scene.driver.at])
    phi4 = math.degrees(other.members[4].angle[0]) % 360
    assert phi4 == pytest.approx(min(roots, key=lambda r: abs(r - phi4)), abs=1e-2)
    assert min(abs(r - math.degrees(motion.members[4].angle[0]) % 360) for r in roots) < 1e-2
    assert abs(roots[0] - roots[1]) > 1.0
