"""``python -m solvers practice SCENE --method …``: a construction's steps with their exact
values and tolerances, and with ``--answers`` a student's answers graded step by step by the
same function the pages use (methods.practice.grade); hints in English from locales/en.toml.
"""

from __future__ import annotations

import json
from pathlib import Path

from figures.plans import plain
from mechanisms import SceneError
from mechanisms.messages import KEEP, strings
from methods.practice import Step, Verdict, answer_of, hint_texts
from methods.progress import Progress
from methods.practice_steps import steps_for


def hint(step: Step, verdict: Verdict, language: str = "en") -> str:
    """The hint for a diagnosis (methods.practice.hint_texts, the words every surface says),
    in English unless ``language`` says "sr" (a decimal comma; a term's name as text with
    sub- and superscripts, aᵏ_A4A, not LaTeX source)."""
    table = strings(language)
    return " ".join(text.render(lambda key: KEEP.sub(r"\1", table[key]), language == "sr")
                    for text in hint_texts(step, verdict, plain))


def graded(steps: list[Step], answers: dict) -> dict:
    """``{"results": [{"id", "diagnosis", "term", "hint"}], "score": {"ok", "of"}}`` for the answers
    (a step not answered is ``none``)."""
    known = [s.id for s in steps]
    unknown = [name for name in answers if name not in known]
    if unknown:
        raise SceneError(f"answers: no step {', '.join(map(repr, unknown))} in these steps; "
                         f"they are {', '.join(known)}")
    progress, results = Progress.start(), []
    for step in steps:
        given = answers.get(step.id)
        try:
            value = answer_of(given, step.kind)
        except ValueError as exc:
            raise SceneError(f"answers: {step.id} must be {exc}") from None
        verdict = progress.give(step, value)
        results.append({"id": step.id, "diagnosis": verdict.diagnosis, "term": verdict.term,
                        "hint": hint(step, verdict)})
    return {"results": results, "score": {"ok": sum(r["diagnosis"] == "ok" for r in results),
                                          "of": len(steps)}}


ANSWERS_MAX = 1_000_000  # bytes: a method's answers are a few kB; a 50 MB file is not one


def read_answers(path: str) -> dict:
    """The answers file: ``{"answers": {"<id>": [x, y] or number}}`` (SceneError if not).
    Its size and encoding were checked with the command line (``arguments.input_file``)."""
    try:
        data = json.loads(Path(path).read_text(encoding="utf-8"), parse_constant=_not_json)
    except OSError as exc:
        raise SceneError(f"answers: cannot read {path}: {exc.strerror}") from None
    except json.JSONDecodeError as exc:
        raise SceneError(f"answers: {path} is not JSON ({exc.msg}, line {exc.lineno})") from None
    except ValueError as exc:  # (after JSONDecodeError, one of them)
        raise SceneError(f"answers: {path} holds {exc}, which is not a number") from None
    if not isinstance(data, dict) or not isinstance(data.get("answers"), dict):
        raise SceneError(f'answers: {path} must hold {{"answers": {{"<step id>": [x, y] or a '
                         'number}}')
    return data["answers"]


def _not_json(constant: str):
    """JSON has no NaN or Infinity (Python's reader takes them): refused."""
    raise ValueError(constant)


def run(scene, method: str, at: float | None, answers_path: str | None) -> dict:
    """What ``practice`` prints: the steps, or the graded answers."""
    steps = steps_for(scene, method, at)
    if answers_path is not None:
        return graded(steps, read_answers(answers_path))
    return {"scene": scene.id, "method": method, "steps": [s.json() for s in steps]}
