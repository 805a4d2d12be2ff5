"""ui.plot: plotly.js is served from Plotly's own bundles, copied once, the smallest that
draws a chart's traces chosen per chart; the charts' own script is a static file named by
its content, which the component imports."""

from __future__ import annotations

from pathlib import Path

import plotly
import pytest

from figures.raw import RawFigure
from ui.plot import (
    LOADER,
    PLOTLY_JS_VERSION,
    bundle_url,
    chart_module,
    publish_chart_js,
    publish_plotly_js,
)

ROOT = Path(__file__).resolve().parents[1]


def test_the_bundles_are_copied_once_smallest_first_the_full_one_last(tmp_path):
    static = tmp_path / "static"
    urls = [url for _, url in publish_plotly_js(static)]
    # scripts/test.sh runs npm ci: the partial bundles are there, at plotly.py's version
    assert urls == [f"app/static/plotly-basic-{PLOTLY_JS_VERSION}.min.js",
                    f"app/static/plotly-gl3d-{PLOTLY_JS_VERSION}.min.js",
                    f"app/static/plotly-{PLOTLY_JS_VERSION}.min.js"]
    files = {p.name: p for p in static.iterdir()}
    assert sorted(files) == sorted(u.rsplit("/", 1)[1] for u in urls)  # no partial left
    full = files[f"plotly-{PLOTLY_JS_VERSION}.min.js"]
    assert full.read_bytes() == (Path(plotly.__file__).parent / "package_data" / "plotly.min.js").read_bytes()
    basic = files[f"plotly-basic-{PLOTLY_JS_VERSION}.min.js"]
    assert f"(basic - minified) v{PLOTLY_JS_VERSION}" in basic.read_text(encoding="utf-8")[:200]
    assert basic.stat().st_size < full.stat().st_size / 3
    full.write_text("kept")
    publish_plotly_js(static)
    assert full.read_text() == "kept"  # an existing copy is not written again


def test_the_charts_script_is_published_by_its_content_and_an_older_one_removed(tmp_path):
    static = tmp_path / "static"
    static.mkdir()
    (static / "plot-000000000000.js").write_text("an older version")
    url = publish_chart_js(static)
    (script,) = static.glob("plot-*.js")
    assert url == f"app/static/{script.name}" and script.name != "plot-000000000000.js"
    text = script.read_text(encoding="utf-8")
    assert text.startswith(LOADER) and text.endswith((ROOT / "ui" / "plot.js").read_text(
        encoding="utf-8"))
    assert '"Reset axes": "Vrati ose"' in text and '"Reset axes": "Врати осе"' in text
    assert publish_chart_js(static) == url  # the same content, the same name
    module = chart_module(url)
    assert f'import(new URL("{url}", document.baseURI).href)' in module and len(module) < 300


def test_without_npm_bundles_the_full_bundle_draws_everything(tmp_path, monkeypatch):
    monkeypatch.setattr("ui.plot.ROOT", tmp_path)  # no node_modules there
    assert [drawn for drawn, _ in publish_plotly_js(tmp_path / "static")] == [None]


def test_a_chart_gets_the_smallest_bundle_that_draws_its_traces():
    flat, solid = RawFigure(), RawFigure()
    flat.add_raw([{"type": "scatter", "x": [0, 1], "y": [0, 1]}, {"x": [1], "y": [2]}])
    solid.add_raw([{"type": "scatter", "x": [0], "y": [0]},
                   {"type": "scatter3d", "x": [0], "y": [0], "z": [0]}])
    assert "plotly-basic-" in bundle_url(flat)
    assert "plotly-gl3d-" in bundle_url(solid)
    solid.add_raw([{"type": "sankey"}])  # in neither partial bundle
    assert bundle_url(solid).endswith(f"/plotly-{PLOTLY_JS_VERSION}.min.js")


@pytest.mark.parametrize("lang, separators", [("sr", ",."), ("sr-cyrl", ",."), ("en", None)])
def test_a_serbian_page_asks_its_charts_for_a_decimal_comma(lang, separators):
    from .test_pages import charts, page

    at = page("pages/trajectories.py", lang=lang)
    sent = charts(at)
    assert sent and all(chart["separators"] == separators for chart in sent.values())


def test_a_figure_is_sent_without_a_template():
    """Streamlit installs a placeholder template as Plotly's default on import; a go.Figure
    carried it (7 kB of JSON, copied twice) though no trace used it. A RawFigure is no
    go.Figure and sends none, not even one it was given."""
    import json

    import plotly.io as pio

    assert pio.templates.default == "streamlit"  # (ui.plot, imported above, imports Streamlit)
    given = RawFigure()
    given.merge_layout({"title": {"text": "A"}, "template": pio.templates["plotly"]})
    given.merge_layout({"xaxis": {"scaleanchor": "y"}})
    for fig in (given, RawFigure()):
        sent = json.loads(pio.to_json(fig, validate=False))
        assert "template" not in sent["layout"] and json.loads(fig.json()) == sent
    assert sent["layout"]["paper_bgcolor"] == "white"  # the house look is still there
    kept = json.loads(given.json())["layout"]
    assert kept["title"]["text"] == "A" and kept["title"]["x"] == 0.0
    assert kept["xaxis"]["scaleanchor"] == "y"
