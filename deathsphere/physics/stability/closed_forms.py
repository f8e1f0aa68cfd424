"""Closed forms of exact stability results (beyond the paper;
docs/stability.md): the nutation frequency of a rolling sphere's horizontal
orbit, and the exact nutation frequencies of the wheel's orbit on the
equator (the corrected eqs. 133-138, erratum E4).  Both agree with the
numerical linearisation of :mod:`~deathsphere.physics.stability.horizontal`
to round-off (tests/physics/test_stability.py).
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.sphere import centre_distance, omega3_from_rate
from deathsphere.physics.stability.frequencies import nutation_from_invariants
from deathsphere.physics.wheel import omega_squared

__all__ = ["sphere_nutation_closed_form", "equator_exact_closed_form"]


def sphere_nutation_closed_form(theta, omega, a, r, k, g, outside=False):
    """Nutation frequency of a sphere's steady horizontal orbit, closed form.

    Beyond the paper (sec. 4 says a complete analysis can be given; this is
    it, docs/stability.md): eq. (46) is a heavy symmetric top with
    I_perp = (k+1) r', spin angular momentum L3 = -k a omega3, m g l = g
    (per unit mass and a).  About steady precession at rate Omega (eq. 55)
    the one nutation mode has, in the turning frame (omega = Omega [rad/s]),

        w^2 = (k a omega3/((k+1) r') + 2 Omega cos(theta))^2 + Omega^2 sin^2(theta) > 0,

    r' = r - a inside, r + a outside, omega3 = w.e3 from eq. (55).  Always
    positive: every horizontal orbit of a rolling sphere is linearly stable,
    inside and outside (as sec. 5 states, citing Milne).  Agrees with
    :func:`sphere_stability` to round-off (tests/physics/test_stability.py).
    Returns w [rad/s].
    """
    theta, omega, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (theta, omega, a, r, k, g)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    omega3 = omega3_from_rate(theta, omega, a, r, k, g, outside)
    b = k * a * omega3 / ((k + 1) * centre_distance(a, r, outside))
    return np.sqrt((b + 2 * omega * np.cos(theta)) ** 2 + (omega * np.sin(theta)) ** 2)


def equator_exact_closed_form(alpha, a, r, k, g):
    """Exact nutation frequencies of the orbit on the equator, closed form.

    Beyond the paper: the correct version of eqs. (133)-(138) (erratum E4,
    docs/stability.md).  Derived symbolically (sympy) from the exact
    equations of motion: the characteristic polynomial of the linearised flow
    in the turning frame is lambda^5 (lambda^4 + e2 lambda^2 + e4), i.e.
    w^4 - e2 w^2 + e4 = 0 for the nutation frequencies w, with
    (u = a/r, c = cos(alpha), Omega^2 from eq. 29):

        e2/Omega^2 = P2 / ((k+1)(2k+1) u^2 c (c - u))
        e4/Omega^4 = P4 / ((k+1)(2k+1) u^2 c^2 (c - u))

        P2 = 2 (2k+1)^2 c^2 - (2k+1) c (2c^2 + 8k + 3) u
             + (2k+1) (-(k+1) c^4 + 4 (k+1) c^2 + 3k + 2) u^2
             + (k+1) c ((k+2) c^2 - (5k+4)) u^3
        P4 = (2k+1)^2 c (6 - 4 c^2)
             + (2k+1) (2 (7k+5) c^4 - 2 (10k+7) c^2 - (2k+1)) u
             + (-2 (8k+5)(k+1) c^5 + 2 (12k+7)(k+1) c^3 + k (2k+1) c) u^2
             + (k+1) c^4 (3 (k+1) c^2 - (5k+4)) u^3

    (c - u = (r cos(alpha) - a)/r > 0 is the fit condition, eq. 0.)  For
    u -> 0: w_fast^2 -> 2 (2k+1)/(k+1) (r/a)^2 Omega^2 and
    w_slow^2 -> (1 + 3 tan^2 alpha) Omega^2 (eq. 207 instead gives
    tan(alpha)(1 + sin 2 alpha) Omega^2).  Stable iff e2 > 0, e4 > 0 and
    e2^2 >= 4 e4.

    Returns dict ``e2`` [1/s^2], ``e4`` [1/s^4], ``omega2`` (2, ...)
    complex [rad^2/s^2], ``stable`` (bool), ``freq_slow``, ``freq_fast``
    [rad/s], ``Omega`` [rad/s].
    """
    alpha, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (alpha, a, r, k, g)))
    om2 = omega_squared(np.pi / 2, alpha, a, r, k, g)
    om2 = np.where(om2 > 0, om2, np.nan)
    u = a / r
    c = np.cos(alpha)
    k1, k2 = k + 1, 2 * k + 1
    P2 = (2 * k2 ** 2 * c ** 2 - k2 * c * (2 * c ** 2 + 8 * k + 3) * u
          + k2 * (-k1 * c ** 4 + 4 * k1 * c ** 2 + 3 * k + 2) * u ** 2
          + k1 * c * ((k + 2) * c ** 2 - (5 * k + 4)) * u ** 3)
    P4 = (k2 ** 2 * c * (6 - 4 * c ** 2)
          + k2 * (2 * (7 * k + 5) * c ** 4 - 2 * (10 * k + 7) * c ** 2 - k2) * u
          + (-2 * (8 * k + 5) * k1 * c ** 5 + 2 * (12 * k + 7) * k1 * c ** 3 + k * k2 * c) * u ** 2
          + k1 * c ** 4 * (3 * k1 * c ** 2 - (5 * k + 4)) * u ** 3)
    den = k1 * k2 * u ** 2 * c * (c - u)
    with np.errstate(divide="ignore", invalid="ignore"):
        e2 = om2 * P2 / den
        e4 = om2 ** 2 * P4 / (den * c)
    x1, x2, stable, slow, fast = nutation_from_invariants(e2, e4)
    return {"e2": e2, "e4": e4, "omega2": np.stack((x1, x2)), "stable": stable,
            "freq_slow": slow, "freq_fast": fast, "Omega": np.sqrt(om2)}
