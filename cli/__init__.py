"""The command line (``python -m solvers …``, docs/cli.md): it sits on top of every package and
may import any of them. ``commands`` parses and prints; ``bench`` times the solver against a
closed form."""

from .commands import main

__all__ = ["main"]
