"""The app as an LTI 1.3 tool against a real Moodle (4.5) — too heavy for CI; run it where a
Moodle is installed (docs/lti.md has the recipe that installed one on this machine):

    .venv/bin/python bench/moodle_lti.py --moodle-dir /path/to/moodle --moodle-url http://127.0.0.1:8710

It registers the app in Moodle as an LTI 1.3 tool (keyset URL, deep linking, grades by AGS;
bench/moodle/setup.php) with a course, a teacher, a student and one activity for task
3.1's plans, serves the app (``asgi.py``) with a store of its own, registers the platform
in it, and then, in chromium: the student opens the activity in Moodle and lands in practice,
checks the first step, and the bench waits for the grade in Moodle's gradebook; the teacher
opens the same activity and lands on the class's live view; the teacher's deep-linking
request (Moodle's "Select content") gets the app's picker, and the signed link it returns
is taken by Moodle. It prints the seconds from the check to the grade, and keeps
screenshots of each page in ``--shots``.
"""

from __future__ import annotations

import argparse
import asyncio
import cmath
import json
import math
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from cli.practice import steps_for  # noqa: E402
from deploy.client import free_port, start_server, wait_ready  # noqa: E402
from lti import store as lti  # noqa: E402
from mechanisms import load_preset  # noqa: E402

SCRIPTS = {"setup": "mehanizmi_setup.php", "grade": "mehanizmi_grade.php"}


def php(moodle: Path, script: str, *args: str) -> dict:
    """One of bench/moodle/'s scripts, run in Moodle's folder; its JSON line."""
    done = subprocess.run(["php", "-d", "max_input_vars=5000", SCRIPTS[script], *args],
                          cwd=moodle, capture_output=True, text=True, check=True)
    return json.loads(done.stdout.strip().splitlines()[-1])


def login(page, moodle_url: str, user: str, password: str) -> None:
    page.goto(f"{moodle_url}/login/index.php")
    page.wait_for_timeout(1500)  # (the login token is the session's once the page is whole)
    page.fill("#username", user)
    page.fill("#password", password)
    page.click("#loginbtn")
    page.wait_for_url("**/my/**", timeout=30_000)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--moodle-dir", type=Path, required=True)
    parser.add_argument("--moodle-url", required=True)
    parser.add_argument("--shots", type=Path, default=Path(tempfile.gettempdir()) / "moodle-lti")
    args = parser.parse_args()
    from playwright.sync_api import sync_playwright

    from tests.test_browser import CHROMIUM, FLAGS

    args.shots.mkdir(parents=True, exist_ok=True)
    for name, file in SCRIPTS.items():
        shutil.copy(ROOT / "bench" / "moodle" / f"{name}.php", args.moodle_dir / file)
    data = Path(tempfile.mkdtemp(prefix="mz-lti-"))
    port = free_port()
    base = f"http://127.0.0.1:{port}"
    steps = steps_for(load_preset("zbirka-3.1"), "plans")
    made = php(args.moodle_dir, "setup", base, str(len(steps)), str(int(time.time())))
    lti.add_platform(made["issuer"], made["client_id"], made["deployment"], made["auth_url"],
                     made["token_url"], made["jwks_url"], f"sqlite:///{data / 'mehanizmi.db'}")
    log = open(data / "server.log", "w")
    server = start_server(port, log=log, env={"MEHANIZMI_DATA": str(data),
                                              "MEHANIZMI_BASE_URL": base})
    try:
        asyncio.run(wait_ready(f"ws://127.0.0.1:{port}/_stcore/stream"))
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
            student(browser, args, made, steps, made["cmid"], made["instance"])
            teacher(browser, args, made)
            # an activity typed by hand (no deep linking, no grade of its own): the tool
            # makes its line item, and the grade reaches it
            student(browser, args, made, steps, made["typed_cmid"], made["typed_instance"], "typed-")
            browser.close()
    finally:
        server.terminate()
        server.wait(timeout=10)
        log.close()
        for file in SCRIPTS.values():
            (args.moodle_dir / file).unlink(missing_ok=True)
    print(f"screenshots: {args.shots}")


def student(browser, args, made: dict, steps, cmid: int, instance: int, shot: str = "") -> None:
    """The student's click on the activity ``cmid``, their first check, and the grade in
    Moodle's gradebook."""
    page = browser.new_context(viewport={"width": 1400, "height": 1000}).new_page()
    login(page, args.moodle_url, made["student"], "Student-1!")
    page.goto(f"{args.moodle_url}/mod/lti/view.php?id={cmid}")
    page.screenshot(path=str(args.shots / f"{shot}1-moodle-activity.png"))
    started = time.monotonic()
    page.goto(f"{args.moodle_url}/mod/lti/launch.php?id={cmid}")
    page.wait_for_url("**/velocity_plans?**", timeout=60_000)
    page.get_by_text("Step 1 of").wait_for(timeout=60_000)
    print(f"the student's click to practice open: {time.monotonic() - started:.1f} s")
    step = steps[0]
    sid = step.id.replace(".", "-")
    page.locator(f".st-key-pr_plans_len_{sid} input").fill(f"{abs(complex(step.expected)):.4f}")
    page.locator(f".st-key-pr_plans_ang_{sid} input").fill(
        f"{math.degrees(cmath.phase(complex(step.expected))) % 360:.3f}")
    page.get_by_role("button", name="Check").click()
    page.locator("[data-testid='stAlertContentSuccess']").wait_for(timeout=30_000)
    checked = time.monotonic()
    page.screenshot(path=str(args.shots / f"{shot}2-app-practice.png"))
    grade = {"grade": None}
    while grade["grade"] is None and time.monotonic() - checked < 60:
        time.sleep(1)
        grade = php(args.moodle_dir, "grade", str(made["course"]), str(instance),
                    str(made["student_id"]))
    print(f"{shot}the check to Moodle's gradebook: {time.monotonic() - checked:.1f} s, "
          f"grade {grade['grade']} of {grade['max']} (steps: {len(steps)}; {grade.get('label')})")
    if grade["grade"] is None:
        raise SystemExit("no grade reached Moodle within 60 s")


def teacher(browser, args, made: dict) -> None:
    """The teacher's click to the live view, the gradebook, and deep linking's round trip."""
    page = browser.new_context(viewport={"width": 1400, "height": 1000}).new_page()
    login(page, args.moodle_url, made["teacher"], "Nastavnik-1!")
    page.goto(f"{args.moodle_url}/mod/lti/launch.php?id={made['cmid']}")
    page.wait_for_url("**/class?**", timeout=60_000)
    page.wait_for_timeout(4000)
    page.screenshot(path=str(args.shots / "3-app-live-view.png"))
    print(f"the teacher lands on: {page.url.split('?')[0]}")
    page.goto(f"{args.moodle_url}/grade/report/grader/index.php?id={made['course']}")
    page.wait_for_selector("#user-grades", timeout=30_000)
    page.wait_for_timeout(1500)
    if page.get_by_role("button", name="Skip tour").count():  # Moodle's first-visit tour
        page.get_by_role("button", name="Skip tour").click()
    page.screenshot(path=str(args.shots / "4-moodle-gradebook.png"))
    page.goto(f"{args.moodle_url}/mod/lti/contentitem.php?id={made['deployment']}"
              f"&course={made['course']}&section=0&title=x&text=")
    page.wait_for_url("**/lti/launch", timeout=60_000)
    page.screenshot(path=str(args.shots / "5-app-picker.png"))
    page.select_option("select[name=task]", "zbirka-3.1")
    page.select_option("select[name=method]", "plans")
    page.click("button[type=submit]")
    page.wait_for_url("**/contentitem_return.php**", timeout=60_000)
    page.wait_for_timeout(1500)
    said = page.inner_text("body")
    page.screenshot(path=str(args.shots / "6-moodle-deep-link-return.png"))
    print(f"deep linking's return taken by Moodle: {'error' not in said.lower()} "
          f"({said.strip()[:80]!r})")


if __name__ == "__main__":
    main()
