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

import functools
from collections.abc import Callable
from types import CodeType
from typing import TypeVar

import streamlit as st

from mechanisms import Scene, load_preset
from solvers import Motion, solve
from solvers.diagnostics import solve_instant
from solvers.paths import cycle_values
from solvers.triads import TOL

BY_REPR = {Scene: repr}
F = TypeVar("F", bound=Callable)
_APPLIED: dict[CodeType, Callable] = {}


def page_cache(decorator: Callable[[F], F]) -> Callable[[F], F]:
    """``decorator`` (``st.cache_resource(...)`` or ``st.cache_data(...)``) applied once per
    process to a function defined in a page script. A page defines its functions anew on
    every run, and Streamlit's decorator reads and hashes the function's source each time
    it is applied: about 0.5 ms a function, 5 % of a rerun of the trajectories page.

    The wrapper is kept per code: each run's function has the last run's code, and code
    objects compare by their content, so a page compiled again unchanged (Streamlit does
    when every session has left) finds the same wrapper, and an edited page gets a new one.
    Such a function must read only its arguments and the page's imports and constants, as
    any cached function shared by every session must: the first run's are the ones it
    sees."""
    def apply(func: F) -> F:
        if func.__code__ not in _APPLIED:
            _APPLIED[func.__code__] = decorator(func)
        return _APPLIED[func.__code__]  # type: ignore[return-value]
    return apply


def same_call(cached: F) -> F:
    """``cached`` asked again with the very same arguments as its last call (the same
    objects: a run hands its scene from call to call) answers as then, without Streamlit
    hashing them again: a scene's key is its repr, 0.27 ms a call, and the plans page asked
    for its instant four times a run. Only for arguments that cannot change (frozen scenes,
    numbers, strings, tuples): the same object then means the same key. An exception is not
    kept. Sessions share the one last call; one that finds another's answers it alike."""
    last: list[tuple | None] = [None]  # (args, kwargs, result) of the last call

    @functools.wraps(cached)
    def call(*args, **kwargs):
        seen = last[0]
        if (seen is not None and len(seen[0]) == len(args) and seen[1].keys() == kwargs.keys()
                and all(a is b for a, b in zip(seen[0], args))
                and all(seen[1][k] is v for k, v in kwargs.items())):
            return seen[2]
        result = cached(*args, **kwargs)
        last[0] = (args, kwargs, result)
        return result
    return call  # type: ignore[return-value]


@st.cache_resource(max_entries=64, show_spinner=False)
def preset(preset_id: str) -> Scene:
    return load_preset(preset_id)


@same_call
@st.cache_resource(max_entries=128, show_spinner=False, hash_funcs=BY_REPR)
def cycle(scene: Scene, steps: int, order: int = 0) -> Motion:
    """The scene at ``steps`` equal positions over the cycle, from its instant
    (``solvers.paths.cycle_values``): keyed by the count, not by thousands of values."""
    return solve(scene, cycle_values(scene, steps), order=order)


@same_call
@st.cache_resource(max_entries=64, show_spinner=False, hash_funcs=BY_REPR)
def instant(scene: Scene, tol: float = TOL) -> Motion:
    """The scene solved at its own instant, class III groups to ``tol`` (raises Unsolvable
    with the reason)."""
    return solve_instant(scene, None, tol)
