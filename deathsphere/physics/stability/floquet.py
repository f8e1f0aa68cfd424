"""Exact linear stability of vertical orbits by Floquet analysis (beyond
the paper, whose eqs. 100-106 freeze the coefficients at the top of the
orbit; docs/stability.md sec. 2).

The monodromy over half a lap is integrated with the exact equations of
motion and a fixed-step order-8 Runge-Kutta method
(:mod:`~deathsphere.physics.stability.rk8`); the full lap follows by the
orbit's reversing symmetry.
"""

from __future__ import annotations

import cmath

import numpy as np

from deathsphere.physics import dynamics as dyn
from deathsphere.physics.geometry import r_prime
from deathsphere.physics.stability import rk8
from deathsphere.physics.stability.reduction import COMPLEX_STEP, orthonormal_complement
from deathsphere.physics.stability.verdict import Verdict
from deathsphere.physics.vectors import dot, zcross
from deathsphere.physics.vertical_orbit import lap_time, vertical_fits

__all__ = ["FLOQUET_STABLE_TOL", "FLOQUET_UNSTABLE_TOL", "FLOQUET_SCALAR_MAX", "REVERSAL",
           "vertical_state", "vertical_neutral_basis", "vertical_floquet"]

#: |multiplier| - 1 at or below which a vertical orbit is called stable, and at
#: or above which unstable (unknown between).  The order-8 monodromy with the
#: default step reproduces |mu| = 1 to ~1e-11 on stable orbits and its
#: multipliers are within ~1e-9 of a run with a quarter of the step
#: (docs/stability.md sec. 2).
FLOQUET_STABLE_TOL = 1e-6
FLOQUET_UNSTABLE_TOL = 1e-4

#: orbits up to which the monodromy is integrated orbit by orbit on Python
#: complex numbers (dynamics.equations_by_component with cmath.sqrt); more orbits go
#: through numpy arrays, all orbits and directions at once
FLOQUET_SCALAR_MAX = 16


#: the reversing symmetry of a vertical orbit (orbit plane normal to y, top
#: at x = 0): the mirror x -> -x combined with time reversal flips the x
#: components of c, e1 and w, and G f(X) = -f(G X) for the flow f
REVERSAL = np.array([-1.0, 1, 1, -1, 1, 1, -1, 1, 1])


def _bottom_rate(th, pd, a, r, k, g):
    """Rate at the bottom of the vertical orbit with rate pd at the top,
    phidot^2 = pd^2 + 4 g/((2k+1) r') (eq. 27 at phi = pi); complex inputs
    accepted (complex step)."""
    return np.sqrt(pd * pd + 4 * g / ((2 * k + 1) * r_prime(th, 0.0, a, r)))


def vertical_state(th, pd, a, r, k, g, bottom=False):
    """State of a vertical orbit at its top (:func:`dynamics.vertical_orbit_state`)
    or, with ``bottom``, half a lap later at its bottom: the top state turned
    by pi about the orbit's axis y (x, z of each vector flipped) with the
    bottom rate phidot^2 = phidot_top^2 + 4 g/((2k+1) r') (eq. 27).  Complex
    theta / phidot_top accepted (complex step)."""
    if not bottom:
        return dyn.vertical_orbit_state(th, pd, a, r)
    X = dyn.vertical_orbit_state(th, _bottom_rate(th, pd, a, r, k, g), a, r)
    return X * np.array([-1.0, 1, -1, -1, 1, -1, -1, 1, -1])[:, None]


def vertical_neutral_basis(X0, th, pd, a, r, k, g, p, D, bottom=False):
    """Orthonormal basis (n, 9, 3) (scaled coordinates) of the complement of
    the six neutral directions of a vertical orbit at the state X0 (its top,
    or with ``bottom`` its bottom): the two constraint normals, phase f(X0),
    rotation about the vertical z x X0, d/dtheta and d/dphidot_top of the
    family (docs/stability.md sec. 2)."""
    n = th.size
    c, e1 = X0[dyn.C], X0[dyn.E1]
    fx = dyn.rhs(X0, p)
    gen = np.concatenate((zcross(c), zcross(e1), zcross(X0[dyn.W])))
    dth = np.imag(vertical_state(th + 1j * COMPLEX_STEP, pd, a, r, k, g, bottom)) / COMPLEX_STEP
    dpd = np.imag(vertical_state(th, pd + 1j * COMPLEX_STEP, a, r, k, g, bottom)) / COMPLEX_STEP
    V = np.stack((fx, gen, dth, dpd), axis=-1) / D[..., None]
    e3 = dyn.contact_geometry(X0, p).e3
    pv = c + a * e3
    n1 = np.concatenate((np.zeros((3, n)), e1, np.zeros((3, n))))
    n2 = np.concatenate((pv, -a * dot(c, e1) * e3, np.zeros((3, n))))
    Nrm = np.stack((n1, n2), axis=-1) * D[..., None]
    A = np.moveaxis(np.concatenate((Nrm, V), axis=-1), 0, 1)
    A = A / np.linalg.norm(A, axis=1, keepdims=True)
    return orthonormal_complement(A, 9)


def _rk8_columns(x, p, dt, steps):
    """``steps`` fixed steps dt (n,) of the order-8 Runge-Kutta method
    (:mod:`deathsphere.physics.stability.rk8`) of the unperturbed flow (lab frame)
    from the complex states x (9, n, m); returns the states at the end.

    Few orbits: orbit by orbit, each column's right-hand side on Python
    complex numbers (the lines of :func:`dynamics.equations_by_component` with
    cmath.sqrt; ~40x cheaper than numpy on 9-element arrays); stage sums by
    numpy.  Many orbits: :func:`dynamics.rhs` on all at once.  Both run the
    same equations; tests/physics/test_floquet.py compares them."""
    n = x.shape[1]
    out = np.empty_like(x)
    if n <= FLOQUET_SCALAR_MAX:
        for i in range(n):
            coef = dyn.scalar_coefficients(dyn.BodyParams(*(f[i:i + 1] for f in p)))
            out[:, i, :] = _rk8_scalar(x[:, i, :].T.copy(), coef, float(dt[i]), steps).T
        return out
    pc = dyn.BodyParams(*(f[:, None] for f in p))
    h = np.asarray(dt, dtype=float)[:, None]
    ks = [None] * len(rk8.B)
    for _ in range(steps):
        for s, row in enumerate(rk8.A):
            xs = x
            for j, a_sj in row:
                xs = xs + (h * a_sj) * ks[j]
            ks[s] = dyn.rhs(xs, pc)
        x = x + h * sum(b * kj for b, kj in zip(rk8.B, ks) if b)
    return x


def _rk8_scalar(X, coef, dt, steps):
    """:func:`_rk8_columns` for one orbit: X (m, 9) complex."""
    m = X.shape[0]
    eq = dyn.equations_by_component
    sqrt = cmath.sqrt
    nst = len(rk8.B)
    A = [np.array([a_sj * dt for _, a_sj in row]) for row in rk8.A]
    J = [[j for j, _ in row] for row in rk8.A]
    Bw = np.array(rk8.B) * dt
    x = X.reshape(-1)
    ks = np.empty((nst, m * 9), dtype=complex)
    for _ in range(steps):
        for s in range(nst):
            xs = (x + A[s].dot(ks[J[s]]) if s else x).tolist()
            ks[s] = [v for col in range(0, 9 * m, 9) for v in eq(*xs[col:col + 9], coef, sqrt)]
        x = x + Bw.dot(ks)
    return x.reshape(m, 9)


def vertical_floquet(theta, phidot_top, a, r, k, g, step=0.25):
    """Exact linear stability of vertical orbits by Floquet analysis.

    Beyond the paper (the paper's eqs. 100-106 freeze the coefficients at the
    top of the orbit; docs/stability.md sec. 2).  The monodromy matrix over
    one period T (eq. 27; :func:`deathsphere.physics.vertical_orbit.lap_time`) is taken on
    the constraint manifold modulo the six neutral directions (phase,
    energy, theta family, rotation about the vertical, and the two
    constraint normals): only the three directions spanning that quotient
    are integrated, as complex-step perturbations of the state (exact
    derivatives), with the exact equations of motion
    (:mod:`deathsphere.physics.dynamics`) and a fixed-step order-8
    Runge-Kutta method (``step`` = largest rate x time step), over half a
    lap only: the flow is reversible (mirror x -> -x with time reversal,
    ``REVERSAL``), top and bottom are symmetric points, so the monodromy is
    M = G Mh^-1 G Mh with Mh the half-lap one, taken on the quotient bases at
    top and bottom.  That leaves 3 multipliers: one is 1 (a further neutral
    direction, found numerically), the other two are the nutation pair.

    Inputs broadcast: theta [rad] (orbit plane at distance r cos(theta)
    from the centre), phidot_top [rad/s] rate at the top, a, r [m], k [-],
    g [m/s^2].  Batched.

    Returns dict: ``multipliers`` (..., 3) complex; ``max_abs`` max |mu|;
    ``growth_rate`` log(max |mu|)/T [1/s]; ``nu`` [rad/s] |arg mu|/T of the
    multiplier farthest from 1 (the nutation frequency modulo 2 pi/T);
    ``period`` T [s]; ``verdict`` int8 :class:`Verdict` with the tolerances
    FLOQUET_STABLE_TOL / FLOQUET_UNSTABLE_TOL on |mu| - 1; ``return_error``
    [m] |c(T/2) - c_bottom| of the integrated reference orbit against the
    bottom of eq. (27) (integration check).  NaN/UNKNOWN where the wheel
    does not fit (:func:`deathsphere.physics.vertical_orbit.vertical_fits`)
    or phidot_top = 0.
    """
    theta, phidot_top, a, r, k, g = np.broadcast_arrays(
        *(np.asarray(x, dtype=float) for x in (theta, phidot_top, a, r, k, g)))
    dyn.body_params(a, r, k, g)                   # validation only
    shape = theta.shape
    th, pd, a, r, k, g = (x.reshape(-1) for x in (theta, phidot_top, a, r, k, g))
    ok = vertical_fits(th, a, r) & (pd != 0)
    # placeholders where no orbit exists keep the algebra finite (NaN later)
    th = np.where(ok, th, np.pi / 2)
    r = np.where(ok, r, 10 * a)
    pd = np.where(ok, pd, np.sqrt(g / a))
    T = lap_time(th, pd, a, r, k, g)
    Wb, Wh, Kh, ret = _half_lap(th, pd, a, r, k, g, T, step)
    mu, finite = _multipliers(Wb, Wh, Kh, ok)
    mabs = np.max(np.abs(mu), axis=-1)
    far = np.argmax(np.abs(mu - 1), axis=-1)
    mu_far = np.take_along_axis(mu, far[:, None], axis=-1)[:, 0]
    verdict = np.full(th.size, Verdict.UNKNOWN, dtype=np.int8)
    dev = mabs - 1
    verdict[np.nan_to_num(dev, nan=np.inf) <= FLOQUET_STABLE_TOL] = Verdict.STABLE
    verdict[np.nan_to_num(dev, nan=-np.inf) >= FLOQUET_UNSTABLE_TOL] = Verdict.UNSTABLE
    with np.errstate(invalid="ignore", divide="ignore"):
        growth = np.log(mabs) / T
        nu = np.abs(np.angle(mu_far)) / T

    def nanif(y):
        return np.where(finite, y, np.nan)
    return {
        "multipliers": mu.reshape(shape + (3,)),
        "max_abs": nanif(mabs).reshape(shape),
        "growth_rate": nanif(growth).reshape(shape),
        "nu": nanif(nu).reshape(shape),
        "period": nanif(T).reshape(shape),
        "verdict": verdict.reshape(shape),
        "return_error": nanif(ret).reshape(shape),
    }


def _half_lap(th, pd, a, r, k, g, T, step):
    """The half-lap monodromy on the quotient bases: integrates the three
    directions of the top's quotient basis Wb from top to bottom (fixed
    steps, the largest rate S times the step at most ``step``) and projects
    the result on the bottom's basis Wh.  Returns (Wb, Wh, Kh, return_error)
    with Kh (n, 3, 3) in scaled coordinates (lengths by a, rates by S)."""
    n = th.size
    rp = r_prime(th, 0.0, a, r)
    X0 = dyn.vertical_orbit_state(th, pd, a, r)
    p = dyn.BodyParams(a, r, k, g, np.zeros(n, dtype=bool), np.zeros(n, dtype=bool))
    pdmax = _bottom_rate(th, pd, a, r, k, g)
    S = np.sqrt((rp * pdmax / a) ** 2 + pdmax ** 2 + g / a)     # fastest rate
    N = int(np.ceil(np.max(T * S) / (2 * step))) if n else 0               # steps per half lap
    D = np.concatenate((np.broadcast_to(a, (3, n)), np.ones((3, n)), np.broadcast_to(S, (3, n))))
    Wb = vertical_neutral_basis(X0, th, pd, a, r, k, g, p, D)                # (n, 9, 3)
    x = X0[:, :, None] + 1j * COMPLEX_STEP * (np.moveaxis(Wb, 0, 1) * D[:, :, None])    # (9, n, 3)
    x = _rk8_columns(x, p, 0.5 * T / max(N, 1), N)                            # top -> bottom
    Xb = vertical_state(th, pd, a, r, k, g, bottom=True)
    ret = np.sqrt(np.sum((np.real(x[0:3, :, 0]) - Xb[0:3]) ** 2, axis=0))
    Wh = vertical_neutral_basis(np.real(x[:, :, 0]), th, pd, a, r, k, g, p, D, bottom=True)
    Kh = np.einsum("nji,njl->nil", Wh, np.moveaxis(np.imag(x) / COMPLEX_STEP / D[:, :, None], 1, 0))
    return Wb, Wh, Kh, ret


def _multipliers(Wb, Wh, Kh, ok):
    """Floquet multipliers (n, 3) of the full lap from the half-lap monodromy
    Kh by reversibility: M = G Mh^-1 G Mh (Mh the half-lap monodromy, G
    REVERSAL), taken on the quotient bases Wb, Wh at top and bottom.
    Returns (multipliers, finite); NaN where not ``ok`` or not finite."""
    G0 = np.einsum("nji,j,njl->nil", Wb, REVERSAL, Wb)
    Gh = np.einsum("nji,j,njl->nil", Wh, REVERSAL, Wh)
    finite = np.all(np.isfinite(Kh), axis=(-2, -1)) & ok
    Kh = np.where(finite[:, None, None], Kh, np.eye(3))
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        K = G0 @ np.linalg.solve(Kh, Gh @ Kh)
    finite &= np.all(np.isfinite(K), axis=(-2, -1))
    mu = np.linalg.eigvals(np.where(finite[:, None, None], K, np.eye(3)))
    return np.where(finite[:, None], mu, np.nan), finite
