"""A test's life in chromium, on phones, in Serbian and English (issue 82): a student joins by
typing the code in the sidebar (which then gets out of the way), answers a step; the same
student's second, stale phone tries that step — refused with the step named as the page
shows it, a lock, no hint promised; the lecturer closes the test; the open page says so
within seconds, a late check is refused in words and not stored, the stale phone shows the
step's one verdict with its hint, and a student who opens the join link after the closing
gets no seat. And a class form with a refused instant starts nothing."""

from __future__ import annotations

import math

import pytest

from classes import store
from classes.steps import steps_of
from ui.i18n import t

from .test_browser import keep, wait_idle

pytestmark = pytest.mark.browser


def _answer(page, step, language: str) -> None:
    """Type a plan step's arrow (its size and angle) and press Check."""
    z = complex(step.expected)
    boxes = page.locator("[data-testid='stForm'] input")
    sign = "," if language == "sr" else "."
    boxes.nth(0).fill(f"{abs(z):.6g}".replace(".", sign))
    boxes.nth(1).fill(f"{math.degrees(math.atan2(z.imag, z.real)):.6g}".replace(".", sign))
    page.get_by_role("button", name=t("practice.check", language)).click()


@pytest.mark.parametrize("language", ["sr", "en"])
def test_a_closed_test_takes_no_answer_and_no_late_student(app_url, chromium, tmp_path, language):
    browser, phone = chromium
    code, key = store.create("zbirka-3.1", "plans", test=True)
    steps = steps_of(store.find(code))
    locale = "sr-RS" if language == "sr" else "en-US"
    context = browser.new_context(**phone, locale=locale)
    page = context.new_page()
    page.goto(f"{app_url}/?lang={language}")
    wait_idle(page)
    page.locator("[data-testid='stExpandSidebarButton'], "
                 "[data-testid='stSidebarCollapsedControl'] button").first.tap()
    box = page.get_by_label(t("class.sidebar_code", language))
    box.fill(code.lower())
    box.press("Enter")
    join = page.get_by_role("button", name=t("class.join", language))
    join.wait_for(timeout=30_000)
    join.click(trial=True, timeout=10_000)  # tappable: the sidebar is not lying over it
    join.tap()
    page.locator("[data-testid='stForm'] input").first.wait_for(timeout=30_000)
    stale = browser.new_context(**phone, locale=locale).new_page()  # the student's other phone
    stale.goto(page.url)
    stale.locator("[data-testid='stForm'] input").first.wait_for(timeout=30_000)
    wait_idle(stale)
    hint_promised = t("practice.rule_hidden", language).split("? ")[1]
    assert stale.get_by_text(hint_promised).count() == 0  # "no hints", not contradicted
    _answer(page, steps[0], language)
    page.get_by_text(t("practice.test_stored", language)[:20]).first.wait_for(timeout=30_000)
    wait_idle(page)
    _answer(stale, steps[0], language)  # the step is taken: refused, named as shown
    tried = t("class.one_try", language, step="v_BA")
    stale.get_by_text(tried).first.wait_for(timeout=30_000)
    assert stale.locator("[data-testid='stAlertContentError']").count() == 0  # a lock, no cloud

    store.close(code, key)  # the lecturer's Close the test (tests/test_classview_browser.py)
    closed = t("class.test_closed_seen", language, at="")[:18]
    page.get_by_text(closed).first.wait_for(timeout=15_000)  # learnt within seconds
    page.get_by_role("button", name=t("practice.next", language)).click()
    page.get_by_text(t("practice.step", language, n=2, of=len(steps), part="")[:12]).first.wait_for(
        timeout=30_000)
    wait_idle(page)
    _answer(page, steps[1], language)
    late = t("class.test_closed_try", language, at="00:00").split(". ")[-1].rstrip(".")
    page.get_by_text(late).first.wait_for(timeout=30_000)  # "This answer was not stored"
    assert [r["step"] for r in store.export(code, key)] == [steps[0].id]  # nothing late stored
    shot = tmp_path / f"test-closed-phone-{language}.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)

    stale.reload()  # after the closing: the step's one try, its verdict and its hint
    stale.get_by_text(t("practice.step", language, n=2, of=len(steps), part="")[:12]).first.wait_for(
        timeout=30_000)  # (it opens at the first step not done)
    wait_idle(stale)
    stale.get_by_role("button", name=t("practice.previous", language)).click()
    stale.locator("[data-testid='stAlertContentSuccess']").first.wait_for(timeout=30_000)
    assert stale.get_by_text(t("practice.settled_here", language, outcome="")[:20]).count() == 0
    stale.context.close()

    newcomer = browser.new_context(**phone, locale=locale).new_page()
    newcomer.goto(f"{app_url}/class?join={code}&lang={language}")
    newcomer.get_by_text(t("class.test_closed_join", language, at="")[:18]).first.wait_for(
        timeout=30_000)
    assert newcomer.get_by_role("button", name=t("class.join", language)).count() == 0
    assert len(store.export(code, key)) == 1
    assert newcomer.locator("[data-testid='stException']").count() == 0
    assert page.locator("[data-testid='stException']").count() == 0
    newcomer.context.close()
    context.close()


@pytest.mark.parametrize("language", ["sr", "en"])
def test_a_refused_instant_keeps_the_class_from_starting(app_url, chromium, language):
    """Issue 82, point 2: "30,5" on the English class page was refused at its field, and
    *Start the class* then made a class at the task's own instant without a word."""
    context = chromium[0].new_context(locale="en-US", viewport={"width": 1400, "height": 900})
    page = context.new_page()
    page.goto(f"{app_url}/class?lang={language}")
    box = page.get_by_label(t("class.at", language))
    box.fill("30,5" if language == "en" else "30;5")
    box.press("Enter")
    label = t("class.start", language)
    state = "t => [...document.querySelectorAll('button')].some(b => b.innerText.includes(t[0]) && b.disabled === t[1])"
    page.wait_for_function(state, arg=[label, True], timeout=30_000)  # refused: it starts nothing
    page.get_by_role("button", name=label).hover(force=True)
    page.get_by_text(t("num.fix_first", language, fields="")[:20]).first.wait_for(timeout=10_000)
    box.fill("30.5" if language == "en" else "30,5")
    box.press("Enter")
    page.wait_for_function(state, arg=[label, False], timeout=30_000)
    context.close()

