"""Steady orbits on any surface of revolution (deathsphere.physics.revolution,
docs/surfaces.md): the sphere through the general path is today's sphere
path; on the drum, the cone and flat ground every ok orbit satisfies
Newton's and Euler's equations written out with 3-d vectors here, rolls
without slipping, and its rim or ball stays inside the wall."""

import warnings

import numpy as np
import pytest

from deathsphere.physics import particle, revolution, sphere, wheel
from deathsphere.physics.ground import Cone, Cylinder, Plane, Sphere
from deathsphere.physics.status import Reason, Status

G = 9.81
R = 3.0
GLOBE = Sphere(R)
DRUM = Cylinder(4.8768, 6.0)          # a 32 ft drum
WELL = Cone(3.0, np.radians(80.0), 8.0)
BOARDS = Cone(10.0, np.radians(50.0), 6.0)
LEANING_IN = Cone(6.0, np.radians(100.0), 5.0)
FLAT = Plane()
WALLS = [DRUM, WELL, BOARDS, LEANING_IN]
WALL_IDS = ["drum", "well80", "boards50", "lean100"]

# the general path's reason words for the sphere's (the same conditions)
SPHERE_WORDS = {Reason.SURFACE_NO_FIT: Reason.NO_FIT_INSIDE, Reason.SURFACE_NO_FIT_OUTSIDE: Reason.NO_FIT_OUTSIDE,
                Reason.SURFACE_NO_CONTACT: (Reason.NO_CONTACT_INSIDE, Reason.SPHERE_NO_CONTACT_INSIDE),
                Reason.SURFACE_NO_CONTACT_OUTSIDE: (Reason.NO_CONTACT_OUTSIDE, Reason.SPHERE_NO_CONTACT_OUTSIDE,
                                                    Reason.PARTICLE_OUTSIDE_BELOW_EQUATOR),
                Reason.PARTICLE_STEEP_WALL: Reason.PARTICLE_ABOVE_EQUATOR}


def _same_as_sphere(general, reference):
    assert set(reference) <= set(general)
    for key, ref in reference.items():
        got, ref = np.asarray(general[key]), np.asarray(ref)
        assert got.shape == ref.shape, key
        if key == "reason":
            for g_code, s_code in zip(got.ravel(), ref.ravel()):
                expected = SPHERE_WORDS.get(Reason(g_code), Reason(g_code))
                assert s_code in np.atleast_1d(expected), (Reason(g_code), Reason(s_code))
            continue
        if ref.dtype.kind != "f":
            assert np.array_equal(got, ref), key
            continue
        assert np.array_equal(np.isnan(got), np.isnan(ref)), key
        fin = np.isfinite(ref)
        assert np.all(np.abs(got[fin] - ref[fin]) <= 1e-12 * np.maximum(np.abs(ref[fin]), 1e-300)), key


def _globe_lanes():
    # degrees off the round numbers (no exact fit boundary on the grid); the
    # reference takes the theta each height means, so both see one lane
    heights = GLOBE.height(np.radians(np.linspace(3.37, 176.37, 47)))
    return heights[:, None], GLOBE.theta(heights)[:, None]


@pytest.mark.parametrize("outside", [False, True])
def test_the_globe_through_the_general_path_is_the_sphere_path(outside):
    heights, theta = _globe_lanes()
    alpha = np.radians(np.linspace(-174.89, 175.11, 61))[None, :]
    _same_as_sphere(revolution.wheel_orbit(GLOBE, heights, alpha, 0.3, 0.5, G, outside=outside, mu=1.2),
                    wheel.horizontal_orbit(theta, alpha, 0.3, R, 0.5, G, outside=outside, mu=1.2))
    omega3 = np.linspace(-90.0, 90.0, 31)[None, :]
    _same_as_sphere(revolution.ball_orbit(GLOBE, heights, omega3, 0.3, 0.4, G, outside=outside, mu=1.2),
                    sphere.sphere_orbit(theta, omega3, 0.3, R, 0.4, G, outside=outside, mu=1.2))
    omega = np.linspace(-9.0, 9.0, 30)[None, :]
    _same_as_sphere(revolution.ball_orbit_from_rate(GLOBE, heights, omega, 0.3, 0.4, G, outside=outside),
                    sphere.sphere_orbit_from_rate(theta, omega, 0.3, R, 0.4, G, outside=outside))
    _same_as_sphere(revolution.particle_orbit(GLOBE, heights[:, 0], G, outside=outside),
                    particle.particle_orbit(theta[:, 0], R, G, outside=outside))


# --- independent checks: Newton and Euler with explicit vectors -------------

def _wall_frame(ground, height):
    rho, z = (float(v) for v in ground.contact(height))
    n_rho, n_z = (float(v) for v in ground.normal(height))
    n = np.array([n_rho, 0.0, n_z])               # inward normal, meridian plane y = 0
    t = np.array([n_z, 0.0, -n_rho])              # up the wall: (cos beta, sin beta)
    return np.array([rho, 0.0, z]), n, t


def _contact_force(res, n, t, i=(), outside=False):
    """F/m from the result's push (pressing body and wall together: along n
    inside, against it outside) and friction (positive down the wall)."""
    return float(res["normal"][i]) * (-n if outside else n) - float(res["friction"][i]) * t


@pytest.mark.parametrize("ground", WALLS + [FLAT], ids=WALL_IDS + ["flat"])
def test_wheel_orbits_solve_newton_euler_and_roll(ground):
    k, a = 0.5, 0.3
    lanes = [0.5, 1.7, 3.1] if ground is not FLAT else [2.0, 6.0, 15.0]
    alpha = np.radians(np.linspace(2.0, 88.0, 23))
    checked = 0
    for h in lanes:
        res = revolution.wheel_orbit(ground, h, alpha, a, k, G)
        p, n, t = _wall_frame(ground, h)
        for i in np.flatnonzero(res["status"] == Status.OK):
            al, om = alpha[i], float(res["omega"][i])
            e3 = np.array([np.cos(al), 0.0, -np.sin(al)])       # centre -> contact
            e2 = np.array([0.0, 1.0, 0.0])                       # the direction of motion
            e1 = np.cross(e2, e3)                                # the axle
            c = p - a * e3
            zhat = np.array([0.0, 0.0, 1.0])
            v_c = om * np.cross(zhat, c)
            # rolling fixes the axle's component: v_c + w x (a e3) = 0 with w = w1 e1 + w3 e3
            w3 = float(res["omega3"][i])
            w1 = -v_c @ e2 / (a * (np.cross(e1, e3) @ e2))
            w = w1 * e1 + w3 * e3
            assert np.allclose(v_c + np.cross(w, a * e3), 0.0, atol=1e-12 * (1 + abs(om)))
            assert np.isclose(abs(w1), abs(float(res["spin"][i])), rtol=1e-10)
            force = _contact_force(res, n, t, i)
            accel = om * np.cross(zhat, v_c)
            assert np.allclose(force, accel + G * zhat, atol=1e-10 * G)          # Newton
            inertia = a * a * (2 * k * np.outer(e1, e1) + k * (np.outer(e2, e2) + np.outer(e3, e3)))
            spin = inertia @ w
            euler = om * np.cross(zhat, spin) - np.cross(a * e3, force)
            assert np.abs(euler).max() < 1e-10 * a * G                            # Euler
            assert np.isclose(float(res["mu_required"][i]),
                              abs(force @ t) / (force @ n), rtol=1e-12)
            checked += 1
    assert checked >= 10


def _rim_clearance(ground, height, alpha, a):
    """The least clearance of the wheel's rim from the wall (the contact's
    neighbourhood left out) and its lowest point's z."""
    p, _, _ = _wall_frame(ground, height)
    e3 = np.array([np.cos(alpha), 0.0, -np.sin(alpha)])
    c = p - a * e3
    psi = np.linspace(0.02, 2 * np.pi - 0.02, 4000)
    pts = c[:, None] + a * (np.cos(psi) * e3[:, None] + np.sin(psi) * np.array([0.0, 1.0, 0.0])[:, None])
    return float(np.min(ground.clearance(np.hypot(pts[0], pts[1]), pts[2]))), float(pts[2].min())


@pytest.mark.parametrize("ground", WALLS, ids=WALL_IDS)
def test_a_wheel_that_fits_stays_inside_the_wall(ground):
    a = 0.9
    for h in (0.05, 1.2, 2.5):
        alpha = np.radians(np.linspace(-60.5, 170.5, 78))
        res = revolution.wheel_orbit(ground, h, alpha, a, 0.5, G)
        fits = ~np.isin(res["reason"], (Reason.SURFACE_NO_FIT, Reason.BELOW_FLOOR))
        for i in range(alpha.size):
            clearance, lowest = _rim_clearance(ground, h, alpha[i], a)
            if fits[i]:
                assert clearance > -1e-9 and lowest >= -1e-9
            elif res["reason"][i] == Reason.BELOW_FLOOR:
                assert lowest < 0
    # the drum cuts a wheel's plane in an ellipse whose sharpest point is the
    # contact: there the local fit is the whole fit, and a wheel refused cuts the wall
    alpha = np.radians(np.linspace(5.5, 175.5, 35))
    res = revolution.wheel_orbit(DRUM, 3.0, alpha, 4.0, 0.5, G)
    for i in np.flatnonzero(res["reason"] == Reason.SURFACE_NO_FIT):
        assert _rim_clearance(DRUM, 3.0, alpha[i], 4.0)[0] < 0


def test_wall_of_death_rule():
    """On an upright wall the wall pushes Omega^2 r' and friction holds the
    weight: mu_required = g r' / v_cm^2."""
    alpha = np.radians([5.0, 10.0, 20.0])
    res = revolution.wheel_orbit(DRUM, 2.0, alpha, 0.3, 0.5, G)
    rp = DRUM.radius - 0.3 * np.cos(alpha)
    assert np.all(res["status"] == Status.OK)
    assert np.allclose(res["normal"], rp * res["omega"] ** 2, rtol=1e-13)
    assert np.allclose(res["friction"], -G, rtol=1e-13)          # up the wall
    assert np.allclose(res["mu_required"], G * rp / res["v_cm"] ** 2, rtol=1e-12)
    assert np.allclose(res["rho_contact"], DRUM.radius) and np.allclose(res["wall_angle"], np.pi / 2)


def test_flat_ground_wheel_turns_with_friction_only():
    alpha = np.radians(70.0)
    res = revolution.wheel_orbit(FLAT, 10.0, alpha, 0.3, 0.5, G)
    rp = 10.0 - 0.3 * np.cos(alpha)
    # Omega^2 of eq. (29), written out: g cot(alpha) / ((2k+1) r' + k a cos(alpha))
    om2 = G / np.tan(alpha) / (2 * rp + 0.5 * 0.3 * np.cos(alpha))
    assert np.isclose(res["omega2"], om2, rtol=1e-13)
    assert np.isclose(res["normal"], G) and np.isclose(res["mu_required"], om2 * rp / G, rtol=1e-12)


@pytest.mark.parametrize("ground", WALLS, ids=WALL_IDS)
@pytest.mark.parametrize("outside", [False, True])
def test_ball_orbits_solve_newton_and_euler(ground, outside):
    a, k = 0.4, 0.4
    omega3 = np.linspace(-200.0, 200.0, 17)
    checked = 0
    for h in (0.8, 2.0):
        res = revolution.ball_orbit(ground, h, omega3, a, k, G, outside=outside)
        p, n, t = _wall_frame(ground, h)
        u = n if outside else -n                                    # centre -> contact
        c = p - a * u
        zhat = np.array([0.0, 0.0, 1.0])
        for i, b in zip(*np.nonzero(res["status"] == Status.OK)):
            om = float(res["omega"][i, b])
            assert np.isclose(float(res["r_prime"][i, b]), c[0], rtol=1e-12)
            v_c = om * np.cross(zhat, c)
            w = omega3[i] * u - np.cross(u, v_c) / a                # rolls: v_c + w x (a u) = 0
            assert np.allclose(v_c + np.cross(w, a * u), 0.0, atol=1e-12 * (1 + abs(om)))
            force = _contact_force(res, n, t, (i, b), outside)
            assert np.allclose(force, om * np.cross(zhat, v_c) + G * zhat, atol=1e-10 * G)   # Newton
            euler = k * a * a * om * np.cross(zhat, w) - np.cross(a * u, force)
            assert np.abs(euler).max() < 1e-9 * a * G                                       # Euler
            checked += 1
    if not outside or ground is LEANING_IN:
        assert checked >= 4
    else:
        # outside a wall that leans out or stands upright the push r_C Omega^2
        # sin(beta) + g cos(beta) would have to pull: no contact, whatever the spin
        res = revolution.ball_orbit(ground, 2.0, omega3, a, k, G, outside=True)
        assert np.all(np.isin(res["status"], (Status.NO_CONTACT, Status.NO_ORBIT)))


def test_ball_fit_takes_both_curvatures_and_the_floor():
    # a drum bends only along its parallels: a ball fits while a < R
    assert revolution.ball_orbit(DRUM, 4.5, 60.0, 4.0, branch=0)["status"] != Status.NO_FIT
    res = revolution.ball_orbit(DRUM, 5.0, 60.0, 5.0, branch=0)
    assert res["status"] == Status.NO_FIT and res["reason"] == Reason.BALL_NO_FIT_MERIDIAN
    # on the drum's wall the ball's centre is at the contact's height: it needs height >= a
    res = revolution.ball_orbit(DRUM, 0.2, 60.0, 0.3, branch=0)
    assert res["reason"] == Reason.BELOW_FLOOR
    res = revolution.ball_orbit(FLAT, 5.0, 60.0, 0.3, branch=0)
    assert res["status"] == Status.NO_ORBIT and res["reason"] == Reason.BALL_FLAT_GROUND


def test_particle_rate_and_push():
    h = np.array([0.5, 2.0, 5.0])
    for ground in (WELL, BOARDS):
        res = revolution.particle_orbit(ground, h, G)
        rho, _ = ground.contact(h)
        beta = ground.wall_angle(h)
        assert np.all(res["status"] == Status.OK)
        assert np.allclose(res["omega2"], G * np.tan(beta) / rho, rtol=1e-13)
        assert np.allclose(res["normal"], G / np.cos(beta), rtol=1e-13)
        # frictionless: the force g z - Omega^2 rho rho-hat is along the normal
        n_rho, n_z = ground.normal(h)
        cross = -res["omega2"] * rho * n_z - G * n_rho
        assert np.allclose(cross, 0.0, atol=1e-12 * G)
    assert np.all(revolution.particle_orbit(DRUM, h, G)["reason"] == Reason.PARTICLE_STEEP_WALL)
    assert np.all(revolution.particle_orbit(LEANING_IN, h, G)["reason"] == Reason.PARTICLE_STEEP_WALL)
    assert np.all(revolution.particle_orbit(FLAT, h, G)["reason"] == Reason.PARTICLE_FLAT_GROUND)


def test_lanes_off_the_wall_and_singular_inputs_are_statuses():
    heights = np.array([-0.1, 6.5, np.nan, 0.0, 6.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        res = revolution.wheel_orbit(DRUM, heights, np.radians(10.0), 0.3, 0.5, G)
        assert res["reason"][:3].tolist() == [Reason.LANE_OFF_WALL] * 3
        assert np.all(np.isnan(res["omega"][:3])) and np.all(np.isnan(res["rho_contact"][:3]))
        assert np.all(res["status"][3:] == Status.OK)
        # the leaning-in cone's lanes end at its top (below the apex)
        assert revolution.wheel_orbit(LEANING_IN, 5.5, 0.3, 0.3, 0.5, G)["reason"] == Reason.LANE_OFF_WALL
        singular = revolution.wheel_orbit(WELL, 1.0, np.radians([0.0, 90.0, 180.0, -90.0]), 0.3, 0.5, G)
        assert np.all(singular["status"] != Status.OK)
        ball = revolution.ball_orbit(DRUM, heights, 0.0, 0.3, 0.4, G)
        assert np.all(ball["status"] != Status.OK)
        revolution.particle_orbit(FLAT, np.array([0.0, 1.0]), G)
        floor = revolution.wheel_orbit(DRUM, 0.01, np.radians(-30.0), 0.3, 0.5, G)
        assert floor["reason"] == Reason.BELOW_FLOOR
