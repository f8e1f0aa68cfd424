"""Exact linear stability (deathsphere.physics.stability), beyond the paper.

The reduced Jacobian is checked against (i) the full Jacobian of the flow
(the neutral modes removed are exactly the zero eigenvalues), (ii) nonlinear
solve_ivp runs of slightly perturbed orbits (frequency of a stable orbit,
growth rate of an unstable one), (iii) the closed form for the sphere.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import curve_fit

from deathsphere.physics import dynamics as dyn
from deathsphere.physics import stability as st

G = 9.80665
A, R, K = 0.3, 3.0, 0.5
TABLE1 = [(15, 5), (30, 5), (45, 10), (60, 10), (60, 25), (75, 15), (75, 30),
          (90, 25), (90, 45), (135, 60)]


def table1():
    return np.radians(np.array(TABLE1, dtype=float)).T


def full_jacobian(X0, p, Om):
    """9x9 Jacobian of the turning-frame flow by complex step (per orbit)."""
    n = X0.shape[1]
    J = np.zeros((n, 9, 9))
    for j in range(9):
        d = np.zeros((9, n))
        d[j] = 1.0
        J[:, :, j] = (np.imag(dyn.rhs(X0 + 1e-30j * d, p, Om)) / 1e-30).T
    return J


def test_table1_orbits_are_stable_with_two_nutation_frequencies():
    th, al = table1()
    res = st.wheel_stability(th, al, A, R, K, G)
    assert np.all(res["verdict"] == st.Verdict.STABLE)
    assert np.all(res["freq_slow"] > 0) and np.all(res["freq_fast"] > 2 * res["freq_slow"])
    # spectrum symmetric under lambda -> -lambda and on the imaginary axis
    ev = res["eigenvalues"]
    assert np.all(np.abs(ev.real) < 1e-12 * res["rate_scale"][:, None])


def test_removed_neutral_modes_are_exactly_the_zero_eigenvalues():
    th, al = np.radians([60.0, 90.0, 40.0]), np.radians([25.0, 80.0, 12.0])
    a, r = np.array([0.3, 0.3, 1.2]), 3.0
    res = st.wheel_stability(th, al, a, r, K, G)
    assert res["verdict"][1] == st.Verdict.UNSTABLE      # includes an unstable orbit
    X0, Om = dyn.wheel_orbit_state(th, al, a, r, K, G)
    p = dyn.BodyParams(a, np.full(3, r), np.full(3, K), np.full(3, G),
                       np.zeros(3, bool), np.zeros(3, bool))
    ev9 = np.linalg.eigvals(full_jacobian(X0, p, Om))
    for i in range(3):
        nontrivial = ev9[i][np.abs(ev9[i]) > 1e-6 * res["rate_scale"][i]]
        assert nontrivial.size == 4           # 5 zeros: 2 constraints, phase, family (Jordan)
        d = np.abs(np.sort_complex(nontrivial)[:, None] - res["eigenvalues"][i][None, :])
        assert np.all(d.min(axis=1) < 1e-9 * res["rate_scale"][i])


def _perturbed_run(th, al, a, r, k, pick, eps, T_of_lambda, n_t=3000):
    L = st.wheel_reduced_jacobian(th, al, a, r, k, G)
    Kr, B, X0, Om = L["K"][0], L["basis"][0], L["state"][:, 0], L["omega"][0]
    ev, vec = np.linalg.eig(Kr)
    j = pick(ev)
    lam = ev[j]
    dX = (B @ vec[:, j]).real
    dX /= np.linalg.norm(dX / np.r_[[a] * 3, [1] * 3, [np.linalg.norm(X0[6:])] * 3])
    p = dyn.body_params(a, r, k, G)
    X = dyn.project(X0 + eps * dX, p)
    T = T_of_lambda(lam)
    t = np.linspace(0, T, n_t)
    sol = solve_ivp(dyn.ode(p, Om), (0, T), X, method="DOP853", rtol=1e-10, atol=1e-13, t_eval=t)
    return lam, t, sol.y[5] - X0[5]          # e1_z: invariant under the rotation symmetry


@pytest.mark.parametrize("mode", ["slow", "fast"])
def test_nonlinear_oscillation_frequency_matches_linearisation(mode):
    th, al = np.radians(90.0), np.radians(45.0)
    if mode == "slow":
        pick = lambda ev: np.argmin(np.abs(ev.imag) - 1e-9 * (ev.imag > 0))
    else:
        pick = lambda ev: np.argmax(ev.imag)
    lam, t, d = _perturbed_run(th, al, A, R, K, pick, 1e-6, lambda l: 5 * 2 * np.pi / abs(l.imag))
    d = d - d.mean()
    s = np.sign(d)
    i = np.nonzero(s[1:] != s[:-1])[0]
    tc = t[i] - d[i] * (t[i + 1] - t[i]) / (d[i + 1] - d[i])
    measured = np.pi * (len(tc) - 1) / (tc[-1] - tc[0])
    assert abs(measured / abs(lam.imag) - 1) < 0.01


def test_nonlinear_growth_rate_of_an_unstable_orbit_matches_linearisation():
    # a large wheel (a/r = 0.3) on the equator tilted 60 deg: unstable
    th, al, a = np.radians(90.0), np.radians(60.0), 0.9
    res = st.wheel_stability(th, al, a, R, K, G)
    assert res["verdict"] == st.Verdict.UNSTABLE
    lam, t, d = _perturbed_run(th, al, a, R, K, lambda ev: np.argmax(ev.real + 1e-9 * ev.imag),
                               1e-8, lambda l: 6 / l.real, n_t=1500)
    f = lambda t, s, w, a1, b1, c1: np.exp(s * t) * (a1 * np.cos(w * t) + b1 * np.sin(w * t)) + c1
    popt, _ = curve_fit(f, t, d / 1e-8, p0=[lam.real, abs(lam.imag), 1.0, 0.0, 0.0])
    assert abs(popt[0] / lam.real - 1) < 0.02
    assert abs(abs(popt[1]) / abs(lam.imag) - 1) < 0.02
    np.testing.assert_allclose(res["growth_rate"], lam.real, rtol=1e-12)


def test_spurious_real_parts_are_far_below_the_stable_tolerance():
    """Round-off real parts of stable orbits vs STABLE_TOL (docs/stability.md)."""
    th, al = np.meshgrid(np.radians(np.arange(5, 176, 10.0)), np.radians(np.arange(2, 89, 4.0)),
                         indexing="ij")
    for a_r in (0.1, 0.3, 0.6):
        res = st.wheel_stability(th, al, a_r, 1.0, 0.25, G)
        rel = res["growth_rate"] / res["rate_scale"]
        stable = res["verdict"] == st.Verdict.STABLE
        unstable = res["verdict"] == st.Verdict.UNSTABLE
        assert stable.sum() > 50 and unstable.sum() > 5
        assert np.nanmax(rel[stable]) < 1e-3 * st.STABLE_TOL
        assert np.nanmin(rel[unstable]) > 10 * st.UNSTABLE_TOL


@pytest.mark.parametrize("outside", [False, True])
def test_sphere_exact_matches_closed_form_and_is_stable(outside):
    k = 0.4
    th, Om = np.meshgrid(np.radians(np.arange(10, 171, 20.0)), [-6.0, -0.7, 0.3, 2.0, 9.0],
                         indexing="ij")
    res = st.sphere_stability(th, Om, A, R, k, G, outside)
    cf = st.sphere_nutation_closed_form(th, Om, A, R, k, G, outside)
    np.testing.assert_allclose(res["freq_fast"], cf, rtol=1e-9)
    assert np.all(res["verdict"] == st.Verdict.STABLE)
    assert np.all(np.isnan(res["freq_slow"]))


def test_wheel_outside_linearisation_and_nonlinear_check():
    """An outside orbit with alpha near pi + theta (sec. 3): stable, and a
    perturbed run oscillates at the predicted slow frequency."""
    th, al = np.radians(45.0), np.radians(222.0)
    res = st.wheel_stability(th, al, A, R, K, G, outside=True)
    assert res["verdict"] == st.Verdict.STABLE
    L = st.wheel_reduced_jacobian(th, al, A, R, K, G, outside=True)
    X0, Om = L["state"][:, 0], L["omega"][0]
    p = dyn.body_params(A, R, K, G, outside=True)
    np.testing.assert_allclose(dyn.rhs(X0, p, Om), 0, atol=1e-12 * np.linalg.norm(X0[6:]) * Om)
    ev, vec = np.linalg.eig(L["K"][0])
    j = np.argmin(np.abs(ev.imag) - 1e-9 * (ev.imag > 0))
    dX = (L["basis"][0] @ vec[:, j]).real
    X = dyn.project(X0 + 1e-6 * dX / np.linalg.norm(dX), p)
    T = 4 * 2 * np.pi / abs(ev[j].imag)
    t = np.linspace(0, T, 2000)
    sol = solve_ivp(dyn.ode(p, Om), (0, T), X, method="DOP853", rtol=1e-10, atol=1e-13, t_eval=t)
    d = sol.y[5] - sol.y[5].mean()
    s = np.sign(d)
    i = np.nonzero(s[1:] != s[:-1])[0]
    tc = t[i] - d[i] * (t[i + 1] - t[i]) / (d[i + 1] - d[i])
    assert abs(np.pi * (len(tc) - 1) / (tc[-1] - tc[0]) / abs(ev[j].imag) - 1) < 0.01


def test_no_orbit_gives_nan_and_unknown_without_warnings():
    th = np.radians([30.0, 30.0, 90.0, 90.0])
    al = np.radians([40.0, 0.0, 90.0, 120.0])       # no fit, alpha=0, Omega=0, Omega^2<0
    res = st.wheel_stability(th, al, A, R, K, G)
    assert np.all(res["verdict"] == st.Verdict.UNKNOWN)
    assert np.all(np.isnan(res["growth_rate"]))
    empty = st.wheel_stability(np.zeros(0), np.zeros(0), A, R, K, G)
    assert empty["growth_rate"].shape == (0,)


def test_broadcasting_and_shapes():
    th = np.radians(np.array([[60.0], [90.0]]))
    al = np.radians(np.array([10.0, 25.0, 45.0]))
    res = st.wheel_stability(th, al, A, R, K, G)
    assert res["growth_rate"].shape == (2, 3) and res["eigenvalues"].shape == (2, 3, 4)
    flat = st.wheel_stability(np.repeat(th.ravel(), 3), np.tile(al, 2), A, R, K, G)
    np.testing.assert_allclose(res["freq_slow"].ravel(), flat["freq_slow"], rtol=1e-12)


def test_vertical_floquet_stable_and_resonant_orbits():
    """Floquet multipliers of vertical orbits: |mu| = 1 on a typical orbit;
    a resonance tongue (a/r = 0.6, k = 1/4) has a multiplier -1.107."""
    a, r, k = np.array([0.3, 0.6]), 1.0, 0.25
    th = np.radians([70.0, 75.57897221815767])
    rp = r * np.sin(th) - a
    pd0 = np.array([2.0, 1.2]) * np.sqrt(G / rp)
    res = st.vertical_floquet(th, pd0, a, r, k, G)
    assert res["verdict"][0] == st.Verdict.STABLE
    assert abs(res["max_abs"][0] - 1) < 1e-8
    assert res["verdict"][1] == st.Verdict.UNSTABLE
    assert np.isclose(res["max_abs"][1], 1.1074, atol=2e-4)
    assert np.all(res["return_error"] < 1e-9)
    # every multiplier set contains 1 (a neutral direction beyond the six removed)
    assert np.all(np.min(np.abs(res["multipliers"] - 1), axis=-1) < 1e-6)
