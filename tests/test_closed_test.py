"""A closed test is closed (issue 82): after the lecturer closes it, no surface stores a try
— a page that read the class before the closing, the command line, a new student by the join
link or by a launch from Moodle — and each refusal says so in the student's words; the
summary, the export and the grades sent at closing stay equal. Also the test's own words:
no hint promised, a step tried on another phone named as the page names it, and a class
form with a refused instant that cannot start anything."""

from __future__ import annotations

import json

import pytest

from classes import store
from classes.steps import steps_of
from ui.i18n import t

from .test_classroom_page import _check, _prompt, _seated
from .test_cli import run
from .test_pages import page


@pytest.fixture(autouse=True)
def database(tmp_path, monkeypatch):
    """The pages' store (AppTest reads MEHANIZMI_DATABASE_URL): a file of this test's own."""
    monkeypatch.setenv("MEHANIZMI_DATABASE_URL", f"sqlite:///{tmp_path / 'class.db'}")


def _pair(value) -> list[float]:
    """A plan step's answer as the store keeps it: [x, y]."""
    return [complex(value).real, complex(value).imag]


def _test_with_two_answers(url: str | None = None) -> tuple[str, str, str, list]:
    code, key = store.create("zbirka-3.1", "plans", test=True, url=url)
    token = store.join(code, "Ana", url=url)
    steps = steps_of(store.find(code, url))
    for step in steps[:2]:
        store.record(code, token, step.id, _pair(step.expected), "ok", store.new_check(), url=url)
    return code, key, token, steps


def test_the_store_refuses_a_late_try_even_from_a_page_that_read_the_class_before(url):
    """The closing time is a rule of the store, in the statement that inserts: a caller
    whose class (``known``) was read before the closing still stores nothing."""
    code, key, token, steps = _test_with_two_answers(url)
    known = store.seated(code, token, url)  # read while the test is open
    before = store.export(code, key, url)
    store.close(code, key, url)
    for given in (known, None):
        with pytest.raises(store.TestClosed) as refused:
            store.record(code, token, steps[2].id, _pair(steps[2].expected), "ok",
                         store.new_check(), url=url, known=given)
        assert refused.value.args[0].key == "class.test_closed_try"
    with pytest.raises(store.TestClosed):
        store.join(code, "Late", url=url)  # no new seat in a closed test
    assert store.export(code, key, url) == before
    assert store.find(code, url).closed is not None  # not reopened by a stray try


def test_the_command_line_after_closing_exits_2_and_stores_nothing(tmp_path, monkeypatch):
    database = f"sqlite:///{tmp_path / 'cli.db'}"
    monkeypatch.setenv("MEHANIZMI_DATABASE_URL", database)
    code, key, token, steps = _test_with_two_answers()
    graded = run("class", "summary", code, "--key", key, "--json").stdout
    answers = tmp_path / "answers.json"
    answers.write_text(json.dumps({"answers": {steps[2].id: [1.0, 2.0]}}))
    store.close(code, key)
    done = run("practice", "--method", "plans", "--answers", str(answers), "--class", code,
               "--student", token)
    assert done.returncode == 2 and "closed at" in done.stderr and "stored as" not in done.stdout
    assert len(done.stderr.strip().splitlines()) == 1
    late = run("class", "join", code)
    assert late.returncode == 2 and "closed at" in late.stderr
    after = run("class", "summary", code, "--key", key, "--json").stdout
    assert json.loads(after)["students"] == json.loads(graded)["students"]  # the grades sent


def test_a_student_page_open_at_the_closing_is_refused_in_words_and_learns_of_it():
    """The issue's walk-through: a student answers, the lecturer closes, the student presses
    Check on the next step — not stored, said with the closing time and a lock, and from
    then on the page says the test is closed (its verdicts shown)."""
    code, key = store.create("zbirka-3.1", "plans", test=True)
    token = store.join(code, "Ana")
    steps = steps_of(store.find(code))
    at = _seated(code, token)
    _check(at, steps[0], steps[0].expected)
    assert _prompt(at).startswith("Step 2") or "Stored" in " ".join(i.value for i in at.info)
    store.close(code, key)
    if not _prompt(at).startswith("Step 2"):
        next(b for b in at.button if b.label == t("practice.next", "en")).click().run()
    _check(at, steps[1], steps[1].expected)
    said = " ".join(i.value for i in at.info)
    assert "The test was closed at" in said and not at.error, said
    assert [r["step"] for r in store.export(code, key)] == [steps[0].id]
    again = _seated(code, token)  # the page that opens (or runs again) after the closing
    assert any(i.value.startswith("The test was closed at") and "verdicts" in i.value for i in again.info)


def test_the_join_link_of_a_closed_test_seats_no_one():
    code, key = store.create("zbirka-3.1", "plans", test=True)
    store.close(code, key)
    at = page("pages/class.py", lang="en")
    at.query_params["join"] = code
    at.run()
    assert any("closed at" in i.value for i in at.info)
    assert not [b for b in at.button if b.label == t("class.join", "en")]


def test_a_test_page_promises_no_hint_and_names_a_step_tried_elsewhere_as_it_shows_it():
    code, key = store.create("zbirka-3.1", "plans", test=True)
    token = store.join(code, "Ana")
    steps = steps_of(store.find(code))
    phone1, phone2 = _seated(code, token), _seated(code, token)
    captions = " ".join(c.value for c in phone1.caption)
    assert "hint comes" not in captions.lower()  # "no hints", said once, not contradicted
    _check(phone1, steps[0], steps[0].expected)
    _check(phone2, steps[0], steps[0].expected)  # a stale phone: the step is taken
    said = " ".join(i.value for i in phone2.info)
    assert "has been tried already" in said and steps[0].id not in said, said
    assert not phone2.error  # a lock, not the store's "not saved" cloud


def test_a_refused_instant_keeps_the_class_from_starting():
    at = page("pages/class.py", lang="en")
    at.text_input(key="class_at").input("30,5").run()
    start = next(b for b in at.button if b.label == t("class.start", "en"))
    assert start.disabled and "Correct the refused field first" in (start.help or "")
    at.text_input(key="class_at").input("30.5").run()
    assert not next(b for b in at.button if b.label == t("class.start", "en")).disabled


def test_a_stale_phone_s_show_it_after_another_phone_s_right_answer_says_done_elsewhere():
    """Issue 82, point 5: the stale phone's *Show it* showed "Right, within …" for an
    answer it never gave; now the one notice of a step settled on another device."""
    code, key = store.create("zbirka-3.1", "plans")
    token = store.join(code, "Ana")
    steps = steps_of(store.find(code))
    phone1, phone2 = _seated(code, token), _seated(code, token)
    _check(phone1, steps[0], steps[0].expected)
    phone2.button(key="pr_plans_reveal").click().run()
    assert not phone2.success and any("another device" in i.value for i in phone2.info)
    assert [r["diagnosis"] for r in store.export(code, key)] == ["ok", store.REVEALED]


def test_after_closing_a_step_whose_second_try_was_refused_shows_its_verdict_and_hint():
    """Issue 82, point 6: such a step said "already done (wrong)" without the hint every
    other step shows once the test is closed."""
    code, key = store.create("zbirka-3.1", "plans", test=True)
    token = store.join(code, "Ana")
    steps = steps_of(store.find(code))
    phone1, phone2 = _seated(code, token), _seated(code, token)
    _check(phone1, steps[0], -complex(steps[0].expected))  # reversed: its one try, wrong
    _check(phone2, steps[0], steps[0].expected)  # refused: tried already
    store.close(code, key)
    phone2.run()
    assert any(t("practice.hint_sense", "en") in w.value for w in phone2.warning)
    assert not any("already done" in i.value for i in phone2.info)


def test_the_command_line_names_a_step_tried_already_as_the_pages_do(tmp_path, monkeypatch):
    """Issue 82, point 3: the command line said "v.a-b, v.b has been tried already"."""
    monkeypatch.setenv("MEHANIZMI_DATABASE_URL", f"sqlite:///{tmp_path / 'cli.db'}")
    code, key, token, steps = _test_with_two_answers()
    answers = tmp_path / "answers.json"
    answers.write_text(json.dumps({"answers": {steps[0].id: [1.0, 2.0]}}))
    done = run("practice", "--method", "plans", "--answers", str(answers), "--class", code,
               "--student", token)
    assert done.returncode == 2 and "v_BA (v.a-b) has been tried already" in done.stderr
