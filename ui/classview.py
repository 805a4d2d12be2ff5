"""The lecturer's live class view (the lecturer's link): for each step of the class's method,
how many students reached it and how they did at the first try, as one bar per step; the
mistake most of them made; the class's latest answers to one step drawn over the exact
construction; the same counts split by a given value in a class of variants; exports.

Results are hidden until the lecturer reveals them (per step or all), and nicknames until
asked for: a projector must not give the answers away. The figures refresh in a fragment
that reruns every second and fetches only the checks stored since the last one.
"""

from __future__ import annotations

import html
from datetime import datetime

import pandas as pd
import streamlit as st

from classes import store, summary
from classes.steps import scene_of
from classes.store import Class, ClassError, StoreDown
from lti.grades import close_test
from exams.codes import parse
from exams.variants import MAX_COUNT, VariantError, from_code, generate
from figures.classview import COLOURS, spread, step_bars
from figures.classview import cloud as cloud_figure
from figures.plans import plain
from mechanisms import SceneError
from methods.practice import DIAGNOSES, Step
from methods.practice_steps import steps_for
from ui.boundary import boundary
from ui.classroom import wait_for_store
from ui.export import chart
from ui.i18n import counted, current, kept_language, message, num, t, title_of
from ui.practice import shown_unit
from ui.present import look

TICK = 1.0  # s between two looks at the store: a check shows within about this and a rerun
MARGIN = 256  # checks fetched again below the last one seen (see ``_fetch``)


@st.cache_resource(max_entries=16, show_spinner=False)
def class_scene(scene: str):
    """A class's scene (a preset id or a builder link's ``s=`` text)."""
    return scene_of(scene)


@st.cache_resource(max_entries=16, show_spinner=False)
def class_steps(scene: str, method: str, at: float | None) -> list[Step]:
    """The steps of a class's method on its scene."""
    return steps_for(class_scene(scene), method, at)


@st.cache_resource(max_entries=256, show_spinner=False)
def variant_steps(code: str, method: str, at: float | None) -> dict[str, Step]:
    """A variant's own steps by id: each student's answer is drawn relative to these."""
    return {s.id: s for s in steps_for(from_code(code).scene, method, at)}


@st.cache_resource(max_entries=16, show_spinner=False)
def variant_givens(settings_code: str, count: int) -> dict[str, tuple[str, str, dict[str, float]]]:
    """Each given of a variant set's first ``count`` variants: label → (label, unit, variant
    code → value). (Made again as more students join: ``count`` grows by 30.)"""
    settings, _ = parse(settings_code)
    out: dict[str, tuple[str, str, dict[str, float]]] = {}
    for variant in generate(settings, count).variants:
        for given, value in variant.given:
            out.setdefault(given.label, (given.label, given.unit, {}))[2][variant.code] = value
    return out


def _fetch(found: Class) -> list[dict]:
    """The class's checks, kept in the session and topped up with what was stored since.
    A check's number is drawn before its transaction commits, so one numbered below the
    last seen can still appear (PostgreSQL, several writers): the last MARGIN are fetched
    again and merged by number."""
    memo = st.session_state.setdefault(f"_class_rows_{found.code}", {})
    after = max(memo, default=0)
    try:
        for row in store.since(found, max(0, after - MARGIN)):
            memo[row["id"]] = row
    except StoreDown:  # the view keeps what it has, says so, and catches up after
        st.warning(t("class.store_down_view"), icon=":material/cloud_off:")
    return _seen(found)


def _seen(found: Class) -> list[dict]:
    """The checks this view has fetched, in the order stored."""
    memo = st.session_state.setdefault(f"_class_rows_{found.code}", {})
    return [memo[k] for k in sorted(memo)]


def view(code: str, key: str) -> bool:
    """The whole view, for the lecturer's link (``?class=CODE&key=KEY``): whether the key
    opened it."""
    try:
        found = store.opened(code, key)
    except StoreDown:
        wait_for_store(t("class.store_down_open"))
        return False
    except ClassError as exc:
        st.error(message(exc.args[0]))
        return False
    st.header(t("class.results", code=found.code))
    try:
        steps = class_steps(found.scene, found.method, found.at)
    except (SceneError, ValueError) as exc:
        st.error(t("class.no_steps", why=message(exc)))
        return True
    st.caption(f"{t(f'class.method_{found.method}')} · {title_of(class_scene(found.scene))} · "
               f"{t('class.view_live')}")
    if found.test:
        test_state(found, key)
    symbols = {s.id: f"{i + 1}. {plain(s.symbol)}" for i, s in enumerate(steps)}
    # the lecturer's controls in one row (the sidebar is hidden on a projector)
    cols = st.columns([1, 1, 1, 2, 1], vertical_alignment="bottom")
    every = cols[0].toggle(t("class.reveal_all"), key="cv_all", help=t("class.hidden_note"))
    right = cols[1].toggle(t("class.show_right"), key="cv_right")
    names = cols[2].toggle(t("class.show_names"), key="cv_names", help=t("class.names_help"))
    look_at = cols[3].selectbox(t("class.look_step"), list(symbols), key="cv_step",
                                format_func=symbols.get)
    with cols[4].popover(t("class.more"), icon=":material/tune:", width="stretch"):
        chosen = st.multiselect(t("class.revealed_steps"), list(symbols), key="cv_shown",
                                format_func=symbols.get, disabled=every,
                                placeholder=t("class.choose_steps"))
        split = _split_choice(found)
    shown = set(symbols) if every else set(chosen)
    live(found, key, steps, shown, names, look_at, right, split)
    exports(found, key, steps)
    return True


def test_state(found: Class, key: str) -> None:
    """A test's state, and its lecturer's button to close it (the students then see their
    verdicts, and a Moodle activity's grades are sent)."""
    if found.closed is not None:
        st.success(t("class.test_closed"), icon=":material/lock_open:")
        return
    st.info(t("class.test_open"), icon=":material/lock:")
    if st.button(t("class.test_close"), key="cv_close", icon=":material/lock_open:"):
        try:
            close_test(found.code, key)
        except ClassError as exc:
            st.error(message(exc.args[0]))
            return
        st.rerun()


def _split_choice(found: Class) -> str | None:
    """In a class of variants: the label of the given the lecturer splits the counts by."""
    if not found.variants:
        return None
    try:
        labels = list(variant_givens(found.variants, 1))
    except (VariantError, SceneError):
        return None
    none = t("class.split_none")
    label = st.selectbox(t("class.split_by"), [none, *labels], key="cv_split")
    return None if label == none else label


@st.fragment(run_every=TICK)
def live(found: Class, key: str, steps: list[Step], shown: set[str], names: bool,
         look_at: str, right: bool, split: str | None) -> None:
    """What changes as students check: refreshed every TICK seconds, alone (the lecturer's
    controls above keep their state, the charts their zoom). A class deleted or ended
    meanwhile is said, and its last counts stay for the lecturer to read."""
    with boundary():
        try:
            store.opened(found.code, key)
        except StoreDown:
            pass  # (said by _fetch, which keeps what it has)
        except ClassError as exc:
            st.error(message(exc.args[0]), icon=":material/event_busy:")
            return _counts(found, key, steps, shown, names, look_at, right, split, live=False)
        _counts(found, key, steps, shown, names, look_at, right, split)


def _counts(found: Class, key: str, steps: list[Step], shown: set[str], names: bool,
            look_at: str, right: bool, split: str | None, live: bool = True) -> None:
    """The counts, bars, cloud, bands and students' table from the checks seen (fetched
    anew while the class is open), and its exports."""
    rows = _fetch(found) if live else _seen(found)
    ids = [s.id for s in steps]
    counts = summary.counts(rows, ids, found.rules)
    left, right_col = st.columns(2)
    left.metric(t("class.students"), len({r["student"] for r in rows}))
    right_col.metric(t("class.checks"), len(rows))
    if not rows:
        st.info(t("class.waiting"), icon=":material/hourglass_empty:")
    if not shown:
        st.caption(t("class.hidden_note"))
    chart(step_bars(steps, [dict(c.first_tries) for c in counts], [s in shown for s in ids],
                    t("class.bars_title"), t, look()), f"class-{found.code}", key="cv_bars")
    for i, (step, count) in enumerate(zip(steps, counts)):
        if step.id in shown and count.reached:
            st.markdown(t("class.step_counts_test" if found.test else "class.step_counts", n=i + 1,
                          symbol=plain(step.symbol), reached=count.reached, first=count.first,
                          later=count.later, revealed=count.revealed, wrong=count.wrong)
                        + " " + mistake_text(count))
    if look_at in shown:
        _drawing(found, steps, ids.index(look_at), rows, right)
    if split is not None:
        _by_band(found, rows, steps, shown, split)
    if names:
        table = pd.DataFrame(summary.students(rows, ids, found.rules), columns=["nickname", "done", "first"])
        st.dataframe(table.rename(columns={"nickname": t("class.table_nickname"),
                                           "done": t("class.table_done"),
                                           "first": t("class.table_first")}),
                     hide_index=True, width="stretch")


def mistake_text(count: summary.StepCount) -> str:
    """The step's most common mistake in words, with how many made it (or the mistakes
    made equally often, each named)."""
    made = count.mistake
    if made is None:
        return t("class.no_mistake")
    students, tied = made
    if len(tied) == 1:
        return t(f"class.mistake_{tied[0][0]}", who=counted("class.n_students", students),
                 term=plain(tied[0][1]))
    return t("class.mistake_tie", who=counted("class.n_students", students), made="; ".join(
        t(f"class.diagnosis_{d}") + (f" ({plain(term)})" if term else "") for d, term in tied))


def _drawing(found: Class, steps: list[Step], index: int, rows: list[dict], right: bool) -> None:
    """The class's latest answers to one step: a cloud of tips over the construction, or
    for a number, how the values spread."""
    step = steps[index]
    latest = summary.latest(rows, step.id, found.rules).values()
    answers = []
    for row in latest:
        value = complex(*row["answer"]) if isinstance(row["answer"], list) else float(row["answer"])
        own = _own(found, row, step)
        answers.append((summary.relative(value, own, step.expected, step.kind), row["diagnosis"]))
    if found.variants:
        st.caption(t("class.relative_note"))
    title = t("class.cloud_title", symbol=plain(step.symbol), who=counted("class.n_students", len(answers)))
    if step.kind == "scalar":
        fig = spread(step, [(float(v.real) if isinstance(v, complex) else v, d) for v, d in answers],
                     right, title, t, shown_unit(step), look())
    else:
        fig = cloud_figure(steps, index, [(complex(v), d) for v, d in answers], right, title, t, look())
    chart(fig, f"class-{found.code}-{step.id}", key="cv_cloud")


def _own(found: Class, row: dict, step: Step):
    """The exact value of ``step`` for the student who gave ``row`` (their variant's)."""
    if not row["variant"]:
        return step.expected
    try:
        own = variant_steps(row["variant"], found.method, found.at).get(step.id)
    except (VariantError, SceneError):
        return step.expected
    return step.expected if own is None else own.expected


def _by_band(found: Class, rows: list[dict], steps: list[Step], shown: set[str], label: str) -> None:
    """The first-try counts of each band of the chosen given, side by side."""
    most = max([parse(r["variant"])[1] for r in rows if r["variant"]] + [1])
    _, unit, values = variant_givens(found.variants, min(MAX_COUNT, 30 * -(-most // 30)))[label]
    by_student = {r["student"]: values.get(r["variant"]) for r in rows if r["variant"]}
    bands = summary.bands({s: v for s, v in by_student.items() if v is not None})
    table = {}
    for band in sorted(set(bands.values())):
        members = {s for s, b in bands.items() if b == band}
        counts = summary.counts([r for r in rows if r["student"] in members], [s.id for s in steps], found.rules)
        name = t("class.band", low=num(band[0], 4), high=num(band[1], 4), unit=unit)
        table[f"{name} ({len(members)})"] = [f"{c.first}/{c.reached}" if s.id in shown else "·"
                                             for s, c in zip(steps, counts)]
    st.markdown(f"**{t('class.split_title', label=label)}**")
    st.dataframe(pd.DataFrame(table, index=[f"{i + 1}. {plain(s.symbol)}" for i, s in enumerate(steps)]),
                 width="stretch")


def exports(found: Class, key: str, steps: list[Step]) -> None:
    """Every try as CSV or JSON lines (what ``class export`` writes), and a printable
    summary; made when clicked, from the store — or, when it cannot answer (down, or the
    class deleted meanwhile), from the checks this view has seen."""
    memo = st.session_state.setdefault(f"_class_rows_{found.code}", {})

    def rows() -> list[dict]:
        try:
            return store.export(found.code, key)
        except ClassError:
            return [{k: v for k, v in memo[n].items() if k != "id"} for n in sorted(memo)]

    def outcomes() -> str:
        done = rows()
        try:
            everyone = store.roster(found)
        except ClassError:  # (the students seen in the checks)
            everyone = {}
        return summary.as_json(summary.of_class(found, done, everyone))

    cols = st.columns(4)
    cols[3].download_button(t("class.export_summary"), lambda: outcomes().encode("utf-8"),
                            f"class-{found.code}-summary.json", mime="application/json",
                            on_click="ignore", icon=":material/summarize:")
    cols[0].download_button(t("class.export_csv"), lambda: store.as_csv(rows()).encode("utf-8"),
                            f"class-{found.code}.csv", mime="text/csv", on_click="ignore",
                            icon=":material/download:")
    cols[1].download_button(t("class.export_jsonl"), lambda: store.as_jsonl(rows()).encode("utf-8"),
                            f"class-{found.code}.jsonl", mime="application/jsonl",
                            on_click="ignore", icon=":material/download:")
    cols[2].download_button(t("class.export_print"), kept_language(
        lambda: printable(found, steps, rows()).encode("utf-8")), f"class-{found.code}.html",
        mime="text/html", on_click="ignore", icon=":material/print:")


def printable(found: Class, steps: list[Step], rows: list[dict]) -> str:
    """The summary on one A4 page: per step the counts, the first tries as a bar, the most
    common mistake (numbers the page's language's way)."""
    counts = summary.counts(rows, [s.id for s in steps], found.rules)
    most = max([c.reached for c in counts] + [1])
    head = "".join(f"<th>{html.escape(t(k))}</th>" for k in (
        "class.print_step", "class.print_reached", "class.print_first", "class.print_later",
        "class.print_revealed", "class.print_bar", "class.print_mistake"))
    body = []
    for i, (step, c) in enumerate(zip(steps, counts)):
        share = f" ({num(100 * c.first / c.reached, 3)} %)" if c.reached else ""
        bar = "".join(f'<span style="width:{100 * n / most:.1f}%;background:{COLOURS[d]}"></span>'
                      for d, n in sorted(c.first_tries.items(), key=lambda kv: DIAGNOSES.index(kv[0])))
        body.append(f"<tr><td>{i + 1}. {html.escape(plain(step.symbol))}</td><td>{c.reached}</td>"
                    f"<td>{c.first}{share}</td><td>{c.later}</td><td>{c.revealed}</td>"
                    f'<td class="bar">{bar}</td><td>{html.escape(mistake_text(c))}</td></tr>')
    legend = " ".join(f'<span class="key" style="background:{COLOURS[d]}"></span>'
                      f"{html.escape(t(f'class.diagnosis_{d}'))}" for d in DIAGNOSES)
    made = t("class.print_made", time=datetime.now().strftime("%Y-%m-%d %H:%M"),
             students=len({r["student"] for r in rows}), checks=len(rows))
    return (f'<!DOCTYPE html><html lang="{current()}"><head><meta charset="utf-8">'
            f"<title>{html.escape(t('class.print_title', code=found.code))}</title><style>{PRINT_STYLE}</style>"
            f"</head><body><h1>{html.escape(t('class.print_title', code=found.code))}</h1>"
            f"<p>{html.escape(t(f'class.method_{found.method}'))} · "
            f"{html.escape(title_of(class_scene(found.scene)))}</p>"
            f"<table><tr>{head}</tr>{''.join(body)}</table><p>{legend}</p>"
            f'<p class="small">{html.escape(made)}</p></body></html>')


PRINT_STYLE = """@page { size: A4 landscape; margin: 12mm; }
body { font-family: "DejaVu Sans", sans-serif; font-size: 10pt; }
table { border-collapse: collapse; width: 100%; }
th, td { border: 1px solid #999; padding: 3px 5px; text-align: left; vertical-align: top; }
td.bar { width: 25%; }
td.bar span, span.key { display: inline-block; height: 10px; -webkit-print-color-adjust: exact;
  print-color-adjust: exact; }
span.key { width: 10px; margin: 0 3px 0 10px; }
.small { color: #555; font-size: 8pt; }"""
