"""Practice mode on a page: the student gives each step of a construction — by dragging the new
arrow's tip (or the new point) on the sheet at the page's scale, or by typing it — and hears
at once whether it is right and, if not, which usual mistake it looks like
(methods.practice). Three tries, or "Show it", reveal a step; the score and a CSV of every
answer come at the end. The state lives in the session, one run per page and scene.
"""

from __future__ import annotations

import functools
import math

import pandas as pd
import streamlit as st

from classes.methods import METHODS
from figures.plans import plain
from figures.practice import practice_figure
from figures.raw import RawFigure
from figures.style import Look
from methods.practice import RULES, Step, Verdict, hint_texts, polar, printed_tolerance
from methods.progress import Progress, verdict_of
from ui import classroom
from ui.export import chart
from ui.firstpaint import finish, whole
from ui.fragments import fragment
from ui.i18n import current, decimal_comma, kept_language, num, t
from ui.inview import into_view
from ui.numbers import Refused, number_field, refusal
from ui.present import look

PARTS = {"vector": "practice.part_vector", "point": "practice.part_point",
         "scalar": "practice.part_scalar"}
# a step's SI unit as its page writes it: the rotor page draws U in kg·mm and V in kg·mm²
SHOWN_UNITS = {"kg·m": ("kg·mm", 1e3), "kg·m²": ("kg·mm²", 1e6)}
OUTCOMES = {"first": "practice.first", "later": "practice.later",
            "revealed": "practice.revealed", "wrong": "practice.wrong", "open": "practice.open"}


def shown_unit(step: Step) -> tuple[str, float]:
    """The unit the page shows the step in, and its size in the step's SI unit (×)."""
    return SHOWN_UNITS.get(step.unit, (step.unit, 1.0))


def toggle(key: str) -> bool:
    """The page's "Practise" switch: on by itself for a student in a class that practises
    this (a reload, or another app process, keeps them practising)."""
    classroom.seat_refused()  # a link to a class or student that is not (or no longer) there
    seated = classroom.seat(key)
    if seated and st.session_state.get(f"{key}_seated") != seated:  # once a seat is found
        st.session_state[f"{key}_on"], st.session_state[f"{key}_seated"] = True, seated
    return st.toggle(t("practice.mode"), key=f"{key}_on", help=t("practice.mode_help"))


def class_only(*keys: str) -> None:
    """A student seated in a class that practises on this page (one of its practice
    ``keys``) gets the class's practice and nothing else: no readings, tables, book values,
    self-check box, other tabs or figures that would show what the steps ask, whatever the
    link or the sliders say — the class's scene, instant and method, a note naming the
    link's values left out. Then the page's run ends (``finish``). A link to a class while
    its store cannot be reached waits for it (practice never starts unstored). Anyone
    else: nothing here."""
    if not st.query_params.get("class") or not st.query_params.get("student"):
        return
    seated = next((s for s in map(classroom.seat, keys) if s), None)
    if classroom.waiting_for_store():
        classroom.seat_refused()  # (the waiting notice, which reruns the page when it answers)
        finish()
    if seated is None:
        return  # not this page's class, or no such student: the page as it is (its practice switch says why)
    found, steps = classroom.class_steps(seated)
    method = METHODS[found.method]
    key, sheet, drawable = method.panel, method.sheet, method.drawable
    st.caption(t("class.seated", code=found.code)
               + (" · " + t("class.seated_test") if found.test else ""))
    ignored = classroom.fixed_link(found, seated[1])
    if ignored:
        st.info(t("class.fixed", names=", ".join(ignored)), icon=":material/lock:")
    whole()  # (nothing of the page waits for the sheet's paint)
    _seated_panel(steps, key, t(sheet) if sheet else "", drawable)
    finish()


@fragment
def _seated_panel(steps: list[Step], key: str, title: str, drawable: bool) -> None:
    """A seated student's practice, a fragment: a check, a drag or a move reruns it alone,
    not app.py's controls and the seat's note around it (a check's run is what a class's
    server spends most of its time on: docs/performance.md, issue 70)."""
    panel(steps, key, title, drawable)


def hint(step: Step, verdict: Verdict) -> str:
    """The diagnosis in words (methods.practice.hint_texts: the words every surface says),
    and the book's rule for the step where it helps, in the page's language."""
    return " ".join(text.render(t, decimal_comma())
                    for text in hint_texts(step, verdict, plain))


def _state(key: str, steps: list[Step], seated: tuple[str, str] | None) -> dict:
    """This page's practice run. Answers and tips are kept in SI units, so a change of scale
    or of language keeps them (the sheet redraws them at the new scale); another scene or
    instant (other exact values) starts a new run, and the page says so."""
    signature = (tuple((s.id, str(s.expected)) for s in steps), seated)
    state = st.session_state.get(f"{key}_state")
    if state is None or state["signature"] != signature:
        restarted = state is not None and bool(state["progress"].records)
        progress = classroom.resumed(seated, steps) if seated else Progress.start()
        state = {"signature": signature, "progress": progress, "seat": seated, "tips": {},
                 "index": classroom.first_open(steps, progress) if seated else 0,
                 "revision": 0, "restarted": restarted, "mine": {}}
        st.session_state[f"{key}_state"] = state
    state["steps"] = steps  # (the same values: the signature says so)
    return state


def seated_before(state: dict) -> bool:
    """Whether this run was a class's and the class went away (deleted or expired)."""
    return bool(state["signature"][1])


def panel(steps: list[Step], key: str, title: str, drawable: bool = True) -> None:
    """The practice of ``steps`` under the key ``key`` (one per page and method)."""
    if not steps:
        st.info(t("practice.no_steps"))
        return
    state = _state(key, steps, classroom.seat(key))
    if state.pop("restarted", False):
        st.info(t("practice.restarted"), icon=":material/restart_alt:")
    if state["seat"] is None and seated_before(state):
        st.warning(t("class.gone_note"), icon=":material/cloud_off:")
    classroom.closing(state)  # (a test: said when its lecturer closes it)
    progress: Progress = state["progress"]
    index = min(state["index"], len(steps) - 1)
    step = steps[index]
    zero = step.kind == "vector" and abs(complex(step.expected)) <= step.tolerance
    drawn = drawable and step.kind != "scalar" and bool(step.sheet) and not zero
    prompt = st.container(key=f"{key}_prompt")  # what a check or a move brings to the screen's top
    prompt.markdown(t("practice.step", n=index + 1, of=len(steps), part=t(PARTS[step.kind]))
                    + f" ${step.symbol}$ [{shown_unit(step)[0]}]")
    if zero:  # a question to type, not a drag: a tip cannot be left on its tail
        st.info(t("practice.zero_step"), icon=":material/info:")
    sheet = st.container() if drawn else None  # drawn last, where it shows: above the boxes
    if progress.rules.hints:
        hidden = "practice.rule_hidden_value" if step.kind == "scalar" else "practice.rule_hidden"
    else:  # a test has no hints: its words promise none
        hidden = "practice.rule_hidden_value_test" if step.kind == "scalar" else "practice.rule_hidden_test"
    rule = (t(RULES[step.rule]) if step.rule in ("sum", "point", "closing", "correction")
            else t(hidden))
    if drawn:
        _dragged(step, key, state)  # (before the boxes it fills are drawn)
        unit, factor = shown_unit(step)  # (the scale and the rule: one element, two lines)
        rule = t("practice.sheet_scale", scale=num(step.scale * factor, 4), unit=unit) + "  \n" + rule
    st.caption(rule)
    _typing(step, key, state)
    if drawn:  # after the check: the tip where it now is, its prompt brought to the screen
        with sheet:
            _drawing(steps, index, key, state, progress, title)
    # a sheet's check scrolls the prompt and its verdict, written under it, to the top; a
    # typed step's verdict goes under its Check button instead, where the eyes are (put
    # above it, a phone's browser kept the button in place and the verdict landed above
    # the screen)
    with prompt if drawn else st.container(key=f"{key}_verdict"):
        if not classroom.not_saved():
            _feedback(step, state)
    if not drawn and state.get("checked"):  # a typed step's verdict, under the thumb
        into_view(f".st-key-{key}_verdict", state["checked"], f"{key}_in_view")
    _moves(steps, index, key, state)
    if all(progress.done(s) for s in steps) and classroom.verdicts_shown(state):
        score(steps, progress, key)


def _drawing(steps: list[Step], index: int, key: str, state: dict, progress: Progress,
             title: str) -> None:
    """The sheet: drag the red circle to the tip; its place fills the boxes under it."""
    step = steps[index]
    tip = state["tips"].get(step.id)  # SI: where the student put it, at any scale
    tip = None if tip is None else tip / (step.scale or 1.0)
    revision = f"{step.id}-{state['revision']}-{step.scale}"
    record = progress.record(step)
    seen = len(record.counted) + len(record.late)  # a check, a drag or a move: a new focus
    chart(_sheet(tuple(steps), index, tip, title, current(), look(), revision),
          f"practice-{key}", key=f"{key}_fig", handle="tip",
          focus=f".st-key-{key}_prompt|{index}-{seen}-{state['revision']}")
    st.caption(t("practice.drag_hint"))


@functools.lru_cache(maxsize=256)
def _sheet(steps: tuple[Step, ...], index: int, tip: complex | None, title: str, language: str,
           look_: Look, revision: str) -> RawFigure:
    """The sheet of a step, shared by every session that shows it alike (steps are frozen:
    equal steps, the same sheet): a class opening its first step draws it once, not once a
    student. Never changed once made (ui.plot only reads it), so frozen: its JSON is made
    once too, not at each opening and check that shows it."""
    return practice_figure(list(steps), index, tip, title,
                           lambda key, **values: t(key, language, **values), look_,
                           revision).freeze()


def _dragged(step: Step, key: str, state: dict) -> None:
    """The tip the student just let go (the sheet's trigger of this run), read before the
    boxes are drawn: its place fills them, and the sheet drawn after shows it — one run a
    drag, and one a check, where each took two (a rerun to redraw; issue 70)."""
    drag = (st.session_state.get(f"{key}_fig") or {}).get("drag")
    if drag and drag.get("point") == "tip":
        at = complex(float(drag["x"]), float(drag["y"])) * step.scale
        state["tips"][step.id] = at
        _fill(step, key, at - step.tail if step.kind == "vector" else at)
        state["revision"] += 1


def _fill(step: Step, key: str, answer: complex) -> None:
    """A drag writes its answer into the boxes under the sheet, and only Check grades it:
    a drag that ended a little off (a finger lifted early, the sheet scrolled) used to cost
    a try. Five significant digits: finer than the drawing's tolerance, as a ruler reads."""
    unit, factor = shown_unit(step)
    if step.kind == "vector":
        values = {"len": abs(answer) * factor,
                  "ang": math.degrees(math.atan2(answer.imag, answer.real)) % 360}
    else:
        values = {"x": answer.real, "y": answer.imag}
    for name, value in values.items():
        st.session_state[f"{key}_{name}_{step.id}"] = float(f"{value:.5g}")


def _typing(step: Step, key: str, state: dict) -> None:
    """The same answer typed: length and direction, a point's x and y, or a signed value
    (each read by ui.numbers: 0,35 or 0.35 on a Serbian page). A Check with a box empty or
    unreadable names that box and grades nothing."""
    unit, factor = shown_unit(step)
    if step.kind == "vector":
        fields = {"len": t("practice.length", unit=unit), "ang": t("practice.angle")}
    elif step.kind == "point":
        fields = {"x": "x [m]", "y": "y [m]"}
    else:
        fields = {"value": t("practice.value", unit=unit)}
    with st.form(f"{key}_form_{step.id}", border=False):
        row = st.container(horizontal=True, vertical_alignment="bottom")  # one block, not three
        values = [number_field(label, f"{key}_{name}_{step.id}", optional=True, where=row)
                  for name, label in fields.items()]
        if not st.form_submit_button(t("practice.check"), icon=":material/check:"):
            return
        if step.kind == "vector" and values[0] == 0 and values[1] is None:
            values[1] = 0.0  # no length: no direction to give
        for (name, label), value in zip(fields.items(), values):
            if value is None and not st.session_state[f"{key}_{name}_{step.id}"].strip():
                st.error(refusal(label, Refused("empty", "")), icon=":material/error:")
        if any(v is None for v in values):
            return
        if step.kind == "vector":
            answer = polar(values[0] / factor, values[1])
        elif step.kind == "point":
            answer = complex(*values)
        else:
            answer = values[0] / factor
        if step.kind != "scalar":  # the sheet's tip goes where the typed answer puts it
            state["tips"][step.id] = step.tail + answer if step.kind == "vector" else answer
        state["revision"] += 1
        state["checked"] = f"{step.id}-{state['revision']}"  # (ui.inview: show its verdict)
        classroom.give(state, step, answer)  # (drawn below it in this same run, and the sheet)


def _feedback(step: Step, state: dict) -> None:
    """The verdict of the last check of ``step`` (in a class: this device's own, as stored;
    the tries of another tab count in the progress), then the exact answer once done. A
    check that came after the step was settled is said to count for nothing; in a test not
    yet closed, only that the try is stored."""
    progress: Progress = state["progress"]
    record, mine = progress.record(step), state["mine"].get(step.id)
    if not classroom.verdicts_shown(state):
        if mine in (classroom.SETTLED, classroom.DONE_HERE):
            st.info(t("class.one_try", step=plain(step.symbol)), icon=":material/lock:")
        elif record.counted:
            st.info(t("practice.test_stored"), icon=":material/lock:")
        return
    elsewhere = mine in (classroom.SETTLED, classroom.DONE_HERE)
    if elsewhere and progress.rules.hints:
        st.info(t("practice.settled" if mine == classroom.SETTLED else "practice.settled_here",
                  outcome=t(OUTCOMES[record.outcome])), icon=":material/devices:")
    else:  # (a closed test: the step's one stored try, with its hint, as every other step)
        last = (None if elsewhere else mine) or (verdict_of(step, record.graded[-1])
                                                 if record.graded else None)
        if last is not None:
            (st.success if last.ok else st.warning)(hint(step, last))
    if record.outcome == "revealed":
        st.info(t("practice.shown", tries=len(record.graded), limit=progress.rules.tries))
    if record.done:
        st.markdown(t("practice.exact") + " " + exact_text(step))


def exact_text(step: Step) -> str:
    """The exact answer as the student would write it, in the page's unit."""
    unit, factor = shown_unit(step)
    if step.kind == "scalar":
        return f"{num(float(step.expected) * factor, 5)} {unit}"
    z = complex(step.expected)
    if step.kind == "point":
        return f"({num(z.real, 5)}; {num(z.imag, 5)}) m"
    return (f"{num(abs(z) * factor, 5)} {unit}, "
            f"{num(math.degrees(math.atan2(z.imag, z.real)) % 360, 4)}°")


def _moves(steps: list[Step], index: int, key: str, state: dict) -> None:
    """Previous, Show it, Next: one row that wraps on a narrow screen (one block, where three
    columns sent four)."""
    progress = state["progress"]

    def go(to: int) -> None:
        state["index"] = max(0, min(to, len(steps) - 1))

    row = st.container(horizontal=True)
    row.button(t("practice.previous"), key=f"{key}_prev", on_click=go, args=(index - 1,),
               disabled=index == 0, icon=":material/arrow_back:", width="stretch")
    if progress.rules.hints:  # (a test gives no "Show it")
        row.button(t("practice.reveal"), key=f"{key}_reveal",
                   on_click=lambda: classroom.reveal(state, steps[index]),
                   disabled=progress.done(steps[index]), icon=":material/visibility:",
                   width="stretch")
    row.button(t("practice.next"), key=f"{key}_next", on_click=go, args=(index + 1,),
               disabled=index == len(steps) - 1, icon=":material/arrow_forward:",
               width="stretch")


def score(steps: list[Step], progress: Progress, key: str) -> None:
    """The score (first try, after hints, revealed — or in a test, right and wrong) and
    every step's answers as CSV (a decimal point, for spreadsheets)."""
    counts = progress.score(steps)
    st.header(t("practice.score"))
    shown = ("first", "later", "revealed") if progress.rules.hints else ("first", "wrong")
    cols = st.columns(len(shown))
    for col, outcome in zip(cols, shown):
        col.metric(t(OUTCOMES[outcome]), f"{counts[outcome]} / {len(steps)}")
    st.download_button(t("practice.csv"), kept_language(lambda: answers_table(steps, progress).to_csv(
        index=False).encode("utf-8")), f"practice-{key}.csv", mime="text/csv",
        key=f"{key}_csv", on_click="ignore", icon=":material/download:")


CSV_COLUMNS = {"step": "practice.col_step", "symbol": "practice.col_symbol",
               "unit": "practice.col_unit", "exact": "practice.col_exact",
               "tolerance": "practice.col_tolerance", "answers": "practice.col_answers",
               "diagnoses": "practice.col_diagnoses", "outcome": "practice.col_outcome"}
DIAGNOSES = {"ok": "practice.word_ok", "sense": "practice.word_sense",
             "direction": "practice.word_direction", "length": "practice.word_length",
             "scale": "practice.word_scale", "missing-term": "practice.word_missing_term",
             "wrong": "practice.word_wrong", "none": "practice.word_none"}


def answers_table(steps: list[Step], progress: Progress) -> pd.DataFrame:
    """One row per step: what was asked, the exact value, each answer and its diagnosis, in
    the page's words; the numbers keep a decimal point (for spreadsheets, as the button
    says)."""
    def value(v) -> str:
        if v is None:
            return ""
        if isinstance(v, (list, tuple)):  # (as the store keeps a pair)
            v = complex(*v)
        if isinstance(v, complex):
            return f"{v.real:.6g}; {v.imag:.6g}"
        return f"{float(v):.6g}"

    rows = [{
        "step": s.id, "symbol": plain(s.symbol), "unit": s.unit, "exact": value(s.expected),
        "tolerance": num(printed_tolerance(s.tolerance), 3),
        "answers": " | ".join(value(a.answer) for a in progress.record(s).graded),
        "diagnoses": " | ".join(t(DIAGNOSES[a.diagnosis]) for a in progress.record(s).graded),
        "outcome": t(OUTCOMES[progress.outcome(s)])} for s in steps]
    return pd.DataFrame(rows).rename(columns={k: t(v) for k, v in CSV_COLUMNS.items()})
