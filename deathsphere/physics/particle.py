"""A particle sliding freely (no friction) on a horizontal circle of a fixed sphere.

The contrast case of McDonald (1993), introduction and sec. 2.2.1: "a particle
sliding freely on the inside of a sphere" has no orbit at or above the
equator.  Beyond the paper's equations; derivation in
docs/derivations-configurations.md.

With the particle at polar angle theta (from the upward vertical) on a sphere
of radius r, the only force besides gravity is the normal force, along the
radius.  Its horizontal and vertical components must give the centripetal
acceleration r sin(theta) Omega^2 and cancel gravity, so on either side

    Omega^2 = -g / (r cos(theta)),     N/m = r Omega^2 = -g / cos(theta)  (towards the centre)

Inside, N must push towards the centre: both hold just for theta > 90 deg
(below the equator).  Outside, N must push away from the centre, N/m =
g/cos(theta) outward, which needs theta < 90 deg, where Omega^2 < 0: a freely
sliding particle has no horizontal orbit on the outside at all.

Units: rad, m, s; broadcasting; statuses instead of exceptions.
"""

import numpy as np

from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.status import Reason, Status, first_failure, mu_required

__all__ = ["omega_squared", "particle_orbit"]


def omega_squared(theta, r, g):
    """Omega^2 = -g / (r cos(theta)) [rad^2/s^2] of a horizontal orbit of a
    freely sliding particle, inside or outside (beyond the paper; see the
    module docstring).  NaN on the equator, where no rate balances gravity."""
    theta, r, g = (np.asarray(x, dtype=float) for x in (theta, r, g))
    c = np.cos(theta)
    eq = np.abs(c) <= SINGULAR
    return np.where(eq, np.nan, -g / (r * np.where(eq, 1.0, c)))


def particle_orbit(theta, r, g, outside=False, mu=np.inf):
    """Horizontal orbit of a freely sliding particle, vectorised.

    Introduction of McDonald (1993) (the contrast case; the formulas are
    beyond the paper, module docstring).

    Parameters
    ----------
    theta : [rad]; r : [m] sphere radius; g : [m/s^2]
    outside : bool   particle on the outside of the sphere
    mu : [-]   accepted for a uniform interface; a frictionless particle
               needs mu_required = 0, so it never slips.

    Returns
    -------
    dict of arrays: ``r_prime`` = r sin(theta) (distance from the vertical
    axis) [m], ``omega2``, ``omega`` (>= 0) [rad/s], ``period`` [s], ``v_cm``
    [m/s], ``spin`` (0: a point particle has no rolling spin), ``accel``,
    ``accel_g``, ``load_g`` (|F| / (m g) = sqrt(1 + accel_g^2), what a rider
    feels), ``normal`` (per unit mass, pressing particle and sphere
    together) [m/s^2], ``friction`` (0), ``mu_required`` (0; NaN without
    contact), int8
    ``status``/``reason``:

    - inside: ok below the equator; no_orbit with PARTICLE_ABOVE_EQUATOR at
        and above it (Omega^2 < 0, or undefined on the equator);
    - outside: no_orbit with PARTICLE_ABOVE_EQUATOR at and above the equator,
        no_contact with PARTICLE_OUTSIDE_BELOW_EQUATOR below it;
    - no_orbit with POLE at theta = 0 or 180 deg (the particle sits on the
        vertical axis: rest, not an orbit).
    """
    theta, r, g, mu = (np.asarray(x, dtype=float) for x in (theta, r, g, mu))
    outside = np.asarray(outside, dtype=bool)
    theta, r, g, mu, outside = np.broadcast_arrays(theta, r, g, mu, outside)
    pole = np.abs(np.sin(theta)) <= SINGULAR
    om2 = omega_squared(theta, r, g)
    real = np.isfinite(om2) & (om2 > 0) & ~pole
    om2_r = np.where(real, om2, np.nan)
    omega = np.sqrt(np.where(real, om2, 1.0))
    omega = np.where(real, omega, np.nan)
    period = np.where(real, 2 * np.pi / np.where(real, omega, 1.0), np.nan)
    rp = r * np.sin(theta)
    # inward push r Omega^2 inside; the outward push outside is its negative
    normal = np.where(outside, -r * om2_r, r * om2_r)
    zero = np.where(real, 0.0, np.nan)
    # 0 where the particle presses on the wall, NaN where it would have to pull
    mu_req = mu_required(normal, zero)
    status, reason = first_failure([
        (pole, Status.NO_ORBIT, Reason.POLE),
        (~real, Status.NO_ORBIT, Reason.PARTICLE_ABOVE_EQUATOR),
        (~(normal > 0), Status.NO_CONTACT, Reason.PARTICLE_OUTSIDE_BELOW_EQUATOR),
        (mu_req > mu, Status.SLIPS, Reason.SLIPS),
    ])
    accel = np.abs(rp) * om2_r
    return {
        "r_prime": rp,
        "omega2": om2,
        "omega": omega,
        "period": period,
        "v_cm": np.abs(rp) * omega,
        "spin": zero,
        "accel": accel,
        "accel_g": accel / g,
        # what the rider feels, |a - g| / g (a horizontal, g vertical: eq. 32)
        "load_g": np.sqrt(accel * accel + g * g) / g,
        "normal": normal,
        "friction": zero,
        "mu_required": mu_req,
        "status": status,
        "reason": reason,
    }
