"""Kinetostatics: joint reactions, inertia loads and the driving torque over the cycle.

As the course teaches (kinetostatics lectures; problem collection, tasks 5.1–5.4), the
mechanism is taken apart into its Assur groups and solved from the last group toward the
driver. Each group is one small linear system per position — three equilibrium equations
per member, two unknowns per pair: a revolute pair's force components through the joint,
a prismatic pair's force normal to the guide and its couple (its offset h along the
guide) — batched over the cycle. The driver's system adds the driving torque M_p
(or the driving force F_p of a linear driver).

Two further methods give M_p without any reaction, and are always computed as checks:
the virtual-power balance Σ F·v + Σ M·ω + M_p·ω₂ = 0, and Zhukovsky's lever (the
velocity plan turned 90°, each force moved to the image of its point of action; the
inertia force of a member moved to Huygens' centre K, an external couple replaced by two
forces on the member's points). Velocities here are per unit driver speed, so the checks
hold even when ω₂ = 0 (a static mechanism).

Sign conventions: F_pq is the force of member p on member q (F_qp = −F_pq); M_p is the
torque the motor applies to member 2 (counter-clockwise positive), P = M_p·ω₂ the power
it delivers (negative: the mechanism drives the motor).
"""

from __future__ import annotations

import cmath
import dataclasses
from dataclasses import dataclass, field

import numpy as np

from mechanisms.schema import DRIVER, Pair, Scene

from .kinematics import Motion, solve
from .loops import cross, group_size
from .state import Body

SINGULAR = 1e12  # condition number beyond which a group's system is treated as singular


@dataclass
class Load:
    """A force on a member over the cycle: the complex force (N) and its point of action."""

    name: str  # as the course writes it: F_4, G_3, F_i3
    member: int
    force: np.ndarray
    point: np.ndarray
    local: complex  # the point of action in the member's frame
    inertial: bool = False


@dataclass
class Couple:
    name: str  # M_4, M_i3
    member: int
    value: np.ndarray  # N·m, counter-clockwise positive
    inertial: bool = False


@dataclass
class Inertia:
    """A member's inertia loads: F_i = −m·a_S at S and M_i = −J_S·ε, J_S = m·ρ².

    Huygens' centre K lies on the line from the member's first point B through S, at
    BK = BS + ρ²/BS. The same loads are −m·a_B at S plus −m·a_SB at K (a_SB = a_S − a_B):
    the couple is absorbed, as the book does on the reduced mechanism. K is None when S
    coincides with B, or nearly (the couple cannot be moved to a point).
    """

    member: int
    force: np.ndarray
    moment: np.ndarray
    centre: np.ndarray  # S, world
    base: np.ndarray  # B, world
    huygens: np.ndarray | None  # K, world
    huygens_local: complex | None  # K in the member's frame
    base_force: np.ndarray  # −m·a_B, acting at S
    relative_force: np.ndarray  # −m·a_SB, acting at K

    @property
    def huygens_moment(self) -> np.ndarray:
        """The moment about S of −m·a_SB at K: equal to M_i, which is what the book's form
        relies on (M_i itself where there is no K)."""
        if self.huygens is None:
            return self.moment
        return cross(self.huygens - self.centre, self.relative_force)


@dataclass
class Reaction:
    """F_pq over the cycle: the force (N) of member ``by`` on member ``on`` at ``point``.

    For a prismatic pair ``couple`` is the moment (N·m) the pair transmits about the slider
    point; the force then acts at the offset ``offset`` = couple/force along the guide.
    """

    pair: Pair
    by: int
    on: int
    force: np.ndarray
    point: np.ndarray
    couple: np.ndarray
    direction: complex | np.ndarray = 1.0  # the guide's direction (prismatic pairs)

    @property
    def magnitude(self) -> np.ndarray:
        return np.abs(self.force)

    @property
    def offset(self) -> np.ndarray:
        """h along the guide from the slider point (m); 0 for a revolute pair."""
        normal = (np.conj(1j * self.direction) * self.force).real
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(np.abs(normal) > 0, self.couple / normal, 0.0)

    def reversed(self) -> Reaction:
        return dataclasses.replace(self, by=self.on, on=self.by, force=-self.force,
                                   couple=-self.couple)


@dataclass
class LeverForce:
    """A force on Zhukovsky's lever: applied at ``image``, the velocity-plan image (per unit
    driver speed, turned 90°) of its point of action. Its moment about the pole is
    cross(image, force) = −F·v."""

    name: str
    member: int
    image: np.ndarray
    force: np.ndarray
    local: complex = 0j  # the point of action in the member's frame

    @property
    def moment(self) -> np.ndarray:
        """About the pole, per unit driver speed (N·m·s, or N·s for a linear driver)."""
        return cross(self.image, self.force)


@dataclass
class Kinetostatics:
    """Everything chapter 5 reads, as arrays over ``motion.at``."""

    motion: Motion
    loads: list[Load]
    couples: list[Couple]
    inertia: dict[int, Inertia]
    reactions: dict[tuple[int, int], Reaction]  # (p, q) → F_pq, both orders present
    driving: np.ndarray  # M_p in N·m (rotating driver) or F_p in N (linear driver)
    driving_power: np.ndarray  # M_p from the virtual-power balance
    driving_lever: np.ndarray  # M_p from Zhukovsky's lever
    power: np.ndarray  # P = M_p·ω₂ (or F_p·v), W
    power_residual: np.ndarray  # Σ F·v + Σ M·ω + P with the group-by-group M_p, W
    condition: dict[str, np.ndarray] = field(default_factory=dict)  # per group
    order: tuple[str, ...] = ()  # groups in solving order: last group first, driver last
    scale: np.ndarray | float = 1.0  # Σ|F·v| + Σ|M·ω| per unit driver speed: the size of
    # the terms the three methods add, against which their disagreement is measured
    lever: list[LeverForce] = field(default_factory=list)  # Zhukovsky's lever
    unit: dict[int, Body] = field(default_factory=dict)  # the members' motion per unit ω₂

    @property
    def rotating(self) -> bool:
        return self.motion.scene.driver.kind == "rotating"

    @property
    def disagreement(self) -> np.ndarray:
        """The largest difference between the three M_p, relative to ``scale`` — or, where the
        loads do almost no work (their points stand still, as a slider held at the crank's
        pivot), to a millionth of their moments about the driver: round-off, not the
        methods, is then all the three can differ by."""
        spread = np.maximum(np.abs(self.driving - self.driving_power),
                            np.abs(self.driving - self.driving_lever))
        with np.errstate(invalid="ignore", divide="ignore"):
            return spread / np.maximum(self.scale, 1e-6 * self._load_size() + np.finfo(float).tiny)

    def _load_size(self) -> np.ndarray:
        """Σ|F|·|r − pivot| + Σ|M| over the loads (N·m; for a linear driver Σ|F| in N)."""
        scene = self.motion.scene
        if not self.rotating:
            return sum((np.abs(ld.force) for ld in self.loads), np.zeros_like(self.driving))
        pivot = scene.frame[scene.pair(scene.driver.pair).point]
        size = sum((np.abs(ld.force) * np.abs(ld.point - pivot) for ld in self.loads),
                   np.zeros_like(self.driving))
        return size + sum((np.abs(c.value) for c in self.couples), np.zeros_like(self.driving))

    @property
    def crank_force(self) -> np.ndarray | None:
        """The book's driving force F_p = M_p/AB: the force at the crank's end, at right
        angles to it, that balances the mechanism (None for a linear driver)."""
        length = self.motion.scene.members[DRIVER].length
        return self.driving / length if self.rotating and length else None

    def on_member(self, member: int) -> list[Reaction]:
        """The reactions acting on a member (F_pq with q = member)."""
        return [r for (p, q), r in self.reactions.items() if q == member]


def analyse(scene: Scene, at=None, *, inertia: bool | None = None, motion: Motion | None = None
            ) -> Kinetostatics:
    """Reactions and driving torque at driver value(s) ``at`` (default: the scene's instant).

    ``inertia=False`` leaves the inertia loads out, as the book does in tasks 5.1–5.2; by
    default the scene says (``Scene.inertia``).
    """
    motion = motion or solve(scene, at, order=2)
    bodies = motion.bodies
    loads, couples, inertias = _loads(scene, motion, scene.inertia if inertia is None else inertia)
    known: dict[tuple[int, int], Reaction] = {}
    condition: dict[str, np.ndarray] = {}
    order = []
    for group in reversed(motion.structure.groups):
        solution, _, condition[group.name] = _solve_body(
            scene, group.members, group.pairs, group_size(scene, group), bodies, loads, couples,
            known, motion.at.shape)
        order.append(group.name)
        _record(known, solution)
    solution, driving, condition["driver"] = _solve_driver(scene, motion, loads, couples, known)
    order.append("driver")
    _record(known, solution)

    unit_v = _unit_velocities(scene, motion)
    shape = motion.at.shape
    virtual, scale = (np.broadcast_to(x, shape) for x in _virtual_power(unit_v, loads, couples))
    lever = _lever_forces(scene, unit_v, loads, couples, inertias)
    # a couple M on a member turning at ω has the lever moment −M·ω: the balancing torque's
    # is −M_p per unit ω₂, so M_p is the sum of the others' moments about the pole
    driving_lever = np.broadcast_to(sum((f.moment for f in lever), 0.0), shape)
    power = driving * scene.driver.speed
    return Kinetostatics(motion, loads, couples, inertias, known, driving, -virtual,
                         driving_lever, power, virtual * scene.driver.speed + power, condition,
                         tuple(order), scale, lever, unit_v)


def _record(known: dict, reactions: list[Reaction]) -> None:
    """Each reaction F_pq, and F_qp = −F_pq."""
    for r in reactions:
        known[(r.by, r.on)] = r
        known[(r.on, r.by)] = r.reversed()


# --- loads ----------------------------------------------------------------------------

def centre_of_mass(scene: Scene, member: int) -> complex:
    """S in the member's frame: as given, else the middle of its two axis points (a one-point
    member, e.g. a slider block, has S at its point)."""
    m = scene.members[member]
    if m.centre is not None:
        return m.centre
    return sum(m.points[p] for p in m.axis) / len(m.axis)


def _loads(scene: Scene, motion: Motion, with_inertia: bool):
    bodies = motion.bodies
    n = motion.at.shape

    def full(value):
        return np.broadcast_to(value, n).astype(complex if np.iscomplexobj(value) else float)

    loads: list[Load] = []
    couples: list[Couple] = []
    for f in scene.forces:
        body = bodies[f.member]
        local = scene.points_of(f.member)[f.point]
        direction = cmath.exp(1j * f.angle) * (body.rot if f.follows_member else 1.0)
        name = f.label or f"F_{f.member}"
        loads.append(Load(name, f.member, full(f.magnitude * direction), full(body.position(local)),
                          local))
    for mo in scene.moments:
        couples.append(Couple(f"M_{mo.member}", mo.member, full(float(mo.value))))
    inertias: dict[int, Inertia] = {}
    for number, member in scene.members.items():
        if member.mass <= 0:
            continue
        body = bodies[number]
        s_local = centre_of_mass(scene, number)
        s = full(body.position(s_local))
        if scene.gravity > 0:
            loads.append(Load(f"G_{number}", number, full(-1j * member.mass * scene.gravity), s,
                              s_local))
        if with_inertia:
            inertias[number] = _inertia(scene, number, body, s_local, full)
            loads.append(Load(f"F_i{number}", number, inertias[number].force, s, s_local, True))
            couples.append(Couple(f"M_i{number}", number, inertias[number].moment, True))
    return loads, couples, inertias


def _inertia(scene: Scene, number: int, body: Body, s_local: complex, full) -> Inertia:
    member = scene.members[number]
    m = member.mass
    b_local = member.points[member.axis[0]]
    s, b = full(body.position(s_local)), full(body.position(b_local))
    a_s, a_b = full(body.acceleration(s_local)), full(body.acceleration(b_local))
    moment = full(-m * member.gyration ** 2 * body.epsilon)
    bs = abs(s_local - b_local)
    k_local = huygens = None
    if bs > 0 and member.gyration < 1e9 * bs:  # else S sits on B: K would be at infinity
        k_local = b_local + (s_local - b_local) * (1 + (member.gyration / bs) ** 2)
        huygens = full(body.position(k_local))
    return Inertia(number, -m * a_s, moment, s, b, huygens, k_local, -m * a_b, -m * (a_s - a_b))


# --- group-by-group equilibrium --------------------------------------------------------

def _unknowns(scene: Scene, pair: Pair, bodies: dict[int, Body]):
    """The pair's two unknowns as unit actions of members[0] on members[1]:
    (force, point of action, couple) each; and the guide's direction (prismatic)."""
    a, b = pair.members
    point = bodies[b].position(scene.points_of(b)[pair.point])
    if pair.kind == "revolute":
        return [(1.0 + 0j, point, 0.0), (1j, point, 0.0)], 1.0
    direction = cmath.exp(1j * pair.angle) * bodies[a].rot  # a is the guide
    return [(1j * direction, point, 0.0), (0j, point, 1.0)], direction


def _equations(members: tuple[int, ...], bodies, size: float, n: tuple[int, ...]):
    """Rows: ΣFx, ΣFy and ΣM/size about the member's reference point, per member."""
    rows = {m: 3 * i for i, m in enumerate(members)}
    refs = {m: bodies[m].z for m in members}

    def wrench(member, force, point, couple):
        """(3,) rows of one action on one member, broadcast over the cycle."""
        moment = cross(point - refs[member], force) + couple
        return np.stack(np.broadcast_arrays(np.real(force), np.imag(force), moment / size,
                                            np.zeros(n)))[:3]
    return rows, wrench


def _known_actions(member: int, loads, couples, known: dict) -> list[tuple]:
    """Every known action on ``member``: loads, couples, and reactions of solved pairs."""
    out = [(ld.force, ld.point, 0.0) for ld in loads if ld.member == member]
    out += [(0j, 0j, c.value) for c in couples if c.member == member]
    out += [(r.force, r.point, r.couple) for (p, q), r in known.items() if q == member]
    return out


def _solve_system(columns: list[np.ndarray], rhs: np.ndarray, n, k: int):
    """Batched k×k solve; positions whose system is singular (a dead centre) or not assembled
    come out NaN. Returns the unknowns (k, N) and the condition number per position."""
    a = np.zeros(n + (k, k))
    for j, col in enumerate(columns):
        a[..., :, j] = np.moveaxis(col, 0, -1)
    b = np.moveaxis(rhs, 0, -1)
    finite = np.isfinite(a).all(axis=(-1, -2)) & np.isfinite(b).all(axis=-1)
    a[~finite] = np.eye(k)
    cond = _condition(a)
    bad = ~finite | ~(cond <= SINGULAR)
    a[bad] = np.eye(k)
    x = np.linalg.solve(a, np.where(bad[..., None], 0.0, b)[..., None])[..., 0]
    x[bad] = np.nan
    return np.moveaxis(x, -1, 0), np.where(~finite, np.nan, cond)


def _condition(a: np.ndarray) -> np.ndarray:
    """The 1-norm condition number of each matrix (inf where exactly singular): an inverse
    costs a fifth of the singular values that the 2-norm one would need."""
    def norm(m):
        return np.abs(m).sum(axis=-2).max(axis=-1)

    try:
        return norm(a) * norm(np.linalg.inv(a))
    except np.linalg.LinAlgError:  # some matrix is exactly singular: find it one by one
        flat = a.reshape((-1,) + a.shape[-2:])
        return np.array([_condition(m[None])[0] if np.linalg.matrix_rank(m) == m.shape[0]
                         else np.inf for m in flat]).reshape(a.shape[:-2])


def _solve_body(scene: Scene, members: tuple[int, ...], pairs, size: float, bodies, loads,
                couples, known, n, extra=()):
    """Equilibrium of a free body (an Assur group, or the driving member) at every position:
    two unknowns per pair, plus ``extra`` unknown actions (force, point, couple) on its first
    member — the driving torque or force. Returns the pairs' reactions, the extra unknowns
    and the condition number per position."""
    rows, wrench = _equations(members, bodies, size, n)
    k = 3 * len(members)
    rhs = np.zeros((k,) + n)
    for m in members:
        for action in _known_actions(m, loads, couples, known):
            rhs[rows[m]:rows[m] + 3] -= wrench(m, *action)
    columns, meta = [], []
    for pair in pairs:
        units, direction = _unknowns(scene, pair, bodies)
        for force, point, couple in units:
            col = np.zeros((k,) + n)
            for sign, member in ((-1.0, pair.members[0]), (1.0, pair.members[1])):
                if member in rows:
                    col[rows[member]:rows[member] + 3] += sign * _column(wrench, member, size,
                                                                          force, point, couple)
            columns.append(col)
        meta.append((pair, units, direction))
    for force, point, couple in extra:
        col = np.zeros((k,) + n)
        col[:3] = _column(wrench, members[0], size, force, point, couple)
        columns.append(col)
    x, cond = _solve_system(columns, rhs, n, k)
    out = []
    for i, (pair, units, direction) in enumerate(meta):
        (f1, point, _), (f2, _, c2) = units
        u1, u2 = x[2 * i], x[2 * i + 1]
        couple = u2 * size if c2 else np.zeros(n)
        out.append(Reaction(pair, pair.members[0], pair.members[1], u1 * f1 + u2 * f2,
                            np.broadcast_to(point, n), couple, direction))
    extras = [x[2 * len(meta) + j] * (size if couple else 1.0)
              for j, (_, _, couple) in enumerate(extra)]
    return out, extras, cond


def _column(wrench, member: int, size: float, force, point, couple) -> np.ndarray:
    """One unknown's column; a couple unknown is counted in units of size·N, so that every
    column has entries of one order."""
    return (size if couple else 1.0) * wrench(member, force, point, couple)


def _solve_driver(scene: Scene, motion: Motion, loads, couples, known):
    """Member 2: its pair with the frame (two unknowns) and M_p (or F_p along the guide)."""
    n = motion.at.shape
    pair = scene.pair(scene.driver.pair)
    size = max((abs(c) for c in scene.members[DRIVER].points.values()), default=0.0) or 1.0
    units, direction = _unknowns(scene, pair, motion.bodies)
    drive = (0j, 0j, 1.0) if scene.driver.kind == "rotating" else (direction, units[0][1], 0.0)
    reactions, (driving,), cond = _solve_body(scene, (DRIVER,), (pair,), size, motion.bodies,
                                              loads, couples, known, n, extra=(drive,))
    return reactions, driving, cond


# --- the two checks ---------------------------------------------------------------------

def _unit_velocities(scene: Scene, motion: Motion) -> dict[int, Body]:
    """Every member's motion per unit driver speed (virtual velocities): the actual ones
    divided by ω₂, or solved again at ω₂ = 1 when the mechanism stands still."""
    speed = scene.driver.speed
    if speed != 0:
        return {m: dataclasses.replace(b, v=b.v / speed, omega=b.omega / speed)
                for m, b in motion.bodies.items()}
    unit = dataclasses.replace(scene, driver=dataclasses.replace(scene.driver, speed=1.0))
    return solve(unit, motion.at, order=1).bodies


def _virtual_power(bodies: dict[int, Body], loads, couples):
    """Σ F·v + Σ M·ω per unit driver speed, and the sum of the terms' magnitudes."""
    terms = [(np.conj(bodies[ld.member].velocity(ld.local)) * ld.force).real for ld in loads]
    terms += [c.value * bodies[c.member].omega for c in couples]
    return sum(terms, 0.0), sum((np.abs(t) for t in terms), 0.0)


def _lever_forces(scene: Scene, bodies: dict[int, Body], loads, couples, inertias
                  ) -> list[LeverForce]:
    """The forces on Zhukovsky's lever. Inertia forces go to Huygens' centre K as in tasks
    5.3–5.4 (−m·a_B at S, −m·a_SB at K), and every couple becomes two opposite forces at two
    points of its member, as the book replaces M_6 by a force at D."""
    def at(member: int, local, force, name: str) -> LeverForce:
        image = 1j * bodies[member].velocity(local)  # the point's image, turned 90°
        return LeverForce(name, member, image, force, local)

    out = [at(ld.member, ld.local, ld.force, ld.name) for ld in loads if not ld.inertial]
    as_couples = [c for c in couples if not c.inertial]
    for number, inert in inertias.items():
        out.append(at(number, centre_of_mass(scene, number), inert.base_force, f"F_i{number}^S"))
        if inert.huygens_local is None:
            as_couples.append(Couple(f"M_i{number}", number, inert.moment, True))
        else:
            out.append(at(number, inert.huygens_local, inert.relative_force, f"F_i{number}^K"))
    for c in as_couples:
        member = scene.members[c.member]
        p0 = member.points[member.axis[0]]
        p1 = member.points[member.axis[1]] if len(member.axis) > 1 else p0 + 1.0
        arm = (p1 - p0) * bodies[c.member].rot
        force = 1j * arm * c.value / abs(p1 - p0) ** 2  # at p1, its opposite at p0: the couple
        out.append(at(c.member, p1, force, f"{c.name}'"))
        out.append(at(c.member, p0, -force, f"{c.name}''"))
    return out


# --- free bodies, for the force polygons ------------------------------------------------

@dataclass(frozen=True)
class Action:
    """One force on a free body at one position: a load, or F_pq from outside the body."""

    name: str  # F_5, G_3, F_i3, F_45
    force: complex
    point: complex
    known: bool  # a load, or a reaction found before this body (it is drawn first)


def free_body(k: Kinetostatics, members: tuple[int, ...], index: int) -> list[Action]:
    """The forces on a group of members (a free body) at one position, in the book's drawing
    order: loads, then reactions already known from the later groups, then the body's own
    unknown reactions, which close the polygon. Their sum is zero."""
    body = set(members)
    loads = [Action(ld.name, complex(ld.force[index]), complex(ld.point[index]), True)
             for ld in k.loads if ld.member in body]
    solved_before = _solved_before(k, members)
    reactions = [Action(f"F_{r.by}{r.on}", complex(r.force[index]), complex(r.point[index]),
                        r.by in solved_before)
                 for q in members for r in k.on_member(q) if r.by not in body]
    return loads + sorted(reactions, key=lambda a: not a.known)


def _solved_before(k: Kinetostatics, members: tuple[int, ...]) -> set[int]:
    """Members of the groups solved before the group holding ``members`` (the later ones)."""
    groups = {g.name: g.members for g in k.motion.structure.groups}
    groups["driver"] = (DRIVER,)
    out: set[int] = set()
    for name in k.order:
        if set(groups[name]) & set(members):
            return out
        out |= set(groups[name])
    return out
