"""Numbers typed the way a person writes them, in chromium with the browser's language set to
English and to Serbian (Playwright's ``locale``): on a Serbian page "0,35" and "0.35" are
both 0.35 in a builder cell, a practice answer and every page's number box; what is not one
number is refused at its field, named, and changes nothing; and no request leaves for a host
other than the app's (ui/numbers.py, docs/i18n.md)."""

from __future__ import annotations

from urllib.parse import parse_qs, urlparse

import pytest

from .test_browser import CHROMIUM, FLAGS, check_first_step, keep, open_page, wait_idle
from .test_builder_browser import open_tab, shapes, type_cell
from .test_practice_browser import practising

pytestmark = pytest.mark.browser

LOCALES = ("en-US", "sr-RS")


@pytest.fixture(scope="module", params=LOCALES)
def localised(request, tmp_path_factory):
    """A chromium profile whose language is ``request.param``, and every address it asked
    for."""
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        context = p.chromium.launch_persistent_context(
            str(tmp_path_factory.mktemp("profile")), executable_path=CHROMIUM, args=FLAGS,
            locale=request.param, viewport={"width": 1600, "height": 1100})
        context.asked, context.language = [], request.param
        context.on("request", lambda r: context.asked.append(r.url))
        yield context
        context.close()


def opened(context, url: str):
    return open_page(context, url, (1600, 1100))  # (a context opens pages as a browser does)


def coupler(page) -> float:
    drawn = shapes(page)
    return abs(drawn["B"] - drawn["A"])


def cells(grid) -> list[str]:
    """A data editor's cells as its accessible grid holds them (the canvas draws the same)."""
    return grid.evaluate("g => [...g.querySelectorAll('[role=gridcell]')].map(c => c.textContent)")


def errors(page) -> list[str]:
    return page.locator("[data-testid='stAlertContentError']").all_inner_texts()


def in_view(page, locator) -> bool:
    box = locator.bounding_box()
    size = page.viewport_size
    return box is not None and box["y"] >= 0 and box["y"] + box["height"] <= size["height"]


def test_a_builder_cell_reads_a_comma_and_a_point_and_refuses_the_rest(app_url, localised,
                                                                       tmp_path):
    page = opened(localised, f"{app_url}/builder?lang=sr")
    page.wait_for_selector(".mehanizmi-plot .shapelayer path", timeout=30_000)
    open_tab(page, "Članovi", "druga tačka")
    grid = page.locator("[data-testid='stDataFrame']").filter(has_text="druga tačka")
    assert "0,12" in cells(grid)  # the crank's length, shown the Serbian way
    for text, length in (("0,35", 0.35), ("0,3", 0.3), ("0.35", 0.35)):
        type_cell(page, "druga tačka", 1, 4, text)  # member 3, the coupler AB: its length
        assert coupler(page) == pytest.approx(length, abs=1e-12), text
    before = shapes(page)
    for column, text in ((4, "0,3,5"), (5, "abc")):  # (5: after the ⚠ column came first)
        type_cell(page, "druga tačka", 1, column, text, redraws=False)
        page.wait_for_function("t => [...document.querySelectorAll("
                               "\"[data-testid='stAlertContentError']\")]"
                               ".some(e => e.innerText.includes(t))", arg=text, timeout=30_000)
        wait_idle(page)
        said = [e for e in errors(page) if text in e]
        assert said and "dužina [m]" in said[0] and "nije jedan broj" in said[0], said
        assert "dužina [m]" in cells(grid)  # the row's ⚠ cell names the column
        assert shapes(page) == before  # the drawing stays as it was
        grid.scroll_into_view_if_needed()
        message = page.locator("[data-testid='stAlert']").filter(has_text=text).first
        assert in_view(page, message) and in_view(page, grid)
    shot = tmp_path / f"builder-refused-cell-sr-page-{localised.language}-browser.png"
    page.screenshot(path=str(shot))
    keep(shot)
    type_cell(page, "druga tačka", 1, 5, "0,25")  # mended: read, drawn, the mark gone
    assert coupler(page) == pytest.approx(0.25, abs=1e-12)
    page.wait_for_function("() => !document.body.innerText.includes('nije jedan broj')",
                           timeout=30_000)
    type_cell(page, "druga tačka", 1, 4, " ", redraws=False)  # nothing: refused at the cell
    page.get_by_text("Crtež pokazuje poslednji").wait_for(timeout=30_000)
    assert shapes(page) != before and coupler(page) == pytest.approx(0.25, abs=1e-12)
    assert any("Članovi · red 2 · dužina [m]: upišite broj" in e for e in errors(page))
    assert not any("members." in e for e in errors(page))  # no internal key
    assert page.locator("[data-testid='stException']").count() == 0


def test_a_practice_answer_reads_a_comma_and_an_unreadable_one_is_named(app_url, localised):
    page = opened(localised, f"{app_url}/velocity_plans?lang=sr&scene=zbirka-3.1")
    practising(page, "Vežbaj")
    check_first_step(page)  # typed with decimal commas, in a browser set to English
    wait_idle(page)

    page.get_by_role("button", name="Sledeći korak").click()
    page.get_by_text("Korak 2 od").wait_for(timeout=30_000)
    wait_idle(page)
    boxes = page.locator("[data-testid='stForm'] input")
    boxes.nth(0).fill("0,3,5")
    boxes.nth(1).fill("")
    page.get_by_role("button", name="Proveri").click()
    page.wait_for_function("() => [...document.querySelectorAll("
                           "\"[data-testid='stAlertContentError']\")]"
                           ".some(e => e.innerText.includes('0,3,5'))", timeout=30_000)
    wait_idle(page)
    said = errors(page)
    assert any("0,3,5" in e and "intenzitet" in e for e in said), said
    assert any("upišite broj" in e and "pravac" in e for e in said), said
    assert page.locator("[data-testid='stAlertContentWarning']").count() == 0  # no verdict
    assert page.locator("[data-testid='stAlertContentSuccess']").count() == 0


# a number box of every page that has one, kept in the link: (page, scene, the tab or panel
# that holds it, key, text, value)
BOXES = [("velocity_plans", "zbirka-2.1", None, "Uv", "0,35", 0.35),
         ("kinetostatics", "zbirka-5.1", "tab:Poligoni sila", "UF", "12,5", 12.5),
         ("assur_groups", "zbirka-4.1", "panel:Njutnova metoda, iteracija", "back", "2,5", 2.5),
         ("planetary_gears", "zbirka-6.1", None, "UL", "0,02", 0.02),
         ("rotor_balancing", "zbirka-7.1", None, "omega", "104,5", 104.5)]


def box_of(page, key: str):
    return page.locator(f".st-key-num_pos_{key} input, .st-key-num_any_{key} input").first


def linked(page, key: str) -> float | None:
    value = parse_qs(urlparse(page.url).query).get(key)
    return float(value[0]) if value else None


@pytest.mark.parametrize("path, scene, where, key, text, value", BOXES, ids=[b[0] for b in BOXES])
def test_every_pages_number_box_reads_a_comma_and_refuses_the_rest(app_url, localised, path,
                                                                   scene, where, key, text, value):
    page = opened(localised, f"{app_url}/{path}?lang=sr&scene={scene}")
    box = box_of(page, key)
    if where and where.startswith("tab:"):
        page.get_by_role("tab", name=where[4:]).click()
    elif where:
        page.locator("[data-testid='stExpander'] summary").filter(has_text=where[6:]).click()
    box.wait_for(timeout=30_000)
    wait_idle(page)
    assert box.get_attribute("inputmode") == "decimal"
    assert "." not in box.input_value()  # shown the Serbian way
    for typed, wanted in ((text, value), (text.replace(",", "."), value)):
        box.fill(typed)
        box.press("Enter")
        page.wait_for_function(f"() => new URLSearchParams(location.search).get('{key}') "
                               f"=== '{wanted:.15g}'", timeout=30_000)
        wait_idle(page)
        box.fill("")  # the next text must be a change
        box.fill(f"{wanted * 2:.6g}".replace(".", ","))
        box.press("Enter")
        page.wait_for_function(f"() => new URLSearchParams(location.search).get('{key}') "
                               f"=== '{wanted * 2:.15g}'", timeout=30_000)
        wait_idle(page)
    kept = linked(page, key)
    for bad in ("0,3,5", "abc", ""):
        box.fill(bad)
        box.press("Enter")
        wait_idle(page)
        said = bad or "upišite broj"  # (an empty box is asked for a number)
        page.wait_for_function("t => [...document.querySelectorAll("
                               "\"[data-testid='stAlertContentError']\")]"
                               ".some(e => e.innerText.includes(t))", arg=said, timeout=30_000)
        assert linked(page, key) == kept  # nothing else changed
    assert page.locator("[data-testid='stException']").count() == 0


def test_an_english_page_refuses_a_comma_in_words(app_url, localised):
    page = opened(localised, f"{app_url}/velocity_plans?lang=en&scene=zbirka-2.1")
    box = box_of(page, "Uv")
    kept = linked(page, "Uv") or box.input_value()
    box.fill("0,35")
    box.press("Enter")
    page.get_by_text("decimal sign is a point").wait_for(timeout=30_000)
    assert (linked(page, "Uv") or box.input_value()) in (kept, "0,35")
    box.fill("0.35")
    box.press("Enter")
    page.wait_for_function("() => new URLSearchParams(location.search).get('Uv') === '0.35'",
                           timeout=30_000)


def test_no_request_leaves_for_another_host(app_url, localised):
    """Everything a page needs comes from the app: a font or icon from a CDN fails in a room
    without internet and tells a third party who visits."""
    for path in ("", "trajectories", "velocity_plans", "assur_groups", "kinetostatics",
                 "planetary_gears", "rotor_balancing", "builder", "variants", "textbook_check"):
        page = localised.new_page()
        page.goto(f"{app_url}/{path}?lang=sr")
        wait_idle(page)
        page.wait_for_load_state("networkidle")  # late requests: fonts, icons, the charts' bundles
        page.close()
    own = urlparse(app_url).netloc
    outside = {u for u in localised.asked
               if urlparse(u).scheme in ("http", "https", "ws", "wss") and urlparse(u).netloc != own}
    assert not outside, sorted(outside)
