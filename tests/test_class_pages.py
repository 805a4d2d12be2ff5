"""A class fixes what it practises and hides its answers (issue 66), on every page that
practises, for every method: a seated student's link with another instant, speed, scene and
step opens on the class's practice alone — graded and stored at the class's instant, the
link's values named as not used — and nothing on the page says a step's exact value until
that step is done. The lecturer's view and a student practising alone are as before."""

from __future__ import annotations

import cmath
import json
import math

import pytest

from classes import store
from classes.methods import METHODS
from classes.steps import steps_of
from ui.i18n import num, t
from ui.practice import shown_unit

from .test_pages import page, typed

TASKS = {"compass": "zbirka-1.1", "plans": "zbirka-3.1", "forces": "zbirka-5.1",
         "lever": "zbirka-5.1", "willis": "zbirka-6.4", "balance": "zbirka-7.1"}
HOSTILE = {"at": "100", "omega": "7", "scene": "zbirka-2.1", "step": "2", "tab": "1"}


@pytest.fixture(autouse=True)
def database(tmp_path, monkeypatch):
    monkeypatch.setenv("MEHANIZMI_DATABASE_URL", f"sqlite:///{tmp_path / 'class.db'}")


def seated(method: str, **link):
    code, key = store.create(TASKS[method], method)
    token = store.join(code, "Ana")
    at = page(f"pages/{METHODS[method].page}.py", lang="en")
    at.query_params.update({"class": code, "student": token, **link})
    at.run()
    assert not at.exception, at.exception
    return at, code, key, steps_of(store.find(code))


def said(at) -> str:
    """Everything the page writes in words and numbers, and every text its charts carry."""
    out = [e.value for kind in ("markdown", "caption", "info", "success", "warning", "error",
                                "latex", "text", "title", "header", "subheader") for e in getattr(at, kind)]
    out += [str(m.value) for m in at.metric]
    out += [d.value.to_string() for d in at.dataframe] + [d.value.to_string() for d in at.table]
    for element in at.get("bidi_component"):
        out += _strings(json.loads(element.proto.bytes or "{}"))
    return "\n".join(out)


def _strings(value) -> list[str]:
    if isinstance(value, str):
        return [value]
    if isinstance(value, dict):
        return [s for v in value.values() for s in _strings(v)]
    if isinstance(value, list):
        return [s for v in value for s in _strings(v)]
    return []


def written(step) -> set[str]:
    """How a step's exact value would be written (magnitude, to 4 and 5 digits; a direction
    to 4), those long enough not to be any number by chance."""
    z = complex(step.expected)
    values = [abs(z)] if step.kind == "vector" else [z.real] if step.kind == "scalar" else [z.real, z.imag]
    if step.kind == "vector" and abs(z):
        values.append(math.degrees(cmath.phase(z)) % 360)
    out = {num(abs(v), d, "en") for v in values for d in (4, 5)}
    return {w for w in out if sum(c.isdigit() for c in w) >= 4}


@pytest.mark.parametrize("method", list(TASKS))
def test_a_seated_student_sees_the_class_practice_alone_and_no_answer(method):
    at, code, key, steps = seated(method, **HOSTILE)
    text = said(at)
    assert any(m.value.startswith(f"Step 1 of {len(steps)}") for m in at.markdown)
    assert t("class.fixed", "en", names="")[:30] in text and "at" in text  # the link's values named
    assert not at.tabs and not [w for w in at.text_input if w.key and w.key.startswith("self")]
    assert not at.dataframe and not at.table  # no readings, members or book tables
    for step in steps:  # no exact value of any step on the page before it is done
        shown = [w for w in written(step) if w in text]
        assert not shown, (method, step.id, shown)
    assert t("practice.exact", "en") not in text
    # the link now says the class's own values: a reload practises the class; the note stays
    assert at.query_params.get("at") != ["100"] and at.query_params.get("scene") != ["zbirka-2.1"]
    at.run()
    assert t("class.fixed", "en", names="")[:30] in said(at)


@pytest.mark.parametrize("method", ["plans", "forces", "balance"])
def test_a_check_from_a_link_at_another_instant_is_graded_at_the_class_s(method):
    """The class's exact answer, typed on a page whose link said another instant, is right
    and stored as right; the step's exact value shows once it is done."""
    at, code, key, steps = seated(method, at="100")
    first = steps[0]
    key_ = {"compass": "pr_compass", "plans": "pr_plans", "forces": "pr_forces",
            "balance": "pr_balance"}[method]
    z = complex(first.expected)
    if first.kind == "vector":
        typed(at, f"{key_}_len_{first.id}", abs(z) * shown_unit(first)[1])
        typed(at, f"{key_}_ang_{first.id}", math.degrees(cmath.phase(z)))
    elif first.kind == "point":
        typed(at, f"{key_}_x_{first.id}", z.real)
        typed(at, f"{key_}_y_{first.id}", z.imag)
    else:
        typed(at, f"{key_}_value_{first.id}", z.real)
    next(b for b in at.button if b.label == t("practice.check", "en")).click().run()
    right = t("practice.hint_ok_computed" if first.computed else "practice.hint_ok", "en")
    assert any(right in s.value for s in at.success)
    assert [r["diagnosis"] for r in store.export(code, key)] == ["ok"]
    assert t("practice.exact", "en") in said(at)


def test_a_test_class_gives_one_try_no_show_it_and_verdicts_once_closed():
    code, key = store.create("zbirka-3.1", "plans", test=True)
    token = store.join(code)
    at = page("pages/velocity_plans.py", lang="en")
    at.query_params.update({"class": code, "student": token})
    at.run()
    assert not [b for b in at.button if b.label == t("practice.reveal", "en")]
    first = steps_of(store.find(code))[0]
    typed(at, f"pr_plans_len_{first.id}", abs(complex(first.expected)))
    typed(at, f"pr_plans_ang_{first.id}", 0.0 if abs(cmath.phase(complex(first.expected))) > 0.5 else 180.0)
    next(b for b in at.button if b.label == t("practice.check", "en")).click().run()
    assert any(t("practice.test_stored", "en") in i.value for i in at.info)
    assert not at.success and not at.warning  # no verdict, no hint
    assert t("practice.exact", "en") not in said(at)
    next(b for b in at.button if b.label == t("practice.check", "en")).click().run()  # a second try
    assert any("has one try" in i.value for i in at.info) and len(store.export(code, key)) == 1
    store.close(code, key)
    at.run()  # closed: the outcome and the exact value, now
    text = said(at)
    assert t("practice.exact", "en") in text and at.warning  # the one try's verdict and hint
