"""The class store: classes, their students and every check a student makes, through
SQLAlchemy — an SQLite file by default (nothing to install or start; WAL and a busy timeout,
so several app processes on one machine share it), PostgreSQL where
``MEHANIZMI_DATABASE_URL`` says so (a faculty's server behind nginx, deploy/). The schema is
made and upgraded by Alembic (``classes/migrations``), never by ``create_all``.

Students are pseudonymous: a random token (128 bits) and a nickname they chose; no name, no
address, no browser string is stored. A class is read only with its lecturer key, kept as
its SHA-256 (a stolen database does not open a class's results). Classes expire.
"""

from __future__ import annotations

import csv
import hashlib
import io
import json
import os
import secrets
import threading
import time
import uuid
from collections.abc import Mapping
from dataclasses import dataclass
from datetime import UTC, datetime, timedelta
from functools import cache, wraps
from pathlib import Path

import sqlalchemy as sa
from alembic import command
from alembic.config import Config

from exams.codes import CHECK_LETTERS, parse
from exams.codes import code as variant_code
from mechanisms.messages import Text
from methods.practice import finite
from methods.progress import PRACTICE, REVEALED, TEST, Rules  # (REVEALED: a "Show it" check's diagnosis)

from .methods import METHODS  # (the methods a class may practise: classes.methods)

ROOT = Path(__file__).resolve().parents[1]
DATA = Path(os.environ.get("MEHANIZMI_DATA", ROOT / "data"))  # the SQLite file's folder
CODE_LETTERS = CHECK_LETTERS + "34679"  # the variant codes' unambiguous letters, and digits
CODE_LENGTH = 6
LIFETIME_DAYS = int(os.environ.get("MEHANIZMI_CLASS_DAYS", "30"))
NICKNAME_MAX = 40  # characters
ANSWER_MAX = 200  # characters of an answer's JSON
PER_SECOND = 5  # checks a student may send in a second; more are slowed, not refused
FIELDS = ("student", "nickname", "step", "answer", "diagnosis", "term", "try", "time",
          "variant", "check")  # of every try exported, in this order

metadata = sa.MetaData()
classes = sa.Table(
    "classes", metadata,
    sa.Column("id", sa.Integer, primary_key=True),
    sa.Column("code", sa.String(CODE_LENGTH), nullable=False, unique=True),
    sa.Column("key_hash", sa.String(64), nullable=False),
    sa.Column("scene", sa.Text, nullable=False),  # a preset id or a link's s= text
    sa.Column("method", sa.String(16), nullable=False),
    sa.Column("at", sa.Float),  # φ₂ in degrees (or s in m); None: the scene's own
    sa.Column("variants", sa.String(64)),  # a variant set's code (exams.codes), or None
    sa.Column("created", sa.DateTime(timezone=True), nullable=False),
    sa.Column("expires", sa.DateTime(timezone=True), nullable=False, index=True),
    sa.Column("test", sa.Boolean, nullable=False, server_default=sa.false()),  # (0005)
    sa.Column("closed", sa.DateTime(timezone=True)),  # a test's verdicts shown from then (0005)
    sa.Column("deleted", sa.DateTime(timezone=True)))  # by its lecturer: said so (0005)
students = sa.Table(
    "students", metadata,
    sa.Column("id", sa.String(32), primary_key=True),  # the token in the student's link
    sa.Column("class_id", sa.Integer, sa.ForeignKey(classes.c.id, ondelete="CASCADE"),
              nullable=False, index=True),
    sa.Column("nickname", sa.String(NICKNAME_MAX), nullable=False),
    sa.Column("variant", sa.Integer),  # the index of their variant in the class's set
    sa.Column("joined", sa.DateTime(timezone=True), nullable=False))
checks = sa.Table(
    "checks", metadata,
    sa.Column("id", sa.Integer, primary_key=True),
    sa.Column("class_id", sa.Integer, sa.ForeignKey(classes.c.id, ondelete="CASCADE"),
              nullable=False, index=True),
    sa.Column("student", sa.String(32), sa.ForeignKey(students.c.id, ondelete="CASCADE"),
              nullable=False),
    sa.Column("step", sa.String(64), nullable=False),
    sa.Column("answer", sa.String(ANSWER_MAX), nullable=False),  # JSON: [x, y], a number, null
    sa.Column("diagnosis", sa.String(16), nullable=False),  # methods.practice's, or REVEALED
    sa.Column("term", sa.String(64)),  # the term a "missing-term" answer left out (0002)
    sa.Column("try", sa.Integer, nullable=False),
    sa.Column("time", sa.DateTime(timezone=True), nullable=False),
    sa.Column("variant", sa.String(64)),
    sa.Column("check_id", sa.String(36), nullable=False, unique=True),  # made with the check (0003)
    sa.UniqueConstraint("student", "step", "try"))  # tries numbered by the store, one each


class ClassError(ValueError):
    """A wrong, expired or mistyped code or key, an unknown student: ``args[0]`` is a Text."""


class OneTry(ClassError):
    """A second try of a step in a test: refused in words, not stored."""


class TestClosed(ClassError):
    """A try, or a new student, after the lecturer closed the test: refused in words, not
    stored (the grades sent at closing stay the class summary's)."""


def closed_at(found: "Class") -> str:
    """When the test was closed, as a student reads it: the hour and minute, local time."""
    return aware(found.closed).astimezone().strftime("%H:%M") if found.closed else ""


class NotSaved(RuntimeError):
    """The store could not take a check: the student is told, and no verdict is shown."""


class StoreDown(ClassError):
    """The store cannot be reached (its server stopped, the network): said in words, and
    nothing kept of the attempt, so the next one asks the store again."""


def _reachable(function):
    """``function`` with the database's own errors said as StoreDown (a page shows the
    message; nothing is cached from a store that did not answer)."""
    @wraps(function)
    def reached(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except sa.exc.SQLAlchemyError as exc:
            raise StoreDown(Text("class.store_down"), str(exc)) from None
    return reached


@dataclass(frozen=True)
class Class:
    id: int
    code: str
    scene: str
    method: str
    at: float | None
    variants: str | None
    expires: datetime
    test: bool = False  # one try a step, no hints; verdicts shown once ``closed``
    closed: datetime | None = None

    @property
    def rules(self) -> Rules:
        """How the class's steps are settled (methods.progress)."""
        return TEST if self.test else PRACTICE

    @property
    def verdicts_shown(self) -> bool:
        """Whether a student sees the verdicts of their checks: always in practice, once
        the lecturer closed it in a test."""
        return not self.test or self.closed is not None


def variant_of(found: Class, variant: int | None) -> str | None:
    """A student's variant code in a class of variants (None in a class of one scene)."""
    if not found.variants or not variant:
        return None
    return variant_code(parse(found.variants)[0], variant)


def database_url() -> str:
    """``MEHANIZMI_DATABASE_URL``, or the SQLite file in the data folder."""
    url = os.environ.get("MEHANIZMI_DATABASE_URL")
    if url:
        return url
    DATA.mkdir(parents=True, exist_ok=True)
    DATA.chmod(0o700)  # (the app's own folder: its store, tool key, logs, database server)
    return f"sqlite:///{DATA / 'mehanizmi.db'}"


def engine(url: str | None = None) -> sa.Engine:
    """The store's engine for ``url`` (default: ``database_url()``, read each time). Made
    under a lock: a fresh process's first sessions arrive at once, each in its thread, and
    two migrations at once break Alembic's module-level context."""
    with _MAKING:
        return _engine(url or database_url())


_MAKING = threading.Lock()


@cache
def _engine(url: str) -> sa.Engine:
    """One engine per URL and process, its schema upgraded on first use."""
    # (hide_parameters: an error's text, logged with its traceback, names no token)
    made = sa.create_engine(url, pool_pre_ping=True, hide_parameters=True)
    if made.dialect.name == "sqlite" and made.url.database not in (None, "", ":memory:"):
        _private(Path(made.url.database))
    if made.dialect.name == "sqlite":
        @sa.event.listens_for(made, "connect")
        def _sqlite(connection, _record) -> None:  # shared by processes on one machine
            connection.execute("PRAGMA journal_mode=WAL")
            connection.execute("PRAGMA busy_timeout=10000")
            connection.execute("PRAGMA foreign_keys=ON")
    migrate(made)
    return made


def _private(path: Path) -> None:
    """The SQLite file (student tokens) readable by its owner alone, made so before SQLite
    first opens it (its -wal and -shm files take the file's mode); a folder made for it is
    its owner's alone too (a folder the administrator chose keeps its mode)."""
    path.parent.mkdir(mode=0o700, parents=True, exist_ok=True)
    os.close(os.open(path, os.O_CREAT | os.O_WRONLY, 0o600))
    os.chmod(path, 0o600)


def reachable(url: str | None = None) -> bool:
    """Whether the store answers now (a page waiting for it looks every few seconds)."""
    try:
        with _autocommit(url) as db:
            db.execute(sa.text("SELECT 1"))
    except sa.exc.SQLAlchemyError:
        return False
    return True


MIGRATION_LOCK = 0x6D656861  # PostgreSQL's advisory lock key for the schema's upgrade ("meha")


def migrate(made: sa.Engine, to: str = "head") -> None:
    """Bring the schema to the newest migration (``classes/migrations``), or to ``to``."""
    config = Config()
    config.set_main_option("script_location", str(Path(__file__).with_name("migrations")))
    with made.begin() as connection:
        if made.dialect.name == "postgresql":  # hosts starting together: one migrates, the
            # others wait here until it commits and then find nothing left to do
            connection.execute(sa.text("SELECT pg_advisory_xact_lock(:key)"), {"key": MIGRATION_LOCK})
        config.attributes["connection"] = connection
        command.upgrade(config, to)


def _now() -> datetime:
    return datetime.now(UTC)


def _hash(key: str) -> str:
    return hashlib.sha256(key.encode()).hexdigest()


def aware(moment: datetime) -> datetime:
    """A time read back from the store, with its zone (SQLite keeps none)."""
    return moment if moment.tzinfo else moment.replace(tzinfo=UTC)  # SQLite keeps no zone


@_reachable
def create(scene: str, method: str, at: float | None = None, variants: str | None = None,
           days: int = LIFETIME_DAYS, url: str | None = None,
           key: str | None = None, test: bool = False) -> tuple[str, str]:
    """A new class: (join code, lecturer key). The key is shown once; only its hash stays.
    ``key``: one the caller derives again when needed (an LTI link's, lti/keys.py);
    ``test``: one try a step, no hints, verdicts shown once the lecturer closes it."""
    if method not in METHODS:
        raise ClassError(Text("class.no_method", method=method, methods=", ".join(METHODS)))
    key = key or secrets.token_hex(16)  # (hex: never a leading '-', which a command line takes for an option)
    with engine(url).begin() as db:
        for _ in range(20):
            code = "".join(secrets.choice(CODE_LETTERS) for _ in range(CODE_LENGTH))
            if db.execute(sa.select(classes.c.id).where(classes.c.code == code)).first() is None:
                break
        db.execute(classes.insert().values(
            code=code, key_hash=_hash(key), scene=scene, method=method, at=at,
            variants=variants, created=_now(), expires=_now() + timedelta(days=days), test=test))
    return code, key


@_reachable
def find(code: str, url: str | None = None) -> Class:
    """The class a code names (typed in any case, spaces ignored); ClassError if none or
    expired."""
    code = _code(code)
    return _class(_class_row(code, url), code)


def _code(text: str) -> str:
    return "".join(text.split()).upper()


def _class_row(code: str, url: str | None):
    """The ``classes`` row of ``code`` (None if there is none), in one statement."""
    with _autocommit(url) as db:
        return db.execute(sa.select(classes).where(classes.c.code == code)).first()


def _class(row, code: str) -> Class:
    """The class of a ``classes`` row read for ``code``: ClassError if none, deleted or expired."""
    if row is None:
        raise ClassError(Text("class.no_code", code=code))
    if row.deleted is not None:
        raise ClassError(Text("class.deleted", code=code))
    if aware(row.expires) < _now():
        raise ClassError(Text("class.expired", code=code))
    return Class(row.id, row.code, row.scene, row.method, row.at, row.variants, aware(row.expires),
                 bool(row.test), aware(row.closed) if row.closed else None)


def _autocommit(url: str | None) -> sa.Connection:
    """A connection whose every statement is a transaction of its own: a read or a check's
    one insert costs its own round trip, not a BEGIN and a COMMIT (or ROLLBACK) beside it
    — three where one does. (What must be one transaction of several statements uses
    ``engine(url).begin()``.)"""
    return engine(url).connect().execution_options(isolation_level="AUTOCOMMIT")


@_reachable
def opened(code: str, key: str, url: str | None = None) -> Class:
    """The class, for its lecturer: ClassError unless ``key`` is its key. One statement (a
    live view asks it every second)."""
    code = _code(code)
    row = _class_row(code, url)
    found = _class(row, code)
    if not secrets.compare_digest(row.key_hash, _hash(key.strip())):
        raise ClassError(Text("class.wrong_key", code=found.code))
    return found


def nickname_of(text: str) -> str:
    """A nickname as stored: printable characters, spaces squeezed, at most NICKNAME_MAX."""
    cleaned = " ".join("".join(c for c in text if c.isprintable()).split())
    return cleaned[:NICKNAME_MAX] or "student"


@_reachable
def join(code: str, nickname: str = "", url: str | None = None) -> str:
    """A student joins: their token. In a class of variants each gets the next one."""
    found = find(code, url)
    if found.test and found.closed is not None:  # (its grades are given: no new seat)
        raise TestClosed(Text("class.test_closed_join", at=closed_at(found)))
    token = secrets.token_hex(16)  # 32 characters, 128 bits; never a leading '-'
    with engine(url).begin() as db:
        count = db.execute(sa.select(sa.func.count()).select_from(students)
                           .where(students.c.class_id == found.id)).scalar()
        db.execute(students.insert().values(
            id=token, class_id=found.id, nickname=nickname_of(nickname or f"student {count + 1}"),
            variant=count + 1 if found.variants else None, joined=_now()))
    return token


def student(code: str, token: str, url: str | None = None) -> dict:
    """A student of this class (ClassError for another class's or an unknown token)."""
    return seated(code, token, url)[1]


@_reachable
def seated(code: str, token: str, url: str | None = None) -> tuple[Class, dict]:
    """The class and the student (``record``'s ``known``), read in one statement: a seated
    page's opening reads nothing else before its tries."""
    with _autocommit(url) as db:
        return _seated(db, _code(code), token)


@_reachable
def resume(code: str, token: str, url: str | None = None) -> tuple[Class, dict, list[dict]]:
    """The class, the student and their checks oldest first (``tries``): what a seated
    page opens with, in one statement (a class opening its pages at once waits on every
    round trip of every opening, issue 70)."""
    code = _code(code)
    with _autocommit(url) as db:
        rows = db.execute(_RESUME, {"code": code, "token": token}).all()
    found, who = _seat_of(rows[0] if rows else None, code)
    tried = [{k.removeprefix(TRIED): v for k, v in r._mapping.items() if k.startswith(TRIED)}
             for r in rows]
    return found, who, [_row(t, "") for t in tried if t["id"] is not None]


def _seated(db: sa.Connection, code: str, token: str) -> tuple[Class, dict]:
    """The class of ``code`` and its student ``token``, one row: ClassError for either not
    there (the class's own reasons first)."""
    return _seat_of(db.execute(_SEATED, {"code": code, "token": token}).first(), code)


# The class of :code with its student :token (no student: None in their columns), and, for
# ``resume``, that student's checks beside them. Built once: made anew at each opening,
# building the statement took a third of the opening's store time.
_SEATED = (sa.select(classes, students.c.id.label("token"), students.c.nickname,
                     students.c.variant.label("seat"))
           .select_from(classes.outerjoin(students, (students.c.class_id == classes.c.id)
                                          & (students.c.id == sa.bindparam("token"))))
           .where(classes.c.code == sa.bindparam("code")))
TRIED = "tried_"  # (``resume``: a check's columns beside the class's, named apart)
_RESUME = (_SEATED.add_columns(*(c.label(f"{TRIED}{c.name}") for c in checks.c))
           .outerjoin(checks, (checks.c.student == students.c.id) & (checks.c.class_id == classes.c.id))
           .order_by(checks.c.id))


def _seat_of(row, code: str) -> tuple[Class, dict]:
    """The class and the student of a row read for ``code`` (``_seated``, ``resume``)."""
    found = _class(row, code)
    if row.token is None:
        raise ClassError(Text("class.no_student", code=found.code))
    return found, {"student": row.token, "nickname": row.nickname, "variant": row.seat}


@_reachable
def roster(found: Class, url: str | None = None) -> dict[str, str]:
    """Every student of the class (``found`` from ``opened``): token → nickname, in the
    order they joined."""
    with _autocommit(url) as db:
        rows = db.execute(sa.select(students.c.id, students.c.nickname)
                          .where(students.c.class_id == found.id).order_by(students.c.joined)).all()
    return {r.id: r.nickname for r in rows}


def new_check() -> str:
    """A check's id, made where the check is made (the page, the command line) and kept
    until the store has it: the same id sent again is the same check."""
    return uuid.uuid4().hex


def answer_text(answer) -> str:
    """An answer as the store keeps it: strict JSON of ``None``, a finite number or a pair
    ``[x, y]`` of them; anything else is refused in words (ClassError), never stored."""
    if not (answer is None or finite(answer)
            or (isinstance(answer, (list, tuple)) and len(answer) == 2 and all(map(finite, answer)))):
        raise ClassError(Text("class.bad_answer", answer=str(answer)[:40]))
    text = json.dumps(answer if not isinstance(answer, tuple) else list(answer), allow_nan=False)
    if len(text) > ANSWER_MAX:
        raise ClassError(Text("class.too_long"))
    return text


def record(code: str, token: str, step: str, answer, diagnosis: str, check: str,
           variant: str | None = None, term: str = "", url: str | None = None,
           known: tuple[Class, dict] | None = None) -> int:
    """Store one check, durably, before its verdict is shown: the try number the store gave
    it (each student's tries of a step numbered 1, 2, … in the order they were stored, in
    the statement that inserts). ``check`` is the check's id (``new_check``): sent again
    (after "not saved", or twice by the network) it is stored once and its number returned;
    every other check is stored, from any tab, phone or command line. In a class of variants
    the student's variant code is kept unless ``variant`` names it. A student sending more
    than PER_SECOND checks a second waits. NotSaved when the store cannot take it.
    ``known``: the class and the student (``seated``) as the caller read them before — a
    page's check then costs the store two round trips, not four; a class deleted or expired
    since is found out all the same (the insert fails, or the expiry has passed)."""
    text = answer_text(answer)
    if len(step) > 64 or len(term) > 64 or len(variant or "") > 64 or not 0 < len(check) <= 36:
        raise ClassError(Text("class.too_long"))
    try:
        if known is None or known[0].expires < _now():
            known = seated(code, token, url)
        found, who = known
        if found.test and found.closed is not None:
            raise TestClosed(Text("class.test_closed_try", at=closed_at(found)))
        if found.test and diagnosis == REVEALED:
            raise OneTry(Text("class.one_try", step=step))
        if variant is None:  # in a class of variants, the student's own
            variant = variant_of(found, who["variant"])
        while _recent(url, who["student"]) >= PER_SECOND:
            time.sleep(0.2)  # a machine, not a person: slowed
        values = {"check_id": check, "class_id": found.id, "student": who["student"],
                  "step": step, "answer": text, "diagnosis": diagnosis, "term": term or None,
                  "time": _now(), "variant": variant}
        for _ in range(RACES):
            try:
                with _autocommit(url) as db:  # (one statement: numbered and inserted at once)
                    number = db.execute(*_numbered(values, first=found.test)).scalar()
                if number is None:  # the test closed since ``known`` was read: not stored
                    now = find(code, url)
                    raise TestClosed(Text("class.test_closed_try", at=closed_at(now)))
                return number
            except sa.exc.IntegrityError:  # this check sent again, or a number taken meanwhile
                stored = _stored_try(url, check)
                if stored is not None:
                    return stored  # the same check, stored by an earlier sending
                seated(code, token, url)  # (ClassError: the class or the student gone meanwhile)
                if found.test:  # a test's step has one try, and it is taken
                    raise OneTry(Text("class.one_try", step=step)) from None
        raise NotSaved("too many checks of this step at once")
    except StoreDown as exc:
        raise NotSaved(exc.args[-1]) from None
    except sa.exc.SQLAlchemyError as exc:
        raise NotSaved(str(exc)) from None


RACES = 8  # tries at numbering a check when others of the same step are stored at once


def _numbered(values: dict, first: bool = False) -> tuple:
    """The INSERT of one check whose try number is the next of its student's step, counted
    in the same statement (two checks at once collide on the unique number, and one of
    them numbers again), and its parameters. ``first``: only a first try (a test's), which
    collides with any earlier one."""
    return _numbering(tuple(values), first), {f"v_{k}": v for k, v in values.items()}


@cache
def _numbering(names: tuple[str, ...], first: bool):
    """``_numbered``'s statement for the columns ``names``, built once, as ``_RESUME`` is
    (built anew, the opening's statement took a third of its store time in a class's
    storm of openings)."""
    value = {k: sa.bindparam(f"v_{k}", type_=checks.c[k].type) for k in names}
    after = (sa.literal(1) if first else
             sa.select(sa.func.coalesce(sa.func.max(checks.c["try"]), 0) + 1)
             .where(checks.c.student == value["student"], checks.c.step == value["step"])
             .scalar_subquery())
    # the closing time is a rule of the store, in the statement that inserts: a test closed
    # a moment ago takes no try, whatever the page read before (none is stored, no row)
    open_ = ~sa.exists().where(classes.c.id == value["class_id"], classes.c.closed.is_not(None))
    return (checks.insert().from_select([*names, "try"], sa.select(*value.values(), after)
                                        .where(open_))
            .returning(checks.c["try"]))


def _stored_try(url: str | None, check: str) -> int | None:
    with _autocommit(url) as db:
        return db.execute(sa.select(checks.c["try"]).where(checks.c.check_id == check)).scalar()


def _recent(url: str | None, token: str) -> int:
    with _autocommit(url) as db:
        return db.execute(_RECENT, {"token": token, "since": _now() - timedelta(seconds=1)}).scalar()


_RECENT = (sa.select(sa.func.count()).select_from(checks)  # (built once, as _RESUME)
           .where(checks.c.student == sa.bindparam("token"),
                  checks.c.time >= sa.bindparam("since", type_=checks.c.time.type)))


def tries(code: str, token: str, url: str | None = None) -> list[dict]:
    """A student's checks, oldest first: what brings their progress back on a reload."""
    return resume(code, token, url)[2]


@_reachable
def tries_of(found: Class, token: str, url: str | None = None) -> list[dict]:
    """The checks of student ``token`` in class ``found`` (as ``seated`` read them before),
    oldest first, in one statement: a seated page resumes without reading its seat again."""
    with _autocommit(url) as db:
        rows = db.execute(sa.select(checks).where(checks.c.student == token,
                                                  checks.c.class_id == found.id)
                          .order_by(checks.c.id)).all()
    return [_row(r._mapping, "") for r in rows]


def export(code: str, key: str, url: str | None = None) -> list[dict]:
    """Every try of the class, for its lecturer, in the order stored: FIELDS."""
    return [{k: v for k, v in row.items() if k != "id"} for row in since(opened(code, key, url), 0, url)]


@_reachable
def since(found: Class, after: int, url: str | None = None) -> list[dict]:
    """The class's checks stored after the check numbered ``after``, oldest first, each with
    its number (``id``): what a live view fetches each second, only what is new. (``found``
    comes from ``opened``: the lecturer's key was checked.)"""
    with _autocommit(url) as db:
        rows = db.execute(sa.select(checks, students.c.nickname)
                          .join(students, students.c.id == checks.c.student)
                          .where(checks.c.class_id == found.id, checks.c.id > after)
                          .order_by(checks.c.id)).all()
    return [{"id": r.id, **_row(r._mapping, r.nickname)} for r in rows]


def as_csv(rows: list[dict]) -> str:
    """Exported tries as CSV (FIELDS; the answer as its JSON): ``class export`` and the
    lecturer's download write the same."""
    out = io.StringIO()
    writer = csv.DictWriter(out, FIELDS)
    writer.writeheader()
    writer.writerows({**row, "answer": json.dumps(row["answer"], allow_nan=False)} for row in rows)
    return out.getvalue()


def as_jsonl(rows: list[dict]) -> str:
    """Exported tries as JSON lines, one a try."""
    return "".join(json.dumps(row, ensure_ascii=False, allow_nan=False) + "\n" for row in rows)


def _row(r: Mapping, nickname: str) -> dict:
    """A check as read (a ``checks`` row's columns by name) and as every reader gets it."""
    return {"student": r["student"], "nickname": nickname, "step": r["step"],
            "answer": json.loads(r["answer"]), "diagnosis": r["diagnosis"], "term": r["term"] or "",
            "try": r["try"], "time": aware(r["time"]).isoformat(), "variant": r["variant"],
            "check": r["check_id"]}


@_reachable
def close(code: str, key: str, url: str | None = None) -> Class:
    """A test closed by its lecturer: its students see their verdicts from now on (a
    class that is not a test, or closed already, is left as it is)."""
    found = opened(code, key, url)
    if found.test and found.closed is None:
        with engine(url).begin() as db:
            db.execute(classes.update().where(classes.c.id == found.id).values(closed=_now()))
    return find(code, url)


@_reachable
def delete(code: str, key: str, url: str | None = None) -> None:
    """Everything stored of the class, at once (its lecturer's key). Its code is kept,
    marked deleted until it would have expired, so that a student's link says so."""
    found = opened(code, key, url)
    with engine(url).begin() as db:
        db.execute(checks.delete().where(checks.c.class_id == found.id))
        db.execute(students.delete().where(students.c.class_id == found.id))
        db.execute(classes.update().where(classes.c.id == found.id).values(deleted=_now()))


@_reachable
def purge(url: str | None = None, now: datetime | None = None) -> int:
    """Remove the expired classes and their students and checks: how many classes."""
    now = now or _now()
    with engine(url).begin() as db:
        expired = db.execute(sa.select(classes.c.id).where(classes.c.expires < now)).scalars().all()
        if expired:
            _remove(db, sa.select(classes.c.id).where(classes.c.id.in_(expired)))
    return len(expired)


def _remove(db, which) -> None:
    ids = db.execute(which).scalars().all()
    db.execute(checks.delete().where(checks.c.class_id.in_(ids)))
    db.execute(students.delete().where(students.c.class_id.in_(ids)))
    db.execute(classes.delete().where(classes.c.id.in_(ids)))
