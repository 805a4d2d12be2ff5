"""What the command line is given, read by one set of rules before a command runs: every
number through the one reader (``mechanisms.typed``) with its bounds, every file by one
check (an input: exists, is a file, under its size, UTF-8 text; an output: a file name in a
folder that exists). A refusal is an ``argparse.ArgumentTypeError``, which the parser says
in one line with exit 2 (``commands.Parser.error``), naming the option and what was typed."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Callable

import numpy as np

from mechanisms import Scene
from mechanisms.typed import Refused, check

SHOWN_MAX = 60  # characters of a typed value quoted in a refusal

REASONS = {"empty": "is empty", "not_number": "is not one number (write 0.35, -12.5 or 1.5e-3)",
           "comma": "has a comma: the decimal sign here is a point (0.35)",
           "integer": "is not a whole number", "below": "is less than {limit}",
           "above": "is more than {limit}"}


def quoted(text: str, *, path: bool = False) -> str:
    """What a user typed, quoted once and cut to ``SHOWN_MAX`` characters (a path keeps its
    end, where the file's name is)."""
    text = "".join(c for c in str(text) if c.isprintable())
    if len(text) > SHOWN_MAX:
        text = "…" + text[-SHOWN_MAX:] if path else text[:SHOWN_MAX] + "…"
    return repr(text)


def _refusal(refused: Refused) -> argparse.ArgumentTypeError:
    limit = "" if refused.limit is None else np.format_float_positional(refused.limit, trim="-")
    return argparse.ArgumentTypeError(f"{quoted(refused.text)} "
                                      f"{REASONS[refused.reason].format(limit=limit)}")


def number(minimum: float | None = None, maximum: float | None = None, *,
           integer: bool = False) -> Callable[[str], float]:
    """An argparse ``type``: one finite number within [minimum, maximum] (an int if
    ``integer``), read as the pages read an English field."""
    def read(text: str):
        try:
            value = check(text, "en", minimum=minimum, maximum=maximum, integer=integer)
        except Refused as refused:
            raise _refusal(refused) from None
        return int(value) if integer else value
    read.__name__ = "whole number" if integer else "number"  # (argparse names a type so)
    return read


COUNT = number(1, integer=True)  # how many of something: at least one
POSITION = number()  # the driver's position: finite here, within the scene's range by ``at``


def at(scene: Scene, value: float | None) -> float | None:
    """``--at`` within the scene's range (``Driver.range``, the pages' slider's)."""
    if value is None:
        return None
    low, high = scene.driver.range()
    if not low <= value <= high:
        unit = "°" if scene.driver.kind == "rotating" else " m"
        raise argparse.ArgumentTypeError(f"argument --at: {value:g}{unit} is outside this "
                                         f"scene's range, {low:g}{unit} … {high:g}{unit}")
    return value


def input_file(most_bytes: int) -> Callable[[str], Path]:
    """An argparse ``type``: a file that exists, at most ``most_bytes`` long, in UTF-8."""
    def read(text: str) -> Path:
        path, said = Path(text), quoted(text, path=True)
        if not path.exists():
            raise argparse.ArgumentTypeError(f"{said} does not exist")
        if not path.is_file():
            raise argparse.ArgumentTypeError(f"{said} is a folder, not a file")
        size = path.stat().st_size
        if size > most_bytes:
            raise argparse.ArgumentTypeError(f"{said} is {size / 1000:,.0f} kB; at most "
                                             f"{most_bytes // 1000} kB is read")
        try:
            path.read_bytes().decode("utf-8-sig")
        except UnicodeDecodeError as exc:
            raise argparse.ArgumentTypeError(f"{said} is not text in UTF-8 (byte {exc.start} "
                                             "is not)") from None
        except OSError as exc:
            raise argparse.ArgumentTypeError(f"{said} cannot be read ({exc.strerror})") from None
        return path
    read.__name__ = "file"
    return read


def output_file(text: str) -> Path:
    """An argparse ``type``: a file name to write, in a folder that exists."""
    path, said = Path(text), quoted(text, path=True)
    if path.is_dir() or not path.name:
        raise argparse.ArgumentTypeError(f"{said} is a folder; give a file name in it")
    if not path.parent.is_dir():
        raise argparse.ArgumentTypeError(f"{said}: the folder {quoted(str(path.parent), path=True)} "
                                         "does not exist")
    return path
