"""A log written from a pipe: what a process prints, kept in ``FILE`` (rotated at a size cap,
a few old ones kept, readable by its owner alone) with every lecturer key and student token
a line may carry replaced by "…". deploy/start.sh pipes each app process and nginx into one.

    some-server 2>&1 | python deploy/logpipe.py logs/app-8601.log [--bytes N] [--keep K]

The app keeps keys out of its own lines, and nginx's access log writes paths without their
query; this is the net under both (nginx's error log repeats a failed request's line and its
referrer, query and all, when an app process is down).
"""

from __future__ import annotations

import argparse
import logging
import os
import re
import sys
from logging.handlers import RotatingFileHandler

def _digit(d: str) -> str:
    """A hex digit of a percent-encoding, itself written plainly or percent-encoded (a
    doubly encoded "=" is ``%253D``, or ``%25%33%44`` with its digits encoded too)."""
    codes = sorted({f"{ord(v):02x}" for v in (d.lower(), d.upper())})
    return f"(?:{re.escape(d)}|%(?:25)*(?:{'|'.join(codes)}))"


def _char(c: str) -> str:
    """A pattern for one character written plainly, in either case, or percent-encoded —
    in either case's code, once or more (``k``, ``K``, ``%6B``, ``%4b``, ``%256B`` …)."""
    codes = sorted({f"{ord(v):02x}" for v in (c.lower(), c.upper())})
    encoded = "|".join("".join(_digit(h) for h in code) for code in codes)
    return f"(?:{re.escape(c)}|%(?:25)*(?:{encoded}))"


def _encoded(text: str) -> str:
    return "".join(_char(c) for c in text)


# a secret's name (however encoded, either case, and as the tail of a longer one:
# id_token), its "=" (however encoded) and its value, up to the next separator
SECRET = re.compile(
    rf"(?i)((?:{'|'.join(_encoded(n) for n in ('key', 'student', 'token'))}){_char('=')})"
    r"(?:(?!%(?:25)*26)[^&\s\"',;])+")
CLIENT = re.compile(r"\bclient: [^,\s]+")  # nginx's error log names the client's address


def redacted(line: str) -> str:
    """``line`` with the value of every ``key=``, ``student=`` and ``…token=`` (however
    URL-encoded) and every client address replaced by "…"."""
    return CLIENT.sub("client: …", SECRET.sub(r"\1…", line))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("file")
    parser.add_argument("--bytes", type=int, default=10 * 2**20, help="rotate above this size")
    parser.add_argument("--keep", type=int, default=5, help="old files kept (FILE.1 … FILE.K)")
    args = parser.parse_args(argv)
    os.umask(0o077)
    handler = RotatingFileHandler(args.file, maxBytes=args.bytes, backupCount=args.keep,
                                  encoding="utf-8")
    handler.setFormatter(logging.Formatter("%(message)s"))
    for line in sys.stdin:  # (each line flushed: a killed process's last words are kept)
        handler.emit(logging.makeLogRecord({"msg": redacted(line.rstrip("\n"))}))
    handler.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
