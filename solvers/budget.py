"""A wall-time budget for one solve, so that no scene keeps a server process busy.

The limits on a scene's size (mechanisms/limits.py) keep every allowed scene's solve far
below a second; this is the guard behind them. The outermost ``decompose`` or ``solve`` of
a call starts the clock, the loops that could run long (the structure search, Newton's
method and the march of class III groups, the groups of a cycle) look at it, and past
``SECONDS`` they stop with ``OverBudget`` — an ``Unsolvable``, so every page and the command
line already say it in words instead of hanging.
"""

from __future__ import annotations

import functools
import time
from contextvars import ContextVar

from mechanisms.messages import Text

SECONDS = 5.0
_deadline: ContextVar[float | None] = ContextVar("solve_deadline", default=None)


class Unsolvable(Exception):
    """The mechanism cannot be in the requested position; the message says why."""


class OverBudget(Unsolvable):
    """Solving took longer than one page may spend on it."""


def bounded(function):
    """Run ``function`` under the budget: the outermost bounded call starts the clock."""
    @functools.wraps(function)
    def run(*args, **kwargs):
        if _deadline.get() is not None:
            return function(*args, **kwargs)
        token = _deadline.set(time.monotonic() + SECONDS)
        try:
            return function(*args, **kwargs)
        finally:
            _deadline.reset(token)
    return run


def check() -> None:
    """Stop with OverBudget once the running solve is past its budget."""
    deadline = _deadline.get()
    if deadline is not None and time.monotonic() > deadline:
        raise OverBudget(Text("budget.over", seconds=float(SECONDS)))
