"""Script runs take turns: one process serving a class runs one page script at a time.

Streamlit runs each session's script in its own thread, and Python runs one thread at a
time (the GIL). With a class working at once, five to ten runs share the CPU by turns of
5 ms, so each takes several times its own work, and the event loop that sends their
messages waits behind them. Letting one run finish before the next starts costs the class
no CPU and shortens every run but the last in the queue: with 30 sessions on one process
(deploy/loadtest.py) the reruns' p95 went from 474–676 to 299–323 ms, in three paired runs
(docs/performance.md). Two at a time was no better than none.

A run waits for its turn at most ``WAIT`` seconds and then runs beside the others, as
Streamlit would have run it: a long run (the textbook check, a speed panel) delays the rest
of the class by at most that, never stops it.
"""

from __future__ import annotations

import functools
import threading
from collections.abc import Callable

from streamlit.runtime.scriptrunner import script_runner

WAIT = 0.25  # s: a queue of 30-ms runs this long is a server already past what it can serve


def taking_turns(run: Callable, wait: float = WAIT) -> Callable:
    """``run`` (a script runner's ``_run_script``), holding the process's one turn while it
    runs; after ``wait`` seconds without it, running anyway."""
    turn = threading.Lock()

    @functools.wraps(run)
    def in_turn(*args, **kwargs):
        mine = turn.acquire(timeout=wait)
        try:
            return run(*args, **kwargs)
        finally:
            if mine:
                turn.release()

    return in_turn


def install(wait: float = WAIT) -> None:
    """Every session's script runs from now on take turns."""
    runner = script_runner.ScriptRunner
    runner._run_script = taking_turns(runner._run_script, wait)
