"""scripts/turns.py: page scripts run one at a time, and none waits longer than its bound."""

from __future__ import annotations

import threading
import time

from scripts import turns


def _runs(wait: float) -> tuple:
    """A run that holds until told (``first``) and one that only records its start."""
    release, started, second_started = threading.Event(), threading.Event(), threading.Event()

    def run(name: str) -> None:
        if name == "first":
            started.set()
            release.wait(10)
        else:
            second_started.set()

    in_turn = turns.taking_turns(run, wait)
    first = threading.Thread(target=in_turn, args=("first",))
    second = threading.Thread(target=in_turn, args=("second",))
    first.start()
    assert started.wait(10)
    second.start()
    return first, second, release, second_started


def test_a_run_waits_for_the_one_in_progress():
    first, second, release, second_started = _runs(wait=10)
    assert not second_started.wait(0.3)  # the first still holds its turn
    release.set()
    assert second_started.wait(5)  # and gave it up when it finished
    for thread in (first, second):
        thread.join(5)


def test_a_long_run_holds_the_others_back_no_longer_than_the_bound():
    first, second, release, second_started = _runs(wait=0.05)
    assert second_started.wait(5)  # started beside the first, which still runs
    assert first.is_alive()
    release.set()
    for thread in (first, second):
        thread.join(5)


def test_a_long_run_lets_one_waiting_run_past_not_all_at_once():
    """A class opening its pages behind a process's first (cold, long) run: one run starts
    beside it, and the next only once that one is as old (all at once shared the CPU by
    5-ms slices again)."""
    wait = 0.5
    release = threading.Event()
    starts = {name: threading.Event() for name in ("first", "a", "b")}

    def run(name: str) -> None:
        starts[name].set()
        release.wait(10)

    in_turn = turns.taking_turns(run, wait)
    threads = [threading.Thread(target=in_turn, args=(name,)) for name in starts]
    threads[0].start()
    assert starts["first"].wait(5)
    for thread in threads[1:]:
        thread.start()
    deadline = time.monotonic() + 5
    while not (starts["a"].is_set() or starts["b"].is_set()) and time.monotonic() < deadline:
        time.sleep(0.005)
    past = [name for name in ("a", "b") if starts[name].is_set()]
    assert len(past) == 1  # one went past the long run…
    later = starts["b" if past == ["a"] else "a"]
    assert not later.wait(wait / 2)  # …and the other waits for it to be as old
    assert later.wait(5)
    release.set()
    for thread in threads:
        thread.join(5)


def test_runs_start_in_the_order_they_asked():
    release, began = threading.Event(), threading.Event()
    order: list[str] = []

    def run(name: str) -> None:
        if name == "first":
            began.set()
            release.wait(10)
        order.append(name)

    in_turn = turns.taking_turns(run, wait=10)
    threads = [threading.Thread(target=in_turn, args=(name,)) for name in ("first", *"abcde")]
    threads[0].start()
    assert began.wait(5)
    for thread in threads[1:]:
        thread.start()
        time.sleep(0.05)  # (each has asked before the next)
    release.set()
    for thread in threads:
        thread.join(5)
    assert order == ["first", *"abcde"]


def test_a_failing_run_gives_up_its_turn():
    def fail() -> None:
        raise RuntimeError("a page's exception")

    in_turn = turns.taking_turns(fail, wait=10)
    for _ in range(2):  # the second would wait 10 s if the first had kept the turn
        try:
            in_turn()
        except RuntimeError:
            pass
    done = threading.Event()
    threading.Thread(target=turns.taking_turns(done.set, wait=10)).start()
    assert done.wait(1)

