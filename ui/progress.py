"""Long work (a fine survey, a set of timed measurements): done once per scene and shared,
with a progress bar while it runs.

A cached function cannot draw a bar (Streamlit replays what it drew, and a bar from
another run cannot be replayed), so the result is memoised in a shared per-scene dict
and the work runs outside the cache, told how far it is.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

import streamlit as st

from ui.cache import BY_REPR

T = TypeVar("T")


@st.cache_resource(max_entries=64, show_spinner=False, hash_funcs=BY_REPR)
def _memo(scene, what: str, variant: object) -> dict:
    return {}


def measured(scene, what: str, work: Callable[[Callable[[float], None]], T], text: str,
             variant: object = None) -> T:
    """``work(done)`` once per (scene, what, variant); ``done(f)`` moves the bar to f ∈ [0, 1]."""
    memo = _memo(scene, what, variant)
    if "value" not in memo:
        bar = st.progress(0.0, text=text)
        try:
            memo["value"] = work(lambda f: bar.progress(min(max(f, 0.0), 1.0), text=text))
        finally:
            bar.empty()
    return memo["value"]
