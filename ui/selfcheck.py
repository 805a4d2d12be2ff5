"""Exam self-check: the student types a value and hears the one judge's verdict
(methods.judge) — the same as practice, ``python -m solvers check`` and the Moodle bank —
with the exact value and the tolerance that made it."""

from __future__ import annotations

from dataclasses import dataclass

import streamlit as st

from methods.judge import judge, value_step
from methods.practice import Step, Term, Verdict
from ui.i18n import num, t
from ui.numbers import number_field
from ui.practice import hint


@dataclass(frozen=True)
class Quantity:
    label: str  # already translated, with its unit
    exact: float
    unit: str
    drawing: float | None = None  # the error a drawing at the user's scales allows
    missing: tuple[Term, ...] = ()  # the sizes with one term of its plan's sum left out

    def step(self) -> Step:
        """The value as the one judge asks it (methods.judge: the drawing's error where it
        is read off a drawing, else 0.5 %; a left-out term named)."""
        return value_step(self.label, self.exact, self.unit, self.drawing, self.missing)


def verdict(typed: float, quantity: Quantity) -> tuple[Verdict, Step]:
    """The one judge's verdict of ``typed`` (practice's, the command line's and Moodle's)."""
    step = quantity.step()
    return judge(step, typed), step


def _open_code(key: str) -> None:
    """A typed variant code opens that variant on this page (ui.scenes reads ``v=``)."""
    code = st.session_state[key].strip()
    if code:
        st.query_params["v"] = code
        st.session_state[key] = ""


def answer_box(quantities: list[Quantity], key: str) -> None:
    """Pick a quantity, type a value (0,25 or 0.25), see the verdict; or first type the code
    of a variant from a sheet to open that variant. Filled only while open: closed, it
    costs a rerun nothing."""
    box = st.expander(t("self.title"), icon=":material/school:", key=f"{key}_open",
                      on_change="rerun")
    if not box.open:
        return
    with box:
        st.text_input(t("self.code"), key=f"{key}_code", placeholder="3.1-S42-07K",
                      on_change=_open_code, args=(f"{key}_code",), help=t("self.code_help"))
        labels = [q.label for q in quantities]
        choice = st.selectbox(t("self.quantity"), range(len(labels)), format_func=labels.__getitem__,
                              key=f"{key}_quantity")
        quantity = quantities[choice]
        value = number_field(t("self.value", unit=quantity.unit), f"{key}_value", optional=True)
        if value is None:
            return
        said, step = verdict(value, quantity)
        allowed = f"± {num(step.tolerance, 2)} {quantity.unit}".rstrip()
        exact = t("self.exact", exact=f"{num(quantity.exact, 5)} {quantity.unit}".rstrip(),
                  allowed=allowed,
                  why=t("self.why_drawing" if quantity.drawing is not None else "self.why_computed"))
        (st.success if said.ok else st.warning)(f"{hint(step, said)} {exact}")
