"""Mehanizmi — entry point: ``streamlit run app.py``. Routes to one page per chapter."""

import copy

import streamlit as st

from ui.boundary import boundary
from ui.chapters import BUILDER, CHAPTERS, CLASSROOM, VARIANTS
from ui.classroom import sidebar_join
from ui.firstpaint import begin_run, end_run
from ui.i18n import current, language_picker, t
from ui.layout import frame_css
from ui.present import projector_switch


def home() -> None:
    st.title("Mehanizmi")
    st.write(t("app.intro"))
    for chapter in (BUILDER, *CHAPTERS, VARIANTS, CLASSROOM):
        with st.container(border=True):
            st.page_link(chapter.file, label=t(chapter.title), icon=chapter.icon)
            st.write(t(chapter.summary))


@st.cache_resource(show_spinner=False, max_entries=8)
def _pages(language: str) -> list[st.Page]:
    """The app's pages in ``language``, made once per process: making them (each resolves its
    path and checks its icon) took 3 ms, a tenth of a seated student's opening."""
    pages = [st.Page(home, title=t("app.home"), icon=":material/home:", default=True)]
    pages += [st.Page(c.file, title=t(c.title), icon=c.icon) for c in (*CHAPTERS, BUILDER, VARIANTS)]
    pages.append(st.Page("pages/textbook_check.py", title=t("check.title"),
                         icon=":material/fact_check:"))
    pages.append(st.Page(CLASSROOM.file, title=t(CLASSROOM.title), icon=CLASSROOM.icon))
    return pages


def navigation_pages() -> list[st.Page]:
    """The app's pages in the page's language, copied for this run: ``st.navigation`` marks
    the page it returns as the one this run may run, a mark no two sessions may share."""
    return [copy.copy(page) for page in _pages(current())]


# an emoji, drawn by the browser: a ":material/…:" favicon is fetched from Google's font CDN,
# which fails in a room without internet and tells a third party of every visit
st.set_page_config(page_title="Mehanizmi", page_icon="⚙️", layout="wide")
with boundary():  # no traceback on any page: one sentence, and the server's log
    language_picker()
    projector_switch()
    frame_css()
    page = st.navigation(navigation_pages())
    sidebar_join()  # (after the pages are known: a first run after a restart may switch at once)
    begin_run(page.url_path)
    try:
        page.run()
    finally:  # (st.stop() and a rerun leave run() by an exception)
        end_run()
