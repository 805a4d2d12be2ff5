"""A student in a lecturer's class, on the page of the class's method: who they are (the
class code and their token stay in the page's link, so a reload, a lost connection or
another app process brings them back), where their checks go (classes.store, before the
verdict is shown) and how their progress comes back from the store."""

from __future__ import annotations

import streamlit as st

from classes import store
from classes.store import ClassError, NotSaved, StoreDown
from methods.practice import Progress, Step, answer_of, grade
from ui.i18n import message, t

# the practice of each method: its page, its switch's key, the page's state that shows it
METHODS = {"compass": ("pages/trajectories.py", "pr_compass", {"view": "compass"}),
           "plans": ("pages/velocity_plans.py", "pr_plans", {}),
           "forces": ("pages/kinetostatics.py", "pr_forces", {}),
           "lever": ("pages/kinetostatics.py", "pr_lever", {}),
           "willis": ("pages/planetary_gears.py", "pr_willis", {}),
           "balance": ("pages/rotor_balancing.py", "pr_balance", {})}
PAGE = "pages/class.py"
NOT_SAVED = "_class_not_saved"


def seat(key: str) -> tuple[str, str] | None:
    """(class code, student token) when this page's practice ``key`` is the class's method
    and the link names a student of that class; None otherwise (practice is not stored)."""
    memo = _seat()
    return (memo[0], memo[1]) if memo and not memo[3] and memo[2] == key else None


def seat_refused() -> None:
    """Why the link's class or student was not found, where the practice would be."""
    memo = _seat()
    if memo and memo[3]:
        st.error(memo[3], icon=":material/error:")


def _seat() -> tuple | None:
    """(code, token, the method's practice key, why not) for the link's class and student,
    looked up in the store once per session and link."""
    code, token = st.query_params.get("class"), st.query_params.get("student")
    if not code or not token:
        return None
    memo = st.session_state.get("_class_seat")
    if memo is None or memo[:2] != (code, token):
        try:
            method = store.find(code).method
            store.student(code, token)
        except StoreDown as exc:  # asked again on the next run, not kept
            return (code, token, None, message(exc.args[0]))
        except ClassError as exc:
            memo = (code, token, None, message(exc.args[0]))
        else:
            memo = (code, token, METHODS[method][1], "")
        st.session_state["_class_seat"] = memo
    return memo


def resumed(seated: tuple[str, str], steps: list[Step]) -> Progress:
    """The student's progress as the store has it: their checks graded again, in order.
    A store that cannot be reached stops the page with the reason (nothing is started
    afresh that would hide what the store holds)."""
    progress = Progress.start()
    by_id = {s.id: s for s in steps}
    try:
        checks = store.tries(*seated)
    except StoreDown as exc:
        st.error(message(exc.args[0]), icon=":material/cloud_off:")
        st.stop()
    for check in checks:
        step = by_id.get(check["step"])
        if step is None:
            continue
        if check["diagnosis"] == store.REVEALED:
            progress.reveal(step)
        else:
            progress.give(step, answer_of(check["answer"], step.kind))
    return progress


def give(seated: tuple[str, str] | None, progress: Progress, step: Step, answer) -> None:
    """A check: graded, stored (in a class) and only then counted and shown."""
    if seated is not None and not progress.done(step):
        verdict = grade(step, answer)
        if not _stored(seated, progress, step, _plain(answer), verdict.diagnosis, verdict.term):
            return
    progress.give(step, answer)


def reveal(seated: tuple[str, str] | None, progress: Progress, step: Step) -> None:
    """"Show it": stored as the student's last try of the step (the class view counts it,
    and a reload keeps it shown), then shown."""
    if seated is not None and not progress.done(step):
        if not _stored(seated, progress, step, None, store.REVEALED, ""):
            return
    progress.reveal(step)


def _stored(seated: tuple[str, str], progress: Progress, step: Step, answer, diagnosis: str,
            term: str) -> bool:
    """One try in the store (False, and "not saved" said, when it could not be taken)."""
    try:
        store.record(*seated, step.id, answer, diagnosis,
                     len(progress.verdicts.get(step.id, [])) + 1, term=term)
    except NotSaved:
        st.session_state[NOT_SAVED] = True
        return False
    return True


def _plain(answer):
    """An answer as JSON holds it: [x, y], a number or None."""
    if isinstance(answer, complex):
        return [answer.real, answer.imag]
    return None if answer is None else float(answer)


def not_saved() -> None:
    """The check the store could not take, said where its verdict would have been."""
    if st.session_state.pop(NOT_SAVED, False):
        st.error(t("class.not_saved"), icon=":material/cloud_off:")


def sidebar_join() -> None:
    """A class code typed in the sidebar of any page opens the class's join page."""
    typed = st.sidebar.text_input(t("class.sidebar_code"), key="class_code_typed",
                                  placeholder="ABC123", max_chars=12, autocomplete="off")
    if typed.strip() and st.session_state.get("_class_code_opened") != typed:
        st.session_state["_class_code_opened"] = typed
        st.switch_page(PAGE, query_params={"join": typed.strip().upper(),
                                           "lang": st.query_params.get("lang", "")})

