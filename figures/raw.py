"""A Plotly figure whose traces and animation frames are plain dicts, added unvalidated.

Plotly checks every property of every trace it is given: here about 0.5 ms a trace and
6 ms an animation frame, so a 120-frame animation cost over a second per rerun. The
traces come from a few builders that the tests exercise, so they are kept as dicts and
joined to the (validated) layout only when the figure is serialised — by
``ui.plot``, ``to_json`` or an image export, which all go through ``to_dict``.

No template is sent. Plotly's default template is the one Streamlit installs on import
("streamlit"): placeholder colours that only Streamlit's own chart element fills in, which
our traces never used (each names its colours; plotly.js's defaults do the rest). Yet every
new figure deep-copied it into its layout and ``to_dict`` copied it out again, 7 kB of JSON
a figure: a plans figure cost 1.9 ms to build and serialise, 0.7 ms without. So importing
this module (after Streamlit, as every page does) leaves Plotly without a default template,
and ``to_dict`` drops one that a figure was given anyway.
"""

from __future__ import annotations

import copy

import plotly.graph_objects as go
import plotly.io as pio

# Every figure starts from what Streamlit's own chart theme added (font, left bold title,
# white paper): the pages draw through ui.plot, without that theme, which cost the browser
# 0.5–0.9 s a redraw (bench/browser.py). Set here, the look is part of the figure: no chart
# call has to add it to a figure that may be cached and shared.
HOUSE = dict(font=dict(family='"Source Sans", "Source Sans Pro", sans-serif'),
             title=dict(x=0.0, xanchor="left", font=dict(weight="bold")),
             paper_bgcolor="white")
pio.templates.default = None


class RawFigure(go.Figure):
    def __init__(self) -> None:
        super().__init__()
        self._raw_data: list[dict] = []
        self._raw_frames: list[dict] = []
        self._raw_layout: dict = copy.deepcopy(HOUSE)
        self._frozen: str | None = None

    def merge_layout(self, layout: dict) -> None:
        """Layout settings as a plain dict, merged over the validated layout when serialised
        (``update_layout`` and ``update_xaxes`` cost ~10 ms a figure in validation alone)."""
        _merge(self._raw_layout, layout)

    def legend_names(self) -> list[str]:
        """Names of the traces that appear in the legend."""
        return [str(tr["name"]) for tr in self._raw_data
                if tr.get("showlegend", True) and tr.get("name") is not None]

    def trace_types(self) -> set[str]:
        """The kinds of trace drawn (Plotly's "type"): they decide the plotly.js bundle."""
        return ({str(tr.get("type", "scatter")) for tr in self._raw_data}
                | {str(tr.type) for tr in self.data})

    def add_raw(self, traces: list[dict]) -> list[int]:
        """Append traces; returns their indices (for animation frames)."""
        start = len(self._raw_data)
        self._raw_data.extend(traces)
        return list(range(start, len(self._raw_data)))

    def to_dict(self) -> dict:
        spec = super().to_dict()
        spec["data"] = self._raw_data
        spec["layout"] = _merge(_merge({}, self._raw_layout), spec.get("layout", {}))
        spec["layout"].pop("template", None)
        if self._raw_frames:
            spec["frames"] = self._raw_frames
        return spec

    def raw_dict(self) -> dict:
        """Data and layout as added, without the validated layout (no template, no deep
        copy): for the crank frames of ui/crank.py, about 2 ms cheaper a figure than
        ``to_dict``; their base figure is drawn from the full one first."""
        return {"data": self._raw_data, "layout": self._raw_layout}

    def freeze(self) -> RawFigure:
        """Serialise the figure now, once: for a figure cached and shared across reruns,
        which is never changed again. ``json()`` then returns that text (serialising the
        trajectories page's construction took 5 ms of each of its reruns)."""
        self._frozen = pio.to_json(self, validate=False)
        return self

    def json(self) -> str:
        """The figure as Plotly's JSON (made once if the figure is frozen)."""
        return self._frozen if self._frozen is not None else pio.to_json(self, validate=False)

    def add_frames(self, frames: list[dict]) -> None:
        """Animation frames as plain dicts: ``{"name", "data", "traces"}``."""
        self._raw_frames.extend(frames)


def _merge(into: dict, extra: dict) -> dict:
    """``extra`` merged into ``into``, nested dicts key by key (``extra`` wins)."""
    for key, value in extra.items():
        if isinstance(value, dict) and isinstance(into.get(key), dict):
            _merge(into[key], value)
        else:
            into[key] = value
    return into
