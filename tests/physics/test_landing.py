"""Where a free flight meets a drum or a cone (deathsphere.physics.landing),
each against a derivation of its own: free fall to the floor and the drum's
chord in closed form, a brute-force root of the cone's implicit function
along the parabola, and the globe's quartic."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from deathsphere.physics import fall
from deathsphere.physics.ground import Cone, Cylinder, Sphere
from deathsphere.physics.landing import landing_on

G = 9.81
FT = 0.3048
R = 16 * FT                                   # a 32-foot drum


def _horizontal_starts(n, seed, r_max=R):
    """Starts inside the drum (radius 0.2..0.95 R, height 0.1..3.6 m) moving
    horizontally in any direction at 0..15 m/s."""
    rng = np.random.default_rng(seed)
    rho, phi, z = rng.uniform(0.2, 0.95, n) * r_max, rng.uniform(0, 2 * np.pi, n), rng.uniform(0.1, 12 * FT, n)
    speed, heading = rng.uniform(0.0, 15.0, n), rng.uniform(0, 2 * np.pi, n)
    x0 = np.stack([rho * np.cos(phi), rho * np.sin(phi), z])
    v0 = np.stack([speed * np.cos(heading), speed * np.sin(heading), np.zeros(n)])
    return x0, v0


def test_in_a_drum_he_falls_freely_to_the_floor_or_flies_the_chord_to_the_wall():
    x0, v0 = _horizontal_starts(400, 1)
    out = landing_on(x0, v0, Cylinder(R, 12 * FT), G)
    # free fall: the height reaches the floor at sqrt(2 h / g)
    t_floor = np.sqrt(2 * x0[2] / G)
    # the chord: the horizontal line p + u s meets |.| = R at s = -p.u + sqrt((p.u)^2 - |p|^2 + R^2)
    speed = np.hypot(v0[0], v0[1])
    u = v0[:2] / np.where(speed > 0, speed, 1.0)
    pu = np.sum(x0[:2] * u, axis=0)
    chord = -pu + np.sqrt(pu ** 2 - np.sum(x0[:2] ** 2, axis=0) + R * R)
    t_wall = np.where(speed > 0, chord / np.where(speed > 0, speed, 1.0), np.inf)
    want = np.minimum(t_floor, t_wall)
    assert np.all(out["status"] == fall.LANDS)
    assert out["t_land"] == pytest.approx(want, rel=1e-12, abs=1e-12)
    floor = t_floor < t_wall
    assert np.array_equal(out["on_floor"], floor) and 50 < floor.sum() < 350      # both ends are tried
    # the floor at the end of the free fall, the wall at the end of the chord
    assert out["x_land"][2][floor] == pytest.approx(0.0, abs=1e-9)
    wall_z = x0[2] - 0.5 * G * t_wall ** 2
    assert out["x_land"][2][~floor] == pytest.approx(wall_z[~floor], abs=1e-9)
    assert np.hypot(out["x_land"][0], out["x_land"][1])[~floor] == pytest.approx(R, rel=1e-12)
    # the horizontal path is the chord's direction: x_h = p + v t
    assert out["x_land"][:2] == pytest.approx(x0[:2] + v0[:2] * want, abs=1e-9)
    # the impact: g t down on the floor; on the wall the radial component of v
    assert out["impact_normal"][floor] == pytest.approx(G * want[floor], rel=1e-12)
    radial = np.sum(out["x_land"][:2] * v0[:2], axis=0) / R
    assert out["impact_normal"][~floor] == pytest.approx(radial[~floor], rel=1e-9)
    assert out["impact_speed"] == pytest.approx(np.hypot(speed, G * want), rel=1e-12)


def test_a_dead_stop_drops_straight_down_in_root_2h_over_g():
    x0 = np.array([[4.0, 0.0, 1.0], [0.0, -3.0, 0.5], [2.5, 0.7, 3.0]])
    out = landing_on(x0, np.zeros((3, 3)), Cylinder(R, 12 * FT), G)
    assert out["t_land"] == pytest.approx(np.sqrt(2 * x0[2] / G), rel=1e-14)
    assert out["x_land"][:2] == pytest.approx(x0[:2], abs=1e-15) and out["on_floor"].all()


def _cone_brute_force(x0, v0, beta, radius):
    """The first time the parabola leaves the well, found without the
    module: the cone's implicit function written here, F = (rho - radius)
    sin(beta) - z cos(beta) (< 0 inside), and the height above the floor,
    sampled on 20001 instants up to the fall to the floor, then brentq on
    the first sign change of max(F, -z)."""
    def point(t):
        return x0 + v0 * t - 0.5 * G * t * t * np.array([0.0, 0.0, 1.0])

    def outside(t):
        x = point(t)
        f = (math.hypot(x[0], x[1]) - radius) * math.sin(beta) - x[2] * math.cos(beta)
        return max(f, -x[2])

    t_end = (v0[2] + math.sqrt(v0[2] ** 2 + 2 * G * x0[2])) / G * (1 + 1e-9)      # just past the floor
    ts = np.linspace(0.0, t_end, 20001)
    xs = x0[:, None] + v0[:, None] * ts - 0.5 * G * ts ** 2 * np.array([[0.0], [0.0], [1.0]])
    vals = np.maximum((np.hypot(xs[0], xs[1]) - radius) * math.sin(beta) - xs[2] * math.cos(beta), -xs[2])
    k = int(np.argmax(vals[1:] >= 0)) + 1
    if vals[k] == 0.0:
        return ts[k]
    return brentq(outside, ts[k - 1], ts[k], xtol=1e-15, rtol=1e-15)


@pytest.mark.parametrize("beta_deg", [80.0, 60.0, 95.0])
def test_in_a_cone_the_landing_is_the_brute_force_root_of_its_implicit_function(beta_deg):
    beta = math.radians(beta_deg)
    cone = Cone(R, beta, 12 * FT)
    rng = np.random.default_rng(int(beta_deg))
    n = 12
    # inside the well at its own height (the wall at height z is at radius R + z cot(beta))
    z = rng.uniform(0.3, 3.0, n)
    wall = R + z / math.tan(beta)
    rho, phi = rng.uniform(0.3, 0.95, n) * wall, rng.uniform(0, 2 * np.pi, n)
    x0 = np.stack([rho * np.cos(phi), rho * np.sin(phi), z])
    v0 = rng.normal(size=(3, n)) * np.array([[8.0], [8.0], [2.0]])
    out = landing_on(x0, v0, cone, G)
    want = np.array([_cone_brute_force(x0[:, i], v0[:, i], beta, R) for i in range(n)])
    assert out["t_land"] == pytest.approx(want, rel=1e-9, abs=1e-12)
    f_land = -cone.clearance(np.hypot(out["x_land"][0], out["x_land"][1]), out["x_land"][2])
    assert np.minimum(np.abs(f_land), np.abs(out["x_land"][2])) == pytest.approx(0.0, abs=1e-9)


def test_on_the_globe_it_agrees_with_the_spheres_quartic():
    rng = np.random.default_rng(3)
    r = 2.4384
    d = rng.normal(size=(3, 200))
    x0 = d / np.linalg.norm(d, axis=0) * r * rng.uniform(0.3, 0.95, 200)
    v0 = rng.normal(size=(3, 200)) * 5.0
    globe = Sphere(r)
    general, quartic = landing_on(x0, v0, globe, G), fall.ballistic_landing(x0, v0, globe, G)
    assert general["t_land"] == pytest.approx(quartic["t_land"], rel=1e-10, abs=1e-12)
    assert general["x_land"] == pytest.approx(quartic["x_land"], abs=1e-9)
    assert not general["on_floor"].any() or np.all(general["x_land"][2][general["on_floor"]] <= -r + 1e-9)


def test_a_start_outside_or_not_finite_is_a_status_not_a_nan_leak():
    drum = Cylinder(R, 12 * FT)
    x0 = np.array([[R + 0.5, 1.0, np.nan, 1.0], [0.0, 0.0, 0.0, 0.0], [1.0, -0.2, 1.0, 1.0]])
    v0 = np.zeros((3, 4))
    out = landing_on(x0, v0, drum, np.array([G, G, G, 0.0]))
    assert list(out["status"]) == [fall.STARTS_OUTSIDE, fall.STARTS_OUTSIDE, fall.NOT_FLOWN, fall.NOT_FLOWN]
    assert np.isnan(out["t_land"]).all() and not out["on_floor"].any()
    empty = landing_on(np.zeros((3, 0)), np.zeros((3, 0)), drum, G)
    assert empty["t_land"].shape == (0,)


def test_a_start_on_the_wall_moving_out_lands_at_once_and_moving_in_flies():
    drum = Cylinder(R, 12 * FT)
    x0 = np.array([[R, R], [0.0, 0.0], [2.0, 2.0]])
    v0 = np.array([[1.0, -3.0], [2.0, 0.0], [0.0, 0.0]])
    out = landing_on(x0, v0, drum, G)
    assert out["t_land"][0] == pytest.approx(0.0, abs=1e-12)
    assert out["t_land"][1] == pytest.approx(math.sqrt(2 * 2.0 / G), rel=1e-12) and out["on_floor"][1]
