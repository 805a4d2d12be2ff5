"""A page's figure as a still SVG (figures/svg.py), as a Moodle question carries it: lines
split where the trace has a gap, arrowheads at the heads, indices as subscripts, Plotly's
typed arrays read, one scale on both axes; the rotor's and the gear train's questions show
their masses, planes and members."""

from __future__ import annotations

import base64
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from exams.codes import Settings
from exams.moodle import moodle_xml
from exams.variants import generate
from figures.arrows import arrow_traces
from figures.linkage import scatter
from figures.raw import RawFigure
from figures.svg import figure_svg
from ui.i18n import table

SVG = "{http://www.w3.org/2000/svg}"


def drawn(fig: RawFigure, **options) -> ET.Element:
    return ET.fromstring(figure_svg(fig, **options))


def points(polyline: ET.Element) -> list[tuple[float, float]]:
    return [tuple(map(float, p.split(","))) for p in polyline.get("points").split()]


def test_a_gap_splits_a_line_and_one_scale_keeps_a_circle_round():
    fig = RawFigure()
    ring = np.exp(1j * np.linspace(0, 2 * np.pi, 120))  # sent as a typed array (over 64)
    fig.add_raw([scatter(x=ring.real, y=ring.imag, mode="lines"),
                 scatter(x=[0, 1, None, 2, 3], y=[0, 0, None, 1, 1], mode="lines")])
    svg = drawn(fig, width=10.0)
    circle, first, second = svg.findall(f"{SVG}polyline")
    round_ = points(circle)
    assert len(round_) == 120
    xs, ys = [p[0] for p in round_], [p[1] for p in round_]
    assert math.isclose(max(xs) - min(xs), max(ys) - min(ys), rel_tol=1e-3)  # not an ellipse
    assert len(points(first)) == len(points(second)) == 2
    assert points(second)[0][1] < points(first)[0][1]  # y up, as on the page


def test_an_arrowhead_sits_on_its_head_and_points_away_from_its_tail():
    fig = RawFigure()
    fig.add_raw(arrow_traces([(0j, 3 + 0j, "red"), (0j, 2j, "red")], 2.0))
    svg = drawn(fig, width=8.0)
    lines, heads = svg.findall(f"{SVG}polyline"), svg.findall(f"{SVG}polygon")
    assert len(lines) == len(heads) == 2
    for line, head in zip(lines, heads):
        (tx, ty), (hx, hy) = points(line)
        tip, *back = [complex(*map(float, p.split(","))) for p in head.get("points").split()]
        assert abs(tip - complex(hx, hy)) < 1e-3  # on the arrow's head
        along, shaft = tip - sum(back) / 2, complex(hx - tx, hy - ty)
        assert abs(along / abs(along) - shaft / abs(shaft)) < 0.01  # on from the tail (3 decimals)


def test_indices_are_subscripts_and_text_is_escaped():
    fig = RawFigure()
    fig.add_raw([scatter(x=[0, 1], y=[0, 1], mode="text", text=["F<sub>45</sub>", "a < b"])])
    svg = figure_svg(fig)
    assert 'baseline-shift="sub">45</tspan>' in svg and "a &lt; b" in svg
    ET.fromstring(svg)  # well-formed


@pytest.mark.parametrize("task, names", [("zbirka-7.1", ["m1", "m2", "m3", "I", "II"]),
                                          ("zbirka-6.1", [str(n) for n in range(2, 14)])])
def test_the_rotors_and_the_trains_questions_show_what_is_given(task, names):
    found = generate(Settings(task, 7), 2)
    xml = ET.fromstring(moodle_xml(found, task, "sr", table("sr").__getitem__))
    for question in xml.findall("question[@type='cloze']"):
        text = " ".join("".join(ET.fromstring(base64.b64decode(f.text)).itertext())
                        for f in question.findall("questiontext/file"))
        for name in names:
            assert name in text.split() or f"ravan {name}" in text, name
