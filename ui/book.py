"""The book-vs-exact table, shared by the textbook check page and the chapter pages."""

from __future__ import annotations

import math
from collections.abc import Mapping

import pandas as pd
import streamlit as st

from exams.variants import SUBSCRIPT, symbol, unit_of
from mechanisms.coverage import tasks
from reports.textbook import PRECISION, BookRow, check
from ui.editor_tables import forget_table
from ui.export import show_table
from ui.i18n import in_language, num, t

VERDICTS = {"agrees": "check.agrees", "close": "check.close", "differs": "check.differs", "slip": "check.slip",
            "layout": "check.layout", "missing": "check.missing"}
COUNTED = ("agrees", "close", "slip", "differs", "layout")  # the verdicts the check page counts
RESTORED = "_book_restored"  # "As in the book" was pressed: the whole page runs again
ROLES = {"fitted": "check.fitted", "chose": "check.chose", "predicted": "check.predicted"}
# a result key's kind (its head and last part; "" for any last part) → its words in locales/
WORDS = {
    ("points", "v"): "q.points.v", ("points", "a"): "q.points.a",
    ("points", "x"): "q.points.x", ("points", "y"): "q.points.y",
    ("points", "vx"): "q.points.vx", ("points", "vy"): "q.points.vy",
    ("points", "ax"): "q.points.ax", ("points", "ay"): "q.points.ay",
    ("points", ""): "q.points",  # a gear train's point: its speed
    ("members", "omega"): "q.members.omega", ("members", "epsilon"): "q.members.epsilon",
    ("members", "angle_deg"): "q.members.angle_deg",
    ("reactions", "magnitude"): "q.reactions.magnitude",
    ("reactions", "normal"): "q.reactions.normal",
    ("reactions", "tangential"): "q.reactions.tangential",
    ("sliders", "s"): "q.sliders.s", ("sliders", "v"): "q.sliders.v",
    ("sliders", "a"): "q.sliders.a",
    ("ratios", ""): "q.ratios", ("distances", ""): "q.distances",
    ("arms", ""): "q.arms", ("turned", ""): "q.turned",
    ("corrections", "mass"): "q.corrections.mass",
    ("corrections", "radius"): "q.corrections.radius",
    ("corrections", "angle_deg"): "q.corrections.angle_deg",
    ("driving", "torque"): "q.driving.torque", ("driving", "force"): "q.driving.force",
    ("driving", "power"): "q.driving.power",
    ("travel", "wheel_omega"): "q.travel.wheel_omega",
    ("travel", "crank_omega"): "q.travel.crank_omega",
    ("travel", "cycle_time"): "q.travel.cycle_time",
    ("travel", "step_time"): "q.travel.step_time",
    ("travel", "step_distance"): "q.travel.step_distance",
}
# the travel's givens as task 1.3 writes them (mechanisms.schema.Travel's fields)
TRAVEL_GIVEN = {"speed": ("v_R", "m/s"), "wheel_radius": ("R_t", "m"),
                "sprocket_wheel": ("R_a", "m"), "sprocket_crank": ("R_b", "m")}


def book_table(rows: list[BookRow]) -> pd.DataFrame:
    """One row per printed value: its symbol and unit first, the verdict in view, and what
    the quantity is in words last (put first, the words pushed the verdict out of a
    laptop's view of the table)."""
    fitted = any(r.role for r in rows)
    return pd.DataFrame([{
        t("check.col_quantity"): quantity(r.key),
        **({t("check.col_role"): t(ROLES[r.role])} if fitted else {}),
        t("check.col_book"): num(r.book, 6),
        t("check.col_exact"): "—" if r.exact is None else num(r.exact, 6),
        t("check.col_difference"): "—" if r.difference is None else num(r.difference, 3),
        t("check.col_verdict"): t(VERDICTS[r.verdict]),
        t("check.col_note"): in_language(r.note, r.note_sr) if r.slip is None else
        f"{in_language(r.note, r.note_sr)} {t('check.slip_value', value=num(r.slip, 4))}".strip(),
        t("check.col_what"): words(r.key)}
        for r in rows])


def quantity(key: str) -> str:
    """A printed value's row named as the course writes it, with its unit: v_E [m/s],
    h(G_5, F) [m], F₄₅ᵗ [N] (not points.E.v, arms.G_5.F, reactions.4-5.tangential)."""
    unit = unit_of(key)
    return f"{symbol(key)} [{unit}]" if unit and unit != "–" else symbol(key)


def words(key: str) -> str:
    """A result key's quantity in words in the page's language (``WORDS``): "velocity of
    point E", "arm of G_5 about point F", "action of member 4 on member 5, tangential
    part"; "" for a kind not named."""
    parts = key.split(".")
    head, last = parts[0], parts[-1]
    values: dict[str, str] = {"a": parts[1] if len(parts) > 1 else ""}
    if head in ("reactions", "sliders", "ratios"):
        values["p"], values["q"] = parts[1].split("-")
    if head == "ratios":  # ω₃/ω₁₀
        values["p"], values["q"] = (values[k].translate(SUBSCRIPT) for k in ("p", "q"))
    if head == "distances":
        values["a"] = symbol(key)
    if head == "arms":  # arms.G_5.F, arms.5-4.C: the force named as its symbol shows it
        values["a"], values["b"] = symbol(key)[2:-1].rsplit(", ", 1)
    if head == "turned":
        values["a"] = symbol(key)[3:-1]
    found = WORDS.get((head, last), WORDS.get((head, "")))
    return t(found, **values) if found else ""


def fit_summary(scene, rows: list[BookRow]) -> None:
    """A reconstructed figure: how well its fit reproduces the values it was made to, and
    the verdicts of the predictions — or that the fit is no reconstruction at all."""
    if getattr(scene, "fit", None) is None:  # gear trains and rotors are never fitted
        return
    predictions = [r for r in rows if r.role == "predicted"]
    good = sum(r.verdict in ("agrees", "close", "slip") for r in predictions)
    text = t("check.fit", used=len(scene.fit.used), residual=num(100 * scene.fit.residual, 2),
             good=good, predictions=len(predictions))
    if scene.fit.chose:
        text += " " + t("check.fit_chose", chose=len(scene.fit.chose))
    if scene.fit.residual > PRECISION:
        st.warning(t("check.fit_failed", residual=num(100 * scene.fit.residual, 2)))
    else:
        st.caption(text)


def book_section(scene, base, restore: Mapping[str, object]) -> None:
    """Book vs exact on a chapter page: only for the task as the book poses it (the printed
    values belong to its own data), with its CSV. When the student has changed something,
    what differs in words, and one button that gives the page's widgets ``restore`` (the
    task's own values: its position, speed, loads and switches; nothing else)."""
    if st.session_state.pop(RESTORED, False):
        st.rerun(scope="app")  # the button sits in a fragment: the widgets above it too
    st.header(t("plans.book_title"))
    if scene == base:
        show_table(book_table(check(scene)), f"{scene.id}-book.csv", "csv_book")
        return
    differs(changes(scene, base), {**restore, RESTORED: True})


def differs(lines: list[str], restore: Mapping[str, object], tables: tuple[str, ...] = ()) -> None:
    """What the student changed of the task, each difference in words with both values and
    their units, and one button, *As in the book*, that gives the page's widgets
    ``restore`` and its ``tables`` their task's rows again."""
    st.info("\n".join([t("book.changed"), *(f"- {line}" for line in lines)]))

    def back() -> None:
        st.session_state.update(restore)
        for key in tables:
            forget_table(key)

    st.button(t("book.restore"), help=t("book.restore_help"), icon=":material/menu_book:",
              on_click=back, key="book_restore")


def _both(what: str, now: str, book: str) -> str:
    return t("book.diff_value", what=what, now=now, book=book)


def _changed(what: str, now: float, book: float, unit: str) -> str:
    """A number the student changed, both values with their unit."""
    return _both(what, f"{num(now, 6)} {unit}", f"{num(book, 6)} {unit}")


def rotor_changes(rotor, base) -> list[str]:
    """What a rotor page's inputs changed of the task (each value with its unit)."""
    said = []
    if rotor.mode != base.mode:
        said.append(t("book.diff_mode"))
    if len(rotor.masses) != len(base.masses):
        said.append(_both(t("book.masses"), str(len(rotor.masses)), str(len(base.masses))))
    fields = (("m", "mass", 1.0, "kg"), ("r", "radius", 1e3, "mm"), ("φ", "angle", None, "°"),
              ("x", "x", 1e3, "mm"))
    for n, (now, old) in enumerate(zip(rotor.masses, base.masses), start=1):
        for symbol_, name, factor, unit in fields:
            a, b = getattr(now, name), getattr(old, name)
            if a != b:
                a, b = (math.degrees(a), math.degrees(b)) if factor is None else (a * factor, b * factor)
                said.append(_changed(f"{t('book.mass_n', n=n)}: {symbol_}", a, b, unit))
    for plane, x in rotor.planes.items():
        if plane in base.planes and x != base.planes[plane]:
            said.append(_changed(f"x_{plane}", x * 1e3, base.planes[plane] * 1e3, "mm"))
    for plane, c in rotor.corrections.items():
        old = base.corrections.get(plane)
        if old is not None and c != old:
            said.append(_both(t("book.correction", plane=plane), _given(c), _given(old)))
    if rotor.omega != base.omega and base.omega is not None:
        said.append(_changed("ω", rotor.omega, base.omega, "rad/s"))
    return said


def _given(c) -> str:
    return f"m = {num(c.mass, 6)} kg" if c.mass is not None else f"r = {num(c.radius * 1e3, 6)} mm"


def train_changes(train, base) -> list[str]:
    """What a gear page's inputs changed of the task (each value with its unit)."""
    said = []
    for now, old in zip(train.inputs, base.inputs):
        if now.velocity is not None and now.velocity != old.velocity:
            said.append(_changed(f"v ({t('book.member', member=now.member)})", now.velocity,
                                 old.velocity, "m/s"))
        elif now.velocity is None and now.omega != old.omega:
            said.append(_changed(f"ω{str(now.member).translate(SUBSCRIPT)}", now.omega, old.omega,
                                 "s⁻¹"))
    for now, old in zip(train.meshes, base.meshes):
        if now.internal != old.internal:  # (a ring ticked or not: another train)
            said.append(t("book.diff_ring", mesh=t("book.mesh", a=now.members[0], b=now.members[1]),
                          now=t("book.yes") if now.internal else t("book.no"),
                          book=t("book.yes") if old.internal else t("book.no")))
        for member, a, b in zip(now.members, now.radii, old.radii):
            if a != b:
                said.append(_changed(f"R ({t('book.mesh', a=now.members[0], b=now.members[1])}, "
                                     f"{t('book.member', member=member)})", a, b, "m"))
    return said


def changes(scene, base) -> list[str]:
    """What the page's scene changed of the task as loaded (``base``), each in words with
    the two values."""
    said = []
    if scene.driver.at != base.driver.at:
        if scene.driver.kind == "rotating":
            now, book = (num(math.degrees(d.at) % 360, 5) for d in (scene.driver, base.driver))
            said.append(t("book.diff_position", now=f"{now}°", book=f"{book}°"))
        else:
            said.append(t("book.diff_position_s", now=scene.driver.at, book=base.driver.at))
    if scene.driver.speed != base.driver.speed:
        unit = "s⁻¹" if scene.driver.kind == "rotating" else "m/s"
        said.append(t("book.diff_speed", now=f"{num(scene.driver.speed, 6)} {unit}",
                      book=f"{num(base.driver.speed, 6)} {unit}"))
    if scene.travel and base.travel:  # the hay tedder's travel (task 1.3)
        for field, (name, unit) in TRAVEL_GIVEN.items():
            now, book = getattr(scene.travel, field), getattr(base.travel, field)
            if now != book:
                said.append(_changed(name, now, book, unit))
    if scene.inertia != base.inertia:
        said.append(t("book.diff_inertia_on" if scene.inertia else "book.diff_inertia_off"))
    if scene.gravity != base.gravity:
        said.append(t("book.diff_gravity", now=scene.gravity, book=base.gravity))
    for n, member in scene.members.items():
        old = base.members[n]
        for field, key in (("mass", "book.diff_mass"), ("gyration", "book.diff_gyration"),
                           ("length", "book.diff_length")):
            if getattr(member, field) != getattr(old, field):
                said.append(t(key, member=n, now=getattr(member, field), book=getattr(old, field)))
    for force, old in zip(scene.forces, base.forces):
        name = force.label or f"F_{force.member}"
        if force.magnitude != old.magnitude:
            said.append(t("book.diff_force", name=name, now=force.magnitude, book=old.magnitude))
        if force.angle != old.angle:
            said.append(t("book.diff_force_angle", name=name, now=math.degrees(force.angle),
                          book=math.degrees(old.angle)))
    for moment, old in zip(scene.moments, base.moments):
        if moment.value != old.value:
            said.append(t("book.diff_moment", member=moment.member, now=moment.value,
                          book=old.value))
    return said or [t("book.diff_other")]


def coverage_table(checks: dict[str, list[BookRow] | str]) -> pd.DataFrame:
    """Per chapter: how many of the course's tasks have a preset, and the verdicts of their
    printed values."""
    rows = {}
    for task in tasks():
        row = rows.setdefault(task.chapter, {t("check.col_chapter"): task.chapter,
                                             t("check.col_tasks"): 0, t("check.col_presets"): 0,
                                             **{t(VERDICTS[v]): 0 for v in COUNTED}})
        row[t("check.col_tasks")] += 1
        row[t("check.col_presets")] += task.covered
        found = checks.get(task.preset)
        for r in found if isinstance(found, list) else []:
            if r.verdict in COUNTED:
                row[t(VERDICTS[r.verdict])] += 1
    return pd.DataFrame(sorted(rows.values(), key=lambda r: r[t("check.col_chapter")]))


def tasks_table() -> pd.DataFrame:
    """Every task and worked example of the course's texts, with its preset or why it has none."""
    return pd.DataFrame([{
        t("check.col_text"): in_language(task.text, task.text_sr),
        t("check.col_task"): task.number,
        t("check.col_preset"): task.preset if task.covered else "—",
        t("check.col_why_none"): in_language(task.reason.get("en", ""), task.reason.get("sr", ""))}
        for task in tasks()])
