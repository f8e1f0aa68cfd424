"""Steady horizontal orbits of the single-contact machine on any surface of
revolution: the wall of death's drum, the well of death's cone, flat ground,
a profile, the globe (beyond the paper; docs/machine.md, "On any surface of revolution", eqs.
MS1-MS7).

The sphere's equations M1-M12 (:mod:`deathsphere.physics.machine`) written
for a contact P = (rho_P, z_P) on a parallel of wall angle beta, the inward
normal n = (-sin beta, cos beta) and the parallel's normal curvature
kappa = sin(beta) / rho_P, all answered by the ground (its protocol,
:mod:`deathsphere.physics.ground.protocol`; no ground is named here)::

    Q = P + t n,  G = Q + (h - t) u,  u = (-cos alpha, sin alpha)      (MS1)
    d = P - G:  d_r = t sin(beta) + (h - t) cos(alpha),
                d_z = -t cos(beta) - (h - t) sin(alpha)                 (MS2)
    W = (a - t) + t sin(alpha + beta),  sigma = rho_P / W                (MS3)
    Omega^2 = g d_r / (sin(alpha) (j sigma + delta cos(alpha)) - d_z r_G)  (MS4 = M8)
    N/m = r_G Omega^2 sin(beta) + g cos(beta),
    F_down/m = r_G Omega^2 cos(beta) - g sin(beta)                       (MS5)
    fit: sin(alpha + beta) (1 - t kappa) > (a - t) kappa                 (MS6)
    clearances: the ground's of the head; the tyre's and the head's
    height above the floor z = lowest                                     (MS7)

On the sphere (beta = pi - theta, kappa = 1/r) each is M1-M10 exactly.
A lane is the contact's height above the ground's lowest point (the floor
of the drum and the cone; on flat ground the contact's distance from the
turn's centre, where MS2-MS4 with beta = 0 are the classic lean of a
motorcycle, tan(phi_eff) = v_G^2 / (g r_G) for the line from the contact to
the centre of mass, corrected for the tyre's width and the gyroscopic and
inertial terms); every function is vectorised over heights and
tilts and loops over no orbit.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.machine import ROOT_MATCH_RTOL, _add, _lin, _mul
from deathsphere.physics.machine_arrays import MachineArrays
from deathsphere.physics.status import Reason, Status, first_failure, mu_required
from deathsphere.physics.trig_roots import roots_in

__all__ = ["Contact", "contact_on", "meridian_points_on", "ride_orbit_on", "fit_window_on", "speed_polynomial_on",
           "rate_polynomial_on", "solve_alpha_for_speed_on", "solve_alpha_for_rate_on"]


class Contact(NamedTuple):
    """What the machine needs of the ground at a lane, arrays [m, 1/m]:
    the contact (rho, z), sin and cos of the wall angle beta (the inward
    normal is (-sin beta, cos beta)), the parallel's normal curvature
    kappa, and the lane's height."""

    rho: np.ndarray
    z: np.ndarray
    sin_beta: np.ndarray
    cos_beta: np.ndarray
    kappa: np.ndarray
    height: np.ndarray


def contact_on(height, ground) -> Contact:
    """Beyond the paper (docs/machine.md, eq. MS1): the ground's answers at ``height`` [m] (any shape) as a
    :class:`Contact`: the normal's components are the ground's own, so a
    vertical wall's cos(beta) is exactly 0."""
    height = np.asarray(height, dtype=float)
    rho, z = ground.contact(height)
    n_rho, n_z = ground.normal(height)
    _, kappa = ground.curvatures(height)
    return Contact(*(np.asarray(x, dtype=float) for x in (rho, z, -n_rho, n_z, kappa, height)))


def _up(c: Contact, sa, ca, length, t):
    """Q + (length - t) u, Q = P + t n (eq. MS1), as (rho, z): the one place
    a point on the up-axis is written."""
    return (c.rho - t * c.sin_beta - (length - t) * ca, c.z + t * c.cos_beta + (length - t) * sa)


def meridian_points_on(height, alpha, ground, machine: MachineArrays) -> dict:
    """Eq. MS1 (beyond the paper, docs/machine.md): the contact P, the centre of mass G and the head H as (rho,
    z) [m] in the contact's meridian plane (the ground's coordinates), for
    the lane at ``height`` [m] and the tilt ``alpha`` [rad] (broadcast).
    Keys 'contact', 'com', 'head' (as :func:`~deathsphere.physics.machine.meridian_points`)."""
    c = contact_on(height, ground)
    alpha = np.asarray(alpha, dtype=float)
    sa, ca = np.sin(alpha), np.cos(alpha)
    t = machine.tyre_radius
    return {"contact": (c.rho, c.z), "com": _up(c, sa, ca, machine.com_height, t),
            "head": _up(c, sa, ca, machine.head_height, t)}


def _fits(c: Contact, sab, a, t):
    """Eq. MS6: the crown circle (radius a - t, its tangent at Q along the
    parallel) bends towards the axle more than the parallel of the surface
    Q moves on (curvature kappa / (1 - t kappa)); False where kappa is not
    finite (a cone's apex)."""
    finite = np.isfinite(c.kappa)
    kappa = np.where(finite, c.kappa, 0.0)
    return finite & (sab * (1.0 - t * kappa) > (a - t) * kappa)


def _floor_clearance(c: Contact, sa, ca, head_z, ground, m: MachineArrays):
    """Eq. MS7: the height [m] above the floor (the horizontal plane through
    the ground's lowest point) of the lower of the head and the tyre's
    lowest point.  The crown circle about the axle C = Q + (a - t) u, in
    the plane of u and the (horizontal) direction of travel, reaches down
    to C_z - (a - t) |sin(alpha)|, the tyre a further t.  Inside the globe
    it is never below its floor; on a drum or a cone it stops a lane
    ridden too low; on flat ground (the floor the surface itself) the
    tyre's lowest point is the contact, at 0."""
    a, t = m.wheel_radius, m.tyre_radius
    _, axle_z = _up(c, sa, ca, a, t)
    tyre_z = axle_z - (a - t) * np.abs(sa) - t
    return np.minimum(tyre_z, head_z) - ground.lowest


def ride_orbit_on(height, alpha, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf):
    """Every quantity of a machine's steady horizontal orbit on ``ground`` (beyond the paper, docs/machine.md)
    at the lane ``height`` [m] and tilt ``alpha`` [rad] (broadcast), eqs.
    MS1-MS7: the keys of :func:`~deathsphere.physics.machine.ride_orbit`
    (``friction`` positive down the wall, ``head_clearance`` the ground's
    clearance of the head point) and ``floor_clearance`` [m] (the tyre's
    and the head's least height above the floor, MS7), ``rho_contact``
    [m], ``wall_angle`` [rad].  On the sphere every value is ride_orbit's to rounding, its
    reasons for a wheel that does not fit, a head that hits and a contact
    that pulls worded for any wall (MS5-MS7).  An ok row is all finite."""
    m = machine
    c = contact_on(height, ground)
    alpha, g, mu, max_g = (np.asarray(x, dtype=float) for x in (alpha, g, mu, max_g))
    mass, h, a, t = m.mass, m.com_height, m.wheel_radius, m.tyre_radius
    sa, ca = np.sin(alpha), np.cos(alpha)
    hq = h - t
    r_g, _ = _up(c, sa, ca, h, t)                                    # MS1: the CoM's orbit radius
    d_r = t * c.sin_beta + hq * ca                                   # MS2
    d_z = -t * c.cos_beta - hq * sa                                  # MS2
    sab = sa * c.cos_beta + ca * c.sin_beta                          # sin(alpha + beta) = u . n
    w = (a - t) + t * sab                                            # MS3: the rolling radius
    j = m.spin_inertia / mass
    delta = (m.yaw_inertia - m.pitch_inertia) / mass
    fit = _fits(c, sab, a, t)
    w_ok = w > 0
    with np.errstate(divide="ignore", invalid="ignore"):
        sigma = np.where(w_ok, c.rho / np.where(w_ok, w, 1.0), np.nan)      # MS3
    den = sa * (j * sigma + delta * ca) - d_z * r_g                  # MS4 denominator [m^2]
    # the scales of M8's terms (as the sphere's, with the lane's radius for r)
    den_scale = (np.abs(c.rho) + h + a) * (h + t + a) + np.abs(j) * np.abs(c.rho) / (a - t) + np.abs(delta)
    singular = ~(np.abs(den) > SINGULAR * den_scale)
    with np.errstate(divide="ignore", invalid="ignore"):
        om2 = np.where(singular, np.nan, g * d_r / np.where(singular, 1.0, den))   # MS4
        # Omega^2 against g times the parallel's curvature (1/r on the sphere, as M8's test)
        curved = np.isfinite(c.kappa) & (c.kappa > 0)
        om2_zero = np.abs(om2) <= SINGULAR * g * np.where(curved, c.kappa, 1.0 / (np.abs(c.rho) + h + a))
    real = (om2 > 0) & ~om2_zero
    om2_real = np.where(real, om2, np.nan)
    omega = np.sqrt(om2_real)
    with np.errstate(divide="ignore"):
        period = 2 * np.pi / omega
    centripetal = r_g * om2_real
    normal = centripetal * c.sin_beta + g * c.cos_beta               # MS5: F . n / m
    friction = centripetal * c.cos_beta - g * c.sin_beta             # MS5: F . (down the wall) / m
    mu_req = mu_required(normal, friction)
    load = np.sqrt(centripetal * centripetal + g * g) / g            # M11
    head = _up(c, sa, ca, m.head_height, t)
    # a head past the axis is in the opposite half of the meridian plane: by
    # the symmetry of revolution, its distance from the axis is |rho|
    clearance = np.asarray(ground.clearance(np.abs(head[0]), head[1]), dtype=float)     # MS7
    floor = _floor_clearance(c, sa, ca, head[1], ground, m)
    status, reason = first_failure([
        (~fit, Status.NO_FIT, Reason.MACHINE_NO_FIT_WALL),
        (~(clearance > 0), Status.NO_FIT, Reason.HEAD_HITS_WALL),
        # a tyre standing on the floor touches it, it does not reach below it: on flat
        # ground the floor is the surface ridden and the tyre's lowest point the contact
        (~(floor > -SINGULAR * (h + a)), Status.NO_FIT, Reason.MACHINE_HITS_FLOOR),
        (singular, Status.NO_ORBIT, Reason.MACHINE_ZERO_DENOMINATOR),
        (om2_zero, Status.NO_ORBIT, Reason.MACHINE_OMEGA_ZERO),
        (~real, Status.NO_ORBIT, Reason.MACHINE_OMEGA_IMAGINARY),
        (~(normal > 0), Status.NO_CONTACT, Reason.MACHINE_NO_CONTACT_WALL),
        (mu_req > mu, Status.SLIPS, Reason.SLIPS),
        (load > max_g, Status.OVER_G, Reason.MACHINE_OVER_G),
    ])
    out = {
        "r_g": r_g,
        "omega2": om2,
        "omega": omega,
        "period": period,
        "v_cm": np.abs(r_g) * omega,
        "v_contact": c.rho * omega,
        "spin": sigma * omega,
        "normal": normal,
        "friction": friction,
        "mu_required": mu_req,
        "load_g": load,
        "head_clearance": clearance,
        "floor_clearance": floor,
        "height": c.height,
        "rho_contact": c.rho,
        "wall_angle": np.arctan2(c.sin_beta, c.cos_beta),
        "status": status,
        "reason": reason,
    }
    shape = status.shape
    return {key: (val if val.shape == shape else np.broadcast_to(val, shape)) for key, val in out.items()}


def fit_window_on(height, ground, machine: MachineArrays):
    """The tilts at which the wheel fits (eq. MS6, beyond the paper: docs/machine.md), (lo, hi) [rad]: the open
    interval asin(q) - beta < alpha < pi - asin(q) - beta with
    q = (a - t) kappa / (1 - t kappa); an empty interval (lo = hi = NaN)
    where no tilt fits.  On the sphere: M10's theta - pi + asin(q) <
    alpha < theta - asin(q)."""
    c = contact_on(height, ground)
    a, t = machine.wheel_radius, machine.tyre_radius
    finite = np.isfinite(c.kappa)
    kappa = np.where(finite, c.kappa, 0.0)
    room = 1.0 - t * kappa
    ok = finite & (room > 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        q = np.where(ok, (a - t) * kappa / np.where(ok, room, 1.0), np.nan)
    ok &= q < 1.0
    asin_q = np.arcsin(np.clip(np.where(ok, q, 0.0), -1.0, 1.0))
    beta = np.arctan2(c.sin_beta, c.cos_beta)
    return np.where(ok, asin_q - beta, np.nan), np.where(ok, np.pi - asin_q - beta, np.nan)


def _rows(height, ground, m: MachineArrays):
    """The lengths of MS1-MS3 as coefficient rows in alpha (n, 3): r_G,
    d_r, d_z, W, sin(alpha), cos(alpha); and j rho_P, delta."""
    c = contact_on(height, ground)
    a, t, hq = m.wheel_radius, m.tyre_radius, m.com_height - m.tyre_radius
    zero = np.zeros_like(c.rho)
    r_g = _lin(c.rho - t * c.sin_beta, -hq + zero, zero)
    d_r = _lin(t * c.sin_beta, hq + zero, zero)
    d_z = _lin(-t * c.cos_beta, zero, -hq + zero)
    w = _lin((a - t) + zero, t * c.sin_beta, t * c.cos_beta)
    sin_a, cos_a = _lin(zero, zero, 1.0 + zero), _lin(zero, 1.0 + zero, zero)
    j_rho = _lin(m.spin_inertia / m.mass * c.rho, zero, zero)
    delta = ((m.yaw_inertia - m.pitch_inertia) / m.mass + zero)[:, None]
    return r_g, d_r, d_z, w, sin_a, cos_a, j_rho, delta


def _den_w(r_g, d_z, w, sin_a, cos_a, j_rho, delta):
    """M8's denominator times W: sin(alpha) (j rho_P + delta cos(alpha) W) - d_z r_G W."""
    return _add(_mul(sin_a, _add(j_rho, _mul(cos_a, w) * delta)), -_mul(_mul(d_z, r_g), w))


def speed_polynomial_on(height, speed, ground, g, m: MachineArrays):
    """Beyond the paper (docs/machine.md, M12 with MS2-MS3): coefficient
    rows (n, 9) in alpha whose zeros are the tilts giving the centre of
    mass ``speed`` (eq. M12 on the ground, MS4 times r_G^2 W):
    g d_r r_G^2 W - v^2 D W, all inputs 1-D of one length n."""
    r_g, d_r, d_z, w, sin_a, cos_a, j_rho, delta = _rows(height, ground, m)
    left = _mul(_mul(_mul(d_r, r_g), r_g), w) * np.asarray(g, dtype=float)[:, None]
    v2 = (np.asarray(speed, dtype=float) ** 2)[:, None]
    return _add(left, -v2 * _den_w(r_g, d_z, w, sin_a, cos_a, j_rho, delta))


def rate_polynomial_on(height, omega, ground, g, m: MachineArrays):
    """Beyond the paper (docs/machine.md, M8 with MS2-MS3): coefficient
    rows (n, 7) in alpha whose zeros are the tilts of the orbit at rate
    ``omega`` [rad/s] (MS4 times W): Omega^2 D W - g d_r W."""
    r_g, d_r, d_z, w, sin_a, cos_a, j_rho, delta = _rows(height, ground, m)
    om2 = (np.asarray(omega, dtype=float) ** 2)[:, None]
    return _add(om2 * _den_w(r_g, d_z, w, sin_a, cos_a, j_rho, delta),
                -_mul(d_r, w) * np.asarray(g, dtype=float)[:, None])


def _solve(poly, key, height, target, ground, g, machine: MachineArrays):
    """The zeros of ``poly`` in the fit window, kept where the forward model
    gives ``target`` back in ``key`` (ROOT_MATCH_RTOL); (n, k) sorted, NaN-padded."""
    args = np.broadcast_arrays(*(np.asarray(x, dtype=float).reshape(-1) for x in (height, target, g, *machine)))
    height, target, g = args[:3]
    m = MachineArrays(*args[3:])
    n = height.size
    if n == 0:
        return np.full((0, 0), np.nan)
    coef = poly(height, target, ground, g, m)
    lo, hi = fit_window_on(height, ground, m)
    some = np.isfinite(lo)
    eps = 1e-12
    roots = roots_in(coef, np.where(some, lo + eps, 0.0), np.where(some, hi - eps, 0.0))
    found = np.isfinite(roots) & some[:, None]
    if roots.shape[1] == 0:
        return roots
    col = (slice(None), None)
    # the head set above the centre of mass: only the target is checked here
    mc = m._replace(head_height=m.com_height + 1.0).map(lambda x: x[col])
    orb = ride_orbit_on(height[col], np.where(found, roots, 0.0), ground, g[col], mc)
    with np.errstate(invalid="ignore"):
        found &= np.abs(orb[key] - target[col]) <= ROOT_MATCH_RTOL * np.abs(target[col])
    roots = np.sort(np.where(found, roots, np.nan), axis=1)
    width = max(1, int(np.max(np.sum(np.isfinite(roots), axis=1), initial=0)))
    return roots[:, :width]


def solve_alpha_for_speed_on(height, speed, ground, g, machine: MachineArrays):
    """Beyond the paper (docs/machine.md, M12): every tilt in the fit window (MS6) at which the centre of mass's speed
    on the lane at ``height`` is ``speed`` > 0 (1-D inputs of one length,
    the machine's arrays broadcast): the zeros of
    :func:`speed_polynomial_on`, each checked with :func:`ride_orbit_on`
    (as :func:`~deathsphere.physics.machine.solve_alpha_for_speed`).
    Returns (n, k) sorted, NaN-padded."""
    return _solve(speed_polynomial_on, "v_cm", height, speed, ground, g, machine)


def solve_alpha_for_rate_on(height, omega, ground, g, machine: MachineArrays):
    """Beyond the paper (docs/machine.md, M8): every tilt in the fit window (MS6) of the orbit at rate ``omega`` > 0
    [rad/s] on the lane at ``height`` (the zeros of
    :func:`rate_polynomial_on`, each checked with :func:`ride_orbit_on`).
    Returns (n, k) sorted, NaN-padded."""
    return _solve(rate_polynomial_on, "omega", height, omega, ground, g, machine)
