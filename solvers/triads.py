"""Class III Assur groups (triads) by Newton's method on the group's own small system.

A triad has no closed form, so each member of the group gets an unknown pose — the
position of its frame's origin and its angle, (x, y, θ) — and every pair gives two
equations: a revolute pair makes its point coincide on both members; a prismatic pair
keeps the slider's angle locked to the guide's and its point on the guide's line.
Four members, six pairs: a 12×12 system per position, solved for the whole cycle at once
with batched ``np.linalg.solve``.

Newton needs a start on the right branch. The group is assembled once at the scene's
own instant (from the points the scene file sketches in ``[guess]``), then carried
along a coarse march over the driver's range — each step predicted from the exact
rates and corrected by Newton — and every requested position starts from its nearest
march node. Velocities and accelerations need no iteration: differentiating the
constraints gives linear systems with the same matrix (the Jacobian).

Nothing here is specific to four members: the pairs and members of the group set the
size of the system.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from mechanisms.schema import Pair, Scene

from .budget import check
from .loops import cross
from .state import Body, cplx
from .structure import Group

STALL = 8  # see newton(): how long a requested position may go without progress
MAX_ITERATIONS = 40
MARCH_STEPS = 36  # coarse nodes per full turn of a crank (10°)
MARCH_SPLITS = 5  # halvings of a march step that Newton cannot close from its prediction
MARCH_ITERATIONS = 12  # more than this from a predicted pose means Newton wandered
TOL = 1e-10  # Newton's default stopping residual, relative to the group's size
MARCH_TOL = 1e-12  # the march carries the branch: always tight, whatever the user's tolerance


@dataclass
class TriadSolution:
    bodies: dict[int, Body]
    transmission: np.ndarray | None  # smallest/largest singular value of the scaled Jacobian
    closed: np.ndarray
    iterations: np.ndarray  # Newton iterations per position
    residual: np.ndarray  # final largest constraint violation per position, m


class _System:
    """The constraints of one group, with their first and second time derivatives."""

    def __init__(self, scene: Scene, group: Group, size: float):
        self.scene, self.group, self.size = scene, group, size
        self.unknown = group.members
        self.column = {m: 3 * i for i, m in enumerate(self.unknown)}

    def _local(self, pair: Pair, member: int) -> complex:
        if pair.kind == "prismatic" and member == pair.members[0]:
            return self.scene.points_of(member)[pair.through]
        return self.scene.points_of(member)[pair.point]

    def values(self, bodies: dict[int, Body], level: int) -> np.ndarray:
        """The constraint rows (…, 12): positions (level 0), or their first or second time
        derivatives read from the bodies' ω, v (level 1) and ε, a (level 2)."""
        rows = []
        for pair in self.group.pairs:
            p, q = pair.members
            bp, bq = bodies[p], bodies[q]
            lp, lq = self._local(pair, p), self._local(pair, q)
            if pair.kind == "revolute":
                f = (bp.position, bp.velocity, bp.acceleration)[level]
                g = (bq.position, bq.velocity, bq.acceleration)[level]
                gap = f(lp) - g(lq)
                rows += [np.real(gap), np.imag(gap)]
                continue
            # prismatic: p is the guide, q the slider
            if level == 0:
                turn = np.angle(bq.rot * np.conj(bp.rot) * np.exp(-1j * pair.lock))
            else:
                turn = bq.omega - bp.omega if level == 1 else bq.epsilon - bp.epsilon
            direction = np.exp(1j * pair.angle) * bp.rot
            d = bq.position(lq) - bp.position(lp)
            if level == 0:
                line = cross(direction, d)
            else:
                d1 = bq.velocity(lq) - bp.velocity(lp)
                if level == 1:
                    line = bp.omega * cross(1j * direction, d) + cross(direction, d1)
                else:
                    d2 = bq.acceleration(lq) - bp.acceleration(lp)
                    line = (cross((1j * bp.epsilon - bp.omega ** 2) * direction, d)
                            + 2 * bp.omega * cross(1j * direction, d1) + cross(direction, d2))
            rows += [turn * self.size, line]
        shape = np.broadcast_shapes(*(np.shape(r) for r in rows))
        return np.stack([np.broadcast_to(r, shape) for r in rows], axis=-1)

    def jacobian(self, bodies: dict[int, Body]) -> np.ndarray:
        """∂(rows)/∂(x, y, θ of each unknown member), shape (N, 12, 12)."""
        n = len(next(iter(bodies[m].z for m in self.unknown)))
        jac = np.zeros((n, 2 * len(self.group.pairs), 3 * len(self.unknown)))
        for k, pair in enumerate(self.group.pairs):
            r = 2 * k
            p, q = pair.members
            if pair.kind == "revolute":
                for member, sign in ((p, 1.0), (q, -1.0)):
                    if member in self.column:
                        c = self.column[member]
                        arm = 1j * bodies[member].arm(self._local(pair, member))
                        jac[:, r, c], jac[:, r + 1, c + 1] = sign, sign
                        jac[:, r, c + 2], jac[:, r + 1, c + 2] = sign * arm.real, sign * arm.imag
                continue
            bp, bq = bodies[p], bodies[q]
            direction = np.exp(1j * pair.angle) * bp.rot
            d = bq.position(self._local(pair, q)) - bp.position(self._local(pair, p))
            for member, sign in ((q, 1.0), (p, -1.0)):
                if member not in self.column:
                    continue
                c = self.column[member]
                jac[:, r, c + 2] = sign * self.size
                arm = 1j * bodies[member].arm(self._local(pair, member))
                jac[:, r + 1, c] = sign * cross(direction, 1)
                jac[:, r + 1, c + 1] = sign * cross(direction, 1j)
                jac[:, r + 1, c + 2] = sign * cross(direction, arm)
            if p in self.column:  # turning the guide turns its line
                jac[:, r + 1, self.column[p] + 2] += cross(1j * direction, d)
        return jac


def _solve(jac: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """Batched solve; an exactly singular matrix (a dead centre hit exactly) gives NaN there
    instead of failing the whole batch."""
    try:
        return np.linalg.solve(jac, rhs[..., None])[..., 0]
    except np.linalg.LinAlgError:
        out = np.full(rhs.shape, np.nan)
        ok = np.abs(np.linalg.det(jac)) > 0
        if ok.any():
            out[ok] = np.linalg.solve(jac[ok], rhs[ok][..., None])[..., 0]
        return out


def _poses(unknown, z: np.ndarray, th: np.ndarray) -> dict[int, Body]:
    """Bodies of the unknown members from poses z (N, m) and θ (N, m), origin at local 0."""
    return {m: Body(rot=cplx(np.cos(th[:, i]), np.sin(th[:, i])), z=z[:, i])
            for i, m in enumerate(unknown)}


def pose_bodies(scene: Scene, group: Group, size: float, z: np.ndarray,
                th: np.ndarray) -> dict[int, Body]:
    """The group's members placed at poses z (N, m) and θ (N, m), as ``poses`` finds them."""
    return _poses(_System(scene, group, size).unknown, z, th)


def _take(body: Body, idx) -> Body:
    """A known member's motion at some positions only (constants, and a single position
    shared by many starts, stay as they are and broadcast)."""
    def pick(v):
        return v[idx] if np.size(v) > 1 else v
    return Body(pick(body.rot), pick(body.z), body.ref, pick(body.omega), pick(body.v),
                pick(body.epsilon), pick(body.a), pick(body.angle))


def newton(system: _System, known: dict[int, Body], z, th, tol: float, stall: int = MAX_ITERATIONS):
    """Newton's method from poses (z, θ) for all positions at once.

    Returns (z, θ, iterations, residual in m); positions that do not converge keep NaN.
    ``stall`` gives up a position early when its residual stops falling: right for many
    positions started from good predictions, where a position past the group's limit (no
    pose there) would otherwise wander through all the iterations; the march, which must
    cross dead points, keeps every iteration.
    """
    n = len(z)
    iterations = np.zeros(n, dtype=int)
    active = np.ones(n, dtype=bool)
    residual = np.full(n, np.inf)
    best = np.full(n, np.inf)  # the smallest residual so far, and when it was reached
    since = np.zeros(n, dtype=int)
    for _ in range(MAX_ITERATIONS):
        check()
        idx = np.flatnonzero(active)
        sub = {m: _take(b, idx) for m, b in known.items()}
        sub.update(_poses(system.unknown, z[idx], th[idx]))
        rows = system.values(sub, 0)
        err = np.max(np.abs(rows), axis=-1)
        residual[idx] = err
        improved = err < 0.9 * best[idx]
        best[idx] = np.where(improved, err, best[idx])
        since[idx] = np.where(improved, 0, since[idx] + 1)
        done = ~(err > tol * system.size)  # NaN is never done: it is a failure
        # diverged, or stalled (``stall`` iterations without a 10 % smaller residual)
        bad = ~np.isfinite(err) | (err > 1e3 * system.size) | (~done & (since[idx] > stall))
        active[idx[done | bad]] = False
        if bad.any():
            z[idx[bad]], th[idx[bad]] = np.nan, np.nan
        keep = ~done & ~bad
        step_idx = idx[keep]
        if step_idx.size == 0:
            break
        step = _solve(system.jacobian({m: _take(b, np.flatnonzero(keep)) for m, b in sub.items()}),
                      -rows[keep])
        iterations[step_idx] += 1
        z[step_idx] += cplx(step[:, 0::3], step[:, 1::3])
        th[step_idx] += step[:, 2::3]
    else:
        z[active], th[active] = np.nan, np.nan  # ran out of iterations
    return z, th, iterations, residual


@dataclass(frozen=True)
class Iterate:
    """One iterate of Newton's method at one position, for showing the method at work."""

    residual: float  # m: the largest gap left in the group's pairs
    angles: dict[int, float]  # θ of each member of the group, rad
    correction: float  # the size of the step that follows (m, and rad times the group's size)


def newton_trace(scene: Scene, group: Group, motion, index: int, start: int, size: float,
                 tol: float = TOL) -> list[Iterate]:
    """Newton's method for ``group`` at position ``index`` of a solved ``motion``, started
    from the group's pose at position ``start`` (a neighbouring one, as a student iterates
    from the last position drawn), every iterate kept. The solver runs the same iteration
    batched over the cycle (``newton``); this one is for showing it."""
    known = {m: _take(b, np.array([index])) for m, b in motion.bodies.items()
             if m not in group.members}
    system = _System(scene, group, size)
    z = np.array([[complex(motion.bodies[m].position(0j)[start]) for m in system.unknown]])
    th = np.array([[float(motion.bodies[m].theta[start]) for m in system.unknown]])
    scale = np.tile([1.0, 1.0, size], len(system.unknown))  # a turn counts as its arc
    out: list[Iterate] = []
    for _ in range(MAX_ITERATIONS):
        bodies = {**known, **_poses(system.unknown, z, th)}
        rows = system.values(bodies, 0)
        residual = float(np.max(np.abs(rows)))
        done = not residual > tol * size
        step = np.zeros(3 * len(system.unknown)) if done else _solve(
            system.jacobian(bodies), -rows)[0]
        out.append(Iterate(residual, dict(zip(system.unknown, map(float, th[0]))),
                           float(np.max(np.abs(step * scale)))))
        if done or not np.all(np.isfinite(step)):
            break
        z += cplx(step[0::3], step[1::3])
        th += step[2::3]
    return out


def rates(system: _System, known: dict[int, Body], bodies: dict[int, Body], level: int,
          jac: np.ndarray) -> np.ndarray:
    """Velocities (level 1) or accelerations (level 2) of the unknown members: the constraint
    derivative with the unknown rates set to zero is what the known motion forces."""
    zero = {m: Body(b.rot, b.z, 0j, b.omega if level == 2 else 0.0, b.v if level == 2 else 0j,
                    0.0, 0j) for m, b in bodies.items()}
    return _solve(jac, -system.values({**known, **zero}, level))


def solve_triad(scene: Scene, group: Group, at: np.ndarray, known: dict[int, Body], order: int,
                start: tuple[np.ndarray, np.ndarray],
                known_at: Callable[[np.ndarray], dict[int, Body]], *, tol: float = TOL,
                size: float = 1.0, march: tuple | None = None) -> TriadSolution:
    """Positions (and rates up to ``order``) of a class III group at driver values ``at``.

    ``start`` is (driver value, z, θ per member): the group assembled where the scene
    sketches it;
    ``known_at(values)`` gives the known members at other driver values, with rates per
    unit driver speed (dq/dφ₂), for the march that carries the branch; ``march``, when
    given, is that march already made (``prepare_march``) for a range covering ``at``.
    """
    system = _System(scene, group, size)
    march = march or prepare_march(scene, group, at, start, known_at, size)
    nodes = march[0]
    at = _onto_march(scene, at, nodes)
    m = len(group.members)
    z = np.full((at.size, m), np.nan, dtype=complex)
    th = np.full((at.size, m), np.nan)
    iterations = np.zeros(at.size, dtype=int)
    residual = np.full(at.size, np.nan)
    todo = np.flatnonzero(np.isfinite(at))  # the values the branch reaches
    for rank in (0, 1):  # the nearest node; then, where that failed, the next one
        if rank == 1:
            todo = todo[~np.all(np.isfinite(z[todo]), axis=1)]
        if todo.size == 0 or rank >= len(nodes):
            break
        near = np.argsort(np.abs(at[todo, None] - nodes[None, :]), axis=1)[:, rank]
        sub = {n: _take(b, todo) for n, b in known.items()}
        z[todo], th[todo], it, residual[todo] = _from_node(system, sub, at[todo], near, march, tol)
        iterations[todo] += it
    closed = np.all(np.isfinite(z), axis=1)
    bodies = _poses(group.members, z, th)
    if order < 1:
        return TriadSolution(bodies, None, closed, iterations, residual)
    jac = system.jacobian({**known, **bodies})
    with np.errstate(invalid="ignore"):
        sv = np.linalg.svd(np.where(np.isfinite(jac), jac, 0.0) * _column_scale(system),
                           compute_uv=False)
    transmission = np.where(closed, sv[:, -1] / sv[:, 0], np.nan)
    _set_rates(bodies, rates(system, known, bodies, 1, jac), "omega", "v")
    if order >= 2:
        _set_rates(bodies, rates(system, known, bodies, 2, jac), "epsilon", "a")
    return TriadSolution(bodies, transmission, closed, iterations, residual)


def _onto_march(scene: Scene, at: np.ndarray, nodes: np.ndarray) -> np.ndarray:
    """Each value as a driver value inside the range the march carried the branch over, or
    NaN where it lies outside (the branch does not reach it). A crank angle and the same
    angle a turn on are one position: the turn (…, −2π, 0, +2π, …) that falls inside is
    taken, so the branch comes from the march's own continuous path, even where reaching a
    value directly would mean crossing a dead point backwards."""
    lo, hi = nodes[0] - 1e-12, nodes[-1] + 1e-12
    shifts = np.arange(-2, 3) * 2 * math.pi if scene.driver.kind == "rotating" else np.zeros(1)
    candidates = at[None, :] + shifts[:, None]
    inside = (candidates >= lo) & (candidates <= hi)
    pick = np.argmax(inside / (1.0 + np.abs(shifts))[:, None], axis=0)  # inside, least shift
    out = candidates[pick, np.arange(at.size)]
    return np.where(inside.any(axis=0), out, np.nan)


def _from_node(system, known, at, node, march, tol):
    """Newton for every position, started from the pose predicted by its march node."""
    nodes, z_nodes, th_nodes, dz_nodes, dth_nodes = march
    h = (at - nodes[node])[:, None]
    return newton(system, known, z_nodes[node] + dz_nodes[node] * h,
                  th_nodes[node] + dth_nodes[node] * h, tol, stall=STALL)


def _column_scale(system: _System) -> np.ndarray:
    """Angle columns (m per rad) over the group's size, so every entry is dimensionless."""
    return np.tile([1.0, 1.0, 1.0 / system.size], len(system.unknown))


def _set_rates(bodies: dict[int, Body], x: np.ndarray, angular: str, linear: str) -> None:
    for i, b in enumerate(bodies.values()):
        setattr(b, angular, x[:, 3 * i + 2])
        setattr(b, linear, cplx(x[:, 3 * i], x[:, 3 * i + 1]))


def prepare_march(scene: Scene, group: Group, at: np.ndarray, start, known_at, size: float):
    """The march that carries the branch over ``at`` (see ``_march``): the costly, sequential
    part of a class III solve, and the same for every driver value within its range."""
    return _march(_System(scene, group, size), scene, at, start, known_at)


def _march(system, scene, at, start, known_at):
    """Carry the assembled pose from the scene's instant over the driver's range in coarse
    steps (predictor: the exact rate; corrector: Newton), splitting a step where needed.
    Returns every driver value the branch was carried to (sorted), with its pose and pose
    rate per unit driver motion: the branch ends where the march stopped."""
    a0, *pose = start
    lo, hi = min(float(np.min(at)), a0), max(float(np.max(at)), a0)
    # steps of 10° for a crank, of a 36th of the group's size for a slider
    h = (2 * math.pi if scene.driver.kind == "rotating" else system.size) / MARCH_STEPS
    up = a0 + h * np.arange(1, math.ceil((hi - a0) / h - 1e-9) + 1)
    down = a0 - h * np.arange(1, math.ceil((a0 - lo) / h - 1e-9) + 1)
    known_first = {n: _take(b, [0]) for n, b in known_at(np.array([a0])).items()}
    first = (a0, pose[0], pose[1], *_pose_rate(system, known_first, *pose))
    trail = [first]
    for targets in (up, down):
        known = known_at(targets)
        state = first
        for i, b in enumerate(targets):
            check()
            k = {n: _take(bd, [i]) for n, bd in known.items()}
            if not _step(system, known_at, state, b, k, trail):
                break
            state = trail[-1]
    trail.sort(key=lambda node: node[0])
    nodes, z, th, dz, dth = (np.array(column) for column in zip(*trail))
    return nodes, z, th, dz, dth


def _pose_rate(system, known, z, th):
    """dz/dq, dθ/dq of the group's pose (per unit driver motion) at one position."""
    bodies = _poses(system.unknown, z[None], th[None])
    x = rates(system, known, bodies, 1, system.jacobian({**known, **bodies}))[0]
    return cplx(x[0::3], x[1::3]), x[2::3]


def _step(system, known_at, state, b, known_b, trail, depth: int = 0) -> bool:
    """Carry the pose from ``state`` (value, pose, rate) to driver value b: predicted with
    the rate, corrected by Newton; every pose reached is appended to ``trail``. From a good
    prediction Newton converges in a few steps; one that needs many has wandered and may
    land on the other assembly (the march once jumped branches that way, silently, where
    zbirka-4.1's group reaches its limit). Such a step is split in two (up to 5 times:
    10° down to 0.3°); where even the smallest step fails, the branch ends."""
    a, z0, th0, dz0, dth0 = state
    h = b - a
    z, th, iterations, _ = newton(system, known_b, (z0 + dz0 * h)[None].copy(),
                                  (th0 + dth0 * h)[None].copy(), MARCH_TOL)
    if np.all(np.isfinite(z)) and iterations[0] <= MARCH_ITERATIONS:
        trail.append((b, z[0], th[0], *_pose_rate(system, known_b, z[0], th[0])))
        return True
    if depth >= MARCH_SPLITS:
        return False
    mid = 0.5 * (a + b)
    known_mid = {n: _take(bd, [0]) for n, bd in known_at(np.array([mid])).items()}
    if not _step(system, known_at, state, mid, known_mid, trail, depth + 1):
        return False
    return _step(system, known_at, trail[-1], b, known_b, trail, depth + 1)


def assemble(scene: Scene, group: Group, known: dict[int, Body], size: float,
             tol: float = 1e-12, starts: int = 64) -> tuple[np.ndarray, np.ndarray] | None:
    """The group's pose at the scene's instant, on the branch the scene sketches: of the
    poses that converge (``poses``), the one closest to the ``[guess]`` points (or the first,
    without guesses)."""
    found = poses(scene, group, known, size, tol, starts)
    if found is None:
        return None
    z, th = found
    miss = np.zeros(len(z))
    for i, member in enumerate(group.members):
        rot = np.exp(1j * th[:, i])
        for name, local in scene.members[member].points.items():
            if name in scene.guess:
                miss += np.abs(z[:, i] + local * rot - scene.guess[name]) ** 2
    best = int(np.argmin(miss))
    return z[best], th[best]


def poses(scene: Scene, group: Group, known: dict[int, Body], size: float,
          tol: float = 1e-12, starts: int = 64) -> tuple[np.ndarray, np.ndarray] | None:
    """Every pose Newton reaches from many deterministic starts at once (z and θ of each
    member, one row a start that converged; the same assembly may come more than once),
    or None when none converges."""
    system = _System(scene, group, size)
    rng = np.random.default_rng(7)
    anchors = [known[p.other(m)].position(system._local(p, p.other(m)))
               for p in group.pairs for m in p.members if m in group.members
               and p.other(m) not in group.members]
    centre = complex(np.mean([complex(np.ravel(a)[0]) for a in anchors]))
    m = len(group.members)
    th = rng.uniform(0, 2 * math.pi, (starts, m))
    z = centre + size * (rng.uniform(-1, 1, (starts, m)) + 1j * rng.uniform(-1, 1, (starts, m)))
    for i, member in enumerate(group.members):
        z[:, i] = _guess_origin(scene, member, th[:, i], z[:, i])
    z, th, _, _ = newton(system, known, z, th, tol)
    ok = np.all(np.isfinite(z), axis=1)
    return (z[ok], th[ok]) if ok.any() else None


def _guess_origin(scene: Scene, member: int, th: np.ndarray, default: np.ndarray) -> np.ndarray:
    """Put a start's member where the scene sketches it: its first guessed point at the guess
    (the angle stays the start's own, or follows two guessed points)."""
    points = [(local, scene.guess[name]) for name, local in scene.members[member].points.items()
              if name in scene.guess]
    if not points:
        return default
    (l0, g0), *rest = points
    if rest:
        (l1, g1) = rest[0]
        th[:] = np.angle((g1 - g0) / (l1 - l0))
    return g0 - l0 * np.exp(1j * th)
