"""ui.plot: plotly.js is served from the installed package, copied once."""

from __future__ import annotations

from pathlib import Path

import plotly

from ui.plot import PLOTLY_JS, publish_plotly_js


def test_plotly_js_is_copied_once_from_the_installed_package(tmp_path):
    shipped = Path(plotly.__file__).parent / "package_data" / "plotly.min.js"
    target = publish_plotly_js(tmp_path / "static")
    assert target.read_bytes() == shipped.read_bytes()
    assert [p.name for p in (tmp_path / "static").iterdir()] == [PLOTLY_JS]  # no partial left
    target.write_text("kept")
    publish_plotly_js(tmp_path / "static")
    assert target.read_text() == "kept"  # an existing copy is not written again
