"""Plotly charts drawn in place: a Streamlit component (components v2) that keeps one div
per chart and updates it with ``Plotly.react`` (ui/plot.js).

``st.plotly_chart`` takes its element's identity from the figure itself, so in the browser
every slider step unmounted each chart and drew it from scratch, twice. Measured with
bench/browser.py: slider → figure on the plans page went from ~510 to ~350 ms.

plotly.js comes from the installed ``plotly`` package, copied once into ``static/`` and served
by Streamlit's static file serving (``.streamlit/config.toml``): no network needed.
"""

from __future__ import annotations

import json
import os
from collections.abc import Callable
from pathlib import Path

import plotly
import plotly.io as pio
import streamlit as st

from figures.raw import RawFigure
from ui.crank import Crank

ROOT = Path(__file__).resolve().parents[1]
PLOTLY_JS = f"plotly-{plotly.__version__}.min.js"  # named after the package that ships it
URL = f"app/static/{PLOTLY_JS}"  # relative to a page's URL: a page is one level deep

_render = st.components.v2.component(
    "mehanizmi_plot", js=Path(__file__).with_suffix(".js").read_text(encoding="utf-8"),
    isolate_styles=False)  # plotly.js styles the chart from the page's own stylesheet


def publish_plotly_js(static: Path = ROOT / "static") -> Path:
    """Copy plotly.js from the installed package where Streamlit serves static files."""
    target = static / PLOTLY_JS
    if not target.exists():
        static.mkdir(exist_ok=True)
        source = Path(plotly.__file__).parent / "package_data" / "plotly.min.js"
        partial = target.with_suffix(f".{os.getpid()}.partial")  # one per process (deploy/)
        partial.write_bytes(source.read_bytes())
        partial.replace(target)  # atomic: a server never serves half a file
    return target


def plot(fig: RawFigure, key: str, filename: str, labels: dict[str, str],
         editable: bool = False, crank: Crank | None = None,
         on_crank: Callable[[float | None], None] | None = None):
    """Draw ``fig`` in the chart ``key``; the same key keeps the same div between reruns. Its
    toolbar saves it as ``filename``.svg or .png; ``labels`` name the buttons ("svg", "png",
    "fullscreen").

    ``editable``: the figure's shapes can be dragged and the paper clicked; the rerun that
    follows reads the result's ``drag`` ({point, x, y}: a shape named after a point, moved
    to x, y) or ``click`` ({x, y}), each set for that one rerun.

    ``crank``: the chart's own φ₂ control (ui/crank.py). ``on_crank`` is called before the rerun the control starts: with the angle in degrees
    when the student lets go of it, with None when they first touch it (to ask for the
    frames)."""
    control = "null" if crank is None else crank.json()
    body = (f'{{"src": {json.dumps(URL)}, "filename": {json.dumps(filename)}, '
            f'"labels": {json.dumps(labels)}, "editable": {json.dumps(editable)}, '
            f'"crank": {control}, "figure": {pio.to_json(fig, validate=False)}}}')
    events = {"on_drag_change": _ignore, "on_click_change": _ignore} if editable else {}
    if on_crank is not None:
        events["on_at_change"] = lambda: on_crank(float(st.session_state[key]["at"]))
        events["on_frames_change"] = lambda: on_crank(None)
    return _render(key=key, data=body.encode("utf-8"), **events)


def _ignore() -> None:
    """The trigger's value is read from the result in the rerun it starts."""


publish_plotly_js()
