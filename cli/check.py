"""``python -m solvers check SCENE_OR_CODE NAME VALUE``: the exam self-check, scriptable — a
value typed as a person types it, judged by the one judge (methods.judge) against the exact
value of a task (a preset id) or of a variant (its code from the sheet), with the tolerance
and the usual mistake that practice, the pages' self-check box and the Moodle bank give it."""

from __future__ import annotations

import json

from exams.judged import judged_steps, table
from exams.variants import VariantError, from_code
from mechanisms import SceneError, load_preset, preset_ids
from mechanisms.typed import Refused, parse
from methods.judge import judge
from methods.practice import printed_tolerance

from .practice import hint


def add(sub) -> None:
    p = sub.add_parser("check", help="judge a typed value of a task or a variant (the exam "
                                     "self-check): exact, tolerance, diagnosis, hint")
    p.add_argument("scene", metavar="SCENE_OR_CODE", help="a preset id or a variant code (3.1-S42-07K)")
    p.add_argument("name", help="the value's name as in `variants --json` (points.E.v, members.3.omega)")
    p.add_argument("value", help="the value as typed (0,35 or 0.35 with --language sr)")
    p.add_argument("--language", choices=("sr", "en"), default="en",
                   help="how the value is written (sr: a decimal comma too) and the hint's language")
    p.add_argument("--json", action="store_true")
    p.set_defaults(run=_check)


def _named(text: str) -> dict:
    """A task's (a preset id's) or a variant's judged values by name (exams.judged)."""
    if text in preset_ids():
        return {a.key: (a, step) for a, step in table(load_preset(text))}
    try:
        variant = from_code(text)  # a mistyped code: said in words, exit code 2
    except VariantError as exc:
        raise SceneError(exc.args[0]) from None
    return {a.key: (a, step) for a, step in judged_steps(variant.scene, variant.key)}


def _check(args) -> int:
    named = _named(args.scene)
    if args.name not in named:
        raise SceneError(f"check: {args.scene} has no value named {args.name!r}; it has "
                         f"{', '.join(sorted(named))}")
    try:
        typed = parse(args.value, args.language)
    except Refused as why:
        raise SceneError(f"check: {args.value!r} is not one number ({why.reason.replace('_', ' ')}"
                         f"{'; write a point, or --language sr' if why.reason == 'comma' else ''})") from None
    answer, step = named[args.name]
    verdict = judge(step, typed)
    out = {"name": answer.key, "exact": answer.value, "unit": answer.unit,
           "tolerance": step.tolerance, "diagnosis": verdict.diagnosis,
           "hint": hint(step, verdict, args.language)}
    if args.json:
        print(json.dumps(out, ensure_ascii=False))
    else:
        print(f"{out['name']}: {out['diagnosis']} — {out['hint']} (exact {answer.value:.6g} "
              f"± {printed_tolerance(step.tolerance):.3g} {answer.unit})".rstrip())
    return 0
