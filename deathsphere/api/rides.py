"""Steady horizontal orbits of a machine (a motorcycle and rider) inside the
globe: ``deathsphere ride`` (docs/machine.md; beyond the paper, which it
contains as the machine ``paper-wheel``)."""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from deathsphere.api.arguments import (
    INF,
    TILTS_PER_SPEED,
    G,
    R,
    broadcast_flat,
    checked_array,
    checked_flag,
    checked_statuses,
    grid_shape,
    refuse_large_grid,
)
from deathsphere.params import ParameterError, reduce_angle
from deathsphere.physics.ground import Sphere
from deathsphere.physics.machine import ride_orbit
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.physics.machine_lanes import contact_rate, orbits_for_rate, orbits_for_speed
from deathsphere.records.machine import Machine
from deathsphere.records.machine_presets import DEFAULT_MACHINE, as_machine
from deathsphere.physics.stability import methods
from deathsphere.physics.status import REASON_TEXT, STATUS_LABELS, Reason, Status
from deathsphere.requests.decode import decode_rider, decode_run
from deathsphere.requests.keys import Keys
from deathsphere.requests.records import ComSpeed, ContactSpeed, Period, RiderRequest, Run, Theta, Tilt
from deathsphere.table import Table

#: Orbits evaluated per piece (temporaries stay in cache, as the wheel's).
CHUNK = 1 << 14
#: Orbits per batch of the stability analysis: the per-batch overhead
#: against temporaries falling out of cache (measured fastest of 128..16384;
#: docs/machine.md, "Performance").
STABILITY_CHUNK = 4096
#: Rows one call may return (about 1 GiB at ~500 bytes a row).
MAX_RIDE_ROWS = 2_000_000

#: The columns of ``deathsphere ride``, in order.
RIDE_COLUMNS = (
    "input_row", "machine", "theta_deg", "alpha_deg", "lean_deg", "r_m", "height_m", "g_m_s2", "mu_available",
    "max_g", "status", "reason", "omega_rad_s", "period_s", "v_cm_m_s", "v_cm_km_h", "v_contact_m_s",
    "wheel_spin_rad_s", "com_orbit_radius_m", "normal_per_mass_m_s2", "friction_per_mass_m_s2", "mu_required",
    "load_g", "head_clearance_m", "stability", "stability_method", "growth_rate_1_s", "freq_slow_rad_s",
    "freq_fast_rad_s", "surface", "rho_contact_m", "wall_angle_deg", "stability_kind",
)

#: What ``stability_method`` says on every analysed row (docs/machine.md sec. 5; its sentence:
#: :data:`deathsphere.physics.stability.methods.METHOD_TEXT`).
STABILITY_METHOD = methods.EXACT_STEER_LOCKED

_PHYS = {"omega": "omega_rad_s", "period": "period_s", "v_cm": "v_cm_m_s", "v_contact": "v_contact_m_s",
         "spin": "wheel_spin_rad_s", "r_g": "com_orbit_radius_m", "normal": "normal_per_mass_m_s2",
         "friction": "friction_per_mass_m_s2", "mu_required": "mu_required", "load_g": "load_g",
         "head_clearance": "head_clearance_m"}


def _evaluate(theta, alpha, r, g, mu, max_g, m: Machine) -> dict:
    """ride_orbit over flat arrays, piece by piece; scalars stay scalars."""
    n = theta.size
    arrays = machine_arrays(m)
    pieces = []
    uniform = [x if x.size == 1 else None for x in (r, g, mu, max_g)]
    for start in range(0, n, CHUNK):
        sl = slice(start, start + CHUNK)
        rr, gg, mm, xg = ((float(u[0]) if u is not None else x[sl]) for u, x in zip(uniform, (r, g, mu, max_g)))
        pieces.append(ride_orbit(theta[sl], alpha[sl], Sphere(rr), gg, arrays, mu=mm, max_g=xg))
    if len(pieces) == 1:
        return {k: np.asarray(v).reshape(-1) for k, v in pieces[0].items()}
    return {k: np.concatenate([np.asarray(p[k]).reshape(-1) for p in pieces]) for k in pieces[0]}


class RowRun(NamedTuple):
    """A run's values row by row, as the rows of a table hold them (flat
    arrays, or one value for every row): the globe's radius [m], gravity
    [m/s^2], the friction available and the largest load [g]."""

    r: object
    g: object
    mu: object
    max_g: object


def _table(req_index, theta, alpha, run: RowRun, res, m: Machine, stability: bool, shape=None,
           given: dict | None = None, axes=None, stability_note: str = "", lanes=None) -> Table:
    """The rows of ``ride``.  ``given`` holds the requested inputs per row
    (``theta_deg``, ``alpha_deg``, ``v_contact_m_s``, ``v_cm_m_s``,
    ``period_s``, NaN where not given), echoed as typed rather than as
    recomputed (docs/contract.md).  The arena is the globe, or ``lanes``'
    ground; its contact
    radius and wall angle are ``res``'s ``rho_contact`` and ``wall_angle``
    where given, else the globe's (r sin(theta), 180 deg - theta).
    ``stability_note``: what the stability method says on the rows with an
    orbit when not analysed.  ``lanes``: off the globe, (ground, the
    rows' lane heights [m]): its name is the ``surface`` and the stability
    is on that ground (the rows' theta are empty)."""
    r, g, mu, max_g = run
    n = theta.size
    given = given or {}
    status = res["status"]
    cols = {
        "input_row": req_index + 1,
        "machine": np.full(n, m.name, dtype=object),
        "theta_deg": np.degrees(theta),
        "alpha_deg": np.degrees(alpha),
        "lean_deg": 90.0 - np.degrees(alpha),
        "r_m": np.broadcast_to(r, (n,)),
        "height_m": res["height"],
        "g_m_s2": np.broadcast_to(g, (n,)),
        # inf ("no limit") is empty, as in every table (never inf in a row)
        "mu_available": np.where(np.isinf(np.broadcast_to(mu, (n,))), np.nan, np.broadcast_to(mu, (n,))),
        "max_g": np.where(np.isinf(np.broadcast_to(max_g, (n,))), np.nan, np.broadcast_to(max_g, (n,))),
        "status": STATUS_LABELS[status],
        "reason": REASON_TEXT[res["reason"]],
    }
    for name, values in given.items():  # inputs as given
        cols[name] = np.where(np.isnan(values), cols.get(name, np.nan), values)
    for key, col in _PHYS.items():
        cols[col] = res[key]
        if col in given:
            cols[col] = np.where(np.isnan(given[col]), cols[col], given[col])
        if key == "v_cm":
            # a rider's unit beside SI; rounded at 1e-9 km/h so that a speed
            # typed in km/h reads back as typed (40, not 40.00000000000001)
            cols["v_cm_km_h"] = np.round(cols[col] * 3.6, 9)
    has_orbit = (status == Status.OK) | (status == Status.SLIPS) | (status == Status.OVER_G)
    blank = np.full(n, "", dtype=object)
    cols["stability"], cols["stability_method"], cols["stability_kind"] = blank, blank.copy(), blank.copy()
    for key in ("growth_rate_1_s", "freq_slow_rad_s", "freq_fast_rad_s"):
        cols[key] = np.full(n, np.nan)
    rows = np.flatnonzero(has_orbit) if stability else np.zeros(0, dtype=np.int64)
    if stability_note:
        cols["stability_method"][has_orbit] = stability_note
    _arena_columns(cols, res, "sphere" if lanes is None else lanes[0].name, run.r, theta, n)
    if rows.size:
        from deathsphere.physics.machine_dynamics import machine_stability, yaw_is_determined
        from deathsphere.physics.machine_dynamics_on import machine_stability_on
        from deathsphere.physics.stability.verdict import VERDICT_LABELS, stability_kind

        rr, gg = np.broadcast_to(r, (n,)), np.broadcast_to(g, (n,))
        arrays = machine_arrays(m)
        if not yaw_is_determined(arrays):
            cols["stability_method"][rows] = methods.NOT_ANALYSED_POINT_MASS
            rows = rows[:0]
        for start in range(0, rows.size, STABILITY_CHUNK):
            idx = rows[start:start + STABILITY_CHUNK]
            if lanes is None:
                st = machine_stability(theta[idx], alpha[idx], Sphere(rr[idx]), gg[idx], arrays)
            else:
                st = machine_stability_on(lanes[1][idx], alpha[idx], lanes[0], gg[idx], arrays)
            cols["stability"][idx] = VERDICT_LABELS[st["verdict"]]
            cols["stability_method"][idx] = STABILITY_METHOD
            cols["growth_rate_1_s"][idx] = st["growth_rate"]
            cols["freq_slow_rad_s"][idx] = st["freq_slow"]
            cols["freq_fast_rad_s"][idx] = st["freq_fast"]
            cols["stability_kind"][idx] = stability_kind(st["growth_rate"], st["rate_scale"])
    return Table({name: cols[name] for name in RIDE_COLUMNS}, shape=shape, axes=axes)


def _arena_columns(cols: dict, res: dict, surface: str, r, theta, n: int) -> None:
    """The arena's columns, appended to the ride table (docs/contract.md):
    the surface's name, the contact's distance from the axis [m] and the
    wall angle from the horizontal [deg] (on the globe 180 - theta)."""
    cols["surface"] = np.full(n, surface, dtype=object)
    if "rho_contact" in res:
        cols["rho_contact_m"] = np.asarray(res["rho_contact"], dtype=float).reshape(-1)
        cols["wall_angle_deg"] = np.degrees(np.asarray(res["wall_angle"], dtype=float).reshape(-1))
    else:
        cols["rho_contact_m"] = np.broadcast_to(r, (n,)) * np.sin(theta)
        cols["wall_angle_deg"] = 180.0 - np.degrees(theta)


def ride(theta=None, alpha=None, *, machine=DEFAULT_MACHINE, r=R, g=G, mu=INF, max_g=INF, speed=None, diameter=None,
         height=None, com_speed=None, period=None, only=None, stability: bool = True, vertical: bool = False, v_top=None, summary: bool = False,
         mass=None, com_height=None, wheel_radius=None, tyre_radius=None, roll_inertia=None, pitch_inertia=None,
         yaw_inertia=None, spin_inertia=None, head_height=None, flat: bool = False, steer=None,
         steer_torque=None, surface=None, wall_angle=None, wall_height=None, profile=None,
         turn_radius=None) -> Table:
    """Steady horizontal orbits of a machine inside the globe: ``deathsphere ride``.

    Beyond the paper (docs/machine.md eqs. M1-M12): a single-contact
    gyrostat (motorcycle and rider, wheels spinning) rolling without
    slipping on the inside of a sphere.  All numeric arguments broadcast
    like numpy arrays, as in :func:`deathsphere.orbit`.

    Parameters
    ----------
    theta : float or array_like
        Polar angle of the contact point from the upward vertical [deg]
        (180 = the floor, 90 = the equator); or give ``height``.
    alpha : float or array_like
        Tilt of the machine's up-axis above the orbit plane [deg] (the
        paper's alpha for its wheel; lean from the vertical = 90 - alpha).
        Give exactly one of ``alpha``, ``speed``, ``com_speed`` and ``period``.
    machine : Machine or str
        A :class:`deathsphere.Machine` or a preset's name
        (``deathsphere.api.machines.PRESETS``; ``deathsphere machines``),
        ``"stunt125"`` by default, as the command's.
    mass, com_height, wheel_radius, tyre_radius, roll_inertia, pitch_inertia, yaw_inertia, spin_inertia, head_height
        The machine's overrides, named as the command line's options
        (``--mass`` ...), numbers in SI or text with a unit (``"16in"``):
        the machine with these replaced (:meth:`Machine.with_overrides`).
    r, diameter : sphere radius or diameter [m] (one of them); on a drum or
        a cone its radius or diameter at the floor.
    surface, wall_angle, wall_height : str, float or str
        The arena (docs/machine.md, "On any surface of revolution"):
        ``"sphere"`` (the globe, default), ``"cylinder"`` (the wall of
        death's drum) or ``"cone"`` (the well of death, its wall at
        ``wall_angle`` degrees from the horizontal); ``wall_height`` the
        wall's top above the floor (a lane above it is refused).  On a drum
        or a cone the lane is given by ``height`` (theta is refused), one
        radius, no vertical loops; the stability is the machine's exact
        linearisation on that ground (docs/machine.md, "On any ground"; on
        a profile, "On a profile").  ``"plane"``: flat ground, a lane by ``turn_radius``;
        ``"profile"``: the meridian ``profile`` (a CSV file's path or a
        :class:`~deathsphere.physics.ground.Profile`), a lane by ``height``.
        A two-wheeler (``steer``, ``steer_torque``) rides the drum, the
        cone and a profile too, with its stability (docs/two-wheeler.md sec. 12).
    profile, turn_radius : str or Profile, float or array_like
        The meridian of ``surface="profile"``; the contact's distance from
        the turn's centre [m] on ``surface="plane"``.
    g, mu, max_g : gravity [m/s^2]; friction available; the largest load_g
        (|contact force| / (m g), what the rider feels) allowed.
    speed : float or array_like
        The contact's speed along the ground [m/s], what a speedometer reads
        (``v_contact_m_s``): the contact runs round its parallel of radius
        r sin(theta), so it fixes the rate Omega = speed / (r sin(theta));
        every tilt in the range where the wheel fits that turns at that rate
        (docs/machine.md eq. M12r), one row each (``input_row`` shared); a
        speed no tilt gives is one ``no_orbit`` row (as is a contact on the
        axis, theta 0 or 180, which does not move: reason contact_on_axis).
        A two-wheeler's is its rear contact's.
    com_speed : float or array_like
        The centre of mass's speed [m/s] instead (``v_cm_m_s``; eq. M12):
        what ``speed`` meant before; every tilt giving it, as for ``speed``.
    period : float or array_like
        The lap time [s] instead (``period_s``): the rate Omega = 2 pi /
        period, every tilt giving it, as for ``speed``.
    height : float or array_like
        Height of the contact point above the globe's floor [m] instead of
        theta: theta = arccos(height / r - 1).
    only : status or list of statuses to keep (not with ``summary``).
    summary : bool
        The rider's table instead (:func:`ride_summary`, ``ride
        --summary``): one row per contact point asked for, over the speeds
        (or tilts) tried there.
    stability : bool
        Fill the stability columns (see ``stability_method``).
    vertical, v_top : bool, float or array_like
        A vertical loop instead (docs/machine.md sec. 10): theta is the cone
        angle (90 = a great circle), ``v_top`` the centre of mass's speed at
        the top [m/s]; columns :data:`LOOP_COLUMNS`.
    flat, steer, steer_torque : bool, str, float or array_like
        A two-wheeler instead (``machine`` a :class:`deathsphere.TwoWheeler`
        or a two-wheeler preset such as ``"benchmark-bicycle"``;
        docs/two-wheeler.md sec. 10): ``flat`` gives the eigenvalues of
        upright straight running on flat ground at each ``speed`` (the rear
        contact's, m/s); otherwise every steady turn at each theta (or
        height) and rear contact ``speed``, or held with each
        ``steer_torque`` [N m] (0: hands-free), with its stability, the
        steer ``"free"`` (default) or ``"locked"``; one ``mu`` and one
        ``max_g`` flag its turns ``slips`` and ``over_g`` as a machine's
        orbits, and ``summary`` gives its rider's table, a row per lane
        (:func:`deathsphere.api.two_wheelers.two_wheeler_ride`).

    Returns
    -------
    Table
        Columns :data:`RIDE_COLUMNS`, or :data:`SUMMARY_COLUMNS` with
        ``summary``.  Its shape is the broadcast shape (a grid keeps its
        axes: ``to_xarray()`` gives height x speed), except where one speed
        has several tilts: then it is flat, one row per tilt (as
        :func:`deathsphere.orbit`'s); one speed asked for gives a flat row.

    Raises
    ------
    ParameterError
        A value outside its set, a bad machine, theta and height both or
        neither given (or not exactly one of alpha, speed, com_speed and
        period), a height above the globe's top, a
        wheel that does not fit in the sphere.

    Examples
    --------
    >>> import deathsphere
    >>> t = deathsphere.ride(90, 15, machine="stunt125", diameter="16ft")
    >>> str(t["status"]), round(float(t["v_cm_km_h"]), 1), round(float(t["load_g"]), 2)
    ('ok', 29.9, 4.34)
    >>> row = deathsphere.ride(90, com_speed="30km/h", diameter="16ft", mass=150)[0]
    >>> row["machine"], row["status"], round(row["lean_deg"], 1)
    ('stunt125 (modified)', 'ok', 75.0)
    >>> row = deathsphere.ride(height="5ft", speed="40km/h", diameter="16ft")[0]
    >>> round(row["v_contact_m_s"] * 3.6, 6), round(row["v_cm_km_h"], 1), row["status"]
    (40.0, 26.4, 'ok')
    """
    from deathsphere.api.two_wheelers import is_two_wheeler, two_wheeler_only

    if checked_flag("flat", flat) or steer is not None or steer_torque is not None or (
            is_two_wheeler(machine) and not isinstance(machine, str)) or two_wheeler_only(machine):
        return _two_wheeler(machine, locals())
    body = as_machine(machine).with_overrides(
        mass=mass, com_height=com_height, a=wheel_radius, tyre_radius=tyre_radius, roll_inertia=roll_inertia,
        pitch_inertia=pitch_inertia, yaw_inertia=yaw_inertia, spin_inertia=spin_inertia, head_height=head_height)
    options = RideOptions.checked(stability=stability, summary=summary, only=only)
    if surface is not None or wall_angle is not None or wall_height is not None or profile is not None:
        ground = _arena(surface, r, diameter, wall_angle, wall_height, profile)
        if ground is not None:
            from deathsphere.api import ride_surfaces

            typed = {"theta": theta, "height": height, "alpha": alpha, "speed": speed, "com_speed": com_speed,
                     "period": period, "vertical": vertical, "v_top": v_top, "g": g, "mu": mu, "max_g": max_g,
                     "turn_radius": turn_radius}
            return ride_surfaces.ride_on_surface(ground, typed, body, options, sys.modules[__name__])
    if turn_radius is not None:
        raise ParameterError("turn_radius is the lane on flat ground (surface plane); on the sphere give theta or "
                             "height", "turn_radius")
    vertical = checked_flag("vertical", vertical)
    if vertical and options.summary:
        raise ParameterError("the rider's table (summary) is for horizontal orbits, not a vertical loop", "summary")
    typed = {"theta": theta, "height": height, "alpha": alpha, "speed": speed, "com_speed": com_speed,
             "period": period, "v_top": v_top, "r": r,
             "diameter": diameter, "g": g, "mu": mu, "max_g": max_g}
    rider, run = ride_request(typed, body, vertical)
    return ride_table(rider, run, options)


@dataclass(frozen=True)
class RideOptions:
    """What to make of a ride's orbits: the stability columns, the rider's
    table (summary) instead, the statuses kept (None: all)."""

    stability: bool = True
    summary: bool = False
    keep: tuple | None = None

    @classmethod
    def checked(cls, stability=True, summary=False, only=None) -> RideOptions:
        stability, keep, summary = checked_flag("stability", stability), checked_statuses(only), \
            checked_flag("summary", summary)
        if summary and keep is not None:
            raise ParameterError("the rider's table (summary) counts every status: give only or summary, not both",
                                 "only")
        # the rider's table has no stability column
        return cls(stability=stability and not summary, summary=summary, keep=keep)

    def kept(self, table: Table) -> Table:
        return table if self.keep is None else table[np.isin(table["status"], self.keep)]


def _arena(surface, r, diameter, wall_angle, wall_height, profile=None):
    """The ground the keywords name (requests.arena: a drum, a cone, flat
    ground, a profile), or None for the globe, surface "sphere", which rides
    as it always has (a wall's keyword on it is refused there); the machine
    takes every ground through its protocol (docs/machine.md, "On any
    surface of revolution")."""
    from deathsphere.physics.ground import Sphere
    from deathsphere.requests.arena import arena

    ground = arena(surface, None if r is R else r, diameter, wall_angle, wall_height, profile)
    return None if isinstance(ground, Sphere) else ground


def _read(key: str, raw):
    """One keyword's values, checked against the registry (any shape)."""
    return checked_array(key, raw)


def ride_request(typed: dict, body: Machine, vertical: bool = False) -> tuple[RiderRequest, Run]:
    """The rider (``body`` on the lane the keywords describe) and its run,
    from ``ride``'s keywords as typed (None: not given; ``r`` the Table I
    default unless a diameter is given)."""
    keys = Keys()
    given = {k: v for k, v in typed.items() if v is not None}
    if "diameter" in given and given.get("r") is R:
        del given["r"]                      # the default radius yields to a diameter
    run = decode_run(given, keys, _read, {"g": G, "mu": INF, "max_g": INF})
    if vertical:
        given["lane"] = "vertical"
    return decode_rider(given, keys, _read, body, run.ground, cone=True), run


def ride_table(rider: RiderRequest, run: Run, options: RideOptions = RideOptions()) -> Table:
    """``ride``'s table of one rider request (its lane's values broadcast as
    a grid) in ``run``: the steady orbits of a horizontal lane (by tilt, by
    the contact's or the centre of mass's speed, or by the lap time), or the
    loops of a vertical one."""
    m, lane = rider.body, rider.lane
    if lane.kind == "vertical":
        return options.kept(_loop(lane.theta, lane.v_top, m, run))
    stability = options.stability
    where = ("theta", lane.at.theta) if isinstance(lane.at, Theta) else ("height", lane.at.height)
    how = _HOW[type(lane.by)](lane.by)
    by_height, by_speed = where[0] == "height", how[0] != "alpha"
    checked = {where[0]: where[1], how[0]: how[1], "r": checked_array("r", run.r), "g": run.g, "mu": run.mu,
               "max_g": run.max_g}
    refuse_large_grid(grid_shape(checked), command="ride", limit=MAX_RIDE_ROWS,
                      per_point=TILTS_PER_SPEED if by_speed else 1)
    shape, flat = broadcast_flat(checked)
    n = math.prod(shape)
    if n > MAX_RIDE_ROWS:
        raise ParameterError(f"ride evaluates at most {MAX_RIDE_ROWS} orbits at once (got {n}, shape {shape}): "
                             "split the grid")
    rr = flat["r"]
    if np.any(rr <= m.wheel_radius):
        raise ParameterError(f"the wheel (a = {m.wheel_radius:g} m) does not fit in a sphere of radius "
                             f"{float(rr.min()):g} m "
                             "(needs r > a)", "r")
    th = Sphere(rr).theta(flat["height"]) if by_height else np.radians(flat["theta"])
    g_, mu_, xg = flat["g"], flat["mu"], flat["max_g"]
    if not by_speed:
        al = np.radians(reduce_angle(flat["alpha"]))
        res = _evaluate(th, al, rr, g_, mu_, xg, m)
        given = {"alpha_deg": flat["alpha"].astype(float)}
        if by_height:
            given["height_m"] = flat["height"].astype(float)
        else:
            given["theta_deg"] = flat["theta"].astype(float)
        table = _table(np.arange(n), th, al, RowRun(rr, g_, mu_, xg), res, m, stability, shape=shape, given=given,
                       axes=_axes(checked, shape))
    else:
        table = _by_speed(th, how[0], flat[how[0]], rr, g_, mu_, xg, m, stability,
                          theta_deg=None if by_height else flat["theta"].astype(float),
                          height=None if not by_height else flat["height"].astype(float))
        if len(table) == n and shape:   # one row per request: a grid keeps its shape (one request stays a row)
            table = Table(table.columns, shape=shape, axes=_axes(checked, shape))
    if options.summary:
        return ride_summary(table, groups=_contact_groups(checked, shape, how[0]),
                            tried="speeds" if by_speed else "tilts")
    return options.kept(table)


#: How a horizontal lane is held -> (the keyword, its values).
_HOW = {Tilt: lambda by: ("alpha", by.alpha), ContactSpeed: lambda by: ("speed", by.speed),
        ComSpeed: lambda by: ("com_speed", by.speed), Period: lambda by: ("period", by.period)}

#: What only the single-contact machine takes: a two-wheeler's ride refuses it.
SINGLE_CONTACT_ONLY = ("alpha", "com_speed", "period", "v_top", "vertical", "mass", "com_height", "wheel_radius",
                       "tyre_radius", "roll_inertia", "pitch_inertia", "yaw_inertia", "spin_inertia", "head_height")


def refuse_single_contact(given: dict) -> None:
    """One line naming what a two-wheeler does not take among ``given``
    (those of :data:`SINGLE_CONTACT_ONLY` given: not None, not False)."""
    extra = [k for k in SINGLE_CONTACT_ONLY if given.get(k) is not None and given.get(k) is not False]
    if extra:
        raise ParameterError(f"a two-wheeler (flat or steer) does not take {', '.join(extra)} yet: give theta or "
                             "height (flat ground: turn_radius) and speed or steer_torque (flat: speed only)", extra[0])


def _two_wheeler(machine, given: dict) -> Table:
    """``ride`` of a two-wheeler: what the single-contact machine alone takes is refused."""
    from deathsphere.api.two_wheelers import two_wheeler_ride

    refuse_single_contact(given)
    return two_wheeler_ride(machine, {k: given[k] for k in ("theta", "height", "speed", "steer_torque", "flat",
                                                              "steer", "r", "diameter", "g", "mu", "max_g",
                                                              "summary", "stability", "only", "surface",
                                                              "wall_angle", "wall_height", "profile",
                                                              "turn_radius")})


#: The input -> the column that echoes it (a grid's axes are named after them).
_ECHO = {"theta": "theta_deg", "height": "height_m", "alpha": "alpha_deg", "speed": "v_contact_m_s",
         "com_speed": "v_cm_m_s", "period": "period_s", "r": "r_m",
         "g": "g_m_s2", "mu": "mu_available", "max_g": "max_g"}


def _axes(checked: dict, shape: tuple) -> tuple:
    """Each axis's input column: the one input that varies along it (None
    where none or several do)."""
    ndim = len(shape)
    out = []
    for d in range(ndim):
        along = [k for k, v in checked.items() if ((1,) * (ndim - v.ndim) + v.shape)[d] > 1]
        out.append(_ECHO[along[0]] if len(along) == 1 else None)
    return tuple(out)


def _contact_groups(checked: dict, shape: tuple, how: str) -> np.ndarray:
    """Each request's contact point (0, 1, ...): the requests that differ
    only along the axes of ``how`` (the speeds or tilts tried) share one,
    whatever their values; any other input varying splits them."""
    ndim = len(shape)
    if ndim == 0:
        return np.zeros(1, dtype=np.int64)
    padded = {k: (1,) * (ndim - v.ndim) + v.shape for k, v in checked.items()}
    tried = [d for d in range(ndim) if padded[how][d] > 1
             and not any(p[d] > 1 for k, p in padded.items() if k != how)]
    index = np.indices(shape).reshape(ndim, -1)
    index[tried] = 0
    key = np.ravel_multi_index(index, shape)
    _, first, group = np.unique(key, return_index=True, return_inverse=True)
    # numbered in the order the contact points were asked for
    rank = np.empty(first.size, dtype=np.int64)
    rank[np.argsort(first, kind="stable")] = np.arange(first.size)
    return rank[group.reshape(-1)]


#: A lane held by a value: the column echoing it.
_BY_VALUE = {"speed": "v_contact_m_s", "com_speed": "v_cm_m_s", "period": "period_s"}


def _orbits_for(how: str, th, v, ground: Sphere, g, arrays, mu, max_g):
    """Every tilt holding the lane ``how`` (the contact's speed, the centre
    of mass's speed or the lap time ``v``) and the orbit at each: a contact
    speed and a lap time fix the rate (eq. M12r), the centre's speed is
    eq. M12's."""
    if how == "com_speed":
        return orbits_for_speed(th, v, ground, g, arrays, mu, max_g)
    omega = contact_rate(th, v, ground) if how == "speed" else 2.0 * np.pi / v
    return orbits_for_rate(th, omega, ground, g, arrays, mu, max_g)


def _by_speed(th, how: str, v, r, g, mu, max_g, m: Machine, stability: bool, theta_deg=None, height=None) -> Table:
    """One row per tilt holding each value of ``how`` (``speed``,
    ``com_speed`` or ``period``: eqs. M12, M12r), a no_orbit row where none
    does; ``theta_deg`` or ``height`` as the request gave it, echoed."""
    n = th.size
    arrays = machine_arrays(m)
    parts = []
    for start in range(0, n, CHUNK):
        sl = slice(start, start + CHUNK)
        parts.append(_orbits_for(how, th[sl], v[sl], Sphere(r[sl]), g[sl], arrays, mu[sl], max_g[sl]))
    width = max(1, max(tilts.shape[1] for tilts, _ in parts))

    def padded(x, empty):
        return np.pad(x, ((0, 0), (0, width - x.shape[1])), constant_values=empty)

    roots = np.concatenate([padded(tilts, np.nan) for tilts, _ in parts])
    empty = {"status": Status.NO_ORBIT, "reason": Reason.MACHINE_NO_ALPHA}
    orbits = {key: np.concatenate([padded(orbit[key], empty.get(key, np.nan)) for _, orbit in parts])
              for key in parts[0][1]}
    # the tilts of each request in order (sorted, NaN last), or one no_orbit row where there is none
    reps = np.maximum(np.isfinite(roots).sum(axis=1), 1)
    req = np.repeat(np.arange(n), reps)
    slot = np.arange(req.size) - np.repeat(np.cumsum(reps) - reps, reps)
    al = roots[req, slot]
    res = {key: val[req, slot] for key, val in orbits.items()}
    res["height"] = r[req] * (1.0 + np.cos(th[req]))                # every row's, with a tilt or not (Sphere.height)
    given = {_BY_VALUE[how]: np.asarray(v, dtype=float)[req]}
    if theta_deg is not None:
        given["theta_deg"] = theta_deg[req]
    if height is not None:
        given["height_m"] = height[req]
    return _table(req, th[req], al, RowRun(r[req], g[req], mu[req], max_g[req]), res, m, stability,
                  given=given)


#: Columns of the rider's table (:func:`ride_summary`): ``speeds_tried``
#: and ``speeds_ok`` are ``tilts_tried`` and ``tilts_ok`` where tilts were
#: tried (``alpha``); the counts of failing speeds by cause are appended;
#: ``v_min_km_h`` and ``v_max_km_h`` are the centre of mass's speeds, the
#: contact's (a speedometer's) are appended after them in m/s.
SUMMARY_COLUMNS = ("height_m", "theta_deg", "speeds_tried", "speeds_ok", "v_min_km_h", "v_max_km_h",
                   "lean_min_deg", "lean_max_deg", "load_min_g", "load_max_g", "mu_max", "head_clearance_min_m",
                   "limits", "mu_available", "max_g", "slips", "over_g", "head_hits", "no_contact", "no_orbit",
                   "v_contact_min_m_s", "v_contact_max_m_s",
                   # the contact point's distance from the axis: on flat ground the lane itself (its turn radius)
                   "rho_contact_m")
#: Why a speed fails, as counted in the rider's table: column -> (status,
#: and the reason when one status has several causes).
FAILURES = {"slips": ("slips", None), "over_g": ("over_g", None), "head_hits": ("no_fit", Reason.HEAD_HITS),
            "no_contact": ("no_contact", None), "no_orbit": (("no_orbit", "no_fit"), None)}


def ride_summary(table: Table, groups=None, tried: str = "speeds") -> Table:
    """The rider's question answered per contact point (one row per contact
    point asked for, in order): how many speeds (or tilts) were tried, which
    are ``ok`` (feasible with the friction and the load limit given), and
    over those the speed ranges (the centre of mass's in km/h, the
    contact's in m/s), the lean from the vertical, the load, the
    friction needed and the least head clearance; ``limits`` names the
    statuses that stop the others, and ``slips``, ``over_g``,
    ``head_hits``, ``no_contact`` and ``no_orbit`` (no tilt gives the speed,
    or the wheel does not fit) count them by cause.

    ``groups`` numbers each request's contact point (``ride(...,
    summary=True)`` passes the grid's: the requests that differ only in the
    speed or tilt tried); without it, a grid table (``table.shape`` of two
    axes or more) groups along its last axis, and any other groups its rows
    by their contact inputs as given (``theta_deg`` or ``height_m``, ``r_m``,
    ``g_m_s2``, ``mu_available``, ``max_g``), never by a rounded value.
    ``tried``: ``"speeds"`` or ``"tilts"`` (a table of tilts given), which
    names the counts ``speeds_tried``/``speeds_ok`` or
    ``tilts_tried``/``tilts_ok``.  A speed (or tilt) is counted once
    under each cause among its rows when none of them is ok."""
    if tried not in ("speeds", "tilts"):
        raise ParameterError(f"tried must be 'speeds' or 'tilts' (got {tried!r})", "tried")
    req = np.asarray(table["input_row"], dtype=np.int64).reshape(-1) - 1
    if groups is not None:
        row_group = np.asarray(groups, dtype=np.int64).reshape(-1)[req]
    elif len(table.shape) >= 2:
        row_group = req // table.shape[-1]
    else:
        keys = [np.asarray(table[c], dtype=float).reshape(-1) for c in
                ("theta_deg", "height_m", "r_m", "g_m_s2", "mu_available", "max_g")]
        as_rows = np.stack(keys, axis=1) if len(table) else np.zeros((0, len(keys)))
        _, first, row_group = np.unique(np.nan_to_num(as_rows, nan=-np.inf), axis=0, return_index=True,
                                        return_inverse=True)
        row_group = np.argsort(np.argsort(first, kind="stable"), kind="stable")[row_group.reshape(-1)]
    tried, ok_name = f"{tried}_tried", f"{tried}_ok"
    names = [tried if c == "speeds_tried" else ok_name if c == "speeds_ok" else c for c in SUMMARY_COLUMNS]
    rows = {c: [] for c in names}
    status_all = np.asarray(table["status"]).reshape(-1)
    reason_all = np.asarray(table["reason"]).reshape(-1)
    head_text = (REASON_TEXT[Reason.HEAD_HITS], REASON_TEXT[Reason.HEAD_HITS_WALL])   # the globe's, a wall's
    order = np.unique(row_group)
    for gv in order:
        sel = row_group == gv
        status = status_all[sel]
        ok = status == "ok"
        rq = req[sel]

        def first(col):
            return float(np.asarray(table[col], dtype=float).reshape(-1)[sel][0])

        def span(col, fn, mask=ok):
            vals = np.asarray(table[col], dtype=float).reshape(-1)[sel][mask]
            return float(fn(vals)) if vals.size else math.nan

        rows["height_m"].append(first("height_m"))
        rows["rho_contact_m"].append(first("rho_contact_m"))
        rows["theta_deg"].append(first("theta_deg"))
        rows[tried].append(int(np.unique(rq).size))
        rows[ok_name].append(int(np.unique(rq[ok]).size))
        rows["v_min_km_h"].append(span("v_cm_km_h", np.min))
        rows["v_max_km_h"].append(span("v_cm_km_h", np.max))
        rows["v_contact_min_m_s"].append(span("v_contact_m_s", np.min))
        rows["v_contact_max_m_s"].append(span("v_contact_m_s", np.max))
        rows["lean_min_deg"].append(span("lean_deg", np.min))
        rows["lean_max_deg"].append(span("lean_deg", np.max))
        rows["load_min_g"].append(span("load_g", np.min))
        rows["load_max_g"].append(span("load_g", np.max))
        rows["mu_max"].append(span("mu_required", np.max))
        rows["head_clearance_min_m"].append(span("head_clearance_m", np.min))
        failed = sorted(set(status[~ok].tolist()))
        rows["limits"].append(" ".join(failed) if failed else "")
        rows["mu_available"].append(first("mu_available"))
        rows["max_g"].append(first("max_g"))
        head = np.isin(reason_all[sel], head_text)
        for col, (st, _) in FAILURES.items():
            hit = np.isin(status, st)
            if col == "head_hits":
                hit &= head
            elif col == "no_orbit":
                hit &= ~head
            failing = ~np.isin(rq, rq[ok])
            rows[col].append(int(np.unique(rq[hit & failing]).size))
    counts = {tried, ok_name, *FAILURES}
    cols = {c: np.array(v, dtype=np.int64 if c in counts else object if c == "limits" else float)
            for c, v in rows.items()}
    return Table(cols)


#: The columns of ``deathsphere ride --vertical``.
LOOP_COLUMNS = ("input_row", "machine", "theta_deg", "r_m", "g_m_s2", "v_top_m_s", "status", "reason",
                "v_top_min_m_s", "v_bottom_m_s", "omega_top_rad_s", "omega_bottom_rad_s", "com_loop_radius_m",
                "load_top_g", "load_bottom_g", "head_clearance_m", "mu_available", "max_g", "mu_required",
                "phi_worst_deg")


def _loop(theta, v_top, m: Machine, run: Run) -> Table:
    """Vertical loops of a machine (docs/machine.md sec. 10, eqs. M21-M24)."""
    from deathsphere.physics.machine import vertical_loop

    checked = {"theta": theta, "v_top": v_top, "r": checked_array("r", run.r), "g": run.g, "mu": run.mu,
               "max_g": run.max_g}
    refuse_large_grid(grid_shape(checked), command="ride --vertical", limit=MAX_RIDE_ROWS)
    shape, flat = broadcast_flat(checked)
    n = math.prod(shape)
    th = np.radians(flat["theta"])
    res = vertical_loop(th, flat["v_top"], Sphere(flat["r"]), flat["g"], machine_arrays(m), flat["mu"], flat["max_g"])
    res = {k: np.asarray(v).reshape(-1) for k, v in res.items()}
    cols = {"input_row": np.arange(n) + 1, "machine": np.full(n, m.name, dtype=object),
            "theta_deg": flat["theta"], "r_m": flat["r"], "g_m_s2": flat["g"], "v_top_m_s": flat["v_top"],
            "status": STATUS_LABELS[res["status"]], "reason": REASON_TEXT[res["reason"]],
            "v_top_min_m_s": res["v_top_min"], "v_bottom_m_s": res["v_bottom"], "omega_top_rad_s": res["omega_top"],
            "omega_bottom_rad_s": res["omega_bottom"], "com_loop_radius_m": res["r_g"],
            "load_top_g": res["load_top"], "load_bottom_g": res["load_bottom"],
            "head_clearance_m": res["head_clearance"],
            # inf ("no limit") is empty, as in every table
            "mu_available": np.where(np.isinf(flat["mu"]), np.nan, flat["mu"]),
            "max_g": np.where(np.isinf(flat["max_g"]), np.nan, flat["max_g"]),
            "mu_required": res["mu_required"], "phi_worst_deg": np.degrees(res["phi_worst"])}
    return Table({c: cols[c] for c in LOOP_COLUMNS}, shape=shape)
