"""A fresh visit paints the page's chart first; what only reads the results follows.

On a fresh browser the chart element mounts only when Streamlit's front end has rendered
every element the first run sent, and each kind of element loads its own script the first
time it is shown (a table's grid alone is 1.4 MB): measured in chromium here, a page's
tables, metrics and panels held its first chart back by about 0.4 s (docs/performance.md).

So the session's first run sends the widgets and the charts, and leaves out what waits
(``if not waiting(): …`` after a chart, ``first_run`` before one): tables, metrics, equations, downloads, the answer and speed
panels. Widgets are never left out (Streamlit forgets a widget a run does not draw). The
first chart drawn in the browser reports its paint (``ui/plot.js``, trigger "painted"),
and the rerun that starts sends the whole page. Any later run is whole anyway, so a client
that draws no charts (a test, the load test) gets the whole page from its second run on.
"""

from __future__ import annotations

import streamlit as st

RAN = "first_paint_ran"  # a run of this session has finished
CHARTED = "first_paint_charted"  # the session's first run has sent a chart


def end_run() -> None:
    """Called by app.py after the page ran (or stopped)."""
    st.session_state[RAN] = True


def first_run() -> bool:
    """True in the session's first run. Ask it only on a path that goes on to draw a chart
    (that chart's paint is what brings the rest); after a chart, ask ``waiting``."""
    return not st.session_state.get(RAN, False)


def chart_sent() -> bool:
    """Called for every chart sent: whether it is one of the session's first run, which
    report their paint."""
    if not first_run():
        return False
    st.session_state[CHARTED] = True
    return True


def waiting() -> bool:
    """True in the session's first run once a chart is on its way: leave out what can wait."""
    return first_run() and st.session_state.get(CHARTED, False)
