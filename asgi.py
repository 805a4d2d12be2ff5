"""The app as served (scripts/start.sh, deploy/start.sh): ``app.py``'s pages through
Streamlit's public ``st.App``, with the LTI 1.3 routes beside them (lti/routes.py) and,
while it runs, the thread that sends scores to the platforms' gradebooks (lti/grades.py).
``streamlit run asgi.py`` (scripts/serve.py) finds ``app`` and serves it."""

from __future__ import annotations

import threading
from contextlib import asynccontextmanager

import streamlit as st

from lti import grades
from lti.routes import ROUTES


@asynccontextmanager
async def scores_sent(_app):
    """Send due scores every few seconds while the server runs."""
    stop = threading.Event()
    sender = threading.Thread(target=grades.worker, args=(stop,), name="lti-scores", daemon=True)
    sender.start()
    try:
        yield None
    finally:
        stop.set()


app = st.App("app.py", routes=ROUTES, lifespan=scores_sent)
