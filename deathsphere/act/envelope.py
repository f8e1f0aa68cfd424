"""A rider's envelope and the clearance of two (beyond the paper;
docs/show.md, "The envelope"): the capsule of radius width/2 about the
segment from the contact point to the head point.  The clearance of two
riders is the distance between their segments less the two radii
(negative: they overlap).  Points are arrays (3, ...) with the coordinates
on the first axis; everything broadcasts over the rest, with no Python loop."""

from __future__ import annotations

import numpy as np

#: Below this squared length [m^2] a segment is a point (its direction is
#: not defined; the distance then is the point's).
TINY2 = 1e-24


def _dot(u, v):
    return np.einsum("i...,i...->...", u, v) if u.shape == v.shape else np.sum(u * v, axis=0)


def _ratio(num, den, ok):
    """num / den where ok, 0 elsewhere, without a warning."""
    return np.where(ok, num / np.where(ok, den, 1.0), 0.0)


def segment_distance(p0, p1, q0, q1):
    """Least distance [m] between the segments p0-p1 and q0-q1 (arrays (3,
    ...), broadcast), and the parameters (s, t) in [0, 1] of the closest
    points p0 + s (p1 - p0), q0 + t (q1 - q0).

    The closest points of two segments (beyond the paper; the standard
    construction, docs/show.md): the lines' closest points clamped to the
    first segment, then the second's recomputed and clamped, then the first's
    again; parallel or point-like segments have a defined answer."""
    p0, p1, q0, q1 = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (p0, p1, q0, q1)))
    d1, d2, w = p1 - p0, q1 - q0, p0 - q0
    a, e, b = _dot(d1, d1), _dot(d2, d2), _dot(d1, d2)
    c, f = _dot(d1, w), _dot(d2, w)
    has_a, has_e = a > TINY2, e > TINY2
    denom = a * e - b * b
    general = denom > 1e-12 * np.maximum(a * e, TINY2)
    s = np.clip(_ratio(b * f - c * e, denom, general & has_a & has_e), 0.0, 1.0)
    s = np.where(has_a & ~has_e, np.clip(_ratio(-c, a, has_a), 0.0, 1.0), s)
    t = _ratio(b * s + f, e, has_e)
    below, above = t < 0.0, t > 1.0
    t = np.clip(t, 0.0, 1.0)
    s = np.where(below, np.clip(_ratio(-c, a, has_a), 0.0, 1.0), s)
    s = np.where(above, np.clip(_ratio(b - c, a, has_a), 0.0, 1.0), s)
    gap = w + s * d1 - t * d2
    return np.sqrt(_dot(gap, gap)), s, t


def point_segment_distance(x, q0, q1):
    """Least distance [m] from the points x to the segments q0-q1 (arrays
    (3, ...), broadcast): the projection on the segment, clamped to it."""
    x, q0, q1 = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (x, q0, q1)))
    d = q1 - q0
    e = _dot(d, d)
    t = np.clip(_ratio(_dot(x - q0, d), e, e > TINY2), 0.0, 1.0)
    gap = x - q0 - t * d
    return np.sqrt(_dot(gap, gap))


def clearance(a: dict, b: dict, width_a, width_b):
    """Clearance [m] of two riders' envelopes: ``a`` and ``b`` hold their
    'contact' and 'head' points (3, ...); width/2 is each capsule's radius."""
    d, _, _ = segment_distance(a["contact"], a["head"], b["contact"], b["head"])
    return d - 0.5 * (width_a + width_b)
