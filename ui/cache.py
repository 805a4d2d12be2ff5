"""Cached loading and solving shared by the pages (Streamlit reruns the page on every change).

Scenes are frozen dataclasses; they are hashed by their ``repr`` (every parameter shows
there), so a changed slider is a new cache entry and an unchanged page costs nothing.
Results are cached as shared objects (``cache_resource``) and never mutated.

Caches whose work takes far less than Streamlit's spinner delay (0.5 s) say
``show_spinner=False``, here and in the pages: on every miss a spinner starts a timer thread
and sends a message to clear itself, for nothing the user would see. Only the kinetostatics
cycle (up to 3600 positions) and the textbook check keep theirs.
"""

from __future__ import annotations

import streamlit as st

from mechanisms import Scene, load_preset
from solvers import Motion, solve
from solvers.diagnostics import solve_instant
from solvers.paths import cycle_values
from solvers.triads import TOL

BY_REPR = {Scene: repr}


@st.cache_resource(max_entries=64, show_spinner=False)
def preset(preset_id: str) -> Scene:
    return load_preset(preset_id)


@st.cache_resource(max_entries=128, show_spinner=False, hash_funcs=BY_REPR)
def cycle(scene: Scene, steps: int, order: int = 0) -> Motion:
    """The scene at ``steps`` equal positions over the cycle, from its instant
    (``solvers.paths.cycle_values``): keyed by the count, not by thousands of values."""
    return solve(scene, cycle_values(scene, steps), order=order)


@st.cache_resource(max_entries=64, show_spinner=False, hash_funcs=BY_REPR)
def instant(scene: Scene, tol: float = TOL) -> Motion:
    """The scene solved at its own instant, class III groups to ``tol`` (raises Unsolvable
    with the reason)."""
    return solve_instant(scene, None, tol)
