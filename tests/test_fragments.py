"""Moving φ₂ on the kinetostatics, plans or Assur page, ω₂ or a length on the trajectories
page, the drawing precision on the rotor page, a drawing scale on the gear page or φ₂ (or
a cell) in the builder reruns only what depends on it (a fragment; φ₂ in the builder: not
its tables): against a real server, through Streamlit's WebSocket as a browser speaks it
(deploy/client.py). The answers after a fragment's run are this φ₂'s; any other control
reruns the whole page. A fragment's run that a first chart's paint started runs the whole
page instead (what the first run left out may sit outside the fragment)."""

from __future__ import annotations

import asyncio

import pytest
import websockets
from streamlit.testing.v1 import AppTest

from deploy.client import Report, Session, free_port, start_server, wait_ready
from deploy.loadtest import check
from ui.firstpaint import PAINTED

LOADS = {"omega", "m2", "rho2", "steps"}  # some of the kinetostatics page's controls above


@pytest.fixture(scope="module")
def stream():
    port = free_port()
    server = start_server(port)
    url = f"ws://127.0.0.1:{port}/_stcore/stream"
    try:
        asyncio.run(wait_ready(url))
        yield url
    finally:
        server.terminate()
        server.wait(timeout=10)


async def _moves(url: str, page: str, link: str, moves: list[tuple[str, float]]) -> list[dict]:
    """Open the page, run it whole once more (as its paint does), then make each move; what
    each move's run was."""
    report = Report()
    session = Session(url, page, link, report)
    runs = []
    async with websockets.connect(url, subprotocols=["streamlit"], max_size=None) as ws:
        await session.run(ws)
        await session.run(ws)
        for key, value in moves:
            await session.run(ws, [(session.widgets[key][0], value)])
            runs.append({"whole": session.whole, "drawn": set(session.drawn),
                         "kinds": session.kinds, "charts": session.charts,
                         "script": session.script_bytes, "written": session.written,
                         "figures": session.figure_bytes, "metrics": dict(session.metrics)})
            if page == "kinetostatics" and key == "at":
                check(session, value, report)
    assert not report.errors and not report.wrong, report.errors + report.wrong
    return runs


def test_phi2_on_the_kinetostatics_page_reruns_the_instant_alone_with_its_answers(stream):
    runs = asyncio.run(_moves(stream, "kinetostatics", "scene=predavanja-kinetostatika",
                              [("at", 40.0), ("at", 217.5), ("omega", 12.0), ("at", 90.0)]))
    first, second, speed, after = runs
    for run in (first, second, after):  # (the torque checked against the solver above)
        assert not run["whole"]
        assert "at" in run["drawn"] and not run["drawn"] & LOADS
        assert "M_p group by group [N·m]" in run["metrics"]
    assert speed["whole"] and LOADS | {"at"} <= speed["drawn"]
    assert first["metrics"] != second["metrics"]


def test_the_drawing_precision_on_the_rotor_page_reruns_its_section_alone(stream):
    runs = asyncio.run(_moves(stream, "rotor_balancing", "scene=zbirka-7.1",
                              [("precision", 1.5), ("omega", 200.0), ("precision", 0.3)]))
    moved, speed, again = runs
    for run in (moved, again):
        assert not run["whole"] and run["drawn"] == {"precision"}
        assert run["figures"] == 0  # the polygons are not sent again
    assert speed["whole"] and {"precision", "omega", "xI"} <= speed["drawn"]
    assert speed["figures"] > 0


def test_phi2_on_the_plans_page_reruns_the_plans_alone(stream):
    runs = asyncio.run(_moves(stream, "velocity_plans", "scene=zbirka-2.1",
                              [("at", 40.0), ("at", 95.0), ("omega", 12.0), ("at", 120.0)]))
    first, second, speed, after = runs
    controls = {"omega", "UL", "Uv", "Ua", "prec"}
    for run in (first, second, after):
        assert not run["whole"]
        assert {"at", "step"} <= run["drawn"] and not run["drawn"] & controls
        assert run["figures"] > 0  # the plans at this φ₂
        # the charts' script is a static file (ui/plot.py): each chart names it, 20 kB once
        assert run["charts"] == 3 and run["script"] < 3 * 300
        assert run["written"] == 0  # the scene, tables and plans downloads wait for a click
    assert speed["whole"] and controls | {"at", "step"} <= speed["drawn"]


def test_phi2_on_the_assur_page_reruns_the_drawing_alone_not_the_structure(stream):
    runs = asyncio.run(_moves(stream, "assur_groups", "scene=zbirka-2.3",  # two groups
                              [("at", 40.0), ("at", 95.0), ("upto", 1.0), ("at", 120.0)]))
    first, second, upto, after = runs
    for run in (first, second, after):
        assert not run["whole"] and "at" in run["drawn"] and "upto" not in run["drawn"]
        assert run["figures"] > 0
        assert "degrees of freedom W" not in run["metrics"]  # the counts are not sent again
    assert upto["whole"] and {"at", "upto"} <= upto["drawn"]
    assert "degrees of freedom W" in upto["metrics"]


def test_a_drawing_scale_on_the_gear_page_reruns_the_scales_and_diagram_alone(stream):
    runs = asyncio.run(_moves(stream, "planetary_gears", "scene=zbirka-6.8",
                              [("H", 3.0), ("UL", 0.02), ("in5", 50.0), ("H", 2.5)]))
    pole, scale, given, again = runs
    for run in (pole, scale, again):
        assert not run["whole"] and run["drawn"] == {"UL", "Uv", "H"}
        assert run["figures"] == 0  # the schematic (the open tab) is not sent again
    assert given["whole"] and {"UL", "Uv", "H", "in5"} <= given["drawn"]


def test_omega_and_a_length_on_the_trajectories_page_rerun_the_drawing_alone(stream):
    runs = asyncio.run(_moves(stream, "trajectories", "scene=zbirka-1.1",
                              [("omega", 12.0), ("L2", 0.05), ("omega", -8.0)]))
    for run in runs:
        assert not run["whole"] and {"omega", "L2"} <= run["drawn"]
        assert all(key == "omega" or key.startswith("L") for key in run["drawn"])
        assert run["figures"] > 0


def test_phi2_typed_in_the_builder_reruns_the_drawing_not_the_tables_or_start_controls(stream):
    runs = asyncio.run(_moves(stream, "builder", "",
                              [("build_1_driver_at", 40.0), ("build_1_driver_at", 95.0)]))
    for run in runs:
        assert not run["whole"] and "build_1_driver_at" in run["drawn"]
        assert "build_start" not in run["drawn"]  # the template and preset picker
        assert "dataframe" not in run["kinds"]  # the tables' editor, which φ₂ does not change
        assert run["figures"] > 0  # the drawing at the new φ₂


def _counting_page():
    import streamlit as st

    from ui.fragments import fragment

    st.session_state["page_runs"] = st.session_state.get("page_runs", 0) + 1

    @fragment
    def part():
        st.session_state["part_runs"] = st.session_state.get("part_runs", 0) + 1
        st.write("part")

    part()


@pytest.mark.parametrize("painted, page_runs", [(False, 1), (True, 2)])
def test_a_fragment_run_started_by_a_paint_becomes_the_pages_run(painted, page_runs):
    at = AppTest.from_function(_counting_page)
    if painted:
        at.session_state[PAINTED] = True  # (ui.firstpaint.painted, the chart's trigger)
    at.run()
    assert not at.exception
    assert at.session_state["page_runs"] == page_runs and at.session_state["part_runs"] == 1
    assert PAINTED not in at.session_state
