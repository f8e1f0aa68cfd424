"""A sphere rolling inside / outside a fixed sphere: McDonald (1993) eqs. (41)-(59).

The rates of eq. (55) and the contact force of eq. (57) are checked against
Newton's and Euler's equations written with explicit 3-d vectors (no use of
the paper's component equations), on both sides of the fixed sphere.
"""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from deathsphere.physics import sphere as S
from deathsphere.physics.status import Reason, Status

G = 9.80665
A, R = 0.3, 3.0

thetas = st.floats(np.radians(2), np.radians(178))
ks = st.floats(0.05, 1.5)
spins = st.floats(-400.0, 400.0)


def vector_residuals(theta, omega, omega3, k, outside, a=A, r=R):
    """Newton + Euler for a ball whose centre runs round a horizontal circle.

    Position of the centre rho n(t), n the outward normal at the contact
    point; contact arm (centre -> contact) s a n with s = +1 inside, -1
    outside; omega3 the spin along that arm.  Returns the Euler residual
    k a^2 d(omega)/dt - arm x F (per unit mass, F = r'' + g z) and F.
    """
    s = -1.0 if outside else 1.0
    rho = r - s * a
    n = np.array([np.sin(theta), 0.0, np.cos(theta)])          # at phi = 0
    n_dot = omega * np.sin(theta) * np.array([0.0, 1.0, 0.0])
    n_ddot = -omega ** 2 * np.sin(theta) * np.array([1.0, 0.0, 0.0])
    zhat = np.array([0.0, 0.0, 1.0])
    force = rho * n_ddot + G * zhat
    # rolling: v + w x (s a n) = 0  =>  w = w_n n - (s rho / a) n x n_dot,  w_n = s omega3
    w_n = s * omega3
    w_dot = w_n * n_dot - (s * rho / a) * np.cross(n, n_ddot)
    euler = k * a ** 2 * w_dot - np.cross(s * a * n, force)
    # check the rolling constraint itself
    w = w_n * n - (s * rho / a) * np.cross(n, n_dot)
    slip = rho * n_dot + np.cross(w, s * a * n)
    return euler, force, slip, n


@settings(max_examples=80, deadline=None)
@given(theta=thetas, omega3=spins, k=ks, outside=st.booleans())
def test_roots_of_eq55_solve_newton_and_euler(theta, omega3, k, outside):
    slow, fast = S.orbit_rates(theta, omega3, A, R, k, G, outside)
    rho = R + A if outside else R - A
    for om in (float(slow), float(fast)):
        if np.isnan(om):
            continue
        lhs = (k + 1) * rho * om ** 2 * np.cos(theta) + k * A * omega3 * om + G   # eq. (55)
        scale = (k + 1) * rho * om ** 2 + k * A * abs(omega3 * om) + G
        assert lhs == pytest.approx(0.0, abs=1e-11 * scale)
        euler, force, slip, _ = vector_residuals(theta, om, omega3, k, outside)
        assert np.abs(slip).max() < 1e-9 * (1 + rho * abs(om))
        assert np.abs(euler).max() < 1e-10 * A * scale
    if not (np.isnan(slow) or np.isnan(fast)):
        assert abs(slow) <= abs(fast) * (1 + 1e-12)


@settings(max_examples=60, deadline=None)
@given(theta=thetas, omega3=spins, k=ks)
def test_real_roots_iff_eq56(theta, omega3, k):
    """Eq. (56): real orbits iff (k a omega3)^2 >= 4 (k+1) g r' cos(theta)."""
    disc = (k * A * omega3) ** 2 - 4 * (k + 1) * G * (R - A) * np.cos(theta)
    assume(abs(disc) > 1e-9 * (k * A * omega3) ** 2 + 1e-9)
    assume(abs(np.cos(theta)) > 1e-9)
    slow, fast = S.orbit_rates(theta, omega3, A, R, k, G)
    assert np.isfinite(slow) == (disc > 0)
    assert np.isfinite(fast) == (disc > 0)
    w_min = float(S.omega3_min_real(theta, A, R, k, G))
    assert (abs(omega3) >= w_min) == (disc > 0)


@settings(max_examples=60, deadline=None)
@given(theta=thetas, omega=st.floats(0.05, 30.0), sign=st.sampled_from([-1.0, 1.0]),
       k=ks, outside=st.booleans())
def test_from_rate_round_trip(theta, omega, sign, k, outside):
    omega = sign * omega
    orbit = S.sphere_orbit_from_rate(theta, omega, A, R, k, G, outside)
    w3 = float(orbit["omega3"])
    back = S.sphere_orbit(theta, w3, A, R, k, G, outside, branch=orbit["branch"])
    assert float(back["omega"]) == pytest.approx(omega, rel=1e-9)
    for key in ("normal", "friction", "status", "r_prime", "v_cm"):
        np.testing.assert_allclose(back[key], orbit[key], rtol=1e-8, atol=1e-9)


@settings(max_examples=60, deadline=None)
@given(theta=thetas, omega=st.floats(-30.0, 30.0), outside=st.booleans())
def test_contact_force_is_m_times_acceleration_plus_gravity(theta, omega, outside):
    """Eq. (57), corrected: F/m = r'' + g z projected on the normal and the meridian."""
    normal, friction = S.contact_force(theta, omega, A, R, G, outside)
    _, force, _, n = vector_residuals(theta, omega, 0.0, 0.4, outside)
    theta_hat = np.array([np.cos(theta), 0.0, -np.sin(theta)])
    pressing = force @ n if outside else -(force @ n)
    scale = 1 + abs(omega) ** 2 * R + G
    assert float(normal) == pytest.approx(pressing, abs=1e-12 * scale)
    assert float(friction) == pytest.approx(force @ theta_hat, abs=1e-12 * scale)
    assert force[1] == 0.0          # no azimuthal force on a steady orbit


def brute_force_min_contact(theta, k, outside):
    """Least |omega3| on a fine grid for which some branch keeps contact."""
    w = np.linspace(0.0, 600.0, 120001)
    out = S.sphere_orbit(theta, w, A, R, k, G, outside)
    good = (out["status"] == Status.OK).any(axis=-1)
    return w[np.argmax(good)] if good.any() else np.nan


@pytest.mark.parametrize("outside", [False, True])
@pytest.mark.parametrize("theta_deg", [10.0, 30.0, 45.0, 49.0, 51.0, 60.0, 80.0, 100.0])
def test_min_contact_spin_against_scan(theta_deg, outside):
    theta, k = np.radians(theta_deg), 0.4
    ref = brute_force_min_contact(theta, k, outside)
    got = float(S.omega3_min_contact(theta, A, R, k, G, outside))
    if outside and theta_deg > 90:
        assert np.isnan(got) and np.isnan(ref)
    else:
        assert got == pytest.approx(ref, abs=0.006)


@settings(max_examples=80, deadline=None)
@given(theta=thetas, omega3=spins, k=ks, outside=st.booleans())
def test_contact_window_agrees_with_statuses(theta, omega3, k, outside):
    win = S.contact_spin_window(theta, A, R, k, G, outside)
    out = S.sphere_orbit(theta, omega3, A, R, k, G, outside)
    w = abs(omega3)
    for b in (0, 1):
        lo, hi = float(win[f"lo{b}"]), float(win[f"hi{b}"])
        st_b = out["status"][b]
        if st_b == Status.NO_ORBIT:
            continue
        # stay away from the window's edges, where round-off decides
        assume(np.isnan(lo) or abs(w - lo) > 1e-6 * (1 + lo))
        assume(np.isnan(hi) or np.isinf(hi) or abs(w - hi) > 1e-6 * (1 + hi))
        inside_window = (not np.isnan(lo)) and lo <= w < hi
        assert (st_b == Status.OK) == inside_window, (b, lo, hi, w)


def test_branch_convention():
    theta = np.radians([40.0, 90.0, 130.0, 130.0])
    w3 = np.array([-120.0, 30.0, 25.0, 0.0])
    out = S.sphere_orbit(theta, w3, A, R)
    om = out["omega"]
    assert out["branch"].tolist() == [[0, 1]] * 4
    assert abs(om[0, 0]) < abs(om[0, 1])                      # slow, fast
    assert np.sign(om[0, 0]) == np.sign(om[0, 1]) == 1        # above: both against omega3
    assert om[1, 0] == pytest.approx(-G / (0.4 * A * 30.0))   # equator: one root
    assert out["status"][1, 1] == Status.NO_ORBIT and out["reason"][1, 1] == Reason.EQUATOR_SINGLE_ROOT
    assert np.sign(om[2, 0]) != np.sign(om[2, 1])             # below: opposite senses
    assert om[3, 0] == pytest.approx(-om[3, 1]) and om[3, 0] > 0   # omega3 = 0: mirror pair
    # the slow branch is continuous across the equator
    near = S.sphere_orbit(np.radians([89.999, 90.001]), 30.0, A, R)["omega"][:, 0]
    assert near == pytest.approx(om[1, 0], rel=1e-3)
    # explicit branch argument broadcasts with the inputs
    one = S.sphere_orbit(theta, w3, A, R, branch=1)
    np.testing.assert_array_equal(one["omega"], om[:, 1])


def test_statuses_and_outputs():
    out = S.sphere_orbit(np.radians([0.0, 90.0, 30.0, 60.0]), np.array([50.0, 0.0, 10.0, 0.0]), A, R)
    assert out["status"][:, 0].tolist() == [Status.NO_ORBIT] * 4
    assert out["reason"][:, 0].tolist() == [Reason.POLE, Reason.ZERO_RATE_EQUATOR,
                                           Reason.SPIN_TOO_SMALL, Reason.SPIN_TOO_SMALL]
    big = S.sphere_orbit(np.radians(60.0), -100.0, 3.0, 3.0)
    assert np.all(big["status"] == Status.NO_FIT) and np.all(big["reason"] == Reason.SPHERE_NO_FIT)
    # outside the fixed sphere every size fits
    assert np.all(S.sphere_orbit(np.radians(120.0), 5.0, 3.0, 3.0, outside=True)["status"] != Status.NO_FIT)
    o = S.sphere_orbit(np.radians(60.0), -75.0, A, R, mu=2.0)   # mu_required 13.6 and 1.37
    assert o["status"].tolist() == [Status.SLIPS, Status.OK]
    ok = o["status"] == Status.OK
    for key in ("r_prime", "rho", "alpha", "omega", "period", "v_cm", "spin", "spin_total",
                "accel", "accel_g", "normal", "friction", "mu_required"):
        assert np.all(np.isfinite(o[key][ok])), key
    theta = np.radians(60.0)
    assert o["r_prime"][1] == pytest.approx((R - A) * np.sin(theta))
    assert o["alpha"][1] == pytest.approx(theta - np.pi / 2)
    assert o["v_cm"][1] == pytest.approx(o["r_prime"][1] * abs(o["omega"][1]))
    assert o["period"][1] == pytest.approx(2 * np.pi / abs(o["omega"][1]))
    assert o["spin"][1] == pytest.approx(o["v_cm"][1] / A)
    assert o["spin_total"][1] == pytest.approx(np.hypot(o["spin"][1], 75.0))
    assert o["mu_required"][1] == pytest.approx(abs(o["friction"][1]) / o["normal"][1])
    assert S.equivalent_alpha(theta, True) == pytest.approx(theta + np.pi / 2)
    fr = S.sphere_orbit_from_rate(np.radians([60.0, 60.0]), np.array([0.0, 3.0]), A, R, k=0.0)
    assert fr["reason"].tolist() == [Reason.SPHERE_OMEGA_ZERO, Reason.SPHERE_K_ZERO]


def test_singular_inputs_give_statuses_not_warnings():
    """No warning of any kind on the singular inputs (asserted here, not only
    through the suite's RuntimeWarning filter), and a status on every row."""
    import warnings

    theta = np.array([0.0, np.pi / 2, np.pi, 1e-300, np.pi - 1e-15, np.radians(90.0)])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        for outside in (False, True):
            for k in (0.0, 0.4):
                for a in (0.3, 3.0, 5.0):
                    for w3 in (0.0, -1e-300, 50.0, 1e8):
                        out = S.sphere_orbit(theta, w3, a, R, k, G, outside, mu=0.0)
                        assert np.shape(out["status"])[0] == theta.size      # a row per theta (and branch)
                        S.sphere_orbit_from_rate(theta, w3, a, R, k, G, outside)
                        S.contact_spin_window(theta, a, R, k, G, outside)
                        S.omega3_min_contact(theta, a, R, k, G, outside)
    assert [str(w.message) for w in caught] == []
