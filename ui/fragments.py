"""``st.fragment`` for the pages: a part of a page that a control reruns alone."""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import NamedTuple, TypeVar

import streamlit as st
from streamlit.delta_generator import DeltaGenerator

from mechanisms.schema import Scene
from ui.boundary import boundary
from ui.crank import live
from ui.firstpaint import whole_run_owed
from ui.i18n import run_language
from ui.scenes import driver_position, scene_download
from ui.url import link_sent

F = TypeVar("F", bound=Callable)


def fragment(func: F) -> F:
    """``func`` as a fragment whose runs know the page's language. A fragment's run skips
    app.py, where ``language_picker`` reads the language once per run; without it each of
    the hundred or so ``t()`` of a run read the session instead (a fifth of a fragment run
    on the plans page, measured with py-spy).

    A run that a first chart's paint started becomes the page's run: what a page's first
    run leaves out may sit outside the fragment (ui/firstpaint.py)."""
    @functools.wraps(func)
    def run(*args, **kwargs):
        if whole_run_owed():
            st.rerun(scope="app")
        run_language()
        with boundary(), link_sent():
            return func(*args, **kwargs)

    return st.fragment(run)  # type: ignore[return-value]


class Places(NamedTuple):
    """Where a φ₂ fragment writes in the controls column, made by the page's full run: the
    position slider's place (above the page's other controls), and the place under them that
    holds the scene's download and then the answer box. One place for both, not one each:
    each outside place a fragment writes to costs a block of its own on every run."""
    position: DeltaGenerator
    below: DeltaGenerator


def at_position(places: Places, base: Scene) -> tuple[Scene, bool, DeltaGenerator]:
    """How every φ₂ fragment starts: the φ₂ (or s) slider and the scene there, its download,
    whether a chart's own φ₂ control asked for the frames (``ui.crank.live``), and the answer
    box's place (``places.below``, under the download). Both places are written on every
    run, as a fragment must write where it wrote in the page's last full run: a first run
    that leaves the answer box out still writes the download there."""
    asked = live()
    with places.position:
        scene = driver_position(base)
    with places.below:
        scene_download(scene)
    return scene, asked, places.below
