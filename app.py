"""Mehanizmi — entry point: ``streamlit run app.py``. Routes to one page per chapter."""

import streamlit as st

from ui.boundary import boundary
from ui.chapters import navigation_pages
from ui.classroom import seated_on, sidebar_join
from ui.firstpaint import begin_run, end_run, rerun_whole
from ui.i18n import language_picker
from ui.present import projector_switch
from ui.url import link_sent

# an emoji, drawn by the browser: a ":material/…:" favicon is fetched from Google's font CDN,
# which fails in a room without internet and tells a third party of every visit
st.set_page_config(page_title="Mehanizmi", page_icon="⚙️", layout="wide",
                   initial_sidebar_state="auto")
with boundary(), link_sent():  # no traceback on any page: one sentence, and the server's
    # log; the link's changes in one message
    language_picker()
    page = st.navigation(navigation_pages())
    if not seated_on(page.url_path):  # (a seated student's page: the class's practice alone)
        projector_switch()
        sidebar_join()  # (after the pages are known: a first run after a restart may switch at once)
    begin_run(page.url_path)
    try:
        page.run()
        rerun_whole()  # (a first run that held something back and drew no chart: again)
    finally:  # (st.stop() and a rerun leave run() by an exception)
        end_run()
