"""A rider's envelope and the clearance of two (beyond the paper;
docs/show.md, "The envelope"): the capsule of radius width/2 about the
segment from the contact point to the head point.  The clearance of two
riders is the distance between their segments less the two radii; where
the capsules overlap it is minus the overlap's depth (docs/show.md,
"The depth of an overlap"): the depth across the axes, R - d, and, where
the axes cross, also along the bodies.  Points are arrays (3, ...) with the coordinates
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


#: Points along each axis at which the overlap across the bodies is
#: integrated (the trapezoid rule: its error is below a millimetre for
#: axes of a rider's length).
AXIS_POINTS = 65


def overlap_along(p0, p1, q0, q1, radii, points: int = AXIS_POINTS):
    """The overlap of two capsules integrated along their axes, per unit of
    the radii [m]: A / radii with A the mean over the two axes of the
    integral along each of max(0, radii - its distance to the other axis)
    (arrays (3, m) for m configurations, ``radii`` (m,)).  R for two axes
    crossing at right angles in their middles, the axes' length for two
    riders in one place, R/2 for a tip on the other's axis; ``points``
    along each axis."""
    s = np.linspace(0.0, 1.0, points)
    total = 0.0
    for (a0, a1), (b0, b1) in (((p0, p1), (q0, q1)), ((q0, q1), (p0, p1))):
        points = a0[:, :, None] + (a1 - a0)[:, :, None] * s
        across = np.maximum(0.0, radii[:, None] - point_segment_distance(points, b0[:, :, None], b1[:, :, None]))
        length = np.sqrt(_dot(a1 - a0, a1 - a0))
        total = total + length * np.trapezoid(across, s, axis=1)
    return 0.5 * total / radii


def overlap_clearance(p0, p1, q0, q1, radii, points: int = AXIS_POINTS):
    """Clearance [m] of two capsules of axes p0-p1 and q0-q1 (arrays (3,
    ...), broadcast) whose radii sum to ``radii`` (broadcast on the rest):
    the axes' distance d less the radii; where they overlap (d < radii),
    minus the overlap's depth: the depth across, radii - d, and the overlap
    integrated along the bodies, :func:`overlap_along` (docs/show.md, "The
    depth of an overlap").  Continuous: 0 at a touch, a graze a little
    below, two riders in one place -(radii + their length).  ``points``:
    the integral's points along each axis."""
    p0, p1, q0, q1 = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (p0, p1, q0, q1)))
    d, _, _ = segment_distance(p0, p1, q0, q1)
    radii = np.broadcast_to(np.asarray(radii, dtype=float), d.shape)
    c = d - radii
    inside = c < 0
    if inside.any():
        c = np.array(c)
        c[inside] -= overlap_along(p0[:, inside], p1[:, inside], q0[:, inside], q1[:, inside], radii[inside],
                                   points)
    return c


#: A single-contact machine's envelope: one segment, from the contact to the head.
CAPSULE = (("contact", "head"),)


def segments_clearance(ends_a, ends_b, radii):
    """Clearance [m] of two envelopes of several segments each, ``ends_a``
    and ``ends_b`` lists of (p0, p1) (3, ...): the least over every pair of
    segments of their capsules' :func:`overlap_clearance` (a two-wheeler's
    envelope, docs/show.md, "Two-wheeler riders").  The distance of two
    unions is the least of their parts' distances; where capsules overlap
    the depth is the deepest pair's.  One segment each: that pair's,
    unchanged."""
    if len(ends_a) == len(ends_b) == 1:
        return overlap_clearance(*ends_a[0], *ends_b[0], radii)
    return np.minimum.reduce([overlap_clearance(p0, p1, q0, q1, radii) for p0, p1 in ends_a for q0, q1 in ends_b])


def clearance(a: dict, b: dict, width_a, width_b, segments_a=CAPSULE, segments_b=CAPSULE):
    """Clearance [m] of two riders' envelopes: ``a`` and ``b`` hold their
    points (3, ...) by name ('contact' and 'head' for a single-contact
    machine), ``segments_a`` and ``segments_b`` the envelope's segments by
    the names of their ends; width/2 is each capsule's radius
    (:func:`segments_clearance`)."""
    return segments_clearance([(a[p], a[q]) for p, q in segments_a], [(b[p], b[q]) for p, q in segments_b],
                              0.5 * (width_a + width_b))
