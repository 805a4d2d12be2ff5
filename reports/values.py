"""The results of a scene as plain data: the JSON of ``python -m solvers solve`` and the
textbook check both read them from here."""

from __future__ import annotations

import math

import numpy as np

from mechanisms.gears import GearTrain
from mechanisms.rotor import Rotor
from methods.gear_steps import speed_steps
from methods.plans import Plans, is_construction
from solvers.balancing import Balance, balance
from solvers.diagnostics import Unsolvable, solve_instant
from solvers.gears import TrainSolution, solve_train, stages
from solvers.kinematics import Motion
from solvers.kinetostatics import Kinetostatics, analyse
from solvers.state import value_at


def motion_json(motion: Motion) -> dict:
    """One instant (the first position of ``motion``) in the documented JSON layout."""
    scene = motion.scene
    at = motion.at[0]
    data = {
        "scene": scene.id,
        "at": math.degrees(at) if scene.driver.kind == "rotating" else at,
        "points": {name: _point(p) for name, p in sorted(motion.points.items())},
        "members": {str(n): {"angle_deg": math.degrees(m.angle[0]) % 360.0,
                             "omega": m.omega[0], "epsilon": m.epsilon[0]}
                    for n, m in sorted(motion.members.items())},
        "sliders": {name: _slide(s) for name, s in motion.sliders.items()},
    }
    if motion.special:
        data["special_points"] = {name: _point(p) for name, p in motion.special.items()}
    if scene.travel:
        tr = scene.travel
        data["travel"] = {"wheel_omega": tr.wheel_omega, "crank_omega": tr.crank_omega,
                          "cycle_time": tr.cycle_time, "step_time": tr.step_time(),
                          "step_distance": tr.step_distance()}
    return clean(data)


def _slide(s) -> dict:
    """s (m), v (m/s), a (m/s²) along the guide, the Coriolis part [x, y] (m/s²), and for a
    circular slot the normal part [x, y] of the relative acceleration."""
    out = {"s": s.s[0], "v": s.v[0], "a": s.a[0], "coriolis": [s.coriolis[0].real, s.coriolis[0].imag]}
    if s.normal is not None:
        out["normal"] = [s.normal[0].real, s.normal[0].imag]
    return out


def _point(p) -> dict:
    """x, y (m), vx, vy, v (m/s), ax, ay, a (m/s²); a special point at infinity is null."""
    if not np.isfinite(p.z[0]):
        return None
    return {"x": p.x[0], "y": p.y[0], "vx": p.vx[0], "vy": p.vy[0], "ax": p.ax[0],
            "ay": p.ay[0], "v": abs(p.v[0]), "a": abs(p.a[0])}


def forces_json(k: Kinetostatics) -> dict:
    """One instant (the first position) of the kinetostatics, SI units: reactions keyed "p-q"
    (the force of member p on member q, both orders), the driving torque or force by the
    three methods, and each member's inertia loads."""
    scene = k.motion.scene
    at = k.motion.at[0]
    reactions = {}
    for (p, q), r in sorted(k.reactions.items()):
        f = r.force[0]
        entry = {"x": f.real, "y": f.imag, "magnitude": abs(f),
                 "angle_deg": math.degrees(math.atan2(f.imag, f.real)) % 360.0,
                 "point": _xy(r.point[0])}
        if r.pair.kind == "prismatic":
            entry.update(couple=r.couple[0], offset=r.offset[0])
        reactions[f"{p}-{q}"] = entry
    rotating = k.rotating
    kind = "torque" if rotating else "force"
    driving = {"torque": k.driving[0] if rotating else None,
               "force": k.crank_force[0] if rotating else k.driving[0],
               "power": k.power[0],
               f"{kind}_zhukovsky": k.driving_lever[0],
               f"{kind}_power_balance": k.driving_power[0],
               "power_balance_residual": k.power_residual[0]}
    inertia = {str(n): {"force": _xy(i.force[0]), "moment": i.moment[0],
                        "centre": _xy(i.centre[0]),
                        "huygens_point": None if i.huygens is None else _xy(i.huygens[0])}
               for n, i in sorted(k.inertia.items())}
    loads = {ld.name: {"member": ld.member, "force": _xy(ld.force[0]), "point": _xy(ld.point[0]),
                       "magnitude": abs(ld.force[0])} for ld in k.loads}
    return clean({"scene": scene.id,
                  "at": math.degrees(at) if rotating else at,
                  "reactions": reactions, "driving": driving, "inertia": inertia, "loads": loads,
                  "couples": {c.name: c.value[0] for c in k.couples}})


def has_loads(scene) -> bool:
    """Whether chapter 5 has anything to compute for the scene."""
    return bool(scene.forces or scene.moments or any(m.mass > 0 for m in scene.members.values()))


def plan_json(plans: Plans) -> dict:
    """Both plans: every image (``velocity_image``/``acceleration_image`` per point, m/s and
    m/s²), and per step the components with the two images each joins."""
    data = {"points": {}}
    for name in plans.positions:
        image = name.lower()
        data["points"][name] = {"velocity_image": _xy(plans.velocity.images[image]),
                                "acceleration_image": _xy(plans.acceleration.images[image])}
    for plan in (plans.velocity, plans.acceleration):
        data[plan.quantity] = {
            "construction_points": {k: _xy(z) for k, z in plan.images.items()
                                    if is_construction(k)},
            "steps": [{"target": step.target, "group": step.group, "equation": step.latex,
                       "components": [{"kind": a.kind, "from": a.tail, "to": a.head,
                                       "symbol": a.symbol, "x": a.value.real, "y": a.value.imag,
                                       "magnitude": abs(a.value)}
                                      for _, side in step.sides for a in side]}
                      for step in plan.steps]}
    data["members"] = {str(n): {"omega": w, "epsilon": e} for n, (w, e) in plans.members.items()}
    return clean(data)


def _xy(z: complex) -> list[float]:
    return [z.real, z.imag]


def rotor_json(result: Balance) -> dict:
    return clean({"scene": result.rotor.id, "kind": "rotor",
                  "corrections": {p: {"mass": f.mass, "radius": f.radius,
                                      "angle_deg": math.degrees(f.angle)}
                                  for p, f in result.corrections.items()},
                  "residual": {"force": result.residual_force, "moment": result.residual_moment}})


def gears_json(solution: TrainSolution, with_stages: bool = False) -> dict:
    """The solved train: ω of every member, ratios from each input (and any the book quotes),
    the named points' peripheral velocities and the degrees of freedom; with ``with_stages``
    each carrier's stage (``solvers.gears.stages``) and every member's speed in the book's
    order (``methods.gear_steps``)."""
    train = solution.train
    pairs = {(i.member, m) for i in train.inputs for m in train.members if m != i.member}
    pairs |= {tuple(int(x) for x in k.split(".")[1].split("-")) for k in train.book
              if k.startswith("ratios.")}
    data = {"scene": train.id, "kind": "gears",
            "members": {str(m): {"omega": w} for m, w in solution.omega.items()},
            "ratios": {f"{a}-{b}": _ratio(solution.ratio(a, b)) for a, b in sorted(pairs)},
            "dof": solution.dof}
    if train.points:
        data["points"] = {name: solution.velocity(m, r) for name, (m, r) in train.points.items()}
    if with_stages:
        data["stages"] = [{"carrier": s.carrier, "members": list(s.members),
                           "relative": {str(m): w for m, w in s.relative.items()},
                           "ends": list(s.ends), "ratio": s.ratio,
                           "solved": None if math.isnan(s.solved) else s.solved}
                          for s in stages(solution)]
        data["order"] = [{"member": s.member, "omega": s.omega, "kind": s.kind, "carrier": s.carrier}
                         for s in speed_steps(solution)]
    return clean(data)


def _ratio(value: float):
    return "inf" if math.isinf(value) else value


def clean(value):
    """Plain floats for JSON; -0.0 printed as 0.0."""
    if isinstance(value, dict):
        return {k: clean(v) for k, v in value.items()}
    if isinstance(value, list):
        return [clean(v) for v in value]
    if isinstance(value, (float, np.floating)):
        return float(value) + 0.0
    return value


def flatten(data: dict, prefix: str = "") -> dict[str, float]:
    """{"members": {"4": {"omega": 7.8}}} → {"members.4.omega": 7.8} (the book keys)."""
    out = {}
    for key, value in data.items():
        path = f"{prefix}{key}"
        if isinstance(value, dict):
            out.update(flatten(value, f"{path}."))
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            out[path] = float(value)
    return out


def exact_values(scene) -> dict[str, float]:
    """Every result of the scene (at its own instant), keyed like its ``[book]`` table."""
    if isinstance(scene, Rotor):
        return flatten(rotor_json(balance(scene)))
    if isinstance(scene, GearTrain):
        solution = solve_train(scene)
        if solution.status != "solved":
            raise Unsolvable(solution.message)
        return flatten(gears_json(solution))
    motion = solve_instant(scene, None)
    values = flatten(motion_json(motion))
    values.update(_distances(scene, motion))
    if has_loads(scene):
        k = analyse(scene, motion=motion)
        values.update(flatten(forces_json(k)))
        values.update(_arms(scene, k))
        values.update(_parts(scene, k))
        values.update(_turned(scene, k))
    return values


def _distances(scene, motion: Motion) -> dict[str, float]:
    """A printed distance between two points at the drawn instant ("distances.B-C", m): the
    book lists such lengths of its figure, e.g. from a moving point to a pivot."""
    out = {}
    for key in scene.book:
        head, _, pair = key.partition(".")
        a, _, b = pair.partition("-")
        if head == "distances" and a in motion.points and b in motion.points:
            out[key] = float(abs(motion.points[a].z[0] - motion.points[b].z[0]))
    return out


def _arms(scene, k: Kinetostatics) -> dict[str, float]:
    """A printed lever arm ("arms.G_5.F", m): how far the line of an action — a load by its
    name, or a reaction "p-q" — passes from a point, at the drawn instant. Chapter 5's
    solutions print these arms (h_5, h_54) beside the forces, read off the figure."""
    actions = {ld.name: (ld.force[0], ld.point[0], 0.0) for ld in k.loads}
    actions.update({f"{p}-{q}": (r.force[0], r.point[0], r.couple[0])
                    for (p, q), r in k.reactions.items()})
    points = k.motion.points
    out = {}
    for key in scene.book:
        head, _, rest = key.partition(".")
        name, _, letter = rest.rpartition(".")
        if head == "arms" and name in actions and letter in points:
            force, at, couple = actions[name]
            moment = ((at - points[letter].z[0]).conjugate() * force).imag + couple
            out[key] = float(abs(moment) / abs(force)) if abs(force) > 0 else math.nan
    return out


def _turned(scene, k: Kinetostatics) -> dict[str, float]:
    """A load's lever arm about the pole of the velocity plan turned by 90° ("turned.F_3", read
    at U_v as a speed, m/s): Zhukovsky's lever takes each force's moment there, which is its
    power over its size, |F·v|/|F|. An inertia force acts at Huygens' point K, so its power
    includes the member's inertia couple (F_i·v_S + M_i·ω). Tasks 5.3–5.4 print these arms."""
    bodies, members = k.motion.bodies, k.motion.members
    couples = {c.member: c.value[0] for c in k.couples if c.inertial}
    out = {}
    for key in scene.book:
        head, _, name = key.partition(".")
        load = next((ld for ld in k.loads if ld.name == name), None) if head == "turned" else None
        if load is None or abs(load.force[0]) == 0:
            continue
        v = value_at(bodies[load.member].velocity(load.local), 0)
        power = (load.force[0].conjugate() * v).real
        if load.inertial:
            power += couples.get(load.member, 0.0) * members[load.member].omega[0]
        out[key] = float(abs(power) / abs(load.force[0]))
    return out


def _parts(scene, k: Kinetostatics) -> dict[str, float]:
    """A reaction's normal and tangential parts as the book splits them ("reactions.4-5.normal",
    N): along member 5's line (from the joint to the member's other defining point, e.g. D to
    F for DF) and across it, as magnitudes: the book prints F_45^n and F_45^t for a sense it
    assumes."""
    points = k.motion.points
    out = {}
    for key in scene.book:
        head, _, rest = key.partition(".")
        pair, _, part = rest.partition(".")
        p, _, q = pair.partition("-")
        wanted = head == "reactions" and part in ("normal", "tangential")
        r = k.reactions.get((int(p), int(q))) if wanted and p.isdigit() and q.isdigit() else None
        if r is None:
            continue
        line = [points[name].z[0] for name in scene.members[int(q)].axis if name != r.pair.point]
        if line and abs(line[0] - r.point[0]) > 0:
            n = (line[0] - r.point[0]) / abs(line[0] - r.point[0])
            along = n.conjugate() * r.force[0]
            out[key] = float(abs(along.real if part == "normal" else along.imag))
    return out
