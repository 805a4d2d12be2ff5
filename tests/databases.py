"""A PostgreSQL server of the tests' own (the class store's tests run against a real one,
on SQLite and PostgreSQL alike): the one a worker's run shares is ``tests/conftest.py``'s
``postgres`` fixture; tests that stop it mid-test make their own."""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

from deploy.client import free_port

PG_BIN = next(iter(sorted(Path("/usr/lib/postgresql").glob("*/bin"))), None) \
    if Path("/usr/lib/postgresql").exists() else None


class Postgres:
    """A PostgreSQL server of our own in a temporary folder, on a free port."""

    def __init__(self):
        self.dir = Path(tempfile.mkdtemp(prefix="mz-pg-"))
        self.port = free_port()
        self.as_user = [] if os.getuid() != 0 else ["runuser", "-u", "postgres", "--"]
        if self.as_user:
            shutil.chown(self.dir, "postgres")
        self.run("initdb", "-D", str(self.dir / "data"), "-A", "trust", "-U", "postgres")
        self.start()
        self.url = f"postgresql+psycopg://postgres@127.0.0.1:{self.port}/postgres"

    def run(self, tool: str, *args: str) -> None:
        subprocess.run([*self.as_user, str(PG_BIN / tool), *args], check=True,
                       capture_output=True)

    def start(self) -> None:
        self.run("pg_ctl", "-D", str(self.dir / "data"), "-o",
                 f"-p {self.port} -k {self.dir} -c listen_addresses=127.0.0.1", "-w", "start",
                 "-l", str(self.dir / "log"))

    def stop(self) -> None:
        self.run("pg_ctl", "-D", str(self.dir / "data"), "-m", "fast", "-w", "stop")
