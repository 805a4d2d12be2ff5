"""A fresh visit paints the page's chart first; what only reads the results follows.

On a fresh browser the chart element mounts only when Streamlit's front end has rendered
every element the first run sent, and each kind of element loads its own script the first
time it is shown (a table's grid alone is 1.4 MB): measured in chromium here, a page's
tables, metrics and panels held its first chart back by about 0.4 s (docs/performance.md).

So a page's first run in a session (a fresh visit, a link opened, or the first time a
student turns to that page) sends the widgets and the charts, and leaves out what waits
(``if not waiting(): …`` after a chart, ``if not hold(): …`` before one): tables,
metrics, equations, downloads, the answer and speed panels. Widgets are left out only
where their value is known without them, since nothing can have moved them yet: an input
table's editor under or beside the chart (the rotor's masses, the builder's tables), read
from the link alone (``ui.editor_tables.linked_table``), and the secondary sliders (ω₂, a
cycle's resolution), read as the widget would show them. They come with the whole run. A
first run that held something back and then drew no chart runs again at once, whole
(``rerun_whole``: app.py asks as the page's run ends, a page where it stops).

The first chart drawn in the browser reports its paint (``ui/plot.js``, trigger
"painted"), and the rerun that starts sends the whole page. Any later run of the page is
whole anyway, so a client that draws no charts (a test, the load test) gets the whole page
from its second run on. A chart drawn inside a fragment starts a fragment's run with its
paint: that run becomes the page's (``ui.fragments.fragment``), so what the page left out
outside the fragment comes too.
"""

from __future__ import annotations

from typing import NoReturn

import streamlit as st

from ui.url import stop

PAGE = "first_paint_page"  # the page this run draws (its URL path)
SEEN = "first_paint_seen"  # the pages that have finished a run in this session
CHARTED = "first_paint_charted"  # this run has sent a chart
PAINTED = "first_paint_painted"  # a chart reported its paint: the run it starts is owed whole
HELD = "first_paint_held"  # this first run left something out before its chart (``hold``)


def begin_run(page: str) -> None:
    """Called by app.py before page ``page`` (its URL path) runs."""
    st.session_state[PAGE] = page
    st.session_state[CHARTED] = False
    st.session_state[HELD] = False
    st.session_state.pop(PAINTED, None)  # a whole run pays what a paint asked for


def hold() -> bool:
    """True where what the page draws next may wait for the first chart's paint (a table, a
    metric, an editor, a secondary slider read as the widget would show it: each slider
    above the chart cost the first paint about 15 ms in chromium, docs/performance.md).
    Only in a page's first run, where it is noted: one that then draws no chart runs again
    whole (``rerun_whole``)."""
    if not first_run():
        return False
    st.session_state[HELD] = True
    return True


def end_run() -> None:
    """Called by app.py after the page ran (or stopped)."""
    st.session_state[SEEN] = st.session_state.get(SEEN, frozenset()) | {st.session_state[PAGE]}


def whole() -> None:
    """This run sends all the page shows (a seated student's practice, nothing left out):
    its charts ask for no paint and no second run — 300 students opening a class's page at
    once paid every opening twice (issue 70)."""
    if PAGE in st.session_state:  # (run through app.py)
        end_run()


def finish() -> NoReturn:
    """The page drew all it shows this visitor (a seated student's practice): its run ends
    here, as a run that finished. ``st.stop()`` alone is not enough: what app.py writes at
    a run's end after it (``end_run``) did not stay, so the page's first run never ended
    and its chart's paint never brought the whole page."""
    if PAGE in st.session_state:  # (run through app.py)
        end_run()
    stop()


def rerun_whole() -> None:
    """Asked by app.py as a page's run ends, and by a page before it stops: a first run that
    held something back (``hold``) and drew no chart (a drawing that does not close) gets no
    paint to bring the rest, so the page runs again at once, whole. Otherwise, nothing."""
    if waiting() or not first_run() or not st.session_state.get(HELD):
        return
    whole()
    st.rerun(scope="app")


def painted() -> None:
    """A first run's chart was painted (ui/plot.py's trigger): the run that follows must
    send the whole page."""
    st.session_state[PAINTED] = True


def whole_run_owed() -> bool:
    """Asked as a fragment's run starts: a chart's paint started it, so the page must run
    whole instead (once)."""
    return bool(st.session_state.pop(PAINTED, False))


def first_run() -> bool:
    """True in the first run of this page in the session. Leave something out with it only
    where a chart surely follows in the same run (its paint brings the rest; a run stopped
    by an error first would strand it). After a chart, ask ``waiting``. A page run without
    app.py (a test of the page alone) is never a first run."""
    state = st.session_state
    return PAGE in state and state[PAGE] not in state.get(SEEN, frozenset())


def chart_sent() -> bool:
    """Called for every chart sent: whether it is one of a page's first run, which report
    their paint."""
    if not first_run():
        return False
    st.session_state[CHARTED] = True
    return True


def waiting() -> bool:
    """True in a page's first run once a chart is on its way: leave out what can wait."""
    return first_run() and st.session_state.get(CHARTED, False)
