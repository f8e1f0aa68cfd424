"""Floquet analysis of vertical orbits (stability.vertical_floquet), beyond
the paper (docs/stability.md sec. 2): the fast monodromy (three quotient
directions, order-8 fixed step, Python complex numbers for few orbits)
against the method as first written (RK4 on all nine directions, kept below
as the reference) and against finite differences of the nonlinear flow.
"""

import itertools

import numpy as np
import pytest

from deathsphere.physics import dynamics as dyn
from deathsphere.physics import stability as st
from deathsphere.physics.stability import floquet
from deathsphere.physics.stability.reduction import COMPLEX_STEP, orthonormal_complement
from deathsphere.physics.vectors import dot, zcross
from deathsphere.physics.vertical_orbit import lap_time

G = 9.80665


def floquet_reference(theta, phidot0, a, r, k, g, step=0.05):
    """The Floquet analysis as first written (RK4 on complex-step copies of all
    nine state directions, step 0.05), kept as the reference."""
    theta, phidot0, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (theta, phidot0, a, r, k, g)))
    dyn.body_params(a, r, k, g)                   # validation only
    shape = theta.shape
    th, pd, a, r, k, g = (x.reshape(-1) for x in (theta, phidot0, a, r, k, g))
    n = th.size
    rp = r * np.sin(th) - a
    ok = (rp > 0) & (pd != 0)
    th = np.where(ok, th, np.pi / 2)
    r = np.where(ok, r, 10 * a)
    pd = np.where(ok, pd, np.sqrt(g / a))
    rp = r * np.sin(th) - a
    T = lap_time(th, pd, a, r, k, g)
    X0 = dyn.vertical_orbit_state(th, pd, a, r)
    p = dyn.BodyParams(a, r, k, g, np.zeros(n, dtype=bool), np.zeros(n, dtype=bool))
    pdmax = np.sqrt(pd ** 2 + 4 * g / ((2 * k + 1) * rp))
    S = np.sqrt((rp * pdmax / a) ** 2 + pdmax ** 2 + g / a)     # fastest rate
    N = int(np.ceil(np.max(T * S * 2.0) / step)) if n else 0
    D = np.concatenate((np.broadcast_to(a, (3, n)), np.ones((3, n)), np.broadcast_to(S, (3, n))))
    pc = dyn.BodyParams(*(x[:, None] for x in p))
    x = X0[:, :, None] + 1j * COMPLEX_STEP * (np.eye(9)[:, None, :] * D[:, :, None])   # (9, n, 9)
    dt = (T / max(N, 1))[:, None]
    for _ in range(N):
        k1 = dt * dyn.rhs(x, pc)
        k2 = dt * dyn.rhs(x + 0.5 * k1, pc)
        k3 = dt * dyn.rhs(x + 0.5 * k2, pc)
        k4 = dt * dyn.rhs(x + k3, pc)
        x = x + (k1 + 2 * k2 + 2 * k3 + k4) / 6
    M = np.moveaxis(np.imag(x) / COMPLEX_STEP / D[:, :, None], 1, 0)                 # (n, 9, 9) scaled
    ret = np.sqrt(np.sum((np.real(x[0:3, :, 0]) - X0[0:3]) ** 2, axis=0))
    # neutral directions (scaled)
    c, e1, w = X0[dyn.C], X0[dyn.E1], X0[dyn.W]
    fx = dyn.rhs(X0, p)
    gen = np.concatenate((zcross(c), zcross(e1), zcross(w)))
    dth = np.imag(dyn.vertical_orbit_state(th + 1j * COMPLEX_STEP, pd, a, r)) / COMPLEX_STEP
    dpd = np.imag(dyn.vertical_orbit_state(th, pd + 1j * COMPLEX_STEP, a, r)) / COMPLEX_STEP
    V = np.stack((fx, gen, dth, dpd), axis=-1) / D[..., None]
    e3 = dyn.contact_geometry(X0, p).e3
    pv = c + a * e3
    n1 = np.concatenate((np.zeros((3, n)), e1, np.zeros((3, n))))
    n2 = np.concatenate((pv, -a * dot(c, e1) * e3, np.zeros((3, n))))
    Nrm = np.stack((n1, n2), axis=-1) * D[..., None]
    A = np.moveaxis(np.concatenate((Nrm, V), axis=-1), 0, 1)
    A = A / np.linalg.norm(A, axis=1, keepdims=True)
    Wb = orthonormal_complement(A, 9)                                         # (n, 9, 3)
    K = np.einsum("nji,njk,nkl->nil", Wb, M, Wb)
    finite = np.all(np.isfinite(K), axis=(-2, -1)) & ok
    mu = np.linalg.eigvals(np.where(finite[:, None, None], K, np.eye(3)))
    mu = np.where(finite[:, None], mu, np.nan)
    mabs = np.max(np.abs(mu), axis=-1)
    far = np.argmax(np.abs(mu - 1), axis=-1)
    mu_far = np.take_along_axis(mu, far[:, None], axis=-1)[:, 0]
    verdict = np.full(n, st.Verdict.UNKNOWN, dtype=np.int8)
    dev = mabs - 1
    verdict[np.nan_to_num(dev, nan=np.inf) <= st.FLOQUET_STABLE_TOL] = st.Verdict.STABLE
    verdict[np.nan_to_num(dev, nan=-np.inf) >= st.FLOQUET_UNSTABLE_TOL] = st.Verdict.UNSTABLE
    with np.errstate(invalid="ignore", divide="ignore"):
        growth = np.log(mabs) / T
        nu = np.abs(np.angle(mu_far)) / T
    nanif = lambda y: np.where(finite, y, np.nan)
    return {
        "multipliers": mu.reshape(shape + (3,)),
        "max_abs": nanif(mabs).reshape(shape),
        "growth_rate": nanif(growth).reshape(shape),
        "nu": nanif(nu).reshape(shape),
        "period": nanif(T).reshape(shape),
        "verdict": verdict.reshape(shape),
        "return_error": nanif(ret).reshape(shape),
    }


def _orbits():
    """Vertical orbits of the existing tests, the verify claim, the CLI's
    example and resonance-tongue neighbourhoods: (theta, phidot0, a, r, k)."""
    rows = [(np.radians(70.0), 2.0, 0.3, 1.0, 0.25),
            (np.radians(75.57897221815767), 1.2, 0.6, 1.0, 0.25),      # period doubling
            (np.radians(27.3), 1.2, 0.9, 3.0, 0.5),                    # verify.py's tongue
            (np.radians(27.3), 1.001, 0.9, 3.0, 0.5),                  # at the contact limit
            (np.radians(75.0), 1.1, 0.6, 1.0, 0.25),
            (np.radians(80.0), 1.35, 0.6, 1.0, 0.5)]
    thmin = np.arcsin(0.1)
    for frac in (0.2, 0.6, 1.0):
        for f in (1.05, 2.0):
            rows.append((thmin + (np.pi / 2 - thmin) * frac, f, 0.1, 1.0, 0.5))
    th, f, a, r, k = (np.array(x) for x in zip(*rows))
    pd = f * np.sqrt(G / (r * np.sin(th) - a))
    th = np.append(th, np.pi / 2)                     # `deathsphere vertical --theta 90 --v-top 6`
    pd = np.append(pd, 6.0 / 2.7)
    return th, pd, np.append(a, 0.3), np.append(r, 3.0), np.append(k, 0.5)


def test_reversing_symmetry_of_the_flow():
    """G f(X) = -f(G X) for the mirror x -> -x with time reversal (the basis
    of the half-lap monodromy), and the bottom state is the top state half a
    lap on."""
    rng = np.random.default_rng(3)
    X = rng.normal(size=(9, 40))
    p = dyn.body_params(np.full(40, 0.3), 3.0, 0.5, G)
    Gm = floquet.REVERSAL[:, None]
    np.testing.assert_array_equal(Gm * dyn.rhs(X, p), -dyn.rhs(Gm * X, p))
    th, pd, a, r, k = np.radians(60.0), 3.0, 0.3, 3.0, 0.5
    from scipy.integrate import solve_ivp
    T = float(lap_time(th, pd, a, r, k, G))
    X0 = dyn.vertical_orbit_state(th, pd, a, r)
    end = solve_ivp(dyn.ode(dyn.body_params(a, r, k, G)), (0, T / 2), X0, method="DOP853",
                    rtol=1e-12, atol=1e-12).y[:, -1]
    Xb = floquet.vertical_state(np.atleast_1d(th), pd, a, r, k, G, bottom=True)[:, 0]
    np.testing.assert_allclose(end, Xb, atol=1e-8 * np.max(np.abs(Xb)))


def _match(mu, ref):
    """Largest |mu - ref| over orbits, multipliers paired by the best permutation."""
    return max(min(np.max(np.abs(m[list(pm)] - q)) for pm in itertools.permutations(range(3)))
               for m, q in zip(mu.reshape(-1, 3), ref.reshape(-1, 3)))


@pytest.fixture(scope="module")
def reference():
    th, pd, a, r, k = _orbits()
    return (th, pd, a, r, k), floquet_reference(th, pd, a, r, k, G)


def test_multipliers_agree_with_the_reference_method(reference):
    (th, pd, a, r, k), ref = reference
    new = st.vertical_floquet(th, pd, a, r, k, G)
    assert _match(new["multipliers"], ref["multipliers"]) < 1e-6
    np.testing.assert_array_equal(new["verdict"], ref["verdict"])
    assert np.sum(new["verdict"] == st.Verdict.UNSTABLE) >= 3
    np.testing.assert_allclose(new["max_abs"], ref["max_abs"], rtol=0, atol=1e-6)
    np.testing.assert_allclose(new["period"], ref["period"], rtol=1e-15)
    assert np.all(new["return_error"] < 1e-9)


def test_scalar_and_numpy_paths_agree():
    """Few orbits run on Python complex numbers, many through numpy: the same
    equations, the same multipliers (to round-off)."""
    th, pd, a, r, k = _orbits()
    n = floquet.FLOQUET_SCALAR_MAX + 1
    rep = lambda x: np.resize(x, n)
    many = st.vertical_floquet(rep(th), rep(pd), rep(a), rep(r), rep(k), G)
    few = st.vertical_floquet(th[:4], pd[:4], a[:4], r[:4], k[:4], G)
    assert _match(few["multipliers"], many["multipliers"][:4]) < 1e-10


def test_monodromy_matches_finite_differences_of_the_nonlinear_flow():
    """An independent check of the monodromy: central differences of
    solve_ivp runs (DOP853, rtol 1e-13) from the orbit's top, kicked along
    the three quotient directions, reproduce the multipliers to 1e-6."""
    from scipy.integrate import solve_ivp

    th, a, r, k = np.radians(75.57897221815767), 0.6, 1.0, 0.25       # the period-doubling orbit
    pd = 1.2 * np.sqrt(G / (r * np.sin(th) - a))
    p = dyn.body_params(a, r, k, G)
    T = float(lap_time(th, pd, a, r, k, G))
    X0 = dyn.vertical_orbit_state(th, pd, a, r)
    rp = r * np.sin(th) - a
    pdmax = np.sqrt(pd ** 2 + 4 * G / ((2 * k + 1) * rp))
    S = np.sqrt((rp * pdmax / a) ** 2 + pdmax ** 2 + G / a)
    D = np.r_[[a] * 3, [1.0] * 3, [S] * 3]
    pn = dyn.BodyParams(*(np.atleast_1d(x) for x in p))
    Wb = floquet.vertical_neutral_basis(X0[:, None], *(np.atleast_1d(x) for x in (th, pd, a, r, k, G)),
                                    pn, D[:, None])[0]
    eps = 1e-5
    cols = []
    for j in range(3):
        ends = [solve_ivp(dyn.ode(p), (0, T), X0 + s * eps * Wb[:, j] * D, method="DOP853",
                          rtol=1e-13, atol=1e-13).y[:, -1] for s in (1, -1)]
        cols.append((ends[0] - ends[1]) / (2 * eps) / D)
    K = Wb.T @ np.array(cols).T
    fl = st.vertical_floquet(th, pd, a, r, k, G)
    assert _match(np.linalg.eigvals(K), fl["multipliers"]) < 1e-6
