"""Cached loading and solving shared by the chapter pages (Streamlit reruns on every change)."""

from __future__ import annotations

import numpy as np
import streamlit as st

from mechanisms import Scene, load_preset
from solvers import Motion, solve
from solvers.diagnostics import sweep_values


@st.cache_resource(max_entries=64)
def preset(preset_id: str) -> Scene:
    """A preset scene; never mutated (frozen dataclasses), so it is shared, not copied."""
    return load_preset(preset_id)


@st.cache_resource(max_entries=64)
def cycle(preset_id: str, steps: int) -> Motion:
    """Positions of the whole cycle, for paths (positions only: paths need no more)."""
    scene = preset(preset_id)
    return solve(scene, sweep_values(scene, steps), order=0)


def driver_slider(scene: Scene, key: str) -> float:
    """A slider for the driver coordinate; returns it in SI (rad or m)."""
    if scene.driver.kind == "rotating":
        deg = st.slider("φ₂ — crank angle [°]", 0.0, 359.0, float(np.degrees(scene.driver.at)),
                        step=1.0, key=key)
        return float(np.radians(deg))
    lo, hi = sweep_values(scene, 2)[[0, -1]]
    return st.slider("s — slider position [m]", float(lo), float(hi), float(scene.driver.at),
                     step=0.001, key=key, format="%.3f")
