"""Plotly charts drawn in place: a Streamlit component (components v2) that keeps one div
per chart and updates it with ``Plotly.react`` (ui/plot.js).

``st.plotly_chart`` takes its element's identity from the figure itself, so in the browser
every slider step unmounted each chart and drew it from scratch, twice. Measured with
bench/browser.py: slider → figure on the plans page went from ~510 to ~350 ms.

plotly.js is served by Streamlit's static file serving (``.streamlit/config.toml``) from
``static/``, where it is copied once: no network needed. A chart loads the smallest of
Plotly's own bundles that draws its traces (npm, pinned in package.json at the version the
``plotly`` package ships): the 1.2 MB "basic" bundle runs in 0.3 s in chromium here where
the full 4.8 MB one took 1.2 s, most of a page's first paint (bench/browser.py). Without
``npm ci`` the full bundle from the ``plotly`` package serves every chart.

The component's own script (the bundles' loader, then ui/plot.js) is a static file too,
named by its content; the component is given a two-line module that imports it. Given
inline, its 20 kB rode along with every chart of every rerun: a plans page rerun sent
92 kB, 31 kB without it (bench/pages.py).
"""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Callable
from pathlib import Path

import plotly
import streamlit as st

from figures.raw import RawFigure
from ui.crank import Crank, follow
from ui.firstpaint import chart_sent, painted
from ui.i18n import LANGUAGES, t

ROOT = Path(__file__).resolve().parents[1]
STATIC = ROOT / "static"
PLOTLY_JS_VERSION = plotly.offline.get_plotlyjs_version()
# Plotly's partial bundles, smallest first, with the trace types each draws
BUNDLES = {"basic": {"scatter", "bar", "pie"},
           "gl3d": {"scatter", "scatter3d", "surface", "mesh3d", "isosurface", "volume", "cone",
                    "streamtube"}}

# the bundles' loader, shared with the page's head (scripts/serve.py starts Plotly from there)
LOADER = Path(__file__).with_name("plotly_loader.js").read_text(encoding="utf-8")


def _bundle_source(name: str) -> Path | None:
    """The npm bundle ``name`` if it is installed at the Python package's plotly.js version
    (a figure is JSON for that version), else None."""
    package = ROOT / "node_modules" / f"plotly.js-{name}-dist-min"
    try:
        version = json.loads((package / "package.json").read_text(encoding="utf-8"))["version"]
    except (OSError, ValueError, KeyError):
        return None
    return package / f"plotly-{name}.min.js" if version == PLOTLY_JS_VERSION else None


def _publish(content: Callable[[], bytes], name: str, static: Path) -> str:
    """Write ``content()`` into ``static`` as ``name`` (once); its URL relative to a page."""
    target = static / name
    if not target.exists():
        static.mkdir(exist_ok=True)
        partial = target.with_suffix(f".{os.getpid()}.partial")  # one per process (deploy/)
        partial.write_bytes(content())
        partial.replace(target)  # atomic: a server never serves half a file
    return f"app/static/{name}"  # a page is one level deep


def publish_plotly_js(static: Path = STATIC) -> list[tuple[set[str] | None, str]]:
    """Put the bundles where Streamlit serves static files: (trace types it draws, or None
    for all; URL), smallest first, the full bundle of the ``plotly`` package last."""
    bundles = []
    for name, types in BUNDLES.items():
        source = _bundle_source(name)
        if source is not None:
            bundles.append((types, _publish(source.read_bytes,
                                            f"plotly-{name}-{PLOTLY_JS_VERSION}.min.js", static)))
    full = Path(plotly.__file__).parent / "package_data" / "plotly.min.js"
    return bundles + [(None, _publish(full.read_bytes, f"plotly-{PLOTLY_JS_VERSION}.min.js",
                                      static))]


# the toolbar's and the chart's own English words, which Plotly translates through a locale
# (its own Serbian locales have none: they only name days and months)
PLOTLY_WORDS = ("plotly.zoom", "plotly.pan", "plotly.box_select", "plotly.lasso_select",
                "plotly.zoom_in", "plotly.zoom_out", "plotly.autoscale", "plotly.reset_axes",
                "plotly.spikes", "plotly.closest", "plotly.compare", "plotly.toggle_closest",
                "plotly.orbital", "plotly.turntable", "plotly.camera_default",
                "plotly.camera_saved", "plotly.reset_view", "plotly.reset_views", "plotly.reset",
                "plotly.zoom_back", "plotly.legend_isolate")


def plotly_locales() -> dict[str, dict]:
    """Plotly locales of the app's languages but English, named as the languages are
    (``config.locale``): the toolbar's tooltips in the page's words."""
    return {language: {"moduleType": "locale", "name": language,
                       "dictionary": {t(k, "en"): t(k, language) for k in PLOTLY_WORDS}}
            for language in LANGUAGES if language != "en"}


def publish_chart_js(static: Path = STATIC) -> str:
    """The charts' script (the bundles' loader, the Plotly locales, then ui/plot.js) put
    where Streamlit serves static files, named by its content (``plot-<hash>.js``: a
    browser may keep it a year, scripts/serve.py); an older version is removed, so that
    scripts/page_head.py finds this one. Its URL relative to a page."""
    locales = json.dumps(plotly_locales(), ensure_ascii=False, sort_keys=True)
    text = (LOADER + f"const LOCALES = {locales};\n"
            + Path(__file__).with_suffix(".js").read_text(encoding="utf-8")).encode()
    name = f"plot-{hashlib.sha256(text).hexdigest()[:12]}.js"
    for old in static.glob("plot-*.js"):
        if old.name != name:
            old.unlink(missing_ok=True)
    return _publish(lambda: text, name, static)


def chart_module(url: str) -> str:
    """The component's script: it imports the charts' script from ``url`` (relative to the
    page, as Plotly's bundles are) once per page and hands each chart to it."""
    return (f"const drawn = import(new URL({json.dumps(url)}, document.baseURI).href);\n"
            "export default async (component) => (await drawn).default(component);\n")


def bundle_url(fig: RawFigure) -> str:
    """The URL of the smallest published bundle that draws every trace of ``fig``."""
    types = fig.trace_types()
    return next(url for drawn, url in _URLS if drawn is None or types <= drawn)


def plot(fig: RawFigure, key: str, filename: str, labels: dict[str, str],
         editable: bool = False, crank: Crank | None = None,
         on_crank: Callable[[float | None, bool | str], None] | None = None,
         separators: str | None = None, locale: str = "en", handle: str | None = None,
         focus: str | None = None):
    """Draw ``fig`` in the chart ``key``; the same key keeps the same div between reruns. Its
    toolbar saves it as ``filename``.svg or .png; ``labels`` name the buttons ("svg", "png",
    "fullscreen").

    ``editable``: the figure's shapes can be dragged and the paper clicked; the rerun that
    follows reads the result's ``drag`` ({point, x, y}: a shape named after a point, moved
    to x, y), ``click`` ({x, y}) or ``joint`` ({point}: a joint double-clicked), each set for
    that one rerun.

    ``crank``: the chart's own φ₂ (or length) control (ui/crank.py). ``on_crank(value, asked)``
    is called before the rerun the control starts: with the value (degrees, metres) when the
    student lets go of it, with None when they first touch it or pick another of its choices,
    to ask for the frames (``asked``: True, or the key of the choice picked). The browser
    also says when the keyboard comes onto one of the page's sliders the chart follows, or
    leaves them (trigger "near": ui.crank.follow).

    ``separators``: Plotly's decimal and thousands marks for the page's language (",." on
    a Serbian page), put into the figure's layout in the browser so that a cached figure
    serves every language. ``locale``: the page's language, whose words the toolbar's
    tooltips take (``plotly_locales``).

    ``handle``: the name of the one shape a student moves (practice's tip), by finger or
    mouse, grabbed anywhere within 22 CSS px of it however small it is drawn; two fingers
    zoom the chart, and a one-finger swipe elsewhere scrolls the page. Its new place comes
    back as ``drag``, as an editable chart's.

    ``focus``: a CSS selector of what to scroll to the top of the screen once this chart is
    drawn, each time the text changes (give it a counter: "….st-key-x #3").

    In a page's first run in a session the chart reports its first paint (trigger
    "painted"), and the rerun that follows sends what the page left out until then
    (ui/firstpaint.py)."""
    control = "null" if crank is None else crank.json()
    first = chart_sent()
    body = (f'{{"src": {json.dumps(bundle_url(fig))}, "filename": {json.dumps(filename)}, '
            f'"first": {json.dumps(first)}, '
            f'"labels": {json.dumps(labels)}, "editable": {json.dumps(editable)}, '
            f'"crank": {control}, "separators": {json.dumps(separators)}, '
            f'"locale": {json.dumps(locale)}, "handle": {json.dumps(handle)}, '
            f'"focus": {json.dumps(focus)}, '
            f'"figure": {fig.json()}}}')
    events = ({"on_drag_change": _ignore, "on_click_change": _ignore, "on_joint_change": _ignore}
              if editable or handle else {})
    if first:
        events["on_painted_change"] = painted  # the rerun it starts is what it is for
    if on_crank is not None:
        events["on_at_change"] = lambda: on_crank(float(st.session_state[key]["at"]), True)
        events["on_frames_change"] = lambda: on_crank(None, st.session_state[key]["frames"])
    if crank is not None and crank.follows:
        events["on_near_change"] = lambda: follow(st.session_state[key]["near"])
    return _render(key=key, data=body.encode("utf-8"), **events)


def _ignore() -> None:
    """The trigger's value is read from the result in the rerun it starts."""


_URLS = publish_plotly_js()
_render = st.components.v2.component(
    "mehanizmi_plot", js=chart_module(publish_chart_js()),
    isolate_styles=False)  # plotly.js styles the chart from the page's own stylesheet
