"""Mehanizmi — entry point: ``streamlit run app.py``. Routes to one page per chapter."""

import streamlit as st

from pages.chapters import CHAPTERS


def home() -> None:
    st.title("Mehanizmi")
    st.write("Kinematics and dynamics of planar mechanisms for the course *Mechanisms of "
             "Agricultural Machines*: every number computed exactly, every figure drawn from "
             "that solution.")
    for chapter in CHAPTERS:
        with st.container(border=True):
            st.page_link(chapter.file, label=chapter.title, icon=chapter.icon)
            st.write(chapter.summary)
            if not chapter.ready:
                st.caption("Coming soon.")


st.set_page_config(page_title="Mehanizmi", page_icon=":material/settings:", layout="wide")
pages = [st.Page(home, title="Home", icon=":material/home:", default=True)]
pages += [st.Page(c.file, title=c.title, icon=c.icon) for c in CHAPTERS]
st.navigation(pages).run()
