"""The wheel's and the ball's fit checked against the whole wall
(docs/surfaces.md eqs. S4g, S7g): on cones (so the drum) the local fits S4
and S7 are the whole fit, and on a profile the global check agrees with a
brute force that samples the rim or the ball's surface densely.

The brute forces here do not use the code's fit: on a cone, a point is
inside the solid when its distance from the axis is below the wall's
radius at its height, R + z cot(beta) >= 0 (below the apex); on a profile,
when the ground's own clearance of the point is not negative (or the point
is above the wall's top)."""

import numpy as np
import pytest

from deathsphere.physics import revolution
from deathsphere.physics.ground import Cone, Cylinder, Profile
from deathsphere.physics.status import Reason

G = 9.81
#: rim samples of the brute force on a cone (the whole circle)
RIM = np.linspace(0.0, 2 * np.pi, 10_001)[1:-1]
WHEEL_NO_FIT = (Reason.SURFACE_NO_FIT, Reason.BELOW_FLOOR, Reason.RIM_CROSSES_WALL)
WHEEL_NO_FIT_OUTSIDE = (Reason.SURFACE_NO_FIT_OUTSIDE,)
BALL_NO_FIT = (Reason.BALL_NO_FIT_MERIDIAN, Reason.BELOW_FLOOR, Reason.BALL_CROSSES_WALL)


def _rim(rho0, z0, alpha, a, s):
    """The rim's points (x, y, z) at angles s from the contact (lanes x angles):
    built from the wheel's centre C = P - a e3 and its plane (e3, e_phi)."""
    e3_x, e3_z = np.cos(alpha)[:, None], -np.sin(alpha)[:, None]
    c_x, c_z = rho0[:, None] - a[:, None] * e3_x, z0[:, None] - a[:, None] * e3_z
    x = c_x + a[:, None] * np.cos(s) * e3_x
    z = c_z + a[:, None] * np.cos(s) * e3_z
    y = a[:, None] * np.sin(s)
    return x, y, z


def _inside_cone(cone, x, y, z):
    """Depth inside the infinite solid cone (its lower nappe; positive inside):
    R(z) - rho where the wall's radius R(z) = R + z cot(beta) is not negative."""
    beta = cone.wall_angle_rad
    wall = cone.radius + z * (np.cos(beta) / np.sin(beta))
    return np.where(wall >= 0, wall - np.hypot(x, y), -np.hypot(x, y) - np.abs(wall))


def _lanes(rng, top, n, a_max):
    height = rng.uniform(0.0, top, n)
    alpha = rng.uniform(-np.pi, np.pi, n)
    a = rng.uniform(0.05, a_max, n)
    return height, alpha, a


CONES = [Cone(2.0, np.radians(45.0)), Cone(3.0, np.radians(80.0)), Cone(2.5, np.radians(90.0)),
         Cone(2.0, np.radians(100.0)), Cylinder(2.5)]


@pytest.mark.parametrize("cone", CONES, ids=["board45", "well80", "upright90", "lean100", "drum"])
def test_on_a_cone_the_local_fit_is_the_whole_fit(cone):
    """S4 and the floor (S5) decide exactly what 10^4 rim points inside the
    infinite cone (below its apex) and above the floor decide."""
    rng = np.random.default_rng(11)
    top = min(getattr(cone, "apex_height", np.inf), 6.0)
    height, alpha, a = _lanes(rng, top, 300, 3.0)
    res = revolution.wheel_orbit(cone, height, alpha, a, 0.5, G)
    rho0, z0 = cone.contact(height)
    x, y, z = _rim(rho0, z0, alpha, a, RIM)
    solid = cone if isinstance(cone, Cone) else Cone(cone.radius, np.pi / 2)
    depth = _inside_cone(solid, x, y, z)
    inside = (depth.min(axis=1) >= -1e-9 * a) & (z.min(axis=1) >= -1e-9 * a)
    fits = ~np.isin(res["reason"], WHEEL_NO_FIT)
    assert 20 < fits.sum() < 280                              # both verdicts are tested
    assert np.array_equal(fits, inside)
    assert not np.any(res["reason"] == Reason.RIM_CROSSES_WALL)


@pytest.mark.parametrize("beta_deg", [100.0, 150.0])
def test_outside_a_cone_a_fitting_wheel_stays_outside(beta_deg):
    """Outside a cone leaning in, S4 (sin(alpha + beta) < 0) holds exactly
    when no point of the wheel's disc (its rim and 4 circles within it, 2000
    points each) lies inside the solid cone: the disc lies beyond the
    tangent plane of a convex solid.  (The rim alone can clear the roof with
    sin(alpha + beta) > 0, a hoop round it, while its disc cuts in.)"""
    cone = Cone(3.0, np.radians(beta_deg))
    rng = np.random.default_rng(5)
    height, alpha, a = _lanes(rng, 0.9 * cone.apex_height, 200, 2.0)
    res = revolution.wheel_orbit(cone, height, alpha, a, 0.5, G, outside=True)
    rho0, z0 = cone.contact(height)
    deepest = np.full(height.shape, -np.inf)
    for fraction in np.linspace(0.2, 1.0, 5):        # circles of the disc about its centre, nearest the contact first
        centre_shift = a * (1.0 - fraction)
        x, y, z = _rim(rho0 - centre_shift * np.cos(alpha), z0 + centre_shift * np.sin(alpha), alpha,
                       fraction * a, RIM[::5])
        deepest = np.maximum(deepest, _inside_cone(cone, x, y, z).max(axis=1))
    outside = deepest <= 1e-9 * a
    fits = ~np.isin(res["reason"], WHEEL_NO_FIT_OUTSIDE)
    assert 20 < fits.sum() < 280
    assert np.array_equal(fits, outside)


def _sphere_points(n):
    """n points spread over the unit sphere (a Fibonacci lattice)."""
    i = np.arange(n) + 0.5
    z = 1 - 2 * i / n
    phi = np.pi * (1 + 5 ** 0.5) * i
    r = np.sqrt(1 - z * z)
    return r * np.cos(phi), r * np.sin(phi), z


@pytest.mark.parametrize("cone", CONES[:4], ids=["board45", "well80", "upright90", "lean100"])
def test_a_ball_fits_a_cone_where_its_surface_does(cone):
    """S7 (a < rho / sin(beta)) and the floor are the ball's whole fit in a
    cone: 10^4 points of its surface inside the solid and above the floor."""
    rng = np.random.default_rng(7)
    top = min(cone.apex_height, 6.0)
    height, a = rng.uniform(0.0, top, 200), rng.uniform(0.05, 6.0, 200)
    res = revolution.ball_orbit(cone, height, 30.0, a, branch=0)
    rho0, z0 = cone.contact(height)
    beta = cone.wall_angle_rad
    rho_c, z_c = rho0 - a * np.sin(beta), z0 + a * np.cos(beta)
    ux, uy, uz = _sphere_points(10_000)
    x = rho_c[:, None] + a[:, None] * ux
    y = a[:, None] * uy
    z = z_c[:, None] + a[:, None] * uz
    inside = (_inside_cone(cone, x, y, z).min(axis=1) >= -1e-9 * a) & (z.min(axis=1) >= -1e-9 * a)
    fits = ~np.isin(res["reason"], BALL_NO_FIT)
    assert 10 < fits.sum() < 190
    assert np.array_equal(fits, inside)


# a profile with a neck: a wheel or a ball that fits the wall's bend at its
# contact can still reach the far side of the neck or the bulge above it
NECK = Profile(2.0 - 0.9 * np.sin(0.9 * np.linspace(0.0, 6.0, 121)), np.linspace(0.0, 6.0, 121))


def _profile_margin(profile, x, y, z, side):
    """side * clearance of each point, or its height past the wall's ends (nothing there to hit)."""
    top = profile.lowest + profile.highest_lane
    c = side * profile.clearance(np.hypot(x, y), z)
    return np.maximum(c, np.maximum(z - top, profile.lowest - z))


@pytest.mark.parametrize("outside", [False, True])
def test_on_a_profile_the_rim_fits_where_dense_samples_do(outside):
    """The global check (the tangent ball, then certified sampling) against
    the rim sampled at 5000 points a half (the rim is symmetric about the
    contact's meridian plane: 10^4 on the whole rim) with the profile's own
    clearance (outside, the disc: the rim and four circles within it), on lanes chosen to test every stage: rims held by the tangent
    ball or the tangent cone, rims sampled that fit and rims that cross the
    wall away from the contact."""
    rng = np.random.default_rng(3)
    height, alpha, a = _lanes(rng, NECK.highest_lane, 4000, 2.5)
    res = revolution.wheel_orbit(NECK, height, alpha, a, 0.5, G, outside=outside)
    local = ~np.isin(res["reason"], WHEEL_NO_FIT + WHEEL_NO_FIT_OUTSIDE) | (res["reason"] == Reason.RIM_CROSSES_WALL)
    crossing = np.flatnonzero(res["reason"] == Reason.RIM_CROSSES_WALL)
    reach = NECK.tangent_ball_radius(height, outside)
    tilt = np.abs(np.sin(alpha + res["wall_angle"]))
    rise = 2 * a * np.sin(alpha)
    z0 = res["z_contact"]
    cone = ~outside & NECK.bends_out(z0 + np.minimum(rise, 0), z0 + np.maximum(rise, 0))
    ball = a <= 0.98 * reach * tilt
    sampled = np.flatnonzero(local & (res["reason"] != Reason.RIM_CROSSES_WALL) & ~ball & ~cone)
    held = np.flatnonzero(local & (ball | cone))
    assert crossing.size >= 5 and sampled.size >= 5 and held.size >= 5
    pick = np.concatenate((crossing[:16], sampled[:16], held[:8]))
    rho0, z0 = NECK.contact(height[pick])
    s = np.linspace(0.125, np.pi, 5000)
    margin = np.full(pick.size, np.inf)
    # inside, the rim; outside, the whole disc (the rim and circles within it about its centre)
    for fraction in ((0.2, 0.4, 0.6, 0.8, 1.0) if outside else (1.0,)):
        shift = a[pick] * (1.0 - fraction)
        x, y, z = _rim(rho0 - shift * np.cos(alpha[pick]), z0 + shift * np.sin(alpha[pick]), alpha[pick],
                       fraction * a[pick], s if fraction == 1.0 else np.linspace(0.0, np.pi, 1000))
        margin = np.minimum(margin, _profile_margin(NECK, x, y, z, -1.0 if outside else 1.0).min(axis=1))
    inside = margin >= -1e-7 * a[pick]
    assert np.array_equal(res["reason"][pick] != Reason.RIM_CROSSES_WALL, inside)


def test_on_a_profile_the_ball_fits_where_its_surface_does():
    """The ball in the necked profile: the global check against 10^4 points
    of its surface and the profile's own clearance."""
    rng = np.random.default_rng(9)
    height, a = rng.uniform(0.0, NECK.highest_lane, 3000), rng.uniform(0.05, 2.0, 3000)
    res = revolution.ball_orbit(NECK, height, 30.0, a, branch=0)
    crossing = np.flatnonzero(res["reason"] == Reason.BALL_CROSSES_WALL)
    fitting = np.flatnonzero(~np.isin(res["reason"], BALL_NO_FIT))
    near = fitting[a[fitting] > 0.9 * NECK.tangent_ball_radius(height[fitting])]
    assert crossing.size >= 5 and near.size >= 5
    pick = np.concatenate((crossing[:8], near[:8], fitting[:4]))
    rho0, z0 = NECK.contact(height[pick])
    beta = NECK.wall_angle(height[pick])
    rho_c, z_c = rho0 - a[pick] * np.sin(beta), z0 + a[pick] * np.cos(beta)
    ux, uy, uz = _sphere_points(10_000)
    x = rho_c[:, None] + a[pick, None] * ux
    y = a[pick, None] * uy
    z = z_c[:, None] + a[pick, None] * uz
    inside = _profile_margin(NECK, x, y, z, 1.0).min(axis=1) >= -1e-7 * a[pick]
    assert np.array_equal(res["reason"][pick] != Reason.BALL_CROSSES_WALL, inside)


@pytest.mark.parametrize("beta_deg", [45.0, 80.0, 100.0])
def test_a_profile_sampled_from_a_cone_gives_the_cones_verdicts(beta_deg):
    """Away from the boundary of S4 (its margin over 1e-3), a cone sampled
    at 101 points gives the cone's statuses and reasons: the global check
    finds nothing the cone's proof does not."""
    cone = Cone(3.0, np.radians(beta_deg), 5.0)
    top = min(cone.highest_lane, 5.0)
    rho, z = cone.contact(np.linspace(0.0, top, 101))
    profile = Profile(rho, z)
    rng = np.random.default_rng(1)
    height, alpha, a = _lanes(rng, top, 3000, 2.5)
    exact = revolution.wheel_orbit(cone, height, alpha, a, 0.5, G, mu=0.8)
    sampled = revolution.wheel_orbit(profile, height, alpha, a, 0.5, G, mu=0.8)
    rho0 = cone.contact(height)[0]
    margin = np.sin(alpha + cone.wall_angle_rad) - a * np.sin(cone.wall_angle_rad) / rho0
    lowest = cone.contact(height)[1] + a * np.sin(alpha) - a * np.abs(np.sin(alpha))      # the rim's, S5
    clear = (np.abs(margin) > 1e-3) & (np.abs(lowest) > 1e-6)
    assert np.array_equal(exact["status"][clear], sampled["status"][clear])
    assert np.array_equal(exact["reason"][clear], sampled["reason"][clear])
    assert not np.any(sampled["reason"] == Reason.RIM_CROSSES_WALL)


def test_the_tangent_ball_of_simple_profiles():
    """A sampled sphere's tangent ball is the sphere (to the sampling's
    1e-4), and its bound on the wall's bend 1/R with the quarter's margin; a
    sampled cone's tangent ball is the tangent sphere of the lane, rho /
    sin(beta) (a ball tangent to the wall, centred on the axis, touching the
    far side)."""
    u = np.linspace(0.0, np.pi, 401)
    globe = Profile(2.0 * np.sin(u), -2.0 * np.cos(u))
    h = np.linspace(0.2, 3.8, 9)
    assert np.allclose(globe.tangent_ball_radius(h), 2.0, rtol=1e-4)
    # the bound on the wall's principal curvatures: the sphere's 1/R, and a quarter more
    assert abs(globe.bend_bound() - 1.25 / 2.0) < 1e-4
    cone = Cone(3.0, np.radians(80.0))
    rho, z = cone.contact(np.linspace(0.0, 6.0, 61))
    profile = Profile(rho, z)
    h = np.linspace(0.5, 5.5, 11)
    expected = cone.contact(h)[0] / np.sin(cone.wall_angle_rad)
    assert np.allclose(profile.tangent_ball_radius(h), expected, rtol=2e-3)


def test_one_lane_at_a_time_gets_the_verdicts_of_the_batch():
    # a single lane is a 0-d request: the global check takes it as the batch's element
    rng = np.random.default_rng(5)
    height, alpha, a = _lanes(rng, NECK.highest_lane, 400, 2.5)
    batch = revolution.wheel_orbit(NECK, height, alpha, a, 0.5, G)["reason"]
    crossing = np.flatnonzero(batch == Reason.RIM_CROSSES_WALL)[:3]
    others = np.flatnonzero(batch != Reason.RIM_CROSSES_WALL)[:3]
    assert crossing.size == 3
    for i in np.concatenate((crossing, others)):
        one = revolution.wheel_orbit(NECK, height[i], alpha[i], a[i], 0.5, G)["reason"]
        assert np.shape(one) == () and one == batch[i]
