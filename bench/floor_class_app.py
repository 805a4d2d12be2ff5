"""The least a class's page can be, for ``deploy/loadtest.py --class N --floor``: a student's
page that only grades a typed check, stores it and answers it (no plan, no figure), and a
lecturer's page that only counts the stored checks every second — the same widget keys and
pages as the real ones, so the same simulated class drives it. What the class load costs
here is Streamlit's, the store's and the machine's; the rest of the real pages' is ours."""

import sys
from pathlib import Path

import streamlit as st

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # classes/, not bench/classes.py
from classes import store  # noqa: E402
from mechanisms import load_preset  # noqa: E402
from methods.practice import TRIES, grade, polar  # noqa: E402
from methods.practice_steps import steps_for  # noqa: E402

STEPS = steps_for(load_preset("zbirka-3.1"), "plans")


def student() -> None:
    code, token = st.query_params["class"], st.query_params["student"]
    done = st.session_state.setdefault("done", {})  # step id → tries
    index = st.session_state.setdefault("index", 0)
    step = STEPS[index]
    fields = ("value",) if step.kind == "scalar" else ("len", "ang")
    with st.form(f"form_{step.id}"):
        typed = [st.text_input(name, key=f"pr_plans_{name}_{step.id}") for name in fields]
        if st.form_submit_button("Check"):
            values = [float(v) for v in typed]
            answer = values[0] if step.kind == "scalar" else polar(values[0], values[1])
            verdict = grade(step, answer)
            tries = done.setdefault(step.id, [])
            try:
                store.record(code, token, step.id, answer if step.kind == "scalar" else
                             [answer.real, answer.imag], verdict.diagnosis, store.new_check())
            except store.NotSaved:
                st.error("Not saved")
            else:
                tries.append(verdict.diagnosis)
                (st.success if verdict.ok else st.warning)(verdict.diagnosis)
    finished = "ok" in done.get(step.id, []) or len(done.get(step.id, [])) >= TRIES
    if st.button("Next", key="pr_plans_next", disabled=not finished):
        st.session_state["index"] = min(index + 1, len(STEPS) - 1)
        st.rerun()


def lecturer() -> None:
    found = store.opened(st.query_params["class"], st.query_params["key"])

    @st.fragment(run_every=1.0)
    def count() -> None:  # (only the new checks, as the real view fetches them)
        seen = st.session_state.setdefault("seen", set())
        seen.update(r["id"] for r in store.since(found, max(0, max(seen, default=0) - 256)))
        st.metric("Checks stored", len(seen))

    count()


st.navigation([st.Page(student, title="student", url_path="velocity_plans"),
               st.Page(lecturer, title="lecturer", url_path="class")]).run()
