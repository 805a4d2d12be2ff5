"""What scripts/serve.py adds to a page's HTML head, so that a fresh visit reaches its first
chart sooner. In chromium on this machine the browser's main thread is busy for most of the
time before a fresh visit's first chart (docs/performance.md, "On a phone"). So each tag
here takes a wait or some script off the way to that chart; none of them saves bytes:

- Plotly's basic bundle is fetched and run from the head. ``ui/plotly_loader.js`` runs here
  as it runs in a chart, and the chart then finds the bundle's promise under its own URL.
  Before, the bundle was fetched early (a preload) but it ran only once the first chart
  element had mounted: 0.2–0.3 s of script on the way to the first chart.
- The charts' own script (ui/plot.py publishes it as a static file) is fetched from the
  head, so the first chart does not wait for it once Streamlit has drawn the chart's element.
- The phone keyboard of a number field (ui/numbers.py: a text box the app reads, so that
  the browser's language never parses it): ``inputmode="decimal"`` on the boxes of its
  ``st-key-num_…`` containers, which shows digits, the decimal separator and, on Android,
  a minus. iOS's decimal pad has no minus, so there a field that takes negative values
  (``num_any_``) keeps the full keyboard.
- A Serbian page's sliders write their values with a decimal comma, as every other number
  of the page: Streamlit writes them with a point in any language. The page says its mark
  by the container of its language box (``ui.i18n.language_picker``), so a page with no
  chart (an unsolvable position) is rewritten as well; the charts' script did this before,
  only where it drew.
- The page's frame (``ui/frame.css``: captions dark enough, a phone's order of columns, the
  builder's sticky drawing) is a style sent once a visit, where it was an element of every
  run of every page. It closes the body (``FRAME``), not the head: Streamlit's own styles
  are added to the head as the page draws, and the frame must come after them to win where
  a selector of each weighs the same, as the element in the page did.
- Streamlit's front end is told where its server is (``window.__streamlit``). Without it, on
  a page such as ``/kinetostatics`` the front end first asks
  ``/kinetostatics/_stcore/health``, gets a 404, and only then tries the root. That is a
  round trip lost before the page's first run.
"""

from __future__ import annotations

import json
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
# read once: every page's HTML carries it
LOADER = (ROOT / "ui" / "plotly_loader.js").read_text(encoding="utf-8")
FRAME = f'<style>\n{(ROOT / "ui" / "frame.css").read_text(encoding="utf-8")}</style>'
# One observer of the page for the head's small fixes, each a rewrite of what Streamlit drew:
# - the phone keyboard of a number field (see above);
# - a Serbian page's sliders: Streamlit writes their values and ends ("3.58") with a point
#   whatever the page's language, and the page's decimal mark is said by the container of
#   its language box (ui.i18n.language_picker); rewritten before the browser paints, so no
#   point flickers, and written back when the page turns English (the slider is the same
#   element then, and React leaves its unchanged value as it was).
FIXES = """(() => {
const POINT = [/^([\u2212\\-+]?\\d*)\\.(\\d+)/, "$1,$2"];  // 3.58 → 3,58
const COMMA = [/^([\u2212\\-+]?\\d*),(\\d+)/, "$1.$2"];  // and back, on a page turned English
const SLIDER_TEXT = "[data-testid='stSliderThumbValue'], [data-testid='stSliderTickBar']";
new MutationObserver(() => {
  const ios = /iPhone|iPad|iPod/.test(navigator.userAgent);
  for (const box of document.querySelectorAll(
      "[class*='st-key-num_'] input:not([inputmode])")) {
    const signed = box.closest("[class*='st-key-num_any_']");
    box.setAttribute("inputmode", signed && ios ? "text" : "decimal");
  }
  const [number, mended] = document.querySelector(".st-key-decimal_comma") ? POINT : COMMA;
  for (const box of document.querySelectorAll(SLIDER_TEXT)) {
    const walk = document.createTreeWalker(box, NodeFilter.SHOW_TEXT);
    for (let node = walk.nextNode(); node; node = walk.nextNode()) {
      if (number.test(node.nodeValue)) node.nodeValue = node.nodeValue.replace(number, mended);
    }
  }
}).observe(document.documentElement, {childList: true, subtree: true, characterData: true});
})();"""


def basic_bundle(static: Path = ROOT / "static") -> Path | None:
    """Plotly's basic bundle as ui/plot.py published it, if it did."""
    return next(iter(sorted(static.glob("plotly-basic-*.min.js"))), None)


def chart_script(static: Path = ROOT / "static") -> Path | None:
    """The charts' script as ui/plot.py published it (named by its content), if it did."""
    return max(static.glob("plot-*.js"), key=lambda p: p.stat().st_mtime, default=None)


def base_url(base_path: str) -> str:
    """The server's path from Streamlit's ``server.baseUrlPath``: "" → "/", "a/b" → "/a/b/"."""
    return "".join(f"/{part}" for part in base_path.split("/") if part) + "/"


def head(base_path: str, static: Path = ROOT / "static") -> str:
    """The tags for a page's head; ``base_path`` is Streamlit's ``server.baseUrlPath``."""
    base = json.dumps(base_url(base_path))
    server = (f"window.__streamlit = {{...window.__streamlit, "
              f"BACKEND_BASE_URL: new URL({base}, location.href).href}};\n{FIXES}")
    script = chart_script(static)
    fetched = ("" if script is None
               else f'<link rel="modulepreload" href="app/static/{script.name}">')
    bundle = basic_bundle(static)
    if bundle is None:
        return f"{fetched}<script>{server}</script>"
    src = f"app/static/{bundle.name}"  # as ui/plot.py names it: a page is one level deep
    return (f'<link rel="preload" as="script" href="{src}">{fetched}'
            f"<script>{server}\n(() => {{\n{LOADER}"
            f"plotly({json.dumps(src)});\n}})();</script>")
