"""The app's one error boundary: an exception no page expected is never shown as a
traceback (server paths, a stranger's "Ask Google" buttons) but as one sentence in the
page's language, and the whole traceback goes to the server's log for its administrator.

It wraps a page's run (app.py) and each fragment's (ui.fragments, the class view's and the
store's waiting fragments); Streamlit's own ``client.showErrorDetails = "none"``
(.streamlit/config.toml) is the net under it for a widget's callback. Expected failures —
a refused value, a class that is gone, a store that is down — are said where they happen;
this is for the rest. With ``MEHANIZMI_ERRORS=raise`` (the test suite) the exception
passes, so a test sees it rather than a polite sentence.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Iterator
from contextlib import contextmanager

import streamlit as st

from ui.i18n import t

LOG = logging.getLogger("mehanizmi")
KEY = "unexpected"  # the sentence's element: st-key-unexpected (a test looks for it)


@contextmanager
def boundary() -> Iterator[None]:
    """Run the block; an exception from it is logged with its traceback and said in words.
    (Streamlit's stop and rerun are not exceptions of this kind and pass.)"""
    try:
        yield
    except Exception:
        if os.environ.get("MEHANIZMI_ERRORS") == "raise":
            raise
        LOG.exception("a page's run failed (the user was told in words)")
        with st.container(key=KEY):
            st.error(t("app.unexpected"), icon=":material/error:")
