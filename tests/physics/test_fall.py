"""A rider who loses speed (deathsphere.physics.fall), each piece against a
derivation of its own: free fall, the point mass's loop (3 psi past the top),
energy, Newton's law integrated step by step, and brute-force sampling."""

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp

from deathsphere.physics import fall
from deathsphere.physics.ground import Sphere
from machine_calls import arrays, loop as vertical_loop

G = 9.81
R = 2.4384                                # a 16-foot globe
ZHAT = np.array([0.0, 0.0, 1.0])[:, None]


def path(x0, v0, t):
    """The parabola at times t (m, n): (3, m, n)."""
    return x0[:, None, :] + v0[:, None, :] * t[None] - 0.5 * G * t[None] ** 2 * ZHAT[:, :, None]


def random_inside(n, seed):
    rng = np.random.default_rng(seed)
    d = rng.normal(size=(3, n))
    d /= np.linalg.norm(d, axis=0)
    return d * R * rng.uniform(0.3, 0.999, n), rng.normal(size=(3, n)) * 6.0


# ---------------------------------------------------------------------------
# the flight
# ---------------------------------------------------------------------------

def test_a_stall_above_the_equator_falls_straight_down():
    theta = np.radians([20.0, 45.0, 70.0, 89.0])
    phi = np.radians([0.0, 100.0, 200.0, 300.0])
    rho_g = R * np.sin(theta) - 0.6                  # the centre of mass 0.6 m in from the wall
    x0 = np.stack([rho_g * np.cos(phi), rho_g * np.sin(phi), R * np.cos(theta)])
    v_before = np.stack([-np.sin(phi), np.cos(phi), np.zeros(4)]) * 9.0
    out = fall.ballistic_landing(x0, fall.drop_velocity(v_before, np.zeros(4)), Sphere(R), G)
    z_floor = -np.sqrt(R * R - rho_g * rho_g)        # where the vertical through G meets the globe
    np.testing.assert_allclose(out["x_land"][:2], x0[:2], atol=1e-12)
    np.testing.assert_allclose(out["x_land"][2], z_floor, rtol=1e-12)
    np.testing.assert_allclose(out["t_land"], np.sqrt(2 * (x0[2] - z_floor) / G), rtol=1e-12)
    np.testing.assert_allclose(out["impact_speed"], np.sqrt(2 * G * (x0[2] - z_floor)), rtol=1e-12)
    assert (out["status"] == fall.LANDS).all()


def test_the_parabola_conserves_energy_and_lands_on_the_globe():
    x0, v0 = random_inside(2000, 1)
    out = fall.ballistic_landing(x0, v0, Sphere(R), G)
    xl = out["x_land"]
    np.testing.assert_allclose(np.linalg.norm(xl, axis=0), R, rtol=1e-12)
    speed2 = np.sum(v0 * v0, axis=0) + 2 * G * (x0[2] - xl[2])
    np.testing.assert_allclose(out["impact_speed"], np.sqrt(speed2), rtol=1e-10)
    np.testing.assert_allclose(out["impact_normal"], np.sum(xl * out["v_land"], axis=0) / R, rtol=1e-10, atol=1e-12)
    assert (out["impact_normal"] >= -1e-9).all()      # it arrives from inside


def test_the_landing_is_the_first_time_the_path_reaches_the_globe():
    x0, v0 = random_inside(500, 2)
    out = fall.ballistic_landing(x0, v0, Sphere(R), G)
    t = np.linspace(0.0, 1.0, 1001)[:-1, None] * out["t_land"][None]
    assert (np.linalg.norm(path(x0, v0, t), axis=0) < R).all()   # brute force: inside until then


def test_a_path_that_leaves_the_globe_briefly_lands_at_the_first_crossing():
    # from the floor's centre straight up, nearly to the top: a miss; slightly more: a hit
    x0 = np.zeros((3, 2))
    v0 = np.array([[0.0, 0.0], [0.0, 0.0], [np.sqrt(2 * G * R) * 0.999, np.sqrt(2 * G * R) * 1.001]])
    out = fall.ballistic_landing(x0, v0, Sphere(R), G)
    np.testing.assert_allclose(out["x_land"][2], [-R, R], rtol=1e-12)
    vz = v0[2, 1]
    np.testing.assert_allclose(out["t_land"][1], (vz - np.sqrt(vz * vz - 2 * G * R)) / G, rtol=1e-10)


def test_a_start_on_the_surface_moving_inward_does_not_land_at_once():
    u = 3.0
    x0 = np.array([[0.0, R, R], [0.0, 0.0, 0.0], [R, 0.0, 0.0]])
    v0 = np.array([[0.0, -u, u], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    out = fall.ballistic_landing(x0, v0, Sphere(R), G)
    # from the top at rest: down the diameter, 2R = g t^2 / 2
    assert out["t_land"][0] == pytest.approx(2 * np.sqrt(R / G), rel=1e-12)
    # from the equator inwards: (R - u t)^2 + g^2 t^4 / 4 = R^2, t != 0: g^2 t^3/4 + u^2 t - 2 R u = 0
    cubic = np.roots([G * G / 4, 0.0, u * u, -2 * R * u])
    t_cubic = cubic[np.abs(cubic.imag) < 1e-12].real.max()
    assert out["t_land"][1] == pytest.approx(t_cubic, rel=1e-12)
    assert out["t_land"][2] == 0.0                  # moving outward: into the steel at once


def test_a_start_outside_the_globe_or_a_bad_row_is_marked_not_flown():
    x0 = np.array([[0.0, np.nan, 0.0], [0.0, 0.0, 0.0], [1.01 * R, 0.0, 0.0]])
    out = fall.ballistic_landing(x0, np.zeros((3, 3)), Sphere(R), np.array([G, G, 0.0]))
    np.testing.assert_array_equal(out["status"], [fall.STARTS_OUTSIDE, fall.NOT_FLOWN, fall.NOT_FLOWN])
    assert np.isnan(out["t_land"]).all() and np.isnan(out["x_land"]).all()


def test_a_hundred_thousand_falls_in_one_call():
    x0, v0 = random_inside(100_000, 3)
    out = fall.ballistic_landing(x0, v0, Sphere(R), G)
    assert out["t_land"].shape == (100_000,) and np.isfinite(out["t_land"]).all()
    assert (out["t_land"] > 0).all()
    np.testing.assert_allclose(np.linalg.norm(out["x_land"], axis=0), R, rtol=1e-12)


# ---------------------------------------------------------------------------
# the loop
# ---------------------------------------------------------------------------

def point_mass_after_drop(v_bottom, rho=R):
    """A point mass (M = m rho^2) at the bottom of a great circle, moving at v_bottom."""
    return fall.loop_departure(np.pi, v_bottom / rho, rho, rho, rho * rho, 1.0, G)


def test_a_point_mass_leaves_where_g_cos_psi_is_v2_over_rho_and_lands_3psi_past_the_top():
    rho = R
    v_b = np.sqrt(G * rho * np.array([2.3, 2.9, 3.5, 4.1, 4.7]))    # 2 < v_b^2/(g rho) < 5: not over the top
    out = point_mass_after_drop(v_b)
    assert (out["outcome"] == fall.FALLS).all()
    # energy from the bottom, and Newton across the circle with no normal force:
    # v^2 = v_b^2 - 2 g rho (1 + cos psi) = g rho cos psi
    cos_psi = (v_b ** 2 - 2 * G * rho) / (3 * G * rho)
    psi = np.arccos(cos_psi)                         # before the top
    np.testing.assert_allclose(np.mod(out["psi_lost"], 2 * np.pi), 2 * np.pi - psi, rtol=1e-12)
    v = rho * out["psi_dot_lost"]
    np.testing.assert_allclose(G * cos_psi, v * v / rho, rtol=1e-10)
    x, vel = fall.loop_state(out["psi_lost"], out["psi_dot_lost"], rho, 0.0)
    land = fall.ballistic_landing(x, vel, Sphere(R), G)
    past_top = np.arctan2(land["x_land"][0], land["x_land"][2])     # from the top, along the travel
    np.testing.assert_allclose(np.mod(past_top - 3 * psi + np.pi, 2 * np.pi) - np.pi, 0.0, atol=1e-9)
    # the flight lasts 4 v sin(psi) / g (the osculating parabola's other root)
    np.testing.assert_allclose(land["t_land"], 4 * v * np.sin(psi) / G, rtol=1e-9)


def loop_by_newton(psi0, w0, rho, r_g, m, m_eff, t_end):
    """Integrate M21's equation of motion psi'' = (m g r_G / M) sin psi step by
    step and stop where the in-plane normal force r_G psi'^2 - g cos psi
    (Newton across the circle) or the speed reaches zero."""
    def rhs(_t, y):
        return [y[1], m * G * r_g / m_eff * np.sin(y[0])]

    def contact(_t, y):
        return r_g * y[1] ** 2 - G * np.cos(y[0])

    def stops(_t, y):
        return y[1]

    contact.terminal = stops.terminal = True
    sol = solve_ivp(rhs, (0, t_end), [psi0, w0], events=[contact, stops], rtol=1e-12, atol=1e-12)
    return sol


@pytest.mark.parametrize("v_b", [6.5, 8.0, 9.0])
def test_a_machines_departure_is_newtons_law_integrated(v_b):
    rho, h, m, i_pitch, j, a = R, 0.55, 190.0, 35.0, 1.1, 0.3
    r_g = rho - h
    m_eff = m * r_g ** 2 + i_pitch + j * (rho * rho - 2 * rho * a) / a ** 2
    out = fall.loop_departure(np.pi, v_b / r_g, rho, r_g, m_eff, m, G)
    sol = loop_by_newton(np.pi, v_b / r_g, rho, r_g, m, m_eff, 10.0)
    assert sol.t_events[0].size == 1 and out["outcome"] == fall.FALLS
    assert out["t_lost"] == pytest.approx(sol.t_events[0][0], rel=1e-8)
    assert out["psi_lost"] == pytest.approx(sol.y_events[0][0][0], rel=1e-8)
    assert out["psi_dot_lost"] == pytest.approx(sol.y_events[0][0][1], rel=1e-7)


def test_the_time_is_the_quadrature_of_dt_dpsi():
    psi0, w0, r_g, m, m_eff = 2.0, 2.2, 1.9, 1.0, 5.0
    kappa = 2 * m * G * r_g / m_eff
    out = fall.loop_departure(psi0, w0, R, r_g, m_eff, m, G)
    assert out["outcome"] == fall.FALLS

    def dt(psi):
        return 1.0 / np.sqrt(w0 ** 2 + kappa * (np.cos(psi0) - np.cos(psi)))

    assert out["t_lost"] == pytest.approx(quad(dt, psi0, out["psi_lost"], epsabs=1e-13, epsrel=1e-13)[0], rel=1e-11)


def test_a_machines_departure_tends_to_the_point_masss():
    rho = R
    v_b = np.sqrt(3.5 * G * rho)
    point = point_mass_after_drop(v_b, rho)
    assert point["outcome"] == fall.FALLS
    eps = np.array([1e-2, 1e-4, 1e-6])
    h, i_pitch, j, a, m = 0.55 * eps, 35.0 * eps, 1.1 * eps, 0.3, 190.0
    r_g = rho - h
    m_eff = m * r_g ** 2 + i_pitch + j * (rho * rho - 2 * rho * a) / a ** 2
    out = fall.loop_departure(np.pi, v_b / r_g, rho, r_g, m_eff, m, G)
    for key in ("psi_lost", "t_lost", "psi_dot_lost"):
        err = np.abs(out[key] / point[key] - 1)
        assert (np.diff(np.log10(err)) < -1.5).all() and err[-1] < 1e-6, key   # first order in h, I, J


def test_a_looper_fast_enough_for_the_top_rides_on_as_ride_vertical_says():
    rho, h, m, i_pitch, j, a = R, 0.55, 190.0, 35.0, 1.1, 0.3
    r_g = rho - h
    m_eff = m * r_g ** 2 + i_pitch + j * (rho * rho - 2 * rho * a) / a ** 2
    v_top = np.sqrt(G * r_g) * np.array([0.9, 0.99, 1.01, 1.3])
    loop = vertical_loop(np.pi / 2, v_top, R, G, m, h, a, 0.0, i_pitch, j, h + 1.2)
    # the same loop met at its bottom, at the bottom's speed
    out = fall.loop_departure(np.pi, loop["omega_bottom"], rho, r_g, m_eff, m, G)
    np.testing.assert_array_equal(out["outcome"] == fall.RIDES_ON, loop["status"] == 0)
    np.testing.assert_array_equal(out["outcome"][:2], [fall.FALLS, fall.FALLS])
    assert np.isnan(out["t_lost"][2:]).all() and (out["psi_max"][2:] == 0).all()


def test_a_slow_looper_swings_below_the_equator():
    rho = R
    v_b = np.sqrt(G * rho) * np.array([0.3, 1.0, 1.4])      # v_b^2 <= 2 g rho
    out = point_mass_after_drop(v_b, rho)
    assert (out["outcome"] == fall.SWINGS).all()
    rise = v_b ** 2 / (2 * G)                                # energy: the height it climbs
    np.testing.assert_allclose(np.pi - out["psi_max"], np.arccos(1 - rise / rho), rtol=1e-12)
    sol = loop_by_newton(np.pi, v_b[1] / rho, rho, rho, 1.0, rho * rho, 10.0)
    assert sol.t_events[0].size == 0                         # never loses contact: stops first
    assert out["t_turn"][1] == pytest.approx(sol.t_events[1][0], rel=1e-8)
    assert out["swing_period"][1] == pytest.approx(4 * sol.t_events[1][0], rel=1e-8)
    # a small swing: the pendulum's 2 pi sqrt(rho / g)
    small = point_mass_after_drop(np.array([1e-4]), rho)
    assert small["swing_period"][0] == pytest.approx(2 * np.pi * np.sqrt(rho / G), rel=1e-8)


def test_a_drop_near_the_top_below_the_top_speed_leaves_at_once():
    psi0 = np.array([-0.3, 0.2, 0.0])
    w0 = np.array([0.5, 0.5, 0.0])                            # r_G w^2 < g cos psi: no push left
    out = fall.loop_departure(psi0, w0, R, R, R * R, 1.0, G)
    assert (out["outcome"] == fall.FALLS).all()
    np.testing.assert_array_equal(out["t_lost"], 0.0)
    np.testing.assert_array_equal(out["psi_lost"], psi0)


def test_a_row_outside_the_model_is_marked():
    out = fall.loop_departure(0.0, 1.0, 1.0, np.array([-0.1, 1.2]), 1.0, 1.0, G)
    np.testing.assert_array_equal(out["outcome"], [fall.NO_LOOP, fall.NO_LOOP])
    assert np.isnan(out["psi_max"]).all()


def test_the_loops_psi_of_t_is_newtons_law_integrated():
    rho, r_g, m, m_eff, psi0, w0 = R, 1.9, 190.0, 190.0 * 1.9 ** 2 + 60.0, 0.7, 3.0
    t = np.linspace(0.0, 6.0, 25)
    prof = fall.loop_speed_profile(t, psi0, w0, r_g, m_eff, m, G)
    sol = solve_ivp(lambda _t, y: [y[1], m * G * r_g / m_eff * np.sin(y[0])], (0, 6.0), [psi0, w0],
                    t_eval=t, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(prof["psi"], sol.y[0], rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(prof["psi_dot"], sol.y[1], rtol=1e-9)
    # a lap later it is back, one turn on
    again = fall.loop_speed_profile(prof["period"][0], psi0, w0, r_g, m_eff, m, G)
    assert again["psi"] == pytest.approx(psi0 + 2 * np.pi, rel=1e-12)

    def reached(_t, y):
        return y[0] - (psi0 + 1.0)

    reached.terminal = True
    hit = solve_ivp(lambda _t, y: [y[1], m * G * r_g / m_eff * np.sin(y[0])], (0, 6.0), [psi0, w0],
                    events=reached, rtol=1e-12, atol=1e-12)
    assert fall.loop_time(psi0, w0, psi0 + 1.0, r_g, m_eff, m, G) == pytest.approx(hit.t_events[0][0], rel=1e-9)


def test_a_hundred_thousand_loop_departures_in_one_call():
    rng = np.random.default_rng(4)
    n = 100_000
    out = fall.loop_departure(rng.uniform(-10, 10, n), rng.uniform(-4, 4, n), R, R - 0.5, 190 * (R - 0.5) ** 2 + 40,
                              190.0, G)
    codes = np.bincount(out["outcome"], minlength=3)
    assert (codes > 0).all()                                 # every outcome drawn
    lost = out["outcome"] == fall.FALLS
    assert np.isfinite(out["t_lost"][lost]).all() and (out["t_lost"][lost] >= 0).all()
    assert np.isfinite(out["swing_period"][out["outcome"] == fall.SWINGS]).all()


# ---------------------------------------------------------------------------
# a horizontal lane after the drop
# ---------------------------------------------------------------------------

MACHINE = dict(mass=190.0, h=0.55, a=0.3, t=0.05, inertia_pitch=35.0, inertia_yaw=30.0, spin_inertia=1.1, head=1.6)


def test_a_horizontal_lane_holds_where_a_scan_of_every_tilt_finds_one():
    from machine_calls import orbit as ride_orbit

    from deathsphere.physics.machine import fit_window

    theta = np.radians([60.0, 90.0, 100.0, 120.0])
    speeds = np.array([0.0, 2.0, 4.0, 6.0, 9.0, 13.0])
    th, v = (x.ravel() for x in np.meshgrid(theta, speeds, indexing="ij"))
    out = fall.horizontal_holds(th, v, 0.2, Sphere(R), G, arrays(MACHINE["mass"], MACHINE["h"], MACHINE["a"],
                                MACHINE["t"], MACHINE["inertia_pitch"], MACHINE["inertia_yaw"],
                                MACHINE["spin_inertia"], MACHINE["head"]), mu=0.9)
    # brute force: a sign change of v_cm - v between neighbouring tilts that both hold
    lo, hi = fit_window(th, Sphere(R), arrays(MACHINE["mass"], MACHINE["h"], MACHINE["a"], MACHINE["t"]))
    alpha = lo[:, None] + (hi - lo)[:, None] * np.linspace(1e-6, 1 - 1e-6, 20001)[None]
    orb = ride_orbit(th[:, None], alpha, R, G, head=MACHINE["head"], mu=0.9,
                     **{k: x for k, x in MACHINE.items() if k != "head"})
    ok = orb["status"] == 0
    gap = np.where(ok, orb["v_cm"] - v[:, None], np.nan)
    with np.errstate(invalid="ignore"):
        crossing = ok[:, 1:] & ok[:, :-1] & (np.sign(gap[:, 1:]) != np.sign(gap[:, :-1]))
    np.testing.assert_array_equal(out["holds"], crossing.any(axis=1) & (v > 0))
    assert out["holds"].any() and not out["holds"].all()
    held = out["holds"]
    check = ride_orbit(th[held], out["alpha"][held], R, G, head=MACHINE["head"], mu=0.9,
                       **{k: x for k, x in MACHINE.items() if k != "head"})
    np.testing.assert_allclose(check["v_cm"], v[held], rtol=1e-6)


def test_on_the_drum_a_lane_holds_only_where_friction_carries_the_weight():
    """The wall of death's rule from the forces alone: the wall's push is
    horizontal, so it turns the centre of mass on its circle, N = m v^2 / r_G,
    and friction alone carries the weight, F = m g: the lane needs
    mu >= g r_G / v^2 whatever the machine's inertia.  r_G is the centre of
    mass's distance from the axis at the tilt (eq. MS1 with beta = 90 deg:
    R - t - (h - t) cos(alpha)), never less than R - h; so below
    v^2 = g (R - h) / mu no tilt holds, and every tilt that holds keeps
    g r_G / v^2 <= mu."""
    from deathsphere.physics.ground import Cylinder

    radius, mu = 16 * 0.3048, 0.8
    heights = np.array([0.5, 1.0, 2.0, 3.0])
    speeds = np.linspace(0.0, 16.0, 33)
    hh, v = (x.ravel() for x in np.meshgrid(heights, speeds, indexing="ij"))
    m = MACHINE
    out = fall.horizontal_holds_on(hh, v, 0.2, Cylinder(radius, 4.0), G,
                                   arrays(m["mass"], m["h"], m["a"], m["t"], m["inertia_pitch"], m["inertia_yaw"],
                                          m["spin_inertia"], m["head"]), mu=mu)
    never = v ** 2 < G * (radius - m["h"]) / mu
    assert not out["holds"][never].any()
    held = out["holds"]
    assert held.sum() > 40 and never.sum() > 8          # both sides of the rule are tried
    r_g = radius - m["t"] - (m["h"] - m["t"]) * np.cos(out["alpha"][held])
    assert np.all(G * r_g / v[held] ** 2 <= mu * (1 + 1e-9))
    # one least speed a height: below it he leaves the wall, above it he rides on (no band above: max_g is not asked)
    for k in range(heights.size):
        row = held[k * speeds.size:(k + 1) * speeds.size]
        first = int(np.argmax(row))
        assert row[first:].all() and not row[:first].any()
