"""The least a Streamlit page can be: one slider and one line of text, served as
"trajectories" so that bench/pages.py drives it like the real pages. Its rerun time is
Streamlit's own floor on this machine."""

import streamlit as st


def page() -> None:
    st.slider("ω₂", 0.0, 100.0, key="omega")
    st.write("floor")


st.navigation([st.Page(page, title="floor", url_path="trajectories")]).run()
