"""The builder in a real browser, as a student with an exam problem uses it: drag, type, open
on a chapter page, read the answer (Playwright + Debian chromium)."""

import cmath
import csv
import io
import math
import time

import numpy as np
import pytest
from playwright.sync_api import TimeoutError as PlaywrightTimeout

from .test_browser import keep, open_page, wait_idle, wait_url

pytestmark = pytest.mark.browser

SHAPES = ("() => Object.fromEntries(document.querySelector('.mehanizmi-plot').layout.shapes"
          ".map(s => [s.name, [(s.x0 + s.x1) / 2, (s.y0 + s.y1) / 2]]))")


def exam_four_bar(phi2=math.radians(60), omega2=10.0):
    """The exam four-bar by hand: circle intersection for B (coupler above OD), then the
    velocity loop r2·ω2·ie2 + r3·ω3·ie3 = r4·ω4·ie4 by numpy's solver."""
    o, d, r2, r3, r4 = 0j, 0.3 + 0j, 0.10, 0.35, 0.25
    a = o + r2 * cmath.exp(1j * phi2)
    ad = d - a
    x = (r3**2 - r4**2 + abs(ad) ** 2) / (2 * abs(ad))
    h = math.sqrt(r3**2 - x**2)
    b = max((a + ad / abs(ad) * (x + s * 1j * h) for s in (1, -1)), key=lambda z: z.imag)
    e2, e3, e4 = (1j * (p / abs(p)) for p in (a - o, b - a, b - d))
    m = np.array([[r3 * e3.real, -r4 * e4.real], [r3 * e3.imag, -r4 * e4.imag]])
    w3, w4 = np.linalg.solve(m, [-(r2 * omega2 * e2).real, -(r2 * omega2 * e2).imag])
    coupler = (b - a) / abs(b - a)
    return dict(A=a, B=b, M=a + (0.20 + 0.05j) * coupler, w3=w3, w4=w4)


def shapes(page) -> dict[str, complex]:
    return {k: complex(*v) for k, v in page.evaluate(SHAPES).items()}


def screen_of(page, x: float, y: float) -> tuple[float, float]:
    """Where a point of the drawing (m) is on the screen."""
    return tuple(page.evaluate("""([x, y]) => { const gd = document.querySelector('.mehanizmi-plot');
        const box = gd.querySelector('.nsewdrag').getBoundingClientRect(), L = gd._fullLayout;
        return [box.left + L.xaxis.c2p(x), box.top + L.yaxis.c2p(y)]; }""", [x, y]))


def drag_shape(page, name: str, to: complex) -> None:
    """Drag the drawing's circle ``name`` to ``to`` (the figure's units) with the mouse. On a
    loaded machine a chart may still be taking its listeners when the mouse goes down, and
    the drag is lost: then the circle has not moved, and the drag is made again."""
    start = shapes(page)[name]
    moved = (f"() => Math.hypot(({SHAPES})()[{name!r}][0] - {start.real}, "
             f"({SHAPES})()[{name!r}][1] - {start.imag}) > {abs(to - start) / 2}")
    for _ in range(3):
        x0, y0 = screen_of(page, start.real, start.imag)
        x1, y1 = screen_of(page, to.real, to.imag)
        page.mouse.move(x0, y0)
        page.mouse.down()
        page.mouse.move((x0 + x1) / 2, (y0 + y1) / 2, steps=5)
        page.mouse.move(x1, y1, steps=5)
        page.mouse.up()
        try:
            page.wait_for_function(moved, timeout=5_000)
            return
        except PlaywrightTimeout:
            page.wait_for_timeout(500)
    raise AssertionError(f"the circle {name} did not follow three drags")


def drag_point(page, name: str, to: complex) -> None:
    drag_shape(page, name, to)
    # Plotly moves the circle at once; the server's redraw puts it on round millimetres
    page.wait_for_function(f"() => Math.hypot(({SHAPES})()[{name!r}][0] - {to.real}, "
                           f"({SHAPES})()[{name!r}][1] - {to.imag}) < 1e-9", timeout=30_000)
    wait_idle(page)


def click_in(page, grid, x: float, y: float, seen: list) -> bool:
    """Click (x, y) and say whether the grid took the focus (it comes a moment after the
    click on a loaded machine; a second click on the cell then selected would open its
    editor); if not, note in ``seen`` what lay at that point (a header, an editor left
    open, another element), for the failure's message, and Escape whatever it opened."""
    page.mouse.click(x, y)
    try:
        page.wait_for_function("g => g.contains(document.activeElement)",
                               arg=grid.element_handle(), timeout=3_000)
        return True
    except PlaywrightTimeout:
        seen.append("click taken by " + page.evaluate(
            "([x, y]) => { const e = document.elementFromPoint(x, y); if (!e) return 'nothing';"
            " const named = e.closest('[data-testid], #portal'); return named ?"
            " (named.getAttribute('data-testid') || named.id) : e.tagName; }", [x, y]))
        page.keyboard.press("Escape")
        return False


def type_cell(page, header: str, row: int, column: int, text: str, redraws: bool = True) -> None:
    """Type into a data editor's cell as a keyboard user does: click the row, Home and arrow to
    the column, Enter to edit, replace the value, Enter to commit. A fresh editor may drop
    keys typed before it has focus (more so on a loaded machine): then Escape and again. The
    table is the one with a column named ``header`` (only the open tab's table is on the page,
    once the tab switch's rerun is done)."""
    grid = page.locator("[data-testid='stDataFrame']").filter(has_text=header)
    grid.wait_for(state="visible")
    wait_idle(page)
    seen = []  # what each try's focused element held, for the failure's message
    for _ in range(5):
        page.wait_for_timeout(300)  # the tab's content laid out
        # centred, not scrolled "if needed": that aligns a grid above the view with its top
        # edge, where the page's fixed header lies over the first rows and takes the click
        grid.evaluate("g => g.scrollIntoView({block: 'center'})")
        box = grid.bounding_box()
        if not click_in(page, grid, box["x"] + 70, box["y"] + 35 + 35 * row + 17, seen):
            continue  # the keys below would go to the tabs, whose arrow keys switch tabs and
            # take the table away
        page.keyboard.press("Home")  # the row's first column, however the grid is scrolled
        for _ in range(column):
            page.keyboard.press("ArrowRight")
        page.keyboard.press("Enter")
        try:  # the cell's editor open and focused (slow to come on a loaded machine)
            page.wait_for_function("() => ['INPUT', 'TEXTAREA'].includes("
                                   "document.activeElement && document.activeElement.tagName)",
                                   timeout=5_000)
        except PlaywrightTimeout:
            seen.append("no editor opened")
            page.keyboard.press("Escape")
            continue
        page.keyboard.press("Control+a")
        page.keyboard.type(text, delay=100)
        held = page.evaluate("() => [document.activeElement && document.activeElement.tagName, "
                             "document.activeElement && document.activeElement.value]")
        if held[1] == text:
            break
        seen.append(held)
        page.keyboard.press("Escape")
    else:
        raise AssertionError(f"the cell editor never held {text!r}: {seen}")
    before = page.evaluate(SHAPES) if redraws else None  # (a builder's drawing only)
    page.keyboard.press("Enter")
    if redraws:
        page.wait_for_function(f"b => JSON.stringify(({SHAPES})()) !== JSON.stringify(b)",
                               arg=before, timeout=30_000)
    wait_idle(page)


def open_tab(page, name: str, header: str) -> None:
    """Open the tables' tab ``name`` and wait until its table (the one with column ``header``)
    is there with the app idle: a click that lands while a rerun is redrawing the tabs, or
    whose table the tab's own rerun (ui.builder.fold) then replaces, is checked again."""
    grid = page.locator("[data-testid='stDataFrame']").filter(has_text=header)
    for _ in range(4):
        wait_idle(page)
        if grid.is_visible():
            return
        page.get_by_role("tab", name=name, exact=True).click()
        try:
            grid.wait_for(state="visible", timeout=10_000)
        except Exception:  # noqa: BLE001 (Playwright's timeout: look again, click again)
            continue
    grid.wait_for(state="visible", timeout=10_000)


def builder(browser, app_url, lang="en"):
    page = open_page(browser, f"{app_url}/builder?lang={lang}", (1600, 1100))
    page.wait_for_selector(".mehanizmi-plot .shapelayer path", timeout=30_000)
    return page


def test_the_exam_four_bar_is_built_by_dragging_and_typing_and_read_on_the_plans_page(
        app_url, browser, tmp_path):
    started = time.perf_counter()
    page = builder(browser, app_url)
    drag_point(page, "D", 0.3 + 0j)  # the template's rocker pivot, to the exam's place
    assert shapes(page)["D"] == pytest.approx(0.3 + 0j, abs=1e-15)  # snapped to millimetres
    open_tab(page, "Members", "second point")
    for row, length in enumerate(("0.1", "0.35", "0.25")):  # crank, coupler, rocker
        type_cell(page, "second point", row, 4, length)
    open_tab(page, "Points of members", "along [m]")
    type_cell(page, "along [m]", 0, 3, "0.2")  # M: 0.20 m along AB …
    type_cell(page, "along [m]", 0, 4, "0.05")  # … and 0.05 m to its left
    exact = exam_four_bar()
    drawn = shapes(page)
    for name in ("A", "B", "M"):
        assert abs(drawn[name] - exact[name]) < 1e-9, name
    shot = tmp_path / "builder-exam-four-bar-en.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)

    omega = omegas_on_the_plans_page(page)
    assert omega[3] == pytest.approx(exact["w3"], rel=1e-4)
    assert omega[4] == pytest.approx(exact["w4"], rel=1e-4)
    assert page.locator("[data-testid='stException']").count() == 0
    shot = tmp_path / "builder-exam-four-bar-plans-en.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)
    print(f"exam four-bar: built and read in {time.perf_counter() - started:.1f} s of browser time")


def test_dragging_a_pivot_redraws_the_paths(app_url, browser, tmp_path):
    page = builder(browser, app_url, "sr")
    paths = "() => Array.from(document.querySelector('.mehanizmi-plot')._fullData[0].x).join()"
    before = page.evaluate(paths)
    assert before.count(",") > 100  # (Plotly's decoded arrays: the figure sends them packed)
    drag_point(page, "O", -0.05 + 0.02j)
    assert shapes(page)["O"] == pytest.approx(-0.05 + 0.02j, abs=1e-12)
    assert page.evaluate(paths) != before
    page.get_by_text("Sastavi mehanizam").first.wait_for()
    assert page.locator("[data-testid='stException']").count() == 0
    shot = tmp_path / "builder-drag-pivot-sr.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)


def test_a_drag_the_loader_refuses_says_why_and_keeps_the_drawing(
        app_url, browser):
    page = builder(browser, app_url)
    before = shapes(page)
    x, y = screen_of(page, before["D"].real, before["D"].imag)
    onto = screen_of(page, 0.0, 0.0)  # the rocker's pivot dropped on the crank's
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(onto[0], onto[1], steps=8)
    page.mouse.up()
    page.get_by_text("coincides with frame.O").first.wait_for(timeout=30_000)
    assert page.get_by_text("Point D cannot go to").count() == 1
    wait_idle(page)
    assert shapes(page) == before


def test_a_click_on_the_paper_adds_a_frame_point_there(app_url, browser):
    page = builder(browser, app_url)
    page.get_by_text("a frame point", exact=True).click()
    wait_idle(page)
    x, y = screen_of(page, 0.2, -0.05)
    page.mouse.click(x, y)
    page.wait_for_function(f"() => 'C' in ({SHAPES})()", timeout=30_000)
    wait_idle(page)
    assert shapes(page)["C"] == pytest.approx(0.2 - 0.05j, abs=1e-12)  # snapped
    assert page.get_by_text("Point C of member 1 is a joint no pair uses").count() == 1


def test_a_typed_length_the_loader_refuses_gets_its_message_and_the_drawing_stays(
        app_url, browser):
    page = builder(browser, app_url)
    before = shapes(page)
    open_tab(page, "Members", "second point")
    type_cell(page, "second point", 1, 4, "-0.35", redraws=False)
    page.get_by_text("Table Members, row 2, column length: must be > 0, got -0.35").wait_for(timeout=30_000)
    assert page.get_by_text("The drawing shows the last mechanism").count() == 1
    assert shapes(page) == before
    assert page.locator("[data-testid='stException']").count() == 0


def start_template(page, title: str) -> None:
    """Choose a template in the "Start from" box by typing its name, then Start."""
    page.locator("[data-testid='stSelectbox']").filter(has_text="Start from").click()
    page.keyboard.type(title, delay=20)
    page.keyboard.press("Enter")
    wait_idle(page)
    before = page.evaluate(SHAPES)
    page.get_by_role("button", name="Start", exact=True).click()
    page.wait_for_function(f"b => JSON.stringify(({SHAPES})()) !== JSON.stringify(b)",
                           arg=before, timeout=30_000)
    wait_idle(page)


def test_a_triangles_three_sides_typed_in_the_builder_place_its_point(app_url, browser, tmp_path):
    """Watt's rocker DB carries E by the sheet's triangle: DB = 0.26 m, DE = 0.2 m, BE = 0.1 m,
    E to the right of D → B. Typed as printed, E is drawn where the law of cosines puts it."""
    page = builder(browser, app_url)
    start_template(page, "Watt six-bar")
    open_tab(page, "Members", "second point")
    type_cell(page, "second point", 2, 4, "0.26")  # member 4, D → B
    open_tab(page, "Points of members", "along [m]")
    type_cell(page, "along [m]", 0, 5, "0.2")  # DE
    type_cell(page, "along [m]", 0, 6, "0.1")  # BE
    drawn = shapes(page)
    d, b = drawn["D"], drawn["B"]
    assert abs(abs(b - d) - 0.26) < 1e-12
    along = (0.2**2 - 0.1**2 + 0.26**2) / (2 * 0.26)
    expected = d + (b - d) / 0.26 * complex(along, -math.sqrt(0.2**2 - along**2))  # right side
    assert abs(drawn["E"] - expected) < 1e-9
    assert abs(abs(drawn["E"] - d) - 0.2) < 1e-9 and abs(abs(drawn["E"] - b) - 0.1) < 1e-9
    assert page.locator("[data-testid='stException']").count() == 0
    shot = tmp_path / "builder-triangle-sides-en.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)


def watt_other_closure(phi2=math.radians(60), omega2=10.0):
    """The Watt template by hand: the first four-bar as drawn (B above OD), E by its
    triangle (DE = 0.16, BE = 0.12, right of D → B), and the second dyad E–F–G closed on the
    side opposite the template's drawing; velocities from the two vector loops."""
    o, d, g = 0j, 0.3 + 0j, 0.55 + 0.05j
    r2, r3, r4, r5, r6 = 0.1, 0.35, 0.25, 0.25, 0.2

    def meet(p, q, rp, rq):  # both intersections of circles about p and q
        pq = q - p
        x = (rp**2 - rq**2 + abs(pq) ** 2) / (2 * abs(pq))
        h = math.sqrt(rp**2 - x**2)
        return [p + pq / abs(pq) * (x + s * 1j * h) for s in (1, -1)]

    a = o + r2 * cmath.exp(1j * phi2)
    b = max(meet(a, d, r3, r4), key=lambda z: z.imag)
    along = (0.16**2 - 0.12**2 + r4**2) / (2 * r4)
    e = d + (b - d) / r4 * complex(along, -math.sqrt(0.16**2 - along**2))
    e2, e3, e4 = (1j * (p / abs(p)) for p in (a - o, b - a, b - d))
    m = np.array([[r3 * e3.real, -r4 * e4.real], [r3 * e3.imag, -r4 * e4.imag]])
    w3, w4 = np.linalg.solve(m, [-(r2 * omega2 * e2).real, -(r2 * omega2 * e2).imag])
    v_e = 1j * w4 * (e - d)
    f = min(meet(e, g, r5, r6), key=lambda z: z.imag)  # the template draws F above: the other
    e5, e6 = 1j * (f - e) / r5, 1j * (f - g) / r6
    m = np.array([[r5 * e5.real, -r6 * e6.real], [r5 * e5.imag, -r6 * e6.imag]])
    w5, w6 = np.linalg.solve(m, [-v_e.real, -v_e.imag])
    return dict(F=f, w3=w3, w4=w4, w5=w5, w6=w6)


def omegas_on_the_plans_page(page) -> dict[int, float]:
    """Open the built scene on the plans page (its button) and read ω per member from the
    members table's CSV."""
    page.get_by_role("button", name="2–3 · Velocity and acceleration plans").click()
    wait_url(page, r"velocity_plans\?.*s=1")
    wait_idle(page)
    return {m: float(r["ω [s⁻¹]"]) for m, r in members_csv(page).items()}


def members_csv(page) -> dict[int, dict]:
    with page.expect_download() as download:
        page.locator(".st-key-csv_members button").click()
    rows = csv.DictReader(io.StringIO(open(download.value.path(), encoding="utf-8").read()))
    return {int(r["member"]): r for r in rows}


def test_groups_flip_to_their_other_assembly_and_the_plans_page_reads_its_omegas(
        app_url, browser, tmp_path):
    """A dyad by a double click on its joint, a class III group by its button: every length
    stays, and ω on the plans page is the other closure's (the dyad's computed by hand)."""
    page = builder(browser, app_url)
    start_template(page, "Watt six-bar")
    before = shapes(page)
    x, y = screen_of(page, before["F"].real, before["F"].imag)
    page.mouse.dblclick(x, y)
    exact = watt_other_closure()
    page.wait_for_function(f"() => Math.abs(({SHAPES})()['F'][1] - {exact['F'].imag}) < 1e-3",
                           timeout=30_000)
    wait_idle(page)
    assert abs(shapes(page)["F"] - exact["F"]) < 1e-3  # drawn to the snapped guess
    omegas = omegas_on_the_plans_page(page)
    for member in (3, 4, 5, 6):
        assert omegas[member] == pytest.approx(exact[f"w{member}"], rel=1e-4)
    shot = tmp_path / "builder-other-assembly-plans-en.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)

    page = builder(browser, app_url)
    start_template(page, "A mechanism with a class III group")
    drawn_before = shapes(page)
    page.get_by_role("button", name="Other assembly").first.click()
    page.wait_for_function(f"b => JSON.stringify(({SHAPES})()) !== JSON.stringify(b)",
                           arg={k: [v.real, v.imag] for k, v in drawn_before.items()}, timeout=30_000)
    wait_idle(page)
    after = shapes(page)
    for a, b in (("B", "C"), ("C", "D"), ("E", "D")):  # the lengths of members 3, 4, 5
        assert abs(abs(after[a] - after[b]) - abs(drawn_before[a] - drawn_before[b])) < 1e-3
    assert max(abs(after[n] - drawn_before[n]) for n in ("C", "D")) > 0.05
    shot = tmp_path / "builder-class-iii-other-assembly-en.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)
    omegas = omegas_on_the_plans_page(page)
    from mechanisms.link import decode
    from solvers.diagnostics import solve_instant
    link = page.evaluate("() => new URL(location.href).searchParams.get('s')")
    motion = solve_instant(decode(link), None)
    for member in (3, 4, 5, 6):
        assert omegas[member] == pytest.approx(float(motion.members[member].omega[0]), rel=1e-4)
    from mechanisms.loader import build_scene
    from mechanisms.sketch import template
    original = solve_instant(build_scene(template("class-iii")), None)
    assert any(abs(omegas[m] - float(original.members[m].omega[0])) > 1e-3 for m in (3, 4, 5, 6))
