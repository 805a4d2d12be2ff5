"""The app as an LTI 1.3 tool (issue 63), driven by a platform made here: its own RSA key,
JWKS, token and line-item endpoints on loopback. Login, launch (a learner to practice, an
instructor to the live view), a replay, a forged, an expired token, an unknown deployment,
deep linking, and a score posted after a stored check (and later, when the platform was
down) — on SQLite and PostgreSQL."""

from __future__ import annotations

import json
import threading
import time
import urllib.parse
import urllib.request
import uuid
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import jwt
import pytest
import sqlalchemy as sa
from cryptography.hazmat.primitives.asymmetric import rsa
from jwt.algorithms import RSAAlgorithm
from starlette.applications import Starlette
from starlette.testclient import TestClient

from classes import store
from classes.steps import steps_of
from lti import grades, keys
from lti import store as lti
from lti.launch import AGS, CLAIM, DEEP, LINEITEM_SCOPE
from lti.launch import _keys as launch_keys
from lti import routes
from lti.routes import ROUTES
from mechanisms import SceneError, load_preset, preset_ids
from methods.practice_steps import steps_for


LEARNER = "http://purl.imsglobal.org/vocab/lis/v2/membership#Learner"
INSTRUCTOR = "http://purl.imsglobal.org/vocab/lis/v2/membership#Instructor"


class Platform:
    """A Moodle's LTI side, as far as a tool sees it: it signs launches with its key, serves
    its JWKS, gives access tokens for a valid client assertion and takes scores."""

    def __init__(self):
        self.key = rsa.generate_private_key(public_exponent=65537, key_size=2048)
        self.issuer = f"https://moodle-{uuid.uuid4().hex[:8]}.example"
        self.client_id = uuid.uuid4().hex
        # its key's id, its own as a real platform's is: the tool keeps a platform's keys
        # by keyset URL and id, and a later test's platform may get a closed one's port
        self.kid = uuid.uuid4().hex[:8]
        self.scores: list[tuple[str, dict, str]] = []  # (path, body, authorization)
        self.assertions: list[dict] = []
        self.lineitems: list[dict] = []  # the container's line items (made by the tool's POST)
        self.claims: dict = {}  # what the next launches claim besides the defaults
        self.down = False
        self.tool_jwks: str | None = None  # the tool's public keyset URL (else its key here)
        self.jwks_html = False  # its key address answers a login page instead (issue 81)
        platform = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args) -> None:
                pass

            def _send(self, status: int, body: bytes, kind: str = "application/json") -> None:
                self.send_response(status)
                self.send_header("Content-Type", kind)
                self.send_header("Content-Length", str(len(body)))
                self.end_headers()
                self.wfile.write(body)

            def do_GET(self) -> None:
                if self.path.startswith("/auth"):  # as Moodle's auth.php: the launch, posted back
                    asked = dict(urllib.parse.parse_qsl(urllib.parse.urlsplit(self.path).query))
                    form = (f"<form method='post' action='{asked['redirect_uri']}'>"
                            f"<input type='hidden' name='id_token' value='{platform.token(asked['nonce'])}'>"
                            f"<input type='hidden' name='state' value='{asked['state']}'></form>"
                            "<script>document.forms[0].submit()</script>")
                    return self._send(200, form.encode(), "text/html")
                if self.path.startswith("/lineitems?"):  # the container, by resource link
                    asked = dict(urllib.parse.parse_qsl(urllib.parse.urlsplit(self.path).query))
                    return self._send(200, json.dumps([i for i in platform.lineitems if i.get(
                        "resourceLinkId") == asked.get("resource_link_id")]).encode())
                if platform.jwks_html:
                    return self._send(200, b"<html><body>Log in</body></html>", "text/html")
                key = json.loads(RSAAlgorithm.to_jwk(platform.key.public_key()))
                self._send(200, json.dumps({"keys": [{**key, "kid": platform.kid, "alg": "RS256"}]}).encode())

            def do_POST(self) -> None:
                body = self.rfile.read(int(self.headers["Content-Length"]))
                if platform.down:
                    return self._send(503, b"{}")
                if self.path == "/token":
                    form = dict(urllib.parse.parse_qsl(body.decode()))
                    tool_key = (jwt.PyJWKClient(platform.tool_jwks).get_signing_key_from_jwt(
                        form["client_assertion"]).key if platform.tool_jwks
                        else keys.private_key().public_key())  # as registered in Moodle
                    claims = jwt.decode(form["client_assertion"], tool_key,
                                        algorithms=["RS256"], audience=platform.url("/token"))
                    platform.assertions.append({**claims, "scope": form["scope"],
                                                "grant_type": form["grant_type"]})
                    return self._send(200, json.dumps({"access_token": "t-" + uuid.uuid4().hex,
                                                       "expires_in": 3600}).encode())
                if self.path == "/lineitems":  # a line item made in the container
                    item = {**json.loads(body), "id": platform.url(f"/lineitems/{len(platform.lineitems) + 90}/lineitem")}
                    platform.lineitems.append({**item, "kind": self.headers["Content-Type"]})
                    return self._send(201, json.dumps(item).encode())
                platform.scores.append((self.path, json.loads(body), self.headers["Authorization"],
                                        self.headers["Content-Type"]))
                self._send(200, b"{}")

        self.server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        threading.Thread(target=self.server.serve_forever, daemon=True).start()

    def url(self, path: str) -> str:
        return f"http://127.0.0.1:{self.server.server_port}{path}"

    def register(self, db: str, deployment: str = "d1") -> None:
        lti.add_platform(self.issuer, self.client_id, deployment, self.url("/auth"),
                         self.url("/token"), self.url("/jwks"), db)

    def token(self, nonce: str, key=None, exp: float | None = None, **claims) -> str:
        now = int(time.time())
        body = {"iss": self.issuer, "aud": self.client_id, "sub": "learner-1", "nonce": nonce,
                "iat": now, "exp": exp if exp is not None else now + 300,
                CLAIM + "deployment_id": "d1", CLAIM + "version": "1.3.0",
                CLAIM + "message_type": "LtiResourceLinkRequest", CLAIM + "roles": [LEARNER],
                CLAIM + "context": {"id": "course-7"}, CLAIM + "resource_link": {"id": "rl-1"},
                CLAIM + "custom": {"task": "zbirka-3.1", "method": "plans"},
                AGS: {"lineitem": self.url("/lineitems/5/lineitem?type_id=3"),
                      "scope": [grades.SCOPE]},
                CLAIM + "launch_presentation": {"locale": "sr", "document_target": "window"}}
        body.update(self.claims)
        body.update(claims)
        return jwt.encode(body, key or self.key, algorithm="RS256", headers={"kid": self.kid})

    def close(self) -> None:
        self.server.shutdown()


@pytest.fixture
def tool(url, tmp_path, monkeypatch):
    """The tool's routes on the store ``url``, with a key of its own, and a platform."""
    monkeypatch.setenv("MEHANIZMI_DATABASE_URL", url)
    monkeypatch.setenv("MEHANIZMI_LTI_KEY", str(tmp_path / "lti" / "tool-key.pem"))
    monkeypatch.setattr(grades, "_TOKENS", {})  # (platform ids repeat from one store to the next)
    # each test's platform is a new one, but its port may be an earlier test's: the tool's
    # keys, kept per key address for the process, would be that platform's, and PyJWT
    # fetches them again for an unknown key id only after a 30-s cooldown (a 502 in the suite)
    launch_keys.cache_clear()
    platform = Platform()
    platform.register(url)
    client = TestClient(Starlette(routes=ROUTES), base_url="https://tool.example")
    yield client, platform, url
    platform.close()


def login(client: TestClient, platform: Platform) -> dict:
    """The platform's login initiation: the tool's redirect, as query parameters."""
    answer = client.get("/lti/login", params={"iss": platform.issuer, "login_hint": "u-1",
                                              "client_id": platform.client_id,
                                              "lti_message_hint": "m-9"}, follow_redirects=False)
    assert answer.status_code == 302, answer.text
    target = urllib.parse.urlsplit(answer.headers["location"])
    assert target.geturl().startswith(platform.url("/auth"))
    return dict(urllib.parse.parse_qsl(target.query))


def launch(client: TestClient, platform: Platform, **claims):
    asked = login(client, platform)
    return client.post("/lti/launch", data={"id_token": platform.token(asked["nonce"], **claims),
                                             "state": asked["state"]}, follow_redirects=False)


def counts(db: str) -> tuple[int, int]:
    with store.engine(db).connect() as connection:
        return (connection.execute(sa.select(sa.func.count()).select_from(store.classes)).scalar(),
                connection.execute(sa.select(sa.func.count()).select_from(store.students)).scalar())


def test_the_login_redirects_to_the_platform_with_what_lti_asks(tool):
    client, platform, _ = tool
    asked = login(client, platform)
    assert {k: asked[k] for k in ("scope", "response_type", "response_mode", "prompt",
                                  "client_id", "redirect_uri", "login_hint", "lti_message_hint")} == {
        "scope": "openid", "response_type": "id_token", "response_mode": "form_post",
        "prompt": "none", "client_id": platform.client_id,
        "redirect_uri": "https://tool.example/lti/launch", "login_hint": "u-1",
        "lti_message_hint": "m-9"}
    assert len(asked["state"]) >= 32 and len(asked["nonce"]) >= 32 and asked["state"] != asked["nonce"]
    unknown = client.get("/lti/login", params={"iss": "https://other.example", "login_hint": "x"})
    assert unknown.status_code == 400 and "No platform is registered" in unknown.text


def test_a_learner_lands_in_practice_and_an_instructor_on_the_live_view(tool):
    client, platform, db = tool
    answer = launch(client, platform)
    assert answer.status_code == 303, answer.text
    where = urllib.parse.urlsplit(answer.headers["location"])
    query = dict(urllib.parse.parse_qsl(where.query))
    assert where.path == "/velocity_plans" and query["scene"] == "zbirka-3.1"
    assert query["lang"] == "sr"  # the platform's locale
    found = store.find(query["class"], db)
    assert (found.scene, found.method) == ("zbirka-3.1", "plans")
    assert store.student(found.code, query["student"], db)["nickname"] != "learner-1"  # no names
    again = urllib.parse.parse_qs(urllib.parse.urlsplit(launch(client, platform).headers["location"]).query)
    assert again["class"] == [found.code] and again["student"] == [query["student"]]  # the same seat
    teacher = launch(client, platform, sub="teacher-1", **{CLAIM + "roles": [INSTRUCTOR]})
    assert teacher.status_code == 303
    lecturer = dict(urllib.parse.parse_qsl(urllib.parse.urlsplit(teacher.headers["location"]).query))
    assert urllib.parse.urlsplit(teacher.headers["location"]).path == "/class"
    assert store.opened(lecturer["class"], lecturer["key"], db).code == found.code  # the platform vouched


@pytest.mark.parametrize("why, claims, status, said", [
    ("forged", {"key": rsa.generate_private_key(public_exponent=65537, key_size=2048)}, 401,
     "signature, issuer, audience or time"),
    ("expired", {"exp": time.time() - 3600}, 401, "signature, issuer, audience or time"),
    ("unknown deployment", {CLAIM + "deployment_id": "d-other"}, 400, "d-other"),
    ("another audience", {"aud": "someone-else"}, 401, "signature, issuer, audience or time"),
    ("LTI 1.1", {CLAIM + "version": "1.1"}, 401, "1.3.0"),
    ("custom as text", {CLAIM + "custom": "task=zbirka-3.1"}, 401, "custom"),
    ("presentation as text", {CLAIM + "launch_presentation": "sr"}, 401, "launch_presentation"),
    ("context as a list", {CLAIM + "context": ["course-7"]}, 401, "context"),
    ("a custom value as a list", {CLAIM + "custom": {"task": ["zbirka-3.1"]}}, 401, "custom"),
    ("roles as text", {CLAIM + "roles": LEARNER}, 401, "roles"),
])
def test_a_launch_that_cannot_be_trusted_is_refused_in_words_and_stores_nothing(tool, why, claims,
                                                                                 status, said):
    client, platform, db = tool
    before = counts(db)
    answer = launch(client, platform, **claims)
    assert answer.status_code == status, (why, answer.text)
    assert said in answer.text and "<p>" in answer.text, why  # in words, both languages
    assert "Signature verification failed" not in answer.text  # the tool's words, not a library's
    assert counts(db) == before


def test_a_tampered_launch_does_not_use_up_the_honest_one_s_state(tool):
    """The state is used up only by a token whose signature verified: a forged token sent
    first with the honest login's state leaves that state to the honest launch."""
    client, platform, _ = tool
    asked = login(client, platform)
    forger = rsa.generate_private_key(public_exponent=65537, key_size=2048)
    forged = client.post("/lti/launch", data={"id_token": platform.token(asked["nonce"], key=forger),
                                              "state": asked["state"]}, follow_redirects=False)
    assert forged.status_code == 401
    honest = client.post("/lti/launch", data={"id_token": platform.token(asked["nonce"]),
                                              "state": asked["state"]}, follow_redirects=False)
    assert honest.status_code == 303


@pytest.mark.parametrize("path", ["/lti/launch", "/lti/deeplink"])
def test_a_launch_address_opened_as_a_page_is_said_in_words(tool, path):
    client, _, _ = tool
    answer = client.get(path)
    assert answer.status_code == 405 and "POST" in answer.text and "<p>" in answer.text


BIG = {"a 5 MB token": dict(data={"id_token": "x" * 5_000_000, "state": "s"}),
       "30 MB said by its length": dict(content=b"", headers={"content-length": str(30 * 2**20)}),
       "20,000 fields": dict(data={f"f{i}": "1" for i in range(20_000)}),
       "a multipart without a boundary": dict(content=b"id_token=1",
                                              headers={"content-type": "multipart/form-data"}),
       "a file": dict(files={"id_token": ("t.txt", b"x")}, data={"state": "s"}),
       "a length that is no number": dict(content=b"a=1", headers={"content-length": "-1"})}


@pytest.mark.parametrize("path", ["/lti/login", "/lti/launch", "/lti/deeplink"])
@pytest.mark.parametrize("sent", BIG, ids=list(BIG))
def test_an_oversized_or_broken_form_is_refused_in_both_languages(tool, path, sent):
    """Every form the tool reads, read within bounds: refused in the tool's words (Serbian
    and English), never Starlette's plain text, and nothing stored."""
    client, _, db = tool
    before = counts(db)
    answer = client.post(path, **BIG[sent])
    assert answer.status_code in (400, 413) and answer.text.count("<p>") == 2, answer.text[:200]
    assert "obrazac" in answer.text and "form" in answer.text
    assert counts(db) == before


def test_a_login_stores_nothing_and_an_honest_launch_survives_2000_strangers(tool):
    """Issue 81: ~2,000 strangers' logins once each stored a state and evicted the honest
    ones (a class locked out). A login's state is now a short value the tool signs, and
    only a launch that passed every check leaves a row (to refuse its replay)."""
    client, platform, db = tool
    honest = login(client, platform)
    rows = lambda: _rows(db, lti.states)  # noqa: E731
    before = rows()
    for k in range(2000):
        client.get("/lti/login", params={"iss": platform.issuer, "login_hint": f"x{k}"},
                   follow_redirects=False)
    assert rows() == before  # no table grew
    answer = client.post("/lti/launch", data={"id_token": platform.token(honest["nonce"]),
                                              "state": honest["state"]}, follow_redirects=False)
    assert answer.status_code == 303 and rows() == before + 1


def _rows(db: str, table) -> int:
    with store.engine(db).connect() as connection:
        return connection.execute(sa.select(sa.func.count()).select_from(table)).scalar()


def test_another_login_s_nonce_leaves_the_state_to_its_honest_launch(tool):
    """A correctly signed token carrying one login's nonce, posted with a second login's
    state, once used that state up: the honest launch then failed."""
    client, platform, _ = tool
    first, second = login(client, platform), login(client, platform)
    mixed = client.post("/lti/launch", data={"id_token": platform.token(first["nonce"]),
                                             "state": second["state"]}, follow_redirects=False)
    assert mixed.status_code == 401
    honest = client.post("/lti/launch", data={"id_token": platform.token(second["nonce"]),
                                              "state": second["state"]}, follow_redirects=False)
    assert honest.status_code == 303


NUL, LONG_ID = "a\x00b", "x" * 300
BAD_IDS = {  # what a launch claims → the identifier it names
    "sub with NUL": ({"sub": NUL}, "sub"), "empty sub": ({"sub": ""}, "sub"),
    "sub of 150 kB": ({"sub": "s" * 150_000}, "sub"), "sub of 300": ({"sub": LONG_ID}, "sub"),
    "context with NUL": ({CLAIM + "context": {"id": NUL}}, "context.id"),
    "context of 300": ({CLAIM + "context": {"id": LONG_ID}}, "context.id"),
    "empty context": ({CLAIM + "context": {"id": ""}}, "context.id"),
    "resource link with NUL": ({CLAIM + "resource_link": {"id": NUL}}, "resource_link.id"),
    "resource link of 300": ({CLAIM + "resource_link": {"id": LONG_ID}}, "resource_link.id"),
    "deployment with NUL": ({CLAIM + "deployment_id": NUL}, "deployment_id"),
}


@pytest.mark.parametrize("name", list(BAD_IDS))
def test_an_identifier_with_nul_empty_or_too_long_is_refused_in_words_storing_nothing(tool, name):
    """Issue 81: a NUL in an identifier was a 500 on PostgreSQL (a class and a link left
    behind for the context); an empty or a 150-kB ``sub`` was taken. One rule refuses them
    all in words (lti.launch.identifier), on either store, before anything is stored."""
    client, platform, db = tool
    claims, field = BAD_IDS[name]
    before = (counts(db), _rows(db, lti.links), _rows(db, lti.learners), _rows(db, lti.states))
    answer = launch(client, platform, **claims)
    assert answer.status_code == 400 and field in answer.text and "<p>" in answer.text, answer.text[:300]
    assert (counts(db), _rows(db, lti.links), _rows(db, lti.learners), _rows(db, lti.states)) == before


@pytest.mark.parametrize("field", ["iss", "client_id", "login_hint", "lti_message_hint"])
@pytest.mark.parametrize("value", [NUL, "y" * 3000])
def test_a_login_with_a_bad_identifier_is_refused_in_words(tool, field, value):
    client, platform, _ = tool
    given = {"iss": platform.issuer, "login_hint": "u-1", "client_id": platform.client_id,
             field: value}
    answer = client.get("/lti/login", params=given, follow_redirects=False)
    assert answer.status_code == 400 and field in answer.text and answer.text.count("<p>") == 2


def test_a_state_with_nul_or_not_the_tool_s_is_refused_in_words(tool):
    client, platform, _ = tool
    asked = login(client, platform)
    for state in (NUL, "x" * 3000, asked["state"][:-6] + "AAAAAA", keys.sign({"use": "other"})):
        answer = client.post("/lti/launch", data={"id_token": platform.token(asked["nonce"]),
                                                  "state": state}, follow_redirects=False)
        assert answer.status_code in (400, 401) and "<p>" in answer.text, state[:20]


def test_a_platform_whose_key_address_answers_a_page_is_refused_in_words(tool, caplog):
    """Issue 81: a JWKS address answering an HTML page with 200 (a login wall) was a 500
    on every launch. Now 502, in words, and the log says why."""
    client, platform, db = tool
    platform.jwks_html = True
    answer = launch(client, platform)
    assert answer.status_code == 502 and "keys" in answer.text and answer.text.count("<p>") == 2
    assert any("not a JSON key set" in r.getMessage() for r in caplog.records)


def test_a_javascript_return_address_never_becomes_a_form_s_action(tool):
    client, platform, _ = tool
    answer = launch(client, platform, sub="teacher-1", **{
        CLAIM + "message_type": "LtiDeepLinkingRequest", CLAIM + "roles": [INSTRUCTOR],
        DEEP + "deep_linking_settings": {"deep_link_return_url": "javascript:alert(document.cookie)"}})
    assert answer.status_code == 400 and "<form" not in answer.text
    assert "deep_link_return_url" in answer.text and "javascript" not in answer.text


@pytest.mark.parametrize("address", ["javascript:alert(1)", "file:///etc/passwd", "ftp://x/y",
                                     "moodle.example/auth", ""])
def test_lti_platform_add_refuses_an_address_that_is_not_http(address, tmp_path, monkeypatch):
    from .test_cli import run

    monkeypatch.setenv("MEHANIZMI_DATABASE_URL", f"sqlite:///{tmp_path / 'lti.db'}")
    done = run("lti", "platform", "add", "--issuer", "https://m.example", "--client-id", "c",
               "--deployment", "1", "--auth-url", "https://m.example/auth", "--token-url",
               "https://m.example/token", "--jwks-url", address)
    assert done.returncode == 2 and "--jwks-url" in done.stderr and "http" in done.stderr
    assert len(done.stderr.strip().splitlines()) == 1


def test_an_unknown_lti_address_or_method_is_said_in_words(tool):
    client, _, _ = tool
    for method, path, status in (("GET", "/lti/unknown", 404), ("POST", "/lti/x/y", 404),
                                 ("OPTIONS", "/lti/launch", 405), ("PROPFIND", "/lti/login", 405),
                                 ("FOO", "/lti/launch", 405)):
        answer = client.request(method, path)
        assert answer.status_code == status and answer.text.count("<p>") == 2, (method, path)


def test_the_address_users_reached_behind_a_proxy_keeps_its_port(tool):
    client, platform, _ = tool
    answer = client.get("/lti/login", params={"iss": platform.issuer, "login_hint": "u-1"},
                        headers={"X-Forwarded-Host": "tool.example:8443",
                                 "X-Forwarded-Proto": "https"}, follow_redirects=False)
    asked = dict(urllib.parse.parse_qsl(urllib.parse.urlsplit(answer.headers["location"]).query))
    assert asked["redirect_uri"] == "https://tool.example:8443/lti/launch"


def test_a_checked_launch_s_refusal_is_in_its_language_and_quotes_once(tool):
    """Issue 81: a 150-kB custom task was echoed twice (both languages) in full; a checked
    launch knows its user's language, and a sent value is cut to 60 characters."""
    client, platform, _ = tool
    task = "t" * 150_000
    answer = launch(client, platform, **{CLAIM + "custom": {"task": task, "method": "plans"}})
    assert answer.status_code == 400 and answer.text.count("<p>") == 1  # Serbian alone (locale sr)
    assert answer.text.count("t" * 60) == 1 and "t" * 61 not in answer.text


@pytest.mark.parametrize("method, path, status", [("PUT", "/lti/login", 405), ("DELETE", "/lti/launch", 405),
                                                  ("GET", "/lti/too-large", 413)])
def test_every_other_answer_of_the_routes_is_in_words(tool, method, path, status):
    client, _, _ = tool
    answer = client.request(method, path)
    assert answer.status_code == status and answer.text.count("<p>") == 2


def test_a_replayed_launch_is_refused(tool):
    client, platform, db = tool
    asked = login(client, platform)
    form = {"id_token": platform.token(asked["nonce"]), "state": asked["state"]}
    assert client.post("/lti/launch", data=form, follow_redirects=False).status_code == 303
    before = counts(db)
    replay = client.post("/lti/launch", data=form, follow_redirects=False)
    assert replay.status_code == 401 and "used already" in replay.text
    assert counts(db) == before
    other = login(client, platform)  # a fresh state with another login's nonce
    mixed = client.post("/lti/launch", data={"id_token": platform.token(asked["nonce"]),
                                             "state": other["state"]}, follow_redirects=False)
    assert mixed.status_code == 401 and "not made for this login" in mixed.text


def test_a_stored_check_is_scored_at_the_platform_and_a_platform_down_gets_it_later(tool, monkeypatch):
    client, platform, db = tool
    query = dict(urllib.parse.parse_qsl(urllib.parse.urlsplit(
        launch(client, platform).headers["location"]).query))
    code, token = query["class"], query["student"]
    steps = steps_of(store.find(code, db))
    assert grades.send_due(db) == 0  # nothing checked yet: nothing to send
    store.record(code, token, steps[0].id, 0.0, "wrong", store.new_check(), url=db)
    store.record(code, token, steps[0].id, 1.0, "ok", store.new_check(), url=db)
    assert grades.send_due(db) == 1
    path, body, authorization, kind = platform.scores[-1]
    assert path == "/lineitems/5/lineitem/scores?type_id=3" and kind == grades.SCORE_TYPE
    assert authorization.startswith("Bearer t-")
    assert {k: body[k] for k in ("userId", "scoreGiven", "scoreMaximum", "activityProgress",
                                 "gradingProgress")} == {
        "userId": "learner-1", "scoreGiven": 1, "scoreMaximum": len(steps),
        "activityProgress": "InProgress", "gradingProgress": "FullyGraded"}
    (assertion,) = platform.assertions  # one token, kept for the next score
    assert assertion["iss"] == assertion["sub"] == platform.client_id
    assert assertion["jti"] and assertion["grant_type"] == "client_credentials"
    assert grades.send_due(db) == 0  # sent once
    platform.down = True
    monkeypatch.setattr(grades, "EVERY", 0.0)  # (tried again at once here)
    store.record(code, token, steps[1].id, None, store.REVEALED, store.new_check(), url=db)
    assert grades.send_due(db) == 0 and len(platform.scores) == 1  # down: kept in the store
    platform.down = False
    assert grades.send_due(db) == 1
    assert platform.scores[-1][1]["scoreGiven"] == 1  # a step shown is not a step right
    assert len(platform.assertions) == 1


def test_an_activity_added_by_hand_gets_one_line_item_and_its_grades(tool):
    """A launch whose AGS claim names only the container (an activity typed by hand, with
    task= and method=, no deep linking): the tool makes one line item for the link — not
    one per learner, per process or per pass — and the scores go there."""
    client, platform, db = tool
    only_container = {AGS: {"lineitems": platform.url("/lineitems"),
                            "scope": [grades.SCOPE, LINEITEM_SCOPE]}}
    query = dict(urllib.parse.parse_qsl(urllib.parse.urlsplit(
        launch(client, platform, **only_container).headers["location"]).query))
    launch(client, platform, sub="learner-2", **only_container)
    code, token = query["class"], query["student"]
    steps = steps_of(store.find(code, db))
    assert grades.make_lineitems(db) == 1 and grades.make_lineitems(db) == 0
    (item,) = platform.lineitems
    assert item["resourceLinkId"] == "rl-1" and item["scoreMaximum"] == len(steps)
    assert item["label"].startswith("Plan") and "zbirka-3.1" in item["label"] and item["kind"] == grades.LINEITEM_TYPE
    assert {a["scope"] for a in platform.assertions} == {LINEITEM_SCOPE}
    store.record(code, token, steps[0].id, 1.0, "ok", store.new_check(), url=db)
    assert grades.send_due(db) == 1
    assert platform.scores[-1][0] == "/lineitems/90/lineitem/scores"
    assert platform.scores[-1][1]["scoreGiven"] == 1
    with store.engine(db).begin() as connection:  # made already (another tool's copy): found, not made again
        connection.execute(lti.links.update().values(lineitem=None, asked=None))
    assert grades.make_lineitems(db) == 1 and len(platform.lineitems) == 1


def test_deep_linking_returns_a_signed_resource_link_with_a_line_item(tool):
    client, platform, _ = tool
    answer = launch(client, platform, sub="teacher-1", **{
        CLAIM + "message_type": "LtiDeepLinkingRequest", CLAIM + "roles": [INSTRUCTOR],
        DEEP + "deep_linking_settings": {"deep_link_return_url": platform.url("/deep-return"),
                                         "data": "opaque-7"}})
    assert answer.status_code == 200 and "zbirka-3.1" in answer.text
    context = answer.text.split("name='context' value='")[1].split("'")[0]
    picked = client.post("/lti/deeplink", data={"context": context, "task": "zbirka-3.1",
                                                "method": "plans"})
    assert picked.status_code == 200 and platform.url("/deep-return") in picked.text
    said = picked.text.split("name='JWT' value='")[1].split("'")[0]
    claims = jwt.decode(said, keys.private_key().public_key(), algorithms=["RS256"],
                        audience=platform.issuer)
    assert claims["iss"] == platform.client_id and claims[CLAIM + "deployment_id"] == "d1"
    assert claims[CLAIM + "message_type"] == "LtiDeepLinkingResponse"
    assert claims[DEEP + "data"] == "opaque-7"
    (item,) = claims[DEEP + "content_items"]
    assert item["type"] == "ltiResourceLink" and item["custom"] == {"task": "zbirka-3.1", "method": "plans"}
    assert item["url"] == "https://tool.example/lti/launch" and item["lineItem"]["scoreMaximum"] > 0
    tampered = context[:-4] + ("AAAA" if not context.endswith("AAAA") else "BBBB")
    assert client.post("/lti/deeplink", data={"context": tampered, "task": "zbirka-3.1",
                                              "method": "plans"}).status_code == 400
    learner = launch(client, platform, **{CLAIM + "message_type": "LtiDeepLinkingRequest"})
    assert learner.status_code == 403


def test_the_picker_offers_only_pairs_that_have_steps(tool):
    """Each task's methods in the picker are those with steps there (a gear train: Willis
    alone); a pair forced into the form anyway is refused with advice for the picker."""
    client, platform, _ = tool
    answer = launch(client, platform, sub="teacher-1", **{
        CLAIM + "message_type": "LtiDeepLinkingRequest", CLAIM + "roles": [INSTRUCTOR],
        DEEP + "deep_linking_settings": {"deep_link_return_url": platform.url("/deep-return")}})
    offered = json.loads(answer.text.split("const pairs=")[1].split(",names=")[0])
    assert set(offered) == {t for t in preset_ids() if routes.pairs()[t]}
    for task, methods in offered.items():
        scene = load_preset(task)
        for method in store.METHODS:
            try:
                has = bool(steps_for(scene, method))
            except SceneError:
                has = False
            assert (method in methods) == has, (task, method)
    assert offered["zbirka-6.1"] == ["willis"] and offered["zbirka-7.1"] == ["balance"]
    context = answer.text.split("name='context' value='")[1].split("'")[0]
    forced = client.post("/lti/deeplink", data={"context": context, "task": "zbirka-6.1",
                                                "method": "plans"})
    assert forced.status_code == 400 and "izaberite drugu metodu" in forced.text  # (its locale's)
    assert forced.text.count("<p>") == 1 and "Planovi" in forced.text  # the method named in Serbian
    assert "vratite se" in forced.text and "Traceback" not in forced.text


def test_a_link_without_a_usable_task_is_refused_in_words(tool):
    client, platform, db = tool
    before = counts(db)
    answer = launch(client, platform, **{CLAIM + "custom": {"task": "zbirka-9.9", "method": "plans"}})
    assert answer.status_code == 400 and "zbirka-9.9" in answer.text
    assert "nijedan zadatak" in answer.text and "known presets" not in answer.text  # (the tool's words)
    answer = launch(client, platform, **{CLAIM + "custom": {"task": "zbirka-6.1", "method": "plans"}})
    assert answer.status_code == 400 and "nema koraka" in answer.text and "scene" not in answer.text
    answer = launch(client, platform, **{CLAIM + "custom": {"task": "zbirka-3.1", "method": "walk"}})
    assert answer.status_code == 400 and "walk" in answer.text
    assert counts(db) == before


@pytest.mark.server
def test_the_served_app_publishes_its_key_and_refuses_an_unknown_platform(app_url):
    """Through the README's start command (scripts/serve.py asgi.py: st.App with the routes)."""
    with urllib.request.urlopen(f"{app_url}/lti/jwks", timeout=10) as answer:
        (key,) = json.load(answer)["keys"]
    assert key["kty"] == "RSA" and key["alg"] == "RS256" and key["kid"] and "d" not in key
    with pytest.raises(urllib.error.HTTPError) as refused:
        urllib.request.urlopen(f"{app_url}/lti/login?iss=https://nobody.example&login_hint=x",
                               timeout=10)
    assert refused.value.code == 400 and "No platform is registered" in refused.value.read().decode()
    for method, path, status in (("GET", "/lti/unknown", 404), ("OPTIONS", "/lti/launch", 405)):
        with pytest.raises(urllib.error.HTTPError) as refused:  # not the app's page with 200
            urllib.request.urlopen(urllib.request.Request(f"{app_url}{path}", method=method), timeout=10)
        assert refused.value.code == status and refused.value.read().decode().count("<p>") == 2


@pytest.mark.server
def test_processes_starting_together_make_one_tool_key(tmp_path):
    """deploy/start.sh's processes ask for the key at once: one key, whole, mode 600."""
    import multiprocessing

    path = tmp_path / "lti" / "tool-key.pem"
    with multiprocessing.get_context("spawn").Pool(4) as pool:
        made = pool.map(_key_of, [str(path)] * 8)
    assert len(set(made)) == 1
    assert oct(path.stat().st_mode & 0o777) == "0o600"
    assert oct(path.parent.stat().st_mode & 0o777) == "0o700"
    assert not [p for p in path.parent.iterdir() if p != path]  # nothing left aside


def _key_of(path: str) -> str:
    from pathlib import Path

    from lti.keys import _private

    key = _private(Path(path))
    return str(key.private_numbers().d)


def test_a_hand_in_from_the_command_line_is_scored_too(tool, tmp_path):
    """``practice … --class … --student …`` stores checks as a page does: the learner's score
    follows them to the platform."""
    from cli import main

    client, platform, db = tool
    query = dict(urllib.parse.parse_qsl(urllib.parse.urlsplit(
        launch(client, platform).headers["location"]).query))
    steps = steps_of(store.find(query["class"], db))
    answers = tmp_path / "answers.json"
    z = [complex(s.expected) for s in steps[:2]]
    answers.write_text(json.dumps({"answers": {steps[0].id: [z[0].real, z[0].imag],
                                               steps[1].id: [-z[1].real, -z[1].imag]}}))
    assert main(["practice", "--method", "plans", "--answers", str(answers),
                 "--class", query["class"], "--student", query["student"]]) == 0
    assert grades.send_due(db) == 1
    assert platform.scores[-1][1]["scoreGiven"] == 1  # the first right, the second reversed


def test_a_test_activity_sends_its_grades_when_its_teacher_closes_it(tool):
    """Picked as a test in deep linking (custom test=1): its class is a test, a check is
    stored but no grade goes while it is open (a gradebook shows students their grade);
    closing it sends every learner's score, as the one fold counts it."""
    client, platform, db = tool
    answer = launch(client, platform, sub="teacher-1", **{
        CLAIM + "message_type": "LtiDeepLinkingRequest", CLAIM + "roles": [INSTRUCTOR],
        DEEP + "deep_linking_settings": {"deep_link_return_url": platform.url("/deep-return")}})
    assert "name='test'" in answer.text
    context = answer.text.split("name='context' value='")[1].split("'")[0]
    picked = client.post("/lti/deeplink", data={"context": context, "task": "zbirka-3.1",
                                                "method": "plans", "test": "1"})
    said = picked.text.split("name='JWT' value='")[1].split("'")[0]
    (item,) = jwt.decode(said, keys.private_key().public_key(), algorithms=["RS256"],
                         audience=platform.issuer)[DEEP + "content_items"]
    assert item["custom"] == {"task": "zbirka-3.1", "method": "plans", "test": "1"}
    query = dict(urllib.parse.parse_qsl(urllib.parse.urlsplit(launch(
        client, platform, **{CLAIM + "custom": item["custom"]}).headers["location"]).query))
    code, token = query["class"], query["student"]
    found = store.find(code, db)
    assert found.test and found.closed is None
    first = steps_of(found)[0]
    store.record(code, token, first.id, 1.0, "ok", store.new_check(), url=db)
    assert grades.send_due(db) == 0 and not platform.scores
    with pytest.raises(store.OneTry):  # one try a step
        store.record(code, token, first.id, 2.0, "ok", store.new_check(), url=db)
    registered = lti.platform(platform.issuer, platform.client_id, db)
    key = keys.lecturer_key(f"{registered.id}|course-7|rl-1")  # (the instructor's link carries it)
    store.close(code, key, db)
    grades.rescore(code, db)
    assert grades.send_due(db) == 1 and platform.scores[-1][1]["scoreGiven"] == 1
    # closed (issue 82): a late try stores nothing, a new learner gets no seat, in words;
    # the learner who took the test still opens it, and the grade sent stays the same
    with pytest.raises(store.TestClosed):
        store.record(code, token, steps_of(found)[1].id, 1.0, "ok", store.new_check(), url=db)
    students = counts(db)[1]
    late = launch(client, platform, sub="learner-late", **{CLAIM + "custom": item["custom"]})
    assert late.status_code == 400 and "zatvoren u" in late.text and late.text.count("<p>") == 1
    assert counts(db)[1] == students
    again = launch(client, platform, **{CLAIM + "custom": item["custom"]})
    assert again.status_code == 303
    grades.rescore(code, db)  # scored again after the late tries: the same grade
    grades.send_due(db)
    assert platform.scores[-1][1]["scoreGiven"] == 1
