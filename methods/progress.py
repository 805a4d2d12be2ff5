"""A student's progress: their tries, in the order they were made (or stored), folded into one
outcome per step — the only rule that says how a step ended. The practice panel, the
lecturer's live view and its summary, the exports, the gradebook's score and ``class
summary`` all call ``fold`` (through ``Progress``), so they cannot disagree.

A step's outcome:

``first``     right at the first try;
``later``     right after one or more wrong tries (hints);
``revealed``  shown: the student asked ("Show it"), or used every try none right;
``wrong``     in a test (no hints, no "Show it"): its one try was not right;
``open``      not settled yet.

The fold is total: any order of tries from any number of devices is folded without an
error. A try made after its step was settled (a stale phone, a second hand-in) happened and
is kept, as ``late``, but changes nothing.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

from .practice import TRIES, Step, Verdict, answer_of, grade

REVEALED = "revealed"  # the diagnosis kept for "Show it"
OUTCOMES = ("first", "later", "revealed", "wrong", "open")


@dataclass(frozen=True)
class Rules:
    """How a step is settled: ``tries`` before it is (``TRIES`` in practice, one in a test),
    and whether hints and "Show it" are given (not in a test)."""

    tries: int = TRIES
    hints: bool = True


PRACTICE = Rules()
TEST = Rules(tries=1, hints=False)


@dataclass(frozen=True)
class Try:
    """One try of a step: its diagnosis (a grader's, or REVEALED for "Show it"), the answer
    and the term a ``missing-term`` left out; ``check`` the stored check's id (a page finds
    its own try by it); ``verdict`` the grader's whole verdict where it was graded here (a
    hint's ratio or turn), None for a try read back from the store."""

    step: str
    diagnosis: str
    answer: object = None
    term: str = ""
    check: str = ""
    verdict: Verdict | None = None

    @property
    def ok(self) -> bool:
        return self.diagnosis == "ok"


@dataclass
class Record:
    """One step's tries: those that counted, up to the one that settled it, and those made
    after (``late``), with the step's outcome."""

    counted: list[Try] = field(default_factory=list)
    late: list[Try] = field(default_factory=list)
    outcome: str = "open"

    @property
    def done(self) -> bool:
        return self.outcome != "open"

    @property
    def graded(self) -> list[Try]:
        """The counted tries that were answers (not a "Show it")."""
        return [made for made in self.counted if made.diagnosis != REVEALED]


def settle(record: Record, made: Try, rules: Rules = PRACTICE) -> bool:
    """One more try of ``record``'s step: whether it counted (False: the step was settled
    already, or the try is one the rules do not give, such as "Show it" in a test)."""
    if record.done or made.diagnosis == "none" or (made.diagnosis == REVEALED and not rules.hints):
        record.late.append(made)
        return False
    record.counted.append(made)
    if made.diagnosis == REVEALED:
        record.outcome = "revealed"
    elif made.ok:
        record.outcome = "first" if len(record.graded) == 1 else "later"
    elif len(record.graded) >= rules.tries:
        record.outcome = "revealed" if rules.hints else "wrong"
    return True


def fold(tries: Iterable[Try], rules: Rules = PRACTICE) -> dict[str, Record]:
    """Each step's record from tries in the order they were made (the store's: by try number
    within a step)."""
    out: dict[str, Record] = {}
    for made in tries:
        settle(out.setdefault(made.step, Record()), made, rules)
    return out


def score(records: dict[str, Record], steps: Iterable[str]) -> dict[str, int]:
    """How many of ``steps`` (ids) ended each way, and ``right`` (first + later) and ``of``:
    what the page's score, the summary and the gradebook say."""
    ids = list(steps)
    counts = dict.fromkeys(OUTCOMES, 0)
    for step in ids:
        counts[records.get(step, Record()).outcome] += 1
    return {**counts, "right": counts["first"] + counts["later"], "of": len(ids)}


@dataclass
class Progress:
    """A student's run through a list of steps on one device or in a class, as the fold
    says: ``give`` grades and adds a try, ``reveal`` adds a "Show it"."""

    rules: Rules = PRACTICE
    records: dict[str, Record] = field(default_factory=dict)

    @classmethod
    def start(cls, rules: Rules = PRACTICE) -> Progress:
        return cls(rules)

    @classmethod
    def of(cls, tries: Iterable[Try], rules: Rules = PRACTICE) -> Progress:
        return cls(rules, fold(tries, rules))

    def add(self, made: Try) -> bool:
        """Fold in one try: whether it counted."""
        return settle(self.records.setdefault(made.step, Record()), made, self.rules)

    def give(self, step: Step, answer, check: str = "") -> Verdict:
        """Grade one try and fold it in (an unanswered one is not a try). A step already
        settled keeps its outcome; the try is kept as late."""
        verdict = grade(step, answer)
        if verdict.diagnosis != "none":
            self.add(Try(step.id, verdict.diagnosis, answer, verdict.term, check, verdict))
        return verdict

    def reveal(self, step: Step, check: str = "") -> None:
        self.add(Try(step.id, REVEALED, check=check))

    def record(self, step: Step | str) -> Record:
        return self.records.get(step if isinstance(step, str) else step.id, Record())

    def done(self, step: Step | str) -> bool:
        return self.record(step).done

    def outcome(self, step: Step | str) -> str:
        return self.record(step).outcome

    def late(self, check: str) -> bool:
        """Whether the try stored as ``check`` came after its step was settled."""
        return any(made.check == check for record in self.records.values() for made in record.late)

    def score(self, steps: Iterable[Step | str]) -> dict[str, int]:
        return score(self.records, [s if isinstance(s, str) else s.id for s in steps])


def verdict_of(step: Step, made: Try) -> Verdict:
    """A try's whole verdict for its hint: the one it was graded with, or — read back from
    the store — graded again when that gives the stored diagnosis (the stored one is the
    truth: a grader changed since keeps the stored diagnosis, with no ratio)."""
    if made.verdict is not None:
        return made.verdict
    try:
        again = grade(step, answer_of(made.answer, step.kind))
    except ValueError:  # (not an answer of this step's kind: the stored diagnosis stands)
        again = None
    if again is not None and again.diagnosis == made.diagnosis:
        return again
    return Verdict(made.diagnosis, term=made.term)
