"""One progress (issue 66): a student's tries, from any number of phones and command-line
hand-ins in any order, fold into one outcome per step, and every surface says it — the
page's progress (ui.classroom, as a phone resumes it), the lecturer's counts and table
(classes.summary), ``class summary --json``, and the score the gradebook gets
(lti.grades.score). No order raises, and no device is told "right" for a wrong value.

The property test drives the page's own functions (``ui.classroom.give``/``reveal`` with a
device's state, which goes stale until that device reloads) and the command line's
``practice --class --student --answers`` against one store."""

from __future__ import annotations

import contextlib
import io
import json
from functools import cache

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from classes import store, summary
from cli.commands import main
from lti.grades import score
from mechanisms import load_preset
from methods.practice import Verdict, grade
from methods.practice_steps import steps_for
from methods.progress import PRACTICE, REVEALED, TEST, Progress, Try, fold
from ui import classroom

EXAMPLES = 80  # interleavings tried by the property test (each a fresh class)
STEPS = 3  # of task 3.1's plans, the ones the devices answer


@cache
def steps() -> list:
    return steps_for(load_preset("zbirka-3.1"), "plans")


@pytest.fixture(scope="module")
def database(tmp_path_factory):
    url = f"sqlite:///{tmp_path_factory.mktemp('progress') / 'class.db'}"
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("MEHANIZMI_DATABASE_URL", url)
        yield url


def answer(step, kind: str):
    exact = complex(step.expected)
    return {"right": exact, "reversed": -exact, "long": exact * 1.7}[kind]


def command(*args: str) -> tuple[int, str]:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        code = main(list(args))
    return code, out.getvalue()


class Device:
    """A phone: its page's practice state, stale until it reloads (``resumed``)."""

    def __init__(self, seat: tuple[str, str]):
        self.seat = seat
        self.reload()

    def reload(self) -> None:
        self.state = {"seat": self.seat, "steps": steps(), "mine": {},
                      "progress": classroom.resumed(self.seat, steps())}

    def check(self, step, kind: str) -> None:
        given_answer = answer(step, kind)
        classroom.give(self.state, step, given_answer)
        told = self.state["mine"].get(step.id)
        if isinstance(told, Verdict):  # never "right" for a wrong value
            assert told.ok == grade(step, given_answer).ok

    def show(self, step) -> None:
        classroom.reveal(self.state, step)


def hand_in(seat: tuple[str, str], step, kind: str, tmp) -> int:
    path = tmp / "answers.json"
    z = answer(step, kind)
    path.write_text(json.dumps({"answers": {step.id: [z.real, z.imag]}}))
    return command("practice", "--method", "plans", "--class", seat[0], "--student", seat[1],
                   "--answers", str(path), "--json")[0]


EVENTS = st.lists(st.tuples(st.sampled_from(["phone1", "phone2", "cli"]),
                            st.integers(0, STEPS - 1),
                            st.sampled_from(["right", "reversed", "long", "show", "reload"])),
                  min_size=1, max_size=14)


def agree(code: str, key: str, token: str) -> dict[str, str]:
    """Every surface's outcome of each step for the one student: asserted equal; returned."""
    ids = [s.id for s in steps()]
    page = classroom.resumed((code, token), steps())
    on_page = {i: page.outcome(i) for i in ids}
    rows = store.export(code, key)
    (reported,) = summary.report(rows, ids, everyone={token: "Ana"})
    assert reported["steps"] == on_page
    counts = summary.counts(rows, ids)
    for i, count in zip(ids, counts):
        outcome = on_page[i]
        assert [getattr(count, o) for o in ("first", "later", "revealed")] == [
            int(outcome == o) for o in ("first", "later", "revealed")]
    done, said = command("class", "summary", code, "--key", key, "--json")
    assert done == 0
    (printed,) = json.loads(said)["students"]
    assert printed["steps"] == {i: on_page.get(i, "open") for i in printed["steps"]}
    right = sum(o in ("first", "later") for o in on_page.values())
    assert printed["score"]["right"] == right
    assert score(code, token, "sub")["scoreGiven"] == right
    table = summary.students(rows, ids)
    assert table == [] or table[0]["first"] == sum(o == "first" for o in on_page.values())
    return on_page


@pytest.mark.sweep
@settings(max_examples=EXAMPLES, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(events=EVENTS)
def test_any_interleaving_of_phones_and_hand_ins_folds_alike_everywhere(events, database, tmp_path):
    code, key = store.create("zbirka-3.1", "plans")
    token = store.join(code, "Ana")
    phones = {"phone1": Device((code, token)), "phone2": Device((code, token))}
    for device, index, kind in events:
        step = steps()[index]
        if device == "cli":
            if kind in ("right", "reversed", "long"):
                assert hand_in((code, token), step, kind, tmp_path) == 0
        elif kind == "reload":
            phones[device].reload()
        elif kind == "show":
            phones[device].show(step)
        else:
            phones[device].check(step, kind)
    outcomes = agree(code, key, token)
    # each step's outcome is the fold of its stored tries by the rule written out here
    for i, outcome in outcomes.items():
        tries = [r for r in store.export(code, key) if r["step"] == i]
        assert outcome == expected_outcome([r["diagnosis"] for r in sorted(tries, key=lambda r: r["try"])])


def expected_outcome(diagnoses: list[str]) -> str:
    """The rule in words: the first "ok" or "Show it" settles a step, as do three wrong
    tries; whatever comes after changes nothing."""
    wrong = 0
    for d in diagnoses:
        if d == REVEALED:
            return "revealed"
        if d == "ok":
            return "first" if wrong == 0 else "later"
        wrong += 1
        if wrong == 3:
            return "revealed"
    return "open"


def test_show_it_then_an_answer_from_a_stale_phone_locks_nobody_out(database, tmp_path):
    """The issue's lock-out: "Show it" on one phone, a graded answer from the other (stale)
    phone and one from the command line; every later open resumes without an error, the
    step counts as shown everywhere, and the stale phone is told it was already done."""
    code, key = store.create("zbirka-3.1", "plans")
    token = store.join(code)
    one, two = Device((code, token)), Device((code, token))
    first = steps()[0]
    one.show(first)
    two.check(first, "right")
    assert two.state["mine"][first.id] == classroom.SETTLED
    assert hand_in((code, token), first, "right", tmp_path) == 0  # stored, counts for nothing
    assert agree(code, key, token)[first.id] == "revealed"
    assert Device((code, token)).state["progress"].outcome(first) == "revealed"
    p = Progress.start()
    p.reveal(first)
    p.give(first, first.expected)  # (the reproduction: no KeyError)
    assert p.outcome(first) == "revealed" and p.record(first).late


def test_three_wrong_then_right_elsewhere_is_shown_on_every_surface(database):
    code, key = store.create("zbirka-3.1", "plans")
    token = store.join(code)
    one, two = Device((code, token)), Device((code, token))
    first = steps()[0]
    for _ in range(3):
        one.check(first, "reversed")
    two.check(first, "right")
    assert two.state["mine"][first.id] == classroom.SETTLED  # not "right"
    assert agree(code, key, token)[first.id] == "revealed"


def test_a_stale_phone_s_wrong_answer_to_a_solved_step_is_no_mistake_and_not_right(database):
    code, key = store.create("zbirka-3.1", "plans")
    token = store.join(code)
    one, two = Device((code, token)), Device((code, token))
    first = steps()[0]
    one.check(first, "right")
    two.check(first, "reversed")
    assert two.state["mine"][first.id] == classroom.SETTLED
    assert len(store.export(code, key)) == 2  # stored: it happened
    (count,) = summary.counts(store.export(code, key), [first.id])
    assert (count.first, count.mistake, dict(count.first_tries)) == (1, None, {"ok": 1})


def test_a_test_gives_one_try_without_show_it_and_refuses_a_second_in_words(database, tmp_path):
    code, key = store.create("zbirka-3.1", "plans", test=True)
    token = store.join(code)
    first, second = steps()[:2]
    phone = Device((code, token))
    assert phone.state["progress"].rules == TEST
    phone.check(first, "reversed")
    assert phone.state["progress"].outcome(first) == "wrong"
    with pytest.raises(store.OneTry):
        store.record(code, token, first.id, [1.0, 0.0], "ok", store.new_check())
    with pytest.raises(store.OneTry):
        store.record(code, token, second.id, None, REVEALED, store.new_check())
    assert hand_in((code, token), first, "right", tmp_path) == 2  # refused whole, nothing stored
    assert len(store.export(code, key)) == 1
    assert score(code, token, "sub") is None  # the gradebook waits for the close
    assert hand_in((code, token), second, "right", tmp_path) == 0
    done, said = command("class", "summary", code, "--key", key, "--json")
    assert json.loads(said)["students"][0]["steps"][first.id] == "wrong"
    store.close(code, key)
    assert score(code, token, "sub")["scoreGiven"] == 1


def test_the_fold_is_total_for_any_diagnoses_in_any_order():
    """Any diagnosis, any order, either rules: no error, and only the counted tries before
    the settling one."""
    diagnoses = ["ok", "sense", "wrong", REVEALED, "none", "scale"]
    for rules in (PRACTICE, TEST):
        for a in diagnoses:
            for b in diagnoses:
                for c in diagnoses:
                    tries = [Try("s", d) for d in (a, b, c)]
                    record = fold(tries, rules)["s"]
                    assert len(record.counted) + len(record.late) == 3
                    assert all(t.diagnosis != "none" for t in record.counted)
                    if record.outcome in ("first", "later"):
                        assert record.counted[-1].ok and not any(t.ok for t in record.counted[:-1])
                    if rules == TEST:
                        assert REVEALED not in [t.diagnosis for t in record.counted]
                        assert len(record.graded) <= 1
