"""Which task of the course's texts has a preset, and why the others have none yet
(``coverage.toml``): the textbook check page's coverage table."""

from __future__ import annotations

import functools
import tomllib
from dataclasses import dataclass
from pathlib import Path

from .loader import PRESETS

FILE = Path(__file__).with_name("coverage.toml")


@dataclass(frozen=True)
class Task:
    text: str  # the text's title, e.g. "Problem collection"
    text_sr: str
    number: str  # "2.3", or the lecture's name
    preset: str  # the id it has, or would have: zbirka-2.3
    reason: dict[str, str]  # why there is no preset (en, sr); empty when there is one

    @property
    def covered(self) -> bool:
        return not self.reason

    @property
    def chapter(self) -> str:
        return self.number.split(".")[0] if self.number[0].isdigit() else "5"


@functools.cache
def tasks() -> tuple[Task, ...]:
    data = tomllib.loads(FILE.read_text(encoding="utf-8"))
    missing = data["missing"]
    out = []
    for text in data["texts"]:
        for number in text["tasks"]:
            preset = f"{text['prefix']}-{number}"
            reason = {}
            if not (PRESETS / f"{preset}.toml").is_file():
                reason = missing.get(preset, missing["fitted"])
            out.append(Task(text["title"], text["title_sr"], number, preset, reason))
    return tuple(out)
