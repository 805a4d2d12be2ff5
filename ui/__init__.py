"""What the chapter pages share: strings and languages, cached solving, the scene picker,
URL state and the chart element.

Importing it also settles how the pages are routed. Streamlit still treats a folder named ``pages/`` beside the main script as a legacy
multipage app until the first script run calls ``st.navigation``. When a user's very first
visit opens a chapter URL directly, that run would show the legacy page list (every module
in this folder). So the first import in the process switches the legacy mode off and reruns
once, and the rerun goes through app.py's navigation like every later one. Imported before
any session (scripts/serve.py imports every ``ui`` module first), it switches the mode off
before a first run can take it.
"""

import streamlit as st
from streamlit.runtime.pages_manager import PagesManager
from streamlit.runtime.scriptrunner import get_script_run_ctx

if PagesManager.uses_pages_directory is not False:  # (None: no session yet — the server
    legacy = PagesManager.uses_pages_directory     # imports us before it serves, serve.py)
    PagesManager.uses_pages_directory = False
    if legacy and get_script_run_ctx() is not None:
        st.rerun()
