"""The class store (classes/store.py), run twice: on an SQLite file and on a real PostgreSQL
server that these tests start in a temporary folder (Debian's ``postgresql``, installed by
scripts/test.sh; ``initdb`` and ``pg_ctl`` on a free port as the ``postgres`` user)."""

from __future__ import annotations

import csv
import io
import json
import multiprocessing
import os
import subprocess
import sys
import time
from datetime import UTC, datetime, timedelta
from pathlib import Path

import pytest
import sqlalchemy as sa

from classes import store, summary

from .test_cli import run

ROOT = Path(__file__).resolve().parents[1]


def test_a_class_is_joined_and_every_check_comes_back_from_the_store(url):
    code, key = store.create("zbirka-3.1", "plans", url=url)
    assert len(code) == 6 and set(code) <= set(store.CODE_LETTERS) and len(key) >= 22
    assert not key.startswith("-")  # (`--key -x…` read as an option: one key in 64 once)
    ana, ben = store.join(code.lower(), "Ana", url=url), store.join(f" {code} ", url=url)
    assert not any(store.join(code, url=url).startswith("-") for _ in range(64))  # --student X
    assert store.record(code, ana, "v.a-b", [0.19, -3.09], "sense", store.new_check(), url=url) == 1
    right = store.new_check()
    assert store.record(code, ana, "v.a-b", [-0.19, 3.09], "ok", right, url=url) == 2
    assert store.record(code, ana, "v.a-b", [-0.19, 3.09], "ok", right, url=url) == 2  # sent again: once
    assert store.record(code, ben, "v.a-b", 3.1, "wrong", store.new_check(), url=url) == 1
    assert [(t["step"], t["diagnosis"], t["try"]) for t in store.tries(code, ana, url=url)] == [
        ("v.a-b", "sense", 1), ("v.a-b", "ok", 2)]
    found, who, tried = store.resume(code, ana, url=url)  # (one statement: seat and tries joined)
    assert (found, who) == store.seated(code, ana, url=url)
    assert tried == store.tries_of(found, ana, url=url) and tried[1]["check"] == right
    assert store.resume(code, store.join(code, url=url), url=url)[2] == []  # no try yet
    rows = store.export(code, key, url=url)
    assert len(rows) == 3 and set(rows[0]) == set(store.FIELDS) and rows[1]["check"] == right
    assert {r["nickname"] for r in rows} == {"Ana", "student 2"}
    assert rows[0]["answer"] == [0.19, -3.09]
    # written as the command line and the lecturer's download write them, and read back
    assert [json.loads(line) for line in store.as_jsonl(rows).splitlines()] == rows
    table = list(csv.DictReader(io.StringIO(store.as_csv(rows))))
    assert [list(r) for r in table] == [list(store.FIELDS)] * 3
    assert [json.loads(r["answer"]) for r in table] == [r["answer"] for r in rows]
    with store.engine(url).connect() as db:  # the schema came from the migrations
        assert db.execute(sa.text("select version_num from alembic_version")).scalar() == "0006"


@pytest.mark.server
def test_a_fresh_process_s_first_sessions_arriving_at_once_make_one_store(tmp_path):
    """Eight threads (a fresh app process's first students) ask for the store at once: the
    schema is made once and each gets the same engine (two migrations at once broke)."""
    from concurrent.futures import ThreadPoolExecutor

    url = f"sqlite:///{tmp_path / 'fresh.db'}"
    with ThreadPoolExecutor(8) as pool:
        made = list(pool.map(lambda _: store.engine(url), range(8)))
    assert len({id(m) for m in made}) == 1
    code, _ = store.create("zbirka-3.1", "plans", url=url)
    assert store.find(code, url=url).method == "plans"


def test_a_store_made_by_the_first_migration_is_upgraded_with_its_checks_kept(url):
    """A faculty's store from before the term column: the start command's migration adds it,
    and the checks stored before come back with no term."""
    if url.startswith("postgresql"):  # a database of its own on the tests' server
        name = f"upgrade_{os.getpid()}_{time.monotonic_ns()}"
        with sa.create_engine(url, isolation_level="AUTOCOMMIT").connect() as db:
            db.execute(sa.text(f"create database {name}"))
        url = url.rsplit("/", 1)[0] + f"/{name}"
    made = sa.create_engine(url)
    store.migrate(made, "0001")
    with made.begin() as db:
        db.execute(sa.text("insert into classes (code, key_hash, scene, method, created, expires) "
                           "values ('OLDONE', 'x', 'zbirka-3.1', 'plans', :now, :later)"),
                   {"now": datetime.now(UTC), "later": datetime.now(UTC) + timedelta(days=1)})
        db.execute(sa.text("insert into students (id, class_id, nickname, joined) "
                           "select 'old-student', id, 'Ana', :now from classes"), {"now": datetime.now(UTC)})
        for n, answer in ((1, "NaN"), (2, "1.0")):  # (0001 stored Python's NaN as it came)
            db.execute(sa.text("insert into checks (class_id, student, step, answer, diagnosis, try, time) "
                               "select id, 'old-student', 'v.b', :answer, 'wrong', :n, :now from classes"),
                       {"now": datetime.now(UTC), "answer": answer, "n": n})
    made.dispose()  # (the store's engine for this new URL is made, and upgrades, below)
    old = store.tries("OLDONE", "old-student", url=url)
    assert [(r["step"], r["term"], r["try"], r["answer"]) for r in old] == [
        ("v.b", "", 1, None), ("v.b", "", 2, 1.0)]  # kept, and strict JSON
    assert len({r["check"] for r in old}) == 2  # each an id of its own (0003)
    store.record("OLDONE", "old-student", "v.c", 2.0, "missing-term", store.new_check(), term="a^k", url=url)
    assert store.tries("OLDONE", "old-student", url=url)[-1]["term"] == "a^k"
    assert store.record("OLDONE", "old-student", "v.b", 1.5, "ok", store.new_check(), url=url) == 3


def test_two_devices_and_two_hand_ins_are_every_one_stored_in_order(url):
    """One student's link on two phones (or a page and the command line): every check is a
    try of its own, numbered by the store in the order stored; only the same check (its id)
    sent again is stored once."""
    code, key = store.create("zbirka-3.1", "plans", url=url)
    token = store.join(code, url=url)
    phone1, phone2 = store.new_check(), store.new_check()
    assert store.record(code, token, "v.b", [0.0, -3.1], "sense", phone1, url=url) == 1
    assert store.record(code, token, "v.b", [0.0, 3.1], "ok", phone2, url=url) == 2
    assert store.record(code, token, "v.b", [0.0, -3.1], "sense", phone1, url=url) == 1  # again
    rows = store.export(code, key, url=url)
    assert [(r["diagnosis"], r["try"], r["check"]) for r in rows] == [
        ("sense", 1, phone1), ("ok", 2, phone2)]


def _racing(args) -> list[int]:
    url, code, token = args
    return [store.record(code, token, "v.b", float(k), "wrong", store.new_check(), url=url)
            for k in range(4)]


@pytest.mark.server
def test_two_processes_checking_one_step_at_once_get_distinct_tries(url):
    code, key = store.create("zbirka-3.1", "plans", url=url)
    token = store.join(code, url=url)
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        numbers = pool.map(_racing, [(url, code, token)] * 2)
    assert sorted(numbers[0] + numbers[1]) == list(range(1, 9))
    assert sorted(r["try"] for r in store.export(code, key, url=url)) == list(range(1, 9))


@pytest.mark.parametrize("answer", [float("nan"), float("inf"), [1.0, float("-inf")], [1.0],
                                    "3.1", True, {"x": 1}])
def test_an_answer_that_is_not_finite_numbers_is_refused_and_nothing_stored(url, answer):
    code, key = store.create("zbirka-3.1", "plans", url=url)
    token = store.join(code, url=url)
    with pytest.raises(store.ClassError) as refused:
        store.record(code, token, "v.b", answer, "wrong", store.new_check(), url=url)
    assert refused.value.args[0].key == "class.bad_answer"
    assert store.export(code, key, url=url) == []


def test_wrong_codes_keys_and_students_are_refused_in_words(url):
    code, key = store.create("zbirka-3.1", "plans", url=url)
    other, _ = store.create("zbirka-3.1", "plans", url=url)
    stranger = store.join(other, url=url)
    cases = [(lambda: store.find("ABCDEF" if code != "ABCDEF" else "ACDEFH", url=url), "no_code"),
             (lambda: store.export(code, key + "x", url=url), "wrong_key"),
             (lambda: store.record(code, stranger, "v.b", 1.0, "ok", store.new_check(), url=url), "no_student"),
             (lambda: store.resume(code, stranger, url=url), "no_student"),
             (lambda: store.create("zbirka-3.1", "dance", url=url), "no_method")]
    for call, said in cases:
        with pytest.raises(store.ClassError) as refused:
            call()
        assert refused.value.args[0].key == f"class.{said}"
    assert store.export(code, key, url=url) == []  # nothing was written as another student


def test_a_class_expires_is_purged_and_its_lecturer_deletes_it_at_once(url):
    old, _ = store.create("zbirka-3.1", "plans", days=-1, url=url)
    with pytest.raises(store.ClassError) as refused:
        store.join(old, url=url)
    assert refused.value.args[0].key == "class.expired"
    code, key = store.create("zbirka-3.1", "plans", url=url)
    store.record(code, store.join(code, url=url), "v.b", 1.0, "ok", store.new_check(), url=url)
    assert store.purge(url=url) >= 1
    with pytest.raises(store.ClassError):
        store.find(old, url=url)
    live = store.find(code, url=url).id  # a live class stays
    store.delete(code, key, url=url)
    with pytest.raises(store.ClassError):
        store.find(code, url=url)
    with store.engine(url).connect() as db:  # and nothing of it is left
        for table in ("checks", "students"):
            assert db.execute(sa.text(f"select count(*) from {table} where class_id = :c"),
                              {"c": live}).scalar() == 0


@pytest.mark.parametrize("nickname", ["<script>alert(1)</script>", "x" * 10_000,
                                      "a\x00b\x1b[31mc\n", "'; DROP TABLE checks; --"])
def test_hostile_nicknames_are_stored_as_bounded_text(url, nickname):
    code, key = store.create("zbirka-3.1", "plans", url=url)
    token = store.join(code, nickname, url=url)
    stored = store.student(code, token, url=url)["nickname"]
    assert len(stored) <= store.NICKNAME_MAX and stored.isprintable()
    assert stored == nickname[:store.NICKNAME_MAX] or "\x00" in nickname
    store.record(code, token, "v.b", 1.0, "ok", store.new_check(), url=url)
    assert store.export(code, key, url=url)[0]["nickname"] == stored  # the table is there
    with pytest.raises(store.ClassError):
        store.record(code, token, "v.b", "9" * 500, "ok", store.new_check(), url=url)  # an answer too long


def _write(args) -> None:
    url, code, token, first = args
    for k in range(first, first + 25):
        store.record(code, token, f"step.{k}", float(k), "ok", store.new_check(), url=url)


@pytest.mark.server
def test_two_processes_write_to_one_class_at_once_and_nothing_is_lost(url):
    code, key = store.create("zbirka-3.1", "plans", url=url)
    students = [store.join(code, url=url) for _ in range(2)]
    with multiprocessing.get_context("spawn").Pool(2) as pool:
        pool.map(_write, [(url, code, students[0], 0), (url, code, students[1], 0)])
    rows = store.export(code, key, url=url)
    assert len(rows) == 50
    assert len({(r["student"], r["step"], r["try"]) for r in rows}) == 50


def test_a_student_faster_than_a_person_is_slowed_not_refused(url):
    code, key = store.create("zbirka-3.1", "plans", url=url)
    token = store.join(code, url=url)
    started = time.perf_counter()
    for k in range(store.PER_SECOND + 3):
        store.record(code, token, f"step.{k}", 1.0, "ok", store.new_check(), url=url)
    assert time.perf_counter() - started > 0.5  # the sixth check waited for the second
    assert len(store.export(code, key, url=url)) == store.PER_SECOND + 3


def test_with_the_database_stopped_a_check_is_not_saved_and_later_stored_once(postgres):
    url = postgres.url
    code, key = store.create("zbirka-3.1", "plans", url=url)
    token = store.join(code, url=url)
    postgres.stop()
    check = store.new_check()  # made with the check, kept by the page until stored
    try:
        with pytest.raises(store.NotSaved):
            store.record(code, token, "v.b", [0.0, 3.1], "ok", check, url=url)
        with pytest.raises(store.StoreDown) as down:  # a page reading the store: said in words
            store.tries(code, token, url=url)
        assert down.value.args[0].key == "class.store_down"
    finally:
        postgres.start()
    store.record(code, token, "v.b", [0.0, 3.1], "ok", check, url=url)
    store.record(code, token, "v.b", [0.0, 3.1], "ok", check, url=url)  # sent once more
    assert [(r["step"], r["try"]) for r in store.export(code, key, url=url)] == [("v.b", 1)]


def _command_line(database: Path):
    """``python -m solvers …`` on the SQLite store ``database`` — run in this process, as
    tests/test_cli.py runs it (a fresh interpreter is 1.5 s of imports a command; the
    store is a file either way, and the tests below of two processes at once use two)."""
    def cli(*args: str) -> subprocess.CompletedProcess:
        with pytest.MonkeyPatch.context() as patch:
            patch.setenv("MEHANIZMI_DATABASE_URL", f"sqlite:///{database}")
            return run(*args)
    return cli


def test_the_command_line_scripts_a_class_on_the_same_store(tmp_path):
    cli = _command_line(tmp_path / "cli.db")
    made = json.loads(cli("class", "create", "zbirka-3.1", "--method", "plans", "--json").stdout)
    assert set(made) == {"code", "key", "join"} and made["join"].endswith(made["code"])
    student = json.loads(cli("class", "join", made["code"], "--nickname", "Ana",
                             "--json").stdout)["student"]
    answers = tmp_path / "answers.json"
    answers.write_text(json.dumps({"answers": {"v.a-b": [0.19357, -3.09395]}}))
    done = cli("practice", "zbirka-3.1", "--method", "plans", "--answers", str(answers),
               "--class", made["code"], "--student", student)
    assert done.returncode == 0, done.stderr
    lines = cli("class", "export", made["code"], "--key", made["key"]).stdout.splitlines()
    assert [json.loads(line)["diagnosis"] for line in lines] == ["sense"]
    assert "v.a-b" in cli("class", "export", made["code"], "--key", made["key"], "--format",
                          "csv").stdout
    for args in (("class", "export", made["code"], "--key", "nope"),
                 ("class", "join", "ZZZZZZ"),
                 ("practice", "zbirka-3.1", "--method", "plans", "--answers", str(answers),
                  "--class", made["code"], "--student", "someone-else")):
        wrong = cli(*args)
        assert wrong.returncode == 2 and wrong.stderr.startswith("error: ") and \
            "Traceback" not in wrong.stderr
    assert cli("class", "delete", made["code"], "--key", made["key"]).returncode == 0
    assert "purged 0" in cli("class", "purge").stdout


def test_a_second_hand_in_is_stored_as_the_next_tries_and_hostile_files_store_nothing(tmp_path):
    cli = _command_line(tmp_path / "cli.db")
    made = json.loads(cli("class", "create", "zbirka-3.1", "--method", "plans", "--json").stdout)
    student = cli("class", "join", made["code"]).stdout.strip()
    seat = ("--class", made["code"], "--student", student)
    exact = next(s for s in json.loads(cli("practice", "zbirka-3.1", "--method", "plans",
                                           "--json").stdout)["steps"] if s["id"] == "v.a-b")
    reversed_ = tmp_path / "first.json"
    reversed_.write_text(json.dumps({"answers": {"v.a-b": [-v for v in exact["expected"]]}}))
    right = tmp_path / "second.json"
    right.write_text(json.dumps({"answers": {"v.a-b": exact["expected"]}}))
    for path, n in ((reversed_, 1), (right, 2)):  # the scene may be left out: the class's
        done = cli("practice", "--method", "plans", "--answers", str(path), *seat, "--json")
        assert done.returncode == 0, done.stderr
        assert json.loads(done.stdout)["stored"] == {"v.a-b": n}
    texts = {"nan.json": '{"answers": {"v.a-b": [NaN, 1]}}',
             "inf.json": '{"answers": {"v.a-b": [Infinity, 1]}}',
             "huge.json": '{"answers": {"v.a-b": [1e309, 1]}}',
             "shape.json": '{"answers": {"v.a-b": [1, 2, 3]}}',
             "text.json": '{"answers": {"v.a-b": ["1", 2]}}'}
    for name, text in texts.items():
        (tmp_path / name).write_text(text)
        refused = cli("practice", "zbirka-3.1", "--method", "plans", "--answers",
                      str(tmp_path / name), *seat)
        assert refused.returncode == 2 and refused.stderr.startswith("error: answers"), (name, refused)
    forces = tmp_path / "forces.json"  # another task's answers, to this class
    step = json.loads(cli("practice", "zbirka-5.1", "--method", "forces", "--json").stdout)["steps"][0]
    forces.write_text(json.dumps({"answers": {step["id"]: step["expected"]}}))
    for args in (("zbirka-5.1", "--method", "forces"), ("--method", "forces"),
                 ("zbirka-3.1", "--method", "plans", "--at", "100")):
        refused = cli("practice", *args, "--answers", str(forces), *seat)
        assert refused.returncode == 2 and "practises plans on zbirka-3.1" in refused.stderr, refused
    rows = [json.loads(line) for line in
            cli("class", "export", made["code"], "--key", made["key"]).stdout.splitlines()]
    assert [(r["step"], r["diagnosis"], r["try"]) for r in rows] == [
        ("v.a-b", "sense", 1), ("v.a-b", "ok", 2)]


def test_a_check_time_is_when_it_was_stored(url):
    code, key = store.create("zbirka-3.1", "plans", url=url)
    store.record(code, store.join(code, url=url), "v.b", 1.0, "ok", store.new_check(), url=url)
    (row,) = store.export(code, key, url=url)
    assert abs(datetime.fromisoformat(row["time"]) - datetime.now(UTC)) < timedelta(minutes=1)


def test_a_planted_class_is_counted_step_by_step_from_the_store(url):
    """Five students on two of three steps: the counts, the first tries, the most common
    mistake with its term, the cloud's latest answers and the table of students, all read
    back from the store (and ``since`` gives only what is newer)."""
    code, key = store.create("zbirka-3.1", "plans", url=url)
    who = {name: store.join(code, name, url=url) for name in "abcde"}
    planted = [("a", "s1", "ok", ""), ("a", "s2", "ok", ""),
               ("b", "s1", "sense", ""), ("b", "s1", "ok", ""),
               ("c", "s1", "missing-term", "X"), ("c", "s1", "missing-term", "X"), ("c", "s1", "wrong", ""),
               ("d", "s1", store.REVEALED, ""),
               ("e", "s1", "missing-term", "X"), ("e", "s1", store.REVEALED, "")]
    tried = {}
    for name, step, diagnosis, term in planted:
        tried[name, step] = tried.get((name, step), 0) + 1
        answer = None if diagnosis == store.REVEALED else [tried[name, step], 0.5]
        store.record(code, who[name], step, answer, diagnosis, store.new_check(), term=term, url=url)
    rows = store.since(store.opened(code, key, url=url), 0, url=url)
    assert len(rows) == len(planted) and rows == sorted(rows, key=lambda r: r["id"])
    assert store.since(store.opened(code, key, url=url), rows[5]["id"], url=url) == rows[6:]

    s1, s2, s3 = summary.counts(rows, ["s1", "s2", "s3"])
    assert (s1.reached, s1.first, s1.later, s1.revealed) == (5, 1, 1, 3)
    assert s1.first_tries == {"ok": 1, "sense": 1, "missing-term": 2, "none": 1}
    assert s1.mistake == (2, [("missing-term", "X")])  # c twice and e once: two students
    assert (s2.reached, s2.first, s2.mistake) == (1, 1, None)
    assert (s3.reached, sum(s3.first_tries.values())) == (0, 0)
    cloud = summary.latest(rows, "s1")
    assert {rows_nick["nickname"]: (rows_nick["diagnosis"], rows_nick["answer"])
            for rows_nick in cloud.values()} == {
        "a": ("ok", [1, 0.5]), "b": ("ok", [2, 0.5]), "c": ("wrong", [3, 0.5]),
        "e": ("missing-term", [1, 0.5])}  # d was shown it: nothing to draw
    assert summary.students(rows, ["s1", "s2", "s3"]) == [
        {"nickname": "a", "done": 2, "first": 2}, {"nickname": "b", "done": 1, "first": 0},
        {"nickname": "c", "done": 1, "first": 0}, {"nickname": "d", "done": 1, "first": 0},
        {"nickname": "e", "done": 1, "first": 0}]


def test_the_most_common_mistake_is_the_same_in_any_process_and_a_tie_is_said_whole():
    """Two mistakes made by as many students: both named, in the grader's order of
    diagnoses, whatever order the checks came in (a set's order once chose one of them,
    differently under another PYTHONHASHSEED)."""
    rows = [{"student": s, "step": "v.b", "diagnosis": d, "term": term, "try": 1, "id": i,
             "nickname": s, "answer": [1.0, 0.0], "variant": None}
            for i, (s, d, term) in enumerate([("a", "wrong", ""), ("b", "missing-term", "Y"),
                                              ("c", "sense", ""), ("d", "missing-term", "X"),
                                              ("e", "sense", ""), ("f", "wrong", "")])]
    said = [summary.counts(order, ["v.b"])[0].mistake for order in (rows, rows[::-1], rows[2:] + rows[:2])]
    assert said == [(2, [("sense", ""), ("wrong", "")])] * 3


def test_students_are_split_in_bands_of_a_given_value():
    split = summary.bands({"a": 10.0, "b": 20.0, "c": 40.0, "d": 39.0}, 3)
    assert split["a"] == (10.0, 20.0) and split["b"] == (20.0, 30.0)
    assert split["c"] == split["d"] == (30.0, 40.0)
    assert set(summary.bands({"a": 5.0, "b": 5.0}).values()) == {(5.0, 5.0)}


def test_the_sqlite_store_is_readable_by_its_owner_alone(tmp_path, monkeypatch):
    """It holds the students' tokens: made 600 before SQLite first opens it, its WAL too, in
    a folder made 700 for it; the default data folder is made 700 too."""
    os.umask(0o022)
    path = tmp_path / "private" / "class.db"
    url = f"sqlite:///{path}"
    code, _ = store.create("zbirka-3.1", "plans", url=url)
    store.record(code, store.join(code, url=url), "v.b", 1.0, "ok", store.new_check(), url=url)
    made = [p for p in path.parent.iterdir() if p.name.startswith("class.db")]
    assert path in made and all(p.stat().st_mode & 0o077 == 0 for p in made), \
        {p.name: oct(p.stat().st_mode) for p in made}
    assert path.parent.stat().st_mode & 0o077 == 0
    monkeypatch.setattr(store, "DATA", tmp_path / "data")
    monkeypatch.delenv("MEHANIZMI_DATABASE_URL", raising=False)
    assert store.database_url().endswith("data/mehanizmi.db")
    assert (tmp_path / "data").stat().st_mode & 0o777 == 0o700


@pytest.mark.server
def test_the_command_line_ends_quietly_on_a_closed_pipe_and_refuses_a_huge_answers_file(tmp_path):
    done = subprocess.run(f"{sys.executable} -m solvers practice zbirka-3.1 --method plans | head -1",
                          shell=True, cwd=ROOT, capture_output=True, text=True)
    assert done.returncode == 0 and "Traceback" not in done.stderr and done.stdout.startswith("v.")
    huge = tmp_path / "answers.json"
    huge.write_text('{"answers": {"v.a-b": [1, 2]}, "pad": "' + "x" * 2_000_000 + '"}')
    cli = _command_line(tmp_path / "cli.db")
    said = cli("practice", "zbirka-3.1", "--method", "plans", "--answers", str(huge))
    assert said.returncode == 2 and "answers.json' is 2,000 kB; at most 1000 kB" in said.stderr and "Traceback" not in said.stderr
