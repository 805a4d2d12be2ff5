"""Hostile values in the parameters Streamlit binds to the link itself (sliders: φ₂, ω₂, a
step, a resolution, a length, the hay tedder's travel), which AppTest cannot see: in
chromium every page opens without an exception element, says each refused value in words,
and keeps its own value — Streamlit alone put a slider at its first value (φ₂ = 0 for
``?at=abc``) without a word (issue 61)."""

from __future__ import annotations

import pytest

from .test_browser import open_page, wait_idle

pytestmark = pytest.mark.browser
EXCEPTION = "[data-testid='stException'], .st-key-unexpected"
BOUND = "at=abc&omega=nan&fstep=999&steps=7&upto=0&prec=9&res=5&cycles=x&L2=abc" \
        "&L3=1e400&vR=-1&step=0&precision=-1"
PAGES = ["trajectories", "trajectories?scene=zbirka-1.3", "velocity_plans", "assur_groups",
         "kinetostatics", "rotor_balancing"]


@pytest.mark.parametrize("path", PAGES)
def test_bound_link_values_are_refused_in_words_and_the_page_keeps_its_own(app_url, browser, path):
    joiner = "&" if "?" in path else "?"
    page = open_page(browser, f"{app_url}/{path}{joiner}lang=en&{BOUND}")
    wait_idle(page)
    assert page.locator(EXCEPTION).count() == 0
    said = page.locator("[data-testid='stAlertContentWarning']").all_inner_texts()
    assert any("This link's value was not used" in text for text in said), said
    page.close()


def test_phi2_from_a_refused_link_is_the_task_s_own(app_url, browser):
    from mechanisms import load_preset
    from ui.scenes import driver_start

    own = driver_start(load_preset("zbirka-3.1"))
    assert own != 0.0  # (so the slider's first value would be a change)
    page = open_page(browser, f"{app_url}/velocity_plans?lang=en&scene=zbirka-3.1&at=abc")
    wait_idle(page)
    thumbs = page.locator("[data-testid='stSliderThumbValue']").all_inner_texts()
    assert f"{own:.2f}" in thumbs, (own, thumbs)
    page.close()


THUMBS = "() => [...document.querySelectorAll(\"[data-testid='stSliderThumbValue']\")].map(e => e.textContent)"


def test_a_serbian_page_without_a_chart_writes_its_sliders_with_a_comma_and_english_with_a_point(
        app_url, browser):
    """The sliders' values follow the page's decimal mark where no chart is drawn (task 2.1's
    four-bar cannot be assembled at 140.5°): it was the charts' script that rewrote them,
    so such a page showed "140.50" beside "φ₂ = 140,5°". Turned English, the same sliders
    are written back with a point (they stayed "140,50")."""
    page = browser.new_page()
    page.goto(f"{app_url}/velocity_plans?lang=sr&scene=analitika-2.1&at=140.5&omega=-7.5")
    page.wait_for_selector("[data-testid='stAlertContentError']", timeout=60_000)
    page.wait_for_function(f"() => ({THUMBS})().length >= 2", timeout=30_000)  # (the whole run)
    wait_idle(page)
    assert page.locator(".js-plotly-plot").count() == 0
    assert page.evaluate(THUMBS)[:2] == ["140,50", "-7,50"]
    page.locator("[data-testid='stSidebar'] [data-testid='stSelectbox']").first.click()
    page.get_by_role("option", name="English").click()
    page.wait_for_function(f"() => ({THUMBS})().includes('140.50')", timeout=30_000)
    assert page.evaluate(THUMBS)[:2] == ["140.50", "-7.50"]
