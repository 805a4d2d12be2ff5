"""A class (Čas): a lecturer starts one — a scene, a method, an instant — and gets a join
code, a link and a QR code to project, and a secret link to the results; a student joins
by the code from a phone, with a nickname, and practises on the method's page, every check
stored (classes.store, docs/classes.md)."""

from __future__ import annotations

import streamlit as st

from classes import store
from classes.methods import METHODS
from classes.steps import practice_link
from classes.store import ClassError, closed_at
from exams.codes import parse
from mechanisms import SceneError
from mechanisms.link import PARAMETER
from ui.chapters import CLASSROOM
from ui.classroom import close_sidebar
from ui.classview import view
from ui.i18n import current, message, t
from ui.joinpanel import MADE, join_panel
from ui.numbers import number_field, refused_fields
from ui.scenes import preset_titles


def start() -> None:
    """The lecturer's form: what the class practises."""
    st.write(t("class.intro"))
    method = st.selectbox(t("class.method"), list(METHODS), key="class_method",
                          format_func=lambda m: t(f"class.method_{m}"))
    titles = preset_titles(METHODS[method].scenes, current())
    scene = st.selectbox(t("class.scene"), list(titles), key=f"class_scene_{METHODS[method].scenes}",
                         format_func=titles.get)
    link = st.text_input(t("class.link"), key="class_link", placeholder=f"{PARAMETER}=…")
    variants = st.text_input(t("class.variants"), key="class_variants", placeholder="3.1-S42-01K")
    at = number_field(t("class.at"), "class_at", optional=True)
    test = st.checkbox(t("class.test"), key="class_test")
    why = refused_fields({"class_at": t("class.at")})  # (never at an instant nobody typed)
    if st.button(t("class.start"), type="primary", icon=":material/groups:",
                 disabled=why is not None, help=why):
        try:
            if variants.strip():
                settings, _ = parse(variants.strip())
                scene = settings.task
            chosen = link.strip() if link.strip().startswith(f"{PARAMETER}=") else scene
            code, key = store.create(chosen, method, at, variants.strip().upper() or None, test=test)
        except (ClassError, SceneError) as exc:
            st.error(message(exc.args[0] if isinstance(exc, ClassError) else exc))
            return
        # the page's address becomes the lecturer's link: any rerun or reload keeps it
        st.query_params.update({"class": code, "key": key, MADE: "1"})
        st.rerun()


def join(code: str) -> None:
    """A student's first visit: a nickname (or the one given), then off to practise."""
    close_sidebar()
    try:
        found = store.find(code)
    except ClassError as exc:
        st.error(message(exc.args[0]))
        return
    st.header(t("class.join_title", code=found.code))
    st.caption(t(f"class.method_{found.method}"))
    if found.test and found.closed is not None:  # its grades are given: no new seat
        st.info(t("class.test_closed_join", at=closed_at(found)), icon=":material/lock:")
        return
    nickname = st.text_input(t("class.nickname"), key="class_nickname", max_chars=store.NICKNAME_MAX)
    if st.button(t("class.join"), type="primary", icon=":material/login:"):
        try:
            token = store.join(found.code, nickname)
        except ClassError as exc:  # (closed, deleted or ended a moment ago)
            st.error(message(exc.args[0]))
            return
        go(found, token)


def go(found: store.Class, token: str) -> None:
    """To the method's page, on the class's scene (or this student's variant), practice on."""
    page, params = practice_link(found, token, current())
    st.switch_page(f"pages/{page}.py", query_params=params)  # (practice is on there)


st.title(f"{CLASSROOM.icon} {t(CLASSROOM.title)}")
query = st.query_params
if query.get("join"):
    join(query["join"])
elif query.get("class") and query.get("key"):
    top = st.container()  # the join code above the results, once the key opened them
    if view(query["class"], query["key"]):
        with top:
            if query.get(MADE):
                join_panel(query["class"], query["key"])
            else:
                st.button(t("class.show_panel"), icon=":material/qr_code:",
                          on_click=lambda: st.query_params.update({MADE: "1"}))
else:
    start()
