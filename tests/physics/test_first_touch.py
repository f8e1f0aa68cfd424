"""A flight's landing on a profile whose gap to the wall is not concave: a
narrow ledge between two of the scan's instants is found (its Lipschitz
bound, physics/first_touch.py), against the ledge's own closed form and a
brute force over densely sampled times; on the drum the bracket is the
scan's."""

import functools
import math

import numpy as np
import pytest

from deathsphere.physics.first_touch import first_crossing
from deathsphere.physics.ground import Cylinder, Profile
from deathsphere.physics.landing import SCAN, landing_on

G = 9.81
R, LEDGE, WIDTH, AT = 3.0, 0.02, 0.01, 1.0     # a drum with a ledge 2 cm deep, its flanks 1 cm wide, 1 m up


@functools.lru_cache(maxsize=1)
def _ledge_profile():
    """rho(z) = R - LEDGE exp(-((z - AT)/WIDTH)^2), sampled finely over the ledge."""
    z = np.unique(np.concatenate((np.linspace(0.0, 0.9, 19), np.linspace(0.9, 1.1, 801), np.linspace(1.1, 2.5, 15))))
    return Profile(R - LEDGE * np.exp(-((z - AT) / WIDTH) ** 2), z)


def test_a_drop_onto_a_narrow_ledge_is_found_between_the_scans_instants():
    ground = _ledge_profile()
    rho0, z0 = R - 0.5 * LEDGE, 2.0                 # half the ledge's depth in from the wall, 2 m up, at rest
    # the ledge's upper flank reaches rho0 where exp(-((z - AT)/WIDTH)^2) = 1/2
    z_hit = AT + WIDTH * math.sqrt(math.log(2.0))
    t_hit = math.sqrt(2.0 * (z0 - z_hit) / G)
    t_floor = math.sqrt(2.0 * z0 / G)
    # the scan alone sees nothing before the floor: every scanned instant is inside
    ts = t_floor * np.arange(1, SCAN) / SCAN
    assert (ground.clearance(np.full_like(ts, rho0), z0 - 0.5 * G * ts ** 2) > 0).all()
    land = landing_on(np.array([[rho0], [0.0], [z0]]), np.zeros((3, 1)), ground, G)
    assert not land["on_floor"][0]
    assert land["t_land"][0] == pytest.approx(t_hit, abs=2e-6)
    assert land["x_land"][2, 0] == pytest.approx(z_hit, abs=2e-5)


def test_a_flight_clipping_the_ledge_against_a_brute_force_over_sampled_times():
    """A rider's centre of mass drifting out towards the wall clips the ledge's
    top: the scan's first instant past the wall is 0.08 s later, below it."""
    ground = _ledge_profile()
    x0, v0 = np.array([[2.9], [0.0], [1.6]]), np.array([[0.235], [0.2], [0.0]])
    land = landing_on(x0, v0, ground, G)
    t = np.linspace(0.0, 0.45, 90001)               # 5 microseconds apart
    x = x0 + v0 * t - 0.5 * G * t ** 2 * np.array([[0.0], [0.0], [1.0]])
    gap = np.minimum(ground.clearance(np.hypot(x[0], x[1]), x[2]), x[2])
    t_brute = t[np.argmax(gap <= 0)]
    assert land["t_land"][0] == pytest.approx(t_brute, abs=5e-6)
    assert land["x_land"][2, 0] == pytest.approx(AT, abs=WIDTH)     # on the ledge
    t_scan = math.sqrt(2 * 1.6 / G) * np.arange(1, SCAN + 1) / SCAN
    xs = x0 + v0 * t_scan - 0.5 * G * t_scan ** 2 * np.array([[0.0], [0.0], [1.0]])
    first = t_scan[np.argmax(ground.clearance(np.hypot(xs[0], xs[1]), xs[2]) <= 0)]
    assert first > land["t_land"][0] + 0.05


def test_on_the_drum_the_bracket_is_the_scans():
    ground = Cylinder(R)
    x0, v0 = np.array([[2.0, 0.0], [0.0, 1.0], [1.5, 0.3]]), np.array([[0.0, 4.0], [5.0, 1.0], [0.0, 0.0]])
    t_max = np.sqrt(2 * x0[2] / G)
    ts = t_max[:, None] * np.arange(1, SCAN + 1) / SCAN

    def gap(rows, t):
        x = x0[:, rows] + v0[:, rows] * t - 0.5 * G * t * t * np.array([[0.0], [0.0], [1.0]])
        return np.minimum(ground.clearance(np.hypot(x[0], x[1]), x[2]), x[2])

    q = np.stack([gap(np.full(SCAN, i), ts[i]) for i in range(2)])
    q[:, -1] = np.minimum(q[:, -1], 0.0)
    first = np.argmax(q <= 0, axis=1)
    lo, hi = first_crossing(gap, ts, q, first, gap(np.arange(2), np.zeros(2)), np.full(2, 20.0))
    assert np.array_equal(hi, ts[np.arange(2), first]) and np.array_equal(lo, ts[np.arange(2), first - 1])
