"""The six chapters of the course: one page each. Shared by the router and the home page."""

from __future__ import annotations

from dataclasses import dataclass

import streamlit as st


@dataclass(frozen=True)
class Chapter:
    file: str
    title: str
    icon: str
    summary: str
    ready: bool = False


CHAPTERS = (
    Chapter("pages/trajectories.py", "1 · Trajectories", ":material/timeline:",
            "Paths of the points of a linkage over a full turn of the crank, as the book's "
            "twelve-step compass construction and as smooth curves. The hay-tedder tine adds "
            "the machine's forward travel to the linkage motion.", ready=True),
    Chapter("pages/velocity_plans.py", "2–3 · Velocity and acceleration plans", ":material/straighten:",
            "The graphical plans drawn from the exact solution, with poles, scales and the "
            "relative, normal, tangential and Coriolis components. Beside them, the same "
            "instant by the complex-number (vector-loop) method."),
    Chapter("pages/assur_groups.py", "4 · Assur groups", ":material/account_tree:",
            "Degrees of freedom and the decomposition of a mechanism into the driver and its "
            "Assur groups. Class III groups are solved with their special points."),
    Chapter("pages/kinetostatics.py", "5 · Kinetostatics", ":material/balance:",
            "Joint reactions F_pq, inertia forces, driving torque and power over the cycle. "
            "Cross-checked by the reduced mechanism (Zhukovsky's lever)."),
    Chapter("pages/planetary_gears.py", "6 · Planetary gear trains", ":material/settings:",
            "The Willis equation for any planetary or differential train, with the "
            "velocity diagram and the ratios. Members at rest and under-determined trains "
            "are explained, not guessed."),
    Chapter("pages/rotor_balancing.py", "7 · Rotor balancing", ":material/autorenew:",
            "Static and two-plane dynamic balancing with the force (U) and moment (V) "
            "polygons. Any unknown pair of mass, radius and angle per plane."),
)


def coming_soon(file: str) -> None:
    """The placeholder of a chapter page whose issue is not done yet."""
    chapter = next(c for c in CHAPTERS if c.file == file)
    st.title(f"{chapter.icon} {chapter.title}")
    st.write(chapter.summary)
    st.info("Coming soon: this chapter's page is being built. The shared solver it will use "
            "already works from the command line: `python -m solvers --help`.")
