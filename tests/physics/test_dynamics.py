"""Exact equations of motion (deathsphere.physics.dynamics), beyond the paper.

The steady orbits of McDonald (1993) -- Table 1 (eq. 29), the rolling sphere
(eq. 55) -- must be fixed points of the exact flow in the turning frame; the
energy and the constraints must be invariant along integrations.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from deathsphere.physics import dynamics as dyn
from deathsphere.physics.sphere import orbit_rates
from deathsphere.physics.vertical_orbit import lap_time
from deathsphere.physics.wheel import horizontal_orbit

G = 9.80665
A, R, K = 0.3, 3.0, 0.5
# McDonald (1993) Table 1: (theta, alpha) in degrees
TABLE1 = [(15, 5), (30, 5), (45, 10), (60, 10), (60, 25), (75, 15), (75, 30),
          (90, 25), (90, 45), (135, 60)]


def table1():
    th, al = np.radians(np.array(TABLE1, dtype=float)).T
    return th, al


def residual_scale(X, Om, a):
    """Natural size of d(state)/dt on an orbit: |c| Omega, Omega, |w| Omega."""
    return np.linalg.norm(X[6:9], axis=0) * np.abs(Om) + np.abs(Om) * (1 + np.linalg.norm(X[0:3], axis=0) / a)


def test_table1_orbits_are_fixed_points_of_the_turning_frame_flow():
    th, al = table1()
    p = dyn.body_params(A, R, K, G)
    X, Om = dyn.wheel_orbit_state(th, al, A, R, K, G)
    f = dyn.rhs(X, p, frame_rate=Om)
    rel = np.max(np.abs(f), axis=0) / residual_scale(X, Om, A)
    assert np.all(rel < 1e-14)
    # the check has teeth: a rate off eq. (29) by 1e-6 is not a fixed point
    f_off = dyn.rhs(X, p, frame_rate=Om * (1 + 1e-6))
    assert np.all(np.max(np.abs(f_off), axis=0) / residual_scale(X, Om, A) > 1e-8)
    X_off, _ = dyn.wheel_orbit_state(th, al, A, R, K, G * (1 + 1e-6))
    f_off = dyn.rhs(X_off, p, frame_rate=Om * np.sqrt(1 + 1e-6))
    assert np.all(np.max(np.abs(f_off), axis=0) / residual_scale(X, Om, A) > 1e-9)


def test_contact_force_from_state_reproduces_eqs_30_32():
    th, al = table1()
    p = dyn.body_params(A, R, K, G)
    X, Om = dyn.wheel_orbit_state(th, al, A, R, K, G)
    cf = dyn.contact_force(X, p)
    h = horizontal_orbit(th, al, A, R, K, G)
    np.testing.assert_allclose(cf["normal"], h["normal"], rtol=1e-12)
    np.testing.assert_allclose(cf["friction_magnitude"], np.abs(h["friction"]), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(cf["mu_required"], h["mu_required"], rtol=1e-12)
    # Table 1's printed mu (16.1, 2.82, ...) to its 2-3 figures
    printed = np.array([16.1, 2.82, 2.15, 1.19, 3.45, 0.96, 2.13, 0.96, 2.04, 0.56])
    np.testing.assert_allclose(cf["mu_required"], printed, rtol=0.02)


def test_outside_wheel_orbit_is_a_fixed_point_with_outward_normal_force():
    th, al = np.radians([40.0, 60.0, 30.0]), np.radians([50.0, 75.0, 205.0])
    p = dyn.body_params(A, R, K, G, outside=True)
    X, Om = dyn.wheel_orbit_state(th, al, A, R, K, G, outside=True)
    h = horizontal_orbit(th, al, A, R, K, G, outside=True)
    assert np.all(h["status"] == 0)
    f = dyn.rhs(X, p, frame_rate=Om)
    assert np.all(np.max(np.abs(f), axis=0) / residual_scale(X, Om, A) < 1e-13)
    res = dyn.constraint_residuals(X, p)
    assert np.all(np.abs(res["contact"]) < 1e-14 * R)
    np.testing.assert_allclose(dyn.contact_force(X, p)["normal"], h["normal"], rtol=1e-12)


@pytest.mark.parametrize("outside", [False, True])
def test_sphere_orbits_of_eq_55_are_fixed_points(outside):
    k = 0.4
    th = np.radians([30.0, 60.0, 90.0, 120.0, 150.0])
    omega3 = np.array([40.0, -30.0, 25.0, 10.0, -5.0])
    slow, fast = orbit_rates(th, omega3, A, R, k, G, outside)
    p = dyn.body_params(A, R, k, G, outside=outside, sphere=True)
    for Om in (slow, fast):
        ok = np.isfinite(Om)
        X, w3 = dyn.sphere_orbit_state(th[ok], Om[ok], A, R, k, G, outside)
        np.testing.assert_allclose(w3, omega3[ok], rtol=1e-11)
        f = dyn.rhs(X, p, frame_rate=Om[ok])
        idx = np.r_[0:3, 6:9]          # rows 3-5 hold a marker, not dynamics
        assert np.all(np.max(np.abs(f[idx]), axis=0) / residual_scale(X, Om[ok], A) < 1e-13)
    # on the equator only one root: Omega = -g/(k a omega3)
    assert np.isnan(fast[2]) and np.isclose(slow[2], -G / (k * A * omega3[2]))


def test_energy_and_constraints_are_invariant_along_a_perturbed_motion():
    p = dyn.body_params(A, R, K, G)
    X, Om = dyn.wheel_orbit_state(np.radians([60.0, 135.0]), np.radians([25.0, 60.0]), A, R, K, G)
    rng = np.random.default_rng(0)
    X = dyn.project(X + 1e-2 * rng.normal(size=X.shape) * np.r_[[A] * 3, [1] * 3, [5] * 3][:, None], p)
    assert np.all(np.abs(dyn.constraint_residuals(X, p)["contact"]) < 1e-14)
    sol = solve_ivp(dyn.ode(dyn.BodyParams(*(np.broadcast_to(x, (2,)) for x in p))),
                    (0, 2.0), X.reshape(-1), method="DOP853", rtol=1e-10, atol=1e-12,
                    vectorized=True, dense_output=False)
    Y = sol.y.reshape(9, 2, -1)
    pcol = dyn.BodyParams(*(np.broadcast_to(x, (2,))[:, None] for x in p))
    E = dyn.energy(Y, pcol)
    res = dyn.constraint_residuals(Y, pcol)
    scale = np.abs(E[:, :1]) + G * R
    assert np.max(np.abs(E - E[:, :1]) / scale) < 1e-9
    assert np.max(np.abs(res["contact"])) < 1e-9 * R
    assert np.max(np.abs(res["axis"])) < 1e-9
    assert np.max(np.abs(res["slip"])) == 0.0
    # the motion really moved: energy is not trivially constant state-wise
    assert np.ptp(Y[2], axis=1).min() > 1e-3


def test_sphere_spin_omega3_is_conserved():
    """For a sphere, w.e3 is a constant of the motion (paper, after eq. 44)."""
    k = 0.4
    p = dyn.body_params(A, R, k, G, sphere=True)
    X, w3 = dyn.sphere_orbit_state(np.radians(70.0), 4.0, A, R, k, G)
    X = dyn.project(X + np.r_[0.01, 0.02, 0, 0, 0, 0, 0.5, -0.3, 0.2], p)
    sol = solve_ivp(dyn.ode(p), (0, 3.0), X, method="DOP853", rtol=1e-10, atol=1e-12)
    e3 = sol.y[0:3] / np.linalg.norm(sol.y[0:3], axis=0)
    w3_t = np.sum(sol.y[6:9] * e3, axis=0)
    assert np.ptp(w3_t) < 1e-8 * np.max(np.abs(sol.y[6:9]))
    assert np.ptp(sol.y[2]) > 1e-3


def test_contact_is_preserved_identically_even_off_the_constraint_surface():
    """d|p|/dt = 0 for any state (docs/dynamics.md eq. D5): a check of the
    contact geometry of the wheel inside and outside and of the sphere."""
    rng = np.random.default_rng(1)
    n = 50
    X = rng.normal(size=(9, n))
    X[0:3] *= 2.0
    for outside in (False, True):
        for sphere in (False, True):
            p = dyn.body_params(A, R, K, G, outside=outside, sphere=sphere)
            res = dyn.constraint_residuals(X, p)
            speed = np.linalg.norm(X[6:9], axis=0) * A
            assert np.all(np.abs(res["contact_rate"]) < 1e-13 * speed * 10)


def test_contact_geometry_of_a_constructed_state():
    """state_from_contact puts the rim tangent to the sphere at p."""
    rng = np.random.default_rng(2)
    n = 20
    ph = rng.normal(size=(3, n))
    e1 = rng.normal(size=(3, n))
    w = rng.normal(size=(3, n))
    for outside in (False, True):
        p = dyn.body_params(A, R, K, G, outside=outside)
        X = dyn.state_from_contact(ph, e1, w, p)
        pc = dyn.contact_point(X, p)
        np.testing.assert_allclose(pc, R * ph / np.linalg.norm(ph, axis=0), atol=1e-14)
        res = dyn.constraint_residuals(X, p)
        ok = np.abs(np.sum(ph * e1, axis=0) / np.linalg.norm(ph, axis=0)
                    / np.linalg.norm(e1, axis=0)) < 0.9          # fits: |p_perp| > a
        assert np.all(np.abs(res["contact"][ok]) < 1e-14)
        # the rim's tangent at p (axis 2) is tangent to the sphere
        e3 = (pc - X[0:3]) / A
        e2 = np.cross(e3, X[3:6], axis=0)
        assert np.all(np.abs(np.sum(e2 * pc, axis=0))[ok] < 1e-13)


def test_vertical_orbit_returns_after_one_period_of_eq_27():
    th, a, r, k = np.radians(70.0), 0.3, 3.0, 0.5
    rp = r * np.sin(th) - a
    pd0 = 1.3 * np.sqrt(G / rp)
    X = dyn.vertical_orbit_state(th, pd0, a, r)
    T = lap_time(th, pd0, a, r, k, G)
    p = dyn.body_params(a, r, k, G)
    sol = solve_ivp(dyn.ode(p), (0, T), X, method="DOP853", rtol=1e-12, atol=1e-13)
    np.testing.assert_allclose(sol.y[:, -1], X, atol=1e-9)
    # and not before: half way round the wheel is at the bottom
    half = solve_ivp(dyn.ode(p), (0, T / 2), X, method="DOP853", rtol=1e-12, atol=1e-13)
    assert half.y[2, -1] < -rp + 1e-6


def test_rhs_vectorised_over_bodies_and_solve_ivp_columns():
    th, al = table1()
    p = dyn.body_params(A, R, K, G)
    X, Om = dyn.wheel_orbit_state(th, al, A, R, K, G)
    fun = dyn.ode(dyn.BodyParams(*(np.broadcast_to(x, th.shape) for x in p)))
    f1 = fun(0.0, X.reshape(-1))
    cols = np.stack([X.reshape(-1), 2 * X.reshape(-1)], axis=1)
    f2 = fun(0.0, cols)
    np.testing.assert_allclose(f2[:, 0], f1, rtol=1e-15)
    one = np.stack([dyn.rhs(X[:, i], p) for i in range(th.size)], axis=1)
    np.testing.assert_allclose(f1.reshape(9, -1), one, rtol=1e-14, atol=1e-14)


def test_singular_inputs_give_nan_without_warnings():
    # alpha = 0: eq. (29) diverges; alpha = 90 deg: Omega = 0
    X, Om = dyn.wheel_orbit_state(np.radians([90.0, 135.0]), np.radians([0.0, 90.0]), A, R, K, G)
    assert np.all(np.isnan(Om))
    slow, fast = orbit_rates(np.radians(30.0), 0.0, A, R, 0.4, G)
    assert np.isnan(slow) and np.isnan(fast)
    X, w3 = dyn.sphere_orbit_state(np.radians(30.0), 0.0, A, R, 0.4, G)
    assert np.isnan(w3)
    assert np.isnan(lap_time(np.radians(5.0), 1.0, A, R, K, G))


@pytest.mark.parametrize("kw", [dict(a=0.0), dict(a=-1.0), dict(k=0.0), dict(g=0.0),
                                dict(r=0.2), dict(a=np.nan)])
def test_invalid_parameters_raise(kw):
    args = dict(a=A, r=R, k=K, g=G)
    args.update(kw)
    with pytest.raises(ValueError):
        dyn.body_params(**args)


def _random_bodies(rng, n):
    """Random states near the constraint surface (both sides, wheels and
    spheres, arbitrary axis and spin) and their parameters."""
    a = rng.uniform(0.05, 1.0, n)
    r = a + rng.uniform(0.5, 5.0, n)
    k = rng.uniform(0.05, 2.0, n)
    outside = rng.random(n) < 0.3
    sphere = rng.random(n) < 0.3
    p = dyn.BodyParams(a, r, k, np.full(n, G), outside, sphere)
    p_hat = rng.normal(size=(3, n))
    e1 = rng.normal(size=(3, n))
    w = rng.normal(scale=10.0, size=(3, n))
    X = dyn.state_from_contact(p_hat, e1, w, p)
    X = X + rng.normal(scale=1e-3, size=X.shape)          # off the constraints too
    return X, p, rng.normal(scale=3.0, size=n)


def test_scalar_one_body_path_equals_numpy_path():
    """The one-body fast path (Python floats) runs the same lines as the
    vectorised right-hand side; both must agree to 1e-12 at random states,
    as must the contact force the simulator's events use."""
    rng = np.random.default_rng(7)
    X, p, fr = _random_bodies(rng, 300)
    f_np = dyn.rhs(X, p, fr)
    cf = dyn.contact_force(X, p)
    scale = np.max(np.abs(f_np), axis=0)
    for i in range(X.shape[1]):
        pi = dyn.BodyParams(*(x[i:i + 1] for x in p))
        coef = dyn.scalar_coefficients(pi)
        f1 = np.array(dyn.scalar_rates(X[:, i].tolist(), coef, float(fr[i])))
        assert np.all(np.abs(f1 - f_np[:, i]) <= 1e-12 * scale[i])
        via_ode = dyn.ode(pi, fr[i])(0.0, X[:, i].copy())
        assert np.all(np.abs(via_ode - f_np[:, i]) <= 1e-12 * scale[i])
        n1, fm1 = dyn.contact_values(X[:, i].tolist(), coef, G)
        fs = abs(cf["normal"][i]) + cf["friction_magnitude"][i]
        assert abs(n1 - cf["normal"][i]) <= 1e-12 * fs
        assert abs(fm1 - cf["friction_magnitude"][i]) <= 1e-12 * fs


def test_vectorised_rhs_matches_per_body_and_complex_step_matches_finite_difference():
    """Bodies are independent: the rhs of n bodies at once equals the
    one-body results; complex input (complex step) gives the Jacobian."""
    rng = np.random.default_rng(8)
    X, p, fr = _random_bodies(rng, 40)
    f = dyn.rhs(X, p, fr)
    for i in range(0, 40, 7):
        pi = dyn.BodyParams(*(x[i:i + 1] for x in p))
        np.testing.assert_allclose(dyn.rhs(X[:, i:i + 1], pi, fr[i:i + 1])[:, 0], f[:, i], rtol=0, atol=0)
    d = rng.normal(size=X.shape)
    jd = np.imag(dyn.rhs(X + 1e-30j * d, p, fr)) / 1e-30
    h = 1e-6
    fd = (dyn.rhs(X + h * d, p, fr) - dyn.rhs(X - h * d, p, fr)) / (2 * h)
    np.testing.assert_allclose(jd, fd, rtol=1e-5, atol=1e-5 * np.max(np.abs(jd)))
