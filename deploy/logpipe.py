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

def _encoded(text: str) -> str:
    """A pattern for ``text`` written plainly or with any letter percent-encoded, once or
    more (``k``, ``%6B``, ``%256B`` …)."""
    return "".join(f"(?:{re.escape(c)}|%(?:25)*{ord(c):02x})" for c in text)


# a secret's name (however encoded, and as the tail of a longer one: id_token), its "=" and
# its value, up to the next separator, plain or encoded
SECRET = re.compile(
    rf"(?i)((?:{'|'.join(_encoded(n) for n in ('key', 'student', 'token'))})(?:=|%(?:25)*3d))"
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
