"""A Plotly figure kept as plain dicts: its traces, layout and animation frames, unvalidated.

Plotly checks every property of every trace it is given: here about 0.5 ms a trace and
6 ms an animation frame, so a 120-frame animation cost over a second per rerun. Even an
empty ``go.Figure`` cost 0.3 ms to make (its layout's validators) and its ``to_dict`` a
deep copy: a third of the three plans figures' 2.2 ms a rerun. The figures come from a few
builders that the tests exercise (tests/test_pages.py validates every chart a page sends
against Plotly's schema), so nothing here is a ``go.Figure``: ``ui.plot``, ``to_json`` and
an image export take the dict this makes (``to_plotly_json``).

No template is sent. Plotly's default template is the one Streamlit installs on import
("streamlit"): placeholder colours that only Streamlit's own chart element fills in, which
our traces never used (each names its colours; plotly.js's defaults do the rest). A
template given anyway is dropped.
"""

from __future__ import annotations

from plotly.io.json import to_json_plotly

# Every figure starts from what Streamlit's own chart theme added (font, left bold title,
# white paper): the pages draw through ui.plot, without that theme, which cost the browser
# 0.5–0.9 s a redraw (bench/browser.py). Set here, the look is part of the figure: no chart
# call has to add it to a figure that may be cached and shared.
def house() -> dict:
    """The house look, made anew for each figure (a deep copy of a constant cost 0.07 ms)."""
    return dict(font=dict(family='"Source Sans", "Source Sans Pro", sans-serif'),
                title=dict(x=0.0, xanchor="left", font=dict(weight="bold")),
                paper_bgcolor="white")


class RawFigure:
    def __init__(self) -> None:
        self._raw_data: list[dict] = []
        self._raw_frames: list[dict] = []
        self._raw_layout: dict = house()
        self._frozen: str | None = None

    def merge_layout(self, layout: dict) -> None:
        """Layout settings as a plain dict (nested, as plotly.js reads them: ``{"xaxis":
        {"title": {"text": …}}}``), merged over what the figure has."""
        _merge(self._raw_layout, layout)

    def legend_names(self) -> list[str]:
        """Names of the traces that appear in the legend."""
        return [str(tr["name"]) for tr in self._raw_data
                if tr.get("showlegend", True) and tr.get("name") is not None]

    def trace_types(self) -> set[str]:
        """The kinds of trace drawn (Plotly's "type"): they decide the plotly.js bundle."""
        return {str(tr.get("type", "scatter")) for tr in self._raw_data}

    def add_raw(self, traces: list[dict]) -> list[int]:
        """Append traces; returns their indices (for animation frames)."""
        start = len(self._raw_data)
        self._raw_data.extend(traces)
        return list(range(start, len(self._raw_data)))

    def to_dict(self) -> dict:
        """The figure as Plotly's dict: data, a copy of the layout, frames if any."""
        layout = _merge({}, self._raw_layout)
        layout.pop("template", None)
        spec = {"data": self._raw_data, "layout": layout}
        if self._raw_frames:
            spec["frames"] = self._raw_frames
        return spec

    to_plotly_json = to_dict  # what plotly.io (to_json, write_image) asks of a figure

    def raw_dict(self) -> dict:
        """Data and layout as added, without copying the layout: for the crank frames of
        ui/crank.py, whose base figure is drawn from the full one first."""
        return {"data": self._raw_data, "layout": self._raw_layout}

    def freeze(self) -> RawFigure:
        """Serialise the figure now, once: for a figure cached and shared across reruns,
        which is never changed again. ``json()`` then returns that text (serialising the
        trajectories page's construction took 5 ms of each of its reruns)."""
        self._frozen = to_json_plotly(self.to_dict())
        return self

    def json(self) -> str:
        """The figure as Plotly's JSON (made once if the figure is frozen)."""
        return self._frozen if self._frozen is not None else to_json_plotly(self.to_dict())

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
