"""The printed sheets in a real browser (Debian chromium): one A4 page per variant, the
mechanism drawn in true centimetres at U_L; and a student's variant link on a live server."""

import re
from urllib.parse import parse_qs, urlparse

import pytest

from exams.codes import Settings
from exams.sheets import sheets_html
from exams.variants import generate

from .test_browser import open_page, wait_url

pytestmark = pytest.mark.browser

PX_PER_CM = 96 / 2.54  # CSS: 96 px per inch


def test_the_sheets_print_one_a4_page_per_variant_drawn_at_the_tasks_scale(app_url, browser, tmp_path):
    found = generate(Settings("zbirka-3.1", 42), 3)
    html = tmp_path / "sheets.html"
    html.write_text(sheets_html(found, "Task 3.1", "en"), encoding="utf-8")
    page = browser.new_page()
    page.goto(html.as_uri())
    page.screenshot(path=str(tmp_path / "sheets.png"), full_page=True)
    boxes = page.eval_on_selector_all("section.sheet svg", "els => els.map(e => e.getBoundingClientRect().width)")
    assert len(boxes) == 3
    for variant, width in zip(found.variants, boxes):
        xs = [z.real for z in variant.drawn.values()]
        ys = [z.imag for z in variant.drawn.values()]
        extent = max(max(xs) - min(xs), max(ys) - min(ys))
        span = (max(xs) - min(xs) + 2 * 0.08 * extent) / variant.scene.scales["L"]  # cm at U_L
        assert abs(width - span * PX_PER_CM) < 1.0
    page.emulate_media(media="print")
    page.set_viewport_size({"width": round(180 / 25.4 * 96), "height": 1100})  # A4 less margins
    heights = page.eval_on_selector_all("section.sheet", "els => els.map(e => e.offsetHeight)")
    assert max(heights) < 267 / 25.4 * 96  # every student's sheet fits one A4 page
    pdf = page.pdf(format="A4")
    pages = len(re.findall(rb"/Type\s*/Page[^s]", pdf))
    assert pages >= 3 + 1  # a page per student, then the key
    page.close()


def test_a_students_link_opens_their_variant_with_its_numbers(app_url, browser, tmp_path):
    variant = generate(Settings("zbirka-3.1", 42), 2).variants[1]
    page = open_page(browser, f"{app_url}/velocity_plans?v={variant.code}&lang=en")
    page.get_by_text(f"variant {variant.code}").first.wait_for(timeout=30_000)
    wait_url(page, "s=1")  # the code became the scene's own link
    assert "v" not in parse_qs(urlparse(page.url).query)  # (Uv=, a scale, is not a code)
    page.screenshot(path=str(tmp_path / "variant.png"))
    page.close()
