"""``python -m solvers class create | join | export | delete | purge | migrate``: a class on the same
store as the pages (classes/store.py; MEHANIZMI_DATABASE_URL or the SQLite file), so that a
lecturer scripts a class and a student hands in answers from a file (``practice … --class
CODE --student ID``)."""

from __future__ import annotations

import json
import sys

from classes import store, summary
from classes.steps import steps_of
from figures.plans import plain
from classes.store import variant_of
from lti.grades import close_test
from mechanisms import Scene, SceneError, load_preset
from mechanisms.link import PARAMETER, decode
from mechanisms.messages import Text, strings
from methods.progress import Progress, score

from . import arguments


def add(sub) -> None:
    """The ``class`` command and its subcommands."""
    p = sub.add_parser("class", help="a lecturer's class on the store: create, join, export, "
                                     "delete, purge (docs/classes.md)")
    verbs = p.add_subparsers(dest="verb", required=True)
    v = verbs.add_parser("create", help="a new class: its join code and the lecturer's key")
    v.add_argument("scene", help="a preset id, or a builder link's s= text")
    v.add_argument("--method", required=True, choices=list(store.METHODS))
    v.add_argument("--at", type=arguments.POSITION, help="φ₂ in degrees, or s in metres")
    v.add_argument("--variants", metavar="SET", help="a variant set's code (3.1-S42): each "
                                                     "student who joins gets the next variant")
    v.add_argument("--test", action="store_true",
                   help="a test: one try a step, no hints or 'Show it'; the verdicts shown "
                        "to the students when you close it (class close)")
    v.add_argument("--json", action="store_true")
    v.set_defaults(run=_create)
    v = verbs.add_parser("join", help="join a class by its code: the student's id")
    v.add_argument("code")
    v.add_argument("--nickname", default="")
    v.add_argument("--json", action="store_true")
    v.set_defaults(run=_join)
    v = verbs.add_parser("export", help="every try of the class (its lecturer's key)")
    v.add_argument("code")
    v.add_argument("--key", required=True)
    v.add_argument("--format", choices=("csv", "jsonl"), default="jsonl")
    v.set_defaults(run=_export)
    v = verbs.add_parser("summary", help="per student, per step the outcome (right at the first "
                                         "try, after hints, shown, wrong, open) and the score "
                                         "a gradebook gets")
    v.add_argument("code")
    v.add_argument("--key", required=True)
    v.add_argument("--json", action="store_true")
    v.set_defaults(run=_summary)
    v = verbs.add_parser("close", help="close a test: its students see their verdicts")
    v.add_argument("code")
    v.add_argument("--key", required=True)
    v.set_defaults(run=_close)
    v = verbs.add_parser("delete", help="the class and all it stored, at once")
    v.add_argument("code")
    v.add_argument("--key", required=True)
    v.set_defaults(run=_delete)
    v = verbs.add_parser("purge", help="remove the expired classes")
    v.set_defaults(run=_purge)
    v = verbs.add_parser("migrate", help="make or upgrade the store's schema (the start "
                                         "commands run it)")
    v.set_defaults(run=_migrate)


def _create(args) -> int:
    scene = (decode(args.scene) if args.scene.startswith(f"{PARAMETER}=")
             else load_preset(args.scene))  # an unknown preset or a damaged link: SceneError, exit 2
    if isinstance(scene, Scene):
        args.at = arguments.at(scene, args.at)
    code, key = store.create(args.scene, args.method, args.at, args.variants, test=args.test)
    join = f"/class?join={code}"
    if args.json:
        print(json.dumps({"code": code, "key": key, "join": join}))
    else:
        print(f"code: {code}\nkey (keep it; shown once): {key}\njoin: {join}")
    return 0


def _join(args) -> int:
    token = store.join(args.code, args.nickname)
    print(json.dumps({"student": token}) if args.json else token)
    return 0


def _export(args) -> int:
    rows = store.export(args.code, args.key)
    sys.stdout.write(store.as_jsonl(rows) if args.format == "jsonl" else store.as_csv(rows))
    return 0


def _summary(args) -> int:
    found = store.opened(args.code, args.key)
    said = summary.of_class(found, store.export(args.code, args.key), store.roster(found))
    if args.json:
        sys.stdout.write(summary.as_json(said))
        return 0
    print(f"class {found.code}: {found.method} on {found.scene[:60]}"
          + (" (a test, closed)" if found.test and found.closed else " (a test, open)" if found.test else ""))
    for row in said["students"]:
        score = row["score"]
        print(f"{row['nickname']} ({row['student'][:8]}…): {score['right']} of {score['of']} right, "
              f"{score['done']} done — " + ", ".join(f"{step} {outcome}" for step, outcome in row["steps"].items()))
    return 0


def _close(args) -> int:
    found = close_test(args.code, args.key)  # (a Moodle activity's scores go now)
    if not found.test:
        print(f"{found.code} is not a test: its students see their verdicts already")
        return 0
    print(f"closed {found.code}: its students now see their verdicts")
    return 0


def _delete(args) -> int:
    store.delete(args.code, args.key)
    print(f"deleted {args.code.upper()}")
    return 0


def _purge(args) -> int:
    print(f"purged {store.purge()} expired classes")
    return 0


def _migrate(args) -> int:
    print(f"class store ready: {store.engine().url.render_as_string(hide_password=True)}")
    return 0


def stored(data: dict, code: str, token: str, answers: dict) -> dict[str, int]:
    """A graded answers file's checks, stored as the student's: each answered step one
    more try, numbered by the store (a second hand-in is the steps' next tries, never
    dropped). Step id → the try it was stored as. Then each result says what the class's
    fold made of it: a try of a step settled before (on a page, by an earlier hand-in)
    counts for nothing and is said so, and in a test not yet closed no verdict is given.
    In a test a step already tried is refused whole, before anything is stored (OneTry); a
    closed test takes no hand-in at all (TestClosed, exit 2: nothing stored)."""
    found = store.find(code)
    answered = [r["id"] for r in data["results"] if r["id"] in answers]
    if found.test and found.closed is not None:
        raise store.TestClosed(Text("class.test_closed_try", at=store.closed_at(found)))
    if found.test:
        again = sorted({r["step"] for r in store.tries(code, token)} & set(answered))
        if again:  # (named as the pages name them, with the answers file's id beside)
            named = {s.id: plain(s.symbol) for s in steps_of(found, store.student(code, token)["variant"])}
            raise store.OneTry(Text("class.one_try", step=", ".join(f"{named.get(i, i)} ({i})"
                                                                     for i in again)))
    out, checks = {}, {}
    for result in data["results"]:
        if result["id"] in answers:
            checks[result["id"]] = store.new_check()
            out[result["id"]] = store.record(code, token, result["id"], answers[result["id"]],
                                             result["diagnosis"], checks[result["id"]],
                                             term=result["term"])
    folded = Progress.of(summary.tried(store.tries(code, token)), found.rules)
    for result in data["results"]:
        result["outcome"] = folded.outcome(result["id"])
        if not found.verdicts_shown:
            result.update(diagnosis="stored" if result["id"] in checks else "none", term="",
                          hint=strings("en")["practice.test_stored"] if result["id"] in checks else "")
        elif result["id"] in checks and folded.late(checks[result["id"]]):
            words = strings("en")
            result["hint"] = words["practice.settled"].format(outcome=words[f"practice.{result['outcome']}"])
    said = score(folded.records, [r["id"] for r in data["results"]])
    data["score"] = ({"ok": said["right"], "of": said["of"]} if found.verdicts_shown
                     else {"done": said["of"] - said["open"], "of": said["of"]})
    return out


def student_steps(code: str, token: str, method: str, given: tuple | None) -> list:
    """The steps this student practises in the class (the class's scene, or their variant),
    which their answers are graded on. ``given``: (scene, steps) named on the command line,
    refused (SceneError, exit 2) unless they are those steps — another scene, method, instant
    or variant would store grades of another task."""
    found = store.find(code)
    variant = store.student(code, token)["variant"]
    own = steps_of(found, variant)
    if method != found.method or (given is not None and _signature(given[1]) != _signature(own)):
        named = f"{method} on {given[0].id}" if given is not None else method
        mine = variant_of(found, variant) or found.scene
        raise SceneError(f"answers: these are the steps of {named}; class {found.code} "
                         f"practises {found.method} on {mine[:60]}"
                         + (f" at {found.at:g}" if found.at is not None else "")
                         + " (leave the scene out: the class's is taken)")
    return own


def _signature(steps: list) -> list[tuple[str, str]]:
    return [(s.id, f"{complex(s.expected):.9g}") for s in steps]
