"""Grades back to the platform (LTI Assignment and Grade Services): a learner whose launch
carried a line item gets a score after every stored check — from a page or from
``practice --class … --student …`` alike, as both only store checks.

The queue is the store itself: a learner is due while the newest check stored for them is
newer than the one last sent (``lti_learners.scored``). ``send_due`` sends each due score
and marks it sent only once the platform took it; a platform that is down is tried again
later, less often each time (never more than five minutes apart), and nothing is lost or
waited on by a student's page. ``worker`` runs it every few seconds beside the app
(``asgi.py``).

A score: ``scoreGiven`` the steps done right (not shown by "Show it"), ``scoreMaximum`` the
steps, ``activityProgress`` and ``gradingProgress`` as AGS names them. The access token is
got with ``client_credentials`` and a client assertion the tool signs (RFC 7523), and kept
until it expires.
"""

from __future__ import annotations

import json
import logging
import threading
import time
import urllib.parse
import urllib.request
from datetime import UTC, datetime, timedelta

import sqlalchemy as sa

from classes import store as classes
from classes import summary
from classes.steps import steps_of
from classes.store import ClassError, engine

from . import keys
from .launch import LINEITEM_SCOPE
from .store import Platform, learners, links, platform_by_id

SCOPE = "https://purl.imsglobal.org/spec/lti-ags/scope/score"
SCORE_TYPE = "application/vnd.ims.lis.v1.score+json"
LINEITEM_TYPE = "application/vnd.ims.lis.v2.lineitem+json"
CONTAINER_TYPE = "application/vnd.ims.lis.v2.lineitemcontainer+json"
EVERY = 5.0  # s between two looks for due scores (a score reaches the platform within 30 s)
LONGEST = 300  # s: the longest wait before a down platform is tried again
TIMEOUT = 10  # s a platform may take to answer
_LOG = logging.getLogger(__name__)
_TOKENS: dict[tuple[int, str], tuple[str, float]] = {}  # (platform, scope) → token, expiry
_LOCK = threading.Lock()


def token(found: Platform, scope: str = SCOPE) -> str:
    """An access token for ``scope``: asked for with a signed client assertion, kept until a
    minute before it expires."""
    with _LOCK:
        kept = _TOKENS.get((found.id, scope))
        if kept and kept[1] > time.time() + 60:
            return kept[0]
    assertion = keys.sign({"iss": found.client_id, "sub": found.client_id,
                           "aud": found.token_url})
    body = urllib.parse.urlencode({
        "grant_type": "client_credentials", "scope": scope,
        "client_assertion_type": "urn:ietf:params:oauth:client-assertion-type:jwt-bearer",
        "client_assertion": assertion}).encode()
    request = urllib.request.Request(found.token_url, body, method="POST",
                                     headers={"Content-Type": "application/x-www-form-urlencoded",
                                              "Accept": "application/json"})
    with urllib.request.urlopen(request, timeout=TIMEOUT) as answer:
        given = json.load(answer)
    with _LOCK:
        _TOKENS[(found.id, scope)] = (given["access_token"],
                                      time.time() + float(given.get("expires_in", 3600)))
    return given["access_token"]


def score(code: str, student: str, sub: str, url: str | None = None) -> dict | None:
    """The learner's score as the store has it now: the steps right (first or after hints,
    not shown) as the one fold says (classes.summary.report, which ``class summary`` prints).
    None while the class is a test not yet closed: a gradebook shows students their grade,
    which would be the verdicts the test keeps until then (``rescore`` sends them after)."""
    found = classes.find(code, url)
    if not found.verdicts_shown:
        return None
    who = classes.student(code, student, url)
    steps = [s.id for s in steps_of(found, who["variant"])]
    (said,) = summary.report(classes.tries(code, student, url), steps, found.rules,
                             {student: who["nickname"]})
    done = said["score"]["done"] >= len(steps)
    return {"userId": sub, "scoreGiven": said["score"]["right"], "scoreMaximum": len(steps),
            "activityProgress": "Completed" if done else "InProgress",
            "gradingProgress": "FullyGraded",
            "timestamp": datetime.now(UTC).isoformat(timespec="milliseconds")}


def post(found: Platform, lineitem: str, body: dict) -> None:
    """One score to ``lineitem``'s scores endpoint (an error if the platform refuses it)."""
    path, _, query = lineitem.partition("?")
    target = path.rstrip("/") + "/scores" + (f"?{query}" if query else "")
    request = urllib.request.Request(target, json.dumps(body).encode(), method="POST", headers={
        "Content-Type": SCORE_TYPE, "Authorization": f"Bearer {token(found)}"})
    with urllib.request.urlopen(request, timeout=TIMEOUT):
        pass


def due(url: str | None = None) -> list:
    """Learners with a check stored since their last score (and not waiting after a failure)."""
    newest = (sa.select(sa.func.max(classes.checks.c.id))
              .where(classes.checks.c.student == learners.c.student).scalar_subquery())
    now = datetime.now(UTC)
    target = sa.func.coalesce(learners.c.lineitem, links.c.lineitem)  # its own, or one made
    query = (sa.select(learners, links.c.platform_id, links.c.class_code, newest.label("newest"),
                       target.label("target"))
             .join(links, links.c.id == learners.c.link_id)
             .where(target.is_not(None), newest > learners.c.scored,
                    sa.or_(learners.c.due.is_(None), learners.c.due <= now)))
    with engine(url).connect() as db:
        return db.execute(query).all()


def send_due(url: str | None = None) -> int:
    """Send every due score; how many the platforms took."""
    sent = 0
    for row in due(url):
        try:
            body = score(row.class_code, row.student, row.sub, url)
            if body is not None:  # (None: a test not closed; its close sends them all)
                post(platform_by_id(row.platform_id, url), row.target, body)
        except ClassError:  # the class went: nothing more to send for it
            _mark(row.id, {"scored": row.newest}, url)
        except Exception as exc:  # the platform down or refusing: later, less often
            wait = min(LONGEST, EVERY * 2 ** min(row.failures, 8))
            _LOG.warning("score for learner %s not taken (%s); again in %.0f s", row.id, exc, wait)
            _mark(row.id, {"failures": row.failures + 1,
                           "due": datetime.now(UTC) + timedelta(seconds=wait)}, url)
        else:
            _mark(row.id, {"scored": row.newest, "failures": 0, "due": None}, url)
            sent += body is not None
    return sent


def make_lineitems(url: str | None = None) -> int:
    """A line item for each link launched with only the platform's container (an activity
    added by hand): the one the platform already has for the link, else one made (POST);
    how many were found or made. One process asks for a link at a time (``asked``, taken in
    one update), and a platform that refused is asked again a minute later."""
    made = 0
    now = datetime.now(UTC)
    free = sa.and_(links.c.lineitems.is_not(None), links.c.lineitem.is_(None),
                   sa.or_(links.c.asked.is_(None), links.c.asked < now - timedelta(seconds=60)))
    with engine(url).connect() as db:
        wanting = db.execute(sa.select(links).where(free)).all()
    for row in wanting:
        with engine(url).begin() as db:  # (another process may have taken it meanwhile)
            if db.execute(links.update().where(links.c.id == row.id, free).values(asked=now)).rowcount != 1:
                continue
        try:
            item = _lineitem(platform_by_id(row.platform_id, url), row, url)
        except Exception as exc:  # the platform down or refusing: a minute later
            _LOG.warning("no line item made for link %s (%s); again in a minute", row.id, exc)
            continue
        with engine(url).begin() as db:
            db.execute(links.update().where(links.c.id == row.id, links.c.lineitems == row.lineitems)
                       .values(lineitem=item))
        made += 1
    return made


def _lineitem(found: Platform, row, url: str | None) -> str:
    """The URL of the link's line item in its container: the platform's for this resource
    link, or one made with the activity's label and its steps as the maximum."""
    path, _, query = row.lineitems.partition("?")
    asked = urllib.parse.urlencode({"resource_link_id": row.resource_link_id})
    headers = {"Authorization": f"Bearer {token(found, LINEITEM_SCOPE)}"}
    listed = urllib.request.Request(f"{path}?{query + '&' if query else ''}{asked}",
                                    headers={**headers, "Accept": CONTAINER_TYPE})
    with urllib.request.urlopen(listed, timeout=TIMEOUT) as answer:
        items = json.load(answer)
    mine = [i for i in items if isinstance(i, dict) and i.get("resourceLinkId") == row.resource_link_id
            and isinstance(i.get("id"), str)]
    if mine:
        return mine[0]["id"]
    maximum = len(steps_of(classes.find(row.class_code, url)))
    body = {"scoreMaximum": maximum, "label": row.label or row.task, "resourceLinkId": row.resource_link_id,
            "tag": "mehanizmi"}
    made = urllib.request.Request(row.lineitems, json.dumps(body).encode(), method="POST",
                                  headers={**headers, "Content-Type": LINEITEM_TYPE,
                                           "Accept": LINEITEM_TYPE})
    with urllib.request.urlopen(made, timeout=TIMEOUT) as answer:
        return str(json.load(answer)["id"])


def close_test(code: str, key: str, url: str | None = None) -> classes.Class:
    """A test closed by its lecturer (``class close``, the live view's button): its students
    see their verdicts, and its Moodle learners' scores go (``rescore``)."""
    found = classes.close(code, key, url)
    if found.test:
        rescore(found.code, url)
    return found


def rescore(code: str, url: str | None = None) -> None:
    """Every learner of the class ``code`` due again (a test just closed: its scores go)."""
    ids = sa.select(links.c.id).where(links.c.class_code == code).scalar_subquery()
    with engine(url).begin() as db:
        db.execute(learners.update().where(learners.c.link_id.in_(ids)).values(scored=0, due=None))


def _mark(learner: int, values: dict, url: str | None) -> None:
    with engine(url).begin() as db:
        db.execute(learners.update().where(learners.c.id == learner).values(**values))


def worker(stop: threading.Event, url: str | None = None, every: float = EVERY) -> None:
    """Send due scores every ``every`` seconds until ``stop`` is set (a thread of the server)."""
    while not stop.wait(every):
        try:
            make_lineitems(url)
            send_due(url)
        except Exception:  # the store down: the scores wait in it
            _LOG.exception("sending scores")
