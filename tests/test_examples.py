"""The shell examples run as a user would run them, and their answers are
checked against the Python API by brute force."""

import os
import subprocess
import sys
from pathlib import Path

import numpy as np

from deathsphere import Setup

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def run_example(name, **env):
    path = os.path.dirname(sys.executable) + os.pathsep + os.environ["PATH"]
    proc = subprocess.run(["bash", str(EXAMPLES / name)], capture_output=True, text=True, check=True,
                          env={**os.environ, "PATH": path, **env}, timeout=120)
    return proc.stdout.strip().splitlines()


def test_highest_orbit_example_matches_brute_force():
    header, best = run_example("highest_orbit_mu1.sh", MAX_G="5")
    assert header == "theta_deg,alpha_deg,v_cm_m_s,load_g,mu_required"
    theta, alpha, v, load, mu = map(float, best.split(","))
    assert mu <= 1 and load <= 5
    grid = Setup(mu=1.0).orbit(np.arange(5, 90.25, 0.5)[:, None], np.arange(0.5, 60.25, 0.5)[None, :])
    # the load a rider feels: the centre's acceleration and gravity at right angles (eq. 32)
    feasible = (grid["status"] == "ok") & (np.hypot(1.0, grid["accel_g"]) <= 5)
    assert grid["theta_deg"][feasible].min() == theta


def test_the_wall_of_death_example_plan_reads_and_every_lane_is_ok():
    import deathsphere

    act = deathsphere.show(str(EXAMPLES / "wall_of_death.toml"))
    assert list(act.riders["status"]) == ["ok", "ok", "ok"]
