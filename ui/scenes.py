"""Choosing a scene: a preset, or a TOML file the user uploads; and downloading the current one."""

from __future__ import annotations

import streamlit as st

from mechanisms import Scene, SceneError, parse_scene, preset_ids
from mechanisms.writer import to_toml
from ui.cache import preset
from ui.i18n import t
from ui.url import url_choice

UPLOADED = "upload"


def _read_upload() -> None:
    file = st.session_state.get("upload_file")
    if file is None:
        return
    try:
        st.session_state["uploaded_scene"] = parse_scene(file.getvalue(), source=file.name)
        st.session_state["upload_error"] = None
        st.session_state["scene"] = UPLOADED
    except SceneError as exc:
        st.session_state["upload_error"] = str(exc)


def scene_picker(kinds: tuple[str, ...] | None = None) -> Scene:
    """The scene select box (kept in the URL), an upload, and a download of the scene."""
    options = [pid for pid in preset_ids() if kinds is None or pid.startswith(kinds)]
    uploaded = st.session_state.get("uploaded_scene")
    if uploaded is not None:
        options.append(UPLOADED)

    def label(pid: str) -> str:
        scene = uploaded if pid == UPLOADED else preset(pid)
        return f"{pid} — {scene.title}"

    choice = url_choice(st.selectbox, t("scene.pick"), options, "scene", format_func=label)
    scene = uploaded if choice == UPLOADED else preset(choice)
    with st.expander(t("scene.about")):
        st.caption(scene.source)
        st.write(scene.note)
        st.file_uploader(t("scene.upload"), type=["toml"], key="upload_file", on_change=_read_upload)
        if st.session_state.get("upload_error"):
            st.error(st.session_state["upload_error"])
    return scene


def scene_download(scene: Scene) -> None:
    """The current scene, with the user's changes, as a TOML file that uploads again."""
    st.download_button(t("scene.download"), to_toml(scene).encode("utf-8"), f"{scene.id}.toml",
                       mime="application/toml", on_click="ignore", icon=":material/download:")
