"""What a lecturer sees of a class, counted from its stored checks (``store.since`` rows):
for each step how many students reached it, how many were right at the first try, after
hints, or were shown it; what each student's first try was (the bars of the class view);
the mistake most of them made; and each student's latest answer (the cloud of tips).

Every count is of students, not of tries: a student who tried five times is one student.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from dataclasses import dataclass, field

from methods.practice import DIAGNOSES, TRIES

from .store import REVEALED


@dataclass
class StepCount:
    step: str
    reached: int = 0  # students with a try of the step (or who asked to be shown it)
    first: int = 0  # right at their first try
    later: int = 0  # right after hints
    revealed: int = 0  # shown it: asked, or three tries none right
    first_tries: Counter = field(default_factory=Counter)  # diagnosis → students ("none": shown untried)
    mistakes: Counter = field(default_factory=Counter)  # (diagnosis, term) → students who made it

    @property
    def mistake(self) -> tuple[int, list[tuple[str, str]]] | None:
        """The wrong answers most students of the step gave at some try: (students, every
        (diagnosis, term) that many made). A tie is all of them, in the grader's order of
        diagnoses, then by term: the same data says the same sentence in any process."""
        if not self.mistakes:
            return None
        most = max(self.mistakes.values())
        tied = [made for made, n in self.mistakes.items() if n == most]
        return most, sorted(tied, key=lambda m: (DIAGNOSES.index(m[0]), m[1]))


def by_student(rows: list[dict]) -> dict[tuple[str, str], list[dict]]:
    """(step, student) → that student's tries of the step, in the order they were made."""
    out: dict[tuple[str, str], list[dict]] = defaultdict(list)
    for row in sorted(rows, key=lambda r: (r["try"], r.get("id", 0))):
        out[(row["step"], row["student"])].append(row)
    return out


def outcome(tries: list[dict]) -> str:
    """A student's tries of one step, as the practice panel scores them: "first" (right at
    the first try), "later" (after hints), "revealed" (shown: asked, or three tries none
    right) or "open"."""
    graded = [r for r in tries if r["diagnosis"] != REVEALED]
    if graded and graded[0]["diagnosis"] == "ok":
        return "first"
    if any(r["diagnosis"] == "ok" for r in graded):
        return "later"
    return "revealed" if len(graded) >= TRIES or len(graded) < len(tries) else "open"


def counts(rows: list[dict], steps: list[str]) -> list[StepCount]:
    """One StepCount per step id of ``steps``, in that order (a step nobody tried: zeros)."""
    out = {step: StepCount(step) for step in steps}
    for (step, _), tries in by_student(rows).items():
        if step not in out:
            continue  # a step of another variant's list, or of an older version of the method
        count = out[step]
        count.reached += 1
        graded = [r for r in tries if r["diagnosis"] != REVEALED]
        count.first_tries[graded[0]["diagnosis"] if graded else "none"] += 1
        done = outcome(tries)
        if done != "open":
            setattr(count, done, getattr(count, done) + 1)
        for made in {(r["diagnosis"], r.get("term", "")) for r in graded
                     if r["diagnosis"] not in ("ok", "none")}:
            count.mistakes[made] += 1
    return [out[step] for step in steps]


def latest(rows: list[dict], step: str) -> dict[str, dict]:
    """Each student's latest answer to ``step`` (a try, not a "Show it"): what the class view
    draws as the cloud."""
    out = {}
    for (name, student), tries in by_student(rows).items():
        graded = [r for r in tries if r["diagnosis"] != REVEALED and r["answer"] is not None]
        if name == step and graded:
            out[student] = graded[-1]
    return out


def students(rows: list[dict], steps: list[str]) -> list[dict]:
    """Each student: nickname, steps done (right or shown) and first-try score, in the order
    they first checked."""
    table: dict[str, dict] = {}
    for (step, student), tries in by_student(rows).items():
        if step not in steps:
            continue
        row = table.setdefault(student, {"nickname": tries[0]["nickname"], "done": 0, "first": 0,
                                         "since": min(r.get("id", 0) for r in tries)})
        row["since"] = min(row["since"], min(r.get("id", 0) for r in tries))
        done = outcome(tries)
        row["done"] += done != "open"
        row["first"] += done == "first"
    ordered = sorted(table.values(), key=lambda r: r["since"])
    return [{k: v for k, v in r.items() if k != "since"} for r in ordered]


def bands(values: dict[str, float], count: int = 3) -> dict[str, tuple[float, float]]:
    """Students split by a given value in ``count`` bands of equal width from the smallest
    to the largest: student → (band's low, band's high)."""
    if not values:
        return {}
    low, high = min(values.values()), max(values.values())
    if high == low:  # every variant has the same value: one band
        return {student: (low, high) for student in values}
    width = (high - low) / count
    out = {}
    for student, value in values.items():
        k = min(int((value - low) / width), count - 1)
        out[student] = (low + k * width, low + (k + 1) * width if k < count - 1 else high)
    return out


def relative(answer: complex | float, own: complex | float, reference: complex | float,
             kind: str) -> complex | float:
    """An answer to another variant's step, carried to the reference variant's geometry: an
    arrow or a number scaled and turned as the student's own right answer is to the
    reference's, a point shifted by the difference; a right answer lands on the
    reference's, and a reversed arrow on its reverse."""
    if own == reference:
        return answer
    if kind != "point" and abs(own) > 1e-12 * abs(reference):
        return answer / own * reference
    return answer - own + reference
