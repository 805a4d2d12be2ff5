"""In a real browser (Debian's chromium through Playwright): a slider moved with the arrow
key → the page's figure redrawn, median of 20 changes per page, against a server on this
machine. This is what a user waits for: the rerun, the network, and Plotly drawing. Also
φ₂ (on the trajectories page a link's length) scrubbed in the browser (ui/crank.py), and
each page opened in a fresh browser context, the pages and the floor in turn: navigation
→ first chart painted, its ratio to the floor's, and the bytes transferred by then.

    .venv/bin/python bench/browser.py           # print the table
    .venv/bin/python bench/browser.py --write   # and regenerate its part of docs/performance.md
    .venv/bin/python bench/browser.py --phone   # only the phone rows (iPhone 13, 10 Mbit/s)
"""

import asyncio
import statistics
import sys
import tempfile
from pathlib import Path

from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from bench.publish import publish  # noqa: E402
from deploy.client import free_port, start_server, wait_ready  # noqa: E402

CHANGES = 20
# page, part of the label of a slider that changes the page's first figure (English page),
# and the expander that holds it; the gear and rotor pages are driven by number inputs and
# tables instead of sliders. ω₂ reruns the whole page (φ₂ and a length only their fragment);
# task 5.3's members have inertia, so its loads grow with ω₂.
PAGES = [
    ("trajectories", "(member 2)", "Link lengths"),
    ("velocity_plans", "Crank angle", None),
    ("assur_groups", "Crank angle", None),
    ("kinetostatics", "Crank angle", None),
    ("velocity_plans", "ω₂", None),
    ("kinetostatics?scene=zbirka-5.3", "ω₂", None),
]
# Timed in the page, so Playwright's round trips are not counted: the key press (the event's
# own time: the charts' script handles an arrow key before any listener added here runs,
# ui/plot.js), the frame that paints the first chart's new data, and the frame that paints
# the last chart the change redrew (Plotly.react wrapped).
WATCH = """() => {
  document.addEventListener('keydown', (e) => { window.__key = e.timeStamp; }, true);
  const react = window.Plotly.react;
  window.Plotly.react = function (...args) {
    return react.apply(this, args).then((gd) => {
      requestAnimationFrame(() => { window.__allDrawn = performance.now(); });
      return gd;
    });
  };
}"""
# a signature of the first chart's data (typed arrays included): it changes when the
# rerun's figure (or an arrow key's neighbour, ui/plot.js) is drawn
SIGNATURE = """(() => { const gd = document.querySelector('.js-plotly-plot');
  if (!gd || !gd.data || !gd._fullLayout) return null;
  const s = JSON.stringify(gd.data.map(t => [t.x, t.y]));
  return s.length + s.slice(0, 300) + s.slice(-300); })()"""
# checked in every frame (requestAnimationFrame) by the page itself from before the key
# press, so it first sees the new data in the frame that paints it: polled from Playwright,
# the first look came a round trip after the press, later than a figure drawn in the
# browser at once
MARK = f"""() => {{
  window.__before = {SIGNATURE};
  window.__painted = undefined;
  const look = () => {{
    if ({SIGNATURE} !== window.__before) window.__painted = performance.now();
    else requestAnimationFrame(look);
  }};
  requestAnimationFrame(look);
}}"""
PAINTED = "() => window.__painted !== undefined"


def measure(page, url: str, label: str, expander: str | None) -> tuple[float, float]:
    """Medians (ms) from the key press to the frame that paints the first chart's new figure,
    and to the frame that paints the last chart the change redrew."""
    page.goto(url)
    page.wait_for_selector(".js-plotly-plot", timeout=60_000)
    page.wait_for_timeout(1500)
    page.evaluate(WATCH)
    if expander:
        page.get_by_text(expander, exact=True).click()
    thumb = page.locator(f"[data-testid='stSlider'] input[type='range'][aria-label*='{label}']").first
    first, last = [], []
    for _ in range(CHANGES):
        page.evaluate(MARK)
        thumb.focus()
        page.keyboard.press("ArrowRight")
        page.wait_for_function(PAINTED, timeout=30_000)
        page.wait_for_timeout(700)  # the page finishes its rerun and draws its other charts
        key, painted, drawn = page.evaluate("() => [window.__key, window.__painted, window.__allDrawn]")
        first.append(painted - key)
        last.append(drawn - key)
    return statistics.median(first), statistics.median(last)


# φ₂ scrubbed in the browser (ui/crank.py): from the slider's input event to the frame that
# paints the first chart redrawn (the one on screen), and to the one after the last chart.
# The first chart's last figure is kept (window.__scrubbed) for its floor (FLOOR_DRAW).
SCRUB = """([k, charts]) => new Promise((resolve) => {
  const react = window.Plotly.react;
  const start = performance.now();
  let drawn = 0, first = null;
  window.Plotly.react = function (...args) {
    const out = react.apply(this, args);
    drawn += 1;
    if (drawn === 1) {
      window.__scrubbed = args;
      requestAnimationFrame(() => { first = performance.now() - start; });
    }
    if (drawn === charts) requestAnimationFrame(() => requestAnimationFrame(() => {
      window.Plotly.react = react;
      resolve([first, performance.now() - start]);
    }));
    return out;
  };
  const range = document.querySelector('.mehanizmi-crank input');
  range.value = String(k % (Number(range.max) + 1));
  range.dispatchEvent(new Event('input'));
})"""
# The scrub's floor (issue 83): bare Plotly drawing the same figure at the chart's size —
# from Plotly.react to the frame that paints it, as SCRUB times the first chart — right
# after each step, so the machine's speed (it moves by a third within a run, and by more
# in a slow hour) moves a step and its floor alike. Drawn twice: in a blank page of its
# own, and in bare Streamlit's page (the floor app's, a div of its own under its small
# chart). The second is the scrub's floor, as bare Streamlit's page is the first chart's:
# in any Streamlit page JavaScript's array copies (slice, concat: Plotly's walk over a
# trace's attributes is made of them) run about six times slower than in a blank page
# (docs/performance.md), and no page of the app escapes that. What the scrub adds to it is
# ours: the control, the frame's figure assembled, the page around the chart.
SCRUBBED_FIGURE = """() => { const [gd, figure] = window.__scrubbed;
  return JSON.stringify({data: figure.data,
                         layout: {...figure.layout, width: gd.clientWidth, height: gd.clientHeight}},
    (key, value) => ArrayBuffer.isView(value) ? Array.from(value) : value); }"""
BUNDLE = ("() => new URL(Object.keys(window.__mehanizmiPlotly)[0], document.baseURI).href"
          )  # the bundle the page's charts were drawn with
FLOOR_DRAW = """(text) => new Promise((resolve) => {
  const gd = document.getElementById('gd');
  const figure = JSON.parse(text);
  if (!gd.data) return Plotly.newPlot(gd, figure).then(() => resolve(null));
  const start = performance.now();
  Plotly.react(gd, figure);
  requestAnimationFrame(() => resolve(performance.now() - start));
})"""
# a div for FLOOR_DRAW in bare Streamlit's page, under its chart, and the page's bundle
# loaded as a plain script (a Plotly of its own: its label caches as cold as the scrub's)
IN_STREAMLIT = """(bundle) => new Promise((resolve) => {
  const gd = document.createElement('div');
  gd.id = 'gd';
  document.querySelector('[data-testid="stMainBlockContainer"]').appendChild(gd);
  const script = document.createElement('script');
  script.src = bundle;
  script.onload = resolve;
  document.head.appendChild(script);
})"""


def floor_pages(page, floor_url: str, browser) -> list:
    """The scrub's two floors, ready to draw (``FLOOR_DRAW``): a blank page with the bundle
    ``page``'s charts were drawn with, and bare Streamlit's page (``floor_url``), both in
    ``browser``, not the scrubbed page's: opened beside it in its own browser, they held
    its later charts back by about a second a step (ui/plot.js draws one chart a frame;
    "→ all its charts" 1,029–3,065 ms against 71–195 in the same hour)."""
    bundle = page.evaluate(BUNDLE)
    blank, bare = browser.new_page(), browser.new_page()
    blank.set_content(f'<script src="{bundle}"></script><div id="gd"></div>')
    bare.goto(floor_url)
    bare.wait_for_selector(".js-plotly-plot", timeout=60_000)
    bare.wait_for_timeout(1000)
    bare.evaluate(IN_STREAMLIT, bundle)
    for other in (blank, bare):
        other.wait_for_function("() => window.Plotly")
    return [blank, bare]


LOADED = ("() => [...document.querySelectorAll('.mehanizmi-plot')]"
          ".every(g => g.__crank && g.__crank.spec.turn)")
FRAME_BYTES = ("() => [...document.querySelectorAll('.mehanizmi-plot')]"
               ".reduce((n, g) => n + JSON.stringify(g.__crank.spec.turn).length, 0)")
# the pages whose charts carry φ₂ frames, on a scene that turns all the way round, and the
# trajectories page, whose paths chart moves a link's length (member 2's: the control's
# first) and whose tedder's field chart moves the chain drive (R_t first); the tab to open
SCRUBBED = [("velocity_plans", None), ("assur_groups?scene=triad-full-turn", None),
            ("kinetostatics", None), ("trajectories", None),
            ("trajectories?scene=zbirka-1.3", "In the field")]


def scrub(page, url: str, tab: str | None, floor_url: str, browser
          ) -> tuple[float, float, tuple[float, float], float, float]:
    """Medians (ms) of a φ₂ (or length, or drive) step redrawn in the browser, to the first
    chart painted and to all; of Plotly's own redraw of the first chart's same figure after
    each step, in a blank page and in bare Streamlit's (``floor_pages``: the scrub's
    floor); the ms from the first touch of the control to the frames there (one rerun); and
    the frames' size in kB."""
    page.goto(url)
    if tab:
        page.get_by_role("tab", name=tab).click(timeout=60_000)
    page.wait_for_selector(".mehanizmi-crank input", timeout=60_000)
    page.wait_for_timeout(1500)
    start = page.evaluate("() => performance.now()")
    page.locator(".mehanizmi-crank input").first.dispatch_event("pointerdown")
    page.wait_for_function(LOADED, timeout=60_000, polling="raf")
    first = page.evaluate("() => performance.now()") - start
    size = page.evaluate(FRAME_BYTES) / 1e3  # as sent: Plotly decodes typed arrays in place
    charts = page.locator(".mehanizmi-crank").count()
    floors = floor_pages(page, floor_url, browser)
    times, floor_times = [], []
    for k in range(CHANGES + 1):  # step 0 draws each floor's first figure (Plotly.newPlot)
        times.append(page.evaluate(SCRUB, [k, charts]))
        figure = page.evaluate(SCRUBBED_FIGURE)
        floor_times.append([other.evaluate(FLOOR_DRAW, figure) for other in floors])
    for other in floors:
        other.close()
    times, floor_times = times[1:], floor_times[1:]
    plotly = tuple(statistics.median(t[i] for t in floor_times) for i in range(2))
    return (statistics.median(t[0] for t in times), statistics.median(t[1] for t in times),
            plotly, first, size)


# Navigation → first chart painted, in a fresh browser context each time (nothing cached):
# polled every frame from the page's own start (performance.now() counts from navigation)
VISITS = 7
FIRST_PAINT = """(() => {
  const poll = () => {
    const gd = document.querySelector('.js-plotly-plot');
    if (gd && gd._fullLayout && gd.data && gd.data.length) window.__firstChart = performance.now();
    else requestAnimationFrame(poll);
  };
  requestAnimationFrame(poll);
})();"""
BYTES = ("() => [...performance.getEntriesByType('navigation'), "
         "...performance.getEntriesByType('resource')].reduce((n, r) => n + r.transferSize, 0)")
FLOOR = "(the floor: sidebar, navigation and one small chart, `bench/floor_chart_app.py`)"
SLIDER_FLOOR = ("(the floor: one length slider redrawing the trajectories page's figure, nothing "
                "else on the page, `bench/floor_chart_app.py?floor=slider`)")
OPENED = ["trajectories", "velocity_plans", "assur_groups", "kinetostatics", "planetary_gears",
          "rotor_balancing", "builder"]  # the pages that open with a chart


def in_turn(urls: dict[str, str], visit) -> dict[str, tuple[float, ...]]:
    """Per page, the medians over VISITS rounds of what ``visit(url)`` measures (a tuple of
    numbers, from a fresh context each time). Each round opens every url once, in turn:
    the machine's speed moves by a third within a run, and in turn it moves the pages and
    the floor alike (measured one page after another, the floor last, the ratios swung by
    0.1–0.2 from run to run)."""
    seen: dict[str, list[tuple[float, ...]]] = {name: [] for name in urls}
    for _ in range(VISITS):
        for name, url in urls.items():
            seen[name].append(visit(url))
    return {name: tuple(statistics.median(column) for column in zip(*visits))
            for name, visits in seen.items()}


def first_paints(browser, urls: dict[str, str]) -> dict[str, tuple[float, ...]]:
    """Per page (``in_turn``): ms from navigation to the first chart painted, and kB
    transferred by then."""
    def visit(url: str) -> tuple[float, float]:
        context = browser.new_context(viewport={"width": 1400, "height": 900})
        context.add_init_script(FIRST_PAINT)
        page = context.new_page()
        page.goto(url, wait_until="commit")
        page.wait_for_function("() => window.__firstChart", timeout=60_000)
        painted = (page.evaluate("() => window.__firstChart"), page.evaluate(BYTES) / 1e3)
        context.close()
        return painted

    return in_turn(urls, visit)


# A phone: iPhone 13 (390 × 664 CSS px, touch) over Chrome's emulated 10 Mbit/s, 40 ms link
PHONE_LINK = {"offline": False, "latency": 40, "downloadThroughput": 10e6 / 8,
              "uploadThroughput": 5e6 / 8}
CHART_TOP = """() => { const chart = document.querySelector('.main-svg');
  const main = document.querySelector('[data-testid="stMain"]');
  return chart.getBoundingClientRect().top + (main ? main.scrollTop : 0); }"""


def phone_paints(browser, device: dict, urls: dict[str, str]) -> dict[str, tuple[float, ...]]:
    """Per page (``in_turn``), a fresh phone context on the slow link: ms to the first chart
    painted, kB on the wire by then (encoded: what a gzip saves counts), and where the chart
    starts (CSS px from the page's top; the screen is 664 high)."""
    def visit(url: str) -> tuple[float, float, float]:
        context = browser.new_context(**device)
        context.add_init_script(FIRST_PAINT)
        page = context.new_page()
        cdp = context.new_cdp_session(page)
        cdp.send("Network.enable")
        cdp.send("Network.emulateNetworkConditions", PHONE_LINK)
        wire = []
        cdp.on("Network.loadingFinished", lambda e: wire.append(e["encodedDataLength"]))
        page.goto(url, wait_until="commit")
        page.wait_for_function("() => window.__firstChart", timeout=120_000)
        painted = (page.evaluate("() => window.__firstChart"), sum(wire) / 1e3,
                   page.evaluate(CHART_TOP))
        context.close()
        return painted

    return in_turn(urls, visit)


def launch(p):
    """Debian's chromium, headless, as the browser tests launch it."""
    return p.chromium.launch(executable_path="/usr/bin/chromium", headless=True,
                             args=["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"])


def phone_rows(p, port: int, floor_port: int) -> list[str]:
    browser = launch(p)
    device = {k: v for k, v in p.devices["iPhone 13"].items() if k != "default_browser_type"}
    urls = {name: f"http://127.0.0.1:{port}/{name}?lang=sr" for name in OPENED}
    urls[FLOOR] = f"http://127.0.0.1:{floor_port}/?lang=sr"
    painted = phone_paints(browser, device, urls)
    browser.close()
    return ["", f"| page, on a phone (iPhone 13, 10 Mbit/s, 40 ms; Serbian) | navigation → first "
            f"chart painted, ms (median of {VISITS}, the pages and the floor in turn) | ÷ the "
            "floor | on the wire by then, kB | the chart starts at, px (screen: 664) |",
            "|---|---:|---:|---:|---:|"] + [
        f"| {name} | {ms:.0f} | {ms / painted[FLOOR][0]:.2f}× | {kb:.0f} | {top:.0f} |"
        for name, (ms, kb, top) in painted.items()]


def servers() -> tuple[int, int, list]:
    """The app and the floor app (bench/floor_chart_app.py) served: their ports, processes."""
    port, floor_port = free_port(), free_port()
    while floor_port == port:
        floor_port = free_port()
    running = [start_server(port), start_server(floor_port, ROOT / "bench" / "floor_chart_app.py")]
    try:
        for ready in (port, floor_port):
            asyncio.run(wait_ready(f"ws://127.0.0.1:{ready}/_stcore/stream"))
    except BaseException:
        for server in running:
            server.terminate()
        raise
    return port, floor_port, running


def phone_table() -> str:
    """The phone rows alone (``--phone``)."""
    port, floor_port, running = servers()
    try:
        with sync_playwright() as p:
            return "\n".join(phone_rows(p, port, floor_port)[1:])
    finally:
        for server in running:
            server.terminate()
            server.wait(timeout=30)


def table() -> str:
    port, floor_port, running = servers()
    rows = [f"| page | slider → first figure painted in chromium, ms (median of {CHANGES}) "
            "| → all its figures painted, ms |", "|---|---:|---:|"]
    try:
        with sync_playwright() as p, tempfile.TemporaryDirectory() as profile:
            context = p.chromium.launch_persistent_context(
                profile, executable_path="/usr/bin/chromium", headless=True,
                args=["--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"],
                viewport={"width": 1400, "height": 900})
            page = context.new_page()
            for name, label, expander in PAGES:
                url = f"http://127.0.0.1:{port}/{name}{'&' if '?' in name else '?'}lang=en"
                first, last = measure(page, url, label, expander)
                shown = f"{name}, ω₂" if label == "ω₂" else name
                rows.append(f"| {shown} | {first:.0f} | {last:.0f} |")
            first, last = measure(page, f"http://127.0.0.1:{floor_port}/?lang=en&floor=slider",
                                  "(member 2)", None)
            rows.append(f"| {SLIDER_FLOOR} | {first:.0f} | {last:.0f} |")
            rows += ["", f"| page | φ₂ (trajectories: a link's length, or the tedder's R_t) "
                     "scrubbed in the browser "
                     f"→ first chart painted, ms (median "
                     f"of {CHANGES}) | Plotly's own redraw of the same figures in bare "
                     "Streamlit's page, ms | ÷ that | the same in a blank page, ms "
                     "| → all its charts, ms | first touch → frames there (one "
                     "rerun), ms | frames, kB |", "|---|---:|---:|---:|---:|---:|---:|---:|"]
            floor_url = f"http://127.0.0.1:{floor_port}/trajectories?lang=en"
            floors = launch(p)
            for name, tab in SCRUBBED:
                url = f"http://127.0.0.1:{port}/{name}{'&' if '?' in name else '?'}lang=en"
                first, every, (blank, bare), touch, size = scrub(page, url, tab, floor_url, floors)
                shown = f"{name}, {tab}" if tab else name
                rows.append(f"| {shown} | {first:.0f} | {bare:.0f} | {first / bare:.2f}× "
                            f"| {blank:.0f} | {every:.0f} | {touch:.0f} | {size:.0f} |")
            floors.close()
            context.close()
            browser = launch(p)
            rows += ["", f"| page | navigation → first chart painted, fresh browser, ms (median "
                     f"of {VISITS}, the pages and the floor in turn) | ÷ the floor | transferred "
                     "by then, kB |", "|---|---:|---:|---:|"]
            urls = {name: f"http://127.0.0.1:{port}/{name}?lang=en" for name in OPENED}
            urls[FLOOR] = f"http://127.0.0.1:{floor_port}/trajectories?lang=en"
            painted = first_paints(browser, urls)
            rows += [f"| {name} | {ms:.0f} | {ms / painted[FLOOR][0]:.2f}× | {kb:.0f} |"
                     for name, (ms, kb) in painted.items()]
            browser.close()
            rows += phone_rows(p, port, floor_port)
    finally:
        for server in running:
            server.terminate()
            server.wait(timeout=30)
    return "\n".join(rows)


if __name__ == "__main__":
    if "--phone" in sys.argv:
        print(phone_table())
    else:
        publish(table(), "<!-- browser table -->", CHANGES)
