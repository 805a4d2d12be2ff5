"""``python -m solvers check SCENE_OR_CODE NAME VALUE``: the exam self-check, scriptable — a
value typed as a person types it, judged by the one judge (methods.judge) against the exact
value of a task (a preset id) or of a variant (its code from the sheet), with the tolerance
and the usual mistake that practice, the pages' self-check box and the Moodle bank give it."""

from __future__ import annotations

import json

from exams.moodle import left_out
from exams.variants import VariantError, answers, from_code, symbol
from mechanisms import SceneError, load_preset, preset_ids
from mechanisms.typed import Refused, parse
from methods.judge import judge, value_step

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


def _named(text: str) -> tuple[object, dict]:
    """The scene and its values by name: a variant's key, or a preset's own."""
    if text in preset_ids():
        scene = load_preset(text)
        return scene, {a.key: a for a in answers(scene, scene)}
    try:
        variant = from_code(text)  # a mistyped code: said in words, exit code 2
    except VariantError as exc:
        raise SceneError(exc.args[0]) from None
    return variant.scene, {a.key: a for a in variant.key}


def _check(args) -> int:
    scene, named = _named(args.scene)
    if args.name not in named:
        raise SceneError(f"check: {args.scene} has no value named {args.name!r}; it has "
                         f"{', '.join(sorted(named))}")
    try:
        typed = parse(args.value, args.language)
    except Refused as why:
        raise SceneError(f"check: {args.value!r} is not one number ({why.reason.replace('_', ' ')}"
                         f"{'; write a point, or --language sr' if why.reason == 'comma' else ''})") from None
    answer = named[args.name]
    step = value_step(answer.key, answer.value, answer.unit, answer.tolerance,
                      left_out(scene).get(answer.key, ()), symbol(answer.key))
    verdict = judge(step, typed)
    out = {"name": answer.key, "exact": answer.value, "unit": answer.unit,
           "tolerance": step.tolerance, "diagnosis": verdict.diagnosis,
           "hint": hint(step, verdict, args.language)}
    if args.json:
        print(json.dumps(out, ensure_ascii=False))
    else:
        print(f"{out['name']}: {out['diagnosis']} — {out['hint']} (exact {answer.value:.6g} "
              f"± {step.tolerance:.3g} {answer.unit})".rstrip())
    return 0
