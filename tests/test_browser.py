"""Real-browser test: Debian's chromium driven by Playwright against a running app.

Skipped on a developer machine without /usr/bin/chromium; in CI (CI=true) a missing
browser is a failure, never a silent skip.
"""

import itertools
import json
import math
import os
import shutil
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
CHROMIUM = "/usr/bin/chromium"
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         "--disable-dev-shm-usage"]

pytestmark = pytest.mark.browser

if not Path(CHROMIUM).exists():
    if os.environ.get("CI") == "true":
        raise RuntimeError(f"{CHROMIUM} is missing in CI: .ci/run must install Debian's chromium")
    pytest.skip(f"{CHROMIUM} not installed (run .ci/run or see README)", allow_module_level=True)


# the script is done, and no chart of a session's first run is waiting for the rerun its
# paint starts (ui/firstpaint.py: that rerun brings the tables and the rest)
IDLE = """() => document.querySelector("[data-testid='stApp'][data-test-script-state='notRunning']")
  && ![...document.querySelectorAll('.mehanizmi-plot')].some((g) => g.__first)"""


# idle for 50 ms on end: a run that reruns itself (``st.rerun``: a first run that drew no
# chart, ui/firstpaint.py) is "not running" for a moment between its two runs, which a
# browser sees since the server sends a session's messages 1 ms apart (scripts/serve.py)
# (each wait its own clock: ``since`` names it)
STILL = f"""(since) => {{
  const clocks = window.__idleSince = window.__idleSince || {{}};
  if (!({IDLE})()) {{ clocks[since] = null; return false; }}
  clocks[since] = clocks[since] ?? performance.now();
  return performance.now() - clocks[since] >= 50;
}}"""
_WAITS = itertools.count()


def wait_idle(page) -> None:
    page.wait_for_function(STILL, arg=next(_WAITS), timeout=30_000)


def plot_x(page, which: int = 0) -> list:
    """The x data of every trace of a Plotly chart, as the browser holds it."""
    return page.evaluate("i => document.querySelectorAll('.js-plotly-plot')[i].data"
                         ".map(t => Array.from(t.x || []).map(v => v === null ? null : +v))", which)


def keep(shot: Path) -> None:
    """Copy a screenshot where a person can look at it (SCREENSHOT_DIR), besides the temp dir."""
    assert shot.stat().st_size > 10_000
    target = os.environ.get("SCREENSHOT_DIR")
    if target:
        Path(target).mkdir(parents=True, exist_ok=True)
        shutil.copy(shot, Path(target) / shot.name)


def check_first_step(page, turn: float = 0.0, verdict: str | None = None) -> None:
    """Type the first step of task 3.1's plans the Serbian way (decimal commas) — right, or
    turned by ``turn`` degrees — press Check and wait for the verdict (right: a success;
    else a warning; or the alert ``verdict`` names: "Info" for a step done elsewhere)."""
    from mechanisms import load_preset
    from methods.practice_steps import steps_for

    z = complex(steps_for(load_preset("zbirka-3.1"), "plans")[0].expected)
    boxes = page.locator("[data-testid='stForm'] input")
    boxes.nth(0).fill(f"{abs(z):.6g}".replace(".", ","))
    boxes.nth(1).fill(f"{math.degrees(math.atan2(z.imag, z.real)) + turn:.6g}".replace(".", ","))
    page.get_by_role("button", name="Proveri").click()
    verdict = verdict or ("Success" if turn == 0 else "Warning")
    page.locator(f"[data-testid='stAlertContent{verdict}']").first.wait_for(timeout=30_000)


def open_page(browser, url: str, size=(1400, 900)):
    page = browser.new_page()
    page.set_viewport_size({"width": size[0], "height": size[1]})
    page.goto(url)
    settle(page)
    return page


def settle(page) -> None:
    """After a page is opened: its chart drawn, and the whole page there (ui/firstpaint.py)."""
    wait_idle(page)  # (also true before the first run has started)
    page.wait_for_selector(".js-plotly-plot", timeout=30_000)
    wait_idle(page)


def wait_url(page, pattern: str, timeout: int = 30_000) -> None:
    """Wait until the address bar matches: Streamlit rewrites it with history.replaceState,
    which is no navigation, so Page.wait_for_url (waiting for a "load") is the wrong tool."""
    page.wait_for_function("p => new RegExp(p).test(location.href)", arg=pattern, timeout=timeout)


def slide_to(slider, target: float, key: str, back: str, url: str) -> None:
    """Press `key` until the slider shows `target` and the app has taken it (the address bar
    matches `url`). A rerun that lands between presses may re-render the widget and drop a
    press, or show a value it never sent: count the value, not the presses, and when the app
    is idle with the slider on target but an older link, step off and back on. A value
    shown late can also carry the slider past the target: then press `back`."""
    page = slider.page
    start = float(slider.input_value())
    for _ in range(200):
        value = float(slider.input_value())
        if abs(value - target) < 1e-9:
            page.wait_for_timeout(500)  # the slider sends its value after a short pause
            wait_idle(page)
            try:
                wait_url(page, url, timeout=5_000)
                return
            except Exception:  # Playwright's TimeoutError: the value shown was not sent
                slider.focus()
                slider.press(back)
                continue
        slider.focus()
        slider.press(back if (value - target) * (start - target) < 0 else key)
    raise AssertionError(f"the slider never reached {target} (it shows {slider.input_value()})")


def test_turning_the_crank_the_other_way_renumbers_the_positions(app_url, browser, tmp_path):
    page = open_page(browser, f"{app_url}/trajectories?lang=en&scene=four-bar-crank-rocker")
    before = plot_x(page)
    omega = page.locator("[data-testid='stSlider'] input[type='range'][aria-label^='ω₂']").first
    # 10 rad/s → −2.5 rad/s in steps of 0.5; the shareable link follows
    slide_to(omega, -2.5, "ArrowLeft", "ArrowRight", r"omega=-2\.5(&|$)")
    wait_idle(page)
    # the positions are numbered the other way round: the drawn data differ from before
    page.wait_for_function(
        "before => JSON.stringify(document.querySelector('.js-plotly-plot').data"
        ".map(t => Array.from(t.x || []).map(v => v === null ? null : +v))) !== before",
        arg=json.dumps(before), timeout=30_000)
    shot = tmp_path / "trajectories-construction.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)


# when the first chart is painted and when the first of what follows it shows (a table; on
# the trajectories page, whose table's section opens shut, the readouts), from the page's start
FIRST_THINGS = """(() => {
  const follows = window.__follows || '[data-testid=stDataFrame]';
  const poll = () => {
    const gd = document.querySelector('.js-plotly-plot');
    if (!window.__chartAt && gd && gd._fullLayout) window.__chartAt = performance.now();
    if (!window.__tableAt && document.querySelector(follows))
      window.__tableAt = performance.now();
    if (!window.__tableAt) requestAnimationFrame(poll);
  };
  requestAnimationFrame(poll);
})();"""
READOUTS = "window.__follows = '[data-testid=stMetric]';"


@pytest.mark.parametrize("path", ["trajectories", "velocity_plans", "kinetostatics", "home"])
def test_a_fresh_visit_paints_the_chart_first_and_the_tables_follow_by_themselves(
        app_url, browser, path):
    """ui/firstpaint.py: a page's first run leaves the tables (the trajectories page: its
    readouts) out; the chart's first paint brings them with no touch of the student's. Also
    when the student comes from the home page (the same session, another page)."""
    page = browser.new_page()
    if path in ("trajectories", "home"):  # (home: the student goes on to the trajectories)
        page.add_init_script(READOUTS)
    page.add_init_script(FIRST_THINGS)
    if path == "home":
        page.goto(f"{app_url}/?lang=en")
        page.get_by_role("link", name="Trajectories").first.click()
    else:
        page.goto(f"{app_url}/{path}?lang=en")
    page.wait_for_function("() => window.__tableAt", timeout=30_000)
    chart_at, table_at = page.evaluate("() => [window.__chartAt, window.__tableAt]")
    assert chart_at is not None and chart_at < table_at
    wait_idle(page)
    assert page.evaluate("() => [...document.querySelectorAll('.mehanizmi-plot')]"
                         ".every((g) => g.__first === false)")
    assert page.locator("[data-testid='stMetric'], [data-testid='stExpander']").count() > 0
    page.close()


def test_the_animation_plays_and_its_frame_slider_advances(app_url, browser, tmp_path):
    page = open_page(browser, f"{app_url}/trajectories?lang=en&scene=analitika-2.1")
    page.get_by_role("tab", name="Animation").click()  # only the open tab runs: one chart
    page.wait_for_function("() => document.querySelector('.js-plotly-plot')?._fullLayout?.sliders?.length")
    plot = page.locator(".js-plotly-plot").first
    active = "() => document.querySelector('.js-plotly-plot')._fullLayout.sliders[0].active"
    assert page.evaluate(active) == 0
    plot.locator(".updatemenu-button").first.click()  # ▶ Play
    page.wait_for_function(f"({active})() >= 5", timeout=30_000)
    shot = tmp_path / "trajectories-animation.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)


def test_a_shared_link_opens_the_same_scene_language_and_values(app_url, browser, tmp_path):
    page = open_page(browser, f"{app_url}/trajectories?lang=sr&scene=zbirka-1.3&vR=4.5")
    page.get_by_role("tab", name="Na njivi").click()
    omega_b = 4.5 / 0.32 * 0.09 / 0.03
    expected = f"{omega_b:.4g}".replace(".", ",") + " s⁻¹"
    page.get_by_text(expected).first.wait_for(timeout=30_000)
    shot = tmp_path / "trajectories-field-sr.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)


@pytest.mark.parametrize("size", [(1920, 1080), (1280, 720)], ids=["1920x1080", "1280x720"])
def test_projector_mode_fills_the_screen_without_the_sidebar(app_url, browser, tmp_path, size):
    page = open_page(browser, f"{app_url}/trajectories?lang=sr&scene=zbirka-1.1&present=1", size)
    assert not page.locator("[data-testid='stSidebar']").is_visible()
    font = page.evaluate("() => parseFloat(getComputedStyle(document.documentElement).fontSize)")
    assert font >= 20
    shot = tmp_path / f"projector-{size[0]}x{size[1]}.png"
    page.screenshot(path=str(shot))
    keep(shot)


def test_the_rotor_page_draws_both_polygons(app_url, browser, tmp_path):
    page = open_page(browser, f"{app_url}/rotor_balancing?lang=en&scene=zbirka-7.1")
    page.get_by_text("0.35408 kg").first.wait_for(state="attached", timeout=30_000)  # a grid cell
    shot = tmp_path / "rotor-v-polygon.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)
    page.get_by_role("tab", name="U polygon (forces)").click()
    page.wait_for_timeout(500)
    shot = tmp_path / "rotor-u-polygon.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)
    # the flat charts came with Plotly's basic bundle; the 3D view needs, and loads, gl3d
    bundles = "() => Object.keys(window.__mehanizmiPlotly).map(u => u.split('/').pop().split('-')[1])"
    assert page.evaluate(bundles) == ["basic"]
    page.get_by_role("tab", name="Rotor in 3D").click()
    page.wait_for_function("() => [...document.querySelectorAll('.js-plotly-plot')]"
                           ".some(g => g.offsetParent && g._fullLayout && g._fullLayout.scene"
                           " && g.querySelector('canvas'))", timeout=30_000)
    assert page.evaluate(bundles) == ["basic", "gl3d"]


def test_the_gear_page_draws_the_train_and_its_velocity_diagram(app_url, browser, tmp_path):
    page = open_page(browser, f"{app_url}/planetary_gears?lang=en&scene=zbirka-6.8")
    shot = tmp_path / "gears-schematic.png"
    page.locator(".mehanizmi-plot").first.screenshot(path=str(shot))
    keep(shot)
    page.get_by_role("tab", name="Velocity diagram (Kutzbach)").click()
    page.get_by_text("pitch points").first.wait_for(timeout=30_000)
    wait_idle(page)
    shot = tmp_path / "gears-velocity-diagram.png"
    page.locator(".mehanizmi-plot").first.screenshot(path=str(shot))
    keep(shot)


def test_uploading_a_broken_scene_shows_the_rule_and_the_page_keeps_working(app_url, browser, tmp_path):
    bad = tmp_path / "broken.toml"
    bad.write_text('[frame]\nO = [0, 0]\n[members.2]\npoints = ["O", "A"]\nlength = -0.2\n')
    page = open_page(browser, f"{app_url}/trajectories?lang=en&scene=four-bar-crank-rocker")
    page.get_by_text("About this scene").first.click()
    page.locator("[data-testid='stFileUploader'] input[type='file']").set_input_files(str(bad))
    page.get_by_text("broken.toml: members.2.length must be > 0, got -0.2").wait_for(timeout=30_000)
    assert page.locator("[data-testid='stException']").count() == 0
    good = tmp_path / "mine.toml"
    good.write_text((ROOT / "mechanisms" / "presets" / "slider-crank.toml").read_text()
                    .replace('id = "slider-crank"', 'id = "mine"'))
    page.locator("[data-testid='stFileUploader'] input[type='file']").set_input_files(str(good))
    wait_url(page, r"scene=upload")
    wait_idle(page)
    assert page.locator("[data-testid='stException']").count() == 0


ARROWS = ("i => document.querySelectorAll('.js-plotly-plot')[i].data"
          ".filter(t => t.marker && t.marker.symbol === 'arrow')"
          ".reduce((n, t) => n + t.x.length / 3, 0)")  # figures.arrows: tail, head, gap


# the frame (counted with requestAnimationFrame) in which each Plotly.react starts
COUNT_FRAMES = """() => {
  window.__frame = 0;
  const tick = () => { window.__frame += 1; requestAnimationFrame(tick); };
  requestAnimationFrame(tick);
  window.__drawnInFrame = [];
  const react = window.Plotly.react;
  window.Plotly.react = function (...args) {
    window.__drawnInFrame.push(window.__frame);
    return react.apply(this, args);
  };
}"""


def arrow_count(page, which: int) -> int:
    return page.evaluate(ARROWS, which)


def test_the_book_plans_of_task_2_1_step_by_step(app_url, browser, tmp_path):
    """A shared link opens zbirka-2.1 at the book's scales; stepping back redraws both plans."""
    page = open_page(browser, f"{app_url}/velocity_plans?lang=en&scene=zbirka-2.1", size=(1600, 1000))
    page.wait_for_function("() => document.querySelectorAll('.js-plotly-plot').length >= 3")
    # the scales' inputs (U_L, U_v, …) once the whole page is there (a rerun may still be
    # bringing the rest when the charts are counted)
    page.wait_for_function("() => document.querySelector(\".st-key-num_pos_Uv input\")"
                           "?.value === '0.5'", timeout=30_000)
    full_v, full_a = arrow_count(page, 0), arrow_count(page, 1)
    assert full_a > full_v > 4
    step = page.locator("[data-testid='stSlider'] input[type='range'][aria-label^='Construction']").first
    step.focus()
    step.press("Home")
    wait_url(page, r"step=1")
    wait_idle(page)
    page.wait_for_function(f"n => ({ARROWS})(1) < n", arg=full_a, timeout=30_000)
    step.press("End")
    wait_idle(page)
    page.wait_for_function(f"n => ({ARROWS})(1) == n", arg=full_a, timeout=30_000)
    # the charts were redrawn in place (ui.plot): the same divs, never unmounted
    assert page.evaluate("() => [...document.querySelectorAll('.js-plotly-plot')]"
                         ".every(gd => gd.__marked)") is False
    page.evaluate("() => document.querySelectorAll('.js-plotly-plot')"
                  ".forEach(gd => { gd.__marked = true; gd.querySelector('.main-svg').__marked = true; })")
    page.evaluate(COUNT_FRAMES)
    step.press("Home")
    wait_idle(page)
    page.wait_for_function(f"n => ({ARROWS})(1) < n", arg=full_a, timeout=30_000)
    assert page.evaluate("() => [...document.querySelectorAll('.js-plotly-plot')]"
                         ".every(gd => gd.__marked)")
    # ... by Plotly.react, not from scratch (a changed config made it start with newPlot)
    assert page.evaluate("() => [...document.querySelectorAll('.js-plotly-plot')]"
                         ".every(gd => gd.querySelector('.main-svg').__marked)")
    # one chart per frame, so the first is on the screen before the others are drawn
    frames = page.evaluate("() => window.__drawnInFrame")
    assert len(frames) >= 2 and len(set(frames)) == len(frames), frames
    assert page.locator(".modebar-btn[data-title^='Full screen']").count() == 3
    assert page.locator(".modebar-btn[data-title^='Share chart']").count() == 0  # no cloud
    page.locator(".js-plotly-plot").first.hover()
    page.locator(".modebar-btn[data-title^='Full screen']").first.click()
    page.wait_for_function("() => document.fullscreenElement?.classList.contains('js-plotly-plot')")
    page.evaluate("() => document.exitFullscreen()")
    shot = tmp_path / "velocity-acceleration-plans.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)


def test_the_assur_page_draws_the_special_point_and_its_path(app_url, browser, tmp_path):
    page = open_page(browser, f"{app_url}/assur_groups?lang=en&scene=triad-full-turn",
                     size=(1600, 1000))
    names = page.evaluate("() => document.querySelector('.js-plotly-plot').data.map(t => t.name)")
    assert "S" in names and "path of S" in names and "III(3,4,5,6) RR-RR-PR" in names
    assert page.locator("[data-testid='stException']").count() == 0
    shot = tmp_path / "assur-groups.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)


def test_the_kinetostatics_page_draws_the_polygon_and_shows_three_equal_torques(app_url, browser,
                                                                                tmp_path):
    page = open_page(browser, f"{app_url}/kinetostatics?lang=en", size=(1600, 1100))
    page.get_by_role("tab", name="Force polygons").click()
    polygon = ("() => [...document.querySelectorAll('.js-plotly-plot')].flatMap(p => p.data)"
               ".filter(t => (t.mode || '').includes('text')).flatMap(t => [...t.text])")
    page.wait_for_function(f"() => ({polygon})().includes('F<sub>45</sub>')", timeout=30_000)
    # the three driving torques agree with the lecture's 4.53 N·m once the rerun that brings
    # the metrics is done (one read between reruns once saw another instant's values)
    metrics = "() => [...document.querySelectorAll(\"[data-testid='stMetricValue']\")].map(e => e.innerText)"
    page.wait_for_function(f"() => {{ const v = ({metrics})(); return v.length >= 3 && "
                           "v[0] === v[1] && v[1] === v[2] && v[0].startsWith('4.53'); }",
                           timeout=30_000)
    labels = page.evaluate(polygon)
    assert {"F<sub>5</sub>", "F<sub>45</sub>", "F<sub>16</sub>"} <= set(labels)
    assert page.locator("[data-testid='stException']").count() == 0
    shot = tmp_path / "kinetostatics-polygon.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)


def test_the_graphical_kinetostatics_steps_in_the_browser(app_url, browser, tmp_path):
    """Task 5.1 at step 2 of its construction (from the link): the group's polygon closes with
    F_45^n and F_16; the step slider moves to the next equation."""
    page = open_page(browser, f"{app_url}/kinetostatics?lang=en&scene=zbirka-5.1&fstep=2",
                     size=(1600, 1800))
    page.get_by_role("tab", name="Step by step").click()
    labels = ("() => [...document.querySelectorAll('.js-plotly-plot')].flatMap(p => p.data)"
              ".filter(t => (t.mode || '').includes('text')).flatMap(t => [...t.text])")
    page.wait_for_function(f"() => ({labels})().includes('F<sub>45</sub><sup>n</sup>')",
                           timeout=30_000)
    assert "F<sub>16</sub>" in page.evaluate(labels)
    assert page.get_by_text("2/10").count() == 1
    assert page.locator("[data-testid='stException']").count() == 0
    shot = tmp_path / "kinetostatics-steps.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)


def test_a_table_downloads_as_csv_when_asked(app_url, browser, tmp_path):
    """The CSV is written when the button is pressed (deferred), and holds the table."""
    page = open_page(browser, f"{app_url}/kinetostatics?lang=en", size=(1600, 1100))
    with page.expect_download(timeout=30_000) as download:
        page.get_by_role("button", name="Download the table (CSV)").first.click()
    text = Path(download.value.path()).read_text(encoding="utf-8")
    assert text.splitlines()[0].startswith("F_pq,") and "F_45" in text


def test_the_scene_downloads_at_the_angle_the_page_shows(app_url, browser):
    """The scene's TOML is written when its button is pressed (deferred, as the tables'), at
    the φ₂ the page was moved to, and reads back as that scene."""
    from mechanisms.loader import parse_scene

    page = open_page(browser, f"{app_url}/velocity_plans?lang=en&scene=zbirka-2.1&at=75",
                     size=(1600, 1100))
    with page.expect_download(timeout=30_000) as download:
        page.get_by_role("button", name="Download this scene (TOML)").click()
    assert download.value.suggested_filename == "zbirka-2.1.toml"
    scene = parse_scene(Path(download.value.path()).read_bytes())
    assert scene.id == "zbirka-2.1" and math.isclose(math.degrees(scene.driver.at), 75.0)


@pytest.mark.parametrize("fmt, start", [("SVG", "<svg"), ("PNG", "\x89PNG")])
def test_a_figure_saves_as_svg_or_png_from_its_toolbar(app_url, browser, fmt, start):
    """Each chart's toolbar has one button per format (Plotly's camera, which
    saves one format chosen in advance, is gone); the file is named after scene and chart."""
    page = open_page(browser, f"{app_url}/velocity_plans?lang=en&scene=zbirka-2.1", size=(1600, 1000))
    page.wait_for_function("() => document.querySelectorAll('.js-plotly-plot').length >= 3")
    assert page.locator(f".modebar-btn[data-title^='Save as {fmt}']").count() == 3
    assert page.locator(".modebar-btn[data-title^='Download plot']").count() == 0
    page.locator(".js-plotly-plot").first.hover()  # the toolbar shows on hover
    with page.expect_download(timeout=30_000) as download:
        page.locator(f".modebar-btn[data-title^='Save as {fmt}']").first.click()
    assert download.value.suggested_filename == f"zbirka-2.1-velocity-plan.{fmt.lower()}"
    data = Path(download.value.path()).read_bytes()
    assert data.decode("latin-1").startswith(start)


def crank_letters(page) -> dict[str, complex]:
    """Where the plans page's mechanism chart (the last chart) writes each point's letter."""
    traces = page.evaluate("() => { const g = [...document.querySelectorAll('.mehanizmi-plot')].pop();"
                           " return g.data.filter(t => t.mode === 'text')"
                           ".map(t => [Array.from(t.text), Array.from(t.x), Array.from(t.y)]); }")
    return {name: complex(x, y) for text, xs, ys in traces for name, x, y in zip(text, xs, ys)}


# the title the last chart (the mechanism) shows, "" until Plotly has drawn it
LAST_TITLE = ("((([...document.querySelectorAll('.mehanizmi-plot')].pop().layout || {})"
              ".title || {}).text || '')")
TABLE_CELLS = ("() => [...document.querySelectorAll('[data-testid=stDataFrame] table td')]"
               ".map(td => td.textContent).join('|')")
GRIDS_DRAWN = ("() => { const grids = [...document.querySelectorAll('[data-testid=stDataFrame]')];"
               " return grids.length > 0 && grids.every(g => g.querySelector('table td')); }")


def scrub(page, index: int, release: bool) -> None:
    page.evaluate("([k, release]) => { const r = document.querySelector('.mehanizmi-crank input');"
                  " r.value = String(k); r.dispatchEvent(new Event('input'));"
                  " if (release) r.dispatchEvent(new Event('change')); }", [index, release])


def test_scrubbing_phi2_redraws_the_plans_locally_and_letting_go_updates_the_tables(
        app_url, browser, tmp_path):
    """The first touch brings the frames; scrubbing to 150° then moves every chart without a
    rerun (the letters sit where the solver puts the joints at 150°, the link says at=150);
    letting go reruns once, and the tables follow. Another scene replaces the frames."""
    import math

    from mechanisms import load_preset
    from solvers.kinematics import solve

    page = open_page(browser, f"{app_url}/velocity_plans?lang=en&scene=four-bar-crank-rocker")
    page.locator(".mehanizmi-crank input").first.dispatch_event("pointerdown")
    loaded = ("() => [...document.querySelectorAll('.mehanizmi-plot')]"
              ".every(g => g.__crank && g.__crank.spec.turn)")
    page.wait_for_function(loaded, timeout=30_000)
    wait_idle(page)
    # a table's grid is drawn by a script of its own, which may still be loading: every grid
    # (on a fast machine the step table's was read before the members table had drawn its own)
    page.wait_for_function(GRIDS_DRAWN, timeout=30_000)
    table = page.evaluate(TABLE_CELLS)
    scrub(page, 30, release=False)  # 30 frames of 5°
    page.wait_for_function(f"() => {LAST_TITLE}.includes('150')", timeout=5_000)  # drawn last
    motion = solve(load_preset("four-bar-crank-rocker"), math.radians(150.0))
    letters = crank_letters(page)
    for name in ("A", "B", "E"):
        assert abs(letters[name] - motion.points[name].z[0]) < 1e-4  # 5 digits sent
    assert "at=150" in page.url
    assert page.evaluate(TABLE_CELLS) == table  # no rerun yet
    assert "30.00" in page.locator("[data-testid='stSlider']").first.inner_text()
    shot = tmp_path / "plans-scrubbed.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)
    scrub(page, 30, release=True)
    page.wait_for_function(f"t => ({TABLE_CELLS})() !== t", arg=table, timeout=30_000)
    wait_idle(page)
    assert "150.00" in page.locator("[data-testid='stSlider']").first.inner_text()

    page.goto(f"{app_url}/velocity_plans?lang=en&scene=analitika-2.1")  # another scene
    settle(page)
    page.wait_for_selector(".mehanizmi-crank input", timeout=30_000)
    page.locator(".mehanizmi-crank input").first.dispatch_event("pointerdown")
    page.wait_for_function(loaded, timeout=30_000)
    scrub(page, 6, release=False)
    page.wait_for_function(f"() => {LAST_TITLE}.includes('= 30°')", timeout=5_000)
    motion = solve(load_preset("analitika-2.1"), math.radians(30.0))
    assert abs(crank_letters(page)["C"] - motion.points["C"].z[0]) < 1e-4
    scrub(page, 28, release=False)  # 140°: this four-bar cannot be assembled there
    label = page.locator(".mehanizmi-crank span").first
    assert label.inner_text().endswith("✕")
    assert label.get_attribute("title").startswith("The mechanism cannot be assembled")


# the first point of E's path on the trajectories chart, as the browser holds it
E_START = ("() => { const g = document.querySelector('.mehanizmi-plot');"
           " const t = g.data.find(t => (t.name || '').includes('of E'));"
           " return [+t.x[0], +t.y[0]]; }")
METRICS = "() => [...document.querySelectorAll('[data-testid=stMetric]')].map(m => m.innerText).join('|')"


def scrubbed_to(page, key: str, k: int, where: str) -> tuple[str, list, list]:
    """Once the chart's control has the frames of ``key``, scrub to frame k without letting
    go: the readouts before, the control's values, and ``where`` (a point the chart draws,
    as JavaScript reads it) once it has moved."""
    page.wait_for_function("k => { const c = document.querySelector('.mehanizmi-plot').__crank;"
                           " return c.spec.turn && c.spec.key === k; }", arg=key, timeout=30_000)
    wait_idle(page)
    readouts, before = page.evaluate(METRICS), page.evaluate(where)
    values = page.evaluate("() => document.querySelector('.mehanizmi-plot').__crank.spec.values")
    scrub(page, k, release=False)
    page.wait_for_function(f"s => ({where})()[0] !== s[0]", arg=before, timeout=5_000)
    return readouts, values, page.evaluate(where)


def test_a_link_s_length_moves_the_paths_in_the_browser_and_letting_go_sets_its_slider(
        app_url, browser, tmp_path):
    """Picking member 3 in the chart's list brings its frames; scrubbing moves E's path to
    where the solver puts it with that length, without a rerun (the readouts stay, the link
    says L3=…); letting go reruns once: the page's own slider and the readouts follow."""
    from mechanisms import load_preset
    from solvers import solve
    from solvers.paths import cycle_values

    page = open_page(browser, f"{app_url}/trajectories?lang=en&scene=four-bar-crank-rocker")
    page.locator(".mehanizmi-crank select").select_option("L3")
    readouts, values, (x, y) = scrubbed_to(page, "L3", 20, E_START)
    longer = load_preset("four-bar-crank-rocker").with_(lengths={3: values[20]})
    e = solve(longer, cycle_values(longer, 12)).points["E"].z[0]
    assert abs(complex(x, y) - e) < 1e-4  # 5 digits sent
    assert f"L3={values[20]}" in page.url
    assert page.locator(".mehanizmi-crank span").first.inner_text() == f"AB = {values[20]} m"
    assert page.evaluate(METRICS) == readouts  # no rerun yet
    shot = tmp_path / "trajectories-length-scrubbed.png"
    page.screenshot(path=str(shot))
    keep(shot)
    scrub(page, 20, release=True)
    page.wait_for_function(f"r => ({METRICS})() !== r", arg=readouts, timeout=30_000)
    wait_idle(page)
    page.get_by_text("Link lengths", exact=True).click()
    slider = page.locator("[data-testid='stSlider'] input[type='range'][aria-label*='(member 3)']")
    assert float(slider.input_value()) == values[20]


# every draw of the page's first chart: whether it was an arrow key's neighbour (ui/plot.js
# marks the chart before drawing one), its numbers once drawn, and its title
DRAWS = """() => { window.__draws = []; const react = window.Plotly.react;
  window.Plotly.react = function (gd, ...rest) {
    const previewed = Boolean(gd.__previewed);
    return react.call(this, gd, ...rest).then((out) => {
      if (gd === document.querySelector('.mehanizmi-plot')) window.__draws.push({ previewed,
        data: gd._fullData.map((t) => [Array.from(t.x || []), Array.from(t.y || [])]),
        title: ((gd.layout.title || {}).text) || '' });
      return out; }); }; }"""
NEAR_OF = "() => (document.querySelector('.mehanizmi-plot').__crank.spec.near || {}).key || null"


def same_numbers(got: list, want: list) -> bool:
    """Two charts' traces alike to the 5 digits a frame is sent with."""
    if len(got) != len(want):
        return False
    for g_trace, w_trace in zip(got, want):
        for g, w in zip(g_trace, w_trace):
            scale = max((abs(v) for v in w if v is not None), default=1.0)
            if len(g) != len(w) or any((a is None) != (b is None) or (
                    a is not None and abs(a - b) > 1e-4 * scale) for a, b in zip(g, w)):
                return False
    return True


@pytest.mark.parametrize("path, label, expander", [
    ("velocity_plans?lang=en", "Crank angle", None),
    ("velocity_plans?lang=en", "ω₂", None),
    ("trajectories?lang=en&scene=four-bar-crank-rocker", "(member 3)", "Link lengths")])
def test_an_arrow_key_on_a_followed_slider_draws_the_next_figure_before_the_rerun(
        app_url, browser, path, label, expander):
    """The slider's focus brings the chart's neighbours; an arrow key draws the one it moves
    to at once (the draw marked as such), and the rerun's own figure, drawn after it, is
    the same to the 5 digits sent. Leaving the slider tells the server: no more neighbours."""
    page = open_page(browser, f"{app_url}/{path}")
    if expander:
        page.get_by_text(expander, exact=True).click()
    slider = page.locator(f"[data-testid='stSlider'] input[type='range'][aria-label*='{label}']")
    slider.first.focus()
    page.wait_for_function(f"() => ({NEAR_OF})() !== null", timeout=30_000)
    wait_idle(page)
    before = page.evaluate("() => document.querySelector('.mehanizmi-plot')._fullData"
                           ".map((t) => [Array.from(t.x || []), Array.from(t.y || [])])")
    page.evaluate(DRAWS)
    for key in ("ArrowRight", "ArrowLeft"):
        page.evaluate("() => { window.__draws = []; }")
        page.keyboard.press(key)
        page.wait_for_function("() => window.__draws.some((d) => !d.previewed)", timeout=30_000)
        wait_idle(page)
        draws = page.evaluate("() => window.__draws")
        assert draws[0]["previewed"]  # the neighbour first, with no rerun in between
        assert same_numbers(draws[0]["data"], draws[-1]["data"]) and not draws[-1]["previewed"]
        assert draws[0]["title"] == draws[-1]["title"]
        assert same_numbers(draws[0]["data"], before) == (key == "ArrowLeft")  # back again
    page.locator("[data-testid='stSidebar'] [data-testid='stSelectbox']").first.click()
    page.keyboard.press("Escape")
    page.wait_for_function(f"() => ({NEAR_OF})() === null", timeout=30_000)


# every frame the chart's control shows, in order, recorded from the page's own frames
SHOWN = """() => { const c = document.querySelector('.mehanizmi-plot').__crank; window.__shown = [];
  const poll = () => { const s = window.__shown;
    if (s[s.length - 1] !== c.index) s.push(c.index);
    requestAnimationFrame(poll); };
  poll(); }"""


def test_a_played_length_goes_back_and_forth_between_its_slider_s_ends(app_url, browser):
    """Play on the length control runs to twice the length and comes back down, frame by
    frame, instead of jumping to a quarter of it (a turn of φ₂ goes round)."""
    page = open_page(browser, f"{app_url}/trajectories?lang=en&scene=four-bar-crank-rocker")
    page.evaluate(SHOWN)
    page.locator(".mehanizmi-crank button[aria-label='Play']").click()
    last = page.evaluate("() => document.querySelector('.mehanizmi-plot').__crank.spec.values"
                         ".length - 1")
    page.wait_for_function("n => { const s = window.__shown, i = s.indexOf(n);"
                           " return i >= 0 && s.length > i + 2; }", arg=last, timeout=30_000)
    shown = page.evaluate("() => window.__shown")
    top = shown.index(last)  # (a frame drawn slowly may let the next tick pass unrecorded)
    after = shown[top + 1:top + 3]
    assert last - 3 <= after[0] < last and after[1] < after[0]  # back down, not round to the start


# the end of the longest line on the chart (the tine's path in the field), as the browser holds it
FIELD_END = ("() => { const g = document.querySelector('.mehanizmi-plot');"
             " const t = g._fullData.reduce((a, b) => (b.x.length > a.x.length ? b : a));"
             " return [+t.x[t.x.length - 1], +t.y[t.y.length - 1]]; }")


def test_the_chain_drive_moves_the_tine_s_field_path_in_the_browser(app_url, browser, tmp_path):
    """On a Serbian page: touching the field chart's control brings R_t's frames; scrubbing
    moves the tine's path to where the solver puts it with that wheel, without a rerun (the
    link says Rt=…, the value has a decimal comma); letting go reruns once and ω_b follows."""
    from dataclasses import replace

    from mechanisms import load_preset
    from solvers import solve
    from solvers.paths import cycle_values, field_path

    page = open_page(browser, f"{app_url}/trajectories?lang=sr&scene=zbirka-1.3")
    page.get_by_role("tab", name="Na njivi").click()
    page.wait_for_selector(".mehanizmi-crank input", timeout=30_000)
    page.locator(".mehanizmi-crank input").first.dispatch_event("pointerdown")
    readouts, values, (x, y) = scrubbed_to(page, "Rt", 30, FIELD_END)
    tedder = load_preset("zbirka-1.3")
    wheel = tedder.with_(travel=replace(tedder.travel, wheel_radius=values[30]))
    point = [p for p in wheel.point_names if p not in wheel.frame][-1]
    _, path = field_path(solve(wheel, cycle_values(wheel, 360)), wheel.travel, point, 3)
    assert abs(complex(x, y) - path[-1]) < 1e-4 * abs(path[-1])  # 5 digits sent
    assert f"Rt={values[30]}" in page.url
    assert page.locator(".mehanizmi-crank span").first.inner_text() == (
        f"R_t = {values[30]} m".replace(".", ","))
    assert page.evaluate(METRICS) == readouts  # no rerun yet
    page.locator(".mehanizmi-crank").scroll_into_view_if_needed()
    shot = tmp_path / "trajectories-field-scrubbed-sr.png"
    page.screenshot(path=str(shot))
    keep(shot)
    scrub(page, 30, release=True)
    page.wait_for_function(f"r => ({METRICS})() !== r", arg=readouts, timeout=30_000)
    omega_b = tedder.travel.speed / values[30] * tedder.travel.sprocket_wheel / (
        tedder.travel.sprocket_crank)
    assert f"{omega_b:.4g}".replace(".", ",") + " s⁻¹" in page.evaluate(METRICS)


def test_scrubbing_phi2_moves_the_loads_and_the_force_polygon_in_the_browser(app_url, browser,
                                                                            tmp_path):
    """The kinetostatics page's charts carry φ₂ frames too: the free body and its polygon
    move together, each title unchanged, and the link follows."""
    page = open_page(browser, f"{app_url}/kinetostatics?lang=en")
    page.get_by_role("tab", name="Force polygons").click()
    page.wait_for_function("() => document.querySelectorAll('.mehanizmi-crank').length === 2"
                           " && document.querySelectorAll('.js-plotly-plot').length === 2",
                           timeout=30_000)  # the free body and the polygon
    before = [plot_x(page, 0), plot_x(page, 1)]
    page.locator(".mehanizmi-crank input").first.dispatch_event("pointerdown")
    page.wait_for_function("() => [...document.querySelectorAll('.mehanizmi-plot')]"
                           ".every(g => g.__crank && g.__crank.spec.turn)", timeout=30_000)
    wait_idle(page)
    scrub(page, 10, release=False)  # 50°, the other chart follows its group
    page.wait_for_function("b => JSON.stringify([0, 1].map(i => document.querySelectorAll("
                           "'.js-plotly-plot')[i].data.map(t => Array.from(t.x || [])))) !== b",
                           arg=json.dumps(before), timeout=5_000)
    assert all(lbl.startswith("φ₂ = 50°") for lbl in page.locator(".mehanizmi-crank span").all_inner_texts())
    assert "at=50" in page.url
    shot = tmp_path / "forces-scrubbed.png"
    page.screenshot(path=str(shot), full_page=True)
    keep(shot)


def test_a_desktop_s_narrow_chart_keeps_its_title_where_plotly_puts_it(app_url, browser):
    """Only a phone's touch screen shows Plotly's toolbar at all times (ui/plot.js moves a
    phone chart's title under it): on a desktop the plans side by side, narrower than a
    phone, keep their titles at the top, the plot's room unchanged."""
    page = open_page(browser, f"{app_url}/velocity_plans?lang=en")
    narrow = page.evaluate("() => [...document.querySelectorAll('.js-plotly-plot')]"
                           ".filter(gd => gd.clientWidth <= 640)"
                           ".map(gd => gd._fullLayout.title.yanchor)")
    assert narrow and all(anchor != "top" for anchor in narrow), narrow
