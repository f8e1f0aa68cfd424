"""A machine's lane at a given speed or rate: every tilt that gives a
height and a centre-of-mass speed (eq. M12) or an orbital rate (eq. M12r:
a contact speed or a lap time), the orbit at each, and the one a rider
takes (beyond the paper; docs/machine.md eqs. M8-M12r, docs/show.md
"Lanes").

Vectorised over lanes: arrays of contact polar angles theta [rad] and
speeds [m/s] or rates [rad/s] (n,), the ground (a
:class:`~deathsphere.physics.ground.Sphere`), gravity and the machine's
arrays (:class:`~deathsphere.physics.machine_arrays.MachineArrays`, one
machine or one per lane) broadcast against them.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.ground import Sphere
from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.machine import ride_orbit, solve_alpha_for_rate, solve_alpha_for_speed
from deathsphere.physics.machine_arrays import MachineArrays
from deathsphere.physics.machine_surface import ride_orbit_on, solve_alpha_for_rate_on, solve_alpha_for_speed_on
from deathsphere.physics.status import Reason, Status

__all__ = ["orbits_for_speed", "orbits_for_rate", "contact_rate", "closest_tilt", "horizontal_lanes",
           "horizontal_lanes_at_rate", "speed_is_feasible", "rate_is_feasible", "orbits_for_speed_on",
           "orbits_for_rate_on", "contact_rate_on", "horizontal_lanes_on", "horizontal_lanes_at_rate_on",
           "rate_is_feasible_on"]


def _flat(theta, speed, ground, g, machine: MachineArrays, *more):
    """theta, speed, the radius, g, the machine's fields and ``more``, all (n,)."""
    args = np.broadcast_arrays(*(np.asarray(x, dtype=float).reshape(-1) for x in
                                 (theta, speed, ground.radius, g, *more, *machine)))
    k = 4 + len(more)
    return args[:k], MachineArrays(*args[k:])


def orbits_for_speed(theta, speed, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf):
    """Every tilt giving the centre of mass ``speed`` at ``theta`` (eq. M12,
    :func:`~deathsphere.physics.machine.solve_alpha_for_speed`: (n, k)
    sorted, NaN-padded) and :func:`~deathsphere.physics.machine.ride_orbit`'s
    quantities at each ((n, k) arrays), evaluated at the tilts found only;
    where none is: NaN, status no_orbit and reason machine_no_alpha."""
    (theta, speed, r, g, mu, max_g), m = _flat(theta, speed, ground, g, machine, mu, max_g)
    tilts = solve_alpha_for_speed(theta, speed, Sphere(r), g, m)
    return tilts, _at_tilts(theta, tilts, r, g, m, mu, max_g)


def orbits_for_rate(theta, omega, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf):
    """Every tilt of a steady orbit at the rate ``omega`` [rad/s] about the
    vertical at ``theta`` (eq. M12r,
    :func:`~deathsphere.physics.machine.solve_alpha_for_rate`) and
    :func:`~deathsphere.physics.machine.ride_orbit`'s quantities at each, as
    :func:`orbits_for_speed`.  A rate that is not finite and positive (a
    contact speed with the contact on the axis: :func:`contact_rate`) has
    no tilt: status no_orbit, reason contact_on_axis."""
    (theta, omega, r, g, mu, max_g), m = _flat(theta, omega, ground, g, machine, mu, max_g)
    moving = np.isfinite(omega) & (omega > 0)
    tilts = solve_alpha_for_rate(theta, np.where(moving, omega, 1.0), Sphere(r), g, m)
    tilts = np.where(moving[:, None], tilts, np.nan)
    orbit = _at_tilts(theta, tilts, r, g, m, mu, max_g)
    orbit["reason"] = np.where(moving[:, None], orbit["reason"], Reason.CONTACT_ON_AXIS).astype(np.int8)
    return tilts, orbit


def contact_rate(theta, v_contact, ground):
    """The orbital rate Omega [rad/s] at which the contact runs along the
    ground at ``v_contact`` [m/s] (arrays, broadcast): on a steady
    horizontal orbit the contact runs round the parallel of radius rho_P =
    r sin(theta) (the contact's distance from the vertical axis), so
    v_contact = Omega rho_P whatever the tilt (beyond the paper;
    docs/machine.md eq. M12r).  NaN where the contact is on the axis
    (rho_P = 0: it does not move on any orbit)."""
    theta, v = np.asarray(theta, dtype=float), np.asarray(v_contact, dtype=float)
    r = np.asarray(ground.radius, dtype=float)
    rho = r * np.sin(theta)
    on_axis = ~(np.abs(rho) > SINGULAR * r)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(on_axis, np.nan, v / np.where(on_axis, 1.0, np.abs(rho)))


def _at_tilts(theta, tilts, r, g, m: MachineArrays, mu, max_g) -> dict:
    """ride_orbit's quantities at the tilts found ((n, k), NaN: none)."""
    rows, cols = np.nonzero(np.isfinite(tilts))
    found = ride_orbit(theta[rows], tilts[rows, cols], Sphere(r[rows]), g[rows], m.take(rows), mu[rows],
                       max_g[rows])
    empty = {"status": Status.NO_ORBIT, "reason": Reason.MACHINE_NO_ALPHA}
    orbit = {}
    for key, val in found.items():
        orbit[key] = np.full(tilts.shape, empty.get(key, np.nan), dtype=val.dtype)
        orbit[key][rows, cols] = val
    return orbit


def closest_tilt(tilts, keep, target):
    """(index (n,), found (n,)): the column of ``tilts`` (n, k) closest to
    ``target`` (n,) [rad] among those ``keep`` (n, k) bool; found False
    (index 0) where none is kept.  The first of equally close ones.  Beyond
    the paper: the rider's choice of tilt, docs/show.md sec. 2."""
    tilts = np.asarray(tilts, dtype=float)
    if tilts.shape[1] == 0:
        return np.zeros(tilts.shape[0], dtype=np.int64), np.zeros(tilts.shape[0], dtype=bool)
    dist = np.where(keep, np.abs(np.where(keep, tilts, 0.0) - np.asarray(target, dtype=float)[:, None]), np.inf)
    return np.argmin(dist, axis=1), keep.any(axis=1)


def horizontal_lanes(theta, speed, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf) -> dict:
    """The steady orbit each lane (theta [rad], centre-of-mass ``speed``
    [m/s], (n,)) is ridden on (docs/show.md, "Lanes"): of the tilts giving
    the speed (eq. M12) the one closest to upright on the wall (alpha =
    theta - 90 deg, the up-axis along the inward normal) among those with
    status ok, or, when none is ok, among those with an orbit (finite
    Omega; the status then says why it fails).

    Returns dict of (n,) arrays: ``alpha`` [rad] (NaN where no tilt has an
    orbit), ``chosen`` bool (a tilt was chosen), ``tilts`` (n, k) every tilt
    for the speed, and every key of
    :func:`~deathsphere.physics.machine.ride_orbit` at the chosen tilt; where
    none is chosen, the first tilt's status and reason (status no_orbit,
    reason machine_no_alpha where no tilt gives the speed at all) and NaN.
    """
    theta = np.asarray(theta, dtype=float).reshape(-1)
    return _rider_choice(theta, *orbits_for_speed(theta, speed, ground, g, machine, mu, max_g), ground)


def horizontal_lanes_at_rate(theta, omega, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf) -> dict:
    """:func:`horizontal_lanes` for lanes held at an orbital rate ``omega``
    [rad/s] (n,) (eq. M12r: a contact speed, :func:`contact_rate`, or a lap
    time 2 pi / T): the same rider's choice among the tilts giving the
    rate; reason contact_on_axis where the rate is not finite."""
    theta = np.asarray(theta, dtype=float).reshape(-1)
    return _rider_choice(theta, *orbits_for_rate(theta, omega, ground, g, machine, mu, max_g), ground)


def _rider_choice(theta, tilts, orbit, ground) -> dict:
    """The tilt a rider takes of ``tilts`` (n, k) with ``orbit`` at each
    (:func:`horizontal_lanes`' rule) and the orbit there."""
    out = _choose(tilts, orbit, np.degrees(theta) - 90.0, theta.size)
    out["height"] = np.broadcast_to(ground.height(theta), theta.shape)
    return out


def _choose(tilts, orbit, upright, n: int) -> dict:
    """The tilt closest to ``upright`` [deg] (n,) of ``tilts`` (n, k), among
    those ok, else among those with an orbit, and ``orbit`` there."""
    if tilts.shape[1] == 0:                      # no lanes: one (empty) column of tilts
        tilts = np.full((n, 1), np.nan)
        orbit = {key: np.zeros((n, 1), dtype=np.asarray(val).dtype) for key, val in orbit.items()}
    found = np.isfinite(tilts)
    # the choice is made in degrees, as the rider's table reads the tilts
    degrees = np.degrees(np.where(found, tilts, 0.0))
    pick_ok, any_ok = closest_tilt(degrees, found & (orbit["status"] == Status.OK), upright)
    pick_orbit, any_orbit = closest_tilt(degrees, found & np.isfinite(orbit["omega"]), upright)
    chosen = any_ok | any_orbit
    rows, col = np.arange(n), np.where(any_ok, pick_ok, np.where(any_orbit, pick_orbit, 0))
    out = {key: np.where(chosen, np.asarray(val)[rows, col], np.nan) for key, val in orbit.items()}
    none = ~found[:, 0]
    out["status"] = np.where(none, Status.NO_ORBIT, orbit["status"][rows, col]).astype(np.int8)
    out["reason"] = np.where(none, orbit["reason"][rows, 0], orbit["reason"][rows, col]).astype(np.int8)
    out["alpha"] = np.where(chosen, tilts[rows, col], np.nan)
    out["chosen"] = chosen
    out["tilts"] = tilts
    return out


def speed_is_feasible(theta, speed, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf):
    """bool (n,): some tilt at ``theta`` gives the centre of mass ``speed``
    (n,) with status ok (eqs. M8-M12): a horizontal lane's speed is
    feasible (docs/show.md, "Speed margin")."""
    tilts, orbit = orbits_for_speed(theta, speed, ground, g, machine, mu, max_g)
    return (np.isfinite(tilts) & (orbit["status"] == Status.OK)).any(axis=1)


def orbits_for_speed_on(height, speed, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf):
    """:func:`orbits_for_speed` on any ground (docs/machine.md, "On any
    surface of revolution"): every tilt giving the centre of mass ``speed``
    on the lane at ``height`` [m] ((n,) each, g, mu, max_g and the machine's
    arrays broadcast against them; one ground for all) and
    :func:`~deathsphere.physics.machine_surface.ride_orbit_on`'s quantities
    at each ((n, k)); where none is: NaN, status no_orbit, reason
    machine_no_alpha."""
    args = np.broadcast_arrays(*(np.asarray(x, dtype=float).reshape(-1) for x in
                                 (height, speed, g, mu, max_g, *machine)))
    (height, speed, g, mu, max_g), m = args[:5], MachineArrays(*args[5:])
    tilts = solve_alpha_for_speed_on(height, speed, ground, g, m)
    return tilts, _at_tilts_on(height, tilts, ground, g, m, mu, max_g)


def orbits_for_rate_on(height, omega, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf):
    """:func:`orbits_for_rate` on any ground (docs/machine.md, "On any
    surface of revolution"): every tilt of a steady orbit at the rate
    ``omega`` [rad/s] on the lane at ``height`` [m] and
    :func:`~deathsphere.physics.machine_surface.ride_orbit_on`'s quantities
    at each ((n, k)).  A rate that is not finite and positive (a contact
    speed with the contact on the axis) has no tilt: status no_orbit, reason
    contact_on_axis."""
    args = np.broadcast_arrays(*(np.asarray(x, dtype=float).reshape(-1) for x in
                                 (height, omega, g, mu, max_g, *machine)))
    (height, omega, g, mu, max_g), m = args[:5], MachineArrays(*args[5:])
    moving = np.isfinite(omega) & (omega > 0)
    tilts = solve_alpha_for_rate_on(height, np.where(moving, omega, 1.0), ground, g, m)
    tilts = np.where(moving[:, None], tilts, np.nan)
    orbit = _at_tilts_on(height, tilts, ground, g, m, mu, max_g)
    orbit["reason"] = np.where(moving[:, None], orbit["reason"], Reason.CONTACT_ON_AXIS).astype(np.int8)
    return tilts, orbit


def contact_rate_on(height, v_contact, ground):
    """The orbital rate Omega [rad/s] at which the contact runs along any
    ground at ``v_contact`` [m/s] on the lane at ``height``: v_contact =
    Omega rho_P, rho_P the contact's distance from the axis (as
    :func:`contact_rate` on the globe; beyond the paper, docs/machine.md eq.
    M12r).  NaN where the contact is on the
    axis (a cone's apex)."""
    rho, _ = ground.contact(height)
    rho, v = np.asarray(rho, dtype=float), np.asarray(v_contact, dtype=float)
    scale = np.maximum(np.abs(rho), 1.0)
    on_axis = ~(np.abs(rho) > SINGULAR * scale)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(on_axis, np.nan, v / np.where(on_axis, 1.0, np.abs(rho)))


def _at_tilts_on(height, tilts, ground, g, m: MachineArrays, mu, max_g) -> dict:
    """ride_orbit_on's quantities at the tilts found ((n, k), NaN: none)."""
    rows, cols = np.nonzero(np.isfinite(tilts))
    found = ride_orbit_on(height[rows], tilts[rows, cols], ground, g[rows], m.take(rows), mu[rows], max_g[rows])
    empty = {"status": Status.NO_ORBIT, "reason": Reason.MACHINE_NO_ALPHA}
    orbit = {}
    for key, val in found.items():
        orbit[key] = np.full(tilts.shape, empty.get(key, np.nan), dtype=val.dtype)
        orbit[key][rows, cols] = val
    return orbit


def _upright_on(height, ground):
    """The tilt [deg] of a rider upright on the wall at ``height``: the
    up-axis (-cos alpha, sin alpha) along the inward normal (-sin beta, cos
    beta), alpha = 90 deg - beta (on the globe theta - 90 deg)."""
    return 90.0 - np.degrees(np.asarray(ground.wall_angle(height), dtype=float))


def horizontal_lanes_on(height, speed, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf) -> dict:
    """:func:`horizontal_lanes` on any ground (docs/machine.md, "On any
    surface of revolution"): the lanes at ``height`` [m] (n,) held by the
    centre of mass's ``speed`` [m/s], each ridden at the tilt closest to
    upright on the wall among those ok (else among those with an orbit),
    :func:`~deathsphere.physics.machine_surface.ride_orbit_on`'s keys there."""
    height = np.asarray(height, dtype=float).reshape(-1)
    tilts, orbit = orbits_for_speed_on(height, speed, ground, g, machine, mu, max_g)
    out = _choose(tilts, orbit, _upright_on(height, ground), height.size)
    out["height"] = height
    return out


def horizontal_lanes_at_rate_on(height, omega, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf) -> dict:
    """:func:`horizontal_lanes_on` for lanes held at an orbital rate
    ``omega`` [rad/s] (n,) (eq. M12r: a contact speed, :func:`contact_rate_on`,
    or a lap time)."""
    height = np.asarray(height, dtype=float).reshape(-1)
    tilts, orbit = orbits_for_rate_on(height, omega, ground, g, machine, mu, max_g)
    out = _choose(tilts, orbit, _upright_on(height, ground), height.size)
    out["height"] = height
    return out


def rate_is_feasible_on(height, omega, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf):
    """:func:`rate_is_feasible` on any ground: some tilt at ``height`` turns
    at ``omega`` (n,) with status ok (beyond the paper: docs/machine.md eqs.
    MS1-MS7 and M12r; docs/show.md, "Speed margin")."""
    tilts, orbit = orbits_for_rate_on(height, omega, ground, g, machine, mu, max_g)
    return (np.isfinite(tilts) & (orbit["status"] == Status.OK)).any(axis=1)


def rate_is_feasible(theta, omega, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf):
    """bool (n,): some tilt at ``theta`` gives a steady orbit at the rate
    ``omega`` (n,) with status ok (eqs. M8-M12r): a horizontal lane held by
    its contact's speed or its lap time is feasible (docs/show.md, "Speed
    margin")."""
    tilts, orbit = orbits_for_rate(theta, omega, ground, g, machine, mu, max_g)
    return (np.isfinite(tilts) & (orbit["status"] == Status.OK)).any(axis=1)
