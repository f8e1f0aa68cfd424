"""A grid too large to hold is refused from the counts of its ranges, before
anything is built: one line, exit status 2, no traceback, and the process
stays small (its peak resident memory, measured by a parent process)."""

import json
import os
import subprocess
import sys
import tracemalloc

import numpy as np
import pytest

import deathsphere
from deathsphere.params import ParameterError

#: Reports the command's exit status, stderr and peak memory (kB) as JSON.
PROBE = """
import json, resource, subprocess, sys
done = subprocess.run([sys.executable, "-m", "deathsphere", *sys.argv[1:]], capture_output=True, text=True)
print(json.dumps([done.returncode, done.stderr, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss]))
"""
#: Far above an interpreter with numpy loaded, far below any of these grids.
PEAK_KB = 300_000


@pytest.mark.parametrize("args, words", [
    ("ride --vertical --theta 0:180:0.01 --v-top 0:100:0.01", "ride --vertical holds at most"),
    ("ride --theta 90 --speed 1:1000000:0.001", "up to 8 rows each"),
    ("ride --height 0:2:0.00001m --speed 1:100:0.001 --summary", "up to 8 rows each"),
    ("ride --theta 0:180:0.001 --alpha 0:100:0.01 --mu 0.8 --mu 1", "holds at most"),
    ("stability --theta 0:180:0.0000002 --alpha 10", "use 'deathsphere sweep'"),
    ("limits --theta 0:180:0.0000002", "split the theta range"),
])
def test_a_grid_too_large_is_refused_in_one_line_before_it_is_built(args, words):
    env = dict(os.environ, NO_COLOR="1")
    out = subprocess.run([sys.executable, "-c", PROBE, *args.split(), "--format", "csv"], capture_output=True,
                         text=True, env=env, check=True).stdout
    status, stderr, peak_kb = json.loads(out)
    assert status == 2
    assert stderr.count("\n") == 1 and "Traceback" not in stderr and words in stderr
    assert "deathsphere." not in stderr.replace("'deathsphere ", "")  # a command to run, not a Python function
    assert peak_kb < PEAK_KB


#: A shell pipeline: the command's first rows, then the reader goes away.
HEAD = """
import json, resource, subprocess, sys
done = subprocess.run(["sh", "-c", '"$0" -m deathsphere "$@" --format csv | head -n 3', sys.executable,
                       *sys.argv[1:]], capture_output=True, text=True)
print(json.dumps([done.returncode, done.stdout, done.stderr, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss]))
"""


@pytest.mark.parametrize("args", [
    "ride --theta 0:180:0.001 --alpha 0:100:0.001",
    "ride --theta 0:180:0.1 --speed 1:100:0.1",
])
def test_a_grid_of_orbits_too_large_to_hold_is_streamed(args):
    """ride's orbits (one mu) stream chunk by chunk as sweep's do: the first
    rows come at once, memory stays flat, and a reader that goes away ends
    the run quietly (the rider's table and a range of mu, which hold the
    grid, and one axis longer than ride holds, which is checked whole before
    the first row, are refused above instead)."""
    env = dict(os.environ, NO_COLOR="1")
    out = subprocess.run([sys.executable, "-c", HEAD, *args.split()], capture_output=True, text=True, env=env,
                         check=True, timeout=120).stdout
    status, stdout, stderr, peak_kb = json.loads(out)
    assert status == 0 and "Traceback" not in stderr
    lines = stdout.splitlines()
    assert len(lines) == 3 and lines[0].startswith("input_row,machine,theta_deg")
    assert peak_kb < PEAK_KB


@pytest.mark.parametrize("call", [
    lambda: deathsphere.ride(np.zeros((200_000, 1)), np.zeros((1, 100_000)), machine="stunt125"),
    lambda: deathsphere.ride(90, speed=np.ones(300_000), machine="stunt125"),
    lambda: deathsphere.ride(np.zeros((200_000, 1)), vertical=True, v_top=np.ones((1, 100_000)),
                             machine="stunt125"),
    lambda: deathsphere.limits(theta=np.zeros((200_000, 1)), a=np.full((1, 100_000), 0.3)),
])
def test_the_api_refuses_from_the_shapes_alone(call):
    tracemalloc.start()
    try:
        with pytest.raises(ParameterError, match="(ride|limits).* holds at most"):
            call()
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 50_000_000  # the inputs are 4 MB; their broadcast would be 160 GB


def test_a_grid_within_the_limit_still_runs():
    t = deathsphere.ride(np.array([60.0, 90.0])[:, None], speed=np.array([8.0, 10.0])[None, :], machine="stunt125",
                         stability=False)
    assert len(t) >= 4
