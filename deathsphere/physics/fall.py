"""A rider who loses speed: where he leaves the wall and where he lands.

Beyond the paper.  The globe is centred at the origin, z up, radius r,
gravity -g z.  Every function is vectorised over a trailing batch axis n:
positions and velocities are (3, n), scalars (n,) or broadcastable; angles
in radians, lengths in metres, times in seconds.  Nothing loops over falls.

The model, in three stages:

1. **The drop.**  At the instant of the failure the centre of mass keeps its
   position and its velocity becomes ``speed_fraction`` times what it was,
   along the direction of travel.
2. **Contact.**  A looper (a vertical lane, a great circle of radius rho,
   the centre of mass G on the circle of radius r_G = rho - h, psi from the
   top) keeps his energy (docs/machine.md sec. 10, eq. M21) and his contact
   while the in-plane normal force m (r_G psidot^2 - g cos psi) is positive
   (the force behind eq. M22); where it reaches zero he leaves the wall.  If
   it never does he rides on over the top; if his speed reaches zero first
   he swings back and forth below the equator.  A rider on a horizontal
   lane whose lane is no longer feasible at the new speed leaves at once.
3. **Flight.**  From contact loss the centre of mass flies on a parabola
   until it meets the globe's surface (:func:`ballistic_landing`).

Limits of the model (say them wherever its numbers are shown): the body is
a point at its centre of mass in flight -- it tumbles, and its extremities
(head, handlebar) reach the steel or another rider before or after the
centre of mass does; bike and rider may separate, and each then flies its
own parabola; after contact loss friction and the wall's touch are ignored
until the centre of mass reaches the surface; a machine that leaves the
wall while its wheels still spin carries their angular momentum, which
changes nothing on the parabola of the centre of mass.
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "RIDES_ON", "SWINGS", "FALLS", "OUTCOMES",
    "LANDS", "STARTS_OUTSIDE",
    "ballistic_landing", "loop_departure", "loop_time", "loop_state",
    "loop_speed_profile", "drop_velocity",
]

#: Outcome codes of :func:`loop_departure` (int8), and their names.
RIDES_ON, SWINGS, FALLS = 0, 1, 2
OUTCOMES = ("rides_on", "swings", "falls")

#: Status codes of :func:`ballistic_landing` (int8).
LANDS, STARTS_OUTSIDE = 0, 1


def ballistic_landing(x0, v0, r, g):
    """Where and when a centre of mass flying freely from ``x0`` with
    velocity ``v0`` meets the globe's surface (beyond the paper).

    The first time t > 0 with |x0 + v0 t - g t^2/2 z| = r, a quartic in t::

        f(t) = g^2/4 t^4 - g v_z t^3 + (|v0|^2 - g z0) t^2 + 2 (x0 . v0) t + |x0|^2 - r^2.

    x0, v0 : (3, n) [m], [m/s]; r [m], g [m/s^2] broadcast to (n,).

    A start on the surface (within 1e-9 r) has the root t = 0 divided out, as
    often as it is a root (tangent start: twice; a point mass leaving a loop,
    where the parabola osculates the circle: three times), so a start on the
    surface moving inward is never reported as landing at t = 0; moving
    outward it lands at t = 0.

    Returns dict: ``t_land`` (n,) [s], ``x_land`` (3, n) [m], ``v_land``
    (3, n) [m/s], ``impact_speed`` (n,) [m/s] (|v_land|), ``impact_normal``
    (n,) [m/s] (the outward radial component of v_land), int8 ``status``
    (LANDS, or STARTS_OUTSIDE where |x0| > r: then NaN).
    """
    raise NotImplementedError


def loop_departure(psi0, psi_dot0, rho, r_g, M_eff, m, g):
    """The rest of a vertical loop from the state just after a speed drop
    (docs/machine.md sec. 10, eqs. M21-M23; the departure itself beyond the
    paper).

    psi0 [rad] (from the top, any branch), psi_dot0 [rad/s] (sign = the
    direction of travel) of the centre of mass G on its circle of radius
    ``r_g`` [m] in the loop of radius ``rho`` [m]; ``M_eff`` [kg m^2] the
    loop's effective inertia M = m r_G^2 + I_pitch + J (rho^2 - 2 rho a)/a^2
    (M21; a point mass: m r_G^2), ``m`` [kg], ``g`` [m/s^2]; all broadcast.

    Energy (M21) gives psidot^2 = C - kappa cos psi with kappa = 2 m g r_G / M
    and C = psi_dot0^2 + kappa cos psi0; the in-plane normal force per unit
    mass is r_G psidot^2 - g cos psi = A - B cos psi with A = r_G C and
    B = g + r_G kappa (= g (1 + 2q) of M24).

    Returns dict of (n,) arrays: int8 ``outcome`` (RIDES_ON: A >= B, contact
    all round, M22; SWINGS: the speed reaches zero first, at cos psi = C /
    kappa <= 0; FALLS: the normal force reaches zero first, at cos psi = A/B,
    or is not positive at once), ``t_lost`` [s] after the drop and
    ``psi_lost`` [rad] (on the branch of psi0, along the travel; FALLS only,
    else NaN),
    ``psi_dot_lost`` [rad/s] (FALLS only, else NaN), ``psi_max`` [rad] (the
    highest point reached with contact, as an angle from the top in [0, pi]:
    the turning point for SWINGS, the departure for FALLS, 0 for RIDES_ON),
    ``t_turn`` [s] (SWINGS: time to the first turning point) and
    ``swing_period`` [s] (SWINGS: a full swing, back and forth).
    """
    raise NotImplementedError


def loop_time(psi0, psi_dot0, psi1, r_g, M_eff, m, g):
    """Time [s] for G to go from psi0 to psi1 (along the travel, psi1 on the
    far side of psi0 in the direction of psi_dot0, less than one turn on)
    with energy conserved (M21): t = int dpsi / psidot(psi), in closed form
    with incomplete elliptic integrals of the first kind (beyond the paper).
    NaN where the speed vanishes strictly before psi1."""
    raise NotImplementedError


def loop_speed_profile(t, psi0, psi_dot0, r_g, M_eff, m, g):
    """psi(t) and psidot(t) [rad, rad/s] of a loop ridden over the top with
    energy conserved (M21), psi(0) = psi0 and psidot(0) = psi_dot0 > 0, for
    times t (n,) (broadcast); psi is unwrapped (increases without bound).
    Returns dict ``psi``, ``psi_dot``, ``period`` [s] (one lap)."""
    raise NotImplementedError


def loop_state(psi, psi_dot, r_g, azimuth):
    """The centre of mass's position and velocity, (3, n) each [m, m/s], on
    a vertical great-circle loop whose plane holds z and e = (cos azimuth,
    sin azimuth, 0): G = r_G (sin psi e + cos psi z), dG/dt = r_G psidot
    (cos psi e - sin psi z)."""
    raise NotImplementedError


def drop_velocity(v, speed_fraction):
    """The velocity (3, n) just after the drop: ``speed_fraction`` (n,) times
    the velocity ``v`` (3, n) before, along the direction of travel."""
    raise NotImplementedError
