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


def test_the_egg_loop_example_binds_below_the_top_as_the_eggs_own_curve_says():
    """The least top speed inside the egg of examples/egg.csv, against a brute
    force over its analytic meridian (rho = 3 sin u, z = 4 cos u + 0.8
    cos^2 u): the largest of S10's bounds -g n_z / kappa_C - 2 g (z_C,top -
    z_C) / (2k+1) lies below the pointed top, so a speed above the top's own
    sqrt(g / kappa_C) still loses the wall."""
    header, *rows = run_example("egg_loop.sh")
    assert header == "v_top_m_s,status,v_top_min_m_s,mu_required,period_s"
    table = [row.split(",") for row in rows]
    A, B, C, a, k, g = 3.0, 4.0, 0.8, 0.3, 0.5, 9.80665
    u = np.linspace(0.0, np.pi, 200001)                      # from the top down the descent
    x1, z1 = A * np.cos(u), -np.sin(u) * (B + 2 * C * np.cos(u))
    x2, z2 = -A * np.sin(u), -np.cos(u) * (B + 2 * C * np.cos(u)) + 2 * C * np.sin(u) ** 2
    speed = np.hypot(x1, z1)
    kappa = np.abs(x1 * z2 - z1 * x2) / speed ** 3
    n_z = -x1 / speed                                        # the inward normal's vertical part
    kappa_c = kappa / (1 - a * kappa)
    z_c = B * np.cos(u) + C * np.cos(u) ** 2 + a * n_z
    bound = -g * n_z / kappa_c - 2 * g * (z_c[0] - z_c) / (2 * k + 1)
    least, top_own = np.sqrt(bound.max()), np.sqrt(bound[0])
    assert np.argmax(bound) > 0 and least > top_own
    np.testing.assert_allclose([float(r[2]) for r in table], least, rtol=2e-5)
    v0, status0 = float(table[0][0]), table[0][1]
    assert top_own < v0 < least and status0 == "no_contact"
    assert all(r[1] in ("ok", "slips") for r in table[1:])
    assert all((float(r[3]) <= 0.8) == (r[1] == "ok") for r in table[1:])
