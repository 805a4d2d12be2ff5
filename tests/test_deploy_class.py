"""A class on the faculty's setup, for real: ``deploy/start.sh`` (two app processes behind
nginx, a PostgreSQL server of its own, the schema migrated by the start command). A student
on a phone joins through nginx and checks a step; the same link opened on each app process
brings the progress back from the store; an app process killed (``kill -9``) is started
again and a reload finds the progress; the check is stored once; SIGTERM stops all."""

from __future__ import annotations

import os
import shutil
import signal
import time
from pathlib import Path

import pytest

from classes import store
from deploy.classload import app_pid, class_load, healthy, start_deploy

from .test_browser import CHROMIUM, FLAGS, check_first_step, wait_idle
from .test_classes import PG_BIN

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
        for app in apps:  # another process (no sticky cookie): the progress from the store
            other = browser.new_context(viewport={"width": 1200, "height": 900}).new_page()
            other.goto(app + link)
            other.locator("[data-testid='stAlertContentSuccess']").wait_for(timeout=60_000)
            other.context.close()
        killed = app_pid(deployed.ports[0])
        os.kill(killed, signal.SIGKILL)  # a process falls over: started again, nothing lost
        time.sleep(1.5)
        healthy(apps[0])
        assert app_pid(deployed.ports[0]) not in (None, killed)
        student.reload()  # through nginx, to whichever process: the progress from the store
        student.locator("[data-testid='stAlertContentSuccess']").wait_for(timeout=60_000)
        browser.close()
    rows = store.export(code, key, url=url)
    assert [(r["nickname"], r["diagnosis"], r["try"]) for r in rows] == [("ana", "ok", 1)]

    script.send_signal(signal.SIGTERM)  # Ctrl-C: nginx, both processes and PostgreSQL stop
    assert script.wait(timeout=60) == 143  # (stopped by the signal, cleaned up on the way out)
    assert not (pgdata / "postmaster.pid").exists()


def test_a_class_load_with_the_database_stopped_loses_nothing():
    """``deploy/loadtest.py --class`` in small: four students and a lecturer's view on
    deploy/start.sh, PostgreSQL stopped for 10 s half-way. The checks in the gap say "not
    saved" and are sent again; every verdict seen is in the store once, with the diagnosis
    the student saw, and the view catches up with the store."""
    found = class_load(4, 30.0, "database")
    assert found["errors"] == 0, found["first_errors"]
    assert found["not_saved"] >= 1  # the gap was felt
    assert found["sent"] == found["stored"] == found["view_last"] > 0
    assert found["lost"] == found["verdict_disagrees"] == 0
