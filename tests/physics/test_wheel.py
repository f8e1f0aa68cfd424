"""Horizontal orbits of a wheel: eqs. (0), (8b), (13), (29)-(36), checked
against first principles (Newton-Euler with vectors), not against the paper's
own algebra."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from deathsphere.physics import wheel
from deathsphere.physics.geometry import SINGULAR, fits_inside, r_prime
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
    # and a 1% wrong rate does not balance: the check can fail.  dL/dt and the
    # torque of the centripetal force scale with Omega^2, gravity's torque
    # a e3 x g z (magnitude a g |cos alpha|) does not, so (1.01^2 - 1) of it
    # is left over; compared with the whole torque (which can be 1000x
    # larger near the poles, cancelling against dL/dt) it could be tiny
    wrong, *_ = newton_euler_residual(theta, alpha, a, r, k, G, 1.01 * omega)
    assert np.max(np.abs(wrong)) == pytest.approx((1.01**2 - 1) * a * G * abs(np.cos(alpha)),
                                                  rel=1e-6, abs=1e-9 * scale)


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
def test_mu_and_centre_accel_invariant_under_scaling(theta_d, alpha_d, a, rr, k, scale):
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
        assert abs(wheel.centre_accel_g(deg(theta_d), deg(alpha_d), a, a * rr, k)) == pytest.approx(res["accel_g"], rel=1e-9)
    assert np.isfinite(res["r_prime"])


def test_centre_accel_g_is_eq36():
    theta, alpha, a, r, k = deg(60), deg(10), 0.3, 3.0, 0.5
    rp = r_prime(theta, alpha, a, r)
    expected = (1 / np.tan(alpha)) / (2 * k + 1 + k * (a / rp) * np.cos(alpha))
    assert wheel.centre_accel_g(theta, alpha, a, r, k) == pytest.approx(expected, rel=1e-14)


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


# --- the optimised core against a plain transcription of the equations -------

def reference_orbit(theta, alpha, a, r, k, g, outside=False, mu=np.inf):
    """horizontal_orbit written straight from the equations: every input
    broadcast to full arrays, each trigonometric function recomputed where it
    is used, status by np.select (first true condition wins).  Eq. (29) is
    written as g cos(alpha) / (sin(alpha) D), the package's operation order,
    so that the two agree to round-off even near the contact boundary."""
    theta, alpha, a, r, k, g, mu = np.broadcast_arrays(*(np.asarray(x, dtype=float)
                                                         for x in (theta, alpha, a, r, k, g, mu)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    with np.errstate(all="ignore"):
        rp = r * np.sin(theta) - a * np.cos(alpha)                                  # eq. (8b)
        fits = np.where(outside, np.sin(alpha - theta) > 0.0, np.sin(theta - alpha) > a / r)  # (81), (0)
        den = np.sin(alpha) * ((2 * k + 1) * rp + k * a * np.cos(alpha))
        undefined = np.abs(den) <= SINGULAR * ((2 * k + 1) * r + (k + 1) * a)
        omega2 = np.where(undefined, np.nan, g * np.cos(alpha) / den)              # eq. (29)
        zero = ~undefined & (np.abs(omega2) <= SINGULAR * g / r)
        real = ~undefined & ~zero & (omega2 > 0)
        om2 = np.where(real, omega2, np.nan)
        omega = np.sqrt(om2)
        f_r = -(rp * om2 * np.sin(theta) - g * np.cos(theta))                      # eq. (32)
        f_theta = -(rp * om2 * np.cos(theta) + g * np.sin(theta))
        normal = np.where(outside, f_r, -f_r)                                       # (83), (33)
        mu_required = np.where(normal > 0, np.abs(f_theta) / normal, np.nan)      # eq. (35)
    failed = [~fits, undefined, zero, ~real, ~(normal > 0), mu_required > mu]
    status = np.select(failed, [Status.NO_FIT, Status.NO_ORBIT, Status.NO_ORBIT, Status.NO_ORBIT,
                                Status.NO_CONTACT, Status.SLIPS], Status.OK)
    reason = np.select(failed, [
        np.where(outside, Reason.NO_FIT_OUTSIDE, Reason.NO_FIT_INSIDE),
        np.where(np.abs(np.sin(alpha)) <= SINGULAR, Reason.ALPHA_IN_ORBIT_PLANE, Reason.ZERO_DENOMINATOR),
        Reason.OMEGA_ZERO, Reason.OMEGA_IMAGINARY,
        np.where(outside, Reason.NO_CONTACT_OUTSIDE, Reason.NO_CONTACT_INSIDE),
        Reason.SLIPS], Reason.NONE)
    return {
        "r_prime": rp, "omega2": omega2, "omega": omega, "period": 2 * np.pi / omega,
        "v_cm": np.abs(rp) * omega, "spin": rp * omega / a, "omega3": -omega * np.sin(alpha),
        "accel": np.abs(rp) * om2, "accel_g": np.abs(rp) * om2 / g,                # eq. (36)
        # the load: the contact force's size per weight, from its two components (eq. 32)
        "load_g": np.hypot(normal, f_theta) / g,
        "normal": normal, "friction": f_theta, "mu_required": mu_required,
        "status": status.astype(np.int8), "reason": reason.astype(np.int8),
    }


def assert_same_orbits(got, want):
    assert list(got) == list(want)
    for key, expected in want.items():
        value = np.asarray(got[key])
        assert value.shape == expected.shape and value.dtype == expected.dtype, key
        if key in ("status", "reason"):
            np.testing.assert_array_equal(value, expected, err_msg=key)
        else:
            np.testing.assert_allclose(value, expected, rtol=1e-12, atol=0, equal_nan=True, err_msg=key)


def _random_orbits(n, seed):
    """Angles in degrees over the whole range, a fifth of them exactly 0, 90
    or 180 deg (alpha also -90, -180): the singular cases of eqs. (29), (32)."""
    rng = np.random.default_rng(seed)
    theta = rng.uniform(0.0, 180.0, n)
    alpha = rng.uniform(-180.0, 180.0, n)
    pick = rng.random(n) < 0.2
    theta[pick] = rng.choice([0.0, 90.0, 180.0], pick.sum())
    pick = rng.random(n) < 0.2
    alpha[pick] = rng.choice([-180.0, -90.0, 0.0, 90.0, 180.0], pick.sum())
    return rng, deg(theta), deg(alpha)


@pytest.mark.parametrize("side", ["inside", "outside", "mixed"])
@pytest.mark.parametrize("params", ["scalars", "per_row", "varied"])
def test_horizontal_orbit_matches_reference(side, params):
    n = 2 * wheel.CHUNK + 1234          # several pieces, and a short last one
    rng, theta, alpha = _random_orbits(n, seed=["inside", "outside", "mixed"].index(side))
    outside = {"inside": False, "outside": True, "mixed": rng.random(n) < 0.5}[side]
    if params == "scalars":
        a, r, k, g, mu = 0.3, 3.0, 0.5, G, 1.0
    elif params == "per_row":             # what the model passes: one value, repeated
        a, r, k, g, mu = (np.full(n, v) for v in (0.3, 3.0, 0.5, G, 1.0))
        outside = np.broadcast_to(outside, (n,)).copy()
    else:
        a = rng.uniform(0.01, 1.0, n)
        r = a * rng.uniform(1.1, 30.0, n)
        k, g = rng.uniform(0.0, 2.0, n), rng.uniform(1.0, 25.0, n)
        mu = np.where(rng.random(n) < 0.3, np.inf, rng.uniform(0.0, 3.0, n))
    got = wheel.horizontal_orbit(theta, alpha, a, r, k, g, outside=outside, mu=mu)
    want = reference_orbit(theta, alpha, a, r, k, g, outside=outside, mu=mu)
    assert_same_orbits(got, want)
    # every status and reason the core can give occurs here
    reasons = set(np.unique(want["reason"]))
    assert {Reason.NONE, Reason.NO_FIT_INSIDE if side != "outside" else Reason.NO_FIT_OUTSIDE,
            Reason.ALPHA_IN_ORBIT_PLANE, Reason.OMEGA_ZERO, Reason.OMEGA_IMAGINARY, Reason.SLIPS} <= reasons


@pytest.mark.parametrize("outside", [False, True])
def test_horizontal_orbit_matches_reference_on_a_degree_grid(outside):
    """Every whole degree, so every exact 0, 90, 180 deg pair, broadcast from
    (181, 1) and (1, 361) and evaluated in pieces; also one orbit at a time."""
    theta = deg(np.arange(0.0, 181.0))[:, None]
    alpha = deg(np.arange(-180.0, 181.0))[None, :]
    want = reference_orbit(theta, alpha, 0.3, 3.0, 0.5, G, outside, 1.0)
    assert_same_orbits(wheel.horizontal_orbit(theta, alpha, 0.3, 3.0, 0.5, G, outside, 1.0), want)
    for i, j in [(0, 180), (0, 0), (90, 270), (90, 180), (180, 180), (180, 0), (60, 190), (30, 260)]:
        one = wheel.horizontal_orbit(theta[i, 0], alpha[0, j], 0.3, 3.0, 0.5, G, outside, 1.0)
        assert_same_orbits({key: np.asarray(v).reshape(1) for key, v in one.items()},
                           {key: v[i, j].reshape(1) for key, v in want.items()})
