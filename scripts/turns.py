"""Script runs take turns: one process serving a class runs one page script at a time.

Streamlit runs each session's script in its own thread, and Python runs one thread at a
time (the GIL). With a class working at once, five to ten runs share the CPU by turns of
5 ms, so each takes several times its own work, and the event loop that sends their
messages waits behind them. Letting one run finish before the next starts costs the class
no CPU and shortens every run but the last in the queue: with 30 sessions on one process
(deploy/loadtest.py) the reruns' p95 went from 474–676 to 299–323 ms, in three paired runs
(docs/performance.md). Two at a time was no better than none.

A run that has held the turn ``WAIT`` seconds no longer holds the others back: the next one
starts beside it, and the one after that waits for either to end or to be as old. So a long
run (the textbook check, a speed panel, a process's first, cold run) delays the rest of the
class by at most that, never stops it — and it lets one run past, not all: when every
waiting run went past a long one at once, a class opening its pages together shared the
CPU by 5-ms slices again, and the event loop that sends their messages starved (issue 70:
300 openings took 2.4× the floor's, every one finishing at the end).
"""

from __future__ import annotations

import functools
import threading
import time
from collections import deque
from collections.abc import Callable

from streamlit.runtime.scriptrunner import script_runner

WAIT = 0.25  # s: a queue of 30-ms runs this long is a server already past what it can serve


def taking_turns(run: Callable, wait: float = WAIT) -> Callable:
    """``run`` (a script runner's ``_run_script``), started in the order the runs asked, each
    once every run in progress has run ``wait`` seconds or more (none in progress: at
    once). In order: a run that came later and found the turn free used to start before
    one that slept, and at 500 students on one core a few openings waited 48 s."""
    lock = threading.Lock()
    queue: deque[threading.Event] = deque()  # the runs waiting, first come first
    started: list[float] = []  # when each run in progress started (time.monotonic)

    @functools.wraps(run)
    def in_turn(*args, **kwargs):
        me = threading.Event()
        with lock:
            queue.append(me)
        while True:
            with lock:
                left = None  # (not first: until the one before it starts)
                if queue[0] is me:
                    left = max(started, default=-wait) + wait - time.monotonic()
                    if left <= 0:
                        queue.popleft()
                        mine = time.monotonic()
                        started.append(mine)
                        if queue:
                            queue[0].set()  # the next one: its wait starts now
                        break
            me.wait(left)
            me.clear()
        try:
            return run(*args, **kwargs)
        finally:
            with lock:
                started.remove(mine)
                if queue:
                    queue[0].set()

    return in_turn


def install(wait: float = WAIT) -> None:
    """Every session's script runs from now on take turns."""
    runner = script_runner.ScriptRunner
    runner._run_script = taking_turns(runner._run_script, wait)
