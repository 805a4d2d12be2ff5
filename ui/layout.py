"""The page's frame for every screen: controls beside the charts on a laptop or a projector,
the charts first on a phone; captions dark enough to read (WCAG's 4.5:1).

Streamlit stacks a row of columns below 640 px in their order, so a chapter page's column of
sliders came first and its chart two to four screens down. ``page_columns`` keys the page's
row, and on a narrow screen that row alone is shown in reverse: the chart (with its own φ₂
control under it) comes first, the rest of the controls follow. What a page puts in a
container keyed ``later…`` (an input table, a results table above the charts) moves after
the charts there, and a row of metrics stays two abreast instead of four screens long.
"""

from __future__ import annotations

import streamlit as st

CSS = """
<style>
/* captions: Streamlit draws them at 60 % opacity, 3.0:1 on white; these are 6.6:1 */
[data-testid="stCaptionContainer"] { opacity: 1; color: #5c5e66; }
/* a page's sections are h2 under its h1 (no level skipped), at a subheading's size */
[data-testid="stHeading"] h2 { font-size: 1.5rem; padding-top: 0.75rem; }
@media (max-width: 640px) {
  .st-key-page > div > [data-testid="stHorizontalBlock"],
  .st-key-page > [data-testid="stHorizontalBlock"] { flex-direction: column-reverse; }
  /* a stacked column no wider than the screen: the metrics' rule below sizes a row's columns
     by their content, and a long scene name in the picker pushed the page 90 px sideways */
  .st-key-page [data-testid="stColumn"] { max-width: 100%; }
  [class*="st-key-later"], div:has(> [class*="st-key-later"]) { order: 1; }
  [data-testid="stHorizontalBlock"]:has(> [data-testid="stColumn"] > [data-testid="stVerticalBlock"]
    > [data-testid="stElementContainer"] > [data-testid="stMetric"]) { flex-wrap: wrap; }
  [data-testid="stHorizontalBlock"]:has(> [data-testid="stColumn"] > [data-testid="stVerticalBlock"]
    > [data-testid="stElementContainer"] > [data-testid="stMetric"]) > [data-testid="stColumn"] {
    flex: 1 1 40% !important; min-width: 40% !important; width: auto !important; }
  [data-testid="stMetricValue"] { font-size: 1.6rem; }
  /* the builder: its drawing held at the top while the tables scroll under it, so that an
     edit, a drag or a flip is seen from where one types (the two columns' contents flow as
     one, the drawing first, the tables next, the checks after) */
  .st-key-build_bench [data-testid="stHorizontalBlock"] { flex-direction: column; }
  .st-key-build_bench [data-testid="stHorizontalBlock"] > [data-testid="stColumn"],
  .st-key-build_bench [data-testid="stHorizontalBlock"] > [data-testid="stColumn"]
    > [data-testid="stVerticalBlock"] { display: contents; }
  div:has(> .st-key-build_sheet) { position: sticky; top: 3.75rem; z-index: 5;
    background: white; order: -2; box-shadow: 0 6px 6px -6px rgba(0, 0, 0, 0.3); }
  div:has(> .st-key-build_tables) { order: -1; }
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
