"""Making a set of exam variants: how long thirty take per task (drawing, checking, keys and
the sheets), how many candidates were refused and why (exams/variants.py).

    .venv/bin/python bench/variants.py [COUNT]
"""

import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from exams.codes import Settings  # noqa: E402
from exams.sheets import sheets_html  # noqa: E402
from exams.variants import TRIES, generate  # noqa: E402

TASKS = ("zbirka-3.1", "zbirka-2.1", "zbirka-5.4", "analitika-2.1", "zbirka-4.2", "zbirka-4.1",
         "zbirka-6.1", "zbirka-6.8", "zbirka-7.1")


def main(count: int) -> None:
    print(f"{count} variants per task, seed 1, ± 20 % (candidates allowed: {count * TRIES})\n")
    print("| task | variants | candidates refused | variants, s | sheets, s | sheets, kB | refused most for |")
    print("|---|---:|---:|---:|---:|---:|---|")
    for pid in TASKS:
        start = time.perf_counter()
        found = generate(Settings(pid, 1), count)
        made = time.perf_counter() - start
        start = time.perf_counter()
        text = sheets_html(found, pid, "sr")
        printed = time.perf_counter() - start
        reason = found.rejected.most_common(1)[0][0] if found.rejected else "—"
        print(f"| {pid} | {len(found.variants)} | {sum(found.rejected.values())} | {made:.2f} | "
              f"{printed:.3f} | {len(text.encode()) / 1024:.0f} | {reason} |")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 30)
