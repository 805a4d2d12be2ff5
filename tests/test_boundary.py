"""No traceback on any page (issue 60): an exception no page expected is said in one
sentence in the page's language and logged whole on the server (ui/boundary.py); a class
deleted under a lecturer's view, a store that is down when a student's link is opened —
each said in words. (A restart with a code in the sidebar: tests/test_faults_browser.py;
AppTest runs a page without app.py's navigation.)"""

from __future__ import annotations

import logging

import pytest
import sqlalchemy as sa

from classes import store
from ui.i18n import t

from .test_pages import page


@pytest.fixture(autouse=True)
def database(tmp_path, monkeypatch):
    monkeypatch.setenv("MEHANIZMI_DATABASE_URL", f"sqlite:///{tmp_path / 'class.db'}")


def _broken(*_args, **_kwargs):
    raise RuntimeError("/srv/secret/path: an invariant broke")


@pytest.mark.parametrize("lang", ["sr", "en", "sr-cyrl"])
@pytest.mark.parametrize("where", ["ui.present.projector_switch", "ui.fragments.at_position"])
def test_an_unexpected_exception_is_one_sentence_and_a_logged_traceback(lang, where, monkeypatch,
                                                                        caplog):
    """In app.py's run (every page's) and in a page's fragment (the plans page's φ₂ part)."""
    monkeypatch.delenv("MEHANIZMI_ERRORS")  # as users get it
    path = "app.py" if where.startswith("ui.present") else "pages/velocity_plans.py"
    at = page(path, lang=lang)
    monkeypatch.setattr(where, _broken)
    with caplog.at_level(logging.ERROR, logger="mehanizmi"):
        at.run()
    assert not at.exception
    said = [e.value for e in at.error]
    assert said == [t("app.unexpected", lang)] and "/srv/secret" not in said[0]
    assert any("/srv/secret/path" in r.exc_text for r in caplog.records if r.exc_text)


def test_a_class_deleted_under_the_lecturer_s_view_is_said_on_its_next_run():
    """(The open view's live part says it at its next tick and keeps its counts: the
    browser's fault crawl, tests/test_faults_browser.py.)"""
    code, key = store.create("zbirka-3.1", "plans")
    token = store.join(code)
    store.record(code, token, "v.b", [0.0, 1.0], "wrong", store.new_check())
    view = page("pages/class.py", lang="en", query=None)
    view.query_params.update({"class": code, "key": key})
    view.run()
    assert [m.value for m in view.metric][:2] == ["1", "1"]
    store.delete(code, key)
    view.run()
    assert not view.exception
    assert any(f"The class {code} was deleted" in e.value for e in view.error)


def test_a_student_link_opened_while_the_store_is_down_comes_back_to_practice(monkeypatch):
    code, _ = store.create("zbirka-3.1", "plans")
    token = store.join(code)

    def down(*_args, **_kwargs):  # the database's own error, whichever read asks it
        raise sa.exc.OperationalError("SELECT 1", {}, ConnectionRefusedError("connection refused"))

    at = page("pages/velocity_plans.py", lang="en", scene="zbirka-3.1")
    at.query_params.update({"class": code, "student": token})
    with monkeypatch.context() as patched:
        patched.setattr(store, "engine", down)
        at.run()
        assert not at.exception
        assert any(t("class.store_down", "en") in w.value for w in at.warning)
        # only the waiting notice: no switch to start practice unstored, no plans
        assert not [w for w in at.toggle if w.key == "pr_plans_on"] and not at.get("plotly_chart")
    at.run()  # the store answers again (the waiting part reran the page): the class's practice
    assert any(m.value.startswith("Step 1 of ") for m in at.markdown)
    assert not any(t("class.store_down", "en") in w.value for w in at.warning)
