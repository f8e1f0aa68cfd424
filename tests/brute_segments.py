"""The least distance of two segments computed the long way, for the
show's tests: an independent check of the envelope's closed-form segment
distance (act/envelope.py)."""

import numpy as np


def brute_distance(p0, p1, q0, q1):
    """Segment distance the long way: the four endpoint-to-segment distances
    and, where both feet fall inside, the distance of the two lines."""
    def point_seg(x, a, b):
        d = b - a
        s = np.clip(np.sum((x - a) * d, axis=0) / np.sum(d * d, axis=0), 0, 1)
        return np.linalg.norm(x - a - s * d, axis=0)

    p0, p1, q0, q1 = np.broadcast_arrays(p0, p1, q0, q1)
    best = np.minimum.reduce([point_seg(p0, q0, q1), point_seg(p1, q0, q1), point_seg(q0, p0, p1),
                              point_seg(q1, p0, p1)])
    u, v, w = p1 - p0, q1 - q0, p0 - q0
    a, b, c, d, e = (np.sum(x * y, axis=0) for x, y in ((u, u), (u, v), (v, v), (u, w), (v, w)))
    den = a * c - b * b
    with np.errstate(divide="ignore", invalid="ignore"):
        s, t = (b * e - c * d) / den, (a * e - b * d) / den
    inside = (s > 0) & (s < 1) & (t > 0) & (t < 1)
    line = np.linalg.norm(w + np.where(inside, s, 0) * u - np.where(inside, t, 0) * v, axis=0)
    return np.where(inside, np.minimum(best, line), best)


def wall_lanes_least_clearance(a, b, t, meridian):
    """The least clearance of two riders' lanes a and b on a wall over the
    times t, from their height and tilt alone: ``meridian(height)`` gives
    the contact's (rho, z, beta) on the wall's own (analytic) meridian; P the
    contact, n = (-sin beta, cos beta) the inward normal, Q = P + t n, H = Q
    + (head - t)(-cos alpha, sin alpha) in the meridian plane at phi = phase
    + rate t; 401 points along a's axis, each one's distance to b's axis by
    projection, less the half widths."""
    import math

    z_hat = np.array([0, 0, 1.0])[:, None]

    def axis(lane, times):
        m, phi = lane.machine, lane.phase + lane.rate * times
        rho_hat = np.stack((np.cos(phi), np.sin(phi), 0 * phi))
        rho, z, beta = (float(x) for x in meridian(lane.height))
        p = rho * rho_hat + z * z_hat
        q = p + m.tyre_radius * (-math.sin(beta) * rho_hat + math.cos(beta) * z_hat)
        u = -math.cos(lane.alpha) * rho_hat + math.sin(lane.alpha) * z_hat
        return p, q + (m.head_height - m.tyre_radius) * u

    best = math.inf
    s = np.linspace(0.0, 1.0, 401)
    for chunk in np.array_split(t, max(1, t.size // 500)):
        (p0, p1), (q0, q1) = axis(a, chunk), axis(b, chunk)
        x = p0[:, :, None] + (p1 - p0)[:, :, None] * s                     # (3, n, 401)
        d = (q1 - q0)[:, :, None]
        w = np.clip(np.sum((x - q0[:, :, None]) * d, axis=0) / np.sum(d * d, axis=0), 0, 1)
        gap = x - q0[:, :, None] - w * d
        best = min(best, float(np.sqrt(np.sum(gap * gap, axis=0)).min()))
    return best - 0.5 * (a.width_m + b.width_m)
