"""What the tool keeps (migration 0004, in the class store): the platforms registered and
their deployments, the login states of the launches that passed (a replay's guard; a login
itself stores nothing), the resource links — each a class — and their learners, a
platform's pseudonymous ``sub`` each, with what was last sent to the platform's gradebook.
No name or e-mail: a launch's other claims are not stored.
"""

from __future__ import annotations

import secrets
import urllib.parse
from dataclasses import dataclass
from datetime import UTC, datetime, timedelta

import jwt
import sqlalchemy as sa

from classes import store
from classes.store import ClassError, engine
from mechanisms.messages import Text

from . import keys

STATE_LIFETIME = timedelta(minutes=10)  # a login's state and nonce, until the launch uses them
STATE_USE = "lti-login"  # what a state the tool signs is for (no other signed value passes)
LINK_DAYS = 400  # a class a link made lives a course's year (the store's default is 30 days)

meta = sa.MetaData()
platforms = sa.Table(
    "lti_platforms", meta,
    sa.Column("id", sa.Integer, primary_key=True), sa.Column("issuer", sa.Text),
    sa.Column("client_id", sa.Text), sa.Column("auth_url", sa.Text),
    sa.Column("token_url", sa.Text), sa.Column("jwks_url", sa.Text),
    sa.Column("created", sa.DateTime(timezone=True)))
deployments = sa.Table(
    "lti_deployments", meta,
    sa.Column("platform_id", sa.Integer), sa.Column("deployment_id", sa.Text))
states = sa.Table(
    "lti_states", meta,
    sa.Column("state", sa.String(64)), sa.Column("nonce", sa.String(64)),
    sa.Column("platform_id", sa.Integer), sa.Column("expires", sa.DateTime(timezone=True)))
links = sa.Table(
    "lti_links", meta,
    sa.Column("id", sa.Integer, primary_key=True), sa.Column("platform_id", sa.Integer),
    sa.Column("context_id", sa.Text), sa.Column("resource_link_id", sa.Text),
    sa.Column("class_code", sa.String(6)), sa.Column("task", sa.Text),
    sa.Column("method", sa.String(16)),
    # (0006) a link launched without a line item of its own: the platform's container, the
    # label for the line item the tool makes there (lti.grades.make_lineitems), when it was
    # last asked for, and that line item
    sa.Column("lineitems", sa.Text), sa.Column("label", sa.Text),
    sa.Column("asked", sa.DateTime(timezone=True)), sa.Column("lineitem", sa.Text))
learners = sa.Table(
    "lti_learners", meta,
    sa.Column("id", sa.Integer, primary_key=True), sa.Column("link_id", sa.Integer),
    sa.Column("sub", sa.Text), sa.Column("student", sa.String(32)),
    sa.Column("lineitem", sa.Text), sa.Column("scored", sa.Integer),
    sa.Column("due", sa.DateTime(timezone=True)), sa.Column("failures", sa.Integer))


class LtiError(ClassError):
    """A request the tool refuses, said in words (the routes answer 4xx with it)."""


@dataclass(frozen=True)
class Platform:
    id: int
    issuer: str
    client_id: str
    auth_url: str
    token_url: str
    jwks_url: str
    deployments: tuple[str, ...]


def web_address(value, name: str) -> str:
    """The one check of an address the tool sends a user or a request to (a platform's
    login, token and key addresses, a deep link's return, a gradebook's line item): an
    http(s) URL with a host and no control character. A ``javascript:`` return address
    would otherwise become a form's action on the tool's own origin."""
    parsed = urllib.parse.urlsplit(value) if isinstance(value, str) else None
    if parsed is None or parsed.scheme not in ("http", "https") or not parsed.netloc \
            or any(ord(c) < 32 or ord(c) == 127 for c in value):
        raise LtiError(Text("lti.not_web", name=name, value=str(value)[:60]))
    return value


def add_platform(issuer: str, client_id: str, deployment: str, auth_url: str, token_url: str,
                 jwks_url: str, url: str | None = None) -> Platform:
    """Register a platform (or add a deployment to one registered): once per Moodle site.
    Its addresses must be web addresses (``web_address``)."""
    for address, name in ((auth_url, "--auth-url"), (token_url, "--token-url"), (jwks_url, "--jwks-url")):
        web_address(address, name)
    with engine(url).begin() as db:
        found = db.execute(sa.select(platforms.c.id).where(
            platforms.c.issuer == issuer, platforms.c.client_id == client_id)).scalar()
        if found is None:
            found = db.execute(platforms.insert().values(
                issuer=issuer, client_id=client_id, auth_url=auth_url, token_url=token_url,
                jwks_url=jwks_url, created=datetime.now(UTC)).returning(platforms.c.id)).scalar()
        else:
            db.execute(platforms.update().where(platforms.c.id == found).values(
                auth_url=auth_url, token_url=token_url, jwks_url=jwks_url))
        if db.execute(sa.select(deployments).where(deployments.c.platform_id == found,
                                                   deployments.c.deployment_id == deployment)).first() is None:
            db.execute(deployments.insert().values(platform_id=found, deployment_id=deployment))
    return platform(issuer, client_id, url)


def all_platforms(url: str | None = None) -> list[Platform]:
    with engine(url).connect() as db:
        rows = db.execute(sa.select(platforms).order_by(platforms.c.id)).all()
    return [_platform(row, url) for row in rows]


def _platform(row, url: str | None) -> Platform:
    with engine(url).connect() as db:
        ids = db.execute(sa.select(deployments.c.deployment_id)
                         .where(deployments.c.platform_id == row.id)
                         .order_by(deployments.c.deployment_id)).scalars().all()
    return Platform(row.id, row.issuer, row.client_id, row.auth_url, row.token_url,
                    row.jwks_url, tuple(ids))


def platform(issuer: str, client_id: str | None = None, url: str | None = None) -> Platform:
    """The platform registered for ``issuer`` (and ``client_id``, when the request names
    one); LtiError in words if none is."""
    query = sa.select(platforms).where(platforms.c.issuer == issuer)
    if client_id:
        query = query.where(platforms.c.client_id == client_id)
    with engine(url).connect() as db:
        rows = db.execute(query).all()
    if len(rows) != 1:
        raise LtiError(Text("lti.unknown_platform", issuer=issuer, client=client_id or "—"))
    return _platform(rows[0], url)


def platform_by_id(platform_id: int, url: str | None = None) -> Platform:
    with engine(url).connect() as db:
        row = db.execute(sa.select(platforms).where(platforms.c.id == platform_id)).first()
    if row is None:
        raise LtiError(Text("lti.unknown_platform", issuer="—", client="—"))
    return _platform(row, url)


def remove_platform(issuer: str, client_id: str, url: str | None = None) -> bool:
    """Forget a platform, its deployments and its links (their classes stay, to expire)."""
    with engine(url).begin() as db:
        found = db.execute(sa.select(platforms.c.id).where(
            platforms.c.issuer == issuer, platforms.c.client_id == client_id)).scalar()
        if found is None:
            return False
        link_ids = sa.select(links.c.id).where(links.c.platform_id == found)
        db.execute(learners.delete().where(learners.c.link_id.in_(link_ids)))
        for table in (links, deployments, states):
            db.execute(table.delete().where(table.c.platform_id == found))
        db.execute(platforms.delete().where(platforms.c.id == found))
    return True


def new_state(found: Platform) -> tuple[str, str]:
    """A login's ``state`` and ``nonce``, with nothing stored: the state is a short-lived
    value the tool signs, carrying the platform and the nonce (a flood of strangers' logins
    grows no table and evicts no honest login's state)."""
    nonce = secrets.token_urlsafe(32)
    state = keys.sign({"use": STATE_USE, "platform": found.id, "nonce": nonce},
                      int(STATE_LIFETIME.total_seconds()))
    return state, nonce


@dataclass(frozen=True)
class State:
    """What a login's state says: the platform, the nonce, its id and end."""

    platform_id: int
    nonce: str
    id: str
    expires: datetime


def read_state(state: str) -> State:
    """A login's ``state`` read back: signed by this tool, for a login, unexpired (LtiError
    if not). Nothing is used up here: a launch is checked whole first (``use_state``)."""
    try:
        claims = keys.verify(state)
    except jwt.PyJWTError:
        raise LtiError(Text("lti.state")) from None
    if claims.get("use") != STATE_USE or not isinstance(claims.get("platform"), int) \
            or not isinstance(claims.get("nonce"), str):
        raise LtiError(Text("lti.state"))
    return State(claims["platform"], claims["nonce"], str(claims["jti"]),
                 datetime.fromtimestamp(claims["exp"], UTC))


def use_state(said: State, url: str | None = None) -> None:
    """Use up a login's state once its launch passed every check: a second launch with it
    (a replay) is refused. The row is the only thing a launch's login leaves, kept until the
    state would have expired anyway."""
    with engine(url).begin() as db:
        db.execute(states.delete().where(states.c.expires < datetime.now(UTC)))
    try:
        with engine(url).begin() as db:
            db.execute(states.insert().values(state=said.id, nonce="", platform_id=said.platform_id,
                                              expires=said.expires))
    except sa.exc.IntegrityError:
        raise LtiError(Text("lti.state")) from None


@dataclass(frozen=True)
class Link:
    id: int
    class_code: str
    key: str  # the class's lecturer key (keys.lecturer_key: derived, not stored)


def link_class(found: Platform, context: str, resource: str, task: str, method: str,
               url: str | None = None, test: bool = False) -> Link:
    """The class of a resource link: made at its first launch, and made again if it expired
    or was deleted (a course outlives a class's days); ``test``: the activity is a test
    (custom ``test=1``: one try a step, grades sent when its teacher closes it)."""
    key = keys.lecturer_key(f"{found.id}|{context}|{resource}")
    with engine(url).connect() as db:
        row = db.execute(sa.select(links).where(
            links.c.platform_id == found.id, links.c.context_id == context,
            links.c.resource_link_id == resource)).first()
    if row is not None:
        try:
            store.opened(row.class_code, key, url)
            return Link(row.id, row.class_code, key)
        except ClassError:
            pass  # gone: a new class for the same link
    code, _ = store.create(task, method, days=LINK_DAYS, url=url, key=key, test=test)
    if row is not None:
        with engine(url).begin() as db:
            db.execute(links.update().where(links.c.id == row.id).values(class_code=code))
            db.execute(learners.delete().where(learners.c.link_id == row.id))  # their tokens went
        return Link(row.id, code, key)
    try:
        with engine(url).begin() as db:
            made = db.execute(links.insert().values(
                platform_id=found.id, context_id=context, resource_link_id=resource,
                class_code=code, task=task, method=method).returning(links.c.id)).scalar()
    except sa.exc.IntegrityError:  # a second first launch at once: the first one's class stands
        return link_class(found, context, resource, task, method, url, test)
    return Link(made, code, key)


def learner(link: Link, sub: str, lineitem: str | None, url: str | None = None) -> str:
    """The student token of a platform's user in the link's class: joined at their first
    launch (a pseudonymous nickname), the same at every later one."""
    with engine(url).connect() as db:
        row = db.execute(sa.select(learners).where(learners.c.link_id == link.id,
                                                   learners.c.sub == sub)).first()
    if row is not None:
        if lineitem and lineitem != row.lineitem:
            with engine(url).begin() as db:
                db.execute(learners.update().where(learners.c.id == row.id).values(lineitem=lineitem))
        return row.student
    token = store.join(link.class_code, "", url)
    try:
        with engine(url).begin() as db:
            db.execute(learners.insert().values(link_id=link.id, sub=sub, student=token,
                                                lineitem=lineitem, scored=0, failures=0))
    except sa.exc.IntegrityError:  # the same user's two first launches at once: one token
        return learner(link, sub, lineitem, url)
    return token


def wants_lineitem(link: Link, container: str, label: str, url: str | None = None) -> None:
    """A link launched with only the platform's line-items container: the tool makes its
    line item there (lti.grades.make_lineitems); a new container (a copied course) a new one."""
    with engine(url).begin() as db:
        db.execute(links.update().where(links.c.id == link.id, sa.or_(
            links.c.lineitems.is_(None), links.c.lineitems != container)).values(
            lineitems=container, label=label, lineitem=None, asked=None))
