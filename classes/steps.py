"""What a class practises: its scene (a preset, a builder link's ``s=`` text, or a student's
own variant of the class's set) and the steps of its method there. The class view draws
them, and the command line checks that a student's answers file is for them."""

from __future__ import annotations

from exams.variants import from_code
from mechanisms import load_preset
from mechanisms.link import PARAMETER, decode
from methods.practice import Step
from methods.practice_steps import steps_for

from .methods import METHODS
from .store import Class, student, variant_of


def scene_of(scene: str):
    """A class's scene from its stored text: a preset id or a builder link's ``s=`` text."""
    if scene.startswith(f"{PARAMETER}="):
        return decode(scene.removeprefix(f"{PARAMETER}="))
    return load_preset(scene)


def steps_of(found: Class, variant: int | None = None) -> list[Step]:
    """The steps a student of ``found`` practises: the class's, or their variant's."""
    return steps_at(found.scene, found.method, found.at, variant_of(found, variant))


def steps_at(scene: str, method: str, at: float | None, variant: str | None) -> list[Step]:
    """The steps of ``method`` on a class's stored scene (or the variant ``variant`` of its
    set) at ``at``: what a seated student's page grades by, whatever its link says (a
    cache keys them by these plain values)."""
    return steps_for(from_code(variant).scene if variant else scene_of(scene), method, at)


def practice_link(found: Class, token: str, language: str, url: str | None = None) -> tuple[str, dict]:
    """Where a student of ``found`` practises: the method's page (its path) and the query
    that opens it on the class's scene — or the student's own variant — with the class and
    the student named, so that practice is on. The class page's *Join* and an LTI launch
    send a student there alike."""
    method = METHODS[found.method]
    params = {"class": found.code, "student": token, "lang": language, **method.link}
    if found.variants:
        params["v"] = variant_of(found, student(found.code, token, url)["variant"])
    elif found.scene.startswith(f"{PARAMETER}="):
        params[PARAMETER] = found.scene.removeprefix(f"{PARAMETER}=")
    else:
        params["scene"] = found.scene
    if found.at is not None:
        params["at"] = f"{found.at:g}"
    return method.page, params
