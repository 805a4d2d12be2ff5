"""The steps a student gives when practising each construction of the course, made from the
methods written out step by step, with the exact values and what a drawing allows.

``compass``: each point of the 12 positions, in the order the construction places them
(task 1.1's method), to 0.05 cm at U_L. ``plans``: every arrow of the velocity and then the
acceleration plan in the book's order, each image reached from the pole, and ω, ε of each
member (chapters 2–3). ``three``: the pivots of the three-position construction, then the
links' lengths (beyond the book, docs/synthesis.md). ``forces``: every part a group's equations give, the force polygons'
closing sides with the loads they add (chapter 5). ``lever``: each force's moment about the
turned plan's pole, then F_p and M_p (the reduced mechanism). ``willis``: each member's ω
in the book's order (chapter 6). ``balance``: the V polygon about plane II, then the U
polygon (chapter 7).
"""

from __future__ import annotations

from itertools import accumulate

import numpy as np

from mechanisms import Scene, SceneError
from mechanisms.gears import GearTrain
from mechanisms.rotor import Rotor
from mechanisms.schema import DRIVER
from solvers.balancing import Balance, balance as solve_balance, unit as rotation
from solvers.diagnostics import solve_instant
from solvers.gears import TrainSolution, solve_train
from solvers.kinematics import Motion, solve
from solvers.kinetostatics import Kinetostatics, analyse
from solvers.paths import cycle_values

from . import three_positions
from .compass import construction as compass_construction
from .force_steps import latex_name, steps as force_construction
from .gear_steps import speed_steps
from .lever_steps import construction as lever_construction
from .plans import POLE, Plans, build, is_construction, readings
from .judge import tolerance
from .practice import Step, Term
from .scales import PRECISION_CM, plan_scales, polygon_scale

UNITS = {"v": "m/s", "a": "m/s²"}


def _tex_image(image: str) -> str:
    name = image.upper()
    return name[0] + (f"_{{{name[1:]}}}" if len(name) > 1 else "")


def compass(motion: Motion, scale_l: float) -> list[Step]:
    """The points of the 12 positions, as the compass construction places them (``motion``
    solved at ``cycle(scene, 12)``); U_L in m per cm. The paths drawn through them at the
    end are not asked."""
    out = []
    for step in compass_construction(motion, []):
        for name, where in step.found.items():
            out.append(Step(f"compass.{name}", f"the point {name} of the construction (m)", name,
                            "point", "m", where, PRECISION_CM * scale_l, scale_l, "L",
                            rule="point"))
    return out


def plans(plans_: Plans, scales: dict[str, float]) -> list[Step]:
    """The velocity plan's arrows and images, then the acceleration plan's, then ω and ε of
    each member; each arrow starts at the exact image before it."""
    out: list[Step] = []
    for plan, key in ((plans_.velocity, "v"), (plans_.acceleration, "a")):
        scale, unit = scales[key], UNITS[key]
        tol = PRECISION_CM * scale
        seen: set[str] = set()
        for st in plan.steps:
            for start, side in st.sides:
                for arrow in side:
                    sid = f"{key}.{arrow.tail}-{arrow.head}"
                    if sid in seen:
                        continue
                    seen.add(sid)
                    out.append(Step(sid, f"the arrow {arrow.symbol} from {arrow.tail} to "
                                         f"{arrow.head} ({unit})", arrow.symbol, "vector", unit,
                                    arrow.value, tol, scale, key, plan.images[arrow.tail],
                                    rule=arrow.kind))
            target = st.target
            if f"{key}.{target}" in seen or is_construction(target):
                continue
            seen.add(f"{key}.{target}")
            terms, missing = _sum_terms(plan, st, key)
            symbol = f"{key}_{{{_tex_image(target)}}}"
            out.append(Step(f"{key}.{target}", f"{symbol} from the pole to {target} ({unit})",
                            symbol, "vector", unit, plan.images[target], tol, scale, key, 0j,
                            terms, missing, "sum"))
    out += _rates(plans_, scales)
    return out


def _sum_terms(plan, st, key: str) -> tuple[tuple[Term, ...], tuple[Term, ...]]:
    """What the image of a step adds up (its first side: the start's image and the arrows),
    and the image with any one of them left out, on either side."""
    target = plan.images[st.target]
    sides = []
    for start, arrows in st.sides:
        known = [] if start == POLE or abs(plan.images[start]) == 0 else \
            [Term(f"{key}_{{{_tex_image(start)}}}", plan.images[start])]
        sides.append(known + [Term(a.symbol, a.value) for a in arrows])
    missing = {t.name: Term(t.name, target - t.value) for side in sides for t in side
               if abs(t.value) > 1e-12 * max(abs(target), 1e-300)}
    return tuple(sides[0]), tuple(missing.values())


def _rates(plans_: Plans, scales: dict[str, float]) -> list[Step]:
    """ω and ε of each member but the driver, signed (counter-clockwise positive), to what
    the plans' lengths allow."""
    error = {r.symbol: r.uncertainty for r in readings(plans_, scales, PRECISION_CM)}
    out = []
    for member, (w, e) in sorted(plans_.members.items()):
        if member == DRIVER:
            continue
        for name, value, unit, symbol in (("omega", w, "s⁻¹", f"\\omega_{{{member}}}"),
                                          ("epsilon", e, "s⁻²", f"\\varepsilon_{{{member}}}")):
            tol = tolerance(value, error.get(symbol))  # (the one rule: methods.judge)
            out.append(Step(f"{name}.{member}", f"{symbol} of member {member}, signed "
                            f"({unit}, counter-clockwise positive)", symbol, "scalar", unit,
                            value, tol, 1.0, "", rule="rate", computed=symbol not in error))
    return out


def forces(k: Kinetostatics, index: int, scale_f: float) -> list[Step]:
    """Graphical kinetostatics at position ``index``: each part a moment equation gives
    (signed), and each polygon's closing sides with the loads the polygon adds."""
    out: list[Step] = []
    for n, st in enumerate(force_construction(k, index).steps):
        if st.kind == "polygon":
            out += _closing_steps(st, n, scale_f)
            continue
        for name, (value, unit) in st.found.items():
            tol = tolerance(value)  # computed from the equation (the one rule: methods.judge)
            missing = balancing_missing(k, index)[1] if name == "M_p" else ()
            out.append(Step(f"forces.{n}.{name}", f"{name} from the {st.kind} equation of "
                            f"members {st.members} ({unit})", latex_name(name), "scalar", unit,
                            value, tol,
                            scale_f if unit == "N" else 1.0, f"F{n}", missing=missing, computed=True,
                            rule="balancing" if name == "M_p" else "moment"))  # (as judge.rule_of)
    return out


def _closing_steps(st, n: int, scale_f: float) -> list[Step]:
    """A polygon's closing side(s): the known forces it adds, and the closing with one of
    them forgotten (a single closing vector: the rest of the sum; two parts: each part of
    the polygon closed without it)."""
    tol = PRECISION_CM * scale_f
    known = [t for t in st.terms if t.force != 0]
    total = sum((t.force for t in known), 0j)
    adds = tuple(Term(t.name, -t.force) for t in known)
    out, tail = [], total
    parts = [(name, value) for name, value in st.closing]
    for i, (name, value) in enumerate(parts):
        missing = []
        for t in known:
            if len(parts) == 1:
                missing.append(Term(t.name, value + t.force))
            elif all(abs(v) > 1e-12 for _, v in parts):
                a, b = (v / abs(v) for _, v in parts)
                rest = -(total - t.force)
                det = (a.conjugate() * b).imag
                x, y = (rest.conjugate() * b).imag / det, (a.conjugate() * rest).imag / det
                missing.append(Term(t.name, (x * a, y * b)[i]))
        out.append(Step(f"forces.{n}.{name}", f"the closing side {name} of the polygon of "
                        f"members {st.members} (N)", latex_name(name), "vector", "N", value, tol,
                        scale_f,
                        f"F{n}", tail, adds, tuple(missing), "closing"))
        tail += value
    return out


def lever(k: Kinetostatics, index: int) -> list[Step]:
    """Zhukovsky's lever: each force's moment about the pole of the turned plan (N·m/s),
    then the balancing F_p at the crank pin's image (N) and M_p = F_p·AB (N·m)."""
    construction = lever_construction(k, index)
    out = []
    for i, m in enumerate(construction.moments):
        out.append(Step(f"lever.{i}.{m.name}", f"the moment of {m.name} about the pole of the "
                        "turned plan, counter-clockwise positive (N·m/s)", f"{m.name}\\cdot h",
                        "scalar", "N·m/s", m.value, tolerance(m.value),
                        rule="moment", computed=True))
    arm = construction.balancing_arm
    missing, torque_missing = balancing_missing(k, index)
    terms = tuple(Term(m.name, -m.value / arm) for m in construction.moments)
    out.append(Step("lever.F_p", "the balancing force F_p at the crank pin's image (N)", "F_p",
                    "scalar", "N", construction.balancing, tolerance(construction.balancing), 1.0,
                    "", 0j, terms, missing, "balancing", computed=True))
    if construction.torque is not None:
        out.append(Step("lever.M_p", f"the driving torque M_p = F_p·{construction.crank} (N·m)",
                        "M_p", "scalar", "N·m", construction.torque,
                        tolerance(construction.torque), 1.0, "", 0j, (), torque_missing,
                        "balancing", computed=True))
    return out


def balancing_missing(k: Kinetostatics, index: int) -> tuple[tuple[Term, ...], tuple[Term, ...]]:
    """The balancing force F_p and the driving torque M_p with one force's moment left out
    (Zhukovsky's lever): what a student who forgot that load gets — whichever way, the
    lever or the force polygons, they found M_p."""
    construction = lever_construction(k, index)
    arm = construction.balancing_arm
    force = tuple(Term(m.name, construction.balancing + m.value / arm) for m in construction.moments)
    if construction.torque is None:
        return force, ()
    length = k.motion.scene.members[DRIVER].length
    return force, tuple(Term(t.name, t.value * length) for t in force)


def three(stages: list[three_positions.Stage], scale_l: float) -> list[Step]:
    """The pivots the three-position construction finds (each where two bisectors cross,
    to 0.05 cm at U_L), then the lengths of the crank, the rocker and the frame read off the
    drawing."""
    out = [Step(f"three.{name}", f"the fixed pivot {name} (m)", name, "point", "m", where,
                PRECISION_CM * scale_l, scale_l, "L", rule="point")
           for stage in stages for name, where in stage.found.items()]
    links = stages[-1].values
    for name, symbol in (("crank", "OA"), ("rocker", "DB"), ("frame", "OD")):
        out.append(Step(f"three.{name}", f"the length {symbol} (m)", symbol, "scalar", "m",
                        links[name], tolerance(links[name], PRECISION_CM * scale_l),
                        scale_l, rule="scalar"))
    return out


def willis(solution: TrainSolution) -> list[Step]:
    """Each member's ω in the book's order (the inputs are given, not asked), signed."""
    return [Step(f"willis.{s.member}", f"ω{s.member}, signed (s⁻¹, counter-clockwise positive)",
                 f"\\omega_{{{s.member}}}", "scalar", "s⁻¹", s.omega,
                 tolerance(s.omega), rule="stage", computed=True)
            for s in speed_steps(solution) if s.kind != "input"]


def balance(result: Balance) -> list[Step]:
    """Two planes: the V polygon about plane II (each mass's V = U·(x − x_II), closed by
    plane I's), plane I's U from it, then the U polygon closed by plane II's. One plane: the
    U polygon closed by plane I's. Each polygon at a round scale that draws it about 8 cm
    long (kg·m and kg·m² per cm)."""
    rotor = result.rotor
    us = [m.mass * m.radius * rotation(m.angle) for m in rotor.masses]
    scale_u = polygon_scale(accumulate(us))
    out: list[Step] = []
    if rotor.mode == "dynamic":
        x2 = rotor.planes["II"]
        vs = [u * (m.x - x2) for u, m in zip(us, rotor.masses)]
        scale_v = polygon_scale(accumulate(vs))
        out += _polygon(vs, "V", "kg·m²", scale_v,
                        result.corrections["I"].u * (rotor.planes["I"] - x2), "I")
        u1 = result.corrections["I"].u
        out.append(Step("U.I", "plane I's correction U_I = V_I / (x_I − x_II) (kg·m)", "U_{I}",
                        "vector", "kg·m", u1, PRECISION_CM * scale_u, scale_u, "U", sum(us, 0j),
                        rule="correction"))
        out += _polygon(us, "U", "kg·m", scale_u, result.corrections["II"].u, "II",
                        extra=[("U_{I}", u1)])
    else:
        out += _polygon(us, "U", "kg·m", scale_u, result.corrections["I"].u, "I")
    return out


def _polygon(vectors, sheet: str, unit: str, scale: float, closing: complex, plane: str,
             extra=()) -> list[Step]:
    """Each mass's vector from the end of the one before, then the closing side, plane
    ``plane``'s correction (with the polygon's vectors it adds, and the side with one of
    them forgotten)."""
    tol = PRECISION_CM * scale
    out, tail = [], 0j
    for i, v in enumerate(vectors):
        label = f"{sheet}_{{{i + 1}}}"
        out.append(Step(f"{sheet}.{i + 1}", f"{label} of mass {i + 1} ({unit})", label, "vector",
                        unit, v, tol, scale, sheet, tail, rule="polygon"))
        tail += v
    tail += sum((v for _, v in extra), 0j)
    known = [(f"{sheet}_{{{i + 1}}}", v) for i, v in enumerate(vectors)] + list(extra)
    name = f"{sheet}_{{{plane}}}"
    return out + [Step(f"{sheet}.{plane}", f"the closing side {name}: plane {plane}'s "
                       f"correction ({unit})", name, "vector", unit, closing, tol, scale, sheet,
                       tail, tuple(Term(n, -v) for n, v in known),
                       tuple(Term(n, closing + v) for n, v in known), "closing")]


# the kind of scene each method practises on
KINDS = {"compass": Scene, "plans": Scene, "forces": Scene, "lever": Scene,
         "willis": GearTrain, "balance": Rotor, "three": Scene}
THREE_APART = (0.0, 40.0, 80.0)  # the three positions' crank angles after the first, °
KIND_NAMES = {Scene: "linkage", GearTrain: "gear train", Rotor: "rotor"}  # (said in errors)


def steps_for(scene, method: str, at: float | None = None) -> list[Step]:
    """The steps of ``method`` on ``scene`` (at ``at``: φ₂ in degrees, or s in m, where the
    method works at one instant); SceneError when the scene is not of the method's kind."""
    kind = KINDS.get(method)
    if kind is None:
        raise SceneError(f"unknown method {method!r}: choose one of {', '.join(KINDS)}")
    if not isinstance(scene, kind):
        raise SceneError(f"the {method} method needs a {KIND_NAMES[kind]}; this is a "
                         f"{KIND_NAMES.get(type(scene), type(scene).__name__.lower())}")
    if method == "compass":
        motion = solve(scene, cycle_values(scene, 12), order=0)
        return compass(motion, plan_scales(scene, None)["L"])
    if method == "three":
        first = np.degrees(scene.driver.at) if at is None else at
        stages = three_positions.construction(
            *three_positions.of_scene(scene, [first + d for d in THREE_APART]))
        return three(stages, plan_scales(scene, None)["L"])
    if method == "willis":
        return willis(solve_train(scene))
    if method == "balance":
        return balance(solve_balance(scene))
    motion = solve_instant(scene, at)
    if method == "plans":
        drawn = build(motion)
        return plans(drawn, plan_scales(scene, drawn))
    k = analyse(scene, inertia=True, motion=motion)
    if method == "lever":
        return lever(k, 0)
    known = [complex(np.ravel(r.force)[0]) for r in k.reactions.values()]
    return forces(k, 0, scene.scales.get("F", polygon_scale(known)))
