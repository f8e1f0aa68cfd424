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
    ("ride --theta 0:180:0.01 --alpha 0:100:0.01", "1.8e+08 orbits"),
    ("ride --theta 0:180:0.001 --alpha 0:100:0.001", "1.8e+10 orbits"),
    ("ride --vertical --theta 0:180:0.01 --v-top 0:100:0.01", "ride --vertical holds at most"),
    ("stability --theta 0:180:0.0000002 --alpha 10", "use 'deathsphere sweep'"),
    ("ride --theta 90 --speed 1:1000000:0.001", "up to 8 rows each"),
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
