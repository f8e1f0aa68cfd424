"""Linear stability of steady orbits: exact, and the paper's results.

Exact (beyond the paper, docs/stability.md): the equations of motion of
:mod:`deathsphere.physics.dynamics` are linearised about a steady horizontal
orbit in the frame turning with it, by complex-step differentiation (exact to
round-off), restricted to the constraint manifold and to the complement of
the neutral modes that the rotation symmetry and the family of steady orbits
produce.  Batched: stacked Jacobians, one ``np.linalg.eigvals`` call.

Paper (McDonald 1993 sec. 2.3): vertical orbits eqs. (100)-(106), orbits on
the equator eqs. (127)-(138), small wheels eqs. (202)-(207), near the poles
eq. (208); each implemented as printed and, where the printed form has a
slip, as corrected (docs/stability.md, "Errata").
"""

from __future__ import annotations

import cmath
from enum import IntEnum

import numpy as np

from deathsphere.physics import _rk8
from deathsphere.physics import dynamics as dyn
from deathsphere.physics.geometry import SINGULAR, fits_inside, fits_outside
from deathsphere.physics.wheel import omega_squared


class Verdict(IntEnum):
    """Stability verdict codes (column ``stability`` of the CLI); beyond the
    paper, tolerances in docs/stability.md sec. 1."""

    STABLE = 0
    UNSTABLE = 1
    UNKNOWN = 2

    @property
    def label(self) -> str:
        return self.name.lower()


VERDICT_LABELS = np.array([v.label for v in Verdict], dtype=object)

#: growth rate / rate scale at or below which an orbit is called stable.
#: The spectrum of an exact stable orbit is purely imaginary (the flow is
#: reversible); round-off gives real parts ~1e-15 of the rate scale for simple
#: eigenvalues and up to ~1e-8 where two frequencies collide (a defective
#: double eigenvalue: error ~ sqrt(eps)).  Measured worst case over 224 895
#: orbits of the survey grids: 3.8e-10 (docs/stability.md).
STABLE_TOL = 1e-7
#: growth rate / rate scale at or above which an orbit is called unstable
#: (measured smallest on the same grids: 3.8e-4).  Between the two the verdict
#: is "unknown": the growth rate rises like the square root of the distance to
#: a stability boundary, so such an orbit lies within ~1e-10 (relative) of one.
UNSTABLE_TOL = 1e-5

#: orbits per vectorised batch (bounds memory; ~1 KB of temporaries per orbit)
CHUNK = 16384

_H = 1e-30   # complex step (relative); any h << sqrt(eps) works for complex step


# --------------------------------------------------------------------------
# exact linearisation

def _vec(x):
    return np.asarray(x, dtype=float)


def _complex_step(fun, x0, dx, h=_H):
    """Directional derivative of ``fun`` at x0 along dx by complex step."""
    return np.imag(fun(x0 + 1j * h * dx)) / h


def _reduce(K, scale):
    """Growth rate, frequencies and verdict from stacked reduced Jacobians."""
    finite = np.all(np.isfinite(K), axis=(-2, -1)) & np.isfinite(scale)
    ev = np.linalg.eigvals(np.where(finite[:, None, None], K, 0.0))   # (n, m)
    ev = np.where(finite[:, None], ev, np.nan)
    growth = np.max(ev.real, axis=-1)
    im = np.sort(np.abs(ev.imag), axis=-1)
    m = K.shape[-1]
    if m == 4:
        slow = 0.5 * (im[:, 0] + im[:, 1])
        fast = 0.5 * (im[:, 2] + im[:, 3])
    else:
        slow = np.full(im.shape[0], np.nan)
        fast = 0.5 * (im[:, 0] + im[:, 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = growth / scale
    verdict = np.full(growth.shape, Verdict.UNKNOWN, dtype=np.int8)
    verdict[np.nan_to_num(rel, nan=np.inf) <= STABLE_TOL] = Verdict.STABLE
    verdict[np.nan_to_num(rel, nan=-np.inf) >= UNSTABLE_TOL] = Verdict.UNSTABLE
    return ev, growth, slow, fast, verdict


def _verdict(growth, scale):
    """Verdict codes from growth rate and rate scale (docs/stability.md sec. 1)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = growth / scale
    verdict = np.full(growth.shape, Verdict.UNKNOWN, dtype=np.int8)
    verdict[np.nan_to_num(rel, nan=np.inf) <= STABLE_TOL] = Verdict.STABLE
    verdict[np.nan_to_num(rel, nan=-np.inf) >= UNSTABLE_TOL] = Verdict.UNSTABLE
    return verdict


def _reduce_invariants(K, scale):
    """:func:`_reduce` for stacked 4x4 reduced Jacobians, from invariants
    instead of an eigenvalue solver (beyond the paper; docs/stability.md
    sec. 1).  The flow is reversible, so the spectrum is symmetric under
    lambda -> -lambda: the characteristic polynomial is
    lambda^4 + e2 lambda^2 + e4 with e2 = (tr(K)^2 - tr(K^2))/2 (the sum of
    the principal 2x2 minors) and e4 = det K; the odd coefficients vanish up
    to round-off and are dropped.  The roots x = lambda^2 of
    x^2 + e2 x + e4 = 0 are taken in the cancellation-free form
    q = -(e2 + sign(e2) sqrt(e2^2 - 4 e4))/2, x = q and e4/q; the
    eigenvalues are +/- sqrt(x).  A stable orbit (both x real and negative)
    gets growth rate 0 exactly."""
    finite = np.all(np.isfinite(K), axis=(-2, -1)) & np.isfinite(scale)
    K = np.where(finite[:, None, None], K, 0.0)
    tr = np.trace(K, axis1=-2, axis2=-1)
    e2 = 0.5 * (tr * tr - np.einsum("nij,nji->n", K, K))
    e4 = np.linalg.det(K)
    sq = np.sqrt((e2 * e2 - 4.0 * e4).astype(complex))
    q = -0.5 * (e2 + np.where(e2 >= 0, 1.0, -1.0) * sq)
    nz = q != 0
    x2 = np.where(nz, e4 / np.where(nz, q, 1.0), 0.0)
    l1, l2 = np.sqrt(q), np.sqrt(x2)
    ev = np.stack((l1, -l1, l2, -l2), axis=-1)
    ev = np.where(finite[:, None], ev, np.nan)
    growth = np.where(finite, np.maximum(np.abs(l1.real), np.abs(l2.real)), np.nan)
    f1, f2 = np.abs(l1.imag), np.abs(l2.imag)
    slow = np.where(finite, np.minimum(f1, f2), np.nan)
    fast = np.where(finite, np.maximum(f1, f2), np.nan)
    return ev, growth, slow, fast, _verdict(growth, scale)


def _orthonormal_complement(A, dim):
    """Orthonormal basis (n, dim, dim - A.shape[-1]) of the complement of the
    column span of the stacked (n, dim, q) matrices A (assumed full rank)."""
    q = A.shape[-1]
    Q, _ = np.linalg.qr(A, mode="complete")
    return Q[..., q:]


def _householder_complement(A):
    """Orthonormal basis (dim, dim - q, n) of the complement of the column
    span of the component-major stack A (dim, q, n) (assumed full rank):
    Householder reflections H_0 ... H_{q-1} triangularise A, and the last
    dim - q columns of Q = H_0 ... H_{q-1} span the complement (the complete
    QR of :func:`_orthonormal_complement`, up to signs).  Every operation
    runs on contiguous n-vectors, ~2x faster than a batched LAPACK QR for
    9 x 5 (beyond the paper; docs/stability.md sec. 1)."""
    dim, q, n = A.shape
    R = A.copy()
    vs = []
    for j in range(q):
        x = R[j:, j]                                             # (dim - j, n)
        nx = np.sqrt(np.einsum("in,in->n", x, x))
        v = x.copy()
        v[0] += np.where(x[0] >= 0, nx, -nx)
        vn = np.sqrt(np.einsum("in,in->n", v, v))
        v[0] = np.where(vn > 0, v[0], 1.0)                       # a zero column: any unit v
        v *= 1.0 / np.where(vn > 0, vn, 1.0)
        if j + 1 < q:
            sub = R[j:, j + 1:]
            sub -= 2.0 * v[:, None, :] * np.einsum("in,ikn->kn", v, sub)[None]
        vs.append(v)
    Y = np.zeros((dim, dim - q, n))
    for i in range(dim - q):
        Y[q + i, i] = 1.0
    for j in reversed(range(q)):
        sub = Y[j:]
        sub -= 2.0 * vs[j][:, None, :] * np.einsum("in,ikn->kn", vs[j], sub)[None]
    return Y


def _wheel_linearisation(theta, alpha, a, r, k, g, outside, want_basis=True):
    """Reduced 4x4 Jacobians of the wheel's flow about steady orbits.

    Component-major throughout (arrays (9, ..., n)): the five directions
    removed (two constraint normals; rotation about the vertical; d/dtheta,
    d/dalpha of the family, by one complex-step call) are scaled (lengths by
    a, rates by S) and normalised, their orthonormal complement comes from
    :func:`_householder_complement`, and the Jacobian acts on its four
    vectors by forward-mode derivatives (:func:`dynamics.jvp`, exact to
    round-off like the complex step it replaces, ~3x cheaper)."""
    shape = theta.shape
    n = theta.size
    th, al, a, r, k, g, out = (x.reshape(-1) for x in (theta, alpha, a, r, k, g, outside))
    om2 = omega_squared(th, al, a, r, k, g)
    fits = np.where(out, fits_outside(th, al), fits_inside(th, al, a, r))
    ok = fits & (np.nan_to_num(om2, nan=-1.0) > SINGULAR * g / r)
    # placeholders where no orbit exists keep the algebra finite (NaN later)
    th_s = np.where(ok, th, np.pi / 2)
    al_s = np.where(ok, al, np.pi / 4)
    r_s = np.where(ok, r, 10.0 * a)
    out_s = np.where(ok, out, False)
    p = dyn.BodyParams(a, r_s, k, g, out_s, np.zeros(n, dtype=bool))
    X0, Om = dyn.wheel_orbit_state(th_s, al_s, a, r_s, k, g, out_s)
    # neutral directions d/dtheta, d/dalpha: one complex-step call, (9, 2, n)
    step = 1j * _H * np.eye(2)[:, :, None]
    dfam = np.imag(dyn.wheel_orbit_state(th_s + step[0], al_s + step[1], a, r_s, k, g, out_s)[0]) / _H
    c, e1, w = X0[dyn.C], X0[dyn.E1], X0[dyn.W]
    # scaling: lengths by a, rates by S
    S = np.sqrt(dyn._dot(w, w) + Om ** 2 + g / a)
    D = np.empty((9, n))
    D[0:3], D[3:6], D[6:9] = a, 1.0, S
    e3 = dyn._geometry(X0, p)[8]
    A = np.zeros((9, 5, n))
    A[3:6, 0] = e1 * D[3:6]                          # constraint gradients (scaled: D grad)
    A[0:3, 1] = (c + a * e3) * D[0:3]
    A[3:6, 1] = -a * dyn._dot(c, e1) * e3 * D[3:6]
    for blk in (dyn.C, dyn.E1, dyn.W):               # rotation about the vertical
        A[blk, 2] = dyn._zcross(X0[blk]) / D[blk]
    A[:, 3:5] = dfam / D[:, None, :]
    A *= 1.0 / np.sqrt(np.einsum("ikn,ikn->kn", A, A))[None]   # well-conditioned columns
    Y = _householder_complement(A)                                 # (9, 4, n)
    # J~ W by forward-mode derivatives of the same equations, 4 directions at once
    JdX = dyn.jvp(X0, Y * D[:, None, :], p, Om)
    K = np.einsum("ijn,ikn->njk", Y, JdX / D[:, None, :])
    K = np.where(ok[:, None, None], K, np.nan)
    scale = np.where(ok, S, np.nan)
    basis = np.moveaxis(Y * D[:, None, :], 2, 0) if want_basis else None      # (n, 9, 4)
    return K, scale, np.where(ok, Om, np.nan), shape, basis, X0


def _result(shape, ev, growth, slow, fast, verdict, scale, omega):
    """The per-orbit dict of :func:`wheel_stability` / :func:`sphere_stability`."""
    return {
        "growth_rate": growth.reshape(shape),
        "freq_slow": slow.reshape(shape),
        "freq_fast": fast.reshape(shape),
        "verdict": verdict.reshape(shape),
        "rate_scale": scale.reshape(shape),
        "eigenvalues": ev.reshape(shape + ev.shape[-1:]),
        "omega": omega.reshape(shape),
    }


def wheel_stability(theta, alpha, a, r, k, g, outside=False):
    """Exact linear stability of steady horizontal orbits of a wheel.

    Beyond the paper (docs/stability.md): Jacobian of the exact flow
    (:mod:`deathsphere.physics.dynamics`, eqs. 2-7b) in the frame turning at
    Omega (eq. 29), by complex step, restricted to the 7-dimensional
    constraint manifold and to the complement of the three neutral
    directions (phase along the orbit; d/dtheta and d/dalpha of the steady
    family), leaving the 4 nutation eigenvalues.

    Parameters broadcast; theta, alpha [rad], a, r [m], k [-], g [m/s^2],
    outside (bool).

    Returns dict of arrays of the broadcast shape:
    ``growth_rate`` [1/s] largest real part of the 4 eigenvalues (>= 0 up to
    round-off: the spectrum is symmetric under lambda -> -lambda);
    ``freq_slow``, ``freq_fast`` [rad/s] the two nutation frequencies
    (|imaginary parts|, pairs averaged) seen in the turning frame;
    ``verdict`` int8 :class:`Verdict`; ``rate_scale`` [1/s] the scale the
    verdict's tolerance is relative to, sqrt(|w|^2 + Omega^2 + g/a);
    ``eigenvalues`` (..., 4) complex [1/s]; ``omega`` [rad/s].
    All NaN / UNKNOWN where eq. (29) has no real Omega or the wheel does not
    fit (eq. 0 / 81).  Contact is not checked (the linearisation assumes the
    contact holds both ways): combine with the status of
    :func:`deathsphere.physics.wheel.horizontal_orbit`.  Raises ValueError
    for invalid parameters (as :func:`dynamics.body_params`).
    """
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (theta, alpha, a, r, k, g)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    dyn.body_params(a, r, k, g, outside)          # validation only
    if theta.size == 0:
        return _empty(theta.shape, 4)
    shape = theta.shape
    flat = [x.reshape(-1) for x in (theta, alpha, a, r, k, g, outside)]
    parts = []
    for i in range(0, theta.size, CHUNK):       # bounded memory; vectorised within
        K, scale, Om, _, _, _ = _wheel_linearisation(*(x[i:i + CHUNK] for x in flat), want_basis=False)
        parts.append((*_reduce_invariants(K, scale), scale, Om))
    ev, growth, slow, fast, verdict, scale, Om = (np.concatenate(z) for z in zip(*parts))
    return _result(shape, ev, growth, slow, fast, verdict, scale, Om)


def _empty(shape, m):
    nan = np.full(shape, np.nan)
    return {"growth_rate": nan, "freq_slow": nan, "freq_fast": nan,
            "verdict": np.full(shape, Verdict.UNKNOWN, dtype=np.int8),
            "rate_scale": nan, "eigenvalues": np.full(shape + (m,), np.nan + 0j),
            "omega": nan}


def sphere_stability(theta, Omega, a, r, k, g, outside=False):
    """Exact linear stability of steady horizontal orbits of a rolling sphere.

    Beyond the paper (sec. 4 states the analysis can be completed; sec. 5
    cites Milne for stability outside): as :func:`wheel_stability`, on the
    5-dimensional manifold (centre on the sphere |c| = r -/+ a, angular
    velocity), minus the three neutral directions (phase; d/dtheta at fixed
    Omega; d/dOmega), leaving one nutation pair.  The orbit is given by
    theta [rad] and Omega [rad/s] (the spin omega3 follows from eq. 55; use
    :func:`deathsphere.physics.dynamics.sphere_orbit_rates` to get Omega from
    omega3).  Returns the dict of :func:`wheel_stability`; the single
    nutation frequency is in ``freq_fast``, ``freq_slow`` is NaN, and
    ``eigenvalues`` has 2 entries.
    """
    theta, Omega, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (theta, Omega, a, r, k, g)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    dyn.body_params(a, r, k, g, outside, sphere=True)     # validation only
    shape = theta.shape
    if theta.size == 0:
        return _empty(shape, 2)
    n = theta.size
    th, Om, a, r, k, g, out = (x.reshape(-1) for x in (theta, Omega, a, r, k, g, outside))
    ok = np.isfinite(Om) & (Om != 0) & (np.abs(np.sin(th)) > 1e-12)
    Om_s = np.where(ok, Om, 1.0)
    th_s = np.where(ok, th, np.pi / 2)
    p = dyn.BodyParams(a, r, k, g, out, np.ones(n, dtype=bool))
    X0, _ = dyn.sphere_orbit_state(th_s, Om_s, a, r, k, g, out)
    dth = np.imag(dyn.sphere_orbit_state(th_s + 1j * _H, Om_s, a, r, k, g, out)[0]) / _H
    dom = np.imag(dyn.sphere_orbit_state(th_s, Om_s + 1j * _H, a, r, k, g, out)[0]) / _H
    c, w = X0[dyn.C], X0[dyn.W]
    idx = np.r_[0:3, 6:9]
    gen = np.concatenate((dyn._zcross(c), dyn._zcross(w)))
    S = np.sqrt(dyn._dot(w, w) + Om_s ** 2 + g / a)
    D = np.concatenate((np.broadcast_to(a, (3, n)), np.broadcast_to(S, (3, n))))
    V = np.stack((gen, dth[idx], dom[idx]), axis=-1) / D[..., None]       # (6, n, 3)
    nrm = (np.concatenate((c, np.zeros((3, n)))) * D)[..., None]
    A = np.moveaxis(np.concatenate((nrm, V), axis=-1), 0, 1)             # (n, 6, 4)
    A = A / np.linalg.norm(A, axis=1, keepdims=True)
    Wb = _orthonormal_complement(A, 6)                                    # (n, 6, 2)
    dX6 = np.moveaxis(Wb, 0, 1) * D[:, :, None]                           # (6, n, 2)
    dX = np.zeros((9, n, 2))
    dX[idx] = dX6
    pc = dyn.BodyParams(*(x[:, None] for x in p))
    JdX = _complex_step(lambda x: dyn.rhs(x, pc, Om_s[:, None]), X0[:, :, None], dX)[idx]
    JW = np.moveaxis(JdX / D[:, :, None], 1, 0)
    K = np.einsum("nij,nik->njk", Wb, JW)
    K = np.where(ok[:, None, None], K, np.nan)
    scale = np.where(ok, S, np.nan)
    ev, growth, slow, fast, verdict = _reduce(K, scale)
    return _result(shape, ev, growth, slow, fast, verdict, scale, np.where(ok, Om, np.nan))


def wheel_reduced_jacobian(theta, alpha, a, r, k, g, outside=False):
    """The reduced Jacobian behind :func:`wheel_stability` (beyond the paper).

    Returns dict: ``K`` (n, 4, 4) [1/s], the flow's Jacobian in the turning
    frame on the 4-dimensional complement of the neutral directions;
    ``basis`` (n, 9, 4): state perturbations (SI units) spanning that
    complement, so a reduced vector y maps to the state perturbation
    ``basis @ y`` (tangent to the constraint surface to first order);
    ``state`` (9, n) the steady state (:func:`dynamics.wheel_orbit_state`);
    ``omega`` (n,) [rad/s].  Inputs are flattened (n = broadcast size).
    """
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (theta, alpha, a, r, k, g)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    K, scale, Om, shape, basis, X0 = _wheel_linearisation(theta, alpha, a, r, k, g, outside)
    return {"K": K, "basis": basis, "state": X0, "omega": Om}


# --------------------------------------------------------------------------
# the paper's results

def _quadratic_roots(A, B, C):
    """Roots x of A x^2 + B x + C = 0 as complex arrays (larger real part
    first).  Used for omega^2 of the paper's biquadratic determinants."""
    A, B, C = (np.asarray(x, dtype=complex) for x in (A, B, C))
    disc = np.sqrt(B * B - 4 * A * C)
    with np.errstate(divide="ignore", invalid="ignore"):
        x1 = (-B + disc) / (2 * A)
        x2 = (-B - disc) / (2 * A)
    swap = x2.real > x1.real
    return np.where(swap, x2, x1), np.where(swap, x1, x2)


def _both_real_positive(x1, x2, rtol=1e-12):
    """True where both roots are real (to rtol) and positive."""
    scale = np.abs(x1) + np.abs(x2)
    real = (np.abs(x1.imag) <= rtol * scale) & (np.abs(x2.imag) <= rtol * scale)
    return real & (x1.real > 0) & (x2.real > 0)


def _sqrt_freq(x1, x2):
    """Frequencies sqrt(omega^2) (slow, fast) where both roots are real and
    positive, else NaN."""
    ok = _both_real_positive(x1, x2)
    lo = np.where(ok, np.minimum(x1.real, x2.real), np.nan)
    hi = np.where(ok, np.maximum(x1.real, x2.real), np.nan)
    with np.errstate(invalid="ignore"):
        return np.sqrt(lo), np.sqrt(hi)


def vertical_paper(theta, phidot0, a, r, k, g):
    """The paper's stability analysis of vertical orbits, eqs. (100)-(106).

    McDonald (1993) sec. 2.3.1: the perturbation equations (76)-(77) frozen
    at the top of the orbit (phi = 0) with eps_r ~ cos(w t),
    eps_s ~ sin(w t) give the 2x2 system (102), whose determinant the paper
    writes A w^4 - B w^2 - C = 0 (103) with A, B, C of eqs. (104)-(105).

    Parameters broadcast: theta [rad] cone angle of the orbit (r sin(theta)
    is the radius of the rim's circle of contact), phidot0 [rad/s] orbital
    rate at the top, a, r [m], k [-], g [m/s^2].

    Returns dict: ``r_prime`` = r sin(theta) - a [m]; ``A`` [m^2],
    ``B`` [m^2/s^2], ``C`` [m^2/s^4] (eqs. 104-105); as printed:
    ``omega2_printed`` (2, ...) complex, roots (B +/- sqrt(B^2 + 4AC))/2A of
    eq. (103a) [rad^2/s^2]; ``stable_printed`` the paper's criterion
    B^2 + 4AC > 0 (its text: "real, positive roots whenever C > -B^2/4A");
    ``eq106`` phidot0^2 > g/((2k+1) r' + k a); ``contact_28a``
    phidot0^2 > g/r' (eq. 28a).  Corrected (errata E1, E2 of
    docs/stability.md): the determinant of (102) is
    -(A w^4 - B w^2 + C), so ``omega2`` (2, ...) = (B +/- sqrt(B^2 - 4AC))/2A
    and ``stable`` = (C > 0) & (B^2 >= 4AC) (both roots real positive);
    ``freq_slow``, ``freq_fast`` [rad/s] their square roots.

    The frozen-coefficient analysis is an approximation in any case (it
    drops the theta perturbation and, off the great circle theta = pi/2,
    mis-states the contact geometry, erratum E3); the exact answer is
    :func:`vertical_floquet`.
    """
    theta, phidot0, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (theta, phidot0, a, r, k, g)))
    rp = r * np.sin(theta) - a
    p2 = phidot0 ** 2
    A = k * (k + 1) * a ** 2
    B = k * a * g + k * ((2 * k + 1) * (2 * rp ** 2 + a ** 2) + (4 * k + 1) * a * rp) * p2
    C = k * (2 * rp + a) * (((2 * k + 1) * rp + k * a) * p2 - g) * p2
    pr1, pr2 = _quadratic_roots(A, -B, -C)
    x1, x2 = _quadratic_roots(A, -B, C)
    slow, fast = _sqrt_freq(x1, x2)
    with np.errstate(divide="ignore", invalid="ignore"):
        eq106 = p2 > g / ((2 * k + 1) * rp + k * a)
        contact = (rp > 0) & (p2 * rp > g)
    return {
        "r_prime": rp, "A": A, "B": B, "C": C,
        "omega2_printed": np.stack((pr1, pr2)),
        "stable_printed": B * B + 4 * A * C > 0,
        "eq106": eq106, "contact_28a": contact,
        "omega2": np.stack((x1, x2)),
        "stable": (C > 0) & (B * B >= 4 * A * C),
        "freq_slow": slow, "freq_fast": fast,
    }


def equator_matrix(alpha, omega, a, r, k, g):
    """The 3x3 coefficient matrix of eq. (133)/(134) as printed, at trial
    frequency omega [rad/s], for the orbit on the equator (theta = pi/2) with
    tilt alpha [rad]; Omega from eq. (29), r'_0 = r - a cos(alpha).
    Rows: the s, t, u equations; columns: delta, eps_s, eps_t.
    Returns an array of shape (..., 3, 3)."""
    c = _equator_coefficients(alpha, a, r, k, g)
    w = np.asarray(omega, dtype=float)
    w2 = w * w
    row1 = (c["A11"] * w, c["A12"] * w, c["A13"] + c["B13"] * w2)
    row2 = (c["A21"] * w2, c["A22"] + c["B22"] * w2, c["A23"] * w)
    row3 = (c["A31"] * w2, c["A32"] + 0 * w, c["A33"] * w)
    rows = [np.stack(np.broadcast_arrays(*row), axis=-1) for row in (row1, row2, row3)]
    return np.stack(rows, axis=-2)


def equator_printed_abc(c):
    """A, B, C of eqs. (136)-(138) as printed, from the coefficients of the
    3x3 system (134) (``c`` as returned by :func:`_equator_coefficients`)."""
    A = c["B13"] * c["B22"] * c["A31"]
    B = (c["A11"] * c["B22"] * c["A33"] + c["A12"] * c["A23"] * c["A31"]
         + c["B13"] * c["A21"] * c["A32"] - c["A13"] * c["B22"] * c["A31"]
         - c["B13"] * c["A22"] * c["A31"] - c["A12"] * c["A21"] * c["A33"])
    C = (c["A11"] * c["A22"] * c["A33"] + c["A13"] * c["A21"] * c["A32"]
         - c["A13"] * c["A22"] * c["A31"] - c["A11"] * c["A23"] * c["A32"])
    return A, B, C


def _equator_coefficients(alpha, a, r, k, g):
    """A_ij, B_ij of eq. (134), read off eq. (133) as printed."""
    alpha, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (alpha, a, r, k, g)))
    sa, ca = np.sin(alpha), np.cos(alpha)
    rp = r - a * ca                                   # r'_0 at theta = pi/2
    om2 = omega_squared(np.pi / 2, alpha, a, r, k, g)
    om2 = np.where(om2 > 0, om2, np.nan)
    Om = np.sqrt(om2)
    return {
        "Omega": Om, "r_prime": rp,
        "A11": 2 * Om * sa * ((2 * k + 1) * rp + k * a * ca),
        "A12": -Om * (2 * k + 1) * (rp + a * ca),
        "A13": -(om2 * ((2 * k + 1) * rp * ca + (k + sa ** 2) * a) - g * sa),
        "B13": -(k + 1) * a,
        "A21": -k * a * sa,
        "A22": k * om2 * ca * (2 * rp + a * ca),
        "B22": k * a,
        "A23": 2 * k * Om * (rp + a * ca),
        "A31": -(2 * k + 1) * rp,
        "A32": om2 * sa * ((2 * k + 1) * rp + (k + 1) * a * ca),
        "A33": 2 * (k + 1) * Om * sa * a,
    }


def equator_paper(alpha, a, r, k, g):
    """The paper's stability analysis of the orbit on the equator,
    eqs. (127)-(138), as printed.

    McDonald (1993) sec. 2.3.3: eq. (133) is a 3x3 homogeneous system in
    (delta, eps_s, eps_t); det = 0 gives A w^4 - B w^2 - C = 0 (135) with the
    closed forms (136)-(138).  Both routes are evaluated:

    ``omega2_det`` (2, ...) complex [rad^2/s^2]: roots in w^2 of
    det(eq. 133)/w^2 (a quadratic in w^2), found numerically by evaluating
    the printed matrix (:func:`equator_matrix`) at three trial frequencies;
    ``A``, ``B``, ``C`` from eqs. (136)-(138) and ``omega2_closed`` the roots
    of eq. (135) with them (the two agree: eqs. 135-138 are the correct
    expansion of the printed determinant); ``stable_printed`` both w^2 roots
    real and positive (what "stable" means); ``all_positive`` A, B, C > 0
    (the paper's stated numerical finding); ``freq_slow``, ``freq_fast``
    [rad/s]; ``Omega`` [rad/s] (eq. 29).

    Beyond-the-paper finding (docs/stability.md, erratum E4): eq. (133)
    rests on eq. (116), which keeps axis 3 in the vertical t-u plane; the
    rolling contact actually tilts it out of that plane by
    eps_s r sin(alpha)/(r cos(alpha) - a) on the equator, a first-order term
    the paper drops, so these frequencies differ from the exact ones
    (:func:`equator_exact_closed_form`, :func:`wheel_stability`).
    """
    c = _equator_coefficients(alpha, a, r, k, g)
    A, B, C = equator_printed_abc(c)
    x1, x2 = _quadratic_roots(A, -B, -C)
    # numerical route: q(x) = det(M(sqrt x))/x is quadratic in x = w^2
    Om2 = c["Omega"] ** 2
    xs = np.stack([Om2 * f for f in (1.0, 2.0, 3.0)])
    alpha_b = np.broadcast_to(_vec(alpha), Om2.shape)
    with np.errstate(invalid="ignore"):
        M = equator_matrix(alpha_b, np.sqrt(xs), a, r, k, g)
    finite = np.all(np.isfinite(M), axis=(-2, -1))
    dets = np.where(finite, np.linalg.det(np.where(finite[..., None, None], M, 0.0)), np.nan)
    q = dets / xs
    # q(x) = q2 x^2 + q1 x + q0 through the three points (x = Om2 (1, 2, 3))
    d1 = (q[1] - q[0]) / Om2
    d2 = (q[2] - q[1]) / Om2
    q2 = (d2 - d1) / (2 * Om2)
    q1 = d1 - q2 * (xs[0] + xs[1])
    q0 = q[0] - q1 * xs[0] - q2 * xs[0] ** 2
    y1, y2 = _quadratic_roots(q2, q1, q0)
    slow, fast = _sqrt_freq(x1, x2)
    return {
        "Omega": c["Omega"], "r_prime": c["r_prime"],
        "A": A, "B": B, "C": C,
        "omega2_closed": np.stack((x1, x2)),
        "omega2_det": np.stack((y1, y2)),
        "stable_printed": _both_real_positive(x1, x2),
        "all_positive": (A > 0) & (B > 0) & (C > 0),
        "freq_slow": slow, "freq_fast": fast,
    }


def small_wheel_paper(theta, alpha, a, r, k, g):
    """The paper's small-wheel result, eqs. (201)-(207), as printed.

    w^2 = Omega^2 sin(alpha)(cos(alpha) + 2 sin(alpha))
          + g sin^2(alpha)/((2k+1) r'_0)                      (207, first form)
        = Omega^2 tan(alpha)(1 + sin(2 alpha))              (207, second form)

    with Omega from eq. (29).  The two forms agree when a << r'_0 (eq. 201):
    checked, no slip in this step.  Returns dict ``omega2_first``,
    ``omega2_second`` [rad^2/s^2], ``freq`` [rad/s] (sqrt of the first
    form, NaN if negative), ``stable_printed`` (w^2 > 0: "all orbits for
    small wheels are stable"), ``validity`` a/r'_0 (eq. 201 asks << 1),
    ``Omega``.

    Eq. (203) inherits the sin/cos slip of eq. (128) (erratum E8: with cos
    the same steps give Omega^2 (1 + 2 sin^2 alpha)), and the physics behind
    eqs. (202)-(204) drops the first-order tilt of axis 3 (eq. 116, erratum
    E4); the correct small-wheel limit is :func:`small_wheel_corrected`.
    """
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (theta, alpha, a, r, k, g)))
    om2 = omega_squared(theta, alpha, a, r, k, g)
    om2 = np.where(om2 > 0, om2, np.nan)
    rp = r * np.sin(theta) - a * np.cos(alpha)
    sa, ca = np.sin(alpha), np.cos(alpha)
    with np.errstate(divide="ignore", invalid="ignore"):
        first = om2 * sa * (ca + 2 * sa) + g * sa ** 2 / ((2 * k + 1) * rp)
        second = om2 * np.tan(alpha) * (1 + np.sin(2 * alpha))
        validity = a / np.abs(rp)
        freq = np.sqrt(np.where(first > 0, first, np.nan))
    return {"omega2_first": first, "omega2_second": second, "freq": freq,
            "stable_printed": first > 0, "validity": validity,
            "Omega": np.sqrt(om2)}


def small_wheel_corrected(theta, alpha, a, r, k, g):
    """Correct small-wheel limit (a << r'_0) of the two nutation frequencies
    of a steady horizontal orbit (beyond the paper: erratum E5,
    docs/stability.md; confirmed against :func:`wheel_stability`).

    slow:  w_s^2 = Omega^2 [1 + 3 sin(alpha) tan(alpha) sin(theta)/sin(theta - alpha)]
    fast:  w_f^2 = 2 (2k+1)/(k+1) w_1^2,   w_1 = r'_0 Omega / a (eq. 13)

    Omega from eq. (29).  Leading order in a/r'_0; the slow form is
    independent of k.  Returns dict ``omega2_slow``, ``omega2_fast``
    [rad^2/s^2], ``freq_slow``, ``freq_fast`` [rad/s].
    """
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (theta, alpha, a, r, k, g)))
    om2 = omega_squared(theta, alpha, a, r, k, g)
    om2 = np.where(om2 > 0, om2, np.nan)
    rp = r * np.sin(theta) - a * np.cos(alpha)
    sa = np.sin(alpha)
    with np.errstate(divide="ignore", invalid="ignore"):
        slow2 = om2 * (1 + 3 * sa * np.tan(alpha) * np.sin(theta) / np.sin(theta - alpha))
        fast2 = 2 * (2 * k + 1) / (k + 1) * (rp / a) ** 2 * om2
        fs = np.sqrt(np.where(slow2 > 0, slow2, np.nan))
    return {"omega2_slow": slow2, "omega2_fast": fast2,
            "freq_slow": fs, "freq_fast": np.sqrt(fast2)}


def near_pole_paper(theta, alpha, a, r, k, g):
    """The paper's near-pole criterion, eq. (208), and its correction.

    McDonald (1993) eq. (208), quoted for a wheel rolling on a horizontal
    plane and offered for orbits with r'_0 <~ a:  Omega^2 > g/((2k+1) a).
    The straight-rolling criterion is in fact
    w^2 > g/(2 (2k+1) a) (erratum E6: the gyroscopic coupling is
    2 (2k+1) w^2 in the lean equation; classical hoop v^2 > g a/4, coin
    v^2 > g a/3; reproduced by :func:`wheel_stability` for a wide circle on a
    nearly flat floor).

    Returns dict ``Omega`` [rad/s] (eq. 29), ``threshold_printed`` =
    g/((2k+1) a) and ``threshold_disk`` = g/(2 (2k+1) a) [rad^2/s^2],
    ``stable_printed`` Omega^2 > threshold_printed, ``stable_disk``
    Omega^2 > threshold_disk, ``applies`` r'_0 <= a (the paper's "r'_0 <~ a").
    """
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (theta, alpha, a, r, k, g)))
    om2 = omega_squared(theta, alpha, a, r, k, g)
    om2 = np.where(om2 > 0, om2, np.nan)
    rp = r * np.sin(theta) - a * np.cos(alpha)
    t_p = g / ((2 * k + 1) * a)
    t_d = t_p / 2
    return {"Omega": np.sqrt(om2), "threshold_printed": t_p, "threshold_disk": t_d,
            "stable_printed": om2 > t_p, "stable_disk": om2 > t_d,
            "applies": np.abs(rp) <= a}


#: |multiplier| - 1 at or below which a vertical orbit is called stable, and at
#: or above which unstable (unknown between).  The order-8 monodromy with the
#: default step reproduces |mu| = 1 to ~1e-11 on stable orbits and its
#: multipliers are within ~1e-9 of a run with a quarter of the step
#: (docs/stability.md sec. 2).
FLOQUET_STABLE_TOL = 1e-6
FLOQUET_UNSTABLE_TOL = 1e-4

#: orbits up to which the monodromy is integrated orbit by orbit on Python
#: complex numbers (dynamics._equations with cmath.sqrt); more orbits go
#: through numpy arrays, all orbits and directions at once
_FLOQUET_SCALAR_MAX = 16


#: the reversing symmetry of a vertical orbit (orbit plane normal to y, top
#: at x = 0): the mirror x -> -x combined with time reversal flips the x
#: components of c, e1 and w, and G f(X) = -f(G X) for the flow f
_REVERSAL = np.array([-1.0, 1, 1, -1, 1, 1, -1, 1, 1])


def _vertical_state(th, pd, a, r, k, g, bottom=False):
    """State of a vertical orbit at its top (:func:`dynamics.vertical_orbit_state`)
    or, with ``bottom``, half a lap later at its bottom: the top state turned
    by pi about the orbit's axis y (x, z of each vector flipped) with the
    bottom rate phidot^2 = phidot0^2 + 4 g/((2k+1) r') (eq. 27).  Complex
    theta / phidot0 accepted (complex step)."""
    if not bottom:
        return dyn.vertical_orbit_state(th, pd, a, r)
    rp = r * np.sin(th) - a
    X = dyn.vertical_orbit_state(th, np.sqrt(pd * pd + 4 * g / ((2 * k + 1) * rp)), a, r)
    return X * np.array([-1.0, 1, -1, -1, 1, -1, -1, 1, -1])[:, None]


def _vertical_neutral_basis(X0, th, pd, a, r, k, g, p, D, bottom=False):
    """Orthonormal basis (n, 9, 3) (scaled coordinates) of the complement of
    the six neutral directions of a vertical orbit at the state X0 (its top,
    or with ``bottom`` its bottom): the two constraint normals, phase f(X0),
    rotation about the vertical z x X0, d/dtheta and d/dphidot0 of the
    family (docs/stability.md sec. 2)."""
    n = th.size
    c, e1 = X0[dyn.C], X0[dyn.E1]
    fx = dyn.rhs(X0, p)
    gen = np.concatenate((dyn._zcross(c), dyn._zcross(e1), dyn._zcross(X0[dyn.W])))
    dth = np.imag(_vertical_state(th + 1j * _H, pd, a, r, k, g, bottom)) / _H
    dpd = np.imag(_vertical_state(th, pd + 1j * _H, a, r, k, g, bottom)) / _H
    V = np.stack((fx, gen, dth, dpd), axis=-1) / D[..., None]
    e3 = dyn._geometry(X0, p)[8]
    pv = c + a * e3
    n1 = np.concatenate((np.zeros((3, n)), e1, np.zeros((3, n))))
    n2 = np.concatenate((pv, -a * dyn._dot(c, e1) * e3, np.zeros((3, n))))
    Nrm = np.stack((n1, n2), axis=-1) * D[..., None]
    A = np.moveaxis(np.concatenate((Nrm, V), axis=-1), 0, 1)
    A = A / np.linalg.norm(A, axis=1, keepdims=True)
    return _orthonormal_complement(A, 9)


def _rk8_columns(x, p, dt, steps):
    """``steps`` fixed steps dt (n,) of the order-8 Runge-Kutta method
    (:mod:`deathsphere.physics._rk8`) of the unperturbed flow (lab frame)
    from the complex states x (9, n, m); returns the states at the end.

    Few orbits: orbit by orbit, each column's right-hand side on Python
    complex numbers (the lines of :func:`dynamics._equations` with
    cmath.sqrt; ~40x cheaper than numpy on 9-element arrays); stage sums by
    numpy.  Many orbits: :func:`dynamics.rhs` on all at once.  Both run the
    same equations; tests/physics/test_floquet.py compares them."""
    n = x.shape[1]
    out = np.empty_like(x)
    if n <= _FLOQUET_SCALAR_MAX:
        for i in range(n):
            coef = dyn.scalar_coefficients(dyn.BodyParams(*(f[i:i + 1] for f in p)))
            out[:, i, :] = _rk8_scalar(x[:, i, :].T.copy(), coef, float(dt[i]), steps).T
        return out
    pc = dyn.BodyParams(*(f[:, None] for f in p))
    h = np.asarray(dt, dtype=float)[:, None]
    ks = [None] * len(_rk8.B)
    for _ in range(steps):
        for s, row in enumerate(_rk8.A):
            xs = x
            for j, a_sj in row:
                xs = xs + (h * a_sj) * ks[j]
            ks[s] = dyn.rhs(xs, pc)
        x = x + h * sum(b * kj for b, kj in zip(_rk8.B, ks) if b)
    return x


def _rk8_scalar(X, coef, dt, steps):
    """:func:`_rk8_columns` for one orbit: X (m, 9) complex."""
    m = X.shape[0]
    eq = dyn._equations
    sqrt = cmath.sqrt
    nst = len(_rk8.B)
    A = [np.array([a_sj * dt for _, a_sj in row]) for row in _rk8.A]
    J = [[j for j, _ in row] for row in _rk8.A]
    Bw = np.array(_rk8.B) * dt
    x = X.reshape(-1)
    ks = np.empty((nst, m * 9), dtype=complex)
    for _ in range(steps):
        for s in range(nst):
            xs = (x + A[s].dot(ks[J[s]]) if s else x).tolist()
            ks[s] = [v for col in range(0, 9 * m, 9) for v in eq(*xs[col:col + 9], coef, sqrt)]
        x = x + Bw.dot(ks)
    return x.reshape(m, 9)


def vertical_floquet(theta, phidot0, a, r, k, g, step=0.25):
    """Exact linear stability of vertical orbits by Floquet analysis.

    Beyond the paper (the paper's eqs. 100-106 freeze the coefficients at the
    top of the orbit; docs/stability.md sec. 2).  The monodromy matrix over
    one period T (eq. 27; :func:`dynamics.vertical_orbit_period`) is taken on
    the constraint manifold modulo the six neutral directions (phase,
    energy, theta family, rotation about the vertical, and the two
    constraint normals): only the three directions spanning that quotient
    are integrated, as complex-step perturbations of the state (exact
    derivatives), with the exact equations of motion
    (:mod:`deathsphere.physics.dynamics`) and a fixed-step order-8
    Runge-Kutta method (``step`` = largest rate x time step), over half a
    lap only: the flow is reversible (mirror x -> -x with time reversal,
    ``_REVERSAL``), top and bottom are symmetric points, so the monodromy is
    M = G Mh^-1 G Mh with Mh the half-lap one, taken on the quotient bases at
    top and bottom.  That leaves 3 multipliers: one is 1 (a further neutral
    direction, found numerically), the other two are the nutation pair.

    Inputs broadcast: theta [rad] (orbit plane at distance r cos(theta)
    from the centre), phidot0 [rad/s] rate at the top, a, r [m], k [-],
    g [m/s^2].  Batched.

    Returns dict: ``multipliers`` (..., 3) complex; ``max_abs`` max |mu|;
    ``growth_rate`` log(max |mu|)/T [1/s]; ``nu`` [rad/s] |arg mu|/T of the
    multiplier farthest from 1 (the nutation frequency modulo 2 pi/T);
    ``period`` T [s]; ``verdict`` int8 :class:`Verdict` with the tolerances
    FLOQUET_STABLE_TOL / FLOQUET_UNSTABLE_TOL on |mu| - 1; ``return_error``
    [m] |c(T/2) - c_bottom| of the integrated reference orbit against the
    bottom of eq. (27) (integration check).  NaN/UNKNOWN where
    r sin(theta) <= a.
    """
    theta, phidot0, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (theta, phidot0, a, r, k, g)))
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
    T = dyn.vertical_orbit_period(th, pd, a, r, k, g)
    X0 = dyn.vertical_orbit_state(th, pd, a, r, k, g)
    p = dyn.BodyParams(a, r, k, g, np.zeros(n, dtype=bool), np.zeros(n, dtype=bool))
    pdmax = np.sqrt(pd ** 2 + 4 * g / ((2 * k + 1) * rp))
    S = np.sqrt((rp * pdmax / a) ** 2 + pdmax ** 2 + g / a)     # fastest rate
    N = int(np.ceil(np.max(T * S) / (2 * step))) if n else 0               # steps per half lap
    D = np.concatenate((np.broadcast_to(a, (3, n)), np.ones((3, n)), np.broadcast_to(S, (3, n))))
    Wb = _vertical_neutral_basis(X0, th, pd, a, r, k, g, p, D)                # (n, 9, 3)
    x = X0[:, :, None] + 1j * _H * (np.moveaxis(Wb, 0, 1) * D[:, :, None])    # (9, n, 3)
    x = _rk8_columns(x, p, 0.5 * T / max(N, 1), N)                            # top -> bottom
    Xb = _vertical_state(th, pd, a, r, k, g, bottom=True)
    ret = np.sqrt(np.sum((np.real(x[0:3, :, 0]) - Xb[0:3]) ** 2, axis=0))
    Wh = _vertical_neutral_basis(np.real(x[:, :, 0]), th, pd, a, r, k, g, p, D, bottom=True)
    Kh = np.einsum("nji,njl->nil", Wh, np.moveaxis(np.imag(x) / _H / D[:, :, None], 1, 0))
    # reversibility: M = G Mh^-1 G Mh (Mh the half-lap monodromy, G
    # _REVERSAL), taken on the quotient bases at top and bottom
    G0 = np.einsum("nji,j,njl->nil", Wb, _REVERSAL, Wb)
    Gh = np.einsum("nji,j,njl->nil", Wh, _REVERSAL, Wh)
    finite = np.all(np.isfinite(Kh), axis=(-2, -1)) & ok
    Kh = np.where(finite[:, None, None], Kh, np.eye(3))
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        K = G0 @ np.linalg.solve(Kh, Gh @ Kh)
    finite &= np.all(np.isfinite(K), axis=(-2, -1))
    mu = np.linalg.eigvals(np.where(finite[:, None, None], K, np.eye(3)))
    mu = np.where(finite[:, None], mu, np.nan)
    mabs = np.max(np.abs(mu), axis=-1)
    far = np.argmax(np.abs(mu - 1), axis=-1)
    mu_far = np.take_along_axis(mu, far[:, None], axis=-1)[:, 0]
    verdict = np.full(n, Verdict.UNKNOWN, dtype=np.int8)
    dev = mabs - 1
    verdict[np.nan_to_num(dev, nan=np.inf) <= FLOQUET_STABLE_TOL] = Verdict.STABLE
    verdict[np.nan_to_num(dev, nan=-np.inf) >= FLOQUET_UNSTABLE_TOL] = Verdict.UNSTABLE
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


def sphere_nutation_closed_form(theta, Omega, a, r, k, g, outside=False):
    """Nutation frequency of a sphere's steady horizontal orbit, closed form.

    Beyond the paper (sec. 4 says a complete analysis can be given; this is
    it, docs/stability.md): eq. (46) is a heavy symmetric top with
    I_perp = (k+1) r', spin angular momentum L3 = -k a omega3, m g l = g
    (per unit mass and a).  About steady precession at rate Omega (eq. 55)
    the one nutation mode has, in the turning frame,

        w^2 = (k a omega3/((k+1) r') + 2 Omega cos(theta))^2 + Omega^2 sin^2(theta) > 0,

    r' = r - a inside, r + a outside, omega3 = w.e3 from eq. (55).  Always
    positive: every horizontal orbit of a rolling sphere is linearly stable,
    inside and outside (as sec. 5 states, citing Milne).  Agrees with
    :func:`sphere_stability` to round-off (tests/physics/test_stability.py).
    Returns w [rad/s].
    """
    theta, Omega, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (theta, Omega, a, r, k, g)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    rp = np.where(outside, r + a, r - a)
    with np.errstate(divide="ignore", invalid="ignore"):
        omega3 = np.where(Omega != 0, -((k + 1) * rp * Omega ** 2 * np.cos(theta) + g)
                          / (k * a * np.where(Omega != 0, Omega, 1.0)), np.nan)
    b = k * a * omega3 / ((k + 1) * rp)
    return np.sqrt((b + 2 * Omega * np.cos(theta)) ** 2 + (Omega * np.sin(theta)) ** 2)


def _rel(x, ref):
    with np.errstate(divide="ignore", invalid="ignore"):
        return (x - ref) / np.abs(ref)


#: a/|r'| below which the small-wheel results (eq. 201, a << r'_0) are
#: flagged as applicable in :func:`compare_with_paper`.
SMALL_WHEEL_VALIDITY = 0.05
#: |theta - pi/2| [rad] within which an orbit counts as "on the equator".
EQUATOR_TOL = 1e-9


def compare_with_paper(theta, alpha, a, r, k, g, outside=False):
    """Every applicable stability result of the paper beside the exact one,
    per horizontal orbit of a wheel (for the ``stability`` command).

    Returns ``(exact, results)``: ``exact`` is the dict of
    :func:`wheel_stability`; ``results`` maps a result name to a dict with

    ``equation`` (str) the paper's equation(s), ``quantity`` (str) what is
    compared, ``units``, ``paper`` (array) the paper's value as printed,
    ``corrected`` (array) the corrected formula's value (NaN if none),
    ``exact`` (array) the exact value, ``deviation`` (array) relative
    deviation (paper - exact)/|exact| for frequencies, or 0/1 (agree /
    disagree) for verdicts, ``corrected_deviation`` likewise,
    ``applies`` (bool array) where the paper states the result holds
    (elsewhere the arrays hold NaN, and UNKNOWN for verdicts),
    ``validity`` (array) the measure of its approximation (NaN if exact
    in principle), ``note`` (str).

    Names: ``equator_slow``, ``equator_fast``, ``equator_verdict``
    (eqs. 133-138, theta = pi/2); ``small_wheel_slow``, ``small_wheel_fast``,
    ``small_wheel_verdict`` (eqs. 201-207; validity a/|r'|);
    ``near_pole_verdict`` (eq. 208, r' <= a).  Verdict arrays hold
    :class:`Verdict` codes.  All apply to the wheel inside only (sec. 2.3;
    sec. 3 says the analysis carries over "formally" but gives no result).
    Fit/contact are not checked: combine with
    :func:`deathsphere.physics.wheel.horizontal_orbit`.
    """
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (theta, alpha, a, r, k, g)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    ex = wheel_stability(theta, alpha, a, r, k, g, outside)
    exists = np.isfinite(ex["growth_rate"])
    S, U, N = Verdict.STABLE, Verdict.UNSTABLE, Verdict.UNKNOWN

    def verdict_of(stable_bool, defined):
        return np.where(defined, np.where(stable_bool, S, U), N).astype(np.int8)

    def disagree(v):
        known = (v != N) & (ex["verdict"] != N)
        return np.where(known, (v != ex["verdict"]).astype(float), np.nan)

    inside = ~outside        # sec. 2.3 is about the wheel inside (sec. 3: "formally" only)
    on_eq = (np.abs(theta - np.pi / 2) <= EQUATOR_TOL) & inside
    eqp = equator_paper(alpha, a, r, k, g)
    eqc = equator_exact_closed_form(alpha, a, r, k, g)
    eq_def = np.isfinite(eqp["Omega"]) & exists
    sw = small_wheel_paper(theta, alpha, a, r, k, g)
    swc = small_wheel_corrected(theta, alpha, a, r, k, g)
    np_ = near_pole_paper(theta, alpha, a, r, k, g)
    sw_def = exists & np.isfinite(sw["omega2_first"]) & inside
    results = {
        "equator_slow": dict(
            equation="133-138", quantity="slow nutation frequency", units="rad/s",
            paper=eqp["freq_slow"], corrected=eqc["freq_slow"], exact=ex["freq_slow"],
            applies=on_eq & eq_def, validity=np.full(theta.shape, np.nan),
            note="printed eq. (133) drops the tilt of axis 3 out of the t-u plane (E4)"),
        "equator_fast": dict(
            equation="133-138", quantity="fast nutation frequency", units="rad/s",
            paper=eqp["freq_fast"], corrected=eqc["freq_fast"], exact=ex["freq_fast"],
            applies=on_eq & eq_def, validity=np.full(theta.shape, np.nan),
            note="printed eq. (133) drops the tilt of axis 3 out of the t-u plane (E4)"),
        "equator_verdict": dict(
            equation="135", quantity="verdict (both w^2 real > 0)", units="",
            paper=verdict_of(eqp["stable_printed"], eq_def),
            corrected=verdict_of(eqc["stable"], eq_def), exact=ex["verdict"],
            applies=on_eq & eq_def, validity=np.full(theta.shape, np.nan),
            note="the paper: all equatorial orbits stable"),
        "small_wheel_slow": dict(
            equation="207", quantity="slow nutation frequency", units="rad/s",
            paper=sw["freq"], corrected=swc["freq_slow"], exact=ex["freq_slow"],
            applies=sw_def & (sw["validity"] <= SMALL_WHEEL_VALIDITY), validity=sw["validity"],
            note="eq. (207) inherits E4; corrected: Omega^2 [1 + 3 sin a tan a sin th / sin(th - a)] (E5)"),
        "small_wheel_fast": dict(
            equation="(none)", quantity="fast nutation frequency", units="rad/s",
            paper=np.full(theta.shape, np.nan), corrected=swc["freq_fast"], exact=ex["freq_fast"],
            applies=sw_def & (sw["validity"] <= SMALL_WHEEL_VALIDITY), validity=sw["validity"],
            note="the paper gives no fast mode; corrected: 2(2k+1)/(k+1) (r' Omega/a)^2"),
        "small_wheel_verdict": dict(
            equation="207", quantity="verdict (w^2 > 0)", units="",
            paper=verdict_of(sw["stable_printed"], sw_def),
            corrected=verdict_of((swc["omega2_slow"] > 0) & (swc["omega2_fast"] > 0), sw_def),
            exact=ex["verdict"],
            applies=sw_def & (sw["validity"] <= SMALL_WHEEL_VALIDITY), validity=sw["validity"],
            note="the paper: all small-wheel orbits stable"),
        "near_pole_verdict": dict(
            equation="208", quantity="verdict (Omega^2 > threshold)", units="",
            paper=verdict_of(np_["stable_printed"], exists),
            corrected=verdict_of(np_["stable_disk"], exists), exact=ex["verdict"],
            applies=np_["applies"] & exists & inside,
            validity=np.abs(r * np.sin(theta) - a * np.cos(alpha)) / a,
            note="eq. (208) is the rolling-disk criterion offered by analogy; "
                 "the disk's own threshold is g/(2(2k+1)a) (E6)"),
    }
    for res in results.values():
        ap = res["applies"]
        if res["units"]:
            res["deviation"] = _rel(res["paper"], res["exact"])
            res["corrected_deviation"] = _rel(res["corrected"], res["exact"])
            for key in ("paper", "corrected", "exact", "deviation", "corrected_deviation"):
                res[key] = np.where(ap, res[key], np.nan)
        else:
            res["deviation"] = np.where(ap, disagree(res["paper"]), np.nan)
            res["corrected_deviation"] = np.where(ap, disagree(res["corrected"]), np.nan)
            for key in ("paper", "corrected", "exact"):
                res[key] = np.where(ap, res[key], N).astype(np.int8)
    return ex, results


def _nutation_from_invariants(e2, e4):
    """Roots w^2 of w^4 - e2 w^2 + e4 = 0 (the reduced characteristic
    polynomial lambda^4 + e2 lambda^2 + e4, lambda = i w): frequencies and
    the verdict (both roots real and positive)."""
    x1, x2 = _quadratic_roots(np.ones_like(e2), -e2, e4)
    stable = (e2 > 0) & (e4 > 0) & (e2 * e2 >= 4 * e4)
    slow, fast = _sqrt_freq(x1, x2)
    return x1, x2, stable, slow, fast


def equator_exact_closed_form(alpha, a, r, k, g):
    """Exact nutation frequencies of the orbit on the equator, closed form.

    Beyond the paper: the correct version of eqs. (133)-(138) (erratum E4,
    docs/stability.md).  Derived symbolically (sympy) from the exact
    equations of motion: the characteristic polynomial of the linearised flow
    in the turning frame is lambda^5 (lambda^4 + e2 lambda^2 + e4), i.e.
    w^4 - e2 w^2 + e4 = 0 for the nutation frequencies w, with
    (u = a/r, c = cos(alpha), Omega^2 from eq. 29):

        e2/Omega^2 = P2 / ((k+1)(2k+1) u^2 c (c - u))
        e4/Omega^4 = P4 / ((k+1)(2k+1) u^2 c^2 (c - u))

        P2 = 2 (2k+1)^2 c^2 - (2k+1) c (2c^2 + 8k + 3) u
             + (2k+1) (-(k+1) c^4 + 4 (k+1) c^2 + 3k + 2) u^2
             + (k+1) c ((k+2) c^2 - (5k+4)) u^3
        P4 = (2k+1)^2 c (6 - 4 c^2)
             + (2k+1) (2 (7k+5) c^4 - 2 (10k+7) c^2 - (2k+1)) u
             + (-2 (8k+5)(k+1) c^5 + 2 (12k+7)(k+1) c^3 + k (2k+1) c) u^2
             + (k+1) c^4 (3 (k+1) c^2 - (5k+4)) u^3

    (c - u = (r cos(alpha) - a)/r > 0 is the fit condition, eq. 0.)  For
    u -> 0: w_fast^2 -> 2 (2k+1)/(k+1) (r/a)^2 Omega^2 and
    w_slow^2 -> (1 + 3 tan^2 alpha) Omega^2 (eq. 207 instead gives
    tan(alpha)(1 + sin 2 alpha) Omega^2).  Stable iff e2 > 0, e4 > 0 and
    e2^2 >= 4 e4.

    Returns dict ``e2`` [1/s^2], ``e4`` [1/s^4], ``omega2`` (2, ...)
    complex [rad^2/s^2], ``stable`` (bool), ``freq_slow``, ``freq_fast``
    [rad/s], ``Omega`` [rad/s].
    """
    alpha, a, r, k, g = np.broadcast_arrays(*(_vec(x) for x in (alpha, a, r, k, g)))
    om2 = omega_squared(np.pi / 2, alpha, a, r, k, g)
    om2 = np.where(om2 > 0, om2, np.nan)
    u = a / r
    c = np.cos(alpha)
    k1, k2 = k + 1, 2 * k + 1
    P2 = (2 * k2 ** 2 * c ** 2 - k2 * c * (2 * c ** 2 + 8 * k + 3) * u
          + k2 * (-k1 * c ** 4 + 4 * k1 * c ** 2 + 3 * k + 2) * u ** 2
          + k1 * c * ((k + 2) * c ** 2 - (5 * k + 4)) * u ** 3)
    P4 = (k2 ** 2 * c * (6 - 4 * c ** 2)
          + k2 * (2 * (7 * k + 5) * c ** 4 - 2 * (10 * k + 7) * c ** 2 - k2) * u
          + (-2 * (8 * k + 5) * k1 * c ** 5 + 2 * (12 * k + 7) * k1 * c ** 3 + k * k2 * c) * u ** 2
          + k1 * c ** 4 * (3 * k1 * c ** 2 - (5 * k + 4)) * u ** 3)
    den = k1 * k2 * u ** 2 * c * (c - u)
    with np.errstate(divide="ignore", invalid="ignore"):
        e2 = om2 * P2 / den
        e4 = om2 ** 2 * P4 / (den * c)
    x1, x2, stable, slow, fast = _nutation_from_invariants(e2, e4)
    return {"e2": e2, "e4": e4, "omega2": np.stack((x1, x2)), "stable": stable,
            "freq_slow": slow, "freq_fast": fast, "Omega": np.sqrt(om2)}
