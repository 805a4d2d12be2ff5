"""A page's first run in a session sends the chart and leaves out what can wait; the rerun
its paint starts sends the whole page (ui/firstpaint.py). The browser side: test_browser.py."""

import re

import pytest
from streamlit.testing.v1 import AppTest

from ui.builder import START, template
from ui.firstpaint import PAGE, SEEN

from .test_pages import ROOT, charts


def first_run(path: str, state: dict | None = None, **params) -> AppTest:
    """The first run of page ``path`` in a session (as a link with ``params`` opens it, with
    ``state`` in the session already)."""
    at = AppTest.from_file(str(ROOT / "app.py"), default_timeout=60)
    at.session_state["lang"] = "en"
    for key, value in (state or {}).items():
        at.session_state[key] = value
    at.query_params.update(params)
    at.run()  # AppTest reaches a page after a run of app.py (the home page) ...
    at.session_state[SEEN] = frozenset()  # ... as if that run had been this page's ...
    at.switch_page(path).run()  # ... and runs the page's file alone
    return at


def rerun(at: AppTest) -> None:
    """The rerun the chart's "painted" trigger starts, after app.py marked the page seen."""
    at.session_state[SEEN] = frozenset({at.session_state[PAGE]})
    at.run()


def test_app_py_marks_each_page_seen_after_its_run():
    at = AppTest.from_file(str(ROOT / "app.py"), default_timeout=60)
    at.run()
    assert at.session_state[PAGE] == "" and at.session_state[SEEN] == {""}  # the home page


@pytest.mark.parametrize("path, tables", [("pages/trajectories.py", 1),  # task 1.3's book;
                                          ("pages/velocity_plans.py", 2),  # its accuracy opens shut
                                          ("pages/kinetostatics.py", 2),
                                          ("pages/rotor_balancing.py", 3)])  # its masses' editor
def test_the_first_run_sends_the_chart_and_the_rerun_after_it_the_tables(path, tables):
    at = first_run(path)
    assert not at.exception
    assert charts(at) and all(c["first"] for c in charts(at).values())  # each reports its paint
    assert len(at.dataframe) == 0
    downloads, metrics = len(at.get("download_button")), len(at.metric)
    assert downloads <= 1  # the scene's own, at most
    rerun(at)
    assert not at.exception
    assert not any(c["first"] for c in charts(at).values())
    assert len(at.dataframe) == tables
    assert len(at.get("download_button")) >= downloads + max(tables, 1)  # each table's CSV
    if path.endswith("trajectories.py"):  # its readouts and the paths' CSV waited too
        assert len(at.metric) > metrics


def test_a_first_run_without_a_chart_leaves_nothing_out():
    """The rotor of a static balancing opens on its moment polygon's tab, which a static
    rotor does not draw: no chart would bring the rest, so nothing waits."""
    at = first_run("pages/rotor_balancing.py", mode="static")
    assert not charts(at)
    whole = len(at.dataframe)
    assert whole >= 2  # the masses (an input) and the corrections
    rerun(at)
    assert len(at.dataframe) == whole and not charts(at)


def test_the_rotor_draws_its_polygons_above_the_masses_and_the_corrections():
    """The polygons sit beside the controls that change them (first on the page's main
    column, on every screen), so the masses' editor and the corrections that follow their
    paint come under them: nothing the first paint shows moves."""
    at = first_run("pages/rotor_balancing.py")
    rerun(at)
    shown = [type(e).__name__ for e in at.main]
    polygons, editor = shown.index("Tab"), shown.index("Dataframe")
    assert polygons < editor < shown.index("Header")  # the tabs, the masses, the corrections


def test_a_rotor_that_cannot_be_balanced_shows_its_masses_at_once():
    """A link whose correction planes coincide stops before any polygon: the masses' editor,
    which waits for a polygon's paint, is drawn in that run with the error."""
    at = first_run("pages/rotor_balancing.py", xI="100", xII="100")
    assert at.error and not charts(at)
    assert len(at.dataframe) == 1  # the masses' editor


def test_the_builder_draws_first_and_the_open_tables_editor_follows():
    at = first_run("pages/builder.py")
    assert not at.exception and "build_fig" in charts(at)
    assert len(at.dataframe) == 0  # the open tab's editor waits for the drawing's paint
    rerun(at)
    assert len(at.dataframe) == 1 and not charts(at)["build_fig"]["first"]


def test_a_builder_document_that_does_not_close_shows_its_table_at_once():
    """A first run with no drawing (a coupler too short to close) reruns at once, whole: no
    paint would bring the editor it left out."""
    doc = template(START)
    doc["members"]["3"]["length"] = 0.01
    at = first_run("pages/builder.py", state={"build_doc": doc, "build_now": doc})
    assert not at.exception and not charts(at)
    assert len(at.dataframe) == 1 and at.error  # the table to mend, and why


def test_the_assur_page_whose_instant_fails_shows_its_groups_at_once():
    """A first run that stops on an error before its drawing leaves nothing out: the groups
    table is there with the message (analitika-2.1's four-bar cannot reach φ₂ = 140°)."""
    at = first_run("pages/assur_groups.py", scene="analitika-2.1", at="140")
    assert at.error and not charts(at)
    assert len(at.dataframe) == 1


@pytest.mark.parametrize("path, waiting", [("pages/assur_groups.py", 4),  # n, p5, p4, W
                                           ("pages/kinetostatics.py", 4)])  # M_p three ways, P
def test_the_counts_and_the_driving_torque_wait_for_the_drawing(path, waiting):
    """Metrics above the drawing held it back (8 ms each in chromium, and the Assur page's W
    formula brought KaTeX's 110 kB: issue 83): a fresh visit draws first, the rerun its paint
    starts brings them."""
    at = first_run(path)
    assert not at.exception and charts(at)
    before, formulas = len(at.metric), len(at.latex)
    rerun(at)
    assert not at.exception
    assert len(at.metric) == before + waiting
    if path.endswith("assur_groups.py"):
        assert formulas == 0 and any("W = 3n" in f.value for f in at.latex)


def test_an_assur_instant_that_fails_shows_its_counts_at_once():
    """No drawing follows an instant the mechanism cannot reach: its first run runs again
    whole at once, so the counts come with the message (analitika-2.1 at φ₂ = 140°)."""
    at = first_run("pages/assur_groups.py", scene="analitika-2.1", at="140")
    assert at.error and len(at.metric) == 4


def test_the_gear_train_draws_first_and_its_meshes_editor_follows():
    """The meshes' editor sits above the charts on a wide screen: on a fresh visit it waits
    for the chart's paint (its grid script held the first chart back: issue 83), and the
    train is solved from the link's table meanwhile — the same table the editor then shows."""
    at = first_run("pages/planetary_gears.py", scene="zbirka-6.8")
    assert not at.exception and charts(at)
    assert len(at.dataframe) == 0
    shown = at.caption.values
    rerun(at)
    assert not at.exception
    editors = [d for d in at.dataframe if "R_a [m]" in d.value.columns]
    assert len(editors) == 1  # the meshes' editor, with the whole page
    assert [c for c in at.caption.values if c in shown] == shown  # the same train solved


@pytest.mark.parametrize("path, held, link", [
    ("pages/trajectories.py", {"omega", "res"}, {"omega": "7", "res": "72"}),
    ("pages/kinetostatics.py", {"omega", "steps"}, {"omega": "7", "steps": "72"}),
    ("pages/velocity_plans.py", {"omega"}, {"omega": "7"})])
def test_secondary_sliders_wait_for_the_paint_and_the_chart_is_drawn_with_their_values(
        path, held, link):
    """Each slider above the chart cost the first paint about 15 ms (issue 83): ω₂ and the
    cycle's resolution come with the whole run. The first run draws with the values the
    sliders then show — the link's here — so the whole run's charts are the same."""
    at = first_run(path, **link)
    assert not at.exception and charts(at)
    sliders = lambda: {w.key: w.value for w in [*at.slider, *at.select_slider] if w.key}  # noqa: E731
    assert not held & set(sliders())
    first = {key: c["figure"] for key, c in charts(at).items()}
    rerun(at)
    assert not at.exception
    assert {key: float(sliders()[key]) for key in held} == {k: float(v) for k, v in link.items()}
    assert {key: c["figure"] for key, c in charts(at).items() if key in first} == first


def held_slider():
    import streamlit as st

    from ui.firstpaint import PAGE, SEEN, rerun_whole
    from ui.numbers import bound_select_slider, bound_slider

    st.session_state[PAGE] = "p"
    st.session_state.setdefault(SEEN, frozenset())
    if st.session_state.get("seed"):
        st.session_state.setdefault("omega", 12.5)
    omega = bound_slider("ω₂", -50.0, 50.0, step=0.5, key="omega", wait=True)
    res = bound_select_slider("res", [12, 72, 360], key="res", value=360, wait=True)
    st.session_state.setdefault("used", []).append((omega, res))
    rerun_whole()  # (no chart: a first run that held a slider runs again, whole)
    st.session_state[SEEN] = frozenset({"p"})


@pytest.mark.parametrize("seed, link, used", [(True, {}, (12.5, 360)),
                                              (True, {"omega": "3", "res": "72"}, (3.0, 72))])
def test_a_held_slider_reads_as_its_widget_and_a_run_without_a_chart_runs_again_whole(
        seed, link, used):
    at = AppTest.from_function(held_slider)
    at.session_state["seed"] = seed
    at.query_params.update(link)
    at.run()
    assert not at.exception
    # the first run held both (no widget) and, drawing no chart, ran again whole at once
    assert at.session_state["used"] == [used, used]
    assert at.slider(key="omega").value == used[0] and at.select_slider(key="res").value == used[1]


LOADS = re.compile(r"^(m|rho|F|Fa|M)\d+$")  # the kinetostatics page's load fields


@pytest.mark.parametrize("link", [{}, {"m3": "5,5"}])
def test_the_load_fields_wait_for_the_paint_unless_the_link_sets_one(link):
    """The default scene's loads are thirteen text boxes in a shut expander (issue 83): a
    fresh visit sends them with the whole run, and the chart drawn before them uses the
    values they then show. A field the link sets is read, and drawn, at once."""
    at = first_run("pages/kinetostatics.py", **link)
    assert not at.exception and charts(at)
    fields = lambda: {w.key: w.value for w in at.text_input if LOADS.match(w.key or "")}  # noqa: E731
    assert set(fields()) == set(link)
    first = {key: c["figure"] for key, c in charts(at).items()}
    rerun(at)
    assert not at.exception
    shown = fields()
    assert len(shown) >= 10  # every member's mass and radius of gyration, the forces
    if link:
        assert shown["m3"] == "5.5"  # the link's, said in the page's language (English)
    assert {key: c["figure"] for key, c in charts(at).items() if key in first} == first
