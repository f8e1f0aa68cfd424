"""A rider who loses speed in the act (beyond the paper; docs/show.md, "A
rider who loses speed"): the show's lanes put together with the fall's
physics (:mod:`deathsphere.physics.fall`), vectorised over falls.

At time t the rider's speed drops to a fraction of his speed, along his
direction of travel.  A horizontal rider rides on where some tilt at his
height holds the new speed within mu (``horizontal_holds``; on a drum or a
cone ``horizontal_holds_on``, by the lane's height), a two-wheeler where
some steady turn at his height holds the new rear contact speed within mu
(``turn_holds``, docs/show.md sec. 13), else he leaves the wall at once;
a looper keeps his energy until the loop's normal force vanishes
(``loop_departure``: rides on over the top, swings below the equator, or
falls where it vanishes).  From contact loss his centre of mass
flies a parabola to the globe (``ballistic_landing``), or on a drum or a
cone to its wall or its floor (``landing_on``, docs/show.md sec. 11).  During the flight
he is a sphere of radius width/2 about his centre of mass, each other rider
his envelope in his own lane (the others do not react); the least clearance
is sampled at :data:`FLIGHT_SAMPLES` instants of the flight (``fall``
refines it to 1 mm with the Lipschitz bound of the pairs)."""

from __future__ import annotations

import numpy as np

from deathsphere.physics.fall import (
    FALLS,
    OUTCOMES,
    RIDES_ON,
    SWINGS,
    ballistic_landing,
    drop_velocity,
    horizontal_holds,
    horizontal_holds_on,
    loop_departure,
    loop_state,
)
from deathsphere.act.envelope import point_segment_distance
from deathsphere.physics.landing import landing_on
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.records.two_wheeler import TwoWheeler

#: Instants of each flight at which the clearance to every other rider is sampled.
FLIGHT_SAMPLES = 64
_Z = np.array([0.0, 0.0, 1.0])[:, None]


def _angles(x, r):
    """theta and phi [deg] of the points x (3, n) on the globe (phi 0..360)."""
    rad = np.sqrt(np.sum(x * x, axis=0))
    theta = np.degrees(np.arccos(np.clip(x[2] / np.where(rad > 0, rad, 1.0), -1.0, 1.0)))
    return theta, np.degrees(np.arctan2(x[1], x[0])) % 360.0


def _effective_inertia(lane, g: float) -> float:
    """M of eq. M21 from the loop's rates at top and bottom (M23: M = 4 m g
    r_G / (psidot_b^2 - psidot_t^2)), ride's own numbers."""
    r_g = lane.points["com"]
    return 4.0 * lane.machine.mass * g * r_g / (lane.rate_bottom ** 2 - lane.rate ** 2)


def _held(lane, globe, kin, fraction):
    """(n,) bool: the horizontal lane still holds its rider after the drop
    to ``fraction`` of his speed (the lane's kinematics ``kin`` at the
    falls' times).  A single-contact machine: some tilt gives a steady
    orbit at the dropped centre of mass's speed.  A two-wheeler: some steady
    turn at the rear contact's speed times ``fraction`` (its whole
    configuration turns at one rate, so every point's speed drops by the
    same fraction), ok within mu (and no max_g, as the machine's test)."""
    # the globe's lane by its polar angle, a wall's by its height (lanes.py)
    where = lane.theta if globe.is_globe else lane.height
    if isinstance(lane.machine, TwoWheeler):
        # the two-wheeler's equations are imported only for an act that has one
        from deathsphere.physics.two_wheeler.holds import turn_holds

        t = lane.machine
        return turn_holds(where, fraction * lane.orbit["v_contact"], t.parameters(), globe.ground, globe.g, t.head,
                          globe.mu)["holds"]
    speed = np.sqrt(np.sum(kin["v_com"] ** 2, axis=0))
    holds = horizontal_holds if globe.is_globe else horizontal_holds_on
    return holds(where, fraction * speed, lane.alpha, globe.ground, globe.g, machine_arrays(lane.machine),
                 globe.mu)["holds"]


def _one_lane(lane, globe, t, fraction) -> dict:
    """The falls of one rider at the times t with the fractions, (n,) each."""
    m, n = lane.machine, t.size
    # a two-wheeler's 'com' is the whole machine's (rider included) and its 'contact' the rear contact's
    kin = lane.kinematics(t)
    out = {"outcome": np.full(n, RIDES_ON, dtype=np.int8), "t_lost": np.full(n, np.nan),
           "x0": np.full((3, n), np.nan), "v0": np.full((3, n), np.nan), "contact_lost": np.full((3, n), np.nan),
           "swing_height": np.full(n, np.nan)}
    if lane.kind == "horizontal":
        falls = ~_held(lane, globe, kin, fraction)
        out["outcome"] = np.where(falls, FALLS, RIDES_ON).astype(np.int8)
        out["t_lost"] = np.where(falls, t, np.nan)
        out["x0"] = np.where(falls, kin["com"], np.nan)
        out["v0"] = np.where(falls, drop_velocity(kin["v_com"], fraction), np.nan)
        out["contact_lost"] = np.where(falls, kin["contact"], np.nan)
        return out
    r, r_g = globe.r, lane.points["com"]
    psidot = np.sqrt(np.sum(kin["v_com"] ** 2, axis=0)) / r_g
    dep = loop_departure(kin["psi"], fraction * psidot, r, r_g, _effective_inertia(lane, globe.g), m.mass, globe.g)
    falls = dep["outcome"] == FALLS
    x0, v0 = loop_state(np.where(falls, dep["psi_lost"], 0.0), np.where(falls, dep["psi_dot_lost"], 0.0), r_g,
                        lane.azimuth)
    out["outcome"] = dep["outcome"]
    out["t_lost"] = np.where(falls, t + dep["t_lost"], np.nan)
    out["x0"], out["v0"] = np.where(falls, x0, np.nan), np.where(falls, v0, np.nan)
    out["contact_lost"] = np.where(falls, r * x0 / r_g, np.nan)
    swings = dep["outcome"] == SWINGS
    out["swing_height"] = np.where(swings, r * (1.0 + np.cos(dep["psi_max"])), np.nan)
    return out


def simulate_falls(lanes, globe, rider, t, fraction, samples: int = FLIGHT_SAMPLES) -> dict:
    """Falls of the riders ``rider`` (indices into lanes, (n,)) at the times
    t (n,) [s] with the speed fractions (n,): dict of (n,) arrays
    ``outcome`` (int8 codes of OUTCOMES), ``t_lost``, ``theta_lost``,
    ``phi_lost``, ``t_land``, ``theta_land``, ``phi_land``, ``fall_time``,
    ``impact_speed``, ``swing_height`` (contact's height at a swing's
    highest point [m]), ``height_lost`` and ``height_land`` (above the
    floor [m]: where contact is lost, the landing point), (3, n) ``x0``,
    ``v0`` (start of the flight), and
    (n, riders) ``clearance`` [m], ``t_min`` [s] (NaN for the rider himself
    and where he does not fly).  One pass per rider, vectorised over his falls."""
    rider, t, fraction = (np.asarray(x).reshape(-1) for x in (rider, t, fraction))
    t, fraction = t.astype(float), fraction.astype(float)
    n = t.size
    res = {"outcome": np.zeros(n, dtype=np.int8), "t_lost": np.full(n, np.nan), "x0": np.full((3, n), np.nan),
           "v0": np.full((3, n), np.nan), "contact_lost": np.full((3, n), np.nan), "swing_height": np.full(n, np.nan)}
    for k, lane in enumerate(lanes):
        sel = np.flatnonzero(rider == k)
        if sel.size:
            part = _one_lane(lane, globe, t[sel], fraction[sel])
            for key, val in part.items():
                res[key][..., sel] = val
    flying = res["outcome"] == FALLS
    (_land_on_the_globe if globe.is_globe else _land_on_a_wall)(res, globe, flying)
    flight = res["fall_time"]
    res["clearance"], res["t_min"] = _victims(lanes, globe.g, rider, res, flight, samples)
    return res


def _land_on_the_globe(res: dict, globe, flying) -> None:
    """The flights of ``res`` in the globe (:func:`ballistic_landing`, the
    sphere's quartic), into ``res``: theta and phi of the contact lost and
    of the landing point, heights above the floor."""
    land = ballistic_landing(np.where(flying, res["x0"], 0.0), np.where(flying, res["v0"], 0.0), globe.ground,
                             globe.g)
    flight = np.where(flying, land["t_land"], np.nan)
    res["theta_lost"], res["phi_lost"] = _angles(res["contact_lost"], globe.r)
    res["fall_time"] = flight
    res["t_land"] = res["t_lost"] + flight
    res["theta_land"], res["phi_land"] = _angles(np.where(flying, land["x_land"], np.nan), globe.r)
    res["impact_speed"] = np.where(flying, land["impact_speed"], np.nan)
    # heights above the floor (the globe is centred at the origin, z up)
    res["height_lost"] = res["contact_lost"][2] + globe.r
    res["height_land"] = np.where(flying, land["x_land"][2], np.nan) + globe.r


def _land_on_a_wall(res: dict, globe, flying) -> None:
    """The flights of ``res`` on a drum or a cone (:func:`landing_on`: to
    the wall or the floor), into ``res``: theta is the globe's (NaN here),
    phi the azimuth about the axis, heights above the floor."""
    land = landing_on(np.where(flying, res["x0"], 0.0), np.where(flying, res["v0"], 0.0), globe.ground, globe.g)
    flight = np.where(flying, land["t_land"], np.nan)
    x_land = np.where(flying, land["x_land"], np.nan)
    res["fall_time"] = flight
    res["t_land"] = res["t_lost"] + flight
    res["impact_speed"] = np.where(flying, land["impact_speed"], np.nan)
    for end, x in (("lost", res["contact_lost"]), ("land", x_land)):
        res[f"theta_{end}"] = np.full(flight.shape, np.nan)
        res[f"phi_{end}"] = np.degrees(np.arctan2(x[1], x[0])) % 360.0
        res[f"height_{end}"] = x[2] - globe.ground.lowest


def flight_point(x0, v0, s, g):
    """The centre of mass (3, ...) a time s after contact loss."""
    return x0 + v0 * s - 0.5 * g * s * s * _Z.reshape((3,) + (1,) * (np.ndim(s)))


def _victims(lanes, g: float, rider, res, flight, samples: int):
    """Least sampled clearance (n, riders) between each flying rider's sphere
    and every other rider's envelope during the flight, and when."""
    n = rider.size
    clear = np.full((n, len(lanes)), np.nan)
    when = np.full((n, len(lanes)), np.nan)
    flying = np.flatnonzero(np.isfinite(flight))
    if not flying.size:
        return clear, when
    frac = np.linspace(0.0, 1.0, samples)
    s = flight[flying, None] * frac                                   # (m, K) after contact loss
    times = res["t_lost"][flying, None] + s
    x0, v0 = res["x0"][:, flying, None], res["v0"][:, flying, None]
    point = x0 + v0 * s - 0.5 * g * s * s * _Z[:, :, None]            # (3, m, K)
    radius = np.array([lanes[k].width_m for k in rider[flying]]) * 0.5
    for k, victim in enumerate(lanes):
        # the least over the victim's segments (a two-wheeler's several, a machine's one)
        d = np.minimum.reduce([point_segment_distance(point, p0.reshape(point.shape), p1.reshape(point.shape))
                               for p0, p1 in victim.segment_ends(times.reshape(-1))])
        d = d - radius[:, None] - 0.5 * victim.width_m
        best = np.argmin(d, axis=1)
        rows = np.arange(flying.size)
        own = rider[flying] == k
        clear[flying, k] = np.where(own, np.nan, d[rows, best])
        when[flying, k] = np.where(own, np.nan, times[rows, best])
    return clear, when


def refine_victim(lane_f, victim, x0, v0, t_lost: float, flight: float, g: float):
    """(least clearance [m] to 1 mm, when [s]) of one flight against one
    envelope (:func:`deathsphere.act.pairs.minimise` with the bound: the
    flying point's greatest speed, at the start or the landing, plus the
    envelope's)."""
    from deathsphere.act.pairs import minimise

    radii = 0.5 * (lane_f.width_m + victim.width_m)
    x0, v0 = np.asarray(x0, dtype=float).reshape(3, 1), np.asarray(v0, dtype=float).reshape(3, 1)
    speed = max(float(np.linalg.norm(v0)), float(np.linalg.norm(v0[:, 0] - g * flight * _Z[:, 0])))

    def gap(s):
        x = x0 + v0 * s - 0.5 * g * s * s * _Z
        return np.minimum.reduce([point_segment_distance(x, p0, p1) for p0, p1 in victim.segment_ends(t_lost + s)]) \
            - radii

    c, s = minimise(gap, 0.0, flight, speed + victim.speed_bound())
    return c, t_lost + s


OUTCOME_NAMES = np.array(OUTCOMES, dtype=object)


def outcome_names(codes) -> np.ndarray:
    """The outcome codes as their names (rides_on, swings, falls)."""
    return OUTCOME_NAMES[np.asarray(codes, dtype=np.int64)]


def fall_chunk(item):
    """One chunk of a Monte Carlo (a picklable work item for
    :func:`deathsphere.parallel.ordered_map`): (lanes, globe, rider, t,
    fraction) -> :func:`simulate_falls`'s dict."""
    lanes, globe, rider, t, fraction = item
    return simulate_falls(lanes, globe, rider, t, fraction)


__all__ = ["simulate_falls", "refine_victim", "fall_chunk", "outcome_names", "FLIGHT_SAMPLES"]
