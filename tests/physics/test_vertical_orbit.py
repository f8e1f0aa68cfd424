"""Vertical orbits of a wheel: McDonald (1993) eqs. (26)-(28b), (82).

Every formula of deathsphere.physics.vertical_orbit is checked against something
computed another way: Newton's and Euler's equations written with explicit
3-d vectors, direct integration of the equation of motion, quadrature, root
finding and bounded scalar maximisation.
"""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq, minimize_scalar

from deathsphere.physics import vertical_orbit as V
from deathsphere.physics.status import Reason, Status

G = 9.80665
A, R = 0.3, 3.0

thetas = st.floats(np.radians(10), np.radians(170))
ks = st.floats(0.0, 1.5)
phis = st.floats(-2 * np.pi, 2 * np.pi)
margins = st.floats(0.01, 20.0)           # r' phidot0^2 / g - 1 (inside)


def top_rate(theta, margin, outside=False, a=A, r=R):
    rp = V.vertical_r_prime(theta, a, r, outside)
    return np.sqrt((1 + margin) * G / rp)


# --------------------------------------------------------------------------
# an independent model: 3-d vectors, Newton and Euler
# z' = x-hat (horizontal), the orbit plane is the y-z plane shifted along x,
# phi measured from the upward vertical z.

def frame(phi):
    rhat = np.array([0.0, np.sin(phi), np.cos(phi)])     # from the z' axis to the centre
    shat = np.array([0.0, np.cos(phi), -np.sin(phi)])    # d rhat / d phi: direction of motion
    return rhat, shat


def newton_euler(phi, phidot, phiddot, theta, k, outside, a=A, r=R):
    """Force per mass F = r_cm'' + g z and the Euler residual about the axle."""
    side = -1.0 if outside else 1.0
    rp = r * np.sin(theta) - side * a
    rhat, shat = frame(phi)
    xhat, zhat = np.array([1.0, 0, 0]), np.array([0, 0, 1.0])
    acc = rp * (phiddot * shat - phidot ** 2 * rhat)
    force = acc + G * zhat
    arm = side * a * rhat                     # centre -> contact point
    # rolling: v + w x arm = 0 with w = w1 xhat  =>  w1 = side r' phidot / a
    w1dot = side * rp * phiddot / a
    euler = 2 * k * a ** 2 * w1dot - np.cross(arm, force)[0]
    n_out = np.sin(theta) * rhat + np.cos(theta) * xhat
    theta_hat = np.cos(theta) * rhat - np.sin(theta) * xhat
    return force, euler, n_out, theta_hat, shat, rhat


@settings(max_examples=60, deadline=None)
@given(theta=thetas, k=ks, phi=phis, margin=margins, outside=st.booleans())
def test_contact_force_matches_newton_and_euler(theta, k, phi, margin, outside):
    """Eq. (26) makes Euler's equation hold, and eq. (28) (with F_2's sign
    corrected) is m (r_cm'' + g z), projected on the sphere's normal and
    tangents (eqs. 28c, 28d)."""
    w0 = top_rate(theta, margin, outside) if not outside else 0.3 * margin
    rp = float(V.vertical_r_prime(theta, A, R, outside))
    w2 = float(V.rate_squared(phi, theta, w0, A, R, k, G, outside))
    phiddot = G * np.sin(phi) / ((2 * k + 1) * rp)          # eq. (26)
    force, euler, n_out, th_hat, shat, rhat = newton_euler(phi, np.sqrt(w2), phiddot, theta, k, outside)
    assert euler == pytest.approx(0.0, abs=1e-9 * (1 + np.abs(force).max()))
    f = V.contact_force(phi, theta, w0, A, R, k, G, outside)
    scale = 1 + np.abs(force).max()
    assert float(f["along"]) == pytest.approx(force @ shat, abs=1e-9 * scale)
    assert float(f["radial"]) == pytest.approx(force @ rhat, abs=1e-9 * scale)
    assert force[0] == pytest.approx(0.0, abs=1e-12)        # no force along z'
    normal = -(force @ n_out) if not outside else force @ n_out
    assert float(f["normal"]) == pytest.approx(normal, abs=1e-9 * scale)
    assert float(f["meridional"]) == pytest.approx(force @ th_hat, abs=1e-9 * scale)
    tangential = force - (force @ n_out) * n_out
    assert float(f["friction"]) == pytest.approx(np.linalg.norm(tangential), abs=1e-9 * scale)


@settings(max_examples=40, deadline=None)
@given(theta=thetas, k=ks, phi=phis, margin=margins)
def test_energy_conservation(theta, k, phi, margin):
    """Eq. (27): kinetic energy (translation + spin omega_1 = r' phidot / a,
    I11 = 2 k m a^2) plus potential energy g r' cos(phi) is the same as at the top."""
    w0 = top_rate(theta, margin)
    rp = float(V.vertical_r_prime(theta, A, R))
    w2 = float(V.rate_squared(phi, theta, w0, A, R, k, G))

    def energy(w2_, phi_):
        v = rp * np.sqrt(w2_)
        return 0.5 * v ** 2 + 0.5 * 2 * k * A ** 2 * (v / A) ** 2 + G * rp * np.cos(phi_)
    assert energy(w2, phi) == pytest.approx(energy(w0 ** 2, 0.0), rel=1e-12)


def test_rate_matches_integrated_equation_of_motion():
    """phidot(phi) from eq. (27) agrees with a numerical integration of eq. (26)."""
    theta, k = np.radians(70), 0.5
    w0 = top_rate(theta, 0.3)
    rp = float(V.vertical_r_prime(theta, A, R))
    sol = solve_ivp(lambda t, y: [y[1], G * np.sin(y[0]) / ((2 * k + 1) * rp)], (0, 1.5),
                    [0.0, w0], rtol=1e-11, atol=1e-12, dense_output=True)
    t = np.linspace(0, 1.5, 40)
    phi, phidot = sol.sol(t)
    assert phidot ** 2 == pytest.approx(V.rate_squared(phi, theta, w0, A, R, k, G), rel=1e-8)


def test_friction_opposes_the_speed_up():
    """Going down (0 < phi < pi) gravity speeds the wheel up; the friction
    that spins the wheel up must point backwards (F_2 < 0).  Eq. (28) prints
    +2k/(2k+1) m g sin(phi): the sign is wrong."""
    phi = np.linspace(0.1, np.pi - 0.1, 7)
    f = V.contact_force(phi, np.radians(80), 4.0, A, R, 0.5, G)
    assert np.all(f["along"] < 0)
    assert f["along"] == pytest.approx(-(2 * 0.5) / (2 * 0.5 + 1) * G * np.sin(phi), rel=1e-14)


# --------------------------------------------------------------------------
# contact, worst point, lap time

@pytest.mark.parametrize("outside", [False])
def test_min_top_rate_is_the_contact_threshold(outside):
    theta = np.radians([30.0, 60.0, 90.0, 140.0])
    w_min = V.min_top_rate(theta, A, R, G)
    rp = V.vertical_r_prime(theta, A, R)
    assert w_min == pytest.approx(np.sqrt(G / rp))
    assert V.min_top_speed(theta, A, R, G) == pytest.approx(np.sqrt(G * rp))
    above = V.vertical_orbit(theta, w_min * (1 + 1e-6), A, R, 0.5, G)
    below = V.vertical_orbit(theta, w_min * (1 - 1e-6), A, R, 0.5, G)
    assert np.all(above["status"] == Status.OK)
    assert np.all(below["status"] == Status.NO_CONTACT)
    assert np.all(below["reason"] == Reason.VERTICAL_TOP_TOO_SLOW)
    assert np.all(below["normal_top"] < 0) and np.all(above["normal_top"] > 0)
    assert np.all(above["contact"]) and not np.any(below["contact"])
    # the normal force is least at the top: a dense grid never goes below it
    phi = np.linspace(0, 2 * np.pi, 721)[:, None]
    prof = V.vertical_profile(phi, theta, w_min * 1.01, A, R, 0.5, G)
    assert np.all(prof["normal"] >= prof["normal"][0] - 1e-12)


def test_speed_helpers_round_trip():
    theta = np.radians([20.0, 90.0, 150.0])
    for outside in (False, True):
        w = V.top_rate_from_speed(7.0, theta, A, R, outside)
        assert V.top_speed_from_rate(w, theta, A, R, outside) == pytest.approx(7.0)
    assert np.isnan(V.top_rate_from_speed(7.0, np.radians(3.0), A, R))   # does not fit


@settings(max_examples=40, deadline=None)
@given(theta=thetas, k=st.floats(0.05, 1.5), margin=st.floats(0.02, 10.0))
def test_worst_point_against_bounded_maximisation(theta, k, margin):
    w0 = top_rate(theta, margin)
    phi_w, mu_w = V.worst_point(theta, w0, A, R, k, G)

    def neg_mu(p):
        return -float(V.contact_force(p, theta, w0, A, R, k, G)["mu_required"])
    grid = np.linspace(0, np.pi, 181)
    i = int(np.argmax(-np.array([neg_mu(p) for p in grid])))
    lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, 180)]
    res = minimize_scalar(neg_mu, bounds=(lo, hi), method="bounded", options={"xatol": 1e-10})
    assert float(mu_w) == pytest.approx(-res.fun, rel=1e-9)
    assert float(phi_w) == pytest.approx(res.x, abs=1e-4)
    assert 0 <= float(phi_w) < np.pi / 2              # in the upper half


def test_worst_point_limits():
    theta = np.radians(60.0)
    # mu diverges as the top rate falls to the contact limit ...
    w_min = float(V.min_top_rate(theta, A, R, G))
    phi_near, mu_near = V.worst_point(theta, w_min * (1 + 1e-6), A, R, 0.5, G)
    assert mu_near > 100 and phi_near < 0.01
    # ... and tends to cot(theta) (eq. 28b) for a fast wheel
    _, mu_fast = V.worst_point(theta, 1e3, A, R, 0.5, G)
    assert float(mu_fast) == pytest.approx(1 / np.tan(theta), rel=1e-6)
    # k = 0: mu is |cot theta| everywhere
    _, mu0 = V.worst_point(theta, 3.0, A, R, 0.0, G)
    prof = V.vertical_profile(np.linspace(0, 2 * np.pi, 13), theta, 3.0, A, R, 0.0, G)
    assert prof["mu_required"] == pytest.approx(np.full(13, 1 / np.tan(theta)))
    assert float(mu0) == pytest.approx(1 / np.tan(theta))


def test_lap_time_against_quadrature():
    theta = np.radians([25.0, 60.0, 90.0, 120.0, 90.0])
    k = np.array([0.5, 0.25, 0.5, 1.0, 0.0])
    margin = np.array([0.001, 0.5, 3.0, 30.0, 1.0])
    w0 = top_rate(theta, margin)
    T = V.lap_time(theta, w0, A, R, k, G)
    for i in range(len(theta)):
        def inv_rate(p):
            return 1 / np.sqrt(float(V.rate_squared(p, theta[i], w0[i], A, R, k[i], G)))
        ref, _ = quad(inv_rate, 0, 2 * np.pi, epsabs=1e-13, epsrel=1e-12, limit=200)
        assert T[i] == pytest.approx(ref, rel=1e-9)
    orbit = V.vertical_orbit(theta, w0, A, R, k, G)
    assert orbit["period"] == pytest.approx(T)


def test_lap_time_of_a_rolling_orbit_the_wall_does_not_hold():
    """Below the contact limit (eq. 28a) the rolling solution of eq. (27)
    still has a period (the Floquet analysis integrates over it); the
    orbit's summary reports none, and a wheel that does not fit has none."""
    theta = np.radians([40.0, 90.0, 135.0])
    w0 = top_rate(theta, np.array([-0.5, -0.9, -0.2]))
    T = V.lap_time(theta, w0, A, R, 0.5, G)
    for i in range(len(theta)):
        def inv_rate(p):
            return 1 / np.sqrt(float(V.rate_squared(p, theta[i], w0[i], A, R, 0.5, G)))
        ref, _ = quad(inv_rate, 0, 2 * np.pi, epsabs=1e-13, epsrel=1e-12, limit=200)
        assert T[i] == pytest.approx(ref, rel=1e-9)
    assert np.all(np.isnan(V.vertical_orbit(theta, w0, A, R, 0.5, G)["period"]))
    assert np.isnan(V.lap_time(np.radians(5.0), 1.0, A, R, 0.5, G))
    assert np.isnan(V.lap_time(np.radians(60.0), 0.0, A, R, 0.5, G))


def test_lap_time_by_integrating_the_motion():
    theta, k = np.radians(50.0), 0.5
    w0 = top_rate(theta, 0.2)
    rp = float(V.vertical_r_prime(theta, A, R))

    def lap(t, y):
        return y[0] - 2 * np.pi
    lap.terminal = True
    sol = solve_ivp(lambda t, y: [y[1], G * np.sin(y[0]) / ((2 * k + 1) * rp)], (0, 10),
                    [0.0, w0], events=lap, rtol=1e-11, atol=1e-12)
    assert sol.t_events[0][0] == pytest.approx(float(V.lap_time(theta, w0, A, R, k, G)), rel=1e-8)


# --------------------------------------------------------------------------
# outside: release and slip

@pytest.mark.parametrize("k", [0.0, 0.25, 0.5, 1.0])
@pytest.mark.parametrize("v_top", [0.0, 1.0, 3.0])
def test_release_angle_against_root_of_normal_force(k, v_top):
    theta = np.radians(75.0)
    w0 = float(V.top_rate_from_speed(v_top, theta, A, R, True))
    phi_l = float(V.release_angle(theta, w0, A, R, k, G))
    n = lambda p: float(V.contact_force(p, theta, w0, A, R, k, G, True)["normal"])  # noqa: E731
    if n(0.0) <= 0:
        assert phi_l == 0.0
    else:
        assert phi_l == pytest.approx(brentq(n, 0.0, np.pi / 2, xtol=1e-14), abs=1e-10)
    if v_top == 0.0:
        assert np.cos(phi_l) == pytest.approx(2 / (3 + 2 * k), rel=1e-12)   # eq. (82)


def test_release_at_once_when_fast():
    theta = np.radians(90.0)
    rp = float(V.vertical_r_prime(theta, A, R, True))
    assert float(V.release_angle(theta, np.sqrt(G / rp) * 1.01, A, R, 0.5, G)) == 0.0


@settings(max_examples=40, deadline=None)
@given(theta=thetas, k=st.floats(0.05, 1.5), margin=st.floats(0.02, 10.0),
       mu=st.floats(0.05, 5.0), outside=st.booleans())
def test_slip_angle_is_first_crossing(theta, k, margin, mu, outside):
    w0 = top_rate(theta, margin) if not outside else 0.2 * margin / (1 + margin)
    phi_s = float(V.slip_angle(theta, w0, A, R, k, G, mu, outside))
    def mu_at(p):
        return V.contact_force(p, theta, w0, A, R, k, G, outside)["mu_required"]
    end = float(V.release_angle(theta, w0, A, R, k, G)) if outside else np.pi
    if mu_at(0.0) > mu:
        assert phi_s == 0.0
        return
    grid = np.linspace(0, end, 2001)[:-1]
    over = mu_at(grid) > mu
    if not over.any():
        assert np.isnan(phi_s) or phi_s > grid[-1]
        return
    j = int(np.argmax(over))
    root = brentq(lambda p: float(mu_at(p)) - mu, grid[j - 1], grid[j], xtol=1e-13)
    assert phi_s == pytest.approx(root, abs=1e-8)


def test_outside_never_closes():
    theta = np.radians([30.0, 90.0, 150.0])
    out = V.vertical_orbit(theta[:, None], np.array([0.0, 0.5, 2.0, 50.0]), A, R, 0.5, G, outside=True)
    assert np.all(out["status"] == Status.NO_CONTACT)
    assert np.all(out["reason"] == Reason.VERTICAL_OUTSIDE_LEAVES)
    assert np.all(out["phi_leave"] < np.pi / 2)
    assert np.all(np.isnan(out["period"]))


# --------------------------------------------------------------------------
# statuses, shapes, singular inputs

def test_statuses():
    theta = np.radians([60.0, 60.0, 60.0, 5.0, 0.0, 180.0])
    w0 = np.array([3.0, 1.0, 3.0, 3.0, 3.0, 3.0])
    mu = np.array([np.inf, np.inf, 0.3, np.inf, np.inf, np.inf])
    out = V.vertical_orbit(theta, w0, A, R, 0.5, G, mu=mu)
    assert out["status"].tolist() == [Status.OK, Status.NO_CONTACT, Status.SLIPS,
                                      Status.NO_FIT, Status.NO_FIT, Status.NO_FIT]
    assert out["reason"][3:].tolist() == [Reason.NO_FIT_VERTICAL] * 3
    slips = out["phi_slip"][2]
    assert 0 <= slips <= out["phi_worst"][2]
    outside = V.vertical_orbit(np.array([0.0, np.pi, 1.0]), 1.0, A, R, 0.5, G, outside=True)
    assert outside["status"].tolist() == [Status.NO_FIT, Status.NO_FIT, Status.NO_CONTACT]
    assert outside["reason"][:2].tolist() == [Reason.NO_FIT_OUTSIDE] * 2


def test_ok_rows_are_finite_and_mu_is_consistent():
    theta = np.radians(np.arange(10.0, 171.0, 10.0))[:, None]
    w0 = np.linspace(1.0, 8.0, 8)
    out = V.vertical_orbit(theta, w0, A, R, 0.5, G, mu=2.0)
    ok = out["status"] == Status.OK
    assert ok.sum() > 20
    keys = ["r_prime", "omega", "omega_bottom", "period", "v_cm", "v_bottom", "spin", "accel",
            "normal", "friction", "mu_required", "phi_worst", "mu_top", "normal_top", "normal_bottom"]
    for key in keys:
        assert np.all(np.isfinite(out[key][ok])), key
    assert out["mu_required"][ok] == pytest.approx(out["friction"][ok] / out["normal"][ok])
    assert np.all(out["mu_required"][ok] >= out["mu_top"][ok] - 1e-12)
    # accel is the largest centre acceleration of the lap, at the bottom
    prof = V.vertical_profile(np.linspace(0, 2 * np.pi, 721)[:, None, None], theta, w0, A, R, 0.5, G)
    assert np.nanmax(prof["accel"], axis=0)[ok] == pytest.approx(out["accel"][ok], rel=1e-12)


def test_profile_shapes_and_point_statuses():
    phi = V.phi_grid(37)
    assert phi[0] == 0 and phi[-1] == pytest.approx(2 * np.pi) and len(phi) == 37
    theta = np.radians([60.0, 90.0])
    prof = V.vertical_profile(phi[:, None], theta, np.array([3.0, 1.5]), A, R, 0.5, G, mu=0.62)
    assert prof["mu_required"].shape == (37, 2)
    # the slow wheel (1.5 rad/s < sqrt(g/r')) has no contact near the top, contact at the bottom
    assert prof["status"][0, 1] == Status.NO_CONTACT and prof["status"][18, 1] == Status.OK
    assert np.isnan(prof["mu_required"][0, 1])
    assert np.any(prof["status"][:, 0] == Status.SLIPS) and prof["status"][0, 0] == Status.OK
    out = V.vertical_profile(phi, np.radians(60.0), 0.0, A, R, 0.25, G, outside=True)
    leave = float(V.release_angle(np.radians(60.0), 0.0, A, R, 0.25, G))   # acos(2/3.5)
    assert np.all((out["status"] == Status.NO_CONTACT) == ((phi >= leave) & (phi <= 2 * np.pi - leave)))


def test_singular_inputs_give_statuses_not_warnings():
    theta = np.array([0.0, np.pi / 2, np.pi, 1e-300, np.arcsin(A / R), np.pi - 1e-15])
    for outside in (False, True):
        for k in (0.0, 0.5):
            for w0 in (0.0, 2.0, 1e8):
                for mu in (0.0, 1.0, np.inf):
                    out = V.vertical_orbit(theta, w0, A, R, k, G, outside=outside, mu=mu)
                    assert out["status"].shape == theta.shape
                    V.vertical_profile(V.phi_grid(5)[:, None], theta, w0, A, R, k, G, outside, mu)
    # a wheel as big as the sphere does not fit anywhere inside
    out = V.vertical_orbit(np.radians([30, 90]), 3.0, 3.0, 3.0, 0.5, G)
    assert np.all(out["status"] == Status.NO_FIT)
