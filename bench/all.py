"""Every benchmark, one after the other, each regenerating its tables in docs/performance.md
(the pages' speed panels read them from there). About ten minutes on this machine; the
browser benchmark needs Debian's chromium, the peers benchmark makes .venv-peers once.

    .venv/bin/python bench/all.py
"""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BENCHES = ("kinematics", "accuracy", "kinetostatics", "peers", "pages", "browser")

if __name__ == "__main__":
    for name in BENCHES:
        print(f"== bench/{name}.py", flush=True)
        subprocess.run([sys.executable, str(ROOT / "bench" / f"{name}.py"), "--write"],
                       cwd=ROOT, check=True)
