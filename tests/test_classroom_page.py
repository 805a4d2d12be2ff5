"""The class page and a student in a class (AppTest): a lecturer starts a class and gets its
code, its join link and QR code and the lecturer's link; a student joins by the code and
lands on the method's page with practice on; each check is stored before its verdict, and
a reload brings the progress back from the store; a store that cannot take a check says
"not saved" and shows no verdict."""

from __future__ import annotations

import cmath
import math

import pytest
import sqlalchemy as sa

from classes import store
from cli.practice import steps_for
from mechanisms import load_preset
from ui.i18n import t

from .test_pages import page, typed


@pytest.fixture(autouse=True)
def database(tmp_path, monkeypatch):
    monkeypatch.setenv("MEHANIZMI_DATABASE_URL", f"sqlite:///{tmp_path / 'class.db'}")


@pytest.mark.parametrize("lang", ["sr", "en"])
def test_a_lecturer_starts_a_class_and_a_student_joins_it(lang, monkeypatch):
    monkeypatch.setattr("ui.i18n.current", lambda: lang)  # (AppTest formats choices outside a run)
    at = page("pages/class.py", lang=lang, class_method="plans")
    assert not at.exception
    next(b for b in at.button if b.label == t("class.start", lang)).click().run()
    assert not at.exception
    code = next(m.value for m in at.markdown if "`" in m.value).split("`")[1]
    join, lecturer = (c.value for c in at.code[:2])
    assert join.endswith(f"/class?join={code}") and f"class={code}&key=" in lecturer
    assert at.get("image")  # the QR code
    key = lecturer.rsplit("key=", 1)[1]
    assert store.find(code).method == "plans" and store.export(code, key) == []
    assert (at.query_params["class"], at.query_params["key"]) == (code, key)  # the page's own link
    assert t("class.results", lang, code=code) in [h.value for h in at.header]  # the view under it

    student = page("pages/class.py", lang=lang, query=None)
    student.query_params["join"] = code.lower()
    student.run()
    assert t("class.join_title", lang, code=code) in [h.value for h in student.header]
    student.text_input(key="class_nickname").input("<b>Ana</b>").run()
    next(b for b in student.button if b.label == t("class.join", lang)).click().run()
    assert not student.exception
    assert student.query_params["class"] == code and student.query_params["student"]
    assert store.student(code, student.query_params["student"])["nickname"] == "<b>Ana</b>"


def _shown(at) -> tuple[str, str, bool]:
    """The join code, the lecturer's link and whether the QR code is on the page."""
    code = next((m.value.split("`")[1] for m in at.markdown if "`" in m.value), "")
    return code, next((c.value for c in at.code if "key=" in c.value), ""), bool(at.get("image"))


def test_the_lecturer_keeps_the_code_and_link_through_reruns_and_a_reload(monkeypatch):
    """Right after Start: the language switched, projector mode on, the page reloaded (a new
    session on the same link) — the code, the QR code and the lecturer's link stay, until the
    lecturer hides them; the results stay under them, and the code can be shown again."""
    language = {"now": "sr"}  # (AppTest formats choices outside a run, in this language)
    monkeypatch.setattr("ui.i18n.current", lambda: language["now"])
    at = page("pages/class.py", lang="sr", class_method="plans")
    next(b for b in at.button if b.label == t("class.start", "sr")).click().run()
    code, lecturer, qr = _shown(at)
    assert code and lecturer and qr
    language["now"] = "en"
    at.session_state["lang"] = "en"  # the language picker's rerun
    at.run()
    assert _shown(at) == (code, lecturer, True) and not at.exception
    at.session_state["present"] = True  # projector mode's rerun
    at.run()
    assert _shown(at) == (code, lecturer, True)
    reload = page("pages/class.py", query=None)  # this browser's reload: its address, anew
    reload.query_params.update({k: at.query_params[k] for k in ("class", "key", "made")})
    reload.run()
    assert _shown(reload) == (code, lecturer, True)
    next(b for b in reload.button if b.label == t("class.close_panel", "en")).click().run()
    assert _shown(reload)[2] is False and "made" not in reload.query_params
    assert t("class.results", "en", code=code) in [h.value for h in reload.header]
    next(b for b in reload.button if b.label == t("class.show_panel", "en")).click().run()
    assert _shown(reload) == (code, lecturer, True)


def test_a_wrong_code_or_key_is_said_in_words():
    at = page("pages/class.py", lang="en")
    at.query_params["join"] = "ZZZZZZ"
    at.run()
    assert at.error and "No class has the code ZZZZZZ" in at.error[0].value
    code, _ = store.create("zbirka-3.1", "plans")
    at = page("pages/class.py", lang="en")
    at.query_params.update({"class": code, "key": "guessed"})
    at.run()
    assert at.error and "not the lecturer's key" in at.error[0].value


def _seated(code: str, token: str):
    at = page("pages/velocity_plans.py", lang="en", pr_plans_on=True, scene="zbirka-3.1")
    at.query_params.update({"class": code, "student": token})
    at.run()
    return at


def _check(at, step, answer) -> None:
    z = complex(answer)
    typed(at, f"pr_plans_len_{step.id}", abs(z))
    typed(at, f"pr_plans_ang_{step.id}", math.degrees(cmath.phase(z)))
    next(b for b in at.button if b.label == t("practice.check", "en")).click().run()


def _prompt(at) -> str:
    return next(m.value for m in at.markdown if m.value.startswith("Step "))


def test_every_check_of_two_tabs_is_stored_and_a_reload_opens_where_they_were():
    """One student's link in two tabs (two phones): a reversed try in one, the right one in
    the other — both stored, in order; the second tab shows its own verdict; a reload opens
    at the first step not yet done, its progress from the store."""
    code, key = store.create("zbirka-3.1", "plans")
    token = store.join(code, "Ana")
    steps = steps_for(load_preset("zbirka-3.1"), "plans")
    first = steps[0]
    phone1, phone2 = _seated(code, token), _seated(code, token)
    assert not phone1.exception and _prompt(phone1).startswith(f"Step 1 of {len(steps)}")
    _check(phone1, first, -complex(first.expected))  # reversed: a warning, stored
    assert any(t("practice.hint_sense", "en") in w.value for w in phone1.warning)
    _check(phone2, first, first.expected)  # right, stored as the second try
    assert any(t("practice.hint_ok", "en") in s.value for s in phone2.success)
    rows = store.export(code, key)
    assert [(r["step"], r["diagnosis"], r["try"]) for r in rows] == [
        (first.id, "sense", 1), (first.id, "ok", 2)]
    again = _seated(code, token)  # a reload, another process: the store says where they are
    assert _prompt(again).startswith(f"Step 2 of {len(steps)}")
    next(b for b in again.button if b.label == t("practice.previous", "en")).click().run()
    assert any(t("practice.hint_ok", "en") in s.value for s in again.success)


def test_a_seat_read_on_another_page_first_still_opens_where_the_store_says():
    """A seated student's link opened on another page first (the seat read there, once a
    session), a right answer from another phone, then the method's page: it opens past
    that step — its progress read from the store when its practice starts, not kept from
    the seat's lookup."""
    code, key = store.create("zbirka-3.1", "plans")
    token = store.join(code, "Ana")
    steps = steps_for(load_preset("zbirka-3.1"), "plans")
    at = page("pages/trajectories.py", lang="en", scene="zbirka-3.1")
    at.query_params.update({"class": code, "student": token})
    at.run()
    assert not at.exception and at.session_state["_class_seat"][2] == "pr_plans"
    _check(_seated(code, token), steps[0], steps[0].expected)  # the other phone
    at.switch_page("pages/velocity_plans.py")
    at.query_params.update({"class": code, "student": token})
    at.run()
    assert not at.exception
    assert _prompt(at).startswith(f"Step 2 of {len(steps)}")


def test_a_seated_page_opens_on_one_statement_and_where_the_store_says():
    """A student's link opened (another phone has done step 1): the page asks the store one
    statement — the class, the student and their tries together; a class opening its pages
    at once waits on every round trip of every opening (issue 70) — and opens at step 2."""
    code, key = store.create("zbirka-3.1", "plans")
    token = store.join(code, "Ana")
    steps = steps_for(load_preset("zbirka-3.1"), "plans")
    _check(_seated(code, token), steps[0], steps[0].expected)  # the other phone
    at = page("pages/velocity_plans.py", lang="en", scene="zbirka-3.1")
    at.query_params.update({"class": code, "student": token})
    statements = []

    def asked(_connection, _cursor, statement, *_rest) -> None:
        statements.append(statement)

    sa.event.listen(store.engine(), "before_cursor_execute", asked)
    try:
        at.run()
    finally:
        sa.event.remove(store.engine(), "before_cursor_execute", asked)
    assert not at.exception
    assert _prompt(at).startswith(f"Step 2 of {len(steps)}")
    assert len(statements) == 1, statements


def test_a_check_the_store_cannot_take_shows_no_verdict(monkeypatch):
    """Not even the verdict of the try before, which would read as this one's."""
    code, key = store.create("zbirka-3.1", "plans")
    token = store.join(code)
    first = steps_for(load_preset("zbirka-3.1"), "plans")[0]
    at = _seated(code, token)
    _check(at, first, -complex(first.expected))  # stored: a warning
    assert at.warning

    def down(*_args, **_kwargs):
        raise store.NotSaved("the database is down")

    monkeypatch.setattr(store, "record", down)
    _check(at, first, first.expected)
    assert any(t("class.not_saved", "en") in e.value for e in at.error)
    assert not at.success and not at.warning
    assert len(store.export(code, key)) == 1  # and the try was not counted


def test_a_class_deleted_while_a_student_practises_is_said_and_practice_goes_on():
    code, key = store.create("zbirka-3.1", "plans")
    token = store.join(code)
    first, second = steps_for(load_preset("zbirka-3.1"), "plans")[:2]
    at = _seated(code, token)
    store.delete(code, key)
    _check(at, first, first.expected)
    assert not at.exception
    assert any(f"The class {code} was deleted" in e.value for e in at.error)
    _check(at, first, first.expected)  # unstored now, graded and said as before
    assert any(t("practice.hint_ok", "en") in s.value for s in at.success)
    assert any(t("class.gone_note", "en") in w.value for w in at.warning)


def test_a_link_with_a_student_of_no_class_says_so_once():
    """Beside the practice switch, whether it is on or off (the panel asks again)."""
    code, _ = store.create("zbirka-3.1", "plans")
    for on in (False, True):
        at = page("pages/velocity_plans.py", lang="en", pr_plans_on=on, scene="zbirka-3.1")
        at.query_params.update({"class": code, "student": "not-a-student"})
        at.run()
        said = [e.value for e in at.error if "not in the class" in e.value]
        assert len(said) == 1, on
