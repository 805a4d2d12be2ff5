"""What a class practises: its scene (a preset, a builder link's ``s=`` text, or a student's
own variant of the class's set) and the steps of its method there. The class view draws
them, and the command line checks that a student's answers file is for them."""

from __future__ import annotations

from exams.variants import from_code
from mechanisms import load_preset
from mechanisms.link import PARAMETER, decode
from methods.practice import Step
from methods.practice_steps import steps_for

from .store import Class, variant_of


def scene_of(scene: str):
    """A class's scene from its stored text: a preset id or a builder link's ``s=`` text."""
    if scene.startswith(f"{PARAMETER}="):
        return decode(scene.removeprefix(f"{PARAMETER}="))
    return load_preset(scene)


def steps_of(found: Class, variant: int | None = None) -> list[Step]:
    """The steps a student of ``found`` practises: the class's, or their variant's."""
    code = variant_of(found, variant)
    scene = from_code(code).scene if code else scene_of(found.scene)
    return steps_for(scene, found.method, found.at)
