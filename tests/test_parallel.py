"""deathsphere.parallel.ordered_map: input order, bounded look-ahead,
early exit, errors, and the one-process path."""

import os
import time

import pytest

from deathsphere.parallel import ordered_map


def square_after(pair):
    """Square of n after sleeping s seconds: later items can finish first."""
    n, s = pair
    time.sleep(s)
    return n * n


def pid(_):
    return os.getpid()


def fail_on_three(n):
    if n == 3:
        raise ValueError("three")
    return n


class Counted:
    """An iterable that counts how many items were drawn from it."""

    def __init__(self, items):
        self.items, self.drawn = list(items), 0

    def __iter__(self):
        for x in self.items:
            self.drawn += 1
            yield x


@pytest.mark.parametrize("jobs", [1, 2])
def test_results_come_in_input_order(jobs):
    # the first items are the slowest: with two processes they finish last
    items = [(n, 0.05 if n < 2 else 0.0) for n in range(12)]
    assert list(ordered_map(square_after, items, jobs)) == [n * n for n in range(12)]


def test_at_most_two_items_per_process_are_drawn_ahead():
    items = Counted((n, 0.0) for n in range(40))
    results = ordered_map(square_after, items, 2)
    assert next(results) == 0
    assert items.drawn == 4
    results.close()
    assert items.drawn == 4


def mark_then_sleep(args):
    """Leave a file named after the item (proof that it ran), then work a while."""
    n, folder = args
    open(os.path.join(folder, str(n)), "w").close()
    time.sleep(0.2)
    return n * n


def test_leaving_early_drops_the_queued_work(tmp_path):
    """Closing the iterator early runs none of the work not yet drawn: the
    items that ran are among the four drawn ahead (checked by what they
    left behind, not by a clock)."""
    items = Counted((n, str(tmp_path)) for n in range(50))    # 10 s of work on two processes
    results = ordered_map(mark_then_sleep, items, 2)
    assert next(results) == 0
    results.close()
    assert items.drawn == 4
    assert {int(name) for name in os.listdir(tmp_path)} <= {0, 1, 2, 3}


def test_one_job_runs_here_and_more_run_elsewhere():
    assert set(ordered_map(pid, range(3), 1)) == {os.getpid()}
    assert os.getpid() not in set(ordered_map(pid, range(6), 2))


@pytest.mark.parametrize("jobs", [1, 2])
def test_an_error_in_the_work_reaches_the_caller(jobs):
    results = ordered_map(fail_on_three, range(8), jobs)
    assert [next(results) for _ in range(3)] == [0, 1, 2]
    with pytest.raises(ValueError, match="three"):
        next(results)
