"""A path-synthesis task as data: the precision points a four-bar's coupler point must pass,
in order, the crank's timing and the bounds of the search (docs/synthesis.md).

Read from TOML by the same ``Reader`` as every scene, so a bad task is refused with a
sentence that names its field, and every number is checked finite and in range before the
search sees it. The search itself lives in ``solvers.synthesis``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from .loader import read_toml
from .messages import Text, given
from .reader import Reader, SceneError

TIMINGS = ("free", "steps", "angles")
MOST_POINTS = 60  # a path is drawn through far fewer; a search over more would not end in seconds
KEYS = {"id", "title", "points", "timing", "crank_angles", "crank_steps", "crank_pivot",
        "frame_angle", "max_length", "min_length", "box"}


@dataclass(frozen=True)
class SynthesisTask:
    """What a synthesis asks for. Lengths and coordinates in the task's own units (the
    found scene uses them as metres); angles in degrees, counter-clockwise from +x (the
    frame line's direction) or from the frame line O→D (the crank's angles)."""

    points: tuple[complex, ...]
    timing: str = "free"  # "free" | "steps" | "angles"
    crank_angles: tuple[float, ...] | None = None  # "angles": φ at each point, from O→D
    crank_steps: tuple[float, ...] | None = None  # "steps": between consecutive points
    crank_pivot: complex | None = None  # O fixed
    frame_angle: float | None = None  # the frame line's direction fixed
    max_length: float = 1.0
    min_length: float = 0.0
    box: float = 1.0
    id: str = "synthesis"
    title: str = ""

    @property
    def turning(self) -> int:
        """+1 when the crank turns counter-clockwise through the points, −1 clockwise (only
        negative steps make it so)."""
        return -1 if self.crank_steps and self.crank_steps[0] < 0 else 1


def load_task(path: str | Path) -> SynthesisTask:
    """The task in a TOML file (unreadable, too big, not UTF-8 or not TOML: said in words)."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise SceneError(Text("scene.unreadable", source=str(path), reason=exc.strerror or "")) from None
    return parse_task(data, source=path.name)


def parse_task(data: bytes | str, source: str = "<task>") -> SynthesisTask:
    """The task in a TOML text, or a ``SceneError`` naming the field that is wrong."""
    return build_task(read_toml(data, source), Reader(source))


def build_task(raw: dict, r: Reader) -> SynthesisTask:
    """The task from parsed TOML (a page's table builds the same dict)."""
    r.check_keys(raw, KEYS, "")
    points = _points(raw, r)
    n = len(points)
    timing = r.text(raw, "timing", "", default="free")
    if timing not in TIMINGS:
        raise r.fail("timing", "synthesis_timing", value=given(timing))
    angles = _list(raw, "crank_angles", r, n if timing == "angles" else None)
    steps = _list(raw, "crank_steps", r, n - 1 if timing == "steps" else None)
    for name, value, wanted in (("crank_angles", angles, "angles"), ("crank_steps", steps, "steps")):
        if value is None and timing == wanted:
            raise r.fail(name, "synthesis_timing_list", wanted=wanted)
        if value is not None and timing != wanted:
            raise r.fail(name, "synthesis_not_for_timing", timing=timing, wanted=wanted)
    if steps is not None:
        if any(s == 0 for s in steps) or len({math.copysign(1, s) for s in steps}) > 1:
            raise r.fail("crank_steps", "synthesis_step_signs", value=list(steps))
        if abs(sum(steps)) > 360:
            raise r.fail("crank_steps", "synthesis_steps_turn", total=float(abs(sum(steps))))
    pivot = r.vector(raw["crank_pivot"], "crank_pivot") if "crank_pivot" in raw else None
    frame_angle = r.number(raw, "frame_angle", "") if "frame_angle" in raw else None
    spread = max(abs(p - q) for p in points for q in points)
    reach = max(max(abs(p.real), abs(p.imag)) for p in points)
    max_length = r.number(raw, "max_length", "", default=_round(4 * spread), positive=True)
    min_length = r.number(raw, "min_length", "", default=0.0, non_negative=True)
    box = r.number(raw, "box", "", default=_round(reach + 2 * spread), positive=True)
    if min_length >= max_length:
        raise r.fail("min_length", "synthesis_no_lengths", low=min_length, high=max_length)
    if pivot is not None and max(abs(pivot.real), abs(pivot.imag)) > box:
        raise r.fail("crank_pivot", "synthesis_pivot_outside", box=box)
    return SynthesisTask(points=points, timing=timing, crank_angles=angles, crank_steps=steps,
                         crank_pivot=pivot, frame_angle=frame_angle, max_length=max_length,
                         min_length=min_length, box=box,
                         id=r.text(raw, "id", "", default="synthesis"),
                         title=r.text(raw, "title", "", default=""))


def _points(raw: dict, r: Reader) -> tuple[complex, ...]:
    value = raw.get("points")
    if value is None:
        raise r.fail("points", "missing")
    if not isinstance(value, list):
        raise r.fail("points", "synthesis_points_list", value=given(value))
    if not 3 <= len(value) <= MOST_POINTS:
        raise r.fail("points", "synthesis_points_count", count=len(value), most=MOST_POINTS)
    points = tuple(r.vector(p, f"points[{i}]") for i, p in enumerate(value))
    if max(abs(p - points[0]) for p in points) == 0:
        raise r.fail("points", "synthesis_points_same")
    return points


def _list(raw: dict, name: str, r: Reader, length: int | None) -> tuple[float, ...] | None:
    """A list of degrees, ``length`` long where the timing needs it."""
    if name not in raw:
        return None
    value = raw[name]
    if not isinstance(value, list):
        raise r.fail(name, "synthesis_angle_list", value=given(value))
    numbers = tuple(r.number({str(i): v for i, v in enumerate(value)}, str(i), name)
                    for i in range(len(value)))
    if length is not None and len(numbers) != length:
        raise r.fail(name, "synthesis_list_length", count=len(numbers), wanted=length)
    return numbers


def _round(value: float) -> float:
    """A default bound as a person would write it: two significant digits, rounded up."""
    if value <= 0:
        return 1.0
    step = 10 ** (math.floor(math.log10(value)) - 1)
    return math.ceil(value / step) * step
