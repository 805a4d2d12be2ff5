"""A class on the faculty's setup, for real: ``deploy/start.sh`` (two app processes behind
nginx, a PostgreSQL server of its own, the schema migrated by the start command). A student
on a phone joins through nginx and checks a step; the same link opened on each app process
brings the progress back from the store; an app process killed (``kill -9``) is started
again and a reload finds the progress; the check is stored once; SIGTERM stops all. The
logs it kept afterwards are private, rotated files with an access log, and no file the
deployment wrote holds a lecturer's key or a student's token, even of requests sent while a
process was down (nginx then logs the request's line and referrer)."""

from __future__ import annotations

import json
import os
import secrets
import shutil
import signal
import stat
import subprocess
import tempfile
import time
import urllib.error
import urllib.request
from pathlib import Path

import pytest

from classes import store
from deploy.classload import app_pid, class_load, healthy, start_deploy

from .test_browser import CHROMIUM, FLAGS, check_first_step, wait_idle
from .databases import PG_BIN

ROOT = Path(__file__).resolve().parents[1]
pytestmark = pytest.mark.browser

if shutil.which("nginx") is None or PG_BIN is None:
    if os.environ.get("CI"):
        raise RuntimeError("nginx or PostgreSQL is missing in CI: scripts/test.sh installs them")
    pytest.skip("nginx and Debian's postgresql are installed by scripts/test.sh",
                allow_module_level=True)


@pytest.fixture(scope="module")
def deployed():
    """deploy/start.sh running, with a PostgreSQL of its own in a temporary folder."""
    running = start_deploy()
    yield running
    running.stop()


def test_the_lti_routes_are_served_through_nginx(deployed):
    """deploy/start.sh serves asgi.py: the tool's keyset and a refused login reach a
    platform through the proxy, from every process alike (one tool key). (Before the test
    below, which ends by stopping the deployment.)"""
    keys = set()
    for base in [deployed.proxy] + [f"http://127.0.0.1:{port}" for port in deployed.ports]:
        with urllib.request.urlopen(f"{base}/lti/jwks", timeout=10) as answer:
            keys.add(json.load(answer)["keys"][0]["kid"])
    assert len(keys) == 1
    with pytest.raises(urllib.error.HTTPError) as refused:
        urllib.request.urlopen(f"{deployed.proxy}/lti/login?iss=https://nobody.example&login_hint=x",
                               timeout=10)
    assert refused.value.code == 400
    big = urllib.request.Request(f"{deployed.proxy}/lti/launch", data=b"id_token=" + b"x" * 400_000,
                                 headers={"Content-Type": "application/x-www-form-urlencoded"})
    with pytest.raises(urllib.error.HTTPError) as refused:  # nginx's limit, the tool's words
        urllib.request.urlopen(big, timeout=10)
    said = refused.value.read().decode()
    assert refused.value.code == 413 and "obrazac" in said and "form sent is larger" in said


def test_a_student_behind_nginx_resumes_on_either_process_from_postgresql(deployed):
    from playwright.sync_api import sync_playwright

    proxy, url, script, pgdata = deployed.proxy, deployed.database, deployed.script, deployed.pgdata
    apps = [f"http://127.0.0.1:{port}" for port in deployed.ports]
    assert (pgdata / "PG_VERSION").exists()  # its own server, its data where it was told
    code, key = store.create("zbirka-3.1", "plans", url=url)
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        phone = {k: v for k, v in p.devices["iPhone 13"].items() if k != "default_browser_type"}
        student = browser.new_context(**phone, locale="sr-RS").new_page()
        student.goto(f"{proxy}/class?join={code}&lang=sr")
        student.get_by_label("Nadimak").fill("ana")
        student.get_by_role("button", name="Pridruži se i vežbaj").tap()
        student.wait_for_url("**/velocity_plans**", timeout=60_000)
        student.locator("[data-testid='stForm'] input").first.wait_for(timeout=60_000)
        wait_idle(student)
        check_first_step(student)
        link = student.url.removeprefix(proxy)
        token = link.split("student=", 1)[1].split("&", 1)[0]
        for app in apps:  # another process (no sticky cookie): the progress from the store
            other = browser.new_context(viewport={"width": 1200, "height": 900}).new_page()
            other.goto(app + link)
            other.get_by_text("Korak 2 od").first.wait_for(timeout=60_000)  # step 1 done
            other.context.close()
        lecturer = browser.new_context(viewport={"width": 1200, "height": 900}).new_page()
        lecturer.goto(f"{proxy}/class?lang=sr&class={code}&key={key}")  # the key in its line
        lecturer.get_by_text("Sačuvane provere").first.wait_for(timeout=60_000)
        killed = app_pid(deployed.ports[0])
        os.kill(killed, signal.SIGKILL)  # a process falls over: started again, nothing lost
        planted = _while_down(proxy, code, key, token)
        _collide(url, token)
        deadline = time.monotonic() + 60  # the supervisor starts it again: waited for, not slept
        while app_pid(deployed.ports[0]) in (None, killed) and time.monotonic() < deadline:
            time.sleep(0.1)
        healthy(apps[0])
        assert app_pid(deployed.ports[0]) not in (None, killed)
        student.reload()  # through nginx, to whichever process: the progress from the store
        student.get_by_text("Korak 2 od").first.wait_for(timeout=60_000)
        browser.close()
    _the_command_line_reaches_the_deployment(deployed, code, key)
    rows = store.export(code, key, url=url)
    assert [(r["nickname"], r["diagnosis"], r["try"]) for r in rows] == [("ana", "ok", 1)]
    _backup_and_restore_as_the_docs_say(deployed, lambda: store.delete(code, key, url=url))
    assert store.export(code, key, url=url) == rows  # the class deleted after the dump: back

    script.send_signal(signal.SIGTERM)  # Ctrl-C: nginx, both processes and PostgreSQL stop
    assert script.wait(timeout=60) == 143  # (stopped by the signal, cleaned up on the way out)
    assert not (pgdata / "postmaster.pid").exists()
    _logs_kept_private_and_without_secrets(deployed, key, [token, *planted])


def _backup_and_restore_as_the_docs_say(deployed, meanwhile) -> None:
    """docs/deploy.md's backup lines, run as written (its folder for data/postgres; as
    another user than root, without runuser): a dump, ``meanwhile``, the dump restored."""
    text = (ROOT / "docs" / "deploy.md").read_text()
    block = text.split("<!-- backup:", 1)[1].split("```bash\n", 1)[1].split("```", 1)[0]
    lines = [" ".join(line.split()) for line in block.strip().splitlines()]
    assert len(lines) == 2 and "pg_dump" in lines[0] and "pg_restore" in lines[1]
    folder = tempfile.mkdtemp(prefix="mz-backup-")
    for n, line in enumerate(lines):
        line = line.replace('"$PWD/data/postgres"', f'"{deployed.pgdata}"')
        if os.getuid() != 0:
            line = line.replace("runuser -u postgres -- ", "")
        done = subprocess.run(["bash", "-c", line], cwd=folder, capture_output=True, text=True)
        assert done.returncode == 0, (line, done.stderr)
        if n == 0:
            dump = (Path(folder) / "mehanizmi.dump").stat()
            assert dump.st_size > 1000 and stat.S_IMODE(dump.st_mode) == 0o600  # (it holds tokens)
            meanwhile()
    shutil.rmtree(folder, ignore_errors=True)


def _while_down(proxy: str, code: str, key: str, token: str) -> list[str]:
    """Requests whose line and referrer carry a lecturer key and a student token, sent while
    an app process is down (each route cookie hashes to one process: half of them to the
    one down, which nginx logs as a failed upstream with the request and its referrer)."""
    planted = [f"plantedkey{secrets.token_hex(8)}", f"plantedtoken{secrets.token_hex(8)}"]
    encoded = {f"planted{n}{secrets.token_hex(6)}": form for n, form in enumerate((
        "class={code}%26key%3D{secret}", "%6Bey={secret}", "class={code}&student%253D{secret}",
        "x=1%26%73tudent%3d{secret}", "id_token={secret}"))}
    planted += list(encoded)
    queries = [f"class={code}&key={planted[0]}&student={planted[1]}",
               *(form.format(code=code, secret=secret) for secret, form in encoded.items())]
    for k in range(16):
        request = urllib.request.Request(
            f"{proxy}/class?{queries[k % len(queries)]}",
            headers={"Cookie": f"mehanizmi_route=r{k}",
                     "Referer": f"{proxy}/velocity_plans?class={code}&key={key}&student={token}"})
        try:
            urllib.request.urlopen(request, timeout=10).read()
        except OSError:
            pass  # (a 502 is what nginx answers for a process that is down)
    return planted


def _collide(url: str, token: str) -> None:
    """A unique collision naming the student's token (as two checks of one step at once
    made): PostgreSQL refuses it, and logs the error without its DETAIL."""
    import sqlalchemy as sa

    with pytest.raises(sa.exc.IntegrityError, match="unique"), store.engine(url).begin() as db:
        first = dict(db.execute(sa.select(store.checks).where(store.checks.c.student == token)).one()._mapping)
        del first["id"]
        db.execute(store.checks.insert().values({**first, "check_id": store.new_check()}))


def _the_command_line_reaches_the_deployment(deployed, code: str, key: str) -> None:
    """deploy/cli.sh: the command line against the deployment's own PostgreSQL, with no
    variable set (``class export`` said "No class has the code" against the SQLite file)."""
    env = {k: v for k, v in os.environ.items() if k != "MEHANIZMI_DATABASE_URL"}
    env["MEHANIZMI_PGDATA"] = str(deployed.pgdata)
    done = subprocess.run(["bash", "deploy/cli.sh", "class", "export", code, "--key", key],
                          cwd=ROOT, env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0 and "ana" in done.stdout, done.stderr


def _logs_kept_private_and_without_secrets(deployed, key: str, tokens: list[str]) -> None:
    """Logs: private, with an access log, and no key or token in any of them (PostgreSQL's
    own log among them). The database's files (mode 700) hold the students' tokens, which
    are their ids, but not the lecturer's key (its hash)."""
    logs = deployed.logs
    names = {path.name for path in logs.iterdir()}
    assert {"access.log", "nginx.log"} <= names and any(n.startswith("app-") for n in names)
    assert stat.S_IMODE(logs.stat().st_mode) == 0o700
    assert all(stat.S_IMODE(path.stat().st_mode) == 0o600 for path in logs.iterdir())
    assert stat.S_IMODE(deployed.pgdata.stat().st_mode) == 0o700
    access = (logs / "access.log").read_text()
    assert " /class " in access and "upstream=" in access  # what an administrator reads
    nginx = (logs / "nginx.log").read_text()
    assert "key=…" in nginx  # the failed requests, said redacted (each planted form: below)
    assert "client: …" in nginx and "client: 127" not in nginx  # and without their address
    logged = [*logs.iterdir(), deployed.pgdata / "server.log"]
    stored = [path for path in deployed.pgdata.rglob("*") if path.is_file()]
    for paths, secrets_ in ((logged, [key, *tokens]), (stored, [key])):
        for path in paths:
            text = path.read_bytes()
            for secret in secrets_:
                assert secret.encode() not in text, (path, secret[:12])


def test_a_class_load_with_the_database_stopped_loses_nothing():
    """``deploy/loadtest.py --class`` in small: four students and a lecturer's view on
    deploy/start.sh, PostgreSQL stopped for 6 s half-way (each student checks every 3–8 s:
    all four missing the gap is rare, about 0.2⁴). The checks
    in the gap say "not saved" and are sent again; every verdict seen is in the store once,
    with the diagnosis the student saw, and the view catches up with the store."""
    found = class_load(4, 20.0, "database", gap=6.0)
    assert found["errors"] == 0, found["first_errors"]
    assert found["not_saved"] >= 1  # the gap was felt
    assert found["sent"] == found["stored"] == found["view_last"] > 0
    assert found["lost"] == found["verdict_disagrees"] == 0
