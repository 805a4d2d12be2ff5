"""Variants for exams and homework: a task's numbers varied, each variant checked to be a
good exercise, with its answer key, printable sheets and a code each student checks with."""

from __future__ import annotations

import json

import pandas as pd
import streamlit as st

from exams.codes import DEFAULT_SPREAD, MAX_SEED, Settings, parse
from exams.moodle import moodle_xml
from exams.sheets import sheets_html
from exams.variants import (
    MAX_COUNT,
    Task,
    VariantError,
    VariantSet,
    as_json,
    generate,
    key_rows,
    symbol,
    task,
)
from mechanisms import SceneError, load_preset, preset_ids
from mechanisms.messages import strings
from ui.cache import page_cache
from ui.chapters import VARIANTS, page_for
from ui.export import dataframe
from ui.i18n import current, message, num, t, title_of
from ui.numbers import number_field, refused_fields


@page_cache(st.cache_resource(max_entries=8, show_spinner=False))
def made(settings: Settings, count: int) -> VariantSet:
    return generate(settings, count)


@page_cache(st.cache_resource(max_entries=16, show_spinner=False))
def task_of(pid: str) -> Task:
    return task(pid)


@page_cache(st.cache_resource(show_spinner=False))
def tasks() -> list[str]:
    """The presets that print answers: a variant's key is their [book] quantities."""
    return [pid for pid in preset_ids() if load_preset(pid).book]


def open_code() -> None:
    """A variant's code in the link (``?v=``, as each variant's link and sheet carry it):
    its set's task, seed, spread and held givens become the page's settings, so a lecturer
    makes the same set again; a damaged code is said, and the page keeps its own."""
    code = st.query_params.get("v")
    if code is None:
        return
    st.query_params.pop("v", None)
    try:
        settings, _ = parse(code)
        if settings.task not in tasks():
            raise VariantError(t("var.no_task", task=settings.task))
    except (SceneError, VariantError) as exc:
        st.session_state["var_code_said"] = ("error", t("var.bad_set_code", reason=message(exc)))
        return
    st.session_state.update({"var_task": settings.task, "var_seed": settings.seed,
                             "var_spread": settings.spread,
                             f"var_hold_{settings.task}": sorted(settings.held)})
    st.session_state["var_code_said"] = ("info", t("var.set_opened", code=code))


st.title(f"{VARIANTS.icon} {t(VARIANTS.title)}")
st.write(t("var.intro"))
open_code()
if said := st.session_state.pop("var_code_said", None):  # (said once, as the page opens)
    getattr(st, said[0])(said[1], icon=":material/link:" if said[0] == "info" else ":material/link_off:")
titles = {pid: f"{pid} — {title_of(load_preset(pid))}" for pid in tasks()}  # in this language
choice = st.selectbox(t("var.task"), tasks(), key="var_task", format_func=titles.__getitem__,
                      index=tasks().index("zbirka-3.1"))  # the course's exam favourite
givens = task_of(choice).givens
c1, c2, c3, c4 = st.columns(4)
count = number_field(t("var.count"), "var_count", 30, minimum=1, maximum=MAX_COUNT, integer=True,
                     where=c1)
seed = number_field(t("var.seed"), "var_seed", 1, minimum=0, maximum=MAX_SEED, integer=True,
                    where=c2)
spread = c3.slider(t("var.spread"), 1, 50, DEFAULT_SPREAD, key="var_spread")
sheet_languages = {"sr": t("var.language_sr"), "en": t("var.language_en")}
language = c4.radio(t("var.language"), tuple(sheet_languages), index=0 if current() != "en" else 1,
                    format_func=sheet_languages.__getitem__, key="var_language", horizontal=True)
named = [f"{g.label} = {num(g.value, 6)} {g.unit}".strip() for g in givens]
held = st.multiselect(t("var.hold"), range(len(givens)), key=f"var_hold_{choice}",
                      format_func=named.__getitem__, placeholder=t("var.hold_none"))
settings = Settings(choice, int(seed), int(spread), frozenset(held))

why = refused_fields({"var_count": t("var.count"), "var_seed": t("var.seed")})
if st.button(t("var.make"), type="primary", icon=":material/casino:", disabled=why is not None,
             help=why):
    try:
        with st.spinner(t("var.making")):
            st.session_state["var_made"] = (settings, int(count), made(settings, int(count)))
    except VariantError as exc:
        st.session_state.pop("var_made", None)
        st.error(t("var.none", reason=message(exc)))

result = st.session_state.get("var_made")
if result is not None and result[:2] == (settings, int(count)):
    found = result[2]
    if found.shortfall:
        st.warning(t("var.short", reason=message(found.shortfall)))
    page = page_for(choice).removeprefix("pages/").removesuffix(".py")
    dataframe(pd.DataFrame([{
        t("var.col_code"): v.code,
        **{g.label: f"{num(value, 6)} {g.unit}".strip() for g, value in v.given},
        t("var.col_link"): f"/{page}?v={v.code}"} for v in found.variants]),
        hide_index=True, column_config={t("var.col_link"): st.column_config.LinkColumn()})
    title = load_preset(choice)
    title = title.title_sr if language == "sr" and title.title_sr else title.title
    key = pd.DataFrame(key_rows(found))
    box = st.expander(t("var.key"), key="var_key_open", on_change="rerun")
    if box.open:  # filled only while open
        with box:
            dataframe(key.assign(quantity=key["quantity"].map(symbol)), hide_index=True)
    stem = f"{choice}-S{settings.seed}"
    d1, d2, d3, d4 = st.columns(4)
    d1.download_button(t("var.sheets"), lambda: sheets_html(found, title, language).encode("utf-8"),
                       f"{stem}-sheets.html", mime="text/html", on_click="ignore",
                       icon=":material/print:")
    d2.download_button(t("var.key_csv"), lambda: key.to_csv(index=False).encode("utf-8"),
                       f"{stem}-key.csv", mime="text/csv", on_click="ignore",
                       icon=":material/download:")
    d3.download_button("JSON", lambda: json.dumps(as_json(found), indent=1, ensure_ascii=False).encode("utf-8"),
                       f"{stem}.json", mime="application/json", on_click="ignore",
                       icon=":material/data_object:")
    d4.download_button(t("var.moodle"), lambda: moodle_xml(
        found, title, language, strings(language).__getitem__).encode("utf-8"),
        f"{stem}-moodle.xml", mime="application/xml", on_click="ignore",
        icon=":material/school:", help=t("var.moodle_help"))
    st.caption(t("var.students"))
