"""Exact linear stability of a wheel's vertical loop inside a closed
profile by Floquet analysis (beyond the paper; derivation in
docs/stability.md, "2.1 A vertical loop inside a closed profile").

The globe's analysis (:mod:`~deathsphere.physics.stability.floquet`)
integrates the sphere's equations of motion; here the wheel's exact
equations on any ground (:mod:`~deathsphere.physics.dynamics_on`) carry the
loop's state and its tangent vectors together, as dual numbers, over half
a lap with the fixed-step order-8 Runge-Kutta method
(:mod:`~deathsphere.physics.stability.rk8`); the full lap follows by the
loop's reversing symmetry (the mirror x -> -x through the axis with time
reversal, :data:`~deathsphere.physics.stability.floquet.REVERSAL`), as on
the globe.  The quotient is 4-dimensional: a profile has no theta family
(a plane off the axis cuts it in no loop the wheel rolls round).
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics import dynamics_on as don
from deathsphere.physics.stability import rk8
from deathsphere.physics.stability.floquet import FLOQUET_STABLE_TOL, FLOQUET_UNSTABLE_TOL, REVERSAL
from deathsphere.physics.stability.reduction import orthonormal_complement
from deathsphere.physics.stability.verdict import Verdict
from deathsphere.physics.status import Status
from deathsphere.physics.vertical_orbit_on import vertical_loop_on

__all__ = ["LOOP_STEP", "QUOTIENT_DIM", "loop_state_on", "loop_neutral_basis_on", "loop_floquet_on"]

#: the largest rate times the time step of the monodromy's fixed steps
#: (the globe's is 0.25).  Measured against a quarter of it: the
#: multipliers move by <= 3e-7 on a sphere sampled at 2001 points and by
#: <= 5e-5 inside the egg of examples/egg.csv (801 points), where a smaller
#: step does no better: a cubic spline's curvature is only piecewise
#: linear, and a fixed-step method keeps its order only between the knots
#: (docs/stability.md sec. 2.1).  Half the globe's work per lap.
LOOP_STEP = 0.5
#: directions of the quotient: 9 state components less 2 constraint normals
#: and 3 neutral directions (phase, rotation about the axis, the top speed)
QUOTIENT_DIM = 4


def loop_state_on(z_end, speed, a, top=True):
    """The wheel's state (9, n) where its loop meets the axis: at the top
    (``top``; the contact at height ``z_end`` [m] on the axis, the centre a
    [m] below it, moving towards -x at ``speed`` [m/s]) or at the bottom
    (the centre a above the contact, moving towards +x).  The wheel lies in
    the meridian plane y = 0, its axle e1 along +y, rolling: w = (v / a) e1
    (v = a e3 x w with e3 = +z at the top, -z at the bottom).  Beyond the
    paper: docs/stability.md sec. 2.1; on the globe
    :func:`deathsphere.physics.dynamics.vertical_orbit_state` at theta = 90 deg."""
    z_end, speed, a = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (z_end, speed, a)))
    zero = np.zeros_like(a)
    c = np.stack((zero, zero, z_end - a if top else z_end + a))
    return np.concatenate((c, np.stack((zero, zero + 1.0, zero)), np.stack((zero, speed / a, zero))))


def _constraint_normals(X, p, D):
    """The gradients (9, n, 2) of the holonomic constraints at X, scaled as
    covectors (times D): |e1| = 1, (0, e1, 0); the gap F(c + a e3), (grad F,
    -a (grad F . e1) e3, 0) with grad F at the contact (the rim's extremal
    point: moving it along the rim changes F at second order only; turning
    e1 moves it by -(e3 . de1) a e1; on the sphere the globe's
    (p, -a (c . e1) e3, 0))."""
    e3, pt = don.contact_on(X, p)
    G = p.ground.gradient(*pt)
    e1 = X[3:6] / np.sqrt(np.sum(X[3:6] ** 2, axis=0))
    zero = np.zeros_like(e1)
    n1 = np.concatenate((zero, e1, zero))
    n2 = np.concatenate((G, -p.a * np.sum(G * e1, axis=0) * e3, zero))
    return np.stack((n1, n2), axis=-1) * D[..., None]


def loop_neutral_basis_on(X, p, dspeed, D):
    """Orthonormal basis (n, 9, 4) (scaled coordinates) of the complement of
    the loop's five neutral directions at X (its top or its bottom): the two
    constraint normals, phase f(X), rotation about the vertical axis z x X
    (for each of c, e1, w) and ``dspeed``, d X / d v_top of the family
    (9, n).  Beyond the paper: docs/stability.md sec. 2.1."""
    fx = don.rhs_on(X, p)
    gen = np.concatenate([np.stack((-X[i + 1], X[i], np.zeros_like(X[i]))) for i in (0, 3, 6)])
    V = np.stack((fx, gen, dspeed), axis=-1) / D[..., None]
    A = np.moveaxis(np.concatenate((_constraint_normals(X, p, D), V), axis=-1), 0, 1)
    A = A / np.linalg.norm(A, axis=1, keepdims=True)
    return orthonormal_complement(A, 9)


def _rk8(x, d, p, dt, steps):
    """``steps`` (n,) fixed steps dt (n,) of the order-8 method of the state
    x (9, n) and its tangent vectors d (9, m, n), one dual pass a stage
    (:func:`~deathsphere.physics.dynamics_on.rhs_jvp_on`); a loop that has
    taken its own steps waits (a zero step) for the others, so that its
    result does not depend on the loops it is computed with."""
    nst = len(rk8.B)
    for i in range(int(np.max(steps, initial=0))):
        h = np.where(i < steps, dt, 0.0)
        kx, kd = [None] * nst, [None] * nst
        for s, row in enumerate(rk8.A):
            xs, ds = x, d
            for j, a_sj in row:
                xs = xs + (h * a_sj) * kx[j]
                ds = ds + (h * a_sj) * kd[j]
            kx[s], kd[s] = don.rhs_jvp_on(xs, ds, p)
        x = x + h * sum(b * kj for b, kj in zip(rk8.B, kx) if b)
        d = d + h * sum(b * kj for b, kj in zip(rk8.B, kd) if b)
    return x, d


def loop_floquet_on(loop, v_top, a, k, g, step=LOOP_STEP) -> dict:
    """Exact linear stability of the wheel's vertical loops inside ``loop``
    (:class:`~deathsphere.physics.meridian_loop.Loop`) by Floquet analysis.

    Beyond the paper (docs/stability.md sec. 2.1; the globe's sec. 2).  The
    loop of top speed v_top (:func:`~deathsphere.physics.vertical_orbit_on.vertical_loop_on`:
    its status, its bottom speed and its lap time T, eq. S12) is a periodic
    orbit of the wheel's equations on the ground; the monodromy over one
    lap, on the constraint manifold modulo phase, rotation about the axis
    and the top speed, is integrated on the 4 directions of that quotient
    over half a lap (top to bottom) and closed by the reversing symmetry,
    M = G Mh^-1 G Mh, as on the globe.  Four multipliers remain: the
    nutation pair and a pair (mu, 1/mu) of the loop's plane tilting and
    moving off the axis (on a sphere both 1: the globe's theta family and
    its further neutral direction).

    Inputs broadcast: v_top [m/s] the centre's speed at the top, a [m], k
    [-], g [m/s^2].  Vectorised over the loops (one Python loop over the
    time steps).  Returns dict: ``multipliers`` (..., 4) complex;
    ``max_abs`` max |mu|; ``growth_rate`` log(max |mu|) / T [1/s];
    ``period`` T [s]; ``verdict`` int8 :class:`Verdict` (the globe's
    tolerances FLOQUET_STABLE_TOL / FLOQUET_UNSTABLE_TOL on |mu| - 1);
    ``return_error`` [m] |c(T/2) - c_bottom| of the integrated loop against
    its bottom on the axis (the integration's check); ``analysed`` bool.
    Where a loop has no orbit (status neither ok nor slips), k = 0 (the
    equations of motion are singular) or v_top = 0: not analysed, the
    verdict UNKNOWN, the numbers NaN (no warning).
    """
    v_top, a, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (v_top, a, k, g)))
    shape = v_top.shape
    v_top, a, k, g = (x.reshape(-1) for x in (v_top, a, k, g))
    n = v_top.size
    orbit = vertical_loop_on(loop, v_top, a, k, g)
    ok = np.isin(orbit["status"], (Status.OK, Status.SLIPS)) & (k > 0) & (v_top != 0)
    mu = np.full((n, QUOTIENT_DIM), np.nan + 0j)
    ret = np.full(n, np.nan)
    rows = np.flatnonzero(ok)
    if rows.size:
        mu[rows], ret[rows] = _monodromy(loop, np.abs(v_top[rows]), orbit["v_bottom"][rows], orbit["period"][rows],
                                         a[rows], k[rows], g[rows], step)
    finite = ok & np.all(np.isfinite(mu), axis=-1)
    mabs = np.where(finite, np.max(np.abs(np.where(finite[:, None], mu, 1.0)), axis=-1), np.nan)
    T = np.where(finite, orbit["period"], np.nan)
    dev = np.where(finite, mabs - 1.0, np.nan)
    verdict = np.full(n, Verdict.UNKNOWN, dtype=np.int8)
    verdict[np.nan_to_num(dev, nan=np.inf) <= FLOQUET_STABLE_TOL] = Verdict.STABLE
    verdict[np.nan_to_num(dev, nan=-np.inf) >= FLOQUET_UNSTABLE_TOL] = Verdict.UNSTABLE
    growth = np.where(finite, np.log(np.where(finite, mabs, 1.0)) / np.where(finite, T, 1.0), np.nan)
    return {
        "multipliers": np.where(finite[:, None], mu, np.nan).reshape(shape + (QUOTIENT_DIM,)),
        "max_abs": mabs.reshape(shape),
        "growth_rate": growth.reshape(shape),
        "period": T.reshape(shape),
        "verdict": verdict.reshape(shape),
        "return_error": np.where(finite, ret, np.nan).reshape(shape),
        "analysed": finite.reshape(shape),
    }


def _monodromy(loop, v_top, v_bottom, T, a, k, g, step):
    """The multipliers (n, 4) and the return error of loops that exist: the
    half-lap monodromy on the quotient bases at the top and the bottom, the
    full lap by reversibility (floquet.py's M = G Mh^-1 G Mh)."""
    n = v_top.size
    p = don.ground_body(loop.ground, a, k, g)
    top = loop_state_on(loop.z[-1], v_top, a)
    bottom = loop_state_on(loop.z[0], v_bottom, a, top=False)
    # the fastest rate: the spin at the bottom, the centre's turn where its path bends most, the pendulum's
    kappa_c = loop.kappa_max / (1.0 - a * loop.kappa_max)
    S = np.sqrt((v_bottom / a) ** 2 + (v_bottom * kappa_c) ** 2 + g / a)
    N = np.maximum(np.ceil(T * S / (2 * step)), 1.0).astype(int)   # steps per half lap, each loop its own
    D = np.concatenate((np.broadcast_to(a, (3, n)), np.ones((3, n)), np.broadcast_to(S, (3, n))))
    zero = np.zeros((9, n))
    d_top, d_bottom = zero.copy(), zero.copy()
    d_top[7] = 1.0 / a                                          # d w_y / d v_top at the top
    d_bottom[7] = v_top / v_bottom / a                          # and at the bottom, by (S9)
    Wt = loop_neutral_basis_on(top, p, d_top, D)                # (n, 9, 4)
    x, d = _rk8(top, np.transpose(Wt, (1, 2, 0)) * D[:, None, :], p, 0.5 * T / N, N)   # top -> bottom
    ret = np.sqrt(np.sum((x[0:3] - bottom[0:3]) ** 2, axis=0))
    Wb = loop_neutral_basis_on(bottom, p, d_bottom, D)
    Kh = np.einsum("nji,jln->nil", Wb, d / D[:, None, :])     # (n, 4, 4) scaled
    G0 = np.einsum("nji,j,njl->nil", Wt, REVERSAL, Wt)
    Gb = np.einsum("nji,j,njl->nil", Wb, REVERSAL, Wb)
    good = np.all(np.isfinite(Kh), axis=(-2, -1)) & (np.abs(np.linalg.det(np.where(
        np.isfinite(Kh), Kh, 0.0))) > 0)
    Kh = np.where(good[:, None, None], Kh, np.eye(QUOTIENT_DIM))
    K = G0 @ np.linalg.solve(Kh, Gb @ Kh)
    mu = np.linalg.eigvals(K)
    return np.where(good[:, None], mu, np.nan), ret
