"""Record what the command line prints for every preset (``solve``, ``plan``, ``forces`` and
``structure`` as JSON, with the exit code), so that a move of code can be checked to change
no number: ``python tests/record_numbers.py`` writes tests/data/numbers.json, and
tests/test_numbers_kept.py finds every number again.

Recorded once, before the packages were laid out by job (issue 34); run it again only when
an answer is meant to change, and say why in the commit.
"""

from __future__ import annotations

import contextlib
import io
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "tests" / "data" / "numbers.json"
COMMANDS = ("solve", "plan", "forces", "structure")


def _main():
    sys.path.insert(0, str(ROOT))
    from cli import main
    return main


def run(main, command: str, preset: str) -> dict:
    """One command's JSON (or its message) and exit code."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main([command, preset, "--json"])
    text = out.getvalue()
    return {"code": code, "json": json.loads(text) if code == 0 else None,
            "error": err.getvalue().strip() if code else ""}


def record() -> dict:
    main = _main()
    from mechanisms import preset_ids
    return {preset: {command: run(main, command, preset) for command in COMMANDS}
            for preset in preset_ids()}


if __name__ == "__main__":
    OUT.write_text(json.dumps(record(), ensure_ascii=False, sort_keys=True) + "\n")
    print(f"{OUT}: {OUT.stat().st_size} bytes")
