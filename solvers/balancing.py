"""Rotor balancing (chapter 7): static and two-plane dynamic balancing, solved exactly.

Every mass m at radius r and angle φ is the vector U = m·r in the plane of rotation, written
as the complex number z + i·y = m·r·e^{iφ}, since the book measures y = r·sin φ and
z = r·cos φ. Balance needs Σ U = 0 (forces, the U polygon) and, for dynamic balance,
Σ U·(x − x_ref) = 0 (moments about a correction plane, the V polygon). Taking moments about
plane II leaves plane I's correction as the only unknown, then the forces give plane II's.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from mechanisms.messages import Text
from mechanisms.rotor import PLANES, Correction, Rotor


class BalanceError(ValueError):
    """The rotor cannot be balanced as asked; the message says why."""


@dataclass(frozen=True)
class Found:
    """One correction, complete: mass (kg), radius (m), angle (rad, 0 ≤ φ < 2π)."""

    mass: float
    radius: float
    angle: float

    @property
    def u(self) -> complex:
        """U = m·r as z + i·y (kg·m)."""
        return self.mass * self.radius * cmath.exp(1j * self.angle)


@dataclass(frozen=True)
class Balance:
    rotor: Rotor
    corrections: dict[str, Found]
    u_needed: dict[str, complex]  # the U each plane must add (kg·m)
    residual_force: float  # |Σ U| after correction (kg·m)
    residual_moment: float  # |Σ U·(x − x_II)| after correction (kg·m²)
    notes: tuple[Text, ...] = ()

    def bearing_forces(self, corrected: bool) -> dict[str, float] | None:
        """|F| on bearings A and B at ω (N): the rotating inertia forces ω²·U carried by the
        two supports (moments about each), before or after the corrections."""
        rotor = self.rotor
        if rotor.omega is None:
            return None
        a = rotor.bearings.get("A", rotor.planes["I"])
        b = rotor.bearings.get("B", rotor.planes.get("II", a + 1.0))
        items = [(m.mass * m.radius * cmath.exp(1j * m.angle), m.x) for m in rotor.masses]
        if corrected:
            items += [(f.u, rotor.planes[p]) for p, f in self.corrections.items()]
        w2 = rotor.omega**2
        force_a = w2 * sum(u * (x - b) for u, x in items) / (a - b)
        force_b = w2 * sum(u for u, _ in items) - force_a
        return {"A": abs(force_a), "B": abs(force_b)}


def unit(angle: float) -> complex:
    return cmath.exp(1j * angle)


def normalised(angle: float) -> float:
    """An angle in 0 … 2π, its quadrant from the signs of y and z as the book explains."""
    return angle % (2 * math.pi)


def balance(rotor: Rotor) -> Balance:
    """The corrections that balance the rotor, or ``BalanceError`` with the reason."""
    if not rotor.masses or all(m.mass * m.radius == 0 for m in rotor.masses):
        raise BalanceError(Text("balance.nothing"))
    us = [m.mass * m.radius * unit(m.angle) for m in rotor.masses]
    total = sum(us)
    notes = []
    if rotor.mode == "static":
        needed = {"I": -total}
        moment = 0j
    else:
        x1, x2 = rotor.planes["I"], rotor.planes["II"]
        span = x1 - x2
        scale = max(abs(m.x - x2) for m in rotor.masses) or 1.0
        if abs(span) <= 1e-9 * scale:
            # in mm, as the page's plane fields (the file's metres read as 0,12 m); + 0.0: no "−0"
            raise BalanceError(Text("balance.same_plane", x=float(f"{x1 * 1e3:.6g}") + 0.0))
        if abs(span) < 1e-3 * scale:
            notes.append(Text("balance.close_planes", span=float(f"{abs(span):.3g}")))
        moment = sum(u * (m.x - x2) for u, m in zip(us, rotor.masses))
        u1 = -moment / span
        needed = {"I": u1, "II": -total - u1}
    found = {p: _complete(p, rotor.corrections[p], u, notes) for p, u in needed.items()}
    after = total + sum(f.u for f in found.values())
    moment_after = 0j
    if rotor.mode == "dynamic":
        x2 = rotor.planes["II"]
        moment_after = moment + found["I"].u * (rotor.planes["I"] - x2)
    return Balance(rotor, found, needed, abs(after), abs(moment_after), tuple(notes))


def _complete(plane: str, known: Correction, u: complex, notes: list) -> Found:
    """Fill in the two unknowns of a correction so that m·r·e^{iφ} = u."""
    size = abs(u)
    if size == 0:
        notes.append(Text("balance.no_correction", plane=plane))
        return Found(0.0, known.radius or 0.0, known.angle or 0.0)
    angle = normalised(cmath.phase(u))
    unknown = set(known.unknowns)
    if unknown == {"mass", "angle"}:
        return Found(size / known.radius, known.radius, angle)
    if unknown == {"radius", "angle"}:
        return Found(known.mass, size / known.mass, angle)
    # mass and radius unknown, angle given: only the product m·r is fixed, and only if U
    # points along (or against) the given angle
    along = (u * unit(-known.angle))
    if abs(along.imag) > 1e-9 * size:
        raise BalanceError(Text("balance.wrong_angle", plane=plane,
                                given=round(math.degrees(known.angle), 2),
                                needed=round(math.degrees(angle), 2)))
    if along.real < 0:
        raise BalanceError(Text("balance.opposite", plane=plane, needed=round(math.degrees(angle), 2)))
    raise BalanceError(Text("balance.product", plane=plane, product=float(f"{size:.6g}")))


def graphical_error(value: float, scale: float, precision: float = 0.5e-3,
                    vectors: int = 4, angle_read: float = math.radians(1.0)) -> tuple[float, float]:
    """Expected error of a length read off a polygon drawn to ``scale`` (units per metre of
    drawing) with ``precision`` (m of drawing) per vector end, and of an angle read to
    ``angle_read``: (absolute error of the value, absolute error of the angle in rad).

    The closing side collects the drawing errors of every vector: √n·precision for n
    vectors drawn independently, times the scale; its direction adds that over its length.
    """
    length_error = math.sqrt(vectors) * precision * scale
    angle_error = math.hypot(angle_read, length_error / value if value else math.pi)
    return length_error, angle_error


__all__ = ["Balance", "BalanceError", "Found", "balance", "graphical_error", "PLANES"]
