"""Horizontal orbits of a wheel: eqs. (0), (8b), (13), (29)-(36), checked
against first principles (Newton-Euler with vectors), not against the paper's
own algebra."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from deathsphere.physics import wheel
from deathsphere.physics.geometry import fits_inside, r_prime
from deathsphere.physics.status import Reason, Status

G = 9.80665
deg = np.deg2rad

angles_theta = st.floats(1.0, 179.0)
angles_alpha = st.floats(-179.0, 179.0)
radius_a = st.floats(0.01, 1.0)
ratio = st.floats(1.1, 100.0)
inertia = st.floats(0.0, 2.0)


def orbit_frame(theta, alpha):
    """Unit vectors at the moment the contact point has azimuth 0:
    r' = x, direction of motion e2 = y, orbit axis z' = z (eqs. 11, 11a)."""
    x, y, z = np.eye(3)
    e3 = np.cos(alpha) * x - np.sin(alpha) * z
    e1 = -np.sin(alpha) * x - np.cos(alpha) * z
    r_hat = np.sin(theta) * x + np.cos(theta) * z
    return x, y, z, e1, e3, r_hat


def newton_euler_residual(theta, alpha, a, r, k, g, omega):
    """dL/dt - torque for a wheel on a steady horizontal orbit at rate omega,
    built only from eqs. (2)-(7b) in vector form."""
    x, y, z, e1, e3, r_hat = orbit_frame(theta, alpha)
    centre = r * r_hat - a * e3                     # contact point minus a e3
    gamma = omega * z                                # triad turns about the vertical
    v_cm = np.cross(gamma, centre)
    # omega_body = w1 e1 + (gamma - (gamma.e1) e1); fix w1 by rolling: v_cm + w x (a e3) = 0
    perp = gamma - gamma @ e1 * e1
    # v_cm + (w1 e1 + perp) x a e3 = 0  ->  w1 (e1 x e3) a = -v_cm - a perp x e3
    e1xe3 = np.cross(e1, e3)
    w1 = (-v_cm - a * np.cross(perp, e3)) @ e1xe3 / (a * e1xe3 @ e1xe3)
    w = w1 * e1 + perp
    assert np.allclose(v_cm + np.cross(w, a * e3), 0, atol=1e-9 * (1 + abs(omega) * r))
    L = k * a**2 * (w + (w @ e1) * e1)               # I11 = 2 k m a^2, I22 = I33 = k m a^2 (m = 1)
    a_cm = np.cross(gamma, v_cm)
    force = a_cm + g * z                             # eq. (2), per unit mass
    torque = np.cross(a * e3, force)                 # eq. (3)
    return np.cross(gamma, L) - torque, w1, force, np.linalg.norm(torque)


@settings(max_examples=300, deadline=None)
@given(angles_theta, angles_alpha, radius_a, ratio, inertia)
def test_eq29_balances_angular_momentum(theta_d, alpha_d, a, rr, k):
    theta, alpha, r = deg(theta_d), deg(alpha_d), a * rr
    om2 = wheel.omega_squared(theta, alpha, a, r, k, G)
    assume(np.isfinite(om2) and om2 > 1e-6 and om2 < 1e6)
    omega = np.sqrt(om2)
    residual, w1, force, torque = newton_euler_residual(theta, alpha, a, r, k, G, omega)
    scale = k * a**2 * om2 * (r + a) / a + a * (G + om2 * (r + a))
    assert np.all(np.abs(residual) <= 1e-9 * scale)
    # spin about the axis, eq. (13): omega_1 = r' Omega / a
    assert w1 == pytest.approx(r_prime(theta, alpha, a, r) * omega / a, rel=1e-9, abs=1e-9)
    # and a 1% wrong rate does not balance: the check can fail
    wrong, *_ = newton_euler_residual(theta, alpha, a, r, k, G, 1.01 * omega)
    assert np.max(np.abs(wrong)) > 1e-4 * torque


@settings(max_examples=200, deadline=None)
@given(angles_theta, angles_alpha, radius_a, ratio, inertia)
def test_eq29_satisfies_eq24_with_beta_zero(theta_d, alpha_d, a, rr, k):
    theta, alpha, r = deg(theta_d), deg(alpha_d), a * rr
    om2 = wheel.omega_squared(theta, alpha, a, r, k, G)
    assume(np.isfinite(om2))
    rp = r_prime(theta, alpha, a, r)
    lhs = ((2 * k + 1) * rp + k * a * np.cos(alpha)) * om2 * np.sin(alpha)
    assert lhs == pytest.approx(G * np.cos(alpha), rel=1e-9, abs=1e-9 * G)


@settings(max_examples=200, deadline=None)
@given(angles_theta, angles_alpha, radius_a, ratio, inertia)
def test_contact_force_eq30_equals_eq32(theta_d, alpha_d, a, rr, k):
    """Eq. (30) in the wheel's (1, 3) axes, rotated by eq. (31), is eq. (32);
    both equal m (a_cm + g z) from the vector construction."""
    theta, alpha, r = deg(theta_d), deg(alpha_d), a * rr
    om2 = wheel.omega_squared(theta, alpha, a, r, k, G)
    assume(np.isfinite(om2) and om2 > 0 and om2 < 1e6)
    rp = r_prime(theta, alpha, a, r)
    f1, f3 = wheel.contact_force_body(alpha, rp, om2, G)
    fr, ftheta = wheel.contact_force_spherical(theta, rp, om2, G)
    d = theta - alpha
    scale = G + abs(rp) * om2
    assert -np.cos(d) * f1 + np.sin(d) * f3 == pytest.approx(fr, abs=1e-10 * scale)
    assert np.sin(d) * f1 + np.cos(d) * f3 == pytest.approx(ftheta, abs=1e-10 * scale)
    _, _, force, _ = newton_euler_residual(theta, alpha, a, r, k, G, np.sqrt(om2))
    x, y, z, e1, e3, r_hat = orbit_frame(theta, alpha)
    theta_hat = np.cos(theta) * x - np.sin(theta) * z
    assert force @ r_hat == pytest.approx(fr, abs=1e-10 * scale)
    assert force @ theta_hat == pytest.approx(ftheta, abs=1e-10 * scale)
    assert force @ e1 == pytest.approx(f1, abs=1e-10 * scale)
    assert force @ e3 == pytest.approx(f3, abs=1e-10 * scale)


@settings(max_examples=200, deadline=None)
@given(st.floats(20.0, 160.0), st.floats(1.0, 60.0), radius_a, st.floats(5.0, 100.0), inertia,
       st.floats(0.01, 100.0))
def test_mu_and_g_load_invariant_under_scaling(theta_d, alpha_d, a, rr, k, scale):
    theta, alpha = deg(theta_d), deg(alpha_d)
    one = wheel.horizontal_orbit(theta, alpha, a, a * rr, k, G)
    big = wheel.horizontal_orbit(theta, alpha, scale * a, scale * a * rr, k, G)
    assert one["status"] == big["status"]
    assume(one["status"] == Status.OK)
    assert big["mu_required"] == pytest.approx(one["mu_required"], rel=1e-9)
    assert big["accel_g"] == pytest.approx(one["accel_g"], rel=1e-9)
    assert big["v_cm"] == pytest.approx(one["v_cm"] * np.sqrt(scale), rel=1e-9)


@settings(max_examples=300, deadline=None)
@given(st.floats(0.0, 180.0), st.floats(-180.0, 180.0), radius_a, ratio, inertia,
       st.one_of(st.just(np.inf), st.floats(0.0, 5.0)), st.booleans())
def test_ok_rows_are_finite_and_consistent(theta_d, alpha_d, a, rr, k, mu, outside):
    res = wheel.horizontal_orbit(deg(theta_d), deg(alpha_d), a, a * rr, k, G, outside=outside, mu=mu)
    if res["status"] == Status.OK:
        for key in ("omega", "period", "v_cm", "spin", "accel", "accel_g", "normal", "friction", "mu_required"):
            assert np.isfinite(res[key]), key
        assert res["normal"] > 0
        assert res["mu_required"] <= mu
        # eq. (36): g-load from the geometry alone equals r' Omega^2 / g
        assert abs(wheel.g_load(deg(theta_d), deg(alpha_d), a, a * rr, k)) == pytest.approx(res["accel_g"], rel=1e-9)
    assert np.isfinite(res["r_prime"])


def test_g_load_is_eq36():
    theta, alpha, a, r, k = deg(60), deg(10), 0.3, 3.0, 0.5
    rp = r_prime(theta, alpha, a, r)
    expected = (1 / np.tan(alpha)) / (2 * k + 1 + k * (a / rp) * np.cos(alpha))
    assert wheel.g_load(theta, alpha, a, r, k) == pytest.approx(expected, rel=1e-14)


def test_fit_condition_matches_printed_eq0():
    """sin(theta - alpha) > a/r is eq. (0) on the branch -180 < alpha <= 180."""
    a, r = 0.3, 3.0
    theta = deg(np.linspace(0.5, 179.5, 120))[:, None]
    alpha = deg(np.linspace(-179.5, 179.5, 241))[None, :]
    s = np.arcsin(a / r)
    printed = (theta - np.pi + s < alpha) & (alpha < theta - s)
    assert np.array_equal(fits_inside(theta, alpha, a, r), printed)


def _one(theta_d, alpha_d, **kw):
    params = dict(a=0.3, r=3.0, k=0.5, g=G)
    params.update(kw)
    res = wheel.horizontal_orbit(deg(theta_d), deg(alpha_d), **params)
    return Status(int(res["status"])), Reason(int(res["reason"])), res


@pytest.mark.parametrize("theta_d", [30.0, 90.0, 150.0])
def test_alpha_zero_has_no_orbit(theta_d):
    status, reason, res = _one(theta_d, 0.0)
    assert (status, reason) == (Status.NO_ORBIT, Reason.ALPHA_IN_ORBIT_PLANE)
    assert np.isnan(res["omega"]) and np.isfinite(res["r_prime"])


def test_alpha_ninety_is_a_wheel_at_rest():
    status, reason, _ = _one(150.0, 90.0)
    assert (status, reason) == (Status.NO_ORBIT, Reason.OMEGA_ZERO)


def test_zero_denominator_of_eq29():
    a, r, k, alpha = 0.3, 3.0, 0.5, deg(30.0)
    theta = np.pi - np.arcsin((k + 1) * a * np.cos(alpha) / ((2 * k + 1) * r))
    res = wheel.horizontal_orbit(theta, alpha, a, r, k, G)
    assert (Status(int(res["status"])), Reason(int(res["reason"]))) == (Status.NO_ORBIT, Reason.ZERO_DENOMINATOR)


@pytest.mark.parametrize("theta_d, alpha_d", [(0.0, -10.0), (0.0, 10.0), (180.0, 30.0), (180.0, -10.0)])
def test_poles_give_a_status_not_a_warning(theta_d, alpha_d):
    status, _, res = _one(theta_d, alpha_d)
    assert status != Status.OK  # no orbit at a pole of zero radius survives the checks
    assert np.isfinite(res["r_prime"])


def test_r_prime_zero_is_defined():
    # r sin(theta) = a cos(alpha): the centre sits on the axis, spinning in place
    alpha = deg(40.0)
    theta = np.pi - np.arcsin(0.3 * np.cos(alpha) / 3.0)
    res = wheel.horizontal_orbit(theta, alpha, 0.3, 3.0, 0.5, G)
    assert abs(res["r_prime"]) < 1e-12
    assert res["v_cm"] == pytest.approx(0.0, abs=1e-9)
    assert np.isfinite(res["omega"])


def test_status_order_and_slips():
    status, reason, res = _one(60.0, 10.0, mu=1.0)
    assert status == Status.SLIPS and res["mu_required"] > 1.0
    status, _, _ = _one(60.0, 10.0, mu=1.2)
    assert status == Status.OK
    status, reason, _ = _one(60.0, 25.0 + 40.0)  # beyond eq. (0): no fit comes first
    assert (status, reason) == (Status.NO_FIT, Reason.NO_FIT_INSIDE)
    status, reason, _ = _one(45.0, 30.0)  # fits, real, but eq. (33) fails
    assert (status, reason) == (Status.NO_CONTACT, Reason.NO_CONTACT_INSIDE)


def test_outside_needs_eq81_and_eq83():
    status, reason, _ = _one(60.0, 10.0, outside=True)
    assert (status, reason) == (Status.NO_FIT, Reason.NO_FIT_OUTSIDE)
    # alpha in (theta, 90): Omega^2 > 0 and, for a small wheel high up, eq. (83) holds
    status, _, res = _one(30.0, 80.0, outside=True)
    assert status == Status.OK
    assert res["omega2"] * res["r_prime"] * np.sin(deg(30.0)) < G * np.cos(deg(30.0))  # eq. (83)


def test_vectorised_shapes_broadcast():
    theta = deg(np.array([30.0, 60.0, 90.0]))[:, None]
    alpha = deg(np.array([5.0, 10.0]))[None, :]
    res = wheel.horizontal_orbit(theta, alpha, 0.3, 3.0, 0.5, G)
    assert res["omega"].shape == (3, 2) and res["status"].shape == (3, 2)
    assert res["omega"].dtype == np.float64
