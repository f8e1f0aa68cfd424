"""Steady horizontal orbits of a wheel rolling on a fixed sphere.

McDonald (1993) sec. 2.2.2, eqs. (13), (29)-(36); sec. 3, eqs. (81), (83)
for the wheel outside.  All functions take broadcastable arrays: theta and
alpha in radians, a and r in m, k dimensionless (I11 = 2 k m a^2), g in m/s^2.

The private helpers (``_omega_squared`` ...) are the same formulas taking
sin and cos already computed: :func:`horizontal_orbit` evaluates sin(theta),
cos(theta), sin(alpha), cos(alpha) once per orbit, plus sin(theta - alpha)
for the fit; these five transcendental functions are half of its cost
(measured in benchmarks/README.md).
"""

import math

import numpy as np

from deathsphere.physics.geometry import (
    SINGULAR,
    fits_inside,
    fits_outside,
    r_prime_from_trig,
)
from deathsphere.physics.status import Reason, Status, first_failure, mu_required

#: horizontal_orbit evaluates larger inputs in pieces of this many orbits:
#: small enough for its temporaries to be recycled through the CPU caches,
#: large enough that its ~100 numpy calls per piece cost little per orbit
#: (benchmarks/README.md).  Also the chunk size of ``deathsphere sweep``.
CHUNK = 1 << 14


def _denominator(rp, sin_alpha, cos_alpha, a, k):
    """See :func:`omega_squared_denominator`."""
    return sin_alpha * ((2 * k + 1) * rp + k * a * cos_alpha)


def _omega_squared(rp, sin_alpha, cos_alpha, a, r, k, g):
    """Eq. (29) from r', sin(alpha), cos(alpha); see :func:`omega_squared`."""
    den = _denominator(rp, sin_alpha, cos_alpha, a, k)
    singular = np.abs(den) <= SINGULAR * ((2 * k + 1) * r + (k + 1) * a)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(singular, np.nan, g * cos_alpha / np.where(singular, 1.0, den))


def _contact_force_spherical(sin_theta, cos_theta, rp, omega2, g):
    """Eq. (32) from sin(theta), cos(theta); see :func:`contact_force_spherical`."""
    centripetal = rp * omega2
    return (-(centripetal * sin_theta - g * cos_theta),
            -(centripetal * cos_theta + g * sin_theta))


def _pick(condition, if_true, if_false):
    """Code ``if_true`` where ``condition`` else ``if_false``: a plain int
    when the condition is a bool (one side for the whole batch), else int8
    arithmetic on the 0/1 bytes of the mask (branch-free, no int64 array)."""
    if isinstance(condition, bool):
        return int(if_true if condition else if_false)
    flag = np.asarray(condition).view(np.int8)
    return np.int8(if_false) + flag * np.int8(if_true - if_false)


def _uniform(x):
    """The value of a 0-d array, or the common value of an array whose
    entries are all equal (the usual case: the model passes a, r, k, g, mu
    and the side per row, and horizontal_orbit checks each piece): then
    arithmetic with it is scalar-times-array, not array-times-array.
    Otherwise the array itself."""
    if x.ndim == 0 or (x.size and (x == x.flat[0]).all()):
        return x.dtype.type(x.flat[0]) if x.dtype != bool else bool(x.flat[0])
    return x


def omega_squared_denominator(theta, alpha, a, r, k):
    """sin(alpha) [(2k+1) r' + k a cos(alpha)], the denominator of eq. (29)
    written with cot(alpha) = cos(alpha)/sin(alpha)."""
    cos_alpha = np.cos(alpha)
    return _denominator(r_prime_from_trig(np.sin(theta), cos_alpha, a, r), np.sin(alpha), cos_alpha, a, k)


def omega_squared(theta, alpha, a, r, k, g):
    """Square of the orbital rate Omega of a steady horizontal orbit, eq. (29).

    .. math:: \\Omega^2 = \\frac{g \\cot\\alpha}{(2k+1) r' + k a \\cos\\alpha}
                        = \\frac{g \\cot\\alpha}{(2k+1) r\\sin\\theta - (k+1) a\\cos\\alpha}

    Same formula inside and outside the sphere (sec. 3).  Where the
    denominator vanishes (alpha = 0 or 180 deg, or (2k+1) r' = -k a cos(alpha))
    Omega^2 is undefined and NaN is returned; :func:`horizontal_orbit` turns
    that into status ``no_orbit`` with its reason.  Checked against the
    angular-momentum balance eq. (24) with beta = 0 in tests/physics.
    """
    cos_alpha = np.cos(alpha)
    rp = r_prime_from_trig(np.sin(theta), cos_alpha, a, r)
    return _omega_squared(rp, np.sin(alpha), cos_alpha, a, r, k, g)


def contact_force_spherical(theta, r_prime_, omega2, g):
    """Contact force per unit mass in the sphere's (r, theta) basis, eq. (32).

    .. math:: F/m = -(r'\\Omega^2\\sin\\theta - g\\cos\\theta)\\,\\hat r
                    -(r'\\Omega^2\\cos\\theta + g\\sin\\theta)\\,\\hat\\theta
                  = -r'\\Omega^2 \\hat r' + g \\hat z

    r-hat points out of the sphere's centre, theta-hat towards increasing
    theta (down the wall).  Returns ``(F_r, F_theta)``.
    """
    return _contact_force_spherical(np.sin(theta), np.cos(theta), r_prime_, omega2, g)


def contact_force_body(alpha, r_prime_, omega2, g):
    """Contact force per unit mass in the wheel's (1, 3) axes, eq. (30).

    .. math:: F/m = (-g\\cos\\alpha + r'\\Omega^2\\sin\\alpha)\\,\\hat 1
                    -(g\\sin\\alpha + r'\\Omega^2\\cos\\alpha)\\,\\hat 3

    Returns ``(F_1, F_3)``; F_2 = 0 on a steady horizontal orbit.
    """
    sin_alpha, cos_alpha = np.sin(alpha), np.cos(alpha)
    centripetal = r_prime_ * omega2
    return (-g * cos_alpha + centripetal * sin_alpha,
            -(g * sin_alpha + centripetal * cos_alpha))


def friction_coefficient(normal, friction):
    """Least static friction coefficient that holds the contact, eq. (35):
    mu = |F_parallel| / F_perp.  NaN where the normal force is not positive
    (no contact: mu is undefined there).  The rule of every body:
    :func:`deathsphere.physics.status.mu_required`."""
    return mu_required(normal, friction)


def _orbit(theta, alpha, a, r, k, g, outside, mu):
    """horizontal_orbit on arrays of one shape (theta, alpha) and scalars or
    arrays broadcasting to it; ``outside`` is a bool when the side is common."""
    sin_theta, cos_theta = np.sin(theta), np.cos(theta)
    sin_alpha, cos_alpha = np.sin(alpha), np.cos(alpha)
    rp = r_prime_from_trig(sin_theta, cos_alpha, a, r)                               # eq. (8b)
    if isinstance(outside, bool):                                           # eq. (81) / (0)
        fits = fits_outside(theta, alpha) if outside else fits_inside(theta, alpha, a, r)
    else:
        fits = np.where(outside, fits_outside(theta, alpha), fits_inside(theta, alpha, a, r))
    om2 = _omega_squared(rp, sin_alpha, cos_alpha, a, r, k, g)              # eq. (29)
    undefined = np.isnan(om2)
    om2_zero = np.abs(om2) <= SINGULAR * g / r                              # False where NaN
    real = (om2 > 0) & ~om2_zero
    om2_real = np.where(real, om2, np.nan)     # NaN propagates to every derived quantity
    with np.errstate(divide="ignore", invalid="ignore"):
        omega = np.sqrt(om2_real)
        period = 2 * np.pi / omega
    f_r, f_theta = _contact_force_spherical(sin_theta, cos_theta, rp, om2_real, g)  # eq. (32)
    if isinstance(outside, bool):                                           # eq. (83) / (33)
        normal = f_r if outside else -f_r
    else:
        normal = np.where(outside, f_r, -f_r)
    mu_req = friction_coefficient(normal, f_theta)                          # eq. (35)

    status, reason = first_failure([
        (~fits, Status.NO_FIT, _pick(outside, Reason.NO_FIT_OUTSIDE, Reason.NO_FIT_INSIDE)),
        (undefined, Status.NO_ORBIT, _pick(np.abs(sin_alpha) <= SINGULAR,
                                           Reason.ALPHA_IN_ORBIT_PLANE, Reason.ZERO_DENOMINATOR)),
        (om2_zero, Status.NO_ORBIT, Reason.OMEGA_ZERO),
        (~real, Status.NO_ORBIT, Reason.OMEGA_IMAGINARY),
        (~(normal > 0), Status.NO_CONTACT, _pick(outside, Reason.NO_CONTACT_OUTSIDE, Reason.NO_CONTACT_INSIDE)),
        (mu_req > mu, Status.SLIPS, Reason.SLIPS),
    ])
    abs_rp = np.abs(rp)
    accel = abs_rp * om2_real                                               # eq. (36) times g
    return {
        "r_prime": rp,
        "omega2": om2,
        "omega": omega,
        "period": period,
        "v_cm": abs_rp * omega,
        "spin": rp * omega / a,                                             # eq. (13)
        "omega3": -omega * sin_alpha,
        "accel": accel,
        "accel_g": accel / g,
        # what the rider feels, |a - g| / g (a horizontal, g vertical: eq. 32)
        "load_g": np.sqrt(accel * accel + g * g) / g,
        "normal": normal,                       # NaN where not real, via om2_real
        "friction": f_theta,
        "mu_required": mu_req,
        "status": status,
        "reason": reason,
    }


def horizontal_orbit(theta, alpha, a, r, k, g, outside=False, mu=np.inf):
    """Every quantity of a steady horizontal orbit of a wheel, vectorised.

    McDonald (1993) eqs. (0)/(81) fit, (8b) r', (29) Omega^2, (13) spin
    omega_1 = r' Omega / a, (32) contact force, (33)/(83) contact, (35) mu,
    (36) acceleration in g.

    Parameters
    ----------
    theta, alpha : array_like, [rad]
    a, r : array_like, [m]   wheel and sphere radii
    k : array_like, [-]      inertia factor, I11 = 2 k m a^2
    g : array_like, [m/s^2]
    outside : array_like of bool   wheel on the outside of the sphere (sec. 3)
    mu : array_like, [-]     friction coefficient available (inf: unlimited)

    Returns
    -------
    dict of float64 arrays (all broadcast to one shape):
    ``r_prime, omega2, omega, period, v_cm, spin, omega3, accel, accel_g,
    load_g, normal, friction, mu_required`` and int8 ``status``, ``reason`` (codes of
    :mod:`deathsphere.physics.status`).  Quantities that are undefined for an
    orbit are NaN there and its status is not OK; an OK row is all finite.

    Notes
    -----
    ``omega3`` is the spin about the contact normal axis 3, -Omega sin(alpha)
    (eq. 13).  ``v_cm`` and ``accel`` are magnitudes, |r'| Omega and |r'| Omega^2;
    ``spin`` keeps the sign of eq. (13) (negative when r' < 0).  ``normal``
    is the component of F/m pressing body and sphere together (-F_r inside,
    +F_r outside); ``friction`` is F_theta/m, positive down the wall.
    ``accel_g`` is eq. (36), the centre's acceleration in g; ``load_g`` is
    what the rider feels, |F| / (m g) = |a - g| / g = sqrt(1 + accel_g^2)
    (eq. 32's two components are orthogonal; beyond the paper, which names
    no load).

    Inputs of more than :data:`CHUNK` orbits are evaluated in pieces of that
    size: the same results, 2-3x faster than one pass over large arrays.
    """
    theta, alpha, a, r, k, g, mu = (np.asarray(x, dtype=float) for x in (theta, alpha, a, r, k, g, mu))
    outside = np.asarray(outside, dtype=bool)
    params = (a, r, k, g, outside, mu)
    shape = np.broadcast_shapes(theta.shape, alpha.shape, *(x.shape for x in params))
    size = math.prod(shape)
    if size <= CHUNK:
        res = _orbit(np.broadcast_to(theta, shape), np.broadcast_to(alpha, shape), *map(_uniform, params))
        if not shape:  # scalar input: each key a numpy scalar or 0-d array, as before
            for key in ("normal", "mu_required"):
                res[key] = np.asarray(res[key])
        return res
    angles = [np.broadcast_to(x, shape).reshape(-1) for x in (theta, alpha)]
    params = [_uniform(x) if x.size == 1 else np.broadcast_to(x, shape).reshape(-1) for x in params]
    out = {}
    for start in range(0, size, CHUNK):
        piece = slice(start, start + CHUNK)
        res = _orbit(*(x[piece] for x in angles),
                     *(_uniform(x[piece]) if isinstance(x, np.ndarray) else x for x in params))
        for key, value in res.items():
            if key not in out:
                out[key] = np.empty(size, dtype=value.dtype)
            out[key][piece] = value
    return {key: value.reshape(shape) for key, value in out.items()}


def centre_accel_g(theta, alpha, a, r, k):
    """Centre acceleration in units of g, eq. (36): cot(alpha) / (2k+1 + k (a/r') cos(alpha)).

    Independent of g; equals r' Omega^2 / g from eq. (29) *signed*: on a
    real orbit (Omega^2 > 0) it is negative where r' < 0, the centre across
    the axis from the contact point.  :func:`horizontal_orbit`'s ``accel_g``
    is the magnitude |r'| Omega^2 / g, so ``accel_g == abs(centre_accel_g)`` on an
    ``ok`` orbit.  NaN where r' = 0 or the denominator vanishes.
    """
    cos_alpha = np.cos(alpha)
    rp = r_prime_from_trig(np.sin(theta), cos_alpha, a, r)
    with np.errstate(divide="ignore", invalid="ignore"):
        den = (2 * k + 1) + k * (a / rp) * cos_alpha
        out = cos_alpha / (np.sin(alpha) * den)
    return np.where(np.isfinite(out), out, np.nan)
