"""Chapter 1's compass construction as steps: each joint found from its two arcs lands
where the solver puts it, and the page steps through it in every language."""

import numpy as np
import pytest

from mechanisms import load_preset, preset_ids
from mechanisms.schema import Scene
from methods.compass import construction
from solvers.kinematics import solve
from solvers.paths import cycle_values

from .test_pages import chart, page

DIGITS = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")


def twelve(pid: str):
    scene = load_preset(pid)
    return solve(scene, cycle_values(scene, 12))


def split(name: str) -> tuple[str, int]:
    letter = name.rstrip("₀₁₂₃₄₅₆₇₈₉")
    return letter, int(name[len(letter):].translate(DIGITS))


LINKAGES = [p for p in preset_ids() if isinstance(load_preset(p), Scene)]


@pytest.mark.parametrize("pid", LINKAGES)
def test_every_point_the_construction_finds_is_the_solutions(pid):
    """Every linkage preset (a slider driver, triads and points hung on offsets included:
    the page ended in the error sentence for 2.1, 2.4, 5.1 …)."""
    motion = twelve(pid)
    steps = construction(motion, ["B"] if "B" in motion.points else [])
    found = {name: z for step in steps for name, z in step.found.items()}
    moving = [n for n in motion.points if n not in motion.scene.frame]
    feasible = [k + 1 for k in range(12) if motion.feasible[k]]
    assert {(n, k) for n in moving for k in feasible} <= {split(n) for n in found}  # each, each time
    for name, z in found.items():
        letter, k = split(name)
        assert z == pytest.approx(complex(motion.points[letter].z[k - 1]), abs=1e-12)


def test_a_joint_is_the_crossing_of_two_arcs_of_its_link_lengths():
    motion = twelve("four-bar-crank-rocker")  # OA 0.1, AB 0.35, DB 0.3
    steps = construction(motion, ["E"])
    crank = steps[0]
    angles = np.degrees(np.angle([z - 0 for z in crank.found.values()]))
    assert np.allclose(np.diff(np.unwrap(np.radians(angles))), np.radians(30))  # 12 equal parts
    first_arcs = [s for s in steps[1:3]]
    assert [s.what for s in first_arcs] == ["arc", "arc"]
    assert [s.values["radius"] for s in first_arcs] == pytest.approx([0.35, 0.3])
    meet = steps[3]
    b1 = meet.found["B₁"]
    for centre, radius in meet.arcs:
        assert abs(b1 - centre) == pytest.approx(radius, abs=1e-12)
    assert steps[-1].what == "path" and len(steps[-1].found) == 12


@pytest.mark.parametrize("lang, first, last", [
    ("en", "Step 1 of 50: Divide the crank circle", "The path of E"),
    ("sr", "Korak 1 od 50: Krug krivaje", "Putanja tačke E"),
    ("sr-cyrl", "Корак 1 од 50", "E"),
])
def test_the_page_steps_through_the_construction(lang, first, last):
    at = page("pages/trajectories.py", lang=lang, scene="four-bar-crank-rocker", view="compass",
              points=["E"])
    assert not at.exception
    spec = chart(at, "paths")
    titles = [f["layout"]["title"]["text"] for f in spec["frames"]]
    assert len(titles) == 50 and titles[0].startswith(first) and last in titles[-1]
    middle = spec["frames"][14]
    assert "DB" in middle["layout"]["title"]["text"]  # step 15: the rocker's arc about D
    highlighted = middle["data"][1]
    xs = [x for x in highlighted["x"] if x is not None]
    ys = [y for y in highlighted["y"] if y is not None]
    d = load_preset("four-bar-crank-rocker").frame["D"]
    assert np.allclose(np.hypot(np.array(xs) - d.real, np.array(ys) - d.imag), 0.3)
    assert spec["layout"]["sliders"][0]["active"] == 49  # opens on the finished drawing
