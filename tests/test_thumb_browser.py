"""By thumb, in chromium's iPhone 13 profile, in Serbian (touches are CDP touch events).

Practice (task 3.1's plans): each step opens around its tip, the paper's tolerance at least
3 pixels wide; two fingers zoom the sheet and a finger drags the tip, grabbed off its centre,
to the exact place, which fills the boxes, and Check grades it — ok at the paper's tolerance;
a swipe beside the tip scrolls the page and leaves the sheet's view; after each check the
step's prompt, its verdict and the sheet are on the screen. A typed step's verdict is on the
screen under its Check button.

The builder: its drawing stays at the top of the screen while the tables scroll under it,
so a typed length is seen redrawn from where it is typed."""

from __future__ import annotations

import pytest
from playwright.sync_api import TimeoutError as PlaywrightTimeout

from cli.practice import steps_for
from mechanisms import load_preset

from .test_browser import CHROMIUM, FLAGS, keep, settle, wait_idle
from .test_builder_browser import SHAPES, click_in, open_tab, shapes

pytestmark = pytest.mark.browser

SHEET = "document.querySelector('.mehanizmi-plot')"
MAIN = "document.querySelector(\"[data-testid='stMain']\")"


@pytest.fixture(scope="module")
def phone(tmp_path_factory):
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        device = {k: v for k, v in p.devices["iPhone 13"].items() if k != "default_browser_type"}
        browser = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        context = browser.new_context(**device, locale="sr-RS")
        yield context
        browser.close()


def touch(cdp, kind: str, points: list[tuple[float, float]]) -> None:
    cdp.send("Input.dispatchTouchEvent",
             {"type": kind, "touchPoints": [{"x": x, "y": y} for x, y in points]})


def gesture(cdp, page, paths: list[list[tuple[float, float]]]) -> None:
    """Fingers down at each path's start, along it in ten moves, then up."""
    touch(cdp, "touchStart", [path[0] for path in paths])
    for k in range(1, 11):
        touch(cdp, "touchMove", [(a[0] + (b[0] - a[0]) * k / 10, a[1] + (b[1] - a[1]) * k / 10)
                                 for a, b in paths])
        page.wait_for_timeout(25)
    touch(cdp, "touchEnd", [])


def view(page) -> list:
    return page.evaluate(f"() => [{SHEET}._fullLayout.xaxis.range, {SHEET}._fullLayout.yaxis.range]")


def area(page) -> dict:
    return page.evaluate(f"() => {{ const r = {SHEET}.querySelector('.nsewdrag')"
                         ".getBoundingClientRect(); return {x: r.left, y: r.top, w: r.width, h: r.height}; }")


def on_screen(page, x: float, y: float) -> tuple[float, float]:
    return tuple(page.evaluate(
        f"([x, y]) => {{ const g = {SHEET}, b = g.querySelector('.nsewdrag').getBoundingClientRect(); "
        "return [b.left + g._fullLayout.xaxis.c2p(x), b.top + g._fullLayout.yaxis.c2p(y)]; }",
        [x, y]))


def tip_now(page) -> complex:
    x, y = page.evaluate(f"() => {{ const s = {SHEET}.layout.shapes[0]; "
                         "return [(s.x0 + s.x1) / 2, (s.y0 + s.y1) / 2]; }")
    return complex(x, y)


def in_view(page, selector: str) -> bool:
    box = page.locator(selector).last.bounding_box()
    return box is not None and box["y"] >= 0 and box["y"] + box["height"] <= 664


def test_a_student_practises_task_3_1_by_finger(app_url, phone, tmp_path):
    page = phone.new_page()
    cdp = phone.new_cdp_session(page)
    page.goto(f"{app_url}/velocity_plans?lang=sr&scene=zbirka-3.1")
    settle(page)
    page.get_by_text("Vežbaj", exact=True).tap()
    page.wait_for_selector(".mehanizmi-plot .shapelayer path", timeout=30_000)
    wait_idle(page)
    steps = steps_for(load_preset("zbirka-3.1"), "plans")
    for n, step in enumerate(steps[:6]):
        page.wait_for_function(f"() => document.body.innerText.includes('Korak {n + 1} od')",
                               timeout=30_000)
        wait_idle(page)
        page.wait_for_timeout(300)
        assert in_view(page, ".st-key-pr_plans_prompt"), n  # the prompt, brought up
        if n < 3:
            opened = view(page)
            box = area(page)
            width = opened[0][1] - opened[0][0]  # cm across the sheet's box
            tail = step.tail / step.scale  # the window holds the tail and the answer (issue 68)
            answer = tail + complex(step.expected) / step.scale
            for z in (tail, answer):
                assert opened[0][0] <= z.real <= opened[0][1] and opened[1][0] <= z.imag <= opened[1][1], n
            assert (step.tolerance / step.scale * box["w"] / width >= 3 - 1e-6  # in pixels, or
                    or width / 2 <= abs(answer - tail) / 2 + 1.0)  # no coarser than the two need
            exact = (step.tail + complex(step.expected)) / step.scale  # in the opening view
            handle = on_screen(page, tip_now(page).real, tip_now(page).imag)
            grab = (handle[0] + 14, handle[1] - 8)  # a finger lands beside a 3 px circle
            target = on_screen(page, exact.real, exact.imag)
            gesture(cdp, page, [[grab, (target[0] + 14, target[1] - 8)]])
            page.wait_for_function("() => document.querySelector("
                                   "\"[class*='st-key-num_any_pr_plans_len'] input\").value")
            wait_idle(page)
            opened = view(page)  # (after the drag: around the student's tip)
            middle = (box["x"] + box["w"] / 2, box["y"] + box["h"] / 2)
            gesture(cdp, page, [[(middle[0] - 20, middle[1]), (middle[0] - 60, middle[1])],
                                [(middle[0] + 20, middle[1]), (middle[0] + 60, middle[1])]])
            page.wait_for_timeout(300)
            zoomed = view(page)
            assert zoomed[0][1] - zoomed[0][0] < (opened[0][1] - opened[0][0]) / 2.5  # × 3
            assert page.locator("[data-testid='stAlertContentSuccess']").count() == 0
            page.get_by_role("button", name="Proveri").tap()
            page.locator("[data-testid='stAlertContentSuccess']").wait_for(timeout=30_000)
            wait_idle(page)
            assert abs(tip_now(page) - exact) < step.tolerance / step.scale
            assert in_view(page, "[data-testid='stAlertContentSuccess']")
            assert in_view(page, ".st-key-pr_plans_prompt")
        if n == 2:  # a coarser U_v keeps the answer and its verdict; the tip is redrawn
            placed = tip_now(page)  # cm at 1 m/s a cm
            box = page.locator(".st-key-num_pos_Uv input")
            box.fill("2")
            box.press("Enter")
            page.wait_for_function("() => new URLSearchParams(location.search).get('Uv') === '2'",
                                   timeout=30_000)
            wait_idle(page)
            assert page.locator("[data-testid='stAlertContentSuccess']").count() == 1
            assert page.get_by_text(f"Korak {n + 1} od").count() == 1
            assert abs(tip_now(page) - placed / 2) < 1e-9  # the same answer, 2 m/s a cm now
        if n == 0:  # a swipe beside the tip scrolls the page and leaves the sheet as it was
            before, scrolled = view(page), page.evaluate(f"() => {MAIN}.scrollTop")
            box = area(page)
            start = (box["x"] + 20, box["y"] + box["h"] - 20)
            gesture(cdp, page, [[start, (start[0], start[1] - 250)]])
            page.wait_for_timeout(600)
            assert page.evaluate(f"() => {MAIN}.scrollTop") > scrolled + 100
            assert view(page) == before
        shot = tmp_path / f"practice-phone-sr-step-{n + 1}.png"
        page.screenshot(path=str(shot))
        keep(shot)
        page.get_by_role("button", name="Sledeći korak").tap()
    assert page.locator("[data-testid='stException']").count() == 0


def test_the_builders_drawing_stays_over_the_tables_being_typed(app_url, phone, tmp_path):
    page = phone.new_page()
    page.goto(f"{app_url}/builder?lang=sr")
    settle(page)
    page.wait_for_selector(".mehanizmi-plot .shapelayer path", timeout=30_000)
    open_tab(page, "Članovi", "naziv")
    page.evaluate(f"""() => {{  // the table just under the drawing, as a student scrolls to it
        const grid = document.querySelector("[data-testid='stDataFrame']").getBoundingClientRect();
        const sheet = document.querySelector('.st-key-build_sheet').getBoundingClientRect();
        {MAIN}.scrollTop += grid.top - sheet.bottom - 8; }}""")
    page.wait_for_timeout(400)
    before = shapes(page)
    table = page.locator("[data-testid='stDataFrame']").first
    seen = []  # what each tap landed on, for the failure's message
    for arrows in (3, 4, 2, 3, 4, 2):  # to the length cell from the one tapped (it holds 0,4)
        wait_idle(page)  # (a click while a rerun redraws the grid lands nowhere, under load)
        grid = table.bounding_box()  # (where it is now: an Escape or a rerun may scroll it)
        if not click_in(page, table, grid["x"] + 70, grid["y"] + 35 + 35 + 17, seen):
            continue  # the coupler's row missed: the arrows would scroll the page
        for _ in range(arrows):  # (arrows, not Home: a Home the grid does not take scrolls
            page.keyboard.press("ArrowRight")  # the page)
        page.keyboard.press("Enter")
        try:  # the cell's editor open and focused (slow to come on a loaded machine)
            page.wait_for_function("() => document.activeElement && document.activeElement.value === '0,4'",
                                   timeout=5_000)
            break
        except PlaywrightTimeout:
            seen.append("no editor with 0,4")
            page.keyboard.press("Escape")
    else:
        pytest.fail(f"the length cell's editor never opened (six taps): {seen}")
    page.keyboard.press("Control+a")
    page.keyboard.type("0,35", delay=60)  # the coupler's length, typed the Serbian way
    page.keyboard.press("Enter")
    page.wait_for_function(f"b => JSON.stringify(({SHAPES})()) !== JSON.stringify(b)",
                           arg=page.evaluate(SHAPES), timeout=30_000)
    wait_idle(page)
    drawn = shapes(page)
    assert abs(abs(drawn["B"] - drawn["A"]) - 0.35) < 1e-9 and drawn != before
    assert in_view(page, ".st-key-build_sheet")  # the drawing is where the student looks
    grid = page.locator("[data-testid='stDataFrame']").first.bounding_box()
    sheet = page.locator(".st-key-build_sheet").bounding_box()
    assert grid["y"] >= sheet["y"] + sheet["height"] - 1 and grid["y"] < 664  # and the table
    shot = tmp_path / "builder-phone-sr-typing.png"
    page.screenshot(path=str(shot))
    keep(shot)


def test_a_typed_steps_verdict_is_on_the_screen_after_check(app_url, phone, tmp_path):
    """Task 6.1's Willis steps are typed (no sheet): the verdict comes under the Check button
    the thumb just tapped, not above the screen's top."""
    page = phone.new_page()
    page.goto(f"{app_url}/planetary_gears?lang=sr&scene=zbirka-6.1")
    settle(page)
    page.get_by_text("Vežbaj", exact=True).tap()
    box = page.locator("[class*='st-key-num_any_pr_willis_value'] input").first
    box.wait_for(timeout=30_000)
    wait_idle(page)
    box.tap()
    box.fill("1")
    page.get_by_role("button", name="Proveri").tap()
    verdict = page.locator("[data-testid='stAlertContentWarning'], [data-testid='stAlertContentSuccess']")
    verdict.first.wait_for(timeout=30_000)
    wait_idle(page)
    page.wait_for_timeout(300)
    assert in_view(page, "[data-testid='stAlertContentWarning'], [data-testid='stAlertContentSuccess']")
    shot = tmp_path / "practice-phone-sr-typed-verdict.png"
    page.screenshot(path=str(shot))
    keep(shot)
    assert page.locator("[data-testid='stException']").count() == 0
