"""A class served by several machines on one PostgreSQL (issue 84): ``deploy/start.sh``'s
roles refused in one line when a host lacks what it needs, two hosts migrating one schema
at once, and a class on two app hosts, PostgreSQL and nginx each in a network namespace of
its own (deploy/hosts.py), one app host killed mid-class."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest
import sqlalchemy as sa

from classes import store
from deploy.classload import class_load
from deploy.hosts import why_not

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.parametrize("args, env, said", [
    (["--role", "app"], {}, "--role app needs --database URL"),
    (["--role", "app", "--database", "sqlite:///x.db"], {}, "--database must be a postgresql URL"),
    (["--role", "app", "--database", "postgresql+psycopg://db/m"], {},
     "needs MEHANIZMI_COOKIE_SECRET"),
    (["--role", "app", "--database", "postgresql+psycopg://db/m"],
     {"MEHANIZMI_COOKIE_SECRET": "s", "MEHANIZMI_LTI_KEY": "/nonexistent/key.pem"},
     "needs MEHANIZMI_LTI_KEY"),
    (["--role", "proxy"], {}, "--role proxy needs --upstream HOST:PORT"),
    (["--role", "proxy", "--upstream", "10.0.0.2"], {}, "--upstream 10.0.0.2: give HOST:PORT"),
    (["--upstream", "10.0.0.2:8601"], {}, "--upstream is for --role proxy"),
    (["--role", "db"], {}, "--role db: all, app or proxy"),
    (["--role"], {}, "--role needs all, app or proxy"),
    (["--port", "80"], {}, "unknown argument --port"),
])
def test_a_role_missing_what_it_needs_is_refused_in_one_line(args, env, said):
    """Refused before anything is installed or started: exit 2, one line naming the want."""
    clean = {k: v for k, v in os.environ.items() if not k.startswith("MEHANIZMI_")}
    done = subprocess.run(["bash", "deploy/start.sh", *args], cwd=ROOT, env={**clean, **env},
                          capture_output=True, text=True, timeout=30)
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr.count("\n") == 1 and said in done.stderr, done.stderr


@pytest.mark.server
def test_hosts_migrating_one_database_at_once_make_one_schema(postgres):
    """Two app hosts started together: both migrations end well (one waits for the other's
    advisory lock), and the schema is there once."""
    fresh = "migrated_together"
    with sa.create_engine(postgres.url, isolation_level="AUTOCOMMIT").connect() as c:
        c.execute(sa.text(f"DROP DATABASE IF EXISTS {fresh}"))
        c.execute(sa.text(f"CREATE DATABASE {fresh}"))
    url = postgres.url.rsplit("/", 1)[0] + f"/{fresh}"
    env = {**os.environ, "MEHANIZMI_DATABASE_URL": url}
    hosts = [subprocess.Popen([str(ROOT / ".venv/bin/python"), "-m", "solvers", "class", "migrate"],
                              cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True) for _ in range(2)]
    said = [h.communicate(timeout=120)[0] for h in hosts]
    assert [h.returncode for h in hosts] == [0, 0], said
    engine = sa.create_engine(url)
    with engine.connect() as c:
        assert c.execute(sa.text("SELECT count(*) FROM alembic_version")).scalar() == 1
    code, key = store.create("zbirka-3.1", "plans", url=url)  # the store works on it
    assert store.export(code, key, url=url) == []
    engine.dispose()


@pytest.mark.server
def test_a_class_on_two_hosts_goes_on_when_one_host_is_lost():
    """16 students through nginx on two app hosts; half-way every process of one host is
    killed: its students reconnect to the other and go on at the step they were on; every
    check seen is stored once; the namespaces are gone afterwards."""
    reason = why_not()
    if reason:
        if os.environ.get("CI"):
            raise RuntimeError(f"CI must run the hosts' test: {reason}")
        pytest.skip(reason)
    found = class_load(16, 20.0, "host", hosts=2)
    assert found["errors"] == 0 and found["lost"] == 0, found["first_errors"]
    assert found["sent"] == found["stored"] > 0  # nothing lost, nothing doubled
    before = found["per_host_checks_before_fault"]
    assert set(before) == {"app1", "app2"} and min(before.values()) > 0  # the class split
    assert found["host_lost"] == "app1" and found["students_moved"] > 0
    assert found["students_resumed"] == found["students_moved"]
    after = found["per_host_checks"]
    assert after["app2"] > before["app2"]  # the lost host's students checked on there
    listed = subprocess.run(["ip", "netns", "list"], capture_output=True, text=True).stdout
    assert f"mz{os.getpid() % 100000}-" not in listed
