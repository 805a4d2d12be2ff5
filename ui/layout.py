"""The page's frame for every screen: controls beside the charts on a laptop or a projector,
the charts first on a phone; captions dark enough to read (WCAG's 4.5:1).

Streamlit stacks a row of columns below 640 px in their order, so a chapter page's column of
sliders came first and its chart two to four screens down. ``page_columns`` keys the page's
row, and on a narrow screen that row alone is shown in reverse: the chart (with its own φ₂
control under it) comes first, the rest of the controls follow. What a page puts in a
container keyed ``later…`` (an input table, a results table above the charts) moves after
the charts there, and a row of metrics stays two abreast instead of four screens long.

Those styles are ``ui/frame.css``, one style closing every page's body (scripts/serve.py,
``scripts/page_head.FRAME``): sent once a visit, not as an element of every run (2.4 kB, one
element more in each of a class's openings).
"""

from __future__ import annotations

import streamlit as st

def page_columns(spec=(1, 3)):
    """The page's controls and main column (``controls, main``), the main one first on a
    phone."""
    with st.container(key="page"):
        return st.columns(list(spec), gap="large")
