"""Work per oversized or hostile scene: how long refusing it takes, and how long the largest
scene the limits allow takes to solve (mechanisms/limits.py, solvers/budget.py).

    .venv/bin/python bench/hostile.py
"""

import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from mechanisms import SceneError, parse_document  # noqa: E402
from solvers.diagnostics import solve_instant, sweep_values  # noqa: E402
from solvers.kinematics import solve  # noqa: E402
from tests.scenes import chain, dyads, largest_allowed, rotor, train  # noqa: E402

CASES = [
    ("gear train, 10,000 members", train(10_000)),
    ("linkage, 6,000 members pinned to the frame", chain(6_000, pinned=True)),
    ("linkage, 3,000-member chain", chain(3_000)),
    ("rotor, 5,000 masses", rotor(5_000)),
    ("gear train, 300 members", train(300)),
    ("linkage, 400 members pinned to the frame", chain(400, pinned=True)),
    ("linkage, 21 dyads (43 members)", dyads(21)),
    ("rotor, 101 masses", rotor(101)),
]


def median_ms(run, repeat: int = 5) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return 1e3 * statistics.median(times)


def refuse(text: str) -> None:
    try:
        parse_document(text)
    except SceneError:
        return
    raise AssertionError("accepted")


def main() -> None:
    print("| scene | file size | refused in, ms (median of 5) |\n|---|---:|---:|")
    for name, text in CASES:
        print(f"| {name} | {len(text.encode()) / 1024:.0f} kB | {median_ms(lambda: refuse(text)):.2f} |")
    scene = parse_document(largest_allowed())
    print(f"\nlargest allowed linkage ({len(scene.members)} moving members, {len(scene.pairs)} pairs): "
          f"instant {median_ms(lambda: solve_instant(scene, None)):.1f} ms, "
          f"360 positions {median_ms(lambda: solve(scene, sweep_values(scene, 360))):.1f} ms, "
          f"3600 positions {median_ms(lambda: solve(scene, sweep_values(scene, 3600))):.1f} ms")
    assert np.isfinite(solve_instant(scene, None).points["C9"].z[0])


if __name__ == "__main__":
    main()
