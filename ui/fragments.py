"""``st.fragment`` for the pages: a part of a page that a control reruns alone."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import TypeVar

import streamlit as st

from ui.i18n import run_language

F = TypeVar("F", bound=Callable)


def fragment(func: F) -> F:
    """``func`` as a fragment whose runs know the page's language. A fragment's run skips
    app.py, where ``language_picker`` reads the language once per run; without it each of
    the hundred or so ``t()`` of a run read the session instead (a fifth of a fragment run
    on the plans page, measured with py-spy)."""
    @functools.wraps(func)
    def run(*args, **kwargs):
        run_language()
        return func(*args, **kwargs)

    return st.fragment(run)  # type: ignore[return-value]
