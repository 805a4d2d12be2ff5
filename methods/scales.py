"""Drawing scales as a student picks them: round numbers (1, 2 or 5 × 10ⁿ units per cm) that
make a plan or a polygon fit the sheet, unless the task prints its own (U_L, U_v, U_a, U_F)."""

from __future__ import annotations

import math

from mechanisms.schema import Scene

from .plans import Plans

PRECISION_CM = 0.05  # a line drawn and read to half a millimetre (variants' keys, practice)


def nice_scale(value: float) -> float:
    """A round drawing scale (1, 2 or 5 × 10ⁿ) at or above ``value``, as a student would pick."""
    if value <= 0:
        return 1.0
    power = 10 ** math.floor(math.log10(value))
    return float(next(k * power for k in (1, 2, 5, 10) if k * power >= value))


def plan_scales(scene: Scene, plans: Plans | None) -> dict[str, float]:
    """U_L, U_v, U_a per cm: the task's own where it prints them, else round ones that fit a
    12 cm plan (the plans: None when they cannot be drawn; then 1 m/s and 10 m/s² per cm)."""
    reach = {"v": 1.0, "a": 10.0}
    if plans is not None:
        reach = {"v": max(map(abs, plans.velocity.images.values())),
                 "a": max(map(abs, plans.acceleration.images.values()))}
    spans = [abs(z) for m in scene.members.values() for z in m.points.values()]
    reach["L"] = max(spans or [1.0])
    return {k: scene.scales.get(k, nice_scale(reach[k] / 12)) for k in ("L", "v", "a")}


def polygon_scale(vectors) -> float:
    """A force or U/V polygon's scale: its longest side about 8 cm."""
    return nice_scale(max((abs(v) for v in vectors), default=1.0) / 8)
