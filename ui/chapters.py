"""The six chapters of the course: one page each. Shared by the router and the home page."""

from __future__ import annotations

import copy
from dataclasses import dataclass

import streamlit as st

from ui.i18n import current, t


@dataclass(frozen=True)
class Chapter:
    file: str
    title: str  # string keys (see locales/)
    summary: str
    icon: str


CHAPTERS = (
    Chapter("pages/trajectories.py", "ch1.title", "ch1.summary", ":material/timeline:"),
    Chapter("pages/velocity_plans.py", "ch2.title", "ch2.summary", ":material/straighten:"),
    Chapter("pages/assur_groups.py", "ch4.title", "ch4.summary", ":material/account_tree:"),
    Chapter("pages/kinetostatics.py", "ch5.title", "ch5.summary", ":material/balance:"),
    Chapter("pages/planetary_gears.py", "ch6.title", "ch6.summary", ":material/settings:"),
    Chapter("pages/rotor_balancing.py", "ch7.title", "ch7.summary", ":material/autorenew:"),
)


# not a chapter: where a student's own mechanism is made, for every linkage chapter
BUILDER = Chapter("pages/builder.py", "build.title", "build.summary", ":material/draw:")
# not a chapter (beyond the book): a four-bar found for the points of a path, opened in the builder
SYNTHESIS = Chapter("pages/synthesis.py", "syn.title", "syn.summary", ":material/design_services:")
# for lecturers: a task's variants with keys and sheets; students open theirs by its code
VARIANTS = Chapter("pages/variants.py", "var.title", "var.summary", ":material/quiz:")
# a lecturer's class: students join by a code and their checks are stored (docs/classes.md)
CLASSROOM = Chapter("pages/class.py", "class.title", "class.summary", ":material/groups:")


def chapter(file: str) -> Chapter:
    return next(c for c in CHAPTERS if c.file == file)


def page_title(file: str) -> None:
    c = chapter(file)
    st.title(f"{c.icon} {t(c.title)}")


def page_for(preset_id: str) -> str:
    """The page a preset belongs to, from its task number (zbirka-7.1 → rotor balancing)."""
    chapter = preset_id.split("-")[-1].split(".")[0]
    if preset_id.startswith("analitika"):
        chapter = "2"
    pages = {"1": "trajectories", "2": "velocity_plans", "3": "velocity_plans",
             "4": "assur_groups", "5": "kinetostatics", "6": "planetary_gears",
             "7": "rotor_balancing"}
    return f"pages/{pages.get(chapter, 'trajectories')}.py"


def home() -> None:
    """The home page: every chapter with its summary."""
    st.title("Mehanizmi")
    st.write(t("app.intro"))
    for chapter in (BUILDER, SYNTHESIS, *CHAPTERS, VARIANTS, CLASSROOM):
        with st.container(border=True):
            st.page_link(chapter.file, label=t(chapter.title), icon=chapter.icon)
            st.write(t(chapter.summary))


@st.cache_resource(show_spinner=False, max_entries=8)
def _pages(language: str) -> list[st.Page]:
    """The app's pages in ``language``, made once per process: making them (each resolves its
    path and checks its icon) took 3 ms, a tenth of a seated student's opening."""
    pages = [st.Page(home, title=t("app.home"), icon=":material/home:", default=True)]
    pages += [st.Page(c.file, title=t(c.title), icon=c.icon) for c in (*CHAPTERS, BUILDER, SYNTHESIS, VARIANTS)]
    pages.append(st.Page("pages/textbook_check.py", title=t("check.title"),
                         icon=":material/fact_check:"))
    pages.append(st.Page(CLASSROOM.file, title=t(CLASSROOM.title), icon=CLASSROOM.icon))
    return pages


def navigation_pages() -> list[st.Page]:
    """app.py's pages in the page's language, copied for this run: ``st.navigation`` marks
    the page it returns as the one this run may run, a mark no two sessions may share."""
    return [copy.copy(page) for page in _pages(current())]
