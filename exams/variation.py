"""The given data of a task, and how a variant changes it (exam and homework variants).

A variant is the task's scene document (the TOML table, as ``writer.to_text`` writes it)
with some of its given numbers replaced: lengths, offsets, the crank angle, ω₂, masses,
loads, tooth counts, unbalances. What is structure stays (pairs, guides, which member is
driven, force directions), so a variant is the same exercise with other numbers. Values
are drawn within ± a spread around the book's and rounded to what the book prints:
millimetres, whole degrees, whole teeth, two significant digits for speeds, masses and
loads. The checks that make a variant a good exercise need the solvers: see
``exams.variants``.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass

import numpy as np

from mechanisms.messages import Text

ANGLE_PER_PERCENT = 0.5  # an angle varies by ± spread/2 degrees (± 10° at 20 %)
MIN_TEETH = 10  # fewer teeth undercut; the book's smallest gears have 15


@dataclass(frozen=True)
class Given:
    """One given number of a task: where it sits in the document and how it may vary."""

    path: tuple  # keys and indices into the scene document
    value: float  # the task's own value
    kind: str  # "length", "angle", "teeth" (a whole count), "speed" (the driver's) or "value"
    unit: str
    label: str  # as a task names it: AB, x_A, φ₂, ω₂, m₃, z₅ …

    @property
    def step(self) -> float:
        """What the value is rounded to, as the book prints such a number."""
        if self.kind == "angle":
            return 1.0
        if self.kind == "teeth":
            return 1.0
        digits = math.floor(math.log10(abs(self.value)))
        if self.kind == "length":
            return max(0.001, 10.0 ** (digits - 2))
        if self.kind == "speed":  # on the pages' ω₂ (0.5 s⁻¹) and v (0.1 m/s) slider steps
            return max(10.0 ** (digits - 1), 0.5 if self.unit == "s⁻¹" else 0.1)
        return 10.0 ** (digits - 1)

    def bounds(self, spread: float) -> tuple[float, float]:
        """The range a variant draws from: ± spread % of the value (± spread/2 degrees for an
        angle)."""
        half = spread * ANGLE_PER_PERCENT if self.kind == "angle" else abs(self.value) * spread / 100
        return self.value - half, self.value + half

    def draw(self, rng: np.random.Generator, spread: float) -> float:
        lo, hi = self.bounds(spread)
        step = self.step
        value = round(rng.uniform(lo, hi) / step) * step
        if self.kind != "angle" and (value == 0 or (value > 0) != (self.value > 0)):
            value = math.copysign(step, self.value)  # a length or a mass keeps its sign
        return float(f"{value:.12g}")  # 0.30000000000000004 → 0.3


def givens(doc: dict) -> list[Given]:
    """The numbers of a scene document a variant may change, in a stable order (a variant
    code's mask of held values counts in it). Zeros stay zeros: an origin, a constant ω₂,
    a plane at x = 0 are choices of the task, not data."""
    kind = doc.get("kind", "linkage")
    found = {"rotor": _rotor, "gears": _gears}.get(kind, _linkage)(doc)
    return [g for g in found if g.value != 0 or g.kind == "angle"]


def _linkage(doc: dict) -> list[Given]:
    out = []
    for name, (x, y) in doc.get("frame", {}).items():
        out += [Given(("frame", name, 0), x, "length", "m", f"x_{name}"),
                Given(("frame", name, 1), y, "length", "m", f"y_{name}")]
    for number, m in doc.get("members", {}).items():
        if "length" in m:
            out.append(Given(("members", number, "length"), m["length"], "length", "m",
                             "".join(m["points"])))
        for name, value in m.get("extra", {}).items():
            out += _extra_givens(number, m, name, value)
    driver = doc["driver"]
    if driver["type"] == "rotating":
        out += [Given(("driver", "at"), driver["at"], "angle", "°", "φ₂"),
                Given(("driver", "omega"), driver["omega"], "speed", "s⁻¹", "ω₂"),
                Given(("driver", "epsilon"), driver.get("epsilon", 0.0), "value", "s⁻²", "ε₂")]
    else:
        out += [Given(("driver", "at"), driver["at"], "length", "m", "s₂"),
                Given(("driver", "velocity"), driver["velocity"], "speed", "m/s", "v₂"),
                Given(("driver", "acceleration"), driver.get("acceleration", 0.0), "value", "m/s²", "a₂")]
    for number, m in doc.get("members", {}).items():
        out += [Given(("members", number, "mass"), m.get("mass", 0.0), "value", "kg", f"m{number}"),
                Given(("members", number, "gyration"), m.get("gyration", 0.0), "length", "m",
                      f"ρ{number}")]
    for i, f in enumerate(doc.get("forces", [])):
        out.append(Given(("forces", i, "magnitude"), f["magnitude"], "value", "N",
                         f.get("label") or f"F{f['member']}"))
    for i, m in enumerate(doc.get("moments", [])):
        out.append(Given(("moments", i, "value"), m["value"], "value", "N·m", f"M{m['member']}"))
    return out


def _extra_givens(number: str, m: dict, name: str, value) -> list[Given]:
    """A member's point as the task gives it: its offsets, the triangle's two sides, or a
    length and an angle (mechanisms.point_forms)."""
    at = ("members", number, "extra", name)
    first, *second = m.get("points", ["?"])
    if isinstance(value, dict) and "distances" in value:
        d1, d2 = value["distances"]
        return [Given((*at, "distances", 0), d1, "length", "m", f"{first}{name}"),
                Given((*at, "distances", 1), d2, "length", "m", f"{(second or ['?'])[0]}{name}")]
    if isinstance(value, dict) and "polar" in value:
        r, angle = value["polar"]
        return [Given((*at, "polar", 0), r, "length", "m", f"{first}{name}"),
                Given((*at, "polar", 1), angle, "angle", "°", f"∠{name}{number}")]
    x, y = value
    return [Given((*at, 0), x, "length", "m", f"x{number}_{name}"),
            Given((*at, 1), y, "length", "m", f"y{number}_{name}")]


def _rotor(doc: dict) -> list[Given]:
    out = []
    for i, m in enumerate(doc.get("masses", [])):
        n = i + 1
        out += [Given(("masses", i, "mass"), m["mass"], "value", "kg", f"m{n}"),
                Given(("masses", i, "radius"), m["radius"], "length", "m", f"r{n}"),
                Given(("masses", i, "angle"), m["angle"], "angle", "°", f"φ{n}"),
                Given(("masses", i, "x"), m["x"], "length", "m", f"x{n}")]
    for plane, c in doc.get("corrections", {}).items():
        for q, kind, unit in (("mass", "value", "kg"), ("radius", "length", "m")):
            if q in c:
                out.append(Given(("corrections", plane, q), c[q], kind, unit, f"{q[0]}{plane}"))
    return out


def _gears(doc: dict) -> list[Given]:
    """A gear's size varies as a whole count: its teeth, or for a train given by radii, its
    radius in millimetres, so that the centre distances of a planetary stage close exactly."""
    out, seen = [], set()
    for member, rim in rims(doc):
        label = (f"z{member}" if rim[0] == "teeth" else f"R{member}") + ("′" if member in seen else "")
        seen.add(member)  # a member's second rim is primed, as the book writes R₁₀ and R′₁₀
        unit = "" if rim[0] == "teeth" else "mm"
        out.append(Given(("rims", member, rim), rim[1], "teeth", unit, label))
    for i, spec in enumerate(doc.get("inputs", [])):
        for q, unit in (("omega", "s⁻¹"), ("velocity", "m/s")):
            if q in spec:
                out.append(Given(("inputs", i, q), spec[q], "value", unit,
                                 f"{'ω' if q == 'omega' else 'v'}{spec['member']}"))
    return out


MM = 0.001


def rims(doc: dict) -> list[tuple[int, tuple[str, int]]]:
    """Each toothed rim once: (member, ("teeth", z)) or (member, ("mm", radius in mm)); a
    planet meshing with a sun and a ring has one rim in both meshes."""
    seen = {}
    for mesh in doc.get("meshes", []):
        seen.update(dict.fromkeys(mesh_rims(mesh)))
    return list(seen)


def mesh_rims(mesh: dict) -> list[tuple[int, tuple[str, int]]]:
    """The two rims of a mesh as the file gives it (one key per rim however often it meshes)."""
    if "teeth" in mesh:
        return [(m, ("teeth", z)) for m, z in zip(mesh["members"], mesh["teeth"])]
    return [(m, ("mm", round(r / MM))) for m, r in zip(mesh["members"], mesh["radii"])]


class VariationError(ValueError):
    """A drawn set of numbers that makes no valid scene (the gears of a stage do not mesh)."""


def apply(doc: dict, found: list[Given], values: list[float]) -> tuple[dict, list[float]]:
    """A copy of ``doc`` with each given at its new value, and what follows from them: a
    member's centre of mass keeps its place along a link whose length changed; a gear
    train's axes follow its new rims, and a rim that closes a planetary stage is resized
    to close it. Returns the document and the values as they ended up."""
    new = copy.deepcopy(doc)
    if doc.get("kind") == "gears":
        return _apply_gears(new, found, values)
    for g, value in zip(found, values):
        *where, last = g.path
        table = new
        for key in where:
            table = table[key]
        table[last] = value
    for number, m in new.get("members", {}).items():
        old = doc["members"][number]
        if "centre" in m and "length" in m and old["length"]:
            factor = m["length"] / old["length"]
            m["centre"] = [c * factor for c in old["centre"]]
    return new, list(values)


def _apply_gears(new: dict, found: list[Given], values: list[float]) -> tuple[dict, list[float]]:
    sizes = {}
    for g, value in zip(found, values):
        if g.path[0] == "rims":
            sizes[(g.path[1], g.path[2])] = int(value)
        else:
            new["inputs"][g.path[1]][g.path[2]] = value
    old_axes = {int(n): m.get("axis", 0.0) for n, m in new["members"].items()}
    axes = _close_stages(new, sizes, old_axes)
    for mesh in new["meshes"]:
        key = "teeth" if "teeth" in mesh else "radii"
        mesh[key] = [_size(sizes, rim) for rim in mesh_rims(mesh)]
    radius = _radius_unit(new)
    remap = {old_axes[n]: axes[n] * radius for n in axes}  # a point at a planet's axis follows it
    for n, m in new["members"].items():
        if int(n) in axes and old_axes[int(n)]:
            m["axis"] = axes[int(n)] * radius
    for name, (member, r) in new.get("points", {}).items():
        new["points"][name] = [member, remap.get(r, r)]
    for spec in new.get("inputs", []):
        if "radius" in spec:
            spec["radius"] = remap.get(spec["radius"], spec["radius"])
    small = [f"{m}" for (m, _), z in sizes.items() if z < MIN_TEETH]
    if small:
        raise VariationError(Text("vary.few_teeth", gears=", ".join(small), least=MIN_TEETH))
    ended = [sizes.get((g.path[1], g.path[2]), v) if g.path[0] == "rims" else v
             for g, v in zip(found, values)]
    return new, ended


def _size(sizes: dict, rim: tuple):
    """A rim's new size as the file writes it: whole teeth, or a radius in metres."""
    value = sizes.get(rim, rim[1][1])
    return value if rim[1][0] == "teeth" else float(f"{value * MM:.12g}")


def _radius_unit(doc: dict) -> float:
    """Metres per count of a rim: half a module for teeth, a millimetre for a radius."""
    for mesh in doc["meshes"]:
        if "teeth" in mesh:
            return mesh.get("module", 0.001) / 2
    return MM


def _close_stages(doc: dict, sizes: dict, old_axes: dict[int, float]) -> dict[int, int]:
    """Every member's axis (distance from the central axis, in counts) from the new rims: a
    central member stays at 0, a mesh puts its other member at the sum of the radii (the
    difference for a ring), shafts share an axis. Where two meshes meet again (a planet
    between a sun and a ring), a rim not yet placed is resized to close the stage; a stage
    that cannot close raises VariationError. Bevel meshes set no distance."""
    unit = _radius_unit(doc)
    axes = {n: 0 for n, a in old_axes.items() if a == 0 and doc["members"][str(n)].get("carrier") is None}
    placed: set = set()
    meshes = [m for m in doc["meshes"] if not m.get("bevel")]
    for _ in range(len(meshes) + len(doc.get("shafts", [])) + 1):
        for shaft in doc.get("shafts", []):
            known = [axes[m] for m in shaft if m in axes]
            for m in shaft:
                if known:
                    axes.setdefault(m, known[0])
        for mesh in meshes:
            a, b = mesh["members"]
            rim = mesh_rims(mesh)
            size = [sizes.get(r, r[1][1]) for r in rim]
            internal = mesh.get("internal")
            distance = abs(size[0] - size[1]) if internal is not None else size[0] + size[1]
            side = 1 if old_axes[b] >= old_axes[a] else -1
            if a in axes and b not in axes:
                axes[b] = axes[a] + side * distance
            elif b in axes and a not in axes:
                axes[a] = axes[b] - side * distance
            elif a in axes and b in axes:
                if abs(axes[b] - axes[a]) != distance:
                    free = [r for r in rim if r not in placed]
                    if not free:
                        raise VariationError(Text("vary.no_mesh", a=a, b=b, distance=float(
                            f"{abs(axes[b] - axes[a]) * unit:.4g}")))
                    _resize(sizes, free[-1], rim, abs(axes[b] - axes[a]), internal)
            else:
                continue
            placed.update(rim)  # these rims now set distances: no later stage resizes them
    return axes


def _resize(sizes: dict, rim, both: list, distance: int, internal) -> None:
    """Give ``rim`` the size that puts the two members of its mesh ``distance`` apart."""
    other = next(r for r in both if r != rim)
    theirs = sizes.get(other, other[1][1])
    if internal is None:
        size = distance - theirs
    elif internal == rim[0]:  # the ring is resized: R_ring = d + R_planet
        size = distance + theirs
    else:
        size = theirs - distance
    if size < MIN_TEETH:
        raise VariationError(Text("vary.no_close", gear=rim[0], size=size))
    sizes[rim] = size
