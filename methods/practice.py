"""Practice: the student gives each step of a construction, and the step is graded against the
exact one with the usual mistake named.

A step asks for a vector (an arrow of a plan or a polygon, in SI units), a point (a compass
position, m) or a signed scalar (ω₄, a stage's ω, a reaction's part). ``grade`` compares an
answer with the step's exact value within what a drawing at the page's scales allows, and
says which of a fixed set of mistakes it looks like:

``ok``            within the tolerance;
``sense``         the arrow reversed (or the sign of a scalar lost);
``direction``     the right length, another direction;
``length``        the right direction (or the right sign), another length;
``scale``         off by a power of ten or by the drawing scale: the usual unit slip;
``missing-term``  the step's sum without one of its known terms (a forgotten Coriolis,
                  normal or tangential part, or inertia force);
``wrong``         none of these; ``none``: not answered.

The steps themselves come from the methods written out step by step (methods.practice_steps);
later steps use the exact earlier results, so one slip does not spoil the rest.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable
from dataclasses import dataclass
from decimal import ROUND_FLOOR, Decimal

from mechanisms.messages import Text

# each diagnosis and each kind of step, by the strings that say it (locales/*.toml); the pages
# and the command line format them in their own language
HINTS = {"ok": "practice.hint_ok", "sense": "practice.hint_sense",
         "direction": "practice.hint_direction", "length": "practice.hint_length",
         "scale": "practice.hint_scale", "missing-term": "practice.hint_missing_term",
         "wrong": "practice.hint_wrong", "none": "practice.hint_none"}
VALUE_HINTS = {**HINTS, "sense": "practice.value_sense", "length": "practice.value_length",
               "scale": "practice.value_scale", "wrong": "practice.value_wrong"}
RULES = {"relative": "practice.rule_relative", "normal": "practice.rule_normal",
         "tangential": "practice.rule_tangential", "coriolis": "practice.rule_coriolis",
         "sliding": "practice.rule_sliding", "absolute": "practice.rule_absolute",
         "sum": "practice.rule_sum", "point": "practice.rule_point", "rate": "practice.rule_rate",
         "moment": "practice.rule_moment", "closing": "practice.rule_closing",
         "balancing": "practice.rule_balancing", "stage": "practice.rule_stage",
         "polygon": "practice.rule_polygon", "correction": "practice.rule_correction"}
ANGLE_READ = math.radians(1.0)  # a direction read with a protractor (as the polygons' error)
SLIP = 0.02  # an answer within 2 % of a slipped value is that slip
TRIES = 3  # after three tries the step is revealed
TURNS = 2  # a direction typed up to this many whole turns away is the same direction
DIAGNOSES = ("ok", "sense", "direction", "length", "scale", "missing-term", "wrong", "none")


@dataclass(frozen=True)
class Term:
    """A known vector (or value) a sum step adds, as it adds it (with its sign)."""

    name: str
    value: complex | float


@dataclass(frozen=True)
class Step:
    """One thing the student gives.

    ``expected`` and ``tolerance`` are in SI units (``unit``); ``scale`` is the drawing's
    scale in ``unit`` per cm (1 for a scalar found by arithmetic), against which the
    student's unit slip is recognised; ``tail`` is where the arrow starts on its drawing
    (``sheet``: "v", "a", a force polygon, "U", "V", "L" for the mechanism) so it can be
    drawn from there; ``terms`` the known vectors a sum step adds; ``missing`` what the
    answer would be with one of them forgotten; ``rule`` the kind of part (relative,
    normal, tangential, coriolis, sliding, sum, point, closing, scalar …) for the hint."""

    id: str
    asks: str  # in English, for the command line; pages show ``symbol`` and ``rule``
    symbol: str  # LaTeX
    kind: str  # "vector", "point" or "scalar"
    unit: str
    expected: complex | float
    tolerance: float
    scale: float = 1.0
    sheet: str = ""
    tail: complex = 0j
    terms: tuple[Term, ...] = ()
    missing: tuple[Term, ...] = ()
    rule: str = "sum"
    computed: bool = False  # its tolerance is a computed value's rounding, not a drawing's

    def json(self) -> dict:
        return {"id": self.id, "asks": self.asks, "kind": self.kind, "unit": self.unit,
                "expected": _out(self.expected, self.kind), "tolerance": self.tolerance,
                "terms": [{"name": term.name, "value": _out(term.value, self.kind)}
                          for term in self.terms]}


@dataclass(frozen=True)
class Verdict:
    """A step's diagnosis, with what the hint needs: ``ratio`` (answer ÷ exact, for
    ``length`` and ``scale``), ``term`` (for ``missing-term``), ``turn`` (degrees, for
    ``direction``)."""

    diagnosis: str
    ratio: float | None = None
    term: str = ""
    turn: float | None = None
    unit: str = ""  # for a unit slip ("scale"): the unit the answer was written in

    @property
    def ok(self) -> bool:
        return self.diagnosis == "ok"


def _real(value: complex | float) -> float:
    return float(value.real if isinstance(value, complex) else value)


def _out(value, kind: str):
    if kind == "scalar":
        return _real(value)
    return [float(value.real), float(value.imag)]


def finite(value) -> bool:
    """A real number a float can hold (not a bool, NaN or an infinity)."""
    return (isinstance(value, (int, float)) and not isinstance(value, bool)
            and math.isfinite(value))


def answer_of(value, kind: str) -> complex | float | None:
    """An answer as the command line or a page gives it: [x, y] or a number (None: none);
    anything else, NaN and infinities among them, is refused (ValueError)."""
    if value is None:
        return None
    if kind == "scalar":
        if not finite(value):
            raise ValueError(f"a finite number, got {value!r}")
        return float(value)
    if not (isinstance(value, (list, tuple)) and len(value) == 2 and all(map(finite, value))):
        raise ValueError(f"a pair [x, y] of finite numbers, got {value!r}")
    return complex(value[0], value[1])


def polar(magnitude: float, angle_deg: float) -> complex:
    """A typed arrow: its length and its direction, counter-clockwise from +x in degrees."""
    return cmath.rect(magnitude, math.radians(angle_deg))


def grade(step: Step, answer: complex | float | None) -> Verdict:
    """The diagnosis of ``answer`` for ``step`` (see the module's list)."""
    if answer is None or (isinstance(answer, float) and math.isnan(answer)):
        return Verdict("none")
    if step.kind == "scalar":
        return _scalar(step, _real(answer))
    return _vector(step, complex(answer))


def _close(a: complex, b: complex, tolerance: float) -> bool:
    """Within the drawing's tolerance: the tip within δ, or the length within δ and the
    direction within a protractor's reading."""
    if abs(a - b) <= tolerance:
        return True
    return (abs(abs(a) - abs(b)) <= tolerance and abs(b) > tolerance
            and abs(cmath.phase(a / b)) <= ANGLE_READ if a else False)


# the units a value of each unit is often written in by mistake, and how many of them make
# one of it: a kg·m² written in kg·mm² is a million times too large, and is a unit slip,
# not a length or a power of ten
UNIT_SLIPS = {"m": (("mm", 1e3), ("cm", 1e2)), "kg·m": (("kg·mm", 1e3),),
              "kg·m²": (("kg·mm²", 1e6),), "N·m": (("N·mm", 1e3),), "N": (("kN", 1e-3),),
              "°": (("rad", math.pi / 180),), "rad": (("°", 180 / math.pi),)}


def _slips(step: Step) -> list[float]:
    """The factors of a unit or scale slip: powers of ten, the drawing scale and its inverse
    (a length on the plan read as the value, or the other way round)."""
    factors = [10.0 ** k for k in (-3, -2, -1, 1, 2, 3)]
    if step.scale not in (0.0, 1.0):
        factors += [step.scale, 1 / step.scale]
    return factors


def _vector(step: Step, answer: complex) -> Verdict:
    exact, tol = complex(step.expected), step.tolerance
    if _close(answer, exact, tol):
        return Verdict("ok")
    for term in step.missing:
        if _close(answer, complex(term.value), tol):
            return Verdict("missing-term", term=term.name)
    if step.kind == "point":  # a point has no sense or length: only where it is
        return _slipped(step, answer, exact) or Verdict("wrong")
    if abs(exact) <= tol:
        return _slipped(step, answer, exact) or Verdict("wrong")
    if _close(answer, -exact, tol):
        return Verdict("sense")
    ratio = abs(answer) / abs(exact)
    turn = math.degrees(cmath.phase(answer / exact)) if answer else None
    same_line = answer != 0 and abs(cmath.phase(answer / exact)) <= ANGLE_READ
    if same_line:
        slipped = _slipped(step, answer, exact)
        return slipped or Verdict("length", ratio=ratio)
    if abs(abs(answer) - abs(exact)) <= tol:
        return Verdict("direction", turn=turn)
    return _slipped(step, answer, exact) or Verdict("wrong")


def _slipped(step: Step, answer: complex, exact: complex) -> Verdict | None:
    for unit, factor in UNIT_SLIPS.get(step.unit, ()):
        if abs(answer - exact * factor) <= max(step.tolerance * factor, SLIP * abs(exact * factor)):
            return Verdict("scale", ratio=factor, unit=unit)
    for factor in _slips(step):
        if abs(answer - exact * factor) <= max(step.tolerance * factor, SLIP * abs(exact * factor)):
            return Verdict("scale", ratio=factor)
    return None


@dataclass(frozen=True)
class Mistake:
    """A wrong answer the grader names for a scalar step: any answer within ``width`` of
    ``value`` gets ``diagnosis`` (with ``ratio`` or ``term`` for its hint), unless an
    earlier one in ``scalar_mistakes``' order took it."""

    diagnosis: str
    value: float
    width: float
    ratio: float | None = None
    term: str = ""
    unit: str = ""


def scalar_mistakes(step: Step) -> list[Mistake]:
    """The usual mistakes of a scalar step, in the order the grader tries them after the
    right answer: a term left out, the sign reversed, a unit slip (kg·mm² for kg·m²), a
    scale slip (a power of ten); for a direction (°), the opposite direction (half a turn
    either way) and radians for degrees. Practice grades by them, and the Moodle export
    (exams/moodle.py) lists them as its answers with the same feedback."""
    exact, tol = _real(step.expected), step.tolerance
    out = [Mistake("missing-term", _real(term.value), tol, term=term.name) for term in step.missing]
    units = [Mistake("scale", exact * f, max(tol * f, SLIP * abs(exact * f)), ratio=f, unit=u)
             for u, f in UNIT_SLIPS.get(step.unit, ())]
    if step.unit == "°":
        return out + [Mistake("sense", exact + half, tol) for half in (180.0, -180.0)] + units
    if abs(exact) > tol:
        out.append(Mistake("sense", -exact, tol))
        out += units
        out += [Mistake("scale", exact * f, max(tol * f, SLIP * abs(exact * f)), ratio=f)
                for f in _slips(step)]
    return out


def _scalar(step: Step, answer: float) -> Verdict:
    exact, tol = _real(step.expected), step.tolerance
    # a direction (°) is the same one or two whole turns away (as the Moodle bank's answers
    # list them; a value a thousand times too large is no direction): compared as the
    # nearest to the right one
    near = step.unit == "°" and abs(answer - exact) <= TURNS * 360.0 + tol
    turned = exact + equivalent_turn(answer - exact) if near else answer
    if abs(turned - exact) <= tol:
        return Verdict("ok")
    for m in scalar_mistakes(step):
        seen = turned if m.diagnosis in ("sense", "missing-term") else answer
        if abs(seen - m.value) <= m.width:
            return Verdict(m.diagnosis, ratio=m.ratio, term=m.term, unit=m.unit)
    if step.unit != "°" and abs(exact) > tol and answer != 0 \
            and math.copysign(1, answer) == math.copysign(1, exact):
        return Verdict("length", ratio=answer / exact)
    return Verdict("wrong")


def equivalent_turn(difference: float) -> float:
    """An angle's difference from the right one, in (−180°, 180°]: −78,92° is 281,08°."""
    return 180.0 - (180.0 - difference) % 360.0


def ratio_digits(ratio: float) -> int:
    """Significant digits that show how far a ratio is from 1 (1,004 times, not "1 times")."""
    return 3 if abs(ratio - 1) >= 0.01 else 4


def printed_tolerance(tolerance: float, digits: int = 3) -> float:
    """A tolerance as every surface prints it: rounded *down* to ``digits`` significant
    digits, so that a value the judge finds outside never reads as inside the printed
    bound (0,2051 printed "± 0,21" beside "not right" for a value 0,2053 off)."""
    if not (math.isfinite(tolerance) and tolerance > 0):
        return tolerance
    shortest = Decimal(repr(float(tolerance)))  # (0.205, not the binary 0.20499999…)
    place = shortest.adjusted() - (digits - 1)
    return float(shortest.scaleb(-place).to_integral_value(ROUND_FLOOR).scaleb(place))


def hint_keys(step: Step, verdict: Verdict) -> list[str]:
    """The strings that say a verdict: its diagnosis — of a value and its sign for a scalar
    step, of an arrow otherwise; a unit slip as one — and for a step drawn the wrong way or
    not at all the book's rule for that kind of step (without the answer; none for a step
    with no rule)."""
    if verdict.unit:
        keys = ["practice.value_unit" if step.kind == "scalar" else "practice.hint_unit"]
    elif verdict.diagnosis == "ok" and step.computed:
        keys = ["practice.hint_ok_computed"]  # (not "what a drawing allows": none was drawn)
    else:
        keys = [(VALUE_HINTS if step.kind == "scalar" else HINTS)[verdict.diagnosis]]
    if verdict.diagnosis in ("sense", "direction", "length", "wrong") and step.rule:
        keys.append(RULES[step.rule])
    return keys


def hint_texts(step: Step, verdict: Verdict, term: Callable[[str], str] = str) -> tuple[Text, ...]:
    """The hint of a verdict as sentences to render in any language — the only place its
    words and numbers are chosen: the practice panel, the self-check box, ``check``,
    ``practice --answers`` and the Moodle bank's feedback all render these. A ratio with the
    digits that show how far it is from 1 (1000, 0,221, 1,006); a scalar's "right sign,
    another size" without one, as Moodle's band of sizes cannot have one; ``term`` writes a
    left-out term's name (LaTeX → text)."""
    if step.kind == "scalar" and verdict.diagnosis == "length":
        return (Text("practice.value_off"),) + tuple(Text(k) for k in hint_keys(step, verdict)[1:])
    ratio = (float(f"{verdict.ratio:.{ratio_digits(verdict.ratio)}g}")
             if verdict.ratio is not None else "")
    values = {"ratio": ratio, "term": term(verdict.term) if verdict.term else "",
              "turn": float(f"{abs(verdict.turn):.2g}") if verdict.turn else "",
              "unit": step.unit, "wrote": verdict.unit}
    return tuple(Text(key, **values) for key in hint_keys(step, verdict))
