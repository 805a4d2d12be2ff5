"""Exam and homework variants of a task, each a good exercise, with its answer key.

A lecturer asks for N variants of a preset: the task's given numbers are drawn around the
book's (``exams.variation``) and each candidate is kept only when it is a good
exercise — it assembles at the asked instant; no group is near a dead centre there; it is
reached from the task's own numbers without passing a dead centre, so every group keeps
the task's branch; it runs the whole cycle when the task's mechanism does; a gear train's
teeth mesh and it solves; a rotor's corrections are not vanishingly small. The same
settings give the same variants on any machine: candidate k draws from a generator seeded
with (seed, k), and numbers are rounded before anything is solved.
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from exams.codes import MAX_SEED, Settings, code, parse
from exams.variation import Given, VariationError, apply, givens
from mechanisms import SceneError
from mechanisms.gears import GearTrain
from mechanisms.loader import build_document, preset_document
from mechanisms.messages import Text
from mechanisms.rotor import Rotor
from mechanisms.schema import Scene
from mechanisms.writer import to_text
from methods.judge import drawing_errors
from reports.values import exact_values
from solvers.balancing import balance
from solvers.diagnostics import Unsolvable, solve_instant
from solvers.kinematics import Motion, solve
from solvers.structure import StructureError

MAX_COUNT = 200  # a class of students; more is a mistake or an attack
TRIES = 30  # candidates per asked variant before the ranges are declared too tight
CONDITION = 10.0  # a group worse than this (or than OWN × the task's own) is near a dead centre
OWN = 3.0  # a class III group's condition number is tens already in the book's drawings
STEPS = 4  # the walk from the task's numbers to a variant's, to see the branch kept
SMALL_CORRECTION = 0.05  # a correction under 5 % of the largest unbalance teaches nothing


class VariantError(ValueError):
    """No variant can be made as asked; the message says which constraint failed most."""


@dataclass(frozen=True)
class Answer:
    key: str  # as the preset's [book] names it: members.4.omega
    value: float
    unit: str
    tolerance: float | None  # ± a drawing at the task's scales allows (None: computed only)
    asked: bool = True  # printed in the task's answers; False: graded by its page's self-check


@dataclass(frozen=True)
class Variant:
    code: str
    index: int  # 1, 2, … in the set
    scene: Scene | Rotor | GearTrain
    given: tuple[tuple[Given, float], ...]  # each given of the task and its value here
    key: tuple[Answer, ...]
    drawn: dict[str, complex] = field(default_factory=dict)  # a linkage's points at its instant


@dataclass
class VariantSet:
    settings: Settings
    variants: list[Variant]
    rejected: Counter = field(default_factory=Counter)  # why candidates were dropped
    asked: int = 0

    @property
    def shortfall(self) -> Text | str:
        """Why fewer variants than asked were made ('' when all were)."""
        if len(self.variants) >= self.asked:
            return ""
        return Text("variants.short", made=len(self.variants), asked=self.asked,
                    tried=self.asked * TRIES, why=_most_often(self.rejected))


def _most_often(rejected: Counter) -> Text:
    reason, times = rejected.most_common(1)[0] if rejected else (Text("reject.none"), 0)
    return Text("variants.most_often", reason=reason, times=times)


@dataclass(frozen=True)
class Task:
    """A preset, read once: its document, its givens and what a variant must match."""

    scene: Scene | Rotor | GearTrain
    doc: dict
    givens: tuple[Given, ...]
    condition: float  # the task's own worst condition number at its instant (linkages)
    cycle: bool  # the task's crank turns the whole way: its variants must too
    drawn: dict[str, list[float]]  # a linkage's points at its instant: where each walk starts


def task(preset_id: str) -> Task:
    doc = preset_document(preset_id)
    scene = build_document(doc, source=f"{preset_id}.toml", default_id=preset_id)
    if not scene.book:
        raise VariantError(Text("variants.no_book", task=preset_id))
    condition, cycle, drawn = 1.0, False, {}
    if isinstance(scene, Scene):
        motion = solve_instant(scene, None)
        condition, drawn = float(motion.condition[0]), _positions(motion)
        if scene.driver.kind == "rotating":
            turn = solve(scene, np.linspace(0, 2 * math.pi, 360, endpoint=False), order=0)
            cycle = bool(turn.feasible.all())
    return Task(scene, doc, tuple(givens(doc)), condition, cycle, drawn)


def generate(settings: Settings, count: int) -> VariantSet:
    """``count`` variants of the settings' task, in order; VariantError when none can be made
    or the count is out of range."""
    if not 1 <= count <= MAX_COUNT:
        raise VariantError(Text("variants.count", most=MAX_COUNT, value=count))
    if not 0 <= settings.seed <= MAX_SEED:
        raise VariantError(Text("variants.seed", most=MAX_SEED, value=settings.seed))
    if not 1 <= settings.spread <= 50:
        raise VariantError(Text("variants.spread", value=settings.spread))
    base = task(settings.task)
    held = {i for i in settings.held if i < len(base.givens)}
    out = VariantSet(settings, [], asked=count)
    seen = set()
    for candidate in range(count * TRIES):
        rng = np.random.default_rng([settings.seed, candidate])
        values = [g.value if i in held else g.draw(rng, settings.spread)
                  for i, g in enumerate(base.givens)]
        if tuple(values) in seen:
            out.rejected[Text("reject.same")] += 1
            continue
        seen.add(tuple(values))
        try:
            scene, ended, drawn = _checked(base, values)
        except (VariationError, Unsolvable, StructureError, SceneError, Rejected) as exc:
            out.rejected[_reason(exc)] += 1
            continue
        index = len(out.variants) + 1
        name = code(settings, index)
        scene = _named(scene, base.scene, name)
        out.variants.append(Variant(name, index, scene, tuple(zip(base.givens, ended)),
                                    tuple(answers(scene, base.scene)), drawn))
        if index == count:
            break
    if not out.variants:
        raise VariantError(Text("variants.none", task=settings.task, tried=count * TRIES,
                                spread=settings.spread, why=_most_often(out.rejected)))
    return out


class Rejected(ValueError):
    """A candidate that solves but is not a good exercise."""


def _reason(exc: Exception) -> Text:
    if isinstance(exc, Rejected):
        return exc.args[0]
    return Text("reject.no_mesh" if isinstance(exc, VariationError) else "reject.no_assembly")


def _checked(base: Task, values: list[float]):
    doc, ended = apply(base.doc, list(base.givens), values)
    if isinstance(base.scene, Scene):
        scene, motion = _linkage(base, doc, values)
        return scene, ended, {n: complex(p.z[0]) for n, p in motion.points.items()}
    scene = build_document(doc, source="variant")
    if isinstance(scene, Rotor):
        found = balance(scene)
        largest = max(m.mass * m.radius for m in scene.masses)
        if any(f.mass * f.radius < SMALL_CORRECTION * largest for f in found.corrections.values()):
            raise Rejected(Text("reject.zero_mass"))
        return scene, ended, {}
    exact_values(scene)  # a train that does not solve raises Unsolvable
    return scene, ended, {}


def _linkage(base: Task, doc: dict, values: list[float]) -> tuple[Scene, Motion]:
    """The variant's scene, reached from the task's numbers in STEPS steps, each drawn
    where the last one was: a group that would have to pass a dead centre, or that ends on
    the other branch than the task's signs give, is rejected."""
    bound = max(CONDITION, OWN * base.condition)
    start = [g.value for g in base.givens]
    drawn = base.drawn
    for k in range(1, STEPS + 1):
        t = k / STEPS
        step, _ = apply(base.doc, list(base.givens), [a + t * (b - a) for a, b in zip(start, values)])
        step.pop("assembly", None)
        step["guess"] = drawn
        motion = solve_instant(build_document(step, source="variant"), None)
        if motion.condition[0] > 10 * bound:
            raise Rejected(Text("reject.dead_centre_on_way"))
        drawn = _positions(motion)
    doc = dict(doc, guess=drawn) if base.scene.guess else doc
    scene = build_document(doc, source="variant")
    motion = solve_instant(scene, None)
    if max(abs(complex(*drawn[n]) - p.z[0]) for n, p in motion.points.items() if n in drawn) > 1e-6:
        raise Rejected(Text("reject.branch"))
    if motion.condition[0] > bound:
        raise Rejected(Text("reject.near_dead_centre", bound=float(f"{bound:.3g}")))
    if base.cycle:
        turn = solve(scene, np.linspace(0, 2 * math.pi, 360, endpoint=False), order=0)
        if not turn.feasible.all():
            raise Rejected(Text("reject.no_turn"))
    return scene, motion


def _positions(motion) -> dict[str, list[float]]:
    return {n: [float(p.x[0]), float(p.y[0])] for n, p in motion.points.items()}


def _named(scene, task_scene, name: str):
    """The variant under its code: its own id and title, no printed values (they are the
    book's, for the book's numbers)."""

    title = f"{task_scene.title} — variant {name}"
    title_sr = f"{task_scene.title_sr} — varijanta {name}" if task_scene.title_sr else ""
    note = f"Variant {name} of {task_scene.source.lower()}: the task's given numbers changed."
    note_sr = (f"Varijanta {name}: zadatak sa izmenjenim zadatim vrednostima."
               if task_scene.title_sr else "")
    fitted = {"fit": None, "book_slips": {}} if isinstance(scene, Scene) else {}  # the book's numbers
    return dataclasses.replace(scene, id=f"variant-{name}", title=title, title_sr=title_sr,
                               note=note, note_sr=note_sr, book={}, book_notes={}, book_notes_sr={},
                               **fitted)


UNITS = {"omega": "s⁻¹", "epsilon": "s⁻²", "v": "m/s", "a": "m/s²", "s": "m", "x": "m", "y": "m",
         "mass": "kg", "radius": "m", "angle_deg": "°", "magnitude": "N", "torque": "N·m",
         "force": "N", "power": "W", "moment": "N·m", "normal": "N", "tangential": "N"}


def unit_of(key: str) -> str:
    """The unit of a result key (members.4.omega → s⁻¹; ratios are pure numbers)."""
    if key.startswith("ratios."):
        return "–"
    if key.startswith("travel."):  # the hay tedder's travel (task 1.3)
        return TRAVEL[key.split(".", 1)[1]][1]
    if key.startswith("turned."):  # an arm on the turned velocity plan, read at U_v
        return "m/s"
    if key.startswith(("distances.", "arms.")):  # a length of the figure at the drawn instant
        return "m"
    if key.startswith("points.") and key.count(".") == 1:  # a gear train's point: its speed
        return "m/s"
    last = key.rsplit(".", 1)[-1]
    if key.startswith("points.") and last in COMPONENTS:
        return COMPONENTS[last]
    return UNITS.get(last.removesuffix("_zhukovsky").removesuffix("_power_balance"), "")


# what the chapter pages' self-check boxes grade, as result keys: the plans page's speeds,
# accelerations, ω and ε (not the driver's: given); the kinetostatics page's M_p or F_p, P
# and |F_pq|; the gear page's ω of every member (a rotor's page grades each plane's
# unknowns, ``_self_checked``)
SELF_CHECKED = re.compile(r"points\.[^.]+\.[va]|members\.\d+\.(omega|epsilon)|"
                          r"driving\.(torque|force|power)|reactions\.(\d+)-(\d+)\.magnitude")


def answers(scene, task_scene) -> list[Answer]:
    """The task's asked quantities (its [book] keys) first, then what its chapter page's
    self-check grades besides; exact for ``scene``, with the error a drawing at the task's
    scales allows where the book reads it off a plan or a polygon."""
    exact = exact_values(dataclasses.replace(scene, book=task_scene.book))  # a train's asked ratios
    tolerance = drawing_errors(scene, task_scene)
    asked = [key for key in task_scene.book if key in exact]
    return ([Answer(key, exact[key], unit_of(key), tolerance.get(key)) for key in asked]
            + [Answer(key, exact[key], unit_of(key), tolerance.get(key), asked=False)
               for key in exact if key not in asked and _self_checked(key, scene)])


def _self_checked(key: str, scene) -> bool:
    if isinstance(scene, Rotor):  # each plane's unknown (its mass, or its radius) and angle
        part = re.fullmatch(r"corrections\.([^.]+)\.(mass|radius|angle_deg)", key)
        plane = part and scene.corrections.get(part.group(1))
        return bool(plane) and (part.group(2) == "angle_deg"
                                or (part.group(2) == "mass") == (plane.mass is None))
    found = SELF_CHECKED.fullmatch(key)
    if not found:
        return False
    if isinstance(scene, Scene):
        parts = key.split(".")
        if parts[0] == "points":
            return parts[1] not in scene.frame  # a frame point's v and a are 0
        if parts[0] == "members":
            return int(parts[1]) != scene.driver.member  # ω₂, ε₂ are given
        if parts[0] == "reactions":
            return int(found.group(3)) < int(found.group(4))  # F_pq once: |F_qp| = |F_pq|
    return True


def from_code(text: str) -> Variant:
    """The variant a student's code names (regenerated: the code holds its settings)."""
    settings, index = parse(text)
    found = generate(settings, index)
    if len(found.variants) < index:
        raise VariantError(Text("variants.not_in_set", code=text, count=len(found.variants)))
    return found.variants[index - 1]


def held_indices(givens_: tuple[Given, ...], names: list[str]) -> frozenset[int]:
    """Givens to hold at the book's values, named by label (AB, ω₂) or by number (1, 2, …)."""
    labels = [g.label for g in givens_]
    out = set()
    for name in names:
        if name.isdigit() and 1 <= int(name) <= len(labels):
            out.add(int(name) - 1)
        elif name in labels:
            out.add(labels.index(name))
        else:
            raise VariantError(Text("variants.no_given", name=name, givens=", ".join(
                f"{i + 1} {label}" for i, label in enumerate(labels))))
    return frozenset(out)


def as_json(found: VariantSet) -> dict:
    """The set as plain data: the same settings print the same bytes."""
    s = found.settings
    return {"task": s.task, "seed": s.seed, "spread_percent": s.spread,
            "held": sorted(s.held),
            "variants": [{"code": v.code, "scene": to_text(v.scene),
                          "given": {g.label: {"value": value, "unit": g.unit} for g, value in v.given},
                          "key": {a.key: a.value for a in v.key},
                          "asked": [a.key for a in v.key if a.asked],
                          "units": {a.key: a.unit for a in v.key},
                          "tolerance": {a.key: a.tolerance for a in v.key}}
                         for v in found.variants]}


def key_rows(found: VariantSet) -> list[dict]:
    """One row per answer of every variant: the lecturer's key as a table (CSV)."""
    return [{"code": v.code, "quantity": a.key, "value": a.value, "unit": a.unit,
             "tolerance": "" if a.tolerance is None else a.tolerance, "asked": a.asked}
            for v in found.variants for a in v.key]


SYMBOLS = {"omega": "ω", "epsilon": "ε", "v": "v", "a": "a", "s": "s"}
COMPONENTS = {"vx": "m/s", "vy": "m/s", "ax": "m/s²", "ay": "m/s²"}  # a point's, along x or y
SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def symbol(key: str) -> str:
    """A result key as the course writes the quantity: points.E.v → v_E, members.3.omega →
    ω₃, reactions.1-2.magnitude → F₁₂, corrections.I.mass → m_I, ratios.2-7 → i₂₇ (3-10 →
    i₃,₁₀), points.M.vx → v_Mx, a gear train's points.C (its speed) → v_C,
    distances.B-C → BC, arms.G_5.F → h(G_5, F) (the lever arm of G_5 about F)."""
    parts = key.split(".")
    head, last = parts[0], parts[-1]
    if head == "points" and len(parts) == 2:  # a gear train's point: its speed
        return f"v_{parts[1]}"
    if head == "points" and last in COMPONENTS:  # points.M.vx → v_Mx
        return f"{last[0]}_{parts[1]}{last[1]}"
    if head == "points":
        return f"{last}_{parts[1]}"
    if head == "members":
        return ("φ" if last == "angle_deg" else SYMBOLS.get(last, last)) + parts[1].translate(SUBSCRIPT)
    if head == "sliders":
        return f"{last}_rel({parts[1]})"
    if head == "reactions":
        part = {"normal": "ⁿ", "tangential": "ᵗ"}.get(last, "")
        return "F" + parts[1].replace("-", "").translate(SUBSCRIPT) + part
    if head == "ratios":  # i₂₇, but i₃,₁₀ where a member has two digits
        members = parts[1].split("-")
        return "i" + ("" if all(len(m) == 1 for m in members) else ",").join(members).translate(SUBSCRIPT)
    if head == "corrections":
        return ("φ" if last == "angle_deg" else last[0]) + "_" + parts[1]
    if head == "distances":
        return parts[1].replace("-", "")
    if head == "turned":  # turned.F_3 → h⁰(F_3), the arm on the turned velocity plan
        return f"h⁰({parts[1]})"
    if head == "arms":  # arms.G_5.F → h(G_5, F); arms.5-4.C → h(F₅₄, C)
        action = ".".join(parts[1:-1])
        if "-" in action:
            action = "F" + action.replace("-", "").translate(SUBSCRIPT)
        return f"h({action}, {last})"
    if head == "driving":
        return {"torque": "M_p", "force": "F_p", "power": "P"}.get(last, last)
    if head == "travel" and last in TRAVEL:
        return TRAVEL[last][0]
    return key


# the hay tedder's travel (task 1.3) as the book writes it: symbol, unit
TRAVEL = {"wheel_omega": ("ω_t", "s⁻¹"), "crank_omega": ("ω₂", "s⁻¹"), "cycle_time": ("T", "s"),
          "step_time": ("Δt", "s"), "step_distance": ("Δs", "m")}
