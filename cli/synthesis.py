"""``python -m solvers synthesize TASK.toml``: a four-bar whose coupler point passes the task's
points in order (docs/synthesis.md). What it prints is the re-solved mechanism: the objective,
each point's error and the positions come from the kinematics core's solve of the found
scene, never from the optimiser."""

from __future__ import annotations

import argparse
import json

import numpy as np

from mechanisms.synthesis import load_task
from solvers.synthesis import DEFAULT_BUDGET, DEFAULT_SECONDS, Result, synthesize

from . import arguments

MOST_BUDGET = 10_000_000
MOST_SECONDS = 600.0


def add(sub) -> None:
    p = sub.add_parser("synthesize", help="find a four-bar whose coupler point passes given "
                                          "points in order (path synthesis)")
    p.add_argument("task", metavar="TASK.toml", help="the points, timing and bounds "
                                                     "(docs/synthesis.md)")
    p.add_argument("--seed", type=arguments.number(integer=True), default=1, help="the same seed gives the same four-bar")
    p.add_argument("--budget", type=arguments.number(100, MOST_BUDGET, integer=True), default=DEFAULT_BUDGET,
                   help=f"evaluations the search may spend (100 … {MOST_BUDGET:,}; more: slower, "
                        f"closer)")
    p.add_argument("--seconds", type=arguments.number(0.1, MOST_SECONDS), default=DEFAULT_SECONDS,
                   help="wall-clock seconds the search may spend, whatever the budget")
    p.add_argument("--json", action="store_true", help="print JSON (the task's units)")
    p.set_defaults(run=_synthesize)


def _synthesize(args: argparse.Namespace) -> int:
    task = load_task(args.task)
    result = synthesize(task, seed=args.seed, budget=args.budget, seconds=args.seconds)
    if args.json:
        print(json.dumps(as_json(result), indent=1, ensure_ascii=False))
        return 0
    print(table(result))
    return 0


def _xy(z: complex) -> list[float]:
    return [float(np.real(z)), float(np.imag(z))]


def as_json(result: Result) -> dict:
    """The answer as the command line's JSON prints it (docs/cli.md, "synthesize")."""
    link = result.linkage
    return {
        "objective": result.objective,
        "max_error": float(np.max(result.errors)),
        "evaluations": result.evaluations,
        "seconds": round(result.seconds, 3),
        "mechanism": {"O": _xy(link.O), "D": _xy(link.D), "crank": link.crank,
                      "coupler": link.coupler, "rocker": link.rocker,
                      "frame": link.frame, "coupler_point": _xy(link.point),
                      "turning": "counter-clockwise" if link.turning > 0 else "clockwise"},
        "positions": [{"crank_angle_deg": float(result.crank_deg[i]),
                       "A": _xy(result.positions["A"][i]), "B": _xy(result.positions["B"][i]),
                       "M": _xy(result.positions["M"][i]), "error": float(result.errors[i])}
                      for i in range(len(result.errors))],
        "scene": result.scene_toml,
    }


def table(result: Result) -> str:
    """The answer for a person: the links, then each point's position and error (units: the
    task's)."""
    link = result.linkage
    lines = [f"four-bar found in {result.seconds:.1f} s ({result.evaluations:,} evaluations), "
             f"re-solved by the solver:",
             f"  O = ({link.O.real:.6g}, {link.O.imag:.6g})   D = ({link.D.real:.6g}, "
             f"{link.D.imag:.6g})   frame OD = {link.frame:.6g}",
             f"  crank OA = {link.crank:.6g}   coupler AB = {link.coupler:.6g}   "
             f"rocker DB = {link.rocker:.6g}",
             f"  coupler point M = [{link.point.real:.6g} along AB, {link.point.imag:.6g} to its left]",
             "",
             f"{'point':>5s} {'φ₂ °':>9s} {'M x':>11s} {'M y':>11s} {'error':>11s}"]
    m = result.positions["M"]
    for i, err in enumerate(result.errors):
        lines.append(f"{i + 1:5d} {result.crank_deg[i]:9.3f} {m[i].real:11.6g} {m[i].imag:11.6g} "
                     f"{err:11.3g}")
    lines += ["", f"Σ squared errors = {result.objective:.6g} (units²), largest error "
                  f"{np.max(result.errors):.3g} (task's units)",
              "open it: save the scene (--json, key \"scene\") as a .toml file, or "
              "python -m solvers link FILE.toml"]
    return "\n".join(lines)
