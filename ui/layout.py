"""The page's frame for every screen: controls beside the charts on a laptop or a projector,
the charts first on a phone; captions dark enough to read (WCAG's 4.5:1).

Streamlit stacks a row of columns below 640 px in their order, so a chapter page's column of
sliders came first and its chart two to four screens down. ``page_columns`` keys the page's
row, and on a narrow screen that row alone is shown in reverse: the chart (with its own φ₂
control under it) comes first, the rest of the controls follow.
"""

from __future__ import annotations

import streamlit as st

CSS = """
<style>
/* captions: Streamlit's grey is 3.7:1 on white; this one is 7:1 */
[data-testid="stCaptionContainer"], [data-testid="stCaptionContainer"] p,
[data-testid="stWidgetLabel"] [data-testid="stCaptionContainer"] { color: #4a4c57; }
@media (max-width: 640px) {
  .st-key-page > div > [data-testid="stHorizontalBlock"],
  .st-key-page > [data-testid="stHorizontalBlock"] { flex-direction: column-reverse; }
  [data-testid="stMainBlockContainer"] { padding-left: 0.75rem; padding-right: 0.75rem; }
  [data-testid="stMainBlockContainer"] h1 { font-size: 1.6rem; padding-top: 0.25rem; }
}
</style>
"""


def frame_css() -> None:
    """The styles above, once per run (app.py)."""
    st.html(CSS)


def page_columns(spec=(1, 3)):
    """The page's controls and main column (``controls, main``), the main one first on a
    phone."""
    with st.container(key="page"):
        return st.columns(list(spec), gap="large")
