"""The largest ball tangent to a profile at a lane that stays inside it (or
outside it): beyond the paper, docs/surfaces.md eq. S4g.

A ball's nearest point on a surface of revolution lies in the meridian
half-plane through the ball's centre, so a ball tangent to the wall at the
contact P lies inside the solid of revolution exactly when its disc in
P's meridian plane lies inside the meridian region folded about the axis
(the meridian and its mirror image rho -> -rho): when the disc holds no
point Q of the meridian or of its mirror.  The disc of radius r tangent at
P on the side n holds Q when |Q - P|^2 < 2 r (Q - P).n, so the largest
such ball has the radius

    r_P = min over Q with (Q - P).n > 0 of |Q - P|^2 / (2 (Q - P).n)

(the limit Q -> P is the meridian's radius of curvature 1/kappa_m where
kappa_m > 0).  The outside's ball takes -n.  Only the meridian's own
points bound it: above the wall's top (a profile's last sample) nothing
is there to hit.

The table is the meridian at equally spaced spline parameters, with Q on a
finer grid of the same meridian and its mirror; a lane between two table
points takes the smaller of their radii (the callers take a margin off it:
docs/surfaces.md, S4g).
"""

from __future__ import annotations

import numpy as np

__all__ = ["tangent_ball_table", "TABLE_POINTS", "QUERY_POINTS"]

#: Table points P along the meridian, and points Q (each side of the axis).
TABLE_POINTS = 257
QUERY_POINTS = 1025
#: Rows of P per block of the (P, Q) matrix (bounded memory).
_BLOCK = 64


def _radii(p, n, q):
    """r_P each side for each P (m, 2) with normal n (m, 2) against the
    points q (k, 2): the least |Q - P|^2 / (2 |(Q - P).n|) over the q on
    the side n, and over those on the side -n (inf where none is)."""
    d_rho = q[None, :, 0] - p[:, None, 0]
    d_z = q[None, :, 1] - p[:, None, 1]
    along = d_rho * n[:, None, 0] + d_z * n[:, None, 1]
    square = d_rho * d_rho + d_z * d_z
    # P itself and the points on its tangent line bound nothing
    edge = 1e-12 * np.sqrt(square)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = square / (2.0 * np.abs(along))
    inside = np.where(along > edge, ratio, np.inf).min(axis=1)
    outside = np.where(along < -edge, ratio, np.inf).min(axis=1)
    return inside, outside


def tangent_ball_table(point, frame, curvature, s_end):
    """The table of r_P over the meridian: ``(s, r_inside, r_outside)``,
    arrays over :data:`TABLE_POINTS` equally spaced spline parameters s in
    [0, s_end].

    point(s) -> (..., 2) the meridian's (rho, z); frame(s) -> (cos beta,
    sin beta); curvature(s) -> kappa_m (positive bending to the inside
    normal (-sin beta, cos beta)).  Vectorised over blocks of the table.
    Beyond the paper: docs/surfaces.md eq. S4g."""
    s = np.linspace(0.0, s_end, TABLE_POINTS)
    p = point(s)
    cos_b, sin_b = frame(s)
    n = np.stack((-sin_b, cos_b), axis=-1)
    sq = np.linspace(0.0, s_end, QUERY_POINTS)
    mq = point(sq)
    q = np.concatenate((mq, mq * np.array([-1.0, 1.0])))
    kappa = curvature(s)
    with np.errstate(divide="ignore"):
        local_in = np.where(kappa > 0, 1.0 / np.where(kappa > 0, kappa, 1.0), np.inf)
        local_out = np.where(kappa < 0, -1.0 / np.where(kappa < 0, kappa, -1.0), np.inf)
    r_in, r_out = np.empty(s.size), np.empty(s.size)
    for start in range(0, s.size, _BLOCK):           # blocks of the table, not lanes
        rows = slice(start, start + _BLOCK)
        r_in[rows], r_out[rows] = _radii(p[rows], n[rows], q)
    return s, np.minimum(r_in, local_in), np.minimum(r_out, local_out)
