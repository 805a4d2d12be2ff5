"""Command line: ``python -m solvers list | solve | plan | structure | forces | practice | link |
variants | class | check | lti | synthesize | bench``
(see docs/cli.md).

Exit codes: 0 done; 2 the scene or the command is wrong; 3 the mechanism cannot be in
the asked position (the message says why and where it can be).
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import re
import sys
from pathlib import Path

from classes.store import ClassError, NotSaved, StoreDown
from exams import variants
from exams.codes import DEFAULT_SPREAD, Settings
from exams.moodle import moodle_xml
from exams.sheets import sheets_html
from exams.variants import MAX_COUNT
from mechanisms import Scene, SceneError, load_any, load_preset, preset_ids
from mechanisms.gears import GearTrain
from mechanisms.link import PARAMETER, decode, encode
from mechanisms.messages import strings
from mechanisms.rotor import Rotor
from methods import practice_steps
from methods.plans import build
from methods.practice import printed_tolerance
from reports.values import forces_json, gears_json, motion_json, plan_json, rotor_json
from solvers.balancing import BalanceError, balance
from solvers.diagnostics import Unsolvable, explain_singular, solve_instant
from solvers.gears import TrainError, solve_train
from solvers.kinetostatics import analyse
from solvers.structure import StructureError, decompose

from solvers.synthesis import SynthesisError

from . import arguments, check, classes, lti, practice, synthesis


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        code = args.run(args)
        sys.stdout.flush()  # (a closed pipe shows here, not at the interpreter's exit)
        return code
    except argparse.ArgumentTypeError as exc:  # (a value checked against the scene: --at)
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # `… | head` closed the pipe: what was wanted was read; quietly
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except (SceneError, StructureError, TrainError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except StoreDown as exc:  # (a ClassError, but the store's fault, not the input's)
        print(f"error: {exc.args[0]}", file=sys.stderr)
        return 3
    except ClassError as exc:
        print(f"error: {exc.args[0]}", file=sys.stderr)
        return 2
    except (Unsolvable, BalanceError, NotSaved, SynthesisError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 3


class Parser(argparse.ArgumentParser):
    """argparse, with a value typed as a person types it taken for a value even when it is
    negative: argparse takes "-4.5" for a number but "-4,51716" (a decimal comma) and
    "-1e0" for options, and stopped with a usage error. None of our options looks like a
    number, so nothing is lost. Sub-commands get this class too (``add_subparsers``)."""

    NEGATIVE = re.compile(r"^-(\d+([.,]\d*)?|[.,]\d+)([eE][-+]?\d+)?$")

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = self.NEGATIVE

    def error(self, message: str):
        """A refusal of the command line itself in one line and exit 2, as every other
        refusal is (argparse printed a usage block of 3–6 lines first; it is one --help
        away)."""
        self.exit(2, f"error: {message} ({self.prog} --help)\n")


def _parser() -> argparse.ArgumentParser:
    parser = Parser(prog="python -m solvers",
                    description="Mehanizmi solvers from the command line.")
    sub = parser.add_subparsers(dest="command", required=True)
    p = sub.add_parser("list", help="list the presets with their titles")
    p.set_defaults(run=_list)
    p = sub.add_parser("solve", help="positions, velocities and accelerations at one instant")
    _scene_arguments(p)
    p.add_argument("--at", type=arguments.POSITION, help="driver coordinate: φ₂ in degrees for a rotating "
                                             "driver, s in metres for a linear one")
    p.add_argument("--json", action="store_true", help="print JSON (SI units)")
    p.add_argument("--stages", action="store_true", help="a gear train: also each carrier's "
                                                       "stage (speeds relative to it, Willis ratio)")
    p.set_defaults(run=_solve)
    p = sub.add_parser("plan", help="the velocity and acceleration plans at one instant")
    _scene_arguments(p)
    p.add_argument("--at", type=arguments.POSITION, help="φ₂ in degrees, or s in metres for a linear driver")
    p.add_argument("--json", action="store_true", help="print JSON (SI units)")
    p.set_defaults(run=_plan)
    p = sub.add_parser("structure", help="degrees of freedom and Assur groups")
    _scene_arguments(p)
    p.add_argument("--json", action="store_true")
    p.set_defaults(run=_structure)
    p = sub.add_parser("forces", help="joint reactions and the driving torque at one instant")
    _scene_arguments(p)
    p.add_argument("--at", type=arguments.POSITION, help="φ₂ in degrees, or s in metres for a linear driver")
    p.add_argument("--no-inertia", action="store_true",
                   help="leave the inertia forces out (as tasks 5.1–5.2 do)")
    p.add_argument("--json", action="store_true", help="print JSON (SI units)")
    p.set_defaults(run=_forces)
    p = sub.add_parser("practice", help="a construction's steps to practise, or a student's "
                                        "answers graded step by step (docs/practice.md)")
    _scene_arguments(p)
    p.add_argument("--method", required=True, choices=list(practice_steps.KINDS),
                   help="compass, plans, forces, lever (linkages), willis (gear trains), "
                        "balance (rotors), three (a four-bar's three-position construction)")
    p.add_argument("--at", type=arguments.POSITION, help="φ₂ in degrees, or s in metres for a linear driver "
                                            "(plans, forces, lever)")
    p.add_argument("--answers", metavar="FILE", type=arguments.input_file(practice.ANSWERS_MAX), help='a JSON file {"answers": {"<step id>": '
                                                      '[x, y] or a number}} to grade')
    p.add_argument("--class", dest="class_code", metavar="CODE",
                   help="store each graded answer as a check of this class (with --student)")
    p.add_argument("--student", metavar="ID", help="the student's id from `class join`")
    p.add_argument("--json", action="store_true", help="print JSON (SI units)")
    p.set_defaults(run=_practice)
    classes.add(sub)
    check.add(sub)
    lti.add(sub)
    synthesis.add(sub)
    p = sub.add_parser("link", help=f"the share parameter ({PARAMETER}=…) that carries a scene "
                                    "in any page's link")
    p.add_argument("scene", help="a preset id (see `list`) or a path to a .toml scene")
    p.set_defaults(run=_link)
    p = sub.add_parser("variants", help="exam and homework variants of a task, with answer keys")
    p.add_argument("scene", help="the task's preset id (one with printed answers, e.g. zbirka-3.1)")
    p.add_argument("--count", type=arguments.number(1, MAX_COUNT, integer=True), default=30, help=f"how many (1 … {MAX_COUNT})")
    p.add_argument("--seed", type=arguments.number(integer=True), default=1, help="the same seed gives the same variants")
    p.add_argument("--spread", type=arguments.number(integer=True), default=DEFAULT_SPREAD,
                   help="± %% around the book's values (angles: ± spread/2 degrees)")
    p.add_argument("--hold", action="append", default=[], metavar="GIVEN",
                   help="keep a given at the book's value: its label (AB) or number (1, 2, …)")
    p.add_argument("--json", action="store_true", help="print JSON (the same bytes for the same arguments)")
    p.add_argument("--sheets", metavar="FILE.html", type=arguments.output_file, help="write the students' sheets and the key (A4)")
    p.add_argument("--key", metavar="FILE.csv", type=arguments.output_file, help="write the answer key as CSV")
    p.add_argument("--moodle", metavar="FILE.xml", type=arguments.output_file,
                   help="write the set as a Moodle question bank (one cloze question a variant)")
    p.add_argument("--language", choices=("sr", "en"), default="sr",
                   help="of the sheets and the Moodle questions")
    p.set_defaults(run=_variants)
    p = sub.add_parser("bench", help="time the solver against a closed-form numpy baseline")
    p.add_argument("scene")
    p.add_argument("--steps", type=arguments.COUNT, default=3600, help="positions per cycle")
    p.add_argument("--repeat", type=arguments.COUNT, default=200, help="timed repetitions (median is shown)")
    p.set_defaults(run=_bench)
    return parser


def _variants(args) -> int:
    try:
        held = variants.held_indices(variants.task(args.scene).givens, args.hold)
        found = variants.generate(Settings(args.scene, args.seed, args.spread, held), args.count)
    except variants.VariantError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if found.shortfall:
        print(f"note: {found.shortfall}", file=sys.stderr)
    task = load_preset(args.scene)
    title = task.title_sr if args.language == "sr" and task.title_sr else task.title
    if args.sheets:
        Path(args.sheets).write_text(sheets_html(found, title, args.language), encoding="utf-8")
    if args.moodle:
        Path(args.moodle).write_text(moodle_xml(found, title, args.language,
                                                strings(args.language).__getitem__),
                                     encoding="utf-8")
    if args.key:
        with open(args.key, "w", newline="", encoding="utf-8") as f:
            writer = csv.DictWriter(f, ["code", "quantity", "value", "unit", "tolerance", "asked"])
            writer.writeheader()
            writer.writerows(variants.key_rows(found))
    if args.json:
        return _print_json(variants.as_json(found))
    for v in found.variants:
        given = ", ".join(f"{g.label} = {value:g} {g.unit}".rstrip() for g, value in v.given)
        print(f"{v.code}: {given}")
        for a in v.key:
            tol = "" if a.tolerance is None else f"  (± {printed_tolerance(a.tolerance):.3g})"
            extra = "" if a.asked else "  [self-check]"
            print(f"    {variants.symbol(a.key):16s} {a.value:12.6g} {a.unit}{tol}{extra}")
    return 0


def _scene_arguments(p: argparse.ArgumentParser) -> None:
    p.add_argument("scene", nargs="?", help="a preset id (see `list`) or a path to a .toml scene")
    p.add_argument("--link", metavar="TEXT", help=f"a page's link (a whole URL, or just its "
                                                  f"{PARAMETER}= value) in place of a scene")


def _load(args):
    """The scene named on the command line, or carried by ``--link``."""
    if (args.scene is None) == (args.link is None):
        raise SceneError("give a scene (a preset id or a .toml file) or --link TEXT, not both "
                         "and not neither")
    scene = decode(args.link) if args.link is not None else load_any(args.scene)
    if getattr(args, "at", None) is not None and isinstance(scene, Scene):
        args.at = arguments.at(scene, args.at)
    return scene


def _link(args) -> int:
    print(f"{PARAMETER}={encode(load_any(args.scene))}")
    return 0


def _practice(args) -> int:
    if bool(args.class_code) != bool(args.student) or (args.class_code and not args.answers):
        raise SceneError("--class and --student go together, with --answers")
    if args.class_code:  # a wrong code or student, or another task's answers: exit code 2
        given = None
        if args.scene is not None or args.link is not None:
            scene = _load(args)
            given = (scene, practice_steps.steps_for(scene, args.method, args.at))
        answers = practice.read_answers(args.answers)
        data = practice.graded(classes.student_steps(args.class_code, args.student,
                                                     args.method, given), answers)
        data["stored"] = classes.stored(data, args.class_code, args.student, answers)
    else:
        data = practice.run(_load(args), args.method, args.at, args.answers)
    if args.json:
        return _print_json(data)
    if "steps" in data:
        for step in data["steps"]:
            print(f"{step['id']:24s} {step['asks']}: {step['expected']} ± "
                  f"{printed_tolerance(step['tolerance']):.3g} "
                  f"{step['unit']}")
        return 0
    stored = data.get("stored", {})
    for result in data["results"]:
        kept = f" (stored as try {stored[result['id']]})" if result["id"] in stored else ""
        print(f"{result['id']:24s} {result['diagnosis']:12s} {result['hint']}{kept}")
    if "ok" in data["score"]:
        print(f"score: {data['score']['ok']} of {data['score']['of']}")
    else:  # a test not yet closed: no verdicts
        print(f"stored: {data['score']['done']} of {data['score']['of']} steps answered")
    return 0


def _list(args) -> int:
    for pid in preset_ids():
        scene = load_preset(pid)
        print(f"{pid:28s} {scene.title}")
    return 0


def _print_json(data: dict) -> int:
    print(json.dumps(data, indent=1, ensure_ascii=False))
    return 0


def _solve_rotor(rotor: Rotor, as_json: bool) -> int:
    try:
        result = balance(rotor)
    except BalanceError as exc:
        raise Unsolvable(str(exc)) from None
    for note in result.notes:
        print(f"note: {note}", file=sys.stderr)
    data = rotor_json(result)
    if as_json:
        return _print_json(data)
    print(f"{rotor.id} — {rotor.title}\n")
    print(f"{'plane':7s}{'mass kg':>12s}{'radius m':>12s}{'angle °':>10s}")
    for plane, c in data["corrections"].items():
        print(f"{plane:7s}{c['mass']:12.5g}{c['radius']:12.5g}{c['angle_deg']:10.2f}")
    print(f"\nresidual after correction: force {data['residual']['force']:.3g} kg·m, "
          f"moment {data['residual']['moment']:.3g} kg·m²")
    return 0


def _solve_gears(train: GearTrain, as_json: bool, with_stages: bool = False) -> int:
    solution = solve_train(train)
    if solution.status != "solved":
        raise Unsolvable(solution.message)
    if solution.message:
        print(f"note: {solution.message}", file=sys.stderr)
    data = gears_json(solution, with_stages)
    if as_json:
        return _print_json(data)
    print(f"{train.id} — {train.title}\n\ndegrees of freedom: {data['dof']}\n")
    print(f"{'member':8s}{'ω rad/s':>14s}")
    for m, w in data["members"].items():
        print(f"{m:8s}{w['omega']:14.6g}")
    print()
    for pair, ratio in data["ratios"].items():
        print(f"i {pair:8s} {'∞ (does not rotate)' if ratio == 'inf' else f'{ratio:.6g}'}")
    for name, v in data.get("points", {}).items():
        print(f"v_{name} = {v:.6g} m/s")
    for stage in data.get("stages", []):
        c = stage["carrier"]
        a, b = stage["ends"]
        seen = "fixed axes" if c is None else f"carrier {c}"
        minus = "" if c is None else f" − ω{c}"
        print(f"\nstage, {seen}: " + ", ".join(f"ω{m}{minus} = {w:.6g}"
                                                for m, w in stage["relative"].items()))
        speeds = ("0/0 from the speeds (both ends turn with the carrier)" if stage["solved"] is None
                  else f"{stage['solved']:.6g} from the speeds")
        print(f"  i{a},{b} = {stage['ratio']:.6g} from the radii, {speeds}"
              if stage["ratio"] is not None else f"  i{a},{b} = {speeds}")
    if "order" in data:
        print("\none unknown speed per equation, in the collection's order:")
        for step in data["order"]:
            where = "" if step["carrier"] is None else f", carrier {step['carrier']}"
            print(f"  ω{step['member']} = {step['omega']:.6g}  ({step['kind']}{where})")
    return 0


def _solve(args) -> int:
    scene = _load(args)
    if isinstance(scene, Rotor):
        return _solve_rotor(scene, args.json)
    if isinstance(scene, GearTrain):
        return _solve_gears(scene, args.json, args.stages)
    motion = solve_instant(scene, args.at)
    for issue in motion.issues:
        print(f"warning: {explain_singular(scene, motion.at[0], issue.group, issue.worst_condition)}",
              file=sys.stderr)
    data = motion_json(motion)
    if args.json:
        return _print_json(data)
    unit = "°" if scene.driver.kind == "rotating" else " m"
    print(f"{scene.id} — {scene.title}\nat {data['at']:.6g}{unit}\n")
    print(f"{'point':6s}{'x m':>11s}{'y m':>11s}{'vx m/s':>11s}{'vy m/s':>11s}"
          f"{'ax m/s²':>11s}{'ay m/s²':>11s}")
    for name, p in data["points"].items():
        print(f"{name:6s}" + "".join(f" {p[k]:10.5g}" for k in ("x", "y", "vx", "vy", "ax", "ay")))
    print(f"\n{'member':8s}{'angle °':>11s}{'ω rad/s':>11s}{'ε rad/s²':>11s}")
    for n, m in data["members"].items():
        print(f"{n:8s}{m['angle_deg']:11.3f} {m['omega']:10.5g} {m['epsilon']:10.5g}")
    if "travel" in data:
        tr = data["travel"]
        print(f"\ntravel: ω_t = {tr['wheel_omega']:.5g} s⁻¹, ω₂ = ω_b = {tr['crank_omega']:.5g} s⁻¹, "
              f"t_c = {tr['cycle_time']:.5g} s, t_c/12 = {tr['step_time']:.5g} s, "
              f"travel per step = {tr['step_distance']:.5g} m")
    if data["sliders"]:
        print(f"\n{'slider':10s}{'s m':>11s}{'v m/s':>11s}{'a m/s²':>11s}{'Coriolis m/s²':>24s}")
        for name, s in data["sliders"].items():
            cor = f"({s['coriolis'][0]:.5g}, {s['coriolis'][1]:.5g})"
            print(f"{name:10s} {s['s']:10.5g} {s['v']:10.5g} {s['a']:10.5g} {cor:>23s}")
    return 0


def _linkage(args) -> Scene:
    scene = _load(args)
    if not isinstance(scene, Scene):
        raise SceneError(f"{args.scene or 'the link'} is a {type(scene).__name__.lower()}, "
                         "not a linkage")
    return scene


def _plan(args) -> int:
    data = plan_json(build(solve_instant(_linkage(args), args.at)))
    if args.json:
        return _print_json(data)
    for quantity in ("velocity", "acceleration"):
        print(f"{quantity} plan (pole p; images in {'m/s' if quantity == 'velocity' else 'm/s²'})")
        for step in data[quantity]["steps"]:
            print(f"  {step['equation']}")
            for c in step["components"]:
                print(f"    {c['kind']:11s} {c['from']:>4s} → {c['to']:4s} "
                      f"({c['x']:.5g}, {c['y']:.5g})  |{c['symbol']}| = {c['magnitude']:.5g}")
    return 0


def _forces(args) -> int:
    scene = _linkage(args)
    data = forces_json(analyse(scene, motion=solve_instant(scene, args.at),
                               inertia=not args.no_inertia))
    if args.json:
        return _print_json(data)
    print(f"{scene.id} — {scene.title}\n")
    print(f"{'F_pq':8s}{'x N':>11s}{'y N':>11s}{'|F| N':>11s}{'angle °':>10s}")
    for key, r in data["reactions"].items():
        p, q = key.split("-")
        if int(p) < int(q):  # F_qp = −F_pq: one line per pair
            print(f"F_{p}{q:6s} {r['x']:10.5g} {r['y']:10.5g} {r['magnitude']:10.5g} "
                  f"{r['angle_deg']:9.2f}" + (f"  h = {r['offset']:.5g} m" if "offset" in r else ""))
    d = data["driving"]
    if d["torque"] is not None:
        print(f"\nM_p = {d['torque']:.6g} N·m (Zhukovsky {d['torque_zhukovsky']:.6g}, "
              f"power balance {d['torque_power_balance']:.6g}), F_p = M_p/AB = {d['force']:.6g} N")
    else:
        print(f"\nF_p = {d['force']:.6g} N (Zhukovsky {d['force_zhukovsky']:.6g}, "
              f"power balance {d['force_power_balance']:.6g})")
    print(f"P = {d['power']:.6g} W")
    return 0


def _structure(args) -> int:
    st = decompose(_linkage(args))
    data = {"dof": st.dof, "members": st.moving_members, "lower_pairs": st.lower_pairs,
            "higher_pairs": st.higher_pairs,
            "groups": [{"members": sorted(g.members), "class": g.cls, "kind": g.kind,
                        "order": g.order} for g in st.groups],
            "formula": st.formula}
    if args.json:
        return _print_json(data)
    print(f"n = {st.moving_members} moving members, p₅ = {st.lower_pairs}, "
          f"p₄ = {st.higher_pairs}, W = 3n − 2p₅ − p₄ = {st.dof}")
    print(f"structural formula: {st.formula}")
    for g in st.groups:
        print(f"  class {g.cls} group of members {sorted(g.members)}: {g.kind}, order {g.order}")
    return 0


def _bench(args) -> int:
    from .bench import run_bench

    print(run_bench(load_any(args.scene), args.steps, args.repeat))
    return 0
