"""``ride`` on the wall of death's drum, the well of death's cone, flat
ground and a profile: a machine's steady laps on any ground but the globe (beyond the paper;
docs/machine.md, "On any surface of revolution" and "The wall of death").

The globe stays on :mod:`deathsphere.api.rides` (its tables byte for
byte); this module takes the lane by its height up the wall (on flat
ground its turn radius), the tilt,
the contact's speed, the centre of mass's speed or the lap time, and gives the same columns, theta empty and the
arena's in ``surface``, ``rho_contact_m``, ``wall_angle_deg``; the
stability on each is the exact linearisation of the machine's equations
of motion there (docs/machine.md, "On any ground"; a profile's, "On a
profile").
"""

from __future__ import annotations

import math

import numpy as np

from deathsphere.api.arguments import (TILTS_PER_SPEED, broadcast_flat, checked_array, checked_flag, grid_shape,
                                      refuse_large_grid)
from deathsphere.params import ParameterError, reduce_angle
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.physics.machine_lanes import contact_rate_on, orbits_for_rate_on, orbits_for_speed_on
from deathsphere.physics.machine_surface import ride_orbit_on
from deathsphere.physics.status import Reason, Status
from deathsphere.requests.arena import lane_key, refuse_above_top
from deathsphere.requests.arena import names_a_wall  # noqa: F401  (the CLI asks through the API)

__all__ = ["ride_on_surface"]


def _lanes(ground, height) -> np.ndarray:
    """The heights, each on the wall: above the ground's highest lane (its
    wall's top, a cone's apex, a profile's last sample) refused in one line;
    flat ground has no top (its lane is a turn radius)."""
    if np.size(height):
        refuse_above_top(ground, float(np.max(height)))
    return height


def floor_radius(ground) -> float:
    """The arena's radius at its floor [m]: the contact's distance from the
    axis on the lowest lane (the ground protocol's answer, whatever the
    ground); NaN for a ground with no radius to name (flat ground, a
    profile: the ``r_m`` column is empty there, as ``orbit``'s)."""
    if not hasattr(ground, "radius"):
        return math.nan
    rho, _ = ground.contact(np.zeros(1))
    return float(np.asarray(rho).reshape(-1)[0])


def _lane_typed(ground, typed: dict):
    """The lane's keyword on ``ground`` (``height`` up a wall, ``turn_radius``
    on flat ground: requests.arena's ``lane_key``) and its values; the other
    one typed is refused naming it."""
    key = lane_key(ground)
    other = "turn_radius" if key == "height" else "height"
    if typed.get(other) is not None:
        where = ("a lane is its turn_radius (the contact's distance from the turn's centre)" if key == "turn_radius"
                 else "a lane is its height above the floor")
        raise ParameterError(f"{other} is not a lane on the {ground.name}: {where}", other)
    if typed.get(key) is None:
        what = ("the contact's distance from the turn's centre" if key == "turn_radius"
                else f"the contact's height above the {ground.name}'s floor")
        raise ParameterError(f"give {key} ({what})", key, missing=True)
    return key, typed[key]


def ride_on_surface(ground, typed: dict, m, options, rides):
    """``ride``'s table on ``ground`` (not the globe): ``typed`` the
    keywords as given (height, alpha or speed, g, mu, max_g; theta is
    refused: a lane on a wall is its height), ``m`` the machine record,
    ``options`` the :class:`~deathsphere.api.rides.RideOptions`, ``rides``
    the module whose table builder and rider's table it shares."""
    if checked_flag("vertical", typed.get("vertical", False)):
        # the machine's loop inside a profile closed over the top (docs/machine.md sec. 10, eqs. M25-M30)
        from deathsphere.api.ride_loops import ride_loop_on

        return ride_loop_on(ground, typed, m, options, rides)
    if typed.get("theta") is not None:
        raise ParameterError(f"theta is the globe's polar angle: on a {ground.name} give {lane_key(ground)} (the "
                             + ("contact's distance from the turn's centre)" if lane_key(ground) == "turn_radius"
                                else "contact's height above the floor)"), "theta")
    if typed.get("v_top") is not None:
        raise ParameterError(f"v_top is a vertical loop's top speed: give vertical (a loop inside a profile closed "
                             f"over the top), or {lane_key(ground)} for a horizontal lane", "v_top")
    at, where = _lane_typed(ground, typed)
    holds = [key for key in ("alpha", "speed", "com_speed", "period") if typed.get(key) is not None]
    if len(holds) != 1:
        raise ParameterError("give exactly one of alpha, speed (the contact's), com_speed (the centre of mass's) "
                             "and period" + (f" (got {' and '.join(holds)})" if holds else ""),
                             holds[1] if len(holds) > 1 else "alpha", missing=not holds)
    how = holds[0]
    by_value = how != "alpha"
    checked = {at: checked_array(at, where), how: checked_array(how, typed[how]),
               **{k: checked_array(k, typed[k]) for k in ("g", "mu", "max_g")}}
    refuse_large_grid(grid_shape(checked), command="ride", limit=rides.MAX_RIDE_ROWS,
                      per_point=TILTS_PER_SPEED if by_value else 1)
    shape, flat = broadcast_flat(checked)
    n = math.prod(shape)
    radius = floor_radius(ground)
    if m.wheel_radius >= radius:        # a drum or a cone; elsewhere each lane's fit is its status (MS6)
        raise ParameterError(f"the wheel (a = {m.wheel_radius:g} m) does not fit in a {ground.name} of radius "
                             f"{radius:g} m at its floor (needs r > a)", "r")
    height, g, mu, max_g = _lanes(ground, flat[at]), flat["g"], flat["mu"], flat["max_g"]
    arrays = machine_arrays(m)
    if by_value:
        value = flat[how]
        if how == "com_speed":
            tilts, orbits = orbits_for_speed_on(height, value, ground, g, arrays, mu, max_g)
        else:
            # the contact's speed and a lap time each fix the rate: v_contact = Omega rho_P, Omega = 2 pi / T
            omega = contact_rate_on(height, value, ground) if how == "speed" else 2.0 * np.pi / value
            tilts, orbits = orbits_for_rate_on(height, omega, ground, g, arrays, mu, max_g)
        reps = np.maximum(np.isfinite(tilts).sum(axis=1), 1)
        req = np.repeat(np.arange(n), reps)
        slot = np.arange(req.size) - np.repeat(np.cumsum(reps) - reps, reps)
        alpha = tilts[req, slot] if tilts.shape[1] else np.full(req.size, np.nan)
        if tilts.shape[1]:
            res = {key: val[req, slot] for key, val in orbits.items()}
        else:
            res = {key: np.full(req.size, np.nan) for key in orbits}
            res["status"] = np.full(req.size, Status.NO_ORBIT, dtype=np.int8)
            res["reason"] = np.full(req.size, Reason.MACHINE_NO_ALPHA, dtype=np.int8)
        echo = {"speed": "v_contact_m_s", "com_speed": "v_cm_m_s", "period": "period_s"}[how]
        given = {echo: value[req]} if at != "height" else {echo: value[req], "height_m": height[req]}
    else:
        req = np.arange(n)
        alpha = np.radians(reduce_angle(flat["alpha"]))
        res = {k: np.asarray(v).reshape(-1) for k, v in
               ride_orbit_on(height, alpha, ground, g, arrays, mu, max_g).items()}
        given = {"alpha_deg": flat["alpha"].astype(float)}
        if at == "height":
            given["height_m"] = height
    # every row's lane, with a tilt or not (on flat ground its height is 0, the lane its turn radius)
    rho, z = ground.contact(height[req])
    res["height"] = np.asarray(z, dtype=float) - ground.lowest
    res["rho_contact"] = np.asarray(rho, dtype=float)
    res["wall_angle"] = np.asarray(ground.wall_angle(height[req]), dtype=float)
    run = rides.RowRun(np.full(req.size, radius), g[req], mu[req], max_g[req])
    # the machine's equations of motion take the ground's parallel surface: a quadric on the drum, the cone
    # and flat ground, a profile's meridian moved along its normal on a profile (docs/machine.md)
    table = rides._table(req, np.full(req.size, np.nan), alpha, run, res, m, stability=options.stability,
                         given=given, stability_note="", lanes=(ground, height[req]))
    if len(table) == n and shape:
        table = type(table)(table.columns, shape=shape)
    if options.summary:
        return rides.ride_summary(table, groups=rides._contact_groups(checked, shape, how),
                                  tried="speeds" if by_value else "tilts")
    return options.kept(table)
