"""What a lecturer sees of a class, counted from its stored checks (``store.since`` rows):
for each step how many students reached it, how many were right at the first try, after
hints, or were shown it; what each student's first try was (the bars of the class view);
the mistake most of them made; and each student's latest answer (the cloud of tips).

Every count is of students, not of tries: a student who tried five times is one student.
"""

from __future__ import annotations

import json
from collections import Counter, defaultdict
from dataclasses import dataclass, field

from methods.practice import DIAGNOSES
from methods.progress import PRACTICE, REVEALED, Progress, Rules, Try

from .steps import steps_of
from .store import Class


@dataclass
class StepCount:
    step: str
    reached: int = 0  # students with a try of the step (or who asked to be shown it)
    first: int = 0  # right at their first try
    later: int = 0  # right after hints
    revealed: int = 0  # shown it: asked, or three tries none right
    wrong: int = 0  # in a test: its one try not right
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


def tried(rows: list[dict]) -> list[Try]:
    """Stored checks as tries, in the order the store numbered them (by try within a step,
    then by check number): the order every fold of them takes."""
    return _tried(list(enumerate(rows)))


def _tried(numbered: list[tuple[int, dict]]) -> list[Try]:
    ordered = sorted(numbered, key=lambda ir: (ir[1]["try"], ir[1].get("id", 0)))
    return [Try(r["step"], r["diagnosis"], r["answer"], r.get("term") or "", _check(i, r))
            for i, r in ordered]


def _check(index: int, row: dict) -> str:
    """A row's check id (a planted row without one: its place in the rows given)."""
    return row.get("check") or f"#{index}"


def progress(rows: list[dict], rules: Rules = PRACTICE) -> dict[str, Progress]:
    """Each student's progress (methods.progress's fold) from their stored checks: what their
    page, this view, ``class summary`` and the gradebook all say."""
    mine: dict[str, list[tuple[int, dict]]] = defaultdict(list)
    for numbered in enumerate(rows):
        mine[numbered[1]["student"]].append(numbered)
    return {student: Progress.of(_tried(own), rules) for student, own in mine.items()}


def counts(rows: list[dict], steps: list[str], rules: Rules = PRACTICE) -> list[StepCount]:
    """One StepCount per step id of ``steps``, in that order (a step nobody tried: zeros).
    Only the tries that counted are counted: one made after the step was settled (a stale
    phone's) is no mistake and no first try."""
    out = {step: StepCount(step) for step in steps}
    for student in progress(rows, rules).values():
        for step, record in student.records.items():
            if step not in out or not record.counted:
                continue  # a step of another variant's list, or of an older version of the method
            count = out[step]
            count.reached += 1
            count.first_tries[record.counted[0].diagnosis if record.counted[0].diagnosis != REVEALED
                              else "none"] += 1
            if record.done:
                setattr(count, record.outcome, getattr(count, record.outcome) + 1)
            for made in {(r.diagnosis, r.term) for r in record.graded if not r.ok}:
                count.mistakes[made] += 1
    return [out[step] for step in steps]


def latest(rows: list[dict], step: str, rules: Rules = PRACTICE) -> dict[str, dict]:
    """Each student's latest answer to ``step`` that counted (a try, not a "Show it"): what
    the class view draws as the cloud."""
    mine = [r for r in rows if r["step"] == step]
    by_check = {_check(i, r): r for i, r in enumerate(mine)}
    out = {}
    for student, own in progress(mine, rules).items():
        graded = [t for t in own.record(step).graded if t.answer is not None]
        if graded:
            out[student] = by_check[graded[-1].check]
    return out


def students(rows: list[dict], steps: list[str], rules: Rules = PRACTICE) -> list[dict]:
    """Each student who checked a step of ``steps``, in the order they first checked: their
    nickname, steps done (settled any way) and right at the first try — ``report``'s."""
    mine = sorted((r for r in rows if r["step"] in steps), key=lambda r: r.get("id", 0))
    first: dict[str, str] = {}
    for row in mine:
        first.setdefault(row["student"], row["nickname"])
    return [{"nickname": said["nickname"], "done": said["score"]["done"],
             "first": list(said["steps"].values()).count("first")}
            for said in report(mine, steps, rules, first)]


def report(rows: list[dict], steps: list[str], rules: Rules = PRACTICE,
           everyone: dict[str, str] | None = None) -> list[dict]:
    """Per student (``everyone``: token → nickname, those who joined and never checked
    too): each step's outcome and the score a gradebook gets — ``class summary``'s rows,
    and what lti.grades sends."""
    folded = progress(rows, rules)
    names = dict(everyone or {})
    for row in rows:
        names.setdefault(row["student"], row["nickname"])
    out = []
    for student, nickname in names.items():
        own = folded.get(student, Progress(rules))
        said = own.score(steps)
        out.append({"student": student, "nickname": nickname,
                    "steps": {step: own.outcome(step) for step in steps},
                    "score": {"right": said["right"], "done": said["of"] - said["open"],
                              "of": said["of"]}})
    return out


def of_class(found: Class, rows: list[dict], everyone: dict[str, str]) -> dict:
    """A class's summary as ``class summary --json`` prints it and the live view's download
    gives it: the steps, and per student each step's outcome and the score (``report``)."""
    steps = [s.id for s in steps_of(found, 1 if found.variants else None)]
    return {"code": found.code, "method": found.method, "scene": found.scene, "at": found.at,
            "test": found.test, "closed": found.closed.isoformat() if found.closed else None,
            "steps": steps, "students": report(rows, steps, found.rules, everyone)}


def as_json(said: dict) -> str:
    """A class's summary (``of_class``) as ``class summary --json`` prints it and the live
    view's *Outcomes* download saves it: the same bytes."""
    return json.dumps(said, ensure_ascii=False, allow_nan=False) + "\n"


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
