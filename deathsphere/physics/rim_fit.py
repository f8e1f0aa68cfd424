"""The wheel's rim and the ball checked against the whole wall of a profile.

Beyond the paper (docs/surfaces.md, eq. S4g).  On the sphere, the drum and
the cone the local fits S4 (the wheel) and S7 (the ball) are the whole fit
(proved there); on a profile the wall can come back to meet the body away
from its contact (a neck, a bump, the far side of a narrow bowl).  Three
stages, vectorised over lanes:

1. the **tangent ball**: the largest ball r_P tangent at the contact that
   stays inside the wall (``ground.tangent_ball_radius``).  The rim lies in
   that ball when a <= r_P sin(alpha + beta) (the wheel's plane cuts it in
   a circle of radius r_P sin(alpha + beta) through the contact), the ball
   when a <= r_P.  A lane accepted so, with a margin of
   :data:`BALL_MARGIN` off r_P for the table's spacing, fits;
2. inside, the **tangent cone**: where the wall bends outwards over the
   rim's heights it holds what its tangent cone holds, and the cone holds
   the rim by S4 (``ground.bends_out``; in :mod:`deathsphere.physics.revolution`);
3. the rest are **certified by sampling**: the rim point at angle s from
   the contact, X(s) = P + a (1 - cos s) u + a sin s e_phi, has the
   clearance c(s) = clearance(|X_xy|, X_z), a signed distance and so
   a-Lipschitz in s (|dX/ds| = a); a point above the wall's top (or below
   its lowest point) has nothing to hit, so the margin is
   m(s) = max(c(s), z(s) - z_top, z_low - z(s)), a-Lipschitz too.  On an
   interval [s1, s2] m >= (m1 + m2)/2 - a (s2 - s1)/2, and where the
   interval is on the wall's heights m >= c >= min(c1, c2) - L (s2 - s1)^2
   / 8, L bounding -c'' by the rim's curvature and the wall's
   (``ground.bend_bound()``); intervals neither bound decides are halved,
   all lanes' together, until one does or the half-width is under the
   tolerance.  Outside, the wheel's disc
   meets the solid exactly when its diameter through the contact does (a
   point of the solid in the disc has its foot on that diameter, at its
   height and nearer the axis, in the solid too), so the diameter's point
   P + a (1 - cos s) u is sampled instead, a-Lipschitz in s as well.  The
   ball's disc is decided by its centre's distance from the meridian and
   from its mirror.
"""

from __future__ import annotations

import numpy as np

__all__ = ["rim_crosses_wall", "ball_crosses_wall", "BALL_MARGIN", "NEAR_CONTACT", "TOLERANCE", "GRID"]

#: The fraction taken off the table's tangent ball before it accepts a lane.
BALL_MARGIN = 0.02
#: The arc |s| < NEAR_CONTACT [rad] of the rim about the contact is S4's:
#: there the clearance is (a s^2 / 2)(sin(alpha + beta) - a kappa_parallel)
#: to second order.
NEAR_CONTACT = 0.125
#: The depth [in units of a] a rim point may lie outside the wall and still
#: be called inside (and the least depth that is called outside).
TOLERANCE = 1e-8
#: Intervals of the first grid on s in [NEAR_CONTACT, pi] (the rim is
#: symmetric about the contact's meridian plane: s and -s have one image).
GRID = 16


def _rim_margin(ground, rho0, z0, cos_a, sin_a, a, side, s):
    """m(s) at the rim angles s (rows of lanes): side * clearance of the
    rim point (outside: of its foot on the diameter through the contact,
    y = 0), or its height past the wall's ends where that is larger."""
    w = 1.0 - np.cos(s)
    x = rho0 - a * w * cos_a
    y = np.where(side > 0, a * np.sin(s), 0.0)
    z = z0 + a * w * sin_a
    c = side * ground.clearance(np.hypot(x, y), z)
    z_low = ground.lowest
    z_top = z_low + ground.highest_lane
    # where the point is on the wall's heights the margin is c itself (for
    # the bound on c'' below), else nothing there to hit past the wall's ends
    on_wall = (z >= z_low) & (z <= z_top)
    return np.maximum(c, np.maximum(z - z_top, z_low - z)), np.where(on_wall, c, np.nan)


def _lower_bound(m1, m2, c1, c2, half, a, bend):
    """The least the margin can be on an interval of half-width ``half``
    with these ends: the Lipschitz bound (m1 + m2)/2 - a half, and, where
    both ends are on the wall's heights (so the whole interval is: z is
    monotone in s on [0, pi]) and the bend bound applies, min(c1, c2) -
    bend half^2 / 2 (the margin is at least the clearance c, and c'' >=
    -bend)."""
    lipschitz = 0.5 * (m1 + m2) - a * half
    with np.errstate(invalid="ignore"):
        quadratic = np.where(np.isfinite(c1) & np.isfinite(c2) & np.isfinite(bend),
                             np.minimum(c1, c2) - 0.5 * bend * half * half, -np.inf)
    return np.maximum(lipschitz, quadratic)


def rim_crosses_wall(ground, rho0, z0, alpha, a, outside):
    """Whether the wheel's rim (radius a [m], tilt alpha [rad], its contact
    at (rho0, z0) [m] on ``ground``) leaves the wall away from its contact,
    for lanes that pass S4 (docs/surfaces.md eq. S4g, sampling and the
    Lipschitz bound; 1-d arrays of one length, a bool array back).  True:
    a rim point lies more than TOLERANCE a outside; False: no rim point
    with |s| >= NEAR_CONTACT lies more than 2 TOLERANCE a outside.
    ``outside``: the wheel on the convex side, whose disc is checked by its
    diameter through the contact (in the solid instead of outside it)."""
    rho0, z0, alpha, a = (np.asarray(x, dtype=float) for x in (rho0, z0, alpha, a))
    side = np.where(np.asarray(outside, dtype=bool), -1.0, 1.0)
    n = rho0.size
    crosses = np.zeros(n, dtype=bool)
    if n == 0:
        return crosses
    cos_a, sin_a = np.cos(alpha), np.sin(alpha)
    s = np.linspace(NEAR_CONTACT, np.pi, GRID + 1)[None, :]
    col = (rho0[:, None], z0[:, None], cos_a[:, None], sin_a[:, None], a[:, None], side[:, None])
    m, c = _rim_margin(ground, *col, s)
    tol = TOLERANCE * a
    crosses |= np.any(m < -tol[:, None], axis=1)
    # c'' >= -(a + a^2 K / (1 - d K)) along the rim: its acceleration is a,
    # and the clearance's second derivative along a unit direction is at
    # least -K / (1 - d K) at a distance d < 1/K from a wall whose principal
    # curvatures are at most K (d <= 2.2 a on an interval of half-width
    # 0.1 about a rim point within 2 a of the contact); inf: no bound
    k_max = ground.bend_bound()
    reach = 2.2 * a * k_max
    bend = np.where(reach < 0.9, a + a * a * k_max / np.maximum(1.0 - reach, 0.1), np.inf)
    # the undecided intervals: (lane, s1, s2, m1, m2, c1, c2)
    half = 0.5 * (s[0, 1] - s[0, 0])
    lower = _lower_bound(m[:, :-1], m[:, 1:], c[:, :-1], c[:, 1:], half, a[:, None], bend[:, None])
    lane, j = np.nonzero((lower < -tol[:, None]) & ~crosses[:, None])
    s1, s2 = s[0, j], s[0, j + 1]
    m1, m2, c1, c2 = m[lane, j], m[lane, j + 1], c[lane, j], c[lane, j + 1]
    while lane.size and half > TOLERANCE:
        mid = 0.5 * (s1 + s2)
        mm, cm = _rim_margin(ground, rho0[lane], z0[lane], cos_a[lane], sin_a[lane], a[lane], side[lane], mid)
        crosses[lane[mm < -tol[lane]]] = True
        half *= 0.5
        lane, s1, s2, m1, m2, c1, c2 = (np.concatenate((v, v)) for v in (lane, s1, s2, m1, m2, c1, c2))
        k = mid.size
        mid2, mm2, cm2 = np.concatenate((mid, mid)), np.concatenate((mm, mm)), np.concatenate((cm, cm))
        s2[:k], m2[:k], c2[:k] = mid2[:k], mm2[:k], cm2[:k]            # [s1, mid]
        s1[k:], m1[k:], c1[k:] = mid2[k:], mm2[k:], cm2[k:]            # [mid, s2]
        lower = _lower_bound(m1, m2, c1, c2, half, a[lane], bend[lane])
        keep = (lower < -tol[lane]) & ~crosses[lane]
        lane, s1, s2, m1, m2, c1, c2 = (v[keep] for v in (lane, s1, s2, m1, m2, c1, c2))
    return crosses


def ball_crosses_wall(ground, rho0, z0, sin_beta, cos_beta, a, outside):
    """Whether the ball (radius a [m], touching the wall of ``ground`` at
    (rho0, z0) with wall angle beta, its centre a along the normal on its
    side) reaches the wall away from its contact: its centre nearer than
    a (1 - TOLERANCE) to the meridian or to the meridian's mirror through
    the axis (docs/surfaces.md eq. S7g; a ball's nearest point on a surface
    of revolution is in the meridian half-plane of its centre)."""
    rho0, z0, sin_beta, cos_beta, a = (np.asarray(x, dtype=float) for x in (rho0, z0, sin_beta, cos_beta, a))
    side = np.where(np.asarray(outside, dtype=bool), -1.0, 1.0)
    rho_c = rho0 - side * a * sin_beta
    z_c = z0 + side * a * cos_beta
    near = a * (1.0 - TOLERANCE)
    own = np.abs(ground.clearance(rho_c, z_c)) < near
    mirror = np.abs(ground.clearance(-rho_c, z_c)) < near
    return own | mirror
