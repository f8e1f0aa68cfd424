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


def pytest_collection_modifyitems(config, items):
    """The longest tests first (marked ``longest``): worksteal hands tests
    out in collection order, and a run that met the sphere's tens of seconds
    of sympy at its end would wait on one core for it."""
    items.sort(key=lambda item: item.get_closest_marker("longest") is None)
