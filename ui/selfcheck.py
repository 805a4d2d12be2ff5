"""Exam self-check: the student types a value and learns how far it is from the exact one."""

from __future__ import annotations

from dataclasses import dataclass

import streamlit as st

from ui.i18n import num, t
from ui.numbers import number_field


@dataclass(frozen=True)
class Quantity:
    label: str  # already translated, with its unit
    exact: float
    unit: str
    drawing: float | None = None  # the error a drawing at the user's scales allows


def grade(typed: float, quantity: Quantity, tolerance: float = 0.005) -> tuple[str, float]:
    """("correct" | "drawing" | "off", relative error): correct within 0.5 %, within the
    drawing's expected error for a graphical answer, or off by the returned fraction."""
    error = typed - quantity.exact
    relative = abs(error) / abs(quantity.exact) if quantity.exact else abs(error)
    if relative <= tolerance:
        return "correct", relative
    if quantity.drawing is not None and abs(error) <= quantity.drawing:
        return "drawing", relative
    return "off", relative


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
        verdict, relative = grade(value, quantity)
        exact = f"{num(quantity.exact, 5)} {quantity.unit}"
        if verdict == "correct":
            st.success(t("self.correct", exact=exact))
        elif verdict == "drawing":
            st.info(t("self.drawing", percent=num(100 * relative, 2), exact=exact,
                      allowed=f"{num(quantity.drawing, 2)} {quantity.unit}"))
        else:
            st.warning(t("self.off", percent=num(100 * relative, 3), exact=exact))
