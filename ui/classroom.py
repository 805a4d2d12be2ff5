"""A student in a lecturer's class, on the page of the class's method: who they are (the
class code and their token stay in the page's link, so a reload, a lost connection or
another app process brings them back), where their checks go (classes.store, before the
verdict is shown) and how their progress comes back from the store."""

from __future__ import annotations

import dataclasses

import streamlit as st
from streamlit.runtime.scriptrunner import get_script_run_ctx

from classes import store
from classes.store import ClassError, NotSaved, OneTry, StoreDown, TestClosed, closed_at
from classes.methods import METHODS
from classes.steps import practice_link, steps_at
from classes.summary import tried
from figures.plans import plain
from methods.practice import Step, grade
from methods.progress import Progress, Rules, Try
from ui.boundary import boundary
from ui.i18n import message, t
from ui.url import stop, url_replace, url_value

PAGE = "pages/class.py"
NOT_SAVED = "_class_not_saved"
LOCKED = ":material/lock:"  # a test's step tried already, or the test closed: not the store's fault


RETRY = 3.0  # s between two looks at a store that did not answer


def seat(key: str) -> tuple[str, str] | None:
    """(class code, student token) when this page's practice ``key`` is the class's method
    and the link names a student of that class; None otherwise (practice is not stored)."""
    memo = _seat()
    return (memo[0], memo[1]) if memo and not memo[3] and memo[2] == key else None


def seated_on(page: str) -> bool:
    """Whether ``page`` (a URL path) is where the link's student practises their class's
    method: that page shows the class's practice alone, without the projector switch and
    the sidebar's code box (two widgets fewer in each of a class's openings)."""
    memo = _seat()
    return bool(memo and memo[4]) and METHODS[memo[4][0].method].page == page


def waiting_for_store() -> bool:
    """Whether the link's class could not be looked up because the store is down (the page
    then shows only the waiting notice of ``seat_refused``)."""
    memo = _seat()
    return bool(memo and memo[3] == DOWN)


def seat_refused() -> None:
    """Why the link's class or student was not found, where the practice would be; while
    the store cannot be reached, a page that looks again every few seconds and comes back
    to practice by itself when it answers."""
    memo = _seat()
    if memo and memo[3] == DOWN:
        wait_for_store(t("class.store_down"))
    elif memo and memo[3]:
        st.error(memo[3], icon=":material/error:")


DOWN = "down"  # a seat's "why not" while the store cannot be reached (asked again each run)


def _seat() -> tuple | None:
    """(code, token, the method's practice key, why not, (class, student)) for the link's
    class and student, read from the store once per session and link — with the student's
    tries, in one statement: the page that opens with it resumes their practice from them
    in this same run (``resumed``), and reads nothing more."""
    code, token = st.query_params.get("class"), st.query_params.get("student")
    if not code or not token:
        return None
    memo = st.session_state.get("_class_seat")
    if memo is None or memo[:2] != (code, token):
        try:
            found, who, checks = store.resume(code, token)
        except StoreDown:  # asked again on the next run, not kept
            return (code, token, None, DOWN, None)
        except ClassError as exc:
            memo = (code, token, None, message(exc.args[0]), None)
        else:
            memo = (code, token, METHODS[found.method].panel, "", (found, who))
            st.session_state[TRIES] = ((code, token), _this_run(), checks)
        st.session_state["_class_seat"] = memo
    return memo


TRIES = "_class_tries"  # (seat, run, checks): the tries the seat was read with, and in which run


def _tries_read(seated: tuple[str, str]) -> list[dict] | None:
    """The student's tries as the seat read them, if it did in this very run (taken once:
    any later run reads them again, another device may have added to them since)."""
    kept = st.session_state.pop(TRIES, None)
    fresh = kept is not None and kept[0] == seated and kept[1] is not None and kept[1] is _this_run()
    return kept[2] if fresh else None


def _this_run() -> object | None:
    """An object of this run of the script alone (None outside a run): Streamlit makes its
    running cursors anew at every run's start, a page's or a fragment's. (A page run
    without app.py, as a test switches pages, is still a run of its own.)"""
    ctx = get_script_run_ctx(suppress_warning=True)
    return None if ctx is None else ctx.cursors


def _known(seated: tuple[str, str]) -> tuple[store.Class, dict] | None:
    """The class and the student of ``seated`` as the session's seat read them."""
    memo = st.session_state.get("_class_seat")
    return memo[4] if memo and memo[:2] == seated else None


def wait_for_store(said: str) -> None:
    """``said`` while the store cannot be reached, looked at again every RETRY seconds in a
    fragment of its own; the page runs again by itself once the store answers."""
    @st.fragment(run_every=RETRY)
    def waiting() -> None:
        with boundary():
            if store.reachable():
                st.rerun(scope="app")
            st.warning(said, icon=":material/cloud_off:")

    waiting()


def resumed(seated: tuple[str, str], steps: list[Step], rules: Rules | None = None) -> Progress:
    """The student's progress as the store has it: every try from every tab, phone or hand-in,
    folded in the order stored by the one rule (methods.progress) the live view and the
    gradebook fold them by (``rules``: the class's, asked of the store when not known yet).
    A store that cannot be reached stops the page with the reason (nothing is started afresh
    that would hide what the store holds) until it answers."""
    known = {s.id for s in steps}
    seat = _known(seated)  # (the session read the class and the student: only the tries now)
    try:
        if seat:
            found, checks = seat[0], _tries_read(seated)
            if checks is None:
                checks = store.tries_of(found, seated[1])
        else:
            found, _, checks = store.resume(*seated)
    except StoreDown:
        wait_for_store(t("class.store_down"))
        stop()
    return Progress.of(tried([c for c in checks if c["step"] in known]), rules or found.rules)


@st.cache_resource(max_entries=64, show_spinner=False)
def _steps_at(scene: str, method: str, at: float | None, variant: str | None) -> list[Step]:
    return steps_at(scene, method, at, variant)


def class_steps(seated: tuple[str, str]) -> tuple[store.Class, list[Step]]:
    """The class of a seated student and the steps it practises — the class's scene (or the
    student's variant), method and instant, never the link's or the sliders': every check
    is graded and stored at the class's instant. Made once per session and seat, from the
    class and student the seat read (a class deleted meanwhile keeps its steps: practice
    goes on, unstored)."""
    memo = st.session_state.setdefault("_class_steps", {})
    if seated not in memo:
        found, who = _known(seated)
        variant = store.variant_of(found, who["variant"])
        memo[seated] = (found, _steps_at(found.scene, found.method, found.at, variant))
    return memo[seated]


def fixed_link(found: store.Class, token: str) -> list[str]:
    """The link's values that would practise something else than the class (``at``, a
    slider's, ``s=``, ``scene``): the names of those given — said on every run of the
    session, not only the one that found them — and the page's link set to the class's
    own, so that a reload or a shared link practises the class."""
    try:
        _, own = practice_link(found, token, url_value("lang", ""))
    except StoreDown:  # (the note waits for the next run)
        return []
    given = {k: st.query_params.get_all(k) for k in st.query_params}
    ignored = sorted(k for k, v in given.items()
                     if k not in ("lang", "class", "student") and v != [own.get(k)])
    said = st.session_state.setdefault("_class_fixed", {})  # kept: the link is clean after
    if ignored:
        url_replace({k: v for k, v in own.items() if v})
        said[found.code] = ignored
    return said.get(found.code, [])


def first_open(steps: list[Step], progress: Progress) -> int:
    """Where a student coming back starts: the first step not yet done (the last when all
    are)."""
    return next((i for i, s in enumerate(steps) if not progress.done(s)), len(steps) - 1)


def give(state: dict, step: Step, answer) -> None:
    """A check: graded, stored (in a class) and only then counted and shown. In a class the
    progress is then the store's — every tab's and phone's tries in the order stored — and
    this device is told its own check's verdict, or, when another device had settled the
    step before it reached the store, that it was already done there (stored, but counting
    for nothing: never "right" for a wrong value)."""
    progress: Progress = state["progress"]
    if progress.done(step):  # this device knows the step is settled: nothing to grade
        state["mine"][step.id] = DONE_HERE
        return
    verdict = grade(step, answer)
    if verdict.diagnosis == "none":
        return
    if state["seat"] is None:
        progress.give(step, answer)
        state["mine"][step.id] = verdict
        return
    made = Try(step.id, verdict.diagnosis, _plain(answer), verdict.term, "", verdict)
    check = _folded(state, made)
    if check:
        state["mine"][step.id] = SETTLED if state["progress"].late(check) else verdict


SETTLED = "settled"  # a device's check of a step settled before it (on another device)
DONE_HERE = "done"  # a check of a step this device already knew settled (not graded)


def reveal(state: dict, step: Step) -> None:
    """"Show it": stored as the student's last try of the step (the class view counts it,
    and a reload keeps it shown), then shown."""
    if state["progress"].done(step):
        return
    if state["seat"] is None:
        state["progress"].reveal(step)
    elif check := _folded(state, Try(step.id, store.REVEALED)):
        if state["progress"].late(check):  # settled on another device first: said so, as a check's
            state["mine"][step.id] = SETTLED
        else:
            state["mine"].pop(step.id, None)


def _folded(state: dict, made: Try) -> str:
    """A seated student's try stored, then folded into the progress the page holds: by
    itself when the store numbered it the step's next try (no other device wrote that step
    meanwhile: the fold is the store's), else by reading the student's tries again (one
    round trip less a check than reading them every time). The check's id, "" when not
    stored."""
    stored = _stored(state, made.step, made.answer, made.diagnosis, made.term)
    if not stored:
        return ""
    check, number = stored
    progress: Progress = state["progress"]
    record = progress.record(made.step)
    if number == len(record.counted) + len(record.late) + 1:
        progress.add(dataclasses.replace(made, check=check))
    else:  # another tab, phone or hand-in tried this step meanwhile: the store's order
        state["progress"] = resumed(state["seat"], state["steps"], progress.rules)
    return check


def verdicts_shown(state: dict) -> bool:
    """Whether this run's student sees verdicts: always, but in a test only once its
    lecturer closed it (asked of the store each run until then)."""
    if state["progress"].rules.hints or state["seat"] is None or state.get("closed"):
        return True
    try:
        found = store.find(state["seat"][0])
    except ClassError:  # (down or gone: not yet)
        return False
    state["closed"] = found.verdicts_shown
    if found.closed is not None:
        state["closed_at"] = closed_at(found)
    return state["closed"]


def closing(state: dict) -> None:
    """A seated student's page in an open test: said when the lecturer closes it. Until
    then a fragment of its own asks the store every RETRY seconds (as the live view's
    refresh) and runs the page again once the test is closed, which then shows the
    verdicts; after that, when it was closed and what counts."""
    if state["seat"] is None or state["progress"].rules.hints:
        return
    if verdicts_shown(state):  # (closed: asked of the store until then, then kept)
        if state.get("closed_at"):
            st.info(t("class.test_closed_seen", at=state["closed_at"]), icon=":material/lock_clock:")
        return

    @st.fragment(run_every=RETRY)
    def watching() -> None:
        with boundary():
            if verdicts_shown(state):
                st.rerun(scope="app")

    watching()


def _stored(state: dict, step: str, answer, diagnosis: str, term: str) -> tuple[str, int] | None:
    """One check in the store: its id and try number (None, and why said, when it was not
    taken). The check's id is made here and kept until the store has it: the same answer
    checked again after "not saved" is that check, stored once; any other is a new try.
    The class and the student are the seat's (``_known``), not read again at every check."""
    pending = state.setdefault("pending", {})
    which = (step, repr(answer), diagnosis)
    check = pending.setdefault(which, store.new_check())
    try:
        number = store.record(*state["seat"], step, answer, diagnosis, check, term=term,
                              known=_known(state["seat"]))
    except (NotSaved, StoreDown):
        st.session_state[NOT_SAVED] = t("class.not_saved")
        return None
    except OneTry:  # a test's step tried already (on another device): named as the page names it
        shown = next((plain(s.symbol) for s in state["steps"] if s.id == step), step)
        st.session_state[NOT_SAVED] = (t("class.one_try", step=shown), LOCKED)
        # the other device's try, which this page had not seen: its verdict once closed
        state["progress"] = resumed(state["seat"], state["steps"], state["progress"].rules)
        return None
    except TestClosed as exc:  # closed meanwhile: not stored, and the verdicts shown from now
        st.session_state[NOT_SAVED] = (message(exc.args[0]), LOCKED)
        verdicts_shown(state)  # (asks the store: closed, and when)
        return None
    except ClassError as exc:  # the class deleted or expired meanwhile: practice goes on, unstored
        st.session_state[NOT_SAVED] = t("class.gone", why=message(exc.args[0]))
        state["seat"] = None
        return None
    del pending[which]
    return check, number


def _plain(answer):
    """An answer as JSON holds it: [x, y], a number or None."""
    if isinstance(answer, complex):
        return [answer.real, answer.imag]
    return None if answer is None else float(answer)


def not_saved() -> bool:
    """The check the store could not take, said where its verdict would have been (and
    nothing else there: an older verdict under it would read as this one's). True if said."""
    said = st.session_state.pop(NOT_SAVED, None)
    if isinstance(said, tuple):  # (a test's refusal: the one notice with a lock, as practice's)
        st.info(said[0], icon=said[1])
    elif said:
        st.error(said, icon=":material/cloud_off:")
    return bool(said)


SIDEBAR_CLOSES = "_sidebar_closes"  # session: a code typed in the sidebar, its page opening


# the sidebar's own « button, pressed where the sidebar lies over the page (a phone's width)
CLOSE_SIDEBAR = """<script>
if (innerWidth < 768) {
  const sidebar = document.querySelector('[data-testid="stSidebar"]');
  const close = sidebar && sidebar.querySelector('[data-testid="stSidebarCollapseButton"] button, '
                                                 + '[data-testid="stSidebarHeader"] button');
  if (close && sidebar.getBoundingClientRect().right > 0) close.click();
}
</script>"""


def close_sidebar() -> None:
    """The join page opened from a code typed in the sidebar closes the sidebar on a phone,
    where it lies over the page: *Join and practise* could not be tapped until it was
    closed by hand. (Streamlit's page config does not close a sidebar already open.)"""
    if st.session_state.pop(SIDEBAR_CLOSES, False):
        st.html(CLOSE_SIDEBAR, unsafe_allow_javascript=True)


def sidebar_join() -> None:
    """A class code typed in the sidebar of any page opens the class's join page. The box
    is emptied as it is read, so a page that runs again (a restart, a reconnect) does not
    send a practising student back to the join page."""
    def typed() -> None:
        st.session_state["_class_join"] = st.session_state["class_code_typed"].strip().upper()
        st.session_state["class_code_typed"] = ""
        st.session_state[SIDEBAR_CLOSES] = True

    st.sidebar.text_input(t("class.sidebar_code"), key="class_code_typed", on_change=typed,
                          placeholder="ABC123", max_chars=12, autocomplete="off")
    code = st.session_state.pop("_class_join", "")
    if code:
        st.switch_page(PAGE, query_params={"join": code, "lang": url_value("lang", "")})
