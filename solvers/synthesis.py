"""Path synthesis: a four-bar whose coupler point passes given points in order
(docs/synthesis.md).

The search runs the other way from analysis and stays in this house: SciPy's
``differential_evolution`` over the four-bar's shape (the whole population's coupler points in
one numpy call, both assembly branches at once), then ``least_squares`` on the residual
vector, then the answer is built as a scene and **re-solved by the kinematics core** over the
whole turn: the error reported is the re-solved one, never the optimiser's own.

Shape parameters, so that every candidate is a crank that turns fully (Grashof, the crank
the shortest link): with the crank ``r2`` and ``x, y, z ≥ 0``,
``frame r1 = r2 + y + z``, ``coupler r3 = r2 + x + z``, ``rocker r4 = r2 + x + y``. Then
``r2`` is the shortest and the longest excess is at most the sum of the other two, which is
Grashof's s + l ≤ p + q; every such linkage has exactly one (r2, x, y, z). A zero x, y or
z is a change-point linkage (s + l = p + q), kept out by a small lower bound.

The assembly branch of a Grashof crank never changes over the turn, so one sign per
mechanism is the "one branch through every point" rule: a jump cannot happen.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Callable

import numpy as np
from scipy.optimize import differential_evolution, least_squares

from mechanisms import parse_scene
from mechanisms.schema import Scene
from mechanisms.synthesis import SynthesisTask

from .kinematics import solve

TAU = 2 * math.pi
SAMPLES = 120  # coupler-curve samples per turn where the timing is free (refined by projection)
MARGIN = 1e-6  # of the largest length: how far from a change point (s + l = p + q) x, y, z stay
TURN = 720  # positions of the whole turn the answer is re-solved at
AGREE = 1e-7  # re-solved and searched coupler points agree to this share of the task's size
DEFAULT_BUDGET = 300_000
DEFAULT_SECONDS = 6.0
STRATEGY = "rand1bin"  # measured against best1bin and currenttobest1bin: docs/synthesis.md
POPSIZE = 15
STARTS = 8
RESTARTS = 3


class SynthesisError(Exception):
    """The search found no working four-bar (the message says why)."""


@dataclass(frozen=True)
class Linkage:
    """A found four-bar in the builder's names: O the crank's pivot, D the rocker's, A the
    crank pin, B the coupler–rocker joint, M the coupler point ``point`` = [along A→B, to its
    left]. ``angles`` are the crank's angles from the frame line O→D at the precision points
    (rad); ``branch`` the assembly sign."""

    O: complex
    frame_angle: float  # rad, direction of O→D from +x
    frame: float
    crank: float
    coupler: float
    rocker: float
    point: complex
    branch: int
    angles: tuple[float, ...]
    turning: int = 1  # +1 counter-clockwise, −1 clockwise

    @property
    def D(self) -> complex:
        return self.O + self.frame * np.exp(1j * self.frame_angle)


@dataclass
class Result:
    """A certified answer: the linkage, its scene, and the positions the kinematics core
    re-solved at the precision points."""

    linkage: Linkage
    scene: Scene
    scene_toml: str
    objective: float  # Σ of squared distances, re-solved
    errors: np.ndarray  # each point's distance, re-solved
    positions: dict[str, np.ndarray]  # "A", "B", "M": complex, one per precision point
    crank_deg: np.ndarray  # φ₂ from +x at each point, as ``solve --at`` takes it
    evaluations: int
    seconds: float
    searched: float  # the optimiser's own objective, for the record


# ---------------------------------------------------------------------------------------
# the coupler point of many four-bars at once


def lengths(shape: np.ndarray) -> tuple[np.ndarray, ...]:
    """(r1, r2, r3, r4) from the shape rows (r2, x, y, z)."""
    r2, x, y, z = shape[0], shape[1], shape[2], shape[3]
    return r2 + y + z, r2, r2 + x + z, r2 + x + y


def coupler(shape: np.ndarray, theta: np.ndarray, branch: float) -> tuple[np.ndarray, ...]:
    """A, B and M in each linkage's own frame (O at 0, D on +x) at crank angles ``theta``.

    ``shape`` rows (r2, x, y, z, cx, cy), columns the linkages (S); ``theta`` (S, K) or (K,).
    Returns complex arrays (S, K)."""
    r1, r2, r3, r4 = (v[:, None] for v in lengths(shape))
    c = (shape[4] + 1j * shape[5])[:, None]
    a = r2 * np.exp(1j * np.asarray(theta))
    d = r1 - a
    span2 = d.real ** 2 + d.imag ** 2
    span = np.sqrt(span2)
    cos = np.clip((r3 * r3 + span2 - r4 * r4) / (2 * r3 * span), -1.0, 1.0)
    e3 = d / span * (cos + 1j * branch * np.sqrt(1 - cos * cos))
    return a, a + r3 * e3, a + c * e3


# ---------------------------------------------------------------------------------------
# the problem the optimisers see


def procrustes(local: np.ndarray, target: np.ndarray, pivot: complex | None,
               angle: float | None) -> tuple[np.ndarray, np.ndarray]:
    """(O, e^{iθ₀}) laying the local points (…, n) on the targets by a rigid motion with
    least squared misses: closed form (Procrustes), the pivot or the angle (degrees) kept
    where given."""
    fixed = local.shape[:-1] + (1,)
    if angle is not None:
        rot = np.full(fixed, np.exp(1j * math.radians(angle)))
    else:
        if pivot is None:
            lc, tc = local - local.mean(axis=-1, keepdims=True), target - target.mean()
        else:
            lc, tc = local, target - pivot
        s = np.sum(np.conj(lc) * tc, axis=-1, keepdims=True)
        rot = np.where(s == 0, 1.0, s / np.where(s == 0, 1, np.abs(s)))
    if pivot is None:
        return np.mean(target - rot * local, axis=-1, keepdims=True), rot
    return np.full(fixed, pivot), rot


def nearest(curve: np.ndarray, target: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each target's squared distance to a sampled closed curve (S, K), measured to the
    nearest sample's two chords, and that sample's index: (S, n) each."""
    # the nearest sample in single precision (its index is all that is kept; the distance
    # is then measured in double precision): half the memory traffic of the (S, n, K) table
    planar = np.array([target.real, target.imag], dtype=np.float32).T  # (n, 2)
    samples = np.stack([curve.real, curve.imag], axis=1).astype(np.float32)  # (S, 2, K)
    square = np.einsum("sck,sck->sk", samples, samples)
    k = np.argmin(square[:, None, :] - 2 * (planar @ samples), axis=-1)  # (S, n)
    rows = np.arange(curve.shape[0])[:, None]
    here = curve[rows, k]
    rel = target - here
    best = rel.real ** 2 + rel.imag ** 2
    for side in (-1, 1):
        chord = curve[rows, (k + side) % curve.shape[1]] - here
        t = np.clip((rel * np.conj(chord)).real / np.maximum(np.abs(chord) ** 2, 1e-300), 0, 1)
        miss = rel - t * chord
        best = np.minimum(best, miss.real ** 2 + miss.imag ** 2)
    return best, k


def overreach(task: SynthesisTask, x: np.ndarray, pivot: np.ndarray,
              rot: np.ndarray) -> list[np.ndarray]:
    """How far each candidate (a column of ``x``; ``pivot``, ``rot`` one each) breaks each
    bound the search's box cannot hold, one array per rule, 0 where it keeps it: the frame,
    the coupler and the rocker against ``max_length``; O's and D's x and y against the box.
    (Grashof and the crank's shortness are the box bounds of r2, x, y, z.)"""
    r1, _, r3, r4 = lengths(x)
    big, box = task.max_length, task.box
    d = pivot + r1 * rot
    return ([np.maximum(0, r - big) for r in (r1, r3, r4)]
            + [np.maximum(0, np.abs(c) - box) for q in (pivot, d) for c in (q.real, q.imag)])


def outside(task: SynthesisTask, x: np.ndarray, pivot: np.ndarray, rot: np.ndarray) -> np.ndarray:
    """The search's penalty: all of ``overreach`` together (``pivot``, ``rot``: (S, 1))."""
    return sum(overreach(task, x, pivot[..., 0], rot[..., 0]))


class _Scale:
    """The search's own coordinates ``u``: lengths on a log scale, offsets and pivots on an
    asinh scale around the points, so that a search whose bounds are fifty times the path's
    size still spends its samples where four-bars of the path's size are. The map is one to
    one onto the same bounds: nothing the task allows is left out."""

    def __init__(self, target: np.ndarray, bounds: list[tuple[float, float]], kinds: list[str]):
        spread = float(np.max(np.abs(target[:, None] - target[None, :])))
        self.unit, floor, centre = spread / 4, spread * 1e-4, target.mean()
        self.kinds, self.bounds = kinds, np.array(bounds)
        # an offset is centred on 0 (the coupler's own frame), a pivot on the points
        self.middles = np.array([{"pivot_x": centre.real, "pivot_y": centre.imag}.get(k, 0.0)
                                 for k in kinds])
        self.search_bounds = []
        for kind, (lo, hi), mid in zip(kinds, bounds, self.middles):
            if kind == "log":
                self.search_bounds.append((math.log(max(lo, min(floor, hi / 10))), math.log(hi)))
            elif kind == "linear":
                self.search_bounds.append((lo, hi))
            else:
                self.search_bounds.append((math.asinh((lo - mid) / self.unit),
                                           math.asinh((hi - mid) / self.unit)))

    def decode(self, u: np.ndarray) -> np.ndarray:
        """The four-bar's numbers (rows as ``bounds``) from the search's coordinates."""
        x = np.empty_like(u)
        for i, kind in enumerate(self.kinds):
            if kind == "log":
                x[i] = np.exp(u[i])
            elif kind == "linear":
                x[i] = u[i]
            else:
                x[i] = self.middles[i] + self.unit * np.sinh(u[i])
        lo, hi = (b[:, None] if x.ndim == 2 else b for b in self.bounds.T)
        return np.clip(x, lo, hi)


class _Problem:
    """The task turned into vectors: which numbers the search varies, their bounds, and the
    error of many candidates at once."""

    def __init__(self, task: SynthesisTask):
        self.task = task
        self.target = np.array(task.points)
        self.n = len(self.target)
        # the points' spread, Σ|p − p̄|²: what a bad candidate's penalty is counted in
        self.spread = float(np.sum(np.abs(self.target - self.target.mean()) ** 2)) or 1.0
        big, box = task.max_length, task.box
        low = max(task.min_length, 1e-9 * big)
        margin = MARGIN * big
        self.shape_bounds = [(low, big), (margin, big), (margin, big), (margin, big),
                             (-box, box), (-box, box)]
        self.free_pivot = task.crank_pivot is None
        self.free_angle = task.frame_angle is None
        # the placement the search varies (the rest is fixed, or found in closed form)
        self.placed = task.timing == "free"
        place, kinds = [], ["log"] * 4 + ["offset"] * 2
        if self.placed and self.free_angle:
            place.append((-math.pi, math.pi))
            kinds.append("linear")
        if self.placed and self.free_pivot:
            place += [(-box, box), (-box, box)]
            kinds += ["pivot_x", "pivot_y"]
        if task.timing == "steps":  # the crank's angle at the first point (the steps give the rest)
            place.append((0.0, TAU))
            kinds.append("linear")
        self.bounds = self.shape_bounds + place
        self.warp = _Scale(self.target, self.bounds, kinds)
        self.search_bounds = self.warp.search_bounds
        if task.timing == "angles":
            self.given = np.radians(np.array(task.crank_angles))
        elif task.timing == "steps":
            self.given = np.radians(np.concatenate([[0.0], np.cumsum(task.crank_steps)]))

    # --- placement: O and the frame line's direction ---------------------------------

    def placement(self, x: np.ndarray, local: np.ndarray):
        """(O, e^{iθ₀}) per candidate: the task's where fixed, the search's where it varies
        them, else the rigid motion that best lays the local points on the targets
        (closed-form Procrustes: no search spent on what has a formula)."""
        task, t = self.task, self.target
        if self.placed:
            k, count = 6, x.shape[1]
            angle = x[k] if self.free_angle else np.full(count, math.radians(task.frame_angle))
            k += self.free_angle
            pivot = (x[k] + 1j * x[k + 1]) if self.free_pivot else np.full(count, task.crank_pivot)
            return pivot[:, None], np.exp(1j * angle)[:, None]
        return procrustes(local, t, task.crank_pivot, task.frame_angle)

    # --- the search's objective ----------------------------------------------------------

    def cost(self, u: np.ndarray) -> np.ndarray:
        """Σ of squared distances for each column of the search's ``u`` (the better branch),
        with the bounds' breaches ranked behind every candidate that keeps them."""
        x = self.warp.decode(u)
        best = np.full(x.shape[1], np.inf)
        for branch in (1.0, -1.0):
            best = np.minimum(best, self._cost(x, branch))
        return best

    def _cost(self, x: np.ndarray, branch: float) -> np.ndarray:
        if self.task.timing == "free":
            err, pivot, rot = self._free(x, branch)
        else:
            _, _, m = coupler(x, self.timed(x), branch)
            pivot, rot = self.placement(x, m)
            err = np.sum(np.abs(pivot + rot * m - self.target) ** 2, axis=-1)
        over = outside(self.task, x, pivot, rot)
        err = np.where(np.isfinite(err), err, 1e300)
        return np.where(over > 0, 1e12 * self.spread * (1 + over), err)

    def _free(self, x, branch):
        """Each target's nearest point of the sampled curve, refined on the two chords
        beside it; a sequence that needs more than one turn pays its excess."""
        theta = np.linspace(0, TAU, SAMPLES, endpoint=False)
        _, _, m = coupler(x, theta, branch)
        pivot, rot = self.placement(x, m)
        best, k = nearest(pivot + rot * m, self.target)
        travel = np.sum((np.diff(k, axis=-1)) % SAMPLES, axis=-1)
        excess = np.maximum(0, travel - SAMPLES) / SAMPLES
        return np.sum(best, axis=-1) + excess * self.spread, pivot, rot

    def timed(self, x: np.ndarray) -> np.ndarray:
        """The crank's angles at the points, from the frame line: given, or the search's
        first angle and the given steps."""
        if self.task.timing == "steps":
            return x[-1][:, None] + self.given[None, :]
        return self.given

    # --- from a search vector to a linkage, and back ----------------------------------------

    def linkage(self, x: np.ndarray, branch: int) -> Linkage:
        """The linkage a search vector stands for (its crank angles found as the search
        found them: nearest on the curve, or from the first angle and the steps, or given)."""
        col = x[:, None]
        if self.task.timing == "free":
            theta = np.linspace(0, TAU, SAMPLES * 8, endpoint=False)
            _, _, m = coupler(col, theta, branch)
            pivot, rot = self.placement(col, m)
            k = nearest(pivot + rot * m, self.target)[1][0]
            angles = theta[k[0]] + np.concatenate([[0.0], np.cumsum(np.mod(np.diff(theta[k]), TAU))])
        else:
            angles = np.ravel(self.timed(col))
            _, _, m = coupler(col, angles, branch)
            pivot, rot = self.placement(col, m)
        r1, r2, r3, r4 = (float(v[0]) for v in lengths(col))
        return Linkage(O=complex(np.ravel(pivot)[0]), frame_angle=float(np.angle(np.ravel(rot)[0])),
                       frame=r1, crank=r2, coupler=r3, rocker=r4,
                       point=complex(x[4], x[5]), branch=branch,
                       angles=tuple(float(a) for a in angles), turning=self.task.turning)


# ---------------------------------------------------------------------------------------
# the local polish: every free number of the linkage, least squares on the residuals


class _Polish:
    """``least_squares`` over shape, placement and timing, the bounds it cannot express as
    box bounds (lengths, pivots in the box, one turn) as steep hinges."""

    WEIGHT = 1e4  # the hinges' first weight; raised ×100 while a rule is still broken

    def __init__(self, problem: _Problem, linkage: Linkage):
        self.p, self.task = problem, problem.task
        self.branch = linkage.branch
        self.start = linkage

    def vector(self, link: Linkage) -> np.ndarray:
        x = [link.crank, *excess(link), link.point.real, link.point.imag]
        if self.task.frame_angle is None:
            x.append(link.frame_angle)
        if self.task.crank_pivot is None:
            x += [link.O.real, link.O.imag]
        a = np.array(link.angles)
        if self.task.timing == "free":
            x += [a[0], *np.mod(np.diff(a), TAU)]
        elif self.task.timing == "steps":
            x.append(a[0])
        return np.array(x, dtype=float)

    def bounds(self) -> tuple[np.ndarray, np.ndarray]:
        box, turns = self.task.box, (-4 * math.pi, 4 * math.pi)
        pairs = list(self.p.shape_bounds)
        if self.task.frame_angle is None:
            pairs.append(turns)
        if self.task.crank_pivot is None:
            pairs += [(-box, box), (-box, box)]
        if self.task.timing == "free":
            pairs += [turns] + [(0.0, TAU)] * (self.p.n - 1)
        elif self.task.timing == "steps":
            pairs.append(turns)
        return tuple(np.array(v) for v in zip(*pairs))

    def unpack(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """O, e^{iθ₀} (S,) and the crank's angles (S, n) of each column of ``x``."""
        task, count, k = self.task, x.shape[1], 6
        if task.frame_angle is None:
            rot, k = np.exp(1j * x[k]), k + 1
        else:
            rot = np.full(count, np.exp(1j * math.radians(task.frame_angle)))
        if task.crank_pivot is None:
            pivot, k = x[k] + 1j * x[k + 1], k + 2
        else:
            pivot = np.full(count, task.crank_pivot)
        if task.timing == "free":
            theta = x[k][:, None] + np.concatenate([np.zeros((count, 1)),
                                                      np.cumsum(x[k + 1:].T, axis=1)], axis=1)
        elif task.timing == "steps":
            theta = x[k][:, None] + self.p.given[None, :]
        else:
            theta = np.broadcast_to(self.p.given, (count, self.p.n))
        return pivot, rot, theta

    def linkage(self, x: np.ndarray) -> Linkage:
        pivot, rot, theta = self.unpack(x[:, None])
        r1, r2, r3, r4 = (float(v[0]) for v in lengths(x[:4, None]))
        angle = float(np.angle(rot[0])) if self.task.frame_angle is None else math.radians(self.task.frame_angle)
        return Linkage(O=complex(pivot[0]), frame_angle=angle, frame=r1, crank=r2, coupler=r3,
                       rocker=r4, point=complex(x[4], x[5]), branch=self.branch,
                       angles=tuple(float(a) for a in theta[0]), turning=self.task.turning)

    def many(self, x: np.ndarray) -> np.ndarray:
        """The residuals of every column of ``x`` at once (rows: the points' x and y misses,
        then the weighted breaches)."""
        pivot, rot, theta = self.unpack(x)
        _, _, m = coupler(x, theta, self.branch)
        miss = (pivot[:, None] + rot[:, None] * m - self.p.target).T  # (n, S)
        over = overreach(self.task, x, pivot, rot)
        if self.task.timing == "free":
            over.append(np.maximum(0, theta[:, -1] - theta[:, 0] - TAU))
        return np.vstack([miss.real, miss.imag, self.weight * np.array(over)])

    def residuals(self, x: np.ndarray) -> np.ndarray:
        return self.many(x[:, None])[:, 0]

    def jacobian(self, x: np.ndarray) -> np.ndarray:
        """Forward differences, every column perturbed in one call of ``many``."""
        h = 1e-7 * np.maximum(1.0, np.abs(x))
        lo, hi = self.limits
        h = np.where(x + h > hi, -h, h)  # stay inside the bounds
        columns = x[:, None] + np.diag(h)
        both = self.many(np.hstack([x[:, None], columns]))
        return (both[:, 1:] - both[:, :1]) / h

    def run(self, evaluations: int) -> tuple[Linkage, int]:
        """The polished linkage and the evaluations spent. A hinge lets a rule go by a
        hair (the weight against the error's pull): the weight is raised and the polish
        goes on from there until the rules hold, as a penalty method's continuation does."""
        lo, hi = self.limits = self.bounds()
        x = np.clip(self.vector(self.start), lo + 1e-12 * (hi - lo), hi - 1e-12 * (hi - lo))
        spent, self.weight = 0, self.WEIGHT
        for _ in range(4):
            fit = least_squares(self.residuals, x, jac=self.jacobian, bounds=(lo, hi),
                                max_nfev=max(evaluations // (len(x) + 2), 10),
                                x_scale="jac", ftol=1e-14, xtol=1e-14, gtol=1e-14)
            x = fit.x
            spent += int(fit.nfev + (fit.njev or 0) * (len(x) + 1))
            if keeps_rules(settle(self.linkage(x), self.task), self.task):
                break
            self.weight *= 100
        return settle(self.linkage(x), self.task), spent


def excess(link: Linkage) -> tuple[float, float, float]:
    """(x, y, z) from the four lengths (the inverse of ``lengths``)."""
    u, v, w = link.frame - link.crank, link.coupler - link.crank, link.rocker - link.crank
    return (v + w - u) / 2, (u + w - v) / 2, (u + v - w) / 2


def points_of(link: Linkage, angles=None) -> np.ndarray:
    """M at the linkage's precision angles (or at ``angles``), in the task's frame."""
    a, b, m = positions_of(link, angles)
    return m


def positions_of(link: Linkage, angles=None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A, B and M at the crank angles ``angles`` (from the frame line; default the
    precision points'), in the task's frame."""
    theta = np.array(link.angles if angles is None else angles, dtype=float)
    shape = np.array([[link.crank], *[[v] for v in excess(link)],
                      [link.point.real], [link.point.imag]])
    a, b, m = coupler(shape, theta, link.branch)
    rot = np.exp(1j * link.frame_angle)
    return tuple(link.O + rot * v[0] for v in (a, b, m))


def settle(link: Linkage, task: SynthesisTask) -> Linkage:
    """The polished linkage with what its hinges let slip by a hair (at most a millionth of
    the task's size: the weight against the error's pull) put back on the bound itself: a
    length on max_length, a pivot on the box's side, the points' span on one turn. The
    error is then re-solved as for any linkage; a larger breach is left for
    ``keeps_rules`` to refuse."""
    hair = 1e-6 * max(task.max_length, task.box)
    big, box = task.max_length, task.box

    def snap(value: float, low: float, high: float) -> float:
        return min(max(value, low), high) if low - hair <= value <= high + hair else value

    def inside(p: complex) -> complex:
        return complex(snap(p.real, -box, box), snap(p.imag, -box, box))

    pivot = link.O if task.crank_pivot is not None else inside(link.O)
    d = inside(link.D)
    frame, angle = link.frame, link.frame_angle
    if d != link.D or pivot != link.O:
        frame, angle = abs(d - pivot), float(np.angle(d - pivot))
    a = np.array(link.angles)
    if task.timing == "free" and TAU < a[-1] - a[0] <= TAU + hair:
        a = a[0] + (a - a[0]) * (TAU / (a[-1] - a[0]))
    return Linkage(O=pivot, frame_angle=angle if task.frame_angle is None else link.frame_angle,
                   frame=snap(frame, task.min_length, big),
                   crank=snap(link.crank, task.min_length, big),
                   coupler=snap(link.coupler, task.min_length, big),
                   rocker=snap(link.rocker, task.min_length, big), point=link.point,
                   branch=link.branch, angles=tuple(float(v) for v in a), turning=link.turning)


def keeps_rules(link: Linkage, task: SynthesisTask) -> bool:
    """Every rule of the task held (to a float's last digits): Grashof with the crank
    shortest, the lengths, the box, the order within one turn, the timing."""
    slack = 1e-12 * max(task.max_length, task.box)
    lengths_ = (link.frame, link.crank, link.coupler, link.rocker)
    s, l = min(lengths_), max(lengths_)
    grashof = s + l < sum(lengths_) - s - l and link.crank == s
    inside = all(task.min_length - slack <= r <= task.max_length + slack for r in lengths_)
    box = all(abs(c) <= task.box + slack for p in (link.O, link.D) for c in (p.real, p.imag))
    a = np.array(link.angles)
    if task.timing == "free":
        order = bool(np.all(np.diff(a) >= 0)) and a[-1] - a[0] <= TAU * (1 + 1e-12)
    elif task.timing == "steps":
        order = np.allclose(np.diff(a), np.radians(task.crank_steps), atol=1e-9)
    else:
        order = np.allclose(a, np.radians(task.crank_angles), atol=1e-9)
    fixed = ((task.crank_pivot is None or abs(link.O - task.crank_pivot) <= slack)
             and (task.frame_angle is None
                  or abs(np.exp(1j * link.frame_angle) - np.exp(1j * math.radians(task.frame_angle))) < 1e-9))
    return bool(grashof and inside and box and order and fixed)


# ---------------------------------------------------------------------------------------
# the search, and the answer re-solved


def synthesize(task: SynthesisTask, seed: int = 1, budget: int = DEFAULT_BUDGET,
               seconds: float = DEFAULT_SECONDS,
               progress: Callable[[float, float], None] | None = None) -> Result:
    """The best four-bar found for ``task`` within ``budget`` evaluations and ``seconds``,
    re-solved by the kinematics core. ``progress(share done, best so far)`` is told after
    each generation (a page's progress bar).

    The budget is split between ``RESTARTS`` independent searches, each polished from its
    best few members: one search that settles early in a poor basin then costs a share of
    the budget, not the answer."""
    began = time.perf_counter()
    problem = _Problem(task)
    dims = len(problem.search_bounds)
    rounds = RESTARTS if budget >= RESTARTS * 400 * dims else 1
    share = budget // rounds
    popsize = max(5, min(POPSIZE, share // (dims * 40) or 5))
    generations = max(1, int(share * 0.85) // (popsize * dims) - 1)
    spent, done = 0, 0
    best, best_err = None, math.inf

    def cost(x: np.ndarray) -> np.ndarray:
        nonlocal spent
        spent += x.shape[1]
        return problem.cost(x)

    seeds = np.random.SeedSequence(seed).spawn(rounds)
    for round_ in range(rounds):
        deadline = began + seconds * 0.85 * (round_ + 1) / rounds

        def told(intermediate_result) -> bool:  # (SciPy passes the result by this name)
            nonlocal done
            done += 1
            if progress is not None:
                progress(min(1.0, done / (generations * rounds)),
                         min(best_err, float(intermediate_result.fun)))
            return time.perf_counter() > deadline

        with np.errstate(all="ignore"):
            found = differential_evolution(
                cost, problem.search_bounds, strategy=STRATEGY, maxiter=generations, popsize=popsize,
                tol=0, atol=0, mutation=(0.5, 1.0), recombination=0.9,
                rng=np.random.default_rng(seeds[round_]), polish=False, vectorized=True,
                updating="deferred", callback=told)
        starts = _starts(problem, found)
        for x, branch in starts:
            start = problem.linkage(x, branch)
            with np.errstate(all="ignore"):
                link, used = _Polish(problem, start).run(max(50 * dims, share // 6 // len(starts)))
            spent += used
            for candidate in (link, start):
                if keeps_rules(candidate, task):
                    err = float(np.sum(np.abs(points_of(candidate) - problem.target) ** 2))
                    if err < best_err:
                        best, best_err = candidate, err
                    break
        if time.perf_counter() > began + seconds:
            break
    if best is None:
        raise SynthesisError("no four-bar within the task's bounds keeps every rule "
                             "(try a larger max_length or box)")
    if progress is not None:
        progress(1.0, best_err)
    return certify(task, best, spent, time.perf_counter() - began, best_err)


def _starts(problem: _Problem, found) -> list[tuple[np.ndarray, int]]:
    """The best few distinct members of the final population, each with its better branch:
    the polish starts from each (one basin's best is not always the deepest after polish)."""
    population = found.population
    ordered = np.argsort(found.population_energies)
    starts: list[tuple[np.ndarray, int]] = []
    for i in ordered:
        x = problem.warp.decode(population[i])
        if any(np.allclose(x, s, rtol=1e-3, atol=1e-9) for s, _ in starts):
            continue
        costs = [problem._cost(x[:, None], b)[0] for b in (1.0, -1.0)]
        starts.append((x, 1 if costs[0] <= costs[1] else -1))
        if len(starts) == STARTS:
            break
    return starts


def certify(task: SynthesisTask, link: Linkage, evaluations: int, seconds: float,
            searched: float) -> Result:
    """The linkage built as a scene, loaded by the scene loader and re-solved by the
    kinematics core at the precision points and over the whole turn: it must close at
    every position, on the searched branch, and its error is computed from that solve."""
    text = scene_toml(task, link)
    scene = parse_scene(text, source="synthesis")
    at = np.mod(np.array(link.angles) + link.frame_angle, TAU)
    motion = solve(scene, at, order=0)
    turn = solve(scene, scene.driver.at + link.turning * np.linspace(0, TAU, TURN, endpoint=False),
                 order=0, points=["M"])
    if not (np.all(motion.feasible) and np.all(turn.feasible)):
        raise SynthesisError("the found four-bar does not close over the whole turn")
    got = {name: motion.points[name].z for name in ("A", "B", "M")}
    mine = dict(zip("ABM", positions_of(link)))
    size = max(task.max_length, task.box)
    if any(np.max(np.abs(got[p] - mine[p])) > AGREE * size for p in "ABM"):
        raise SynthesisError("the re-solved four-bar is not the one searched "
                             "(another assembly branch)")
    errors = np.abs(got["M"] - np.array(task.points))
    return Result(linkage=link, scene=scene, scene_toml=text, objective=float(np.sum(errors ** 2)),
                  errors=errors, positions=got, crank_deg=np.degrees(at), evaluations=evaluations,
                  seconds=seconds, searched=searched)


def scene_toml(task: SynthesisTask, link: Linkage) -> str:
    """The found four-bar as the builder's four-bar template writes it (O, A, B, D; the
    coupler point M), drawn at the first precision point so that its branch is the
    searched one."""
    a, b, _ = positions_of(link)
    at = math.degrees((link.angles[0] + link.frame_angle) % TAU)
    d = link.D

    def v(z: complex) -> str:
        return f"[{float(z.real)!r}, {float(z.imag)!r}]"

    title = task.title or "Four-bar found for the precision points"
    return "\n".join([
        f'id = "{task.id}"',
        f"title = {_quoted(title)}",
        'title_sr = "Zglobni četvorougao nađen za zadate tačke putanje"',
        "",
        "pairs = [",
        '  { type = "revolute", members = [1, 2], point = "O" },',
        '  { type = "revolute", members = [2, 3], point = "A" },',
        '  { type = "revolute", members = [3, 4], point = "B" },',
        '  { type = "revolute", members = [4, 1], point = "D" },',
        "]",
        "",
        "[frame]",
        f"O = {v(link.O)}",
        f"D = {v(d)}",
        "",
        "[driver]",
        'type = "rotating"',
        f"at = {at!r}",
        f"omega = {10.0 * link.turning!r}",
        "epsilon = 0.0",
        "",
        "[members.2]",
        'label = "crank"',
        'points = ["O", "A"]',
        f"length = {link.crank!r}",
        "",
        "[members.3]",
        'label = "coupler"',
        'points = ["A", "B"]',
        f"length = {link.coupler!r}",
        f"extra = {{ M = {v(link.point)} }}",
        "",
        "[members.4]",
        'label = "rocker"',
        'points = ["D", "B"]',
        f"length = {link.rocker!r}",
        "",
        "[guess]",
        f"B = {v(complex(b[0]))}",
        "",
    ])


def _quoted(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'
