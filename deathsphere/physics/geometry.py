"""Where a wheel can sit on the sphere: fit conditions and the orbit radius r'.

Symbols (McDonald 1993, sec. 2.1): theta is the polar angle of the contact
point from the upward vertical through the sphere's centre; alpha is the tilt
of the wheel's diameter through the contact point (axis 3) below the orbit
plane; a and r are the wheel and sphere radii; r' is the distance of the
wheel's centre from the orbit axis.
"""

import numpy as np

#: |sin|, |cos| or a denominator below this (relative) is treated as an exact
#: zero: angles given in degrees land on multiples of 90 deg only up to
#: round-off (sin(pi) = 1.2e-16), and a physical orbit never needs more.
SINGULAR = 1e-12


def r_prime(theta, alpha, a, r):
    """Distance r' of the wheel's centre from the orbit axis, eq. (8b).

    .. math:: r' = r \\sin\\theta - a \\cos\\alpha

    Holds inside and outside (sec. 3).  r' < 0 means the centre is across the
    axis from the contact point (possible near the poles).  A vertical orbit
    is alpha = 0 inside, alpha = pi outside: r' = r sin(theta) -/+ a.
    Complex theta / alpha accepted (complex step).
    """
    return r_prime_from_trig(np.sin(theta), np.cos(alpha), a, r)


def r_prime_from_trig(sin_theta, cos_alpha, a, r):
    """:func:`r_prime`, eq. (8b), from sin(theta) and cos(alpha) already
    computed (the steady-orbit kernels evaluate each once per orbit)."""
    return r * sin_theta - a * cos_alpha


def fits_inside(theta, alpha, a, r):
    """True where a wheel tilted by alpha fits inside the sphere, eq. (0).

    Eq. (0), theta - pi + asin(a/r) < alpha < theta - asin(a/r), is the
    statement that the plane of the wheel cuts the sphere in a circle of
    radius r |sin(theta - alpha)| on which the wheel sits internally tangent
    at the contact point; in the form used here it holds for any branch of
    alpha:  sin(theta - alpha) > a/r  (derivation in docs/derivations.md).
    """
    return np.sin(theta - alpha) > a / r


def fits_outside(theta, alpha):
    """True where a wheel tilted by alpha lies outside the sphere, eq. (81).

    Eq. (81), theta < alpha < pi + theta, i.e. sin(alpha - theta) > 0: axis 3
    (wheel centre to contact point) must point into the sphere.  The wheel's
    size does not enter: circles tangent externally never overlap.
    """
    return np.sin(alpha - theta) > 0.0


def too_big_inside(a, r, outside=False):
    """True where a body of radius a cannot be inside a sphere of radius r
    (r <= a): the one statement of "r > a inside" that every check uses."""
    return ~np.asarray(outside, dtype=bool) & (np.asarray(r) <= np.asarray(a))
