"""The sheet a student practises on: what the construction has drawn so far (the exact earlier
steps, at the page's scale, in cm of paper), the current step's tail, and a circle to drag to
where the student puts the new arrow's tip (or the new point)."""

from __future__ import annotations

import math

from methods.practice import Step

from .arrows import arrow_traces
from .linkage import Text, scatter
from .plans import html
from .raw import RawFigure
from .style import NORMAL, Look, plane_layout

DONE = "#7f7f7f"
ANSWER = "#d62728"
TIP = 0.18  # the tip's circle: radius in cm of paper
REACH = 7.0  # cm of paper shown around the tail


def practice_figure(steps: list[Step], index: int, tip: complex | None, title: str, t: Text,
                    look: Look = NORMAL, revision: str = "") -> RawFigure:
    """Step ``index`` of ``steps`` on its sheet: the earlier steps of the same sheet drawn
    exactly (arrows, or points for a compass step; an image reached from the pole as its
    labelled point), a polygon's known sides before its closing side, the tail as a point,
    and a draggable circle named "tip" at ``tip`` (cm on the paper; the tail plus a small
    offset when None) with the student's arrow to it."""
    step = steps[index]
    fig = RawFigure()
    start = sheet(fig, steps, index, t, look)
    placed = tip is not None
    if tip is None:
        tip = start + (1.0 + 0.5j)
    if step.kind == "vector":
        fig.add_raw(arrow_traces([(start, tip, ANSWER)], 2.4 * look.line))
    shapes = [dict(type="circle", name="tip", xref="x", yref="y", x0=tip.real - TIP,
                   x1=tip.real + TIP, y0=tip.imag - TIP, y1=tip.imag + TIP,
                   line=dict(color=ANSWER, width=1.5 * look.line),
                   fillcolor="rgba(214, 39, 40, 0.15)")]
    plane_layout(fig, title, look, x_title="x [cm]", y_title="y [cm]")
    # no drag mode: a swipe scrolls the page, the tip is moved by its handle (ui/plot.js);
    # each step opens at its own view (a zoom of the last one would show an empty sheet);
    # meta.fine: the browser opens it (and comes back after each drag) zoomed until the
    # step's tolerance is a few screen pixels (ui/plot.js): a new step on a window that holds
    # its tail and its answer (``opening``), a placed tip around the tip
    centre, room = (tip, 0.0) if placed else opening(step, start)
    fig.merge_layout(dict(shapes=shapes, dragmode=False, uirevision=f"practice-{step.id}",
                          editrevision=revision,
                          meta=dict(fine=dict(tolerance=step.tolerance / (step.scale or 1.0),
                                              view=revision, centre=[centre.real, centre.imag],
                                              reach=room))))
    return fig


GRID = 0.5  # cm of paper: a new step's window is placed on this grid, its reach rounded up
ROUND = 0.25  # to this


def answer_at(step: Step) -> complex:
    """Where the step's answer is on its sheet (cm of paper): a point, or an arrow's tip."""
    scale = step.scale or 1.0
    return complex(step.expected) / scale if step.kind == "point" else \
        (step.tail + complex(step.expected)) / scale


def opening(step: Step, start: complex) -> tuple[complex, float]:
    """A new step's first window (its centre, and how far it must reach, cm of paper): the
    tail and the answer's region — the answer with its tolerance and the tip's circle —
    both in it. Its centre lies on a half-centimetre grid and its reach is rounded up to a
    quarter, so that the window tells the region of the answer, as the book's figure does,
    and not the answer itself."""
    answer = answer_at(step)
    centre = complex(round((start.real + answer.real) / 2 / GRID) * GRID,
                     round((start.imag + answer.imag) / 2 / GRID) * GRID)
    margin = step.tolerance / (step.scale or 1.0) + TIP
    need = max(abs(start - centre), abs(answer - centre)) + margin
    return centre, math.ceil(need / ROUND) * ROUND


def reach(step: Step, start: complex) -> float:
    """How far from ``start`` (cm of paper) the sheet must reach for the step's answer."""
    return abs(answer_at(step) - start) + step.tolerance / (step.scale or 1.0) + 2 * TIP


def sheet(fig: RawFigure, steps: list[Step], index: int, t: Text, look: Look = NORMAL) -> complex:
    """Draw on ``fig`` what step ``index``'s sheet holds before it (the earlier steps exactly,
    a polygon's known sides, the tail) and room around the tail: the tail, in cm of paper."""
    step = steps[index]
    scale = step.scale or 1.0
    earlier = [s for s in steps[:index] if s.sheet == step.sheet and s.kind != "scalar"]
    arrows = [(s.tail / scale, (s.tail + complex(s.expected)) / scale, DONE)
              for s in earlier if s.kind == "vector" and s.rule != "sum"]
    if step.rule == "closing":  # the polygon's known sides, head to tail, up to the tail
        end = 0j  # (the rotor's are earlier steps of the sheet, drawn already)
        for term in step.terms:
            side = (end / scale, (end - complex(term.value)) / scale, DONE)
            if side not in arrows:
                arrows.append(side)
            end -= complex(term.value)
    fig.add_raw(arrow_traces(arrows, 1.6 * look.line))
    points = [(complex(s.expected) / scale if s.kind == "point" else
               (s.tail + complex(s.expected)) / scale, s.symbol) for s in earlier
              if s.kind == "point" or s.rule == "sum"]
    start = step.tail / scale
    if step.kind == "vector":  # a point has no tail: only where it goes
        points.append((start, t("practice.tail")))
    fig.add_raw([scatter(x=[z.real for z, _ in points], y=[z.imag for z, _ in points],
                         mode="markers+text", text=[html(n) if n else "" for _, n in points],
                         textposition="top right", hoverinfo="skip", showlegend=False,
                         marker=dict(size=5 * look.line, color="black"))])
    # the sheet around the tail: room for any arrow a plan at a 12 cm scale can hold, or
    # for this step's answer where it reaches further
    room = max(REACH, reach(step, start))
    corners = [start + room * c for c in (1 + 1j, -1 - 1j)]
    fig.add_raw([scatter(x=[z.real for z in corners], y=[z.imag for z in corners], mode="markers",
                         hoverinfo="skip", showlegend=False, marker=dict(opacity=0))])
    return start
