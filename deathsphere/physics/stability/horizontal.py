"""Exact linear stability of steady horizontal orbits (beyond the paper;
docs/stability.md sec. 1).

The equations of motion of :mod:`deathsphere.physics.dynamics` are
linearised about a steady horizontal orbit in the frame turning with it, by
exact derivatives (complex step; forward mode for the wheel), restricted to
the constraint manifold and to the complement of the neutral modes that the
rotation symmetry and the family of steady orbits produce
(:mod:`~deathsphere.physics.stability.reduction`).  Batched: stacked
Jacobians, one eigenvalue (or invariant) evaluation for all orbits.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics import dynamics as dyn
from deathsphere.physics.geometry import SINGULAR, fits_inside, fits_outside
from deathsphere.physics.stability.reduction import (
    COMPLEX_STEP,
    complex_step,
    householder_complement,
    orthonormal_complement,
    spectrum,
    spectrum_from_invariants,
)
from deathsphere.physics.stability.verdict import Verdict
from deathsphere.physics.vectors import dot, zcross
from deathsphere.physics.wheel import CHUNK as WHEEL_CHUNK
from deathsphere.physics.wheel import omega_squared

__all__ = ["CHUNK", "wheel_stability", "sphere_stability", "wheel_reduced_jacobian",
           "stability_result", "empty_result"]

#: orbits per vectorised batch: the wheel's piece size (bounds memory; ~1 KB
#: of temporaries per orbit here)
CHUNK = WHEEL_CHUNK


def _wheel_linearisation(theta, alpha, a, r, k, g, outside, want_basis=True):
    """Reduced 4x4 Jacobians of the wheel's flow about steady orbits.

    Component-major throughout (arrays (9, ..., n)): the five directions
    removed (two constraint normals; rotation about the vertical; d/dtheta,
    d/dalpha of the family, by one complex-step call) are scaled (lengths by
    a, rates by S) and normalised, their orthonormal complement comes from
    :func:`~deathsphere.physics.stability.reduction.householder_complement`, and the Jacobian acts on its four
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
    step = 1j * COMPLEX_STEP * np.eye(2)[:, :, None]
    dfam = np.imag(dyn.wheel_orbit_state(th_s + step[0], al_s + step[1], a, r_s, k, g, out_s)[0]) / COMPLEX_STEP
    c, e1, w = X0[dyn.C], X0[dyn.E1], X0[dyn.W]
    # scaling: lengths by a, rates by S
    S = np.sqrt(dot(w, w) + Om ** 2 + g / a)
    D = np.empty((9, n))
    D[0:3], D[3:6], D[6:9] = a, 1.0, S
    e3 = dyn.contact_geometry(X0, p).e3
    A = np.zeros((9, 5, n))
    A[3:6, 0] = e1 * D[3:6]                          # constraint gradients (scaled: D grad)
    A[0:3, 1] = (c + a * e3) * D[0:3]
    A[3:6, 1] = -a * dot(c, e1) * e3 * D[3:6]
    for blk in (dyn.C, dyn.E1, dyn.W):               # rotation about the vertical
        A[blk, 2] = zcross(X0[blk]) / D[blk]
    A[:, 3:5] = dfam / D[:, None, :]
    A *= 1.0 / np.sqrt(np.einsum("ikn,ikn->kn", A, A))[None]   # well-conditioned columns
    Y = householder_complement(A)                                 # (9, 4, n)
    # J~ W by forward-mode derivatives of the same equations, 4 directions at once
    JdX = dyn.jvp(X0, Y * D[:, None, :], p, Om)
    K = np.einsum("ijn,ikn->njk", Y, JdX / D[:, None, :])
    K = np.where(ok[:, None, None], K, np.nan)
    scale = np.where(ok, S, np.nan)
    basis = np.moveaxis(Y * D[:, None, :], 2, 0) if want_basis else None      # (n, 9, 4)
    return K, scale, np.where(ok, Om, np.nan), shape, basis, X0


def stability_result(shape, ev, growth, slow, fast, verdict, scale, omega):
    """The per-orbit dict of :func:`wheel_stability` / :func:`sphere_stability`
    from flat arrays (n,) and eigenvalues (n, m), reshaped to ``shape``.

    Beyond the paper: bookkeeping of the stability analysis (docs/stability.md sec. 1).
    """
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
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (theta, alpha, a, r, k, g)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    dyn.body_params(a, r, k, g, outside)          # validation only
    if theta.size == 0:
        return empty_result(theta.shape, 4)
    shape = theta.shape
    flat = [x.reshape(-1) for x in (theta, alpha, a, r, k, g, outside)]
    parts = []
    for i in range(0, theta.size, CHUNK):       # bounded memory; vectorised within
        K, scale, Om, _, _, _ = _wheel_linearisation(*(x[i:i + CHUNK] for x in flat), want_basis=False)
        parts.append((*spectrum_from_invariants(K, scale), scale, Om))
    ev, growth, slow, fast, verdict, scale, Om = (np.concatenate(z) for z in zip(*parts))
    return stability_result(shape, ev, growth, slow, fast, verdict, scale, Om)


def empty_result(shape, m):
    """The dict of :func:`stability_result` for no orbit: NaN, UNKNOWN, m
    eigenvalues each.

    Beyond the paper: bookkeeping of the stability analysis (docs/stability.md sec. 1).
    """
    nan = np.full(shape, np.nan)
    return {"growth_rate": nan, "freq_slow": nan, "freq_fast": nan,
            "verdict": np.full(shape, Verdict.UNKNOWN, dtype=np.int8),
            "rate_scale": nan, "eigenvalues": np.full(shape + (m,), np.nan + 0j),
            "omega": nan}


def sphere_stability(theta, omega, a, r, k, g, outside=False):
    """Exact linear stability of steady horizontal orbits of a rolling sphere.

    Beyond the paper (sec. 4 states the analysis can be completed; sec. 5
    cites Milne for stability outside): as :func:`wheel_stability`, on the
    5-dimensional manifold (centre on the sphere |c| = r -/+ a, angular
    velocity), minus the three neutral directions (phase; d/dtheta at fixed
    Omega; d/dOmega), leaving one nutation pair.  The orbit is given by
    theta [rad] and omega = Omega [rad/s] (the spin omega3 follows from eq. 55; use
    :func:`deathsphere.physics.sphere.orbit_rates` to get Omega from
    omega3).  Returns the dict of :func:`wheel_stability`; the single
    nutation frequency is in ``freq_fast``, ``freq_slow`` is NaN, and
    ``eigenvalues`` has 2 entries.
    """
    theta, omega, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (theta, omega, a, r, k, g)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    dyn.body_params(a, r, k, g, outside, sphere=True)     # validation only
    shape = theta.shape
    if theta.size == 0:
        return empty_result(shape, 2)
    n = theta.size
    th, Om, a, r, k, g, out = (x.reshape(-1) for x in (theta, omega, a, r, k, g, outside))
    ok = np.isfinite(Om) & (Om != 0) & (np.abs(np.sin(th)) > SINGULAR)
    Om_s = np.where(ok, Om, 1.0)
    th_s = np.where(ok, th, np.pi / 2)
    p = dyn.BodyParams(a, r, k, g, out, np.ones(n, dtype=bool))
    X0, _ = dyn.sphere_orbit_state(th_s, Om_s, a, r, k, g, out)
    dth = np.imag(dyn.sphere_orbit_state(th_s + 1j * COMPLEX_STEP, Om_s, a, r, k, g, out)[0]) / COMPLEX_STEP
    dom = np.imag(dyn.sphere_orbit_state(th_s, Om_s + 1j * COMPLEX_STEP, a, r, k, g, out)[0]) / COMPLEX_STEP
    c, w = X0[dyn.C], X0[dyn.W]
    idx = np.r_[0:3, 6:9]
    gen = np.concatenate((zcross(c), zcross(w)))
    S = np.sqrt(dot(w, w) + Om_s ** 2 + g / a)
    D = np.concatenate((np.broadcast_to(a, (3, n)), np.broadcast_to(S, (3, n))))
    V = np.stack((gen, dth[idx], dom[idx]), axis=-1) / D[..., None]       # (6, n, 3)
    nrm = (np.concatenate((c, np.zeros((3, n)))) * D)[..., None]
    A = np.moveaxis(np.concatenate((nrm, V), axis=-1), 0, 1)             # (n, 6, 4)
    A = A / np.linalg.norm(A, axis=1, keepdims=True)
    Wb = orthonormal_complement(A, 6)                                    # (n, 6, 2)
    dX6 = np.moveaxis(Wb, 0, 1) * D[:, :, None]                           # (6, n, 2)
    dX = np.zeros((9, n, 2))
    dX[idx] = dX6
    pc = dyn.BodyParams(*(x[:, None] for x in p))
    JdX = complex_step(lambda x: dyn.rhs(x, pc, Om_s[:, None]), X0[:, :, None], dX)[idx]
    JW = np.moveaxis(JdX / D[:, :, None], 1, 0)
    K = np.einsum("nij,nik->njk", Wb, JW)
    K = np.where(ok[:, None, None], K, np.nan)
    scale = np.where(ok, S, np.nan)
    ev, growth, slow, fast, verdict = spectrum(K, scale)
    return stability_result(shape, ev, growth, slow, fast, verdict, scale, np.where(ok, Om, np.nan))


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
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (theta, alpha, a, r, k, g)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    K, scale, Om, shape, basis, X0 = _wheel_linearisation(theta, alpha, a, r, k, g, outside)
    return {"K": K, "basis": basis, "state": X0, "omega": Om}

