"""Chapter 1 — point paths (a first version: the mechanism at φ₂ over the paths of its points)."""

import streamlit as st

from figures.linkage import instant_figure
from mechanisms import preset_ids
from pages.shared import cycle, driver_slider, preset
from solvers import solve
from solvers.diagnostics import explain_open

st.title(":material/timeline: 1 · Trajectories")
left, right = st.columns([1, 3])
with left:
    preset_id = st.selectbox("Scene", preset_ids(), key="scene",
                             format_func=lambda pid: f"{pid} — {preset(pid).title}")
    scene = preset(preset_id)
    at = driver_slider(scene, key="phi")
    st.caption(f"Source: {scene.source}")
    with st.expander("About this scene"):
        st.write(scene.note)
motion = cycle(preset_id, 360)
now = solve(scene, at, order=0)
with right:
    for issue in now.issues:
        if issue.problem == "open":
            st.warning(explain_open(scene, at, issue))
    paths = [p for p in now.scene.point_names if p not in scene.frame]
    st.plotly_chart(instant_figure(motion, now, paths, scene.title), key="figure")
    st.caption("The greyed paths are computed at 360 positions per cycle; gaps are where the "
               "mechanism cannot be.")
