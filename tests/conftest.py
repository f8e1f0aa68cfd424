import os

import pytest
from hypothesis import settings

# Property tests draw the same examples on every run (CI included), so a red
# run is reproducible and a green one is not luck; HYPOTHESIS_PROFILE=explore
# draws new ones, to hunt for counter-examples by hand.
settings.register_profile("deterministic", derandomize=True, database=None)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "deterministic"))
from click.testing import CliRunner

from deathsphere.cli import cli


@pytest.fixture
def run():
    """Invoke the CLI in-process; returns click's Result (stdout, stderr, exit_code)."""
    runner = CliRunner()

    def invoke(*args, input=None, env=None):
        return runner.invoke(cli, list(args), input=input, env=env, catch_exceptions=False)

    return invoke


def _chunk_starts(n: int, workers: int) -> list[int]:
    """Where each worker's first share of ``n`` tests starts: worksteal
    sends the idle workers ``len(pending) // workers_left`` in turn, from
    the front of the collection."""
    starts, start, left = [], 0, n
    for j in range(workers):
        starts.append(start)
        take = left // (workers - j)
        start, left = start + take, left - take
    return starts


def pytest_collection_modifyitems(config, items):
    """The longest tests (marked ``longest``) at the head of each worker's
    first share, dealt round the workers: worksteal splits the collection
    into contiguous shares, so sorted to the front they would all fall to
    the first worker one after another, and a run that met one at its end
    would wait on one core for it.  In one process: simply first."""
    longest = [item for item in items if item.get_closest_marker("longest") is not None]
    others = [item for item in items if item.get_closest_marker("longest") is None]
    workers = int(getattr(config, "workerinput", {}).get("workercount", 1))
    starts = _chunk_starts(len(items), workers) + [len(items)]
    order = []
    for j in range(workers):
        mine = longest[j::workers]
        fill = starts[j + 1] - starts[j] - len(mine)
        order += mine + others[:max(fill, 0)]
        others = others[max(fill, 0):]
    items[:] = order + others
