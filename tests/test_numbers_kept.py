"""Every number the command line printed for every preset before the packages were laid out
by job is found again (tests/data/numbers.json, written by tests/record_numbers.py)."""

from __future__ import annotations

import json
import math

from .record_numbers import COMMANDS, OUT, record

# The same code on another CPU rounds differently in the last bits (numpy picks its SIMD
# loops by CPU), and a class III group's Newton iterations carry that further: 1e-12 relative
# and 7e-13 absolute on accelerations of 20 m/s² between two machines here. A real change
# moves a printed number by far more.
REL, ABS = 1e-9, 1e-9


def _differences(before, after, where: str) -> list[str]:
    if isinstance(before, dict) and isinstance(after, dict):
        if before.keys() != after.keys():
            return [f"{where}: keys {sorted(before.keys() ^ after.keys())}"]
        return [d for k in before for d in _differences(before[k], after[k], f"{where}.{k}")]
    if isinstance(before, list) and isinstance(after, list):
        if len(before) != len(after):
            return [f"{where}: {len(before)} items, now {len(after)}"]
        return [d for i, (b, a) in enumerate(zip(before, after))
                for d in _differences(b, a, f"{where}[{i}]")]
    if isinstance(before, float) or isinstance(after, float):
        if isinstance(before, (int, float)) and isinstance(after, (int, float)) and (
                before == after or math.isclose(before, after, rel_tol=REL, abs_tol=ABS)):
            return []
        return [f"{where}: {before!r} → {after!r}"]
    return [] if before == after else [f"{where}: {before!r} → {after!r}"]


def test_every_preset_prints_the_numbers_it_printed_before():
    before = json.loads(OUT.read_text())
    after = record()
    assert before.keys() == after.keys()
    problems = [d for preset in before for command in COMMANDS
                for d in _differences(before[preset][command], after[preset][command],
                                      f"{preset} {command}")]
    assert not problems, "\n".join(problems[:20])


def test_the_comparison_sees_a_changed_number():
    assert _differences({"a": [1.0, 2.0]}, {"a": [1.0, 2.000001]}, "x") == ["x.a[1]: 2.0 → 2.000001"]
    assert _differences({"a": 1.0}, {"a": 1.0 + 1e-15}, "x") == []
