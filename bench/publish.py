"""Print a benchmark's table and, with ``--write``, put it into docs/performance.md between
its two marker comments (the rest of the document is prose written by hand)."""

import platform
import sys
from datetime import date
from pathlib import Path

DOC = Path(__file__).resolve().parents[1] / "docs" / "performance.md"


def publish(text: str, mark: str, runs: int) -> None:
    print(text)
    if "--write" not in sys.argv:
        return
    head, _, rest = DOC.read_text().partition(mark)
    _, _, tail = rest.partition(mark)
    median = f", median of {runs} runs" if runs > 1 else ""  # errors are computed, not timed
    DOC.write_text(f"{head}{mark}\nMeasured {date.today()} on {platform.machine()}, Python "
                   f"{platform.python_version()}{median}:\n\n{text}\n{mark}{tail}")
