"""The exact stability over the (theta, alpha) plane of horizontal wheel
orbits: a signed margin whose zero is the stability boundary, and that
boundary root-found along alpha (beyond the paper; docs/stability.md sec. 1
and sec. 8 "Stability maps").  Used by ``deathsphere map --stability``.
"""

from __future__ import annotations

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics import region
from deathsphere.physics.stability.horizontal import wheel_reduced_jacobian
from deathsphere.physics.stability.reduction import characteristic_invariants

__all__ = ["STABILITY_ALPHA_STEP_DEG", "stability_margin", "margin_of", "stability_boundary_alphas"]

#: alpha step [deg] of the samples between which the stability boundary is
#: bisected (:func:`stability_boundary_alphas`).
STABILITY_ALPHA_STEP_DEG = 0.25


def stability_margin(theta, alpha, a, r, k, g=STANDARD_GRAVITY, outside=False):
    """Signed stability margin of steady horizontal wheel orbits: > 0 where
    the orbit is linearly stable, < 0 where it is unstable, NaN where no
    orbit exists (beyond the paper; docs/stability.md sec. 1).

    The 4 nutation eigenvalues lambda of the exact reduced Jacobian K
    (:func:`deathsphere.physics.stability.horizontal.wheel_reduced_jacobian`) solve
    lambda^4 + e2 lambda^2 + e4 = 0; the orbit is stable iff both roots
    mu = lambda^2 are real and negative: e2 > 0, e4 > 0 and
    e2^2 - 4 e4 >= 0.  With the similarity-invariant scale
    N^2 = |e2| + 2 sqrt(|e4|) (= (omega_slow + omega_fast)^2 when stable)
    the margin is min(e2 / N^2, e4 / N^4, (e2^2 - 4 e4) / N^4): dimensionless,
    smooth on each branch and crossing zero linearly at a stability
    boundary (where the growth rate rises only like the square root of the
    distance), so its zero set can be contoured and bisected.  Its sign
    agrees with the ``verdict`` of
    :func:`deathsphere.physics.stability.horizontal.wheel_stability` on all 448 999
    status-ok orbits of 0.5 deg grids (a/r = 0.01, 0.1, 0.3, 0.6; k = 1/4,
    1/2; inside and outside; tests check a coarser grid).  Parameters broadcast; angles [rad].  Contact is not
    checked (as in ``wheel_stability``).
    """
    theta, alpha = np.broadcast_arrays(np.asarray(theta, dtype=float), np.asarray(alpha, dtype=float))
    if theta.size == 0:
        return np.empty(theta.shape)
    K = wheel_reduced_jacobian(theta, alpha, a, r, k, g, outside)["K"]
    return margin_of(K).reshape(theta.shape)


def margin_of(K):
    """The signed margin of :func:`stability_margin` from reduced Jacobians
    K (n, 4, 4) of the 4 nutation modes, on the globe or any ground
    (beyond the paper; docs/stability.md sec. 1): (n,), NaN where K is not
    finite (no orbit)."""
    finite = np.all(np.isfinite(K), axis=(-2, -1))
    K = np.where(finite[:, None, None], K, 0.0)
    e2, e4 = characteristic_invariants(K)
    n2 = np.abs(e2) + 2.0 * np.sqrt(np.abs(e4))
    ok = finite & (n2 > 0)
    n2 = np.where(ok, n2, 1.0)
    margin = np.minimum(np.minimum(e2 / n2, e4 / n2 ** 2), (e2 ** 2 - 4.0 * e4) / n2 ** 2)
    return np.where(ok, margin, np.nan)


def stability_boundary_alphas(theta, a, r, k, g=STANDARD_GRAVITY, outside=False, mu=np.inf, max_g=np.inf,
                              alpha_step_deg=STABILITY_ALPHA_STEP_DEG, xtol=1e-10):
    """Tilts alpha [rad] where the stability of feasible orbits changes, at
    each theta [rad] (beyond the paper; docs/stability.md sec. 1 and
    "Stability maps").

    At each theta, alpha is sampled every ``alpha_step_deg`` over the
    interval where the wheel fits (eq. (0) / (81)); the
    samples that are feasible orbits (:func:`region.feasible`, with mu and
    max_g) get the sign of :func:`stability_margin`, and between every two
    neighbouring feasible samples of opposite sign the zero is bisected
    (all brackets at once) to ``xtol`` rad.  Resolution: two crossings less
    than ``alpha_step_deg`` apart, or a crossing less than that from the
    edge of the allowed region, can be missed.

    Returns a float array theta.shape + (m,), sorted, NaN-padded.
    """
    theta = np.asarray(theta, dtype=float)
    t1 = theta.reshape(-1)
    parts = [_stability_crossings(t1[i:i + _THETA_CHUNK], a, r, k, g, outside, mu, max_g, alpha_step_deg, xtol)
             for i in range(0, t1.size, _THETA_CHUNK)]
    m = max((p.shape[1] for p in parts), default=0)
    out = np.full((t1.size, m), np.nan)
    if parts:
        out[:] = np.concatenate([np.pad(p, ((0, 0), (0, m - p.shape[1])), constant_values=np.nan) for p in parts])
    return out.reshape(theta.shape + (m,))


_THETA_CHUNK = 256   # thetas per batch in stability_boundary_alphas (bounds memory)


def _stability_crossings(t1, a, r, k, g, outside, mu, max_g, alpha_step_deg, xtol):
    """:func:`stability_boundary_alphas` for a 1-d batch of thetas."""
    lo, hi = region.fit_interval(t1, a, r, outside)          # the same width at every theta
    h = np.deg2rad(alpha_step_deg)
    width = float(np.max(hi - lo, initial=0.0))
    al = lo[:, None] + (np.arange(int(np.ceil(width / h))) + 0.5) * h     # (n, m)
    th = np.broadcast_to(t1[:, None], al.shape)
    ok = (al < hi[:, None]) & region.feasible(th, al, a, r, k, g, outside=outside, mu=mu, max_g=max_g)
    sign = np.zeros(al.shape)
    sign[ok] = np.sign(stability_margin(th[ok], al[ok], a, r, k, g, outside))
    change = ok[:, :-1] & ok[:, 1:] & (sign[:, :-1] * sign[:, 1:] < 0)
    i, j = np.nonzero(change)
    left, right = al[i, j], al[i, j + 1]
    s_left = sign[i, j]
    while left.size and np.max(right - left) > xtol:
        mid = 0.5 * (left + right)
        same = np.sign(stability_margin(t1[i], mid, a, r, k, g, outside)) == s_left
        left, right = np.where(same, mid, left), np.where(same, right, mid)
    out = np.full((t1.size, int(np.max(np.sum(change, axis=1), initial=0))), np.nan)
    out[i, np.cumsum(change, axis=1)[i, j] - 1] = 0.5 * (left + right)
    return out
