"""The scene schema: a planar linkage in the course's terms, as frozen dataclasses.

Members are numbered as in the course (1 = frame, 2 = driving member), points are
lettered. Every moving member has its own frame: origin at its first point, x-axis
towards its second point (a one-point member, e.g. a slider block, takes its
orientation from the prismatic pair it belongs to). Point coordinates are stored as
complex numbers ``x + iy`` because the solver works with the complex-number method.
SI units throughout; angles in radians (the TOML file uses degrees).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Literal

FRAME = 1
DRIVER = 2


@dataclass(frozen=True)
class Member:
    """A rigid member: its points in its own frame, plus optional mass properties."""

    number: int
    points: dict[str, complex]
    axis: tuple[str, ...]  # the one or two points that define the member's frame
    mass: float = 0.0  # kg
    centre: complex | None = None  # centre of mass S in the member frame, m
    gyration: float = 0.0  # radius of gyration ρ about S, m
    label: str = ""
    forms: dict[str, str] = field(default_factory=dict)  # extra point → "distances" or
    # "polar" where the author gave it so (mechanisms.point_forms); else [along, left]

    @property
    def length(self) -> float | None:
        """Distance between the two axis points (the link length), or None."""
        if len(self.axis) < 2:
            return None
        return abs(self.points[self.axis[1]] - self.points[self.axis[0]])


@dataclass(frozen=True)
class Pair:
    """A lower kinematic pair between two members.

    Revolute: ``members`` share ``point``. Prismatic: ``members = (guide, slider)``;
    the slider's ``point`` stays on a line fixed to the guide member, through the
    guide's point ``through`` at angle ``angle`` in the guide's frame; ``slider_angle``
    is the same line's direction in the slider's frame, so the slider's orientation
    is locked: θ_slider = θ_guide + angle − slider_angle.

    Circular slot: a revolute pair ``members = (guide, slider)`` at the slot's centre
    ``point``, with ``on_slot`` the block's point on the arc. A block in a circular slot moves
    exactly as a link from that point to the centre (every normal of the arc passes through
    the centre, so the slot's force does too): the solvers treat it as that revolute, the
    drawing and the relative motion (along the arc, its normal and Coriolis parts) as a slot.
    """

    kind: Literal["revolute", "prismatic"]
    members: tuple[int, int]
    point: str
    name: str
    through: str | None = None
    angle: float = 0.0
    slider_angle: float = 0.0
    on_slot: str | None = None

    @property
    def letter(self) -> str:
        return "R" if self.kind == "revolute" else "P"

    @property
    def lock(self) -> float:
        """θ_slider − θ_guide for a prismatic pair."""
        return self.angle - self.slider_angle

    def other(self, member: int) -> int:
        a, b = self.members
        return b if member == a else a


@dataclass(frozen=True)
class Driver:
    """The driving member 2: rotating about a frame pivot or sliding on a frame guide.

    ``at`` is the scene's own instant: φ₂ in rad (rotating) or s in m (linear).
    ``speed``/``accel`` are ω₂, ε₂ (rad/s, rad/s²) or v, a (m/s, m/s²).
    """

    kind: Literal["rotating", "linear"]
    member: int
    pair: str  # name of the pair that joins the driver to the frame
    at: float
    speed: float
    accel: float = 0.0

    def range(self) -> tuple[float, float]:
        """Where the driver may be put (the pages' position slider, the command line's
        ``--at``): φ₂ in degrees within one turn either way, or s in metres within three
        times the scene's own s either way (at least ±0.3 m). Beyond it no position is
        meant: a φ₂ of −1e308° is no angle at all."""
        if self.kind == "rotating":
            return -360.0, 360.0
        reach = max(abs(self.at), 0.1)
        return round(-3 * reach, 3), round(3 * reach, 3)


@dataclass(frozen=True)
class Force:
    """An external force on a member, applied at one of its points."""

    member: int
    point: str
    magnitude: float  # N
    angle: float  # rad, direction
    follows_member: bool = False  # direction measured in the member's frame
    label: str = ""  # as the book names it (G_3 for a weight given as a force); default F_<member>


@dataclass(frozen=True)
class Moment:
    member: int
    value: float  # N·m, counter-clockwise positive


@dataclass(frozen=True)
class Travel:
    """A machine that travels while its linkage runs, the crank chain-driven from the ground
    wheel (the hay tedder of task 1.3): ω_t = v_R/R_t, ω₂ = ω_b = ω_t·R_a/R_b."""

    speed: float  # v_R, m/s
    wheel_radius: float  # R_t, m
    sprocket_wheel: float  # R_a, m (on the ground wheel's shaft)
    sprocket_crank: float  # R_b, m (on the crank's shaft)
    angle: float = 0.0  # direction of travel, rad from +x

    @property
    def wheel_omega(self) -> float:
        return self.speed / self.wheel_radius

    @property
    def crank_omega(self) -> float:
        return self.wheel_omega * self.sprocket_wheel / self.sprocket_crank

    @property
    def cycle_time(self) -> float:
        return 2 * math.pi / self.crank_omega

    def step_time(self, steps: int = 12) -> float:
        return self.cycle_time / steps

    def step_distance(self, steps: int = 12) -> float:
        return self.speed * self.step_time(steps)


@dataclass(frozen=True)
class Fit:
    """How a missing figure was reconstructed: the scene's unknown numbers (paths into its
    document, e.g. ``frame.G.0``), found by least squares from ``start`` against the printed
    values ``used``; the book's other values are then predictions that test the
    reconstruction. ``residual``: the root mean square of the relative misfits, as found.
    ``chose``: printed values that picked this layout among several that fit the used values
    equally (a mirror image, another branch): they are evidence spent, not predictions."""

    unknowns: tuple[str, ...]
    start: tuple[float, ...]
    used: tuple[str, ...]
    residual: float
    chose: tuple[str, ...] = ()


@dataclass(frozen=True)
class Scene:
    """A linkage scene: what a TOML file under ``mechanisms/presets`` describes."""

    id: str
    title: str
    source: str
    note: str
    frame: dict[str, complex]  # fixed points, in the book's coordinates
    members: dict[int, Member]
    pairs: tuple[Pair, ...]
    driver: Driver
    assembly: dict[tuple[int, int], int] = field(default_factory=dict)
    forces: tuple[Force, ...] = ()
    moments: tuple[Moment, ...] = ()
    gravity: float = 0.0  # m/s², acting along −y when > 0
    # whether the task counts inertia loads (tasks 5.1, 5.2 and the lecture leave them out): the
    # kinetostatics page opens with its switch so, and the book's values are computed so
    inertia: bool = True
    book: dict[str, float] = field(default_factory=dict)  # the book's printed values
    travel: Travel | None = None
    book_notes: dict[str, str] = field(default_factory=dict)  # why a printed value is off
    book_notes_sr: dict[str, str] = field(default_factory=dict)  # the same in Serbian
    title_sr: str = ""  # the title in Serbian (Latin); Cyrillic is made from it
    note_sr: str = ""  # the note and the source in Serbian (Latin), likewise
    source_sr: str = ""
    # the book's drawing scales per cm of drawing: L in m, v in m/s, a in m/s², F in N
    scales: dict[str, float] = field(default_factory=dict)
    # where the drawing puts some points at the scene's instant: picks a class III group's
    # assembly (Newton starts there), as "assembly" picks a dyad's
    guess: dict[str, complex] = field(default_factory=dict)
    # special (Assur) points of class III groups: name -> the two binary members whose
    # lines meet there
    special: dict[str, tuple[int, int]] = field(default_factory=dict)
    guess_at: float | None = None  # the driver value the guess was sketched at (the file's)
    # the book's figure is missing and the geometry was assumed, not fitted to its values:
    # a printed value that differs says nothing about a slip
    layout_assumed: bool = False
    fit: Fit | None = None  # the figure reconstructed by fitting its printed values
    # a printed value the book miscalculated, as the book's own formula over exact values
    book_slips: dict[str, str] = field(default_factory=dict)

    def with_loads(self, *, masses: dict[int, float] | None = None,
                   gyrations: dict[int, float] | None = None,
                   forces: list[float] | None = None, angles: list[float] | None = None,
                   moments: list[float] | None = None, gravity: float | None = None,
                   inertia: bool | None = None) -> Scene:
        """A copy with new masses (kg) and radii of gyration (m) per member, new magnitudes (N)
        and directions (rad) of the external forces and values of the moments (N·m), in the
        file's order, g, and whether inertia loads count."""
        members = dict(self.members)
        for number, mass in (masses or {}).items():
            members[number] = dataclasses.replace(members[number], mass=mass)
        for number, rho in (gyrations or {}).items():
            members[number] = dataclasses.replace(members[number], gyration=rho)
        new_forces = tuple(
            dataclasses.replace(f, magnitude=f.magnitude if forces is None else forces[i],
                                angle=f.angle if angles is None else angles[i])
            for i, f in enumerate(self.forces))
        new_moments = self.moments if moments is None else tuple(
            dataclasses.replace(m, value=v) for m, v in zip(self.moments, moments))
        return dataclasses.replace(self, members=members, forces=new_forces, moments=new_moments,
                                   gravity=self.gravity if gravity is None else gravity,
                                   inertia=self.inertia if inertia is None else inertia)

    def pair(self, name: str) -> Pair:
        for p in self.pairs:
            if p.name == name:
                return p
        raise KeyError(name)

    def points_of(self, member: int) -> dict[str, complex]:
        return self.frame if member == FRAME else self.members[member].points

    @property
    def point_names(self) -> list[str]:
        names = dict.fromkeys(self.frame)
        for m in self.members.values():
            names.update(dict.fromkeys(m.points))
        return sorted(names)

    @property
    def lengths(self) -> dict[int, float]:
        """Link lengths of the members that have two axis points."""
        return {n: m.length for n, m in self.members.items() if m.length is not None}

    def with_(self, *, lengths: dict[int, float] | None = None, speed: float | None = None,
              accel: float | None = None, at: float | None = None,
              travel: Travel | None = None) -> Scene:
        """A copy with overridden link lengths, driver speed/acceleration, instant or travel.

        With travel, ω₂ follows the chain drive (its sense stays the scene's).
        A new length scales every point of that member about its first axis point (the
        origin of its frame), so extra points such as B on member 3 keep their place
        relative to the link.
        """
        members = dict(self.members)
        for number, new in (lengths or {}).items():
            member = members[number]
            factor = new / member.length
            points = {k: z * factor for k, z in member.points.items()}
            centre = None if member.centre is None else member.centre * factor
            members[number] = dataclasses.replace(member, points=points, centre=centre)
        travel = travel or self.travel
        if travel is not None:
            speed = math.copysign(travel.crank_omega, self.driver.speed if speed is None else speed)
        driver = dataclasses.replace(
            self.driver,
            speed=self.driver.speed if speed is None else speed,
            accel=self.driver.accel if accel is None else accel,
            at=self.driver.at if at is None else at,
        )
        return dataclasses.replace(self, members=members, driver=driver, travel=travel)
