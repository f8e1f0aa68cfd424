"""The allowed tilts on a lane of any ground and the lowest and highest
lanes: checked against a brute-force scan of ``orbit(surface=...)`` over a
fine alpha grid, against the globe's own region code on the sphere, and
against closed forms (the drum's rule mu_required = g r'/v^2, the globe's
theta* = pi/2 + atan(1/G) - atan(mu))."""

import math

import numpy as np
import pytest
from scipy.optimize import brentq

import deathsphere
from deathsphere.physics import lane_region, region
from deathsphere.physics.ground import Cone, Cylinder, Plane, Profile, Sphere

G0 = 9.80665
A, K = 0.3, 0.5
DRUM = Cylinder(4.8768, 6.0)
CONE = Cone(3.0, math.radians(80.0), 8.0)


def _bowl(n=200, radius=5.0):
    """A bowl sampled from a sphere of ``radius``, bottom up to 20 deg from the top."""
    theta = np.linspace(np.pi, np.radians(20.0), n)
    return Profile(radius * np.sin(theta), radius * np.cos(theta))


def _brute_ends(surface, lane, mu, max_g, step_deg=0.004, **shape):
    """Interval ends of the feasible tilts [deg] from orbit's status over a
    fine alpha grid: the grid points where ok-ness changes."""
    alpha = np.arange(-179.9987, 180.0, step_deg)
    t = deathsphere.orbit(alpha=alpha, surface=surface, mu=mu, max_g=max_g, stability=False, **lane, **shape)
    ok = np.asarray(t["status"]) == "ok"
    change = np.flatnonzero(np.diff(ok.astype(int)))
    return alpha[change] + 0.5 * step_deg, ok


BOWL = _bowl()

CASES = [
    ("cylinder", {"height": 2.0}, {"diameter": 9.7536, "wall_height": 6.0}, DRUM, 2.0, 1.0, 4.0),
    ("cone", {"height": 3.0}, {"diameter": 6.0, "wall_angle": 80.0, "wall_height": 8.0}, CONE, 3.0, 0.8, 5.0),
    ("cone", {"height": 1.0}, {"diameter": 6.0, "wall_angle": 30.0, "wall_height": 8.0},
     Cone(3.0, math.radians(30.0), 8.0), 1.0, math.inf, 3.0),
    ("plane", {"turn_radius": 5.0}, {}, Plane(), 5.0, 1.0, math.inf),
    ("profile", {"height": 3.0}, {"profile": BOWL}, BOWL, 3.0, 1.0, 5.0),
]


@pytest.mark.parametrize("surface, lane, shape, ground, height, mu, max_g", CASES)
def test_interval_ends_match_a_brute_force_scan_of_orbit(surface, lane, shape, ground, height, mu, max_g):
    ends, ok = _brute_ends(surface, lane, mu, max_g, **shape)
    iv = lane_region.allowed_alpha_on(ground, height, A, K, G0, False, mu, max_g)
    found = np.rad2deg(np.concatenate([[lo, hi] for lo, hi, _, _ in iv.intervals()]))
    assert ok.any() and found.size == ends.size
    assert np.max(np.abs(found - ends)) < 0.004          # the grid's resolution


@pytest.mark.parametrize("surface, lane, shape, ground, height, mu, max_g", CASES)
def test_speed_range_bounds_the_speeds_orbit_reports(surface, lane, shape, ground, height, mu, max_g):
    (lo, hi, vmin, vmax), = lane_region.allowed_alpha_on(ground, height, A, K, G0, False, mu, max_g).intervals()
    # a grid, and tilts just inside both ends (where the range's bounds are approached)
    alpha = np.concatenate([np.arange(-179.99, 180.0, 0.02), np.rad2deg([lo, hi]) + [1e-6, -1e-6]])
    t = deathsphere.orbit(alpha=alpha, surface=surface, mu=mu, max_g=max_g, stability=False, **lane, **shape)
    ok = np.asarray(t["status"]) == "ok"
    v = np.asarray(t["v_cm_m_s"])[ok]
    assert vmin <= v.min() + 1e-9 and v.max() <= vmax + 1e-9
    # the bounds are tight: the grid comes within its spacing's effect of both
    assert v.min() - vmin < 1e-2 * vmin + 1e-3 and (not math.isfinite(vmax) or vmax - v.max() < 1e-2 * vmax)


def test_the_globe_through_the_general_path_is_the_globes_region():
    globe = Sphere(1.0)
    theta = np.deg2rad(np.array([3.0, 10, 30, 60, 90, 120, 170, 177]))
    for outside in (False, True):
        for mu, max_g in ((math.inf, math.inf), (1.0, 5.0), (1.2, math.inf), (math.inf, 3.0)):
            general = lane_region.allowed_alpha_on(globe, globe.height(theta), 0.1, K, G0, outside, mu, max_g)
            own = region.allowed_alpha(theta, 0.1, 1.0, K, G0, outside, mu, max_g)
            assert np.array_equal(general.count, own.count)
            for name in ("lo", "hi"):
                assert np.nanmax(np.abs(getattr(general, name) - getattr(own, name)), initial=0) < 1e-12
            for name in ("speed_min", "speed_max"):
                # compared squared: v_cm^2 is what eq. (29) gives; near alpha = 90 deg v_cm ~ sqrt(cot alpha)
                # turns a 1e-16 rad difference of the end into 1e-8 m/s
                x, y = getattr(general, name) ** 2, getattr(own, name) ** 2
                same = np.isfinite(y)
                assert np.array_equal(np.isfinite(x), same)
                assert np.all(np.abs(x[same] - y[same]) <= 1e-12 * np.maximum(1.0, y[same]))


def test_the_drum_ends_are_its_friction_and_load_rules():
    """On an upright wall mu_required = g r'/v^2 and the centre's acceleration
    is v^2/(g r'): the ends solve r' C / (S D) = 1/mu and = G (S2)."""
    mu, max_g = 1.0, 4.0
    big_g = math.sqrt(max_g ** 2 - 1)

    def accel_g(alpha):                      # v^2 / (g r') = r' Omega^2 / g, from eq. (29)
        rp = DRUM.radius - A * math.cos(alpha)
        return rp * math.cos(alpha) / (math.sin(alpha) * ((2 * K + 1) * rp + K * A * math.cos(alpha)))

    lo = brentq(lambda x: accel_g(x) - big_g, 1e-6, 1.5)
    hi = brentq(lambda x: accel_g(x) - 1 / mu, 1e-6, 1.5)
    for height in (0.0, 2.0, 6.0):
        (got_lo, got_hi, vmin, vmax), = lane_region.allowed_alpha_on(DRUM, height, A, K, G0, False, mu,
                                                                     max_g).intervals()
        assert abs(got_lo - lo) < 1e-9 and abs(got_hi - hi) < 1e-9
        rp_hi, rp_lo = DRUM.radius - A * math.cos(hi), DRUM.radius - A * math.cos(lo)
        assert vmin == pytest.approx(math.sqrt(G0 * rp_hi / mu), rel=1e-9)
        assert vmax == pytest.approx(math.sqrt(big_g * G0 * rp_lo), rel=1e-9)


def test_a_drum_has_no_highest_lane_but_its_top():
    with_top = lane_region.lane_range(DRUM, A, K, G0, False, 1.0, 4.0)
    assert (with_top.lowest, with_top.highest, with_top.lowest_bound, with_top.highest_bound) == (
        0.0, 6.0, "floor", "top")
    no_top = lane_region.lane_range(Cylinder(4.8768), A, K, G0, False, 1.0, 4.0)
    assert no_top.highest == math.inf and no_top.highest_bound == "none"
    # friction too small for any tilt: mu_required = g r'/v^2 >= 1/G for every speed the load allows
    assert lane_region.allowed_alpha_on(DRUM, [0.0, 3.0, 6.0], A, K, G0, False, 0.2, 4.0).count.tolist() == [0] * 3


def test_the_highest_lane_in_a_bowl_is_the_globes_closed_form():
    """docs/limits.md sec. 4: theta* = pi/2 + atan(1/G) - atan(mu) inside a
    sphere; the bowl sampled from it has its highest lane at r (1 + cos theta*)."""
    radius, a, mu, max_g = 5.0, 0.5, 1.0, 5.0
    theta_star = math.pi / 2 + math.atan(1 / math.sqrt(max_g ** 2 - 1)) - math.atan(mu)
    found = lane_region.lane_range(_bowl(400, radius), a, K, G0, False, mu, max_g)
    assert found.highest_bound == "limits"
    assert found.highest == pytest.approx(radius * (1 + math.cos(theta_star)), abs=1e-4)
    # and the lowest is the bottom of the bowl, approached (the sphere's pole: the globe's lower corner)
    assert found.lowest_bound == "floor" and found.lowest == 0.0


def test_a_cone_leaning_in_ends_at_its_apex_or_at_its_limits():
    cone = Cone(3.0, math.radians(100.0))            # leaning in: the apex at 3 tan(80 deg) = 17 m
    found = lane_region.lane_range(cone, A, K, G0, False, 1.0, 4.0)
    assert found.found and found.highest <= cone.highest_lane
    # the bound found is a change of feasibility: a lane just below is feasible, just above not
    if found.highest_bound == "limits":
        below, above = lane_region.allowed_alpha_on(cone, [found.highest - 1e-6, found.highest + 1e-6], A, K, G0,
                                                    False, 1.0, 4.0).count
        assert below > 0 and above == 0


def test_lanes_off_the_wall_have_no_interval_and_no_warning():
    with np.errstate(all="raise"):
        iv = lane_region.allowed_alpha_on(DRUM, [-1.0, 7.0, np.nan, 3.0], A, K, G0)
    assert iv.count.tolist() == [0, 0, 0, 1]


def test_boundaries_on_a_lane_are_zeros_of_their_conditions():
    """Each S3 (contact) boundary changes the sign of orbit's normal force and
    each mu boundary puts mu_required at mu."""
    b = lane_region.lane_boundaries(CONE, np.array([1.0, 4.0]), A, K, mu=0.8)
    checked = 0
    for j, height in enumerate((1.0, 4.0)):
        for alpha in b["S3"][j][np.isfinite(b["S3"][j])]:
            t = deathsphere.orbit(alpha=np.rad2deg([alpha - 1e-7, alpha + 1e-7]), surface="cone", diameter=6.0,
                                  wall_angle=80.0, wall_height=8.0, height=height, stability=False)
            n = np.asarray(t["normal_per_mass_m_s2"], dtype=float)
            if np.all(np.isfinite(n)):           # the curve also runs where the wheel does not fit
                assert n[0] * n[1] < 0
                checked += 1
        for alpha in b["mu"][j][np.isfinite(b["mu"][j])]:
            t = deathsphere.orbit(alpha=np.rad2deg(alpha), surface="cone", diameter=6.0, wall_angle=80.0,
                                  wall_height=8.0, height=height, stability=False)
            assert float(t["mu_required"]) == pytest.approx(0.8, rel=1e-8)
            checked += 1
    assert checked >= 4
