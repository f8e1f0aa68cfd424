"""Steady horizontal orbits of a wheel rolling on a fixed sphere.

McDonald (1993) sec. 2.2.2, eqs. (13), (29)-(36); sec. 3, eqs. (81), (83)
for the wheel outside.  All functions take broadcastable arrays: theta and
alpha in radians, a and r in m, k dimensionless (I11 = 2 k m a^2), g in m/s^2.
"""

import numpy as np

from deathsphere.physics.geometry import SINGULAR, fits_inside, fits_outside, r_prime
from deathsphere.physics.status import Reason, Status, first_failure


def omega_squared_denominator(theta, alpha, a, r, k):
    """sin(alpha) [(2k+1) r' + k a cos(alpha)], the denominator of eq. (29)
    written with cot(alpha) = cos(alpha)/sin(alpha)."""
    return np.sin(alpha) * ((2 * k + 1) * r_prime(theta, alpha, a, r) + k * a * np.cos(alpha))


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
    den = omega_squared_denominator(theta, alpha, a, r, k)
    num = g * np.cos(alpha)
    scale = (2 * k + 1) * r + (k + 1) * a
    singular = np.abs(den) <= SINGULAR * scale
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(singular, np.nan, num / np.where(singular, 1.0, den))


def contact_force_spherical(theta, r_prime_, omega2, g):
    """Contact force per unit mass in the sphere's (r, theta) basis, eq. (32).

    .. math:: F/m = -(r'\\Omega^2\\sin\\theta - g\\cos\\theta)\\,\\hat r
                    -(r'\\Omega^2\\cos\\theta + g\\sin\\theta)\\,\\hat\\theta
                  = -r'\\Omega^2 \\hat r' + g \\hat z

    r-hat points out of the sphere's centre, theta-hat towards increasing
    theta (down the wall).  Returns ``(F_r, F_theta)``.
    """
    centripetal = r_prime_ * omega2
    f_r = -(centripetal * np.sin(theta) - g * np.cos(theta))
    f_theta = -(centripetal * np.cos(theta) + g * np.sin(theta))
    return f_r, f_theta


def contact_force_body(alpha, r_prime_, omega2, g):
    """Contact force per unit mass in the wheel's (1, 3) axes, eq. (30).

    .. math:: F/m = (-g\\cos\\alpha + r'\\Omega^2\\sin\\alpha)\\,\\hat 1
                    -(g\\sin\\alpha + r'\\Omega^2\\cos\\alpha)\\,\\hat 3

    Returns ``(F_1, F_3)``; F_2 = 0 on a steady horizontal orbit.
    """
    centripetal = r_prime_ * omega2
    return (-g * np.cos(alpha) + centripetal * np.sin(alpha),
            -(g * np.sin(alpha) + centripetal * np.cos(alpha)))


def friction_coefficient(normal, friction):
    """Least static friction coefficient that holds the contact, eq. (35):
    mu = |F_parallel| / F_perp.  NaN where the normal force is not positive
    (no contact: mu is undefined there)."""
    ok = normal > 0
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(ok, np.abs(friction) / np.where(ok, normal, 1.0), np.nan)


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
    normal, friction, mu_required`` and int8 ``status``, ``reason`` (codes of
    :mod:`deathsphere.physics.status`).  Quantities that are undefined for an
    orbit are NaN there and its status is not OK; an OK row is all finite.

    Notes
    -----
    ``omega3`` is the spin about the contact normal axis 3, -Omega sin(alpha)
    (eq. 13).  ``v_cm`` and ``accel`` are magnitudes, |r'| Omega and |r'| Omega^2;
    ``spin`` keeps the sign of eq. (13) (negative when r' < 0).  ``normal``
    is the component of F/m pressing body and sphere together (-F_r inside,
    +F_r outside); ``friction`` is F_theta/m, positive down the wall.
    """
    theta, alpha, a, r, k, g, outside, mu = np.broadcast_arrays(
        *(np.asarray(x, dtype=float) for x in (theta, alpha, a, r, k, g)),
        np.asarray(outside, dtype=bool), np.asarray(mu, dtype=float))
    rp = r_prime(theta, alpha, a, r)
    fits = np.where(outside, fits_outside(theta, alpha), fits_inside(theta, alpha, a, r))
    om2 = omega_squared(theta, alpha, a, r, k, g)
    undefined = np.isnan(om2)
    in_plane = np.abs(np.sin(alpha)) <= SINGULAR
    om2_zero = ~undefined & (np.abs(om2) <= SINGULAR * g / r)
    real = ~undefined & ~om2_zero & (om2 > 0)

    om2_real = np.where(real, om2, np.nan)
    with np.errstate(invalid="ignore", divide="ignore"):
        omega = np.sqrt(om2_real)
        period = 2 * np.pi / omega
    f_r, f_theta = contact_force_spherical(theta, rp, om2_real, g)
    normal = np.where(outside, f_r, -f_r)
    mu_req = friction_coefficient(np.where(real, normal, np.nan), f_theta)

    status, reason = first_failure([
        (~fits, Status.NO_FIT, np.where(outside, Reason.NO_FIT_OUTSIDE, Reason.NO_FIT_INSIDE)),
        (undefined, Status.NO_ORBIT, np.where(in_plane, Reason.ALPHA_IN_ORBIT_PLANE, Reason.ZERO_DENOMINATOR)),
        (om2_zero, Status.NO_ORBIT, Reason.OMEGA_ZERO),
        (~real, Status.NO_ORBIT, Reason.OMEGA_IMAGINARY),
        (~(normal > 0), Status.NO_CONTACT, np.where(outside, Reason.NO_CONTACT_OUTSIDE, Reason.NO_CONTACT_INSIDE)),
        (mu_req > mu, Status.SLIPS, Reason.SLIPS),
    ])
    return {
        "r_prime": rp,
        "omega2": om2,
        "omega": omega,
        "period": period,
        "v_cm": np.abs(rp) * omega,
        "spin": rp * omega / a,
        "omega3": -omega * np.sin(alpha),
        "accel": np.abs(rp) * om2_real,
        "accel_g": np.abs(rp) * om2_real / g,
        "normal": np.where(real, normal, np.nan),
        "friction": f_theta,
        "mu_required": mu_req,
        "status": status,
        "reason": reason,
    }


def g_load(theta, alpha, a, r, k):
    """Centre acceleration in units of g, eq. (36): cot(alpha) / (2k+1 + k (a/r') cos(alpha)).

    Independent of g; equals r' Omega^2 / g from eq. (29).  NaN where r' = 0
    or the denominator vanishes.
    """
    rp = r_prime(theta, alpha, a, r)
    with np.errstate(divide="ignore", invalid="ignore"):
        den = (2 * k + 1) + k * (a / rp) * np.cos(alpha)
        out = np.cos(alpha) / (np.sin(alpha) * den)
    return np.where(np.isfinite(out), out, np.nan)
