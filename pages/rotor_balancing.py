"""Chapter 7 — rotor balancing: static and two-plane dynamic, with the U and V polygons."""

from __future__ import annotations

import math
from itertools import accumulate

import pandas as pd
import streamlit as st

from figures.balancing import end_view_figure, rotor_3d_figure
from figures.polygon import polygon_figure, polygon_svg
from mechanisms.loader import as_loaded
from mechanisms.rotor import PLANES, Correction, Mass, Rotor
from methods import practice_steps
from methods.scales import polygon_scale
from solvers.balancing import Balance, BalanceError, balance, graphical_error, unit
from ui import practice
from ui.benchmarks import speed_panel
from ui.book import differs, rotor_changes
from ui.chapters import page_title
from ui.editor_tables import linked_table, typed_table
from ui.export import Rows, chart, print_button, show_table
from ui.firstpaint import hold, rerun_whole, waiting
from ui.fragments import fragment
from ui.i18n import message, num, scaled_title, t
from ui.layout import page_columns
from ui.numbers import as_given, bound_slider, last_value, link_option, number_field
from ui.present import look
from ui.scenes import scene_download, scene_picker
from ui.selfcheck import answer_box, named
from ui.url import seed, stop


def legend() -> tuple[str, str]:
    return t("rotor.fig_known"), t("rotor.fig_corrections")


MM = 1e3  # the course writes radii and distances in mm, U in kg·mm and V in kg·mm²
COLUMNS = ("m [kg]", "r [mm]", "φ [°]", "x [mm]")

page_title("pages/rotor_balancing.py")
practice.class_only("pr_balance")  # a seated student: the class's practice alone
controls, main = page_columns()



def defaults(base: Rotor) -> dict[str, object]:
    values: dict[str, object] = {"mode": base.mode, "omega": base.omega or 100.0}
    for plane in PLANES:
        c = base.corrections.get(plane, Correction(radius=0.1))
        given = "mass" if c.mass is not None else "radius"
        values[f"given{plane}"] = given
        values[f"value{plane}"] = as_given(getattr(c, given) * (1 if given == "mass" else MM))
        values[f"x{plane}"] = as_given(base.planes.get(plane, 0.0) * MM)
    return values


def table_of(base: Rotor) -> pd.DataFrame:
    """The task's masses in the table's units, as the task gives them (120°, not the
    119,99999999999999 that radians and back make of it)."""
    return pd.DataFrame([tuple(map(as_given, (m.mass, m.radius * MM, math.degrees(m.angle), m.x * MM)))
                         for m in base.masses], columns=COLUMNS)


def masses_of(table: pd.DataFrame) -> tuple[Mass, ...]:
    """The table's masses in the scene's units (m, rad)."""
    return tuple(Mass(float(m), float(r) / MM, math.radians(float(a)), float(x) / MM)
                 for m, r, a, x in table.dropna()[list(COLUMNS)].itertuples(index=False))


def rotor_from_inputs(base: Rotor, table: pd.DataFrame, typed: dict[str, float]) -> Rotor:
    masses = masses_of(table)
    mode = st.session_state["mode"]
    planes = PLANES if mode == "dynamic" else PLANES[:1]
    corrections = {}
    for plane in planes:
        value = typed[f"value{plane}"]
        if st.session_state[f"given{plane}"] == "mass":
            corrections[plane] = Correction(mass=value)
        else:
            corrections[plane] = Correction(radius=value / MM)
    return base.with_(masses=masses, mode=mode, omega=typed["omega"],
                      planes={p: typed[f"x{p}"] / MM for p in planes},
                      corrections=corrections)


with controls:
    base = scene_picker("rotor")
    seed(defaults(base), st.session_state["scene"])
    modes = {"dynamic": "rotor.mode_dynamic", "static": "rotor.mode_static"}
    link_option(st.radio, t("rotor.mode"), list(modes), "mode", default=base.mode,
               format_func=lambda m: t(modes[m]), horizontal=True)
    givens = {"mass": "rotor.given_mass", "radius": "rotor.given_radius"}
    typed: dict[str, float] = {}
    for plane in PLANES[:1] if st.session_state["mode"] == "static" else PLANES:
        st.markdown(f"**{t('rotor.plane', plane=plane)}**")
        typed[f"x{plane}"] = number_field(t("rotor.plane_x"), f"x{plane}", url=True)
        given = link_option(st.radio, t("rotor.given"), list(givens), f"given{plane}",
                           format_func=lambda g: t(givens[g]), horizontal=True)
        unit_label = "kg" if given == "mass" else "mm"
        typed[f"value{plane}"] = number_field(f"{t(givens[given])} [{unit_label}]",
                                              f"value{plane}", minimum=1e-6, url=True)
    typed["omega"] = number_field(t("rotor.omega"), "omega", minimum=0.1, url=True)
    precision_slot = st.container()  # the drawing's precision: drawn by accuracy() below

with main:
    drawing = st.container()  # the polygons first, beside their controls (filled below)
    st.markdown(f"**{t('rotor.masses')}**")
    editor = st.container()
    practising = practice.toggle("pr_balance")
# a fresh visit: the masses' editor (a grid script, the heaviest element here) after the
# polygons' paint, which it held back by a fifth (ui/firstpaint.py); the link's table meanwhile
own = table_of(base)
table_rules = {"name": t("rotor.masses_short"), "rows_fixed": False,
               "loader": lambda rows: as_loaded(base.with_(masses=masses_of(rows))),
               "fields": dict(zip(("mass", "radius", "angle", "x"), COLUMNS))}
if not practising and hold():
    table = linked_table("masses", own, base.id, **table_rules)
else:
    with editor:
        table = typed_table("masses", own, base.id, COLUMNS, num_rows="dynamic", width="stretch",
                            **table_rules)
rotor = rotor_from_inputs(base, table, typed)
try:
    result = balance(rotor)
except BalanceError as exc:
    rerun_whole()  # (no polygon follows to bring the editor)
    with main:
        st.error(message(exc))
    stop()
with main:
    for note in result.notes:
        st.info(message(note))

with controls:
    scene_download(rotor)


def v_polygon(rotor: Rotor, us: list[complex], found: dict[str, complex]) -> None:
    """The moment polygon about the chosen plane, closed by the other plane's correction."""
    reference = link_option(st.radio, t("rotor.reference"), ["II", "I"], "ref", horizontal=True)
    other = "I" if reference == "II" else "II"
    x_ref = rotor.planes[reference]
    vs = [u * (m.x - x_ref) * MM for u, m in zip(us, rotor.masses)]  # kg·mm²
    v_fix = found[other] * (rotor.planes[other] - x_ref) * MM
    scale = polygon_scale(accumulate(vs))
    scale = number_field(t("rotor.scale_v"), f"UV{reference}-{rotor.id}", scale, minimum=1e-6)
    known, closing = [(f"V{i + 1}", v) for i, v in enumerate(vs)], [(f"V{other}", v_fix)]
    title = t("rotor.v_title", plane=reference)
    chart(polygon_figure(known, closing, scale, scaled_title(title, scale, "kg·mm²"), legend(),
                         look(), axes=("z", "y")), f"{rotor.id}-V", key="vpoly")
    if not waiting():  # (on a fresh visit, after the polygon's paint)
        caption = t("rotor.svg_caption", scene=rotor.id, polygon=title, scale=num(scale, 4),
                    unit="kg·mm²")
        print_button(lambda: polygon_svg(known, closing, scale, caption),
                     f"{rotor.id}-V.svg", key="vsvg")


def results_table(result: Balance, as_in_book: bool) -> Rows:
    """Each correction, exact beside the book's printed value where the preset has one and
    the rotor is the task's own (a changed rotor's book values belong to another task)."""
    rows = []
    for plane, f in result.corrections.items():
        for quantity, label, shown, unit_label in (("mass", "rotor.q_mass", f.mass, "kg"),
                                                   ("radius", "rotor.q_radius", f.radius * MM, "mm"),
                                                   ("angle_deg", "rotor.q_angle",
                                                    math.degrees(f.angle), "°")):
            book = rotor.book.get(f"corrections.{plane}.{quantity}") if as_in_book else None
            if quantity == "radius" and book is not None:
                book *= MM
            rows.append({t("rotor.col_plane"): plane, t("rotor.col_quantity"): t(label),
                         t("rotor.col_exact"): f"{num(shown, 5)} {unit_label}",
                         t("rotor.col_book"): "" if book is None else f"{num(book, 5)} {unit_label}",
                         t("rotor.col_diff"): "" if book is None else
                         f"{num(100 * (book - shown) / shown if shown else 0.0, 2)} %"})
    return rows


with main:
    if practising:  # the corrections stay hidden: the student finds them
        practice.panel(practice_steps.balance(result), "pr_balance", t("practice.sheet_rotor"))
        stop()  # (app.py still ends the run)
    results = st.container()  # under the table; filled after the polygons are sent
    names = [f"U{i + 1}" for i in range(len(rotor.masses))]
    us = [m.mass * m.radius * unit(m.angle) * MM for m in rotor.masses]  # kg·mm
    found = {p: f.u * MM for p, f in result.corrections.items()}
    tab_v, tab_u, tab_end, tab_3d = drawing.tabs([t("rotor.tab_v"), t("rotor.tab_u"),
                                                  t("rotor.tab_end"), t("rotor.tab_3d")],
                                                 key="tab", on_change="rerun")
    scale_key = f"UU-{rotor.id}"
    scale_u = last_value(scale_key) or polygon_scale(accumulate(us))
    if tab_u.open:
        with tab_u:
            scale_u = number_field(t("rotor.scale_u"), scale_key, scale_u, minimum=1e-6)
            known, closing = list(zip(names, us)), [(f"U{p}", u) for p, u in found.items()]
            chart(polygon_figure(known, closing, scale_u,
                                 scaled_title(t("rotor.tab_u"), scale_u, "kg·mm"), legend(),
                                 look(), axes=("z", "y")), f"{rotor.id}-U", key="upoly")
            if not waiting():
                caption = t("rotor.svg_caption", scene=rotor.id, polygon=t("rotor.tab_u"),
                            scale=num(scale_u, 4), unit="kg·mm")
                print_button(lambda drawn=(known, closing, scale_u, caption): polygon_svg(*drawn),
                             f"{rotor.id}-U.svg", key="usvg")
    if tab_v.open:
        with tab_v:
            if rotor.mode == "dynamic":
                v_polygon(rotor, us, found)
            else:
                st.info(t("rotor.static_no_v"))
    if tab_end.open:
        with tab_end:
            chart(end_view_figure([(f"m{i + 1}", m.radius * unit(m.angle))
                                   for i, m in enumerate(rotor.masses)],
                                  [(f"m{p}", f.radius * unit(f.angle))
                                   for p, f in result.corrections.items()],
                                  t("rotor.tab_end"), t, look()), f"{rotor.id}-end", key="end")
    if tab_3d.open:
        with tab_3d:
            chart(rotor_3d_figure([(f"m{i + 1}", m.mass, m.radius * unit(m.angle), m.x)
                                   for i, m in enumerate(rotor.masses)],
                                  [(f"m{p}", f.mass, f.radius * unit(f.angle), rotor.planes[p])
                                   for p, f in result.corrections.items()],
                                  rotor.planes, t("rotor.tab_3d"), t, look()), f"{rotor.id}-3d",
                  key="3d")
    rerun_whole()  # (no polygon sent: a static rotor's V tab)
    if not waiting():  # on a fresh visit, after the polygons' paint (ui/firstpaint.py)
        with results:
            st.header(t("rotor.results"))
            changed = rotor_changes(rotor, base) if base.book else []
            corrections_table = results_table(result, not changed)
            show_table(corrections_table, f"{rotor.id}-corrections.csv", "csv")
            if changed:  # the book's values belong to the task as the book poses it
                differs(changed, defaults(base), ("masses",))
            cols = st.columns(2)
            cols[0].metric(t("rotor.residual_force"),
                           f"{num(result.residual_force * MM, 2)} kg·mm")
            cols[1].metric(t("rotor.residual_moment"),
                           f"{num(result.residual_moment * MM**2, 2)} kg·mm²")
            before, after = result.bearing_forces(False), result.bearing_forces(True)
            if before:
                cols = st.columns(4)
                for i, bearing in enumerate(("A", "B")):
                    cols[i].metric(t("rotor.bearing_before", bearing=bearing),
                                   f"{num(before[bearing], 4)} N")
                    cols[2 + i].metric(t("rotor.bearing_after", bearing=bearing),
                                       f"{num(after[bearing], 2)} N")


def analytic_steps(rotor: Rotor) -> Rows:
    """Each mass's y, z, its arm L from plane II and the products the moments sum."""
    x_ref = rotor.planes.get("II", 0.0)

    def row(i: int, m) -> dict:
        y, z = m.radius * math.sin(m.angle) * MM, m.radius * math.cos(m.angle) * MM
        arm = (m.x - x_ref) * MM
        return {"i": i + 1, "y = r·sin φ [mm]": num(y, 5), "z = r·cos φ [mm]": num(z, 5),
                "L [mm]": num(arm, 5), "m·L·y [kg·mm²]": num(m.mass * arm * y, 5),
                "m·L·z [kg·mm²]": num(m.mass * arm * z, 5), "m·y [kg·mm]": num(m.mass * y, 5),
                "m·z [kg·mm]": num(m.mass * z, 5)}
    return [row(i, m) for i, m in enumerate(rotor.masses)]


def drawing_accuracy(precision: float) -> None:
    """Under the polygons: what a drawing to the chosen precision misses, the answer box, and
    the analytical solution step by step."""
    st.header(t("rotor.accuracy_title"))
    rows = []
    for plane, f in result.corrections.items():
        size = abs(found[plane])
        length_error, angle_error = graphical_error(size, scale_u * 100, precision / MM,
                                                    vectors=len(us) + 1)
        if rotor.corrections[plane].mass is None:  # the mass is read off: U = m·r, r given
            error, exact, label = length_error / (f.radius * MM), f.mass, f"m{plane} [kg]"
        else:  # the radius is read off
            error, exact, label = length_error / f.mass, f.radius * MM, f"r{plane} [mm]"
        rows.append({t("rotor.col_plane"): plane, t("rotor.col_graphical"): f"{label}: ± {num(error, 2)}",
                     t("rotor.col_relative"): f"± {num(100 * error / exact, 2)} %",
                     t("rotor.col_angle"): f"± {num(math.degrees(angle_error), 2)}°"})
    show_table(rows, f"{rotor.id}-graphical-error.csv", "csv_accuracy")
    st.caption(t("rotor.accuracy_note", precision=num(precision, 2)))
    answer_box(lambda: named(rotor, base), key="self")  # (exams.judged: the task's tolerances)

    # filled only while open: closed, a rerun skips its table
    steps_box = st.expander(t("rotor.steps_title"), key="steps_open", on_change="rerun")
    if steps_box.open:
        with steps_box:
            show_table(analytic_steps(rotor), f"{rotor.id}-steps.csv", "csv_steps")
            for plane, u in result.u_needed.items():
                st.markdown(t("rotor.step_plane", plane=plane, Y=num(u.imag * MM, 5),
                              Z=num(u.real * MM, 5), tan=num(u.imag / u.real, 5) if u.real else "∞",
                              angle=num(math.degrees(result.corrections[plane].angle), 5)))


@fragment
def accuracy() -> None:
    """The precision a student draws to and what it changes (the section under the
    polygons): moving it reruns this alone, not the inputs, the balance and the polygons.
    The slider is drawn on every run (Streamlit forgets a widget a run leaves out)."""
    with precision_slot:
        precision = bound_slider(t("rotor.precision"), 0.1, 2.0, value=0.5, step=0.1,
                                 key="precision")
    with main:  # (a fragment may only write where it wrote in the last full run: every run)
        section = st.empty()
    if not waiting():  # on a fresh visit, after the chart is painted (ui/firstpaint.py)
        with section.container():
            drawing_accuracy(precision)


accuracy()
if not waiting():
    with main:
        speed_panel("rotor_balancing", rotor.id)
