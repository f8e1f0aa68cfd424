"""A command sizes polars' pool to leave a core to the evaluation
(deathsphere.threads), and leaves a user's setting alone."""

import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

PROBE = """
import os, sys
from deathsphere.threads import leave_a_core_to_the_evaluation
{before}
leave_a_core_to_the_evaluation()
print(os.environ.get("POLARS_MAX_THREADS", "unset"))
"""


def _run(before: str = "", **env) -> str:
    environ = {k: v for k, v in os.environ.items() if k != "POLARS_MAX_THREADS"}
    environ.update(env, PYTHONPATH=ROOT)
    out = subprocess.run([sys.executable, "-c", PROBE.format(before=before)], capture_output=True, text=True,
                         env=environ, check=True)
    return out.stdout.strip()


def test_the_pool_gets_the_cores_less_one():
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    assert _run() == str(max(1, cores - 1))


def test_a_users_setting_is_kept():
    assert _run(POLARS_MAX_THREADS="7") == "7"


def test_too_late_once_polars_is_imported():
    pytest.importorskip("polars")
    assert _run(before="import polars") == "unset"


def test_the_command_sets_it_before_polars_is_imported():
    """The entry point calls it (a sweep's writer imports polars later)."""
    probe = ("import os, sys\nfrom deathsphere.cli import base\nbase.cli.main = lambda **k: None\nbase.main([])\n"
             "print(os.environ.get('POLARS_MAX_THREADS', 'unset'), 'polars' in sys.modules)")
    environ = {k: v for k, v in os.environ.items() if k != "POLARS_MAX_THREADS"}
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                         env=dict(environ, PYTHONPATH=ROOT), check=True).stdout.split()
    assert out[0] != "unset" and out[1] == "False"
