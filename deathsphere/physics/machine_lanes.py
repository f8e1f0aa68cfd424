"""A machine's lane at a given speed: every tilt that gives a height and a
speed, the orbit at each, and the one a rider takes (beyond the paper;
docs/machine.md eqs. M8-M12, docs/show.md "Lanes").

Vectorised over lanes: arrays of contact polar angles theta [rad] and
centre-of-mass speeds [m/s] (n,), the ground (a
:class:`~deathsphere.physics.ground.Sphere`), gravity and the machine's
arrays (:class:`~deathsphere.physics.machine_arrays.MachineArrays`, one
machine or one per lane) broadcast against them.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.ground import Sphere
from deathsphere.physics.machine import ride_orbit, solve_alpha_for_speed
from deathsphere.physics.machine_arrays import MachineArrays
from deathsphere.physics.machine_surface import ride_orbit_on, solve_alpha_for_speed_on
from deathsphere.physics.status import Reason, Status

__all__ = ["orbits_for_speed", "closest_tilt", "horizontal_lanes", "speed_is_feasible", "orbits_for_speed_on"]


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
    rows, cols = np.nonzero(np.isfinite(tilts))
    found = ride_orbit(theta[rows], tilts[rows, cols], Sphere(r[rows]), g[rows], m.take(rows), mu[rows],
                       max_g[rows])
    empty = {"status": Status.NO_ORBIT, "reason": Reason.MACHINE_NO_ALPHA}
    orbit = {}
    for key, val in found.items():
        orbit[key] = np.full(tilts.shape, empty.get(key, np.nan), dtype=val.dtype)
        orbit[key][rows, cols] = val
    return tilts, orbit


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
    tilts, orbit = orbits_for_speed(theta, speed, ground, g, machine, mu, max_g)
    if tilts.shape[1] == 0:                      # no lanes: one (empty) column of tilts
        tilts = np.full((theta.size, 1), np.nan)
        orbit = {key: np.zeros((theta.size, 1), dtype=np.asarray(val).dtype) for key, val in orbit.items()}
    found = np.isfinite(tilts)
    upright = np.degrees(theta) - 90.0
    # the choice is made in degrees, as the rider's table reads the tilts
    degrees = np.degrees(np.where(found, tilts, 0.0))
    pick_ok, any_ok = closest_tilt(degrees, found & (orbit["status"] == Status.OK), upright)
    pick_orbit, any_orbit = closest_tilt(degrees, found & np.isfinite(orbit["omega"]), upright)
    chosen = any_ok | any_orbit
    rows, col = np.arange(theta.size), np.where(any_ok, pick_ok, np.where(any_orbit, pick_orbit, 0))
    out = {key: np.where(chosen, np.asarray(val)[rows, col], np.nan) for key, val in orbit.items()}
    none = ~found[:, 0]
    out["status"] = np.where(none, Status.NO_ORBIT, orbit["status"][rows, col]).astype(np.int8)
    out["reason"] = np.where(none, Reason.MACHINE_NO_ALPHA, orbit["reason"][rows, col]).astype(np.int8)
    out["height"] = np.broadcast_to(ground.height(theta), theta.shape)
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
    rows, cols = np.nonzero(np.isfinite(tilts))
    found = ride_orbit_on(height[rows], tilts[rows, cols], ground, g[rows], m.take(rows), mu[rows], max_g[rows])
    empty = {"status": Status.NO_ORBIT, "reason": Reason.MACHINE_NO_ALPHA}
    orbit = {}
    for key, val in found.items():
        orbit[key] = np.full(tilts.shape, empty.get(key, np.nan), dtype=val.dtype)
        orbit[key][rows, cols] = val
    return tilts, orbit
