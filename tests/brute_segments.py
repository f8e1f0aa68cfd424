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
