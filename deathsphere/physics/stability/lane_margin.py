"""The exact stability over a lane map's (height, alpha) plane of a wheel's
horizontal orbits on any ground: the globe's signed margin from the exact
reduced Jacobian on that ground, and its zero root-found along alpha on
each lane (beyond the paper; docs/stability.md, "On any ground" and
"Stability maps").  Used by ``deathsphere map --surface ... --stability``.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.lane_region import _lane, feasible_on, fit_window
from deathsphere.physics.stability.margin import STABILITY_ALPHA_STEP_DEG, margin_of
from deathsphere.physics.stability.on_ground import wheel_reduced_jacobian_on

__all__ = ["stability_margin_on", "stability_boundary_alphas_on", "lane_batches", "stability_crossings_on",
           "joined_crossings", "LANE_CHUNK"]

#: Lanes per batch of :func:`stability_boundary_alphas_on` (bounds memory:
#: each lane holds up to 720 alpha samples of a 9 x 9 flow); also the unit
#: of work ``map --surface ... --stability --jobs N`` hands a process.
LANE_CHUNK = 16


def stability_margin_on(ground, height, alpha, a, k, g, outside=False):
    """Signed stability margin of a wheel's steady orbits at lane ``height``
    [m] and tilt ``alpha`` [rad] on ``ground`` (broadcast): > 0 stable,
    < 0 unstable, NaN where no orbit exists; the globe's margin
    (:func:`deathsphere.physics.stability.margin.stability_margin`, whose
    sign is the verdict of the 4 nutation eigenvalues) of the reduced
    Jacobian of :func:`deathsphere.physics.stability.on_ground.wheel_stability_on`
    (beyond the paper).  Contact is not checked."""
    height, alpha = np.broadcast_arrays(np.asarray(height, dtype=float), np.asarray(alpha, dtype=float))
    if height.size == 0:
        return np.empty(height.shape)
    K = wheel_reduced_jacobian_on(ground, height, alpha, a, k, g, outside)["K"]
    return margin_of(K).reshape(height.shape)


def stability_boundary_alphas_on(ground, height, a, k, g, outside=False, mu=np.inf, max_g=np.inf,
                                 alpha_step_deg=STABILITY_ALPHA_STEP_DEG, xtol=1e-10):
    """Tilts alpha [rad] where the stability of feasible orbits changes on
    each lane ``height`` [m] of ``ground`` (beyond the paper), as the
    globe's :func:`~deathsphere.physics.stability.margin.stability_boundary_alphas`:
    alpha sampled every ``alpha_step_deg`` over the lane's fit window (S4),
    the feasible samples (:func:`deathsphere.physics.lane_region.feasible_on`,
    with mu and max_g: ``orbit --surface``'s status ok) signed by
    :func:`stability_margin_on`, and every change of sign between
    neighbouring feasible samples bisected (all brackets at once) to
    ``xtol`` rad.  Two crossings closer than the step, or one closer than
    that to the allowed region's edge, can be missed.

    Returns (n, m) for the n lanes, sorted, NaN-padded."""
    h1 = np.asarray(height, dtype=float).reshape(-1)
    return joined_crossings([stability_crossings_on(ground, batch, a, k, g, outside, mu, max_g, alpha_step_deg, xtol)
                             for batch in lane_batches(h1)], h1.size)


def lane_batches(height) -> list:
    """The lanes ``height`` [m] cut into the batches of LANE_CHUNK lanes
    that :func:`stability_boundary_alphas_on` evaluates one call each (every
    alpha sample of a batch at once; beyond the paper, docs/limits.md sec. 8): the pieces a caller may evaluate on
    other processes and join with :func:`joined_crossings`, to the same
    values (a lane's crossings depend only on that lane)."""
    h1 = np.asarray(height, dtype=float).reshape(-1)
    return [h1[i:i + LANE_CHUNK] for i in range(0, h1.size, LANE_CHUNK)]


def joined_crossings(parts, n: int) -> np.ndarray:
    """The crossings of consecutive batches of lanes (each (n_i, m_i) from
    :func:`stability_crossings_on`) as one (n, m) array, each batch padded
    with NaN to the widest (beyond the paper, docs/limits.md sec. 8)."""
    m = max((p.shape[1] for p in parts), default=0)
    out = np.full((n, m), np.nan)
    if parts:
        out[:] = np.concatenate([np.pad(p, ((0, 0), (0, m - p.shape[1])), constant_values=np.nan) for p in parts])
    return out


def stability_crossings_on(ground, h1, a, k, g, outside=False, mu=np.inf, max_g=np.inf,
                           alpha_step_deg=STABILITY_ALPHA_STEP_DEG, xtol=1e-10):
    """:func:`stability_boundary_alphas_on` for one batch of lanes ``h1``
    [m] (1-d; beyond the paper, docs/stability.md "Stability maps"): (n, m)
    sorted, NaN-padded to this batch's most crossings."""
    h1 = np.asarray(h1, dtype=float).reshape(-1)
    lo, hi = fit_window(_lane(ground, h1), a, outside)
    fits = np.isfinite(lo) & np.isfinite(hi)
    lo, hi = np.where(fits, lo, 0.0), np.where(fits, hi, 0.0)
    step = np.deg2rad(alpha_step_deg)
    width = float(np.max(hi - lo, initial=0.0))
    al = lo[:, None] + (np.arange(int(np.ceil(width / step))) + 0.5) * step          # (n, m)
    hh = np.broadcast_to(h1[:, None], al.shape)
    ok = fits[:, None] & (al < hi[:, None])
    ok[ok] = feasible_on(ground, hh[ok], al[ok], a, k, g, outside, mu, max_g)
    sign = np.zeros(al.shape)
    sign[ok] = np.sign(stability_margin_on(ground, hh[ok], al[ok], a, k, g, outside))
    change = ok[:, :-1] & ok[:, 1:] & (sign[:, :-1] * sign[:, 1:] < 0)
    i, j = np.nonzero(change)
    left, right, s_left = al[i, j], al[i, j + 1], sign[i, j]
    while left.size and np.max(right - left) > xtol:
        mid = 0.5 * (left + right)
        same = np.sign(stability_margin_on(ground, h1[i], mid, a, k, g, outside)) == s_left
        left, right = np.where(same, mid, left), np.where(same, right, mid)
    out = np.full((h1.size, int(np.max(np.sum(change, axis=1), initial=0))), np.nan)
    out[i, np.cumsum(change, axis=1)[i, j] - 1] = 0.5 * (left + right)
    return out
