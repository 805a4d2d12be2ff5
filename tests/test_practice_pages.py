"""Practice mode on every page that has a construction, in Serbian and English (AppTest): the
switch hides the answer, a typed right answer is ok, a reversed one is named, three wrong
tries reveal the step, and at the end the score and the CSV of answers."""

from __future__ import annotations

import cmath
import math

import pytest

from cli.practice import steps_for
from mechanisms import load_preset
from ui.i18n import t
from ui.practice import shown_unit

from .test_pages import charts, page, typed

PAGES = [  # page, state, practice key, method, scene
    ("pages/trajectories.py", {"view": "compass", "scene": "zbirka-1.1"}, "pr_compass", "compass"),
    ("pages/velocity_plans.py", {"scene": "zbirka-3.1"}, "pr_plans", "plans"),
    ("pages/kinetostatics.py", {"scene": "zbirka-5.1", "tab": "steps"}, "pr_forces", "forces"),
    ("pages/kinetostatics.py", {"scene": "zbirka-5.1", "tab": "lever"}, "pr_lever", "lever"),
    ("pages/planetary_gears.py", {"scene": "zbirka-6.4"}, "pr_willis", "willis"),
    ("pages/rotor_balancing.py", {"scene": "zbirka-7.1"}, "pr_balance", "balance"),
]
TABS = {"steps": "forces.tab_steps", "lever": "forces.tab_lever"}


def _open(path: str, state: dict, key: str, lang: str):
    state = dict(state)
    if "tab" in state:
        state["tab"] = t(TABS[state["tab"]], lang)
    at = page(path, lang=lang, **state)
    assert not at.exception, at.exception
    at.toggle(key=f"{key}_on").set_value(True).run()
    assert not at.exception, at.exception
    return at


def _type(at, key: str, step, answer) -> None:
    """Type an answer into the step's form, as a person of the page's language writes
    numbers (0,35 in Serbian), and press Check."""
    lang = at.session_state["lang"]
    factor = shown_unit(step)[1]  # the rotor's U in kg·mm, as its page writes it
    if step.kind == "vector":
        z = complex(answer)
        typed(at, f"{key}_len_{step.id}", abs(z) * factor, lang)
        typed(at, f"{key}_ang_{step.id}", math.degrees(cmath.phase(z)), lang)
    elif step.kind == "point":
        typed(at, f"{key}_x_{step.id}", complex(answer).real, lang)
        typed(at, f"{key}_y_{step.id}", complex(answer).imag, lang)
    else:
        typed(at, f"{key}_value_{step.id}", float(answer) * factor, lang)
    next(b for b in at.button if b.label == t("practice.check", lang)).click().run()


def _scene(state: dict):
    return load_preset(state["scene"])


@pytest.mark.parametrize("lang", ["sr", "en"])
@pytest.mark.parametrize("path, state, key, method", PAGES, ids=[p[3] for p in PAGES])
def test_practice_grades_typed_answers_on_every_page(path, state, key, method, lang, monkeypatch):
    # AppTest formats a radio's value (the trajectories page's view) with the page's own
    # format_func outside the script run, where no session says the language
    monkeypatch.setattr("ui.i18n.current", lambda: lang)
    at = _open(path, state, key, lang)
    steps = steps_for(_scene(state), method)
    first = steps[0]
    assert t("practice.step", lang, n=1, of=len(steps), part="").split("—")[0].strip() in \
        " ".join(m.value for m in at.markdown)
    _type(at, key, first, first.expected)
    right = t("practice.hint_ok_computed" if first.computed else "practice.hint_ok", lang)
    assert [s.value for s in at.success] and right in at.success[0].value
    later = next(i for i, s in enumerate(steps) if i and abs(s.expected) > 20 * s.tolerance)
    for _ in range(later):
        next(b for b in at.button if b.key == f"{key}_next").click().run()
    second = steps[later]
    wrong = -second.expected if second.kind != "point" else complex(second.expected) * 1.5
    _type(at, key, second, wrong)
    warning = at.warning[0].value
    diagnosis = {"point": "practice.hint_wrong", "scalar": "practice.value_sense"}.get(
        second.kind, "practice.hint_sense")  # a value is told of its sign, not of an arrow
    assert t(diagnosis, lang).split(" ")[0] in warning
    for _ in range(2):
        _type(at, key, second, wrong)
    assert t("practice.shown", lang, tries=3, limit=3) in " ".join(i.value for i in at.info)


def test_practice_hides_the_plans_and_draws_the_sheet_to_drag_on():
    at = _open("pages/velocity_plans.py", {"scene": "zbirka-3.1"}, "pr_plans", "en")
    drawn = charts(at)
    assert set(drawn) == {"pr_plans_fig"}  # the exact plans are not on the page
    sheet = drawn["pr_plans_fig"]
    assert sheet["handle"] == "tip" and sheet["editable"] is False  # moved by its handle
    assert sheet["figure"]["layout"]["dragmode"] is False  # a swipe scrolls the page
    assert sheet["focus"].startswith(".st-key-pr_plans_prompt|")
    assert [s["name"] for s in sheet["figure"]["layout"]["shapes"]] == ["tip"]


def test_the_score_and_the_csv_come_when_every_step_is_done():
    at = _open("pages/planetary_gears.py", {"scene": "zbirka-6.4"}, "pr_willis", "en")
    steps = steps_for(load_preset("zbirka-6.4"), "willis")
    for i, step in enumerate(steps):
        if i == 1:
            next(b for b in at.button if b.key == "pr_willis_reveal").click().run()
        else:
            _type(at, "pr_willis", step, step.expected)
        if i < len(steps) - 1:
            next(b for b in at.button if b.key == "pr_willis_next").click().run()
    assert t("practice.score", "en") in [h.value for h in at.header]
    values = {m.label: m.value for m in at.metric}
    n = len(steps)
    assert values[t("practice.first", "en")] == f"{n - 1} / {n}"
    assert values[t("practice.revealed", "en")] == f"1 / {n}"


@pytest.mark.parametrize("tab", ["steps", "lever"])
def test_practising_kinetostatics_hides_the_driving_torque_it_ends_with(tab):
    state = {"scene": "zbirka-5.1", "tab": t(TABS[tab], "en")}
    shown = page("pages/kinetostatics.py", lang="en", **state)
    assert any(m.label.startswith("M_p") for m in shown.metric)  # the page shows it …
    at = _open("pages/kinetostatics.py", {"scene": "zbirka-5.1", "tab": tab},
               f"pr_{'forces' if tab == 'steps' else 'lever'}", "en")
    assert not any(m.label.startswith("M_p") for m in at.metric)  # … the practice does not


def test_a_scale_change_keeps_every_answer_and_another_instant_starts_over():
    """Answers are kept in SI: a coarser U_v keeps the verdict (and the step); moving φ₂
    gives other exact values, so practice starts again, and says so."""
    at = _open("pages/velocity_plans.py", {"scene": "zbirka-3.1"}, "pr_plans", "en")
    steps = steps_for(load_preset("zbirka-3.1"), "plans")
    _type(at, "pr_plans", steps[0], steps[0].expected)
    assert at.success
    next(b for b in at.button if b.key == "pr_plans_next").click().run()
    typed(at, "Uv", 1.0).run()
    assert not at.exception
    assert t("practice.step", "en", n=2, of=len(steps), part=t("practice.part_vector", "en")) in \
        " ".join(m.value for m in at.markdown)
    next(b for b in at.button if b.key == "pr_plans_prev").click().run()
    assert at.success and not [i for i in at.info if i.value == t("practice.restarted", "en")]
    at.slider(key="at").set_value(100.0).run()
    assert any(i.value == t("practice.restarted", "en") for i in at.info)
    assert not at.success


def test_the_rotors_practice_speaks_the_pages_units():
    """U in kg·mm and V in kg·mm², as the rotor page draws its polygons, with the sheet's scale."""
    at = _open("pages/rotor_balancing.py", {"scene": "zbirka-7.1"}, "pr_balance", "en")
    text = " ".join([*(m.value for m in at.markdown), *(c.value for c in at.caption)])
    assert "[kg·mm²]" in text and "1 cm =" in text and "kg·mm²." in text
    assert "kg·m²]" not in text.replace("kg·mm²]", "")


def test_a_step_whose_exact_part_is_zero_says_so():
    """Task 3.1's a.n1-b (a tangential part that is zero at this instant) is asked with a
    note and typed — a length of 0, no direction — not as an arrow whose tip cannot stay on
    its tail; a step with a length has no such note, and its sheet."""
    at = _open("pages/velocity_plans.py", {"scene": "zbirka-3.1"}, "pr_plans", "en")
    steps = steps_for(load_preset("zbirka-3.1"), "plans")
    zero = next(i for i, s in enumerate(steps) if abs(complex(s.expected)) <= s.tolerance)
    assert not [i for i in at.info if i.value == t("practice.zero_step", "en")]
    assert charts(at).get("pr_plans_fig")  # a step with a length: its sheet
    for _ in range(zero):
        next(b for b in at.button if b.key == "pr_plans_next").click().run()
    assert steps[zero].id == "a.n1-b"
    assert [i for i in at.info if i.value == t("practice.zero_step", "en")]
    assert not charts(at).get("pr_plans_fig")  # no sheet: a tip cannot stay on its tail
    typed(at, f"pr_plans_len_{steps[zero].id}", 0.0, "en")  # a length of 0, no direction
    next(b for b in at.button if b.label == t("practice.check", "en")).click().run()
    assert at.success and not at.error
