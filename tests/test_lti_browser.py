"""A student's click in Moodle, end to end in chromium against the served app (st.App with
the LTI routes): the platform's login, its launch posted back, the app's practice open on
task 3.1 with no code typed — and the first step checked there reaches the platform's
gradebook by itself (the server's score sender), as a score for that step."""

from __future__ import annotations

import asyncio
import cmath
import math
import time

import pytest

from cli.practice import steps_for
from deploy.client import free_port, start_server, wait_ready
from lti import store as lti
from mechanisms import load_preset

from .test_browser import keep, wait_idle
from lti.launch import CLAIM, DEEP

from .test_lti import INSTRUCTOR, Platform

pytestmark = pytest.mark.browser


@pytest.fixture(scope="module")
def served(tmp_path_factory):
    """The app served with a store and a tool key of its own, and a platform registered."""
    data = tmp_path_factory.mktemp("lti-data")
    env = {"MEHANIZMI_DATA": str(data), "MEHANIZMI_LTI_KEY": str(data / "lti" / "tool-key.pem")}
    platform = Platform()
    platform.register(f"sqlite:///{data / 'mehanizmi.db'}")
    port = free_port()
    log = open(data / "server.log", "w")
    server = start_server(port, log=log, env=env)
    try:
        asyncio.run(wait_ready(f"ws://127.0.0.1:{port}/_stcore/stream"))
        platform.tool_jwks = f"http://127.0.0.1:{port}/lti/jwks"
        yield f"http://127.0.0.1:{port}", platform
    finally:
        server.terminate()
        server.wait(timeout=10)
        log.close()
        platform.close()


def test_a_click_in_moodle_opens_practice_and_the_check_reaches_the_gradebook(served, browser, tmp_path):
    app_url, platform = served
    page = browser.new_page()
    page.set_viewport_size({"width": 1400, "height": 1000})
    page.goto(f"{app_url}/lti/login?iss={platform.issuer}&login_hint=u-1"
              f"&client_id={platform.client_id}")
    page.wait_for_url("**/velocity_plans?**", timeout=30_000)
    page.get_by_text("Korak 1 od").wait_for(timeout=30_000)  # practising, in the course's language
    wait_idle(page)
    assert "class=" in page.url and "student=" in page.url
    step = steps_for(load_preset("zbirka-3.1"), "plans")[0]
    box = page.locator(f".st-key-pr_plans_len_{step.id.replace('.', '-')} input")
    box.fill(f"{abs(complex(step.expected)):.4f}".replace(".", ","))
    angle = page.locator(f".st-key-pr_plans_ang_{step.id.replace('.', '-')} input")
    angle.fill(f"{math.degrees(cmath.phase(complex(step.expected))) % 360:.3f}".replace(".", ","))
    page.get_by_role("button", name="Proveri").click()
    page.locator("[data-testid='stAlertContentSuccess']").wait_for(timeout=30_000)
    shot = tmp_path / "lti-practice-sr.png"
    page.screenshot(path=str(shot))
    keep(shot)
    deadline = time.monotonic() + 30
    while not platform.scores and time.monotonic() < deadline:
        time.sleep(0.5)
    assert platform.scores, "no score reached the platform within 30 s"
    _, body, _, _ = platform.scores[-1]
    assert body["userId"] == "learner-1" and body["scoreGiven"] == 1
    assert body["scoreMaximum"] == len(steps_for(load_preset("zbirka-3.1"), "plans"))
    assert page.locator("[data-testid='stException']").count() == 0


def test_the_picker_s_methods_follow_the_task(served, browser):
    """Deep linking in chromium: the method list holds each task's methods with steps — a
    gear train offers Willis alone, a rotor balancing — and the picked pair is returned."""
    app_url, platform = served
    platform.claims = {CLAIM + "message_type": "LtiDeepLinkingRequest", CLAIM + "roles": [INSTRUCTOR],
                       DEEP + "deep_linking_settings": {"deep_link_return_url": platform.url("/deep-return")},
                       CLAIM + "launch_presentation": {"locale": "en"}}
    try:
        page = browser.new_page()
        page.goto(f"{app_url}/lti/login?iss={platform.issuer}&login_hint=u-1&client_id={platform.client_id}")
        page.get_by_text("What the student practises").wait_for(timeout=30_000)
        method = page.locator("select[name=method]")
        page.select_option("select[name=task]", "zbirka-6.1")
        assert method.locator("option").evaluate_all("o => o.map(x => x.value)") == ["willis"]
        page.select_option("select[name=task]", "zbirka-7.1")
        assert method.locator("option").evaluate_all("o => o.map(x => x.value)") == ["balance"]
        page.select_option("select[name=task]", "zbirka-3.1")
        values = method.locator("option").evaluate_all("o => o.map(x => x.value)")
        assert values == ["compass", "plans", "forces", "lever"] and method.input_value() == "plans"
    finally:
        platform.claims = {}
