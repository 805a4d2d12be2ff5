"""The synthesis page in a real browser (Debian chromium), as a student uses it on a Serbian
page: points typed with a decimal comma into the table, the search run with its progress
bar, the four-bar found drawn, and opened in the builder by its link."""

from __future__ import annotations

import pytest

from .test_browser import keep, open_page, wait_idle, wait_url
from .test_builder_browser import type_cell

pytestmark = pytest.mark.browser

EXCEPTION = "[data-testid='stException']"


def test_points_typed_with_commas_give_a_four_bar_that_opens_in_the_builder(app_url, browser,
                                                                           tmp_path):
    page = open_page(browser, f"{app_url}/synthesis?lang=sr&example=own&timing=free")
    grid = "x [m]"
    type_cell(page, grid, 0, 0, "0,02", redraws=False)  # the first point's x, the Serbian way
    wait_url(page, "points=0.02")  # read as 0.02 and kept in the link (a point, whatever the page)
    page.get_by_role("button", name="Nađi četvorougao").click()
    page.get_by_text("Pretraga: urađeno").first.wait_for(timeout=30_000)  # the progress bar
    page.get_by_text("Nađen za").first.wait_for(timeout=60_000)
    wait_idle(page)
    text = page.locator("[data-testid='stMain']").inner_text()
    assert "Zbir kvadrata grešaka" in text and "M je " in text  # the errors and the links, in words
    curves = page.evaluate("() => [...document.querySelectorAll('.js-plotly-plot')]"
                           ".map(p => (p.data || []).map(t => t.name))")
    assert any(n and "M" in n for names in curves for n in names)  # M's trail, turning
    shot = tmp_path / "synthesis-found-sr.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)
    page.get_by_text("Otvori u graditelju").click()
    page.wait_for_function("() => location.pathname.endsWith('/builder')", timeout=30_000)
    page.wait_for_selector(".mehanizmi-plot .shapelayer path", timeout=30_000)
    wait_idle(page)
    assert page.locator(EXCEPTION).count() == 0
    assert "s=" not in page.url  # the tables hold the scene now, not the link
    shot = tmp_path / "synthesis-in-the-builder-sr.png"
    page.screenshot(path=str(shot))
    keep(shot)
