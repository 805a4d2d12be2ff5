"""A Plotly figure whose traces and animation frames are plain dicts, added unvalidated.

Plotly checks every property of every trace it is given: here about 0.5 ms a trace and
6 ms an animation frame, so a 120-frame animation cost over a second per rerun. The
traces come from a few builders that the tests exercise, so they are kept as dicts and
joined to the (validated) layout only when the figure is serialised — by
``st.plotly_chart``, ``to_json`` or an image export, which all go through ``to_dict``.
"""

from __future__ import annotations

import plotly.graph_objects as go


class RawFigure(go.Figure):
    def __init__(self) -> None:
        super().__init__()
        self._raw_data: list[dict] = []
        self._raw_frames: list[dict] = []
        self._raw_layout: dict = {}

    def merge_layout(self, layout: dict) -> None:
        """Layout settings as a plain dict, merged over the validated layout when serialised
        (``update_layout`` and ``update_xaxes`` cost ~10 ms a figure in validation alone)."""
        _merge(self._raw_layout, layout)

    def underlay(self, layout: dict) -> None:
        """Layout defaults placed under the figure's own settings (those win)."""
        self._raw_layout = _merge(_merge({}, layout), self._raw_layout)

    def legend_names(self) -> list[str]:
        """Names of the traces that appear in the legend."""
        return [str(tr["name"]) for tr in self._raw_data
                if tr.get("showlegend", True) and tr.get("name") is not None]

    def add_raw(self, traces: list[dict]) -> list[int]:
        """Append traces; returns their indices (for animation frames)."""
        start = len(self._raw_data)
        self._raw_data.extend(traces)
        return list(range(start, len(self._raw_data)))

    def to_dict(self) -> dict:
        spec = super().to_dict()
        spec["data"] = self._raw_data
        spec["layout"] = _merge(_merge({}, self._raw_layout), spec.get("layout", {}))
        if self._raw_frames:
            spec["frames"] = self._raw_frames
        return spec

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
