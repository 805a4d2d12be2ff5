"""The lecturer's class view (AppTest), in Serbian (both scripts) and English, on a class planted in the
store: hidden at first (only who reached each step), then revealed — the bars by diagnosis,
the most common mistake in words, the cloud of the latest answers with the right one at a
click, the students' table on demand — and the printable summary with decimal commas."""

from __future__ import annotations

import pytest

from classes import store
from mechanisms import load_preset
from methods.practice_steps import steps_for
from ui import classview
from ui.i18n import counted, t

from .test_pages import chart, page


@pytest.fixture(autouse=True)
def database(tmp_path, monkeypatch):
    monkeypatch.setenv("MEHANIZMI_DATABASE_URL", f"sqlite:///{tmp_path / 'class.db'}")


STEPS = steps_for(load_preset("zbirka-3.1"), "plans")


def planted() -> tuple[str, str]:
    """Three students on task 3.1's first step: one right, two reversed (one then right)."""
    code, key = store.create("zbirka-3.1", "plans")
    first = STEPS[0]
    z = complex(first.expected)
    for name, tries in (("ana", [("ok", z)]), ("ben", [("sense", -z), ("ok", z)]),
                        ("<b>cira</b>", [("sense", -z * 1.01)])):
        token = store.join(code, name)
        for n, (diagnosis, answer) in enumerate(tries, 1):
            store.record(code, token, first.id, [answer.real, answer.imag], diagnosis, store.new_check())
    return code, key


def names(figure: dict) -> list[str]:
    return [str(tr.get("name", "")) for tr in figure["data"]]


@pytest.mark.parametrize("lang", ["sr", "en", "sr-cyrl"])
def test_the_view_is_hidden_until_revealed_then_counts_and_draws_the_class(lang, monkeypatch):
    monkeypatch.setattr("ui.i18n.current", lambda: lang)  # (AppTest formats choices outside a run)
    code, key = planted()
    at = page("pages/class.py", lang=lang, query=None)
    at.query_params.update({"class": code, "key": key})
    at.run()
    assert not at.exception
    bars = chart(at, "cv_bars")
    assert names(bars) == [t("class.hidden", lang)] and bars["data"][0]["x"][0] == 3
    assert "cv_cloud" not in {e.proto.id.rsplit("-", 1)[-1] for e in at.get("bidi_component")}
    assert not any("3" in m.value and t("class.mistake_sense", lang, who=counted("class.n_students", 2, lang)) in m.value for m in at.markdown)
    assert not at.dataframe  # names hidden by default

    at.toggle(key="cv_all").set_value(True).run()
    bars = chart(at, "cv_bars")
    assert names(bars) == [t("class.diagnosis_ok", lang), t("class.diagnosis_sense", lang)]
    assert [tr["x"][0] for tr in bars["data"]] == [1, 2]  # first tries: one right, two reversed
    said = " ".join(m.value for m in at.markdown)
    assert t("class.mistake_sense", lang, who=counted("class.n_students", 2, lang)) in said
    cloud = chart(at, "cv_cloud")
    tips = [tr for tr in cloud["data"] if tr.get("mode") == "markers" and tr.get("name")]
    assert sum(int(tr["name"].rsplit("(", 1)[1].rstrip(")")) for tr in tips) == 3  # three latest answers
    assert t("class.right", lang) not in names(cloud)
    at.toggle(key="cv_right").set_value(True).run()
    assert t("class.right", lang) in names(chart(at, "cv_cloud"))

    at.toggle(key="cv_names").set_value(True).run()
    table = at.dataframe[0].value
    assert list(table[t("class.table_nickname", lang)]) == ["ana", "ben", "<b>cira</b>"]
    assert list(table[t("class.table_first", lang)]) == [1, 0, 0]


def test_a_new_check_shows_at_the_next_tick_without_losing_what_was_revealed():
    code, key = planted()
    at = page("pages/class.py", lang="en", query=None)
    at.query_params.update({"class": code, "key": key})
    at.run()
    at.toggle(key="cv_all").set_value(True).run()
    token = store.join(code, "dan")
    store.record(code, token, STEPS[0].id, [0.0, 0.0], "wrong", store.new_check())
    at.run()  # (the fragment's timer, as AppTest can run it: the whole script)
    bars = chart(at, "cv_bars")
    assert dict(zip(names(bars), (tr["x"][0] for tr in bars["data"]))) == {
        t("class.diagnosis_ok", "en"): 1, t("class.diagnosis_sense", "en"): 2,
        t("class.diagnosis_wrong", "en"): 1}
    assert at.toggle(key="cv_all").value


def test_the_printable_summary_writes_the_language_s_numbers(monkeypatch):
    code, key = planted()
    found = store.opened(code, key)
    rows = store.export(code, key)
    monkeypatch.setattr("ui.i18n.current", lambda: "sr")
    serbian = classview.printable(found, STEPS, rows)
    assert "33,3 %" in serbian and "@page { size: A4" in serbian
    assert t("class.mistake_sense", "sr", who="2 studenta") in serbian
    assert "cira" not in serbian  # a summary for the room: no nicknames
    monkeypatch.setattr("ui.i18n.current", lambda: "en")
    assert "33.3 %" in classview.printable(found, STEPS, rows)


def test_a_class_of_variants_is_drawn_relative_and_split_by_a_given(monkeypatch):
    """Three students with variants 1–3 of task 3.1 (seed 42): each right answer lands on the
    task's right answer in the cloud, and the counts split in bands of the chosen given."""
    from exams.codes import Settings, code
    from exams.variants import from_code

    settings = Settings("zbirka-3.1", 42)
    class_code, key = store.create("zbirka-3.1", "plans", variants=code(settings, 1))
    for n in range(3):
        token = store.join(class_code, f"v{n}")
        own = steps_for(from_code(code(settings, n + 1)).scene, "plans")[0]
        z = complex(own.expected)  # this student's own right answer
        store.record(class_code, token, own.id, [z.real, z.imag], "ok" if n else "sense",
                     store.new_check())
    assert [r["variant"] for r in store.export(class_code, key)] == [code(settings, n) for n in (1, 2, 3)]

    at = page("pages/class.py", lang="en", query=None, cv_all=True, cv_right=True)
    at.query_params.update({"class": class_code, "key": key})
    at.run()
    assert not at.exception
    cloud = chart(at, "cv_cloud")
    right = [tr for tr in cloud["data"] if tr.get("name") == t("class.right", "en")][0]
    ok = [tr for tr in cloud["data"] if tr.get("name") == f"{t('class.diagnosis_ok', 'en')} (2)"][0]
    assert all(abs(x - right["x"][0]) < 1e-9 for x in ok["x"])  # each variant's right answer, on the task's
    label = next(o for o in at.selectbox(key="cv_split").options if o != t("class.split_none", "en"))
    at.selectbox(key="cv_split").set_value(label).run()
    assert not at.exception
    bands = at.dataframe[0].value
    assert bands.shape[1] >= 1 and sum(int(c.rsplit("(", 1)[1].rstrip(")")) for c in bands.columns) == 3


def test_a_number_step_shows_the_class_s_values_around_the_exact_one():
    """A scalar step (ω₃): the values in bins stacked by diagnosis, every value counted once,
    the exact one a line only when shown."""
    from figures.classview import spread

    step = next(s for s in STEPS if s.kind == "scalar")
    exact = float(complex(step.expected).real)
    given = [(exact, "ok"), (exact, "ok"), (-exact, "sense"), (1.5 * exact, "length")]
    shown = spread(step, given, True, "ω", lambda key, **_: key).to_dict()
    heights = {tr["name"]: sum(tr["y"]) for tr in shown["data"]}
    assert heights == {"class.diagnosis_ok (2)": 2, "class.diagnosis_sense (1)": 1,
                       "class.diagnosis_length (1)": 1}
    assert [sh["x0"] for sh in shown["layout"]["shapes"]] == [exact]
    assert not spread(step, given, False, "ω", lambda key, **_: key).to_dict()["layout"].get("shapes")


@pytest.mark.parametrize("n, english, serbian", [
    (1, "1 student", "1 student"), (2, "2 students", "2 studenta"), (5, "5 students", "5 studenata"),
    (11, "11 students", "11 studenata"), (12, "12 students", "12 studenata"),
    (21, "21 students", "21 student"), (24, "24 students", "24 studenta")])
def test_a_count_of_students_is_said_in_each_language_s_plural(n, english, serbian):
    assert counted("class.n_students", n, "en") == english
    assert counted("class.n_students", n, "sr") == serbian
    assert t("class.mistake_tie", "en", who=counted("class.n_students", 1, "en"), made="x") \
        == "Most common mistakes, made equally often (by 1 student each): x."


def test_the_printable_summary_says_nothing_odd_for_a_step_nobody_reached():
    code, key = planted()
    said = classview.printable(store.opened(code, key), STEPS, [])  # (no checks: none reached)
    assert "<td>0</td>" in said and "()" not in said
