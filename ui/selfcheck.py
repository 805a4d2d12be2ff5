"""Exam self-check: the student types a value and hears the one judge's verdict
(methods.judge) — the same as practice, ``python -m solvers check`` and the Moodle bank —
with the exact value and the tolerance that made it. The quantities a page offers come from
the one table of judged values (exams.judged: signed, the task's tolerance), so the box
cannot judge a value by a rule of its own; a page's own extra (a mechanism's W, a path's
length) is a computed value under the same rule (``computed``)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import streamlit as st

from exams.judged import table
from exams.variants import symbol
from methods.judge import judge, value_step
from methods.practice import Step, Verdict, printed_tolerance
from solvers.diagnostics import Unsolvable
from solvers.structure import StructureError
from ui.cache import BY_REPR
from ui.i18n import num, t
from ui.numbers import number_field
from ui.practice import hint


@dataclass(frozen=True)
class Quantity:
    label: str  # already translated, with its unit
    step: Step  # the one judge's step: exact value, unit, tolerance, left-out terms
    drawing: bool = False  # its tolerance is a drawing's error (else a computed value's)


def computed(label: str, exact: float, unit: str) -> Quantity:
    """A page's own value that no task asks (W, a path's length): computed, 0.5 %."""
    return Quantity(label, value_step(label, exact, unit))


@st.cache_resource(max_entries=32, show_spinner=False, hash_funcs=BY_REPR)
def _table(scene, task) -> list:
    try:
        return table(scene, task)
    except (Unsolvable, StructureError, NotImplementedError):  # nothing to check here
        return []


def named(scene, task, keep: Callable[[str], bool] = lambda key: True) -> list[Quantity]:
    """The scene's judged values (the task ``task``'s scales and asked values first), as
    the box offers them: "ω₃ [s⁻¹]", signed, with the tolerance ``check`` gives."""
    return [Quantity(f"{symbol(a.key)} [{a.unit}]" if a.unit not in ("", "–") else symbol(a.key),
                     step, a.tolerance is not None)
            for a, step in _table(scene, task) if keep(a.key)]


def verdict(typed: float, quantity: Quantity) -> tuple[Verdict, Step]:
    """The one judge's verdict of ``typed`` (practice's, the command line's and Moodle's)."""
    return judge(quantity.step, typed), quantity.step


def _open_code(key: str) -> None:
    """A typed variant code opens that variant on this page (ui.scenes reads ``v=``)."""
    code = st.session_state[key].strip()
    if code:
        st.query_params["v"] = code
        st.session_state[key] = ""


def answer_box(quantities: list[Quantity] | Callable[[], list[Quantity]], key: str) -> None:
    """Pick a quantity, type a value (0,25 or 0.25), see the verdict; or first type the code
    of a variant from a sheet to open that variant. Filled only while open: closed, it
    costs a rerun nothing (``quantities`` may be a function, called only then)."""
    box = st.expander(t("self.title"), icon=":material/school:", key=f"{key}_open",
                      on_change="rerun")
    if not box.open:
        return
    with box:
        st.text_input(t("self.code"), key=f"{key}_code", placeholder="3.1-S42-07K",
                      on_change=_open_code, args=(f"{key}_code",), help=t("self.code_help"))
        if callable(quantities):
            quantities = quantities()
        if not quantities:
            st.caption(t("self.none"))
            return
        labels = [q.label for q in quantities]
        choice = st.selectbox(t("self.quantity"), range(len(labels)), format_func=labels.__getitem__,
                              key=f"{key}_quantity")
        quantity = quantities[min(choice, len(quantities) - 1)]
        unit = quantity.step.unit
        value = number_field(t("self.value", unit=unit), f"{key}_value", optional=True)
        if value is None:
            return
        said, step = verdict(value, quantity)
        allowed = f"± {num(printed_tolerance(step.tolerance), 3)} {unit}".rstrip()
        exact = t("self.exact", exact=f"{num(float(step.expected), 5)} {unit}".rstrip(),
                  allowed=allowed,
                  why=t("self.why_drawing" if quantity.drawing else "self.why_computed"))
        (st.success if said.ok else st.warning)(f"{hint(step, said)} {exact}")
