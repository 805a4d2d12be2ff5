"""Choosing a scene: a preset, a scene carried by the link (``?s=``, e.g. from the builder),
or a TOML file the user uploads; and downloading the current one."""

from __future__ import annotations

import hashlib
import math

import streamlit as st

from exams.codes import parse
from exams.variants import VariantError, from_code
from mechanisms import Scene, SceneError, parse_document, preset_ids
from mechanisms.gears import GearTrain
from mechanisms.link import PARAMETER, decode, encode
from mechanisms.messages import text_of
from mechanisms.rotor import Rotor
from mechanisms.writer import to_text
from ui.cache import preset
from ui.chapters import page_for
from ui.crank import OMEGA, PHI
from ui.i18n import current, message, note_of, source_of, t, title_of
from ui.numbers import bound_link, bound_slider, link_option, slider

UPLOADED = "upload"


KINDS = {"linkage": Scene, "rotor": Rotor, "gears": GearTrain}


def of_kind(scene, kind: str, source: str):
    """``scene`` if it is of ``kind`` (a linkage on a linkage page), else SceneError."""
    if not isinstance(scene, KINDS[kind]):
        raise SceneError(t("scene.wrong_kind", file=source, kind=kind))
    return scene


def read_upload(file, kind: str):
    """An uploaded file's scene of ``kind``; SceneError says what is wrong with it."""
    return of_kind(parse_document(file.getvalue(), source=file.name), kind, file.name)


@st.cache_resource(max_entries=64, show_spinner=False)
def from_link(text: str):
    """The scene a link's ``s=`` carries (SceneError, not cached, when it carries none)."""
    return decode(text)


def link_choice(text: str) -> str:
    """The select box's option for a linked scene: one per scene, so that a page's inputs
    start from each new scene's own values (ui.url.seed)."""
    return "link-" + hashlib.sha1(text.encode("ascii", "replace")).hexdigest()[:8]


VARIANT = "v"  # ?v=3.1-S42-07K: a student's variant, by the code on their sheet


@st.cache_resource(max_entries=64, show_spinner=False)
def variant_link(code: str) -> tuple[str, str]:
    """(the link text of the variant a code names, the page it belongs on); SceneError or
    VariantError when the code is damaged or names no variant."""
    variant = from_code(code)
    return encode(variant.scene), page_for(parse(code)[0].task)


def _open_variant(kind: str) -> None:
    """A variant code in the URL becomes its scene's link (``s=``), on the page of its kind;
    a damaged code, or one for another chapter, says so."""
    code = st.query_params.get(VARIANT)
    if not code:
        return
    st.query_params.pop(VARIANT, None)
    try:
        with st.spinner(t("var.opening", code=code)):
            text, page = variant_link(code)
    except (SceneError, VariantError) as exc:
        st.session_state["code_error"] = text_of(exc)
        return
    try:
        of_kind(from_link(text), kind, code)
    except SceneError:
        st.session_state["code_error"] = t("var.other_page", code=code)
        st.page_link(page, label=t("check.open"), icon=":material/open_in_new:",
                     query_params={VARIANT: code})
        return
    st.query_params[PARAMETER] = text


def _linked(kind: str):
    """(option, scene, opened now) for the link's scene, or None; a damaged link says why and
    is dropped, and the page goes on with its default scene."""
    _open_variant(kind)
    in_url = st.query_params.get(PARAMETER)
    text = in_url or st.session_state.get("linked_text")
    if not text:
        return None
    try:
        scene = of_kind(from_link(text), kind, "link")
    except SceneError as exc:
        st.session_state.pop("linked_text", None)
        st.query_params.pop(PARAMETER, None)
        st.session_state["link_error"] = text_of(exc)
        return None
    opened = bool(in_url) and st.session_state.get("linked_text") != in_url
    st.session_state["linked_text"] = text
    return link_choice(text), scene, opened


def _forget_errors() -> None:
    """Another scene picked: the last link's or code's error no longer applies."""
    st.session_state.pop("link_error", None)
    st.session_state.pop("code_error", None)


def _read_upload(kind: str) -> None:
    file = st.session_state.get("upload_file")
    if file is None:
        return
    try:
        st.session_state["uploaded_scene"] = read_upload(file, kind)
        st.session_state["upload_error"] = None
        st.session_state["scene"] = UPLOADED
    except SceneError as exc:
        st.session_state["upload_error"] = text_of(exc)


@st.cache_resource(max_entries=16, show_spinner=False)
def preset_titles(kind: str, language: str) -> dict[str, str]:
    """"id — title" of every preset of a kind, for the select box (made once per language)."""
    return {pid: f"{pid} — {title_of(preset(pid), language)}" for pid in preset_ids(kind)}


def scene_picker(kind: str = "linkage", default: str | None = None):
    """The scene select box (kept in the URL; ``default`` when the link names none), an
    upload, and a download of the scene."""
    options = preset_ids(kind)
    linked = _linked(kind)
    if linked is not None:
        options.append(linked[0])
        if linked[2]:
            st.session_state["scene"] = linked[0]  # a link just opened: show its scene
    uploaded = st.session_state.get("uploaded_scene")
    if not isinstance(uploaded, KINDS[kind]):
        uploaded = None
    if uploaded is not None:
        options.append(UPLOADED)

    titles = preset_titles(kind, current())

    def label(pid: str) -> str:
        if pid == UPLOADED:
            return f"{pid} — {title_of(uploaded)}"
        if linked is not None and pid == linked[0]:
            return f"{t('scene.linked')} — {title_of(linked[1])}"
        return titles[pid]

    if st.session_state.get("link_error"):
        st.error(t("scene.bad_link", reason=message(st.session_state["link_error"])))
    if st.session_state.get("code_error"):
        st.error(t("var.bad_code", reason=message(st.session_state["code_error"])))
    choice = link_option(st.selectbox, t("scene.pick"), options, "scene", default=default,
                        format_func=label, on_change=_forget_errors)
    if linked is not None and choice == linked[0]:
        scene = linked[1]
        st.query_params[PARAMETER] = st.session_state["linked_text"]
    else:
        st.query_params.pop(PARAMETER, None)
        scene = uploaded if choice == UPLOADED else preset(choice)
    about = st.expander(t("scene.about"), key="about", on_change="rerun")
    if about.open:  # filled only while open: closed, it costs a rerun nothing
        with about:
            st.caption(source_of(scene))
            st.write(note_of(scene))
            st.file_uploader(t("scene.upload"), type=["toml"], key="upload_file",
                             on_change=_read_upload, args=(kind,))
            if st.session_state.get("upload_error"):
                st.error(message(st.session_state["upload_error"]))
    return scene


def scene_download(scene) -> None:
    """The current scene, with the user's changes, as a TOML file that uploads again, written
    when the button is pressed (as every download here): not on each of φ₂'s reruns."""
    st.download_button(t("scene.download"), lambda: to_text(scene).encode("utf-8"),
                       f"{scene.id}.toml", mime="application/toml", on_click="ignore",
                       icon=":material/download:")


def driver_start(base: Scene) -> float:
    """The driver slider's value for the scene's own instant: φ₂ in degrees within the
    slider's 0–360° (a file or a variant may say −6°), or s in metres."""
    if base.driver.kind == "rotating":
        return math.degrees(base.driver.at) % 360.0
    return base.driver.at


def driver_position(base: Scene) -> Scene:
    """The driver's position slider (φ₂ in degrees, or s in m for a slider), kept in the URL
    as ``at``; the scene at that position."""
    if base.driver.kind == "rotating":
        low, high, step = PHI
        at = bound_slider(t("plans.phi"), low, high, step=step, key="at")
        if at == driver_start(base):
            return base  # the file's φ₂ exactly: radians(degrees(φ)) may differ in the last bit
        return base.with_(at=math.radians(at))
    low, high = base.driver.range()
    at = bound_slider(t("plans.s"), low, high, step=round(high / 300, 4), key="at")
    return base.with_(at=at)


def length_range(length: float) -> tuple[float, float, float]:
    """A length slider's ends and step: a quarter to twice ``length``, in hundredths of it."""
    return round(length / 4, 4), round(length * 2, 4), round(length / 100, 5)


def length_slider(base: Scene, number: int, **options) -> float:
    """Member ``number``'s length (key ``L<number>``), from a quarter to twice its length in
    ``base``: the trajectories page's, and its floor's in bench/floor_chart_app.py."""
    member = base.members[number]
    lo, hi, step = length_range(base.lengths[number])
    label = t("traj.length", link="".join(member.axis), member=number)
    if options.get("bind"):
        bound_link(f"L{number}", label, lo, hi)
    return slider(label, lo, hi, step=step, format="%.4f", key=f"L{number}", **options)


def driver_speed(scene: Scene, wait: bool = False) -> Scene:
    """The driver's speed slider (``omega`` in the URL): ω₂, or v for a slider; ``wait`` as
    for ``ui.numbers.bound_slider``."""
    if scene.driver.kind == "rotating":
        low, high, step = OMEGA
        speed = bound_slider(t("plans.omega"), low, high, step=step, key="omega", wait=wait)
    else:
        speed = bound_slider(t("plans.v"), -10.0, 10.0, step=0.1, key="omega", wait=wait)
    return scene.with_(speed=speed)
