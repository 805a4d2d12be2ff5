"""A member's extra point in the three forms an exam sheet gives it.

The member's frame has its first point at the origin and its second on the +x axis, so a
point is ``[along, left]`` in metres (the *offset* form). A sheet rarely says that: it gives
the triangle's sides — the point's distances to the member's first and second points, and on
which side of the direction first → second it lies (the *distances* form) — or a length and
an angle from that direction (the *polar* form). All three become the same local point, and
each can be written back from it, so a drag or a new length keeps the form the author used.
"""

from __future__ import annotations

import cmath
import math
from typing import Any

from .messages import Text, given

FORMS = ("offset", "distances", "polar")
SIDES = ("left", "right")
DIGITS = 12  # written back to 12 significant digits: 0.2, not 0.19999999999999998
SLACK = 1e-12  # a triangle this close to flat (relative to its sides) is flat: the point on the line


class FormError(ValueError):
    """A point's form breaks a rule; the message says which and with what numbers (the
    loader puts the member and the point in front of it)."""


def form_of(value: Any) -> str:
    """Which form a point is written in (a pair of numbers is the offset form)."""
    if isinstance(value, dict):
        return "distances" if "distances" in value else "polar" if "polar" in value else "?"
    return "offset"


def _pair(value: Any, what: str) -> tuple[float, float]:
    ok = (isinstance(value, list) and len(value) == 2
          and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value))
    if not ok or not all(math.isfinite(v) for v in value):
        raise FormError(Text("form.pair", what=what, value=given(value)))
    return float(value[0]), float(value[1])


def from_distances(d1: float, d2: float, side: str, length: float | None) -> complex:
    """The point at ``d1`` from the first point and ``d2`` from the second, on ``side`` of
    first → second (law of cosines: along = (d1² − d2² + L²) / 2L)."""
    if length is None:
        raise FormError(Text("form.two_points"))
    if d1 <= 0 or d2 <= 0:
        raise FormError(Text("form.distances_positive", value=[d1, d2]))
    if side not in SIDES:
        raise FormError(Text("form.side", value=given(side)))
    c, b, a = sorted((d1, d2, length))
    if a - b - c > SLACK * a:
        raise FormError(Text("form.no_triangle", d1=d1, d2=d2, length=length))
    along = (d1 * d1 - d2 * d2 + length * length) / (2 * length)
    # the height from the triangle's area, by Heron's formula in Kahan's stable order (the
    # plain √(d1² − along²) loses half its digits for a point near the member's line)
    flat = b + c - a <= SLACK * a
    area = 0.0 if flat else 0.25 * math.sqrt(
        (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c)))
    left = 2 * area / length
    return complex(along, left if side == "left" else -left)


def from_polar(r: float, angle_deg: float) -> complex:
    """The point at ``r`` from the first point, ``angle_deg`` counter-clockwise from the
    direction first → second."""
    if r <= 0:
        raise FormError(Text("form.polar_positive", value=given(r)))
    return cmath.rect(r, math.radians(angle_deg))


def local_point(value: Any, length: float | None) -> complex:
    """The point a value of any form puts in the member's frame (FormError says why not)."""
    form = form_of(value)
    if form == "offset":
        along, left = _pair(value, Text("form.a_point"))
        return complex(along, left)
    if form == "distances":
        unknown = set(value) - {"distances", "side"}
        if unknown:
            raise FormError(Text("form.distances_keys", key=sorted(unknown)[0]))
        d1, d2 = _pair(value["distances"], "distances")
        return from_distances(d1, d2, value.get("side", "?"), length)
    if form == "polar":
        unknown = set(value) - {"polar"}
        if unknown:
            raise FormError(Text("form.polar_keys", key=sorted(unknown)[0]))
        return from_polar(*_pair(value["polar"], "polar"))
    raise FormError(Text("form.unknown", value=given(value)))


def _round(x: float) -> float:
    return float(f"{x:.{DIGITS}g}") + 0.0  # no −0


def written(form: str, z: complex, length: float | None, side: str = "left") -> Any:
    """The local point ``z`` written in ``form`` (the offset form where a distances form has
    no second point to measure from). A point on the line keeps ``side``. Numbers are
    rounded to 12 digits (what was typed comes back as typed) unless that moves the point:
    near the member's line the distances carry the height in their last digits."""
    if form == "distances" and length is not None and z != 0 and z != length:
        if abs(z.imag) > SLACK * abs(z):
            side = "left" if z.imag > 0 else "right"
        exact = {"distances": [abs(z), abs(z - length)], "side": side}
    elif form == "polar" and z != 0:
        exact = {"polar": [abs(z), math.degrees(cmath.phase(z))]}
    else:
        return [_round(z.real), _round(z.imag)]
    key = "distances" if "distances" in exact else "polar"
    rounded = {**exact, key: [_round(v) for v in exact[key]]}
    scale = max(abs(z), length or 0.0)
    return rounded if abs(local_point(rounded, length) - z) <= 1e-14 * scale else exact


def every_form(z: complex, length: float | None) -> dict[str, Any]:
    """The point in every form at once, for a table that shows them side by side."""
    d = written("distances", z, length)
    p = written("polar", z, length)
    return {"along": _round(z.real), "left": _round(z.imag),
            "d1": d["distances"][0] if isinstance(d, dict) else None,
            "d2": d["distances"][1] if isinstance(d, dict) else None,
            "side": d["side"] if isinstance(d, dict) else None,
            "r": p["polar"][0] if isinstance(p, dict) else None,
            "theta": p["polar"][1] if isinstance(p, dict) else None}
