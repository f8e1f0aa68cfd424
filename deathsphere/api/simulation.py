"""The exact equations of motion, integrated: ``simulate``."""

from __future__ import annotations

import dataclasses
import inspect
from collections.abc import Mapping
from dataclasses import dataclass
from functools import partial

import numpy as np

from deathsphere import params
from deathsphere.api.arguments import (
    INF,
    A,
    G,
    R,
    checked_choice,
    checked_flag,
    checked_optional,
    checked_scalar,
    checked_setup,
)
from deathsphere.constants import SIDES
from deathsphere.model import Setup
from deathsphere.physics.ground import Sphere
from deathsphere.physics.status import REASON_TEXT, STATUS_LABELS
from deathsphere.params import ParameterError
from deathsphere.records.paper_bodies import WHEEL, Ball, Wheel
from deathsphere.requests.arena import names_a_wall
from deathsphere.requests.decode import decode_lane, decode_paper_body, decode_paper_lane, decode_run
from deathsphere.requests.keys import Keys
from deathsphere.requests.records import (ComSpeed, ContactSpeed, Height, Horizontal, PaperBody, Rate, RiderRequest,
                                          Run, Solver, Spin, Theta, Tilt, Vertical)
from deathsphere.table import Table

#: solve_ivp's methods and the frames :func:`simulate` integrates in
#: (as in :mod:`deathsphere.simulation`, named here so that a call is
#: checked before scipy is imported).
METHODS = ("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA")


METHODS_LOWER = tuple(m.lower() for m in METHODS)


FRAMES = ("turning", "lab")


def simulate(theta=None, alpha=None, *, body: str | None = None, side: str = "inside", a=None, r=R, k=None, g=G,
             mu=INF, omega3=None, omega=None, branch: int = 0, vertical: bool = False, v_top=None, perturb=0.0,
             periods=20.0, points_per_period=100, method: str = "DOP853", rtol: float = 1e-10,
             atol: float | None = None, frame: str = "turning", max_steps=1_000_000, speed=None,
             diameter=None, machine=None, com_speed=None, surface="sphere", height=None, wall_angle=None,
             wall_height=None, profile=None, turn_radius=None) -> tuple[Table, Table]:
    """Integrate the exact equations of motion from a steady orbit: ``deathsphere simulate``.

    Beyond the paper (docs/simulation.md): the Newton-Euler equations of a
    body rolling without slipping, eqs. (2)-(7b) in general form, are
    integrated with scipy's solve_ivp from the steady orbit of :func:`orbit`
    (or, with ``vertical``, of :func:`vertical`), optionally kicked off it.

    Parameters
    ----------
    theta : float
        Polar angle of the contact point [deg] (vertical: the cone angle);
        on the globe it must be given, off it not (the lane is ``height``).
    alpha : float, optional
        Wheel: tilt of the steady orbit [deg].
    speed, com_speed, omega : float, optional
        Wheel: instead of ``alpha``, the contact's speed along the ground (a
        speedometer's; it fixes the rate speed / (r sin theta)) [m/s], the
        centre's speed v_cm [m/s] or the orbital rate [rad/s] of the steady
        orbit; its tilt is the root ``branch`` (0 first, in increasing
        alpha) of eq. (29) solved for it.
    diameter : float, optional
        The sphere's diameter instead of ``r``.
    body : {"wheel", "sphere"}, default wheel
    side, a, r, k, g, mu : as for :func:`orbit` (k > 0; a default 0.3 m);
        the run stops with ``slips`` when the friction needed exceeds ``mu``.
    machine : Machine or str, optional
        Simulate a machine (motorcycle and rider, :class:`deathsphere.Machine`
        or a preset's name) instead of the paper's body: its exact equations
        of motion, docs/machine.md eqs. M16-M19, from its steady orbit (eq.
        M8) at theta and ``alpha`` (the up-axis's tilt), ``speed`` (the
        contact's, as ``ride``'s, eq. M12r) or ``com_speed`` (the centre of
        mass's, eq. M12), the tilt ``branch`` in increasing alpha;
        ``perturb`` tilts it about its direction of travel.  Not with
        ``body``, ``a``, ``k``, ``side="outside"``, ``omega``, ``omega3``
        or ``vertical``.  The series gains ``v_cm_m_s`` and
        ``head_clearance_m``, the summary ``machine`` and
        ``min_head_clearance_m`` (docs/simulation.md, "Bodies").
    omega3, omega : float, optional
        Sphere: spin about the contact normal, or the signed orbital rate [rad/s].
    branch : {0, 1}
        Sphere with ``omega3``: the root of eq. (55) (0 slow, 1 fast).
    vertical : bool
        A vertical orbit of a wheel started at the top with ``v_top`` [m/s].
    perturb : float
        Kick off the steady orbit [deg], -60..60: the wheel tilted by this
        about its direction of travel (a sphere: its contact point moved
        this far down the meridian); rolling and contact still hold.
    periods : float
        Run length in periods of the steady orbit (vertical: laps).
    points_per_period : int
        Rows per period, 2..100000.
    method : {"DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA"}
    rtol, atol : float
        solve_ivp's tolerances (atol defaults to rtol, per scaled component).
    frame : {"turning", "lab"}
    surface, wall_angle, wall_height, profile : the arena, as for :func:`orbit`
        (docs/surfaces.md): the globe (default), the wall of death's drum
        (``"cylinder"``, ``diameter``, optional ``wall_height``), the well of
        death's cone (``"cone"``, ``wall_angle``), flat ground (``"plane"``)
        or a meridian's samples (``"profile"``); or a ground record.  Off
        the globe the paper's wheel (given ``alpha``) or ball (``omega3``
        and ``branch``, or ``omega``) rides inside or, with
        ``side="outside"``, round a drum's outside or on a cone's or a
        dome's roof (not on flat ground, which has one side), from the
        steady orbit of ``orbit`` on the lane (docs/simulation.md, "On any ground"): its
        equations of motion are docs/dynamics.md sec. 7; the run also
        stops with ``hits_floor`` (the body's lowest point reaches the
        floor at the wall's foot) and ``over_the_top`` (the contact passes
        the wall's top); ``perturb`` tilts a wheel about its direction of
        travel and turns a ball's velocity up the wall.  The series gains
        ``height_m`` and ``rho_contact_m``, the summary ``surface``,
        ``height_m``, ``max_height_drift_m`` and ``max_rho_drift_m``;
        ``theta_deg`` is empty there.
    height : float, optional
        Off the globe: the lane's height above the surface's lowest point [m].
    turn_radius : float, optional
        On flat ground: the lane, the contact's distance from the turn's centre [m].
    max_steps : int
        The step budget: a run estimated to need more steps (a body that
        spins much faster than it orbits, i.e. a small a/r) is refused
        before it starts, with the estimate.  A body spinning more than
        1e7 radians per radian of orbit is refused whatever the budget
        (float64 cannot hold both motions; docs/simulation.md, "Cost").

    Returns
    -------
    (Table, Table)
        The time series (``deathsphere simulate --format csv``: ``t_s``,
        ``theta_deg``, ``alpha_deg``, forces, drifts) and the one-row
        summary (``--summary-only``: ``status`` completed, contact_lost,
        slips, ...).

    Examples
    --------
    >>> import deathsphere
    >>> series, summary = deathsphere.simulate(60, 10, periods=0.1, points_per_period=20)
    >>> len(series), str(summary["status"][0])
    (3, 'completed')
    >>> series, summary = deathsphere.simulate(alpha=10, surface="cylinder", diameter="32ft", height=2,
    ...                                        periods=0.1, points_per_period=20)
    >>> str(summary["surface"][0]), float(series["height_m"][-1]), str(summary["status"][0])
    ('cylinder', 2.0, 'completed')
    """
    typed = {"theta": theta, "alpha": alpha, "body": body, "side": side, "a": a, "r": r, "k": k, "g": g, "mu": mu,
             "omega3": omega3, "omega": omega, "branch": branch, "vertical": vertical, "v_top": v_top,
             "perturb": perturb, "periods": periods, "points_per_period": points_per_period, "method": method,
             "rtol": rtol, "atol": atol, "frame": frame, "max_steps": max_steps, "speed": speed,
             "com_speed": com_speed, "diameter": diameter, "machine": machine, "surface": surface, "height": height,
             "wall_angle": wall_angle, "wall_height": wall_height, "profile": profile, "turn_radius": turn_radius}
    return prepare_simulation(*simulation_request(typed)).run()


@dataclass(frozen=True)
class SimulationOptions:
    """What a run records beyond its physics: rows per period, the frame
    its angles are measured in, its step budget (a run estimated to need
    more is refused before it starts) and whether the full states are kept
    (for the 3-D view)."""

    points_per_period: int = 100
    frame: str = "turning"
    max_steps: int = 1_000_000
    record_states: bool = False


def _keywords() -> dict:
    """:func:`simulate`'s keywords and their defaults, read off its
    signature so that the mapping form cannot drift from the keyword one
    (``theta``, which has none: None, refused as missing)."""
    return {name: None if p.default is p.empty else p.default
            for name, p in inspect.signature(simulate).parameters.items()}


def simulation_request(typed: Mapping) -> tuple[RiderRequest, Run, SimulationOptions]:
    """The rider, its run and the run's options from :func:`simulate`'s
    keywords as typed (a key not given: its default), plus
    ``record_states`` (keep the full states for the 3-D view).  Bad input
    raises :class:`ParameterError` naming the keyword (the command line
    shows it as its option).

    Examples
    --------
    >>> rider, run, options = simulation_request({"theta": 60, "alpha": 10, "periods": 0.1})
    >>> rider.lane.by, run.periods
    (Tilt(alpha=10.0), 0.1)
    """
    keywords = _keywords()
    unknown = sorted(set(typed) - set(keywords) - {"record_states"})
    if unknown:
        raise TypeError(f"simulation_request() got an unexpected key {unknown[0]!r}")
    given = {**keywords, "record_states": False, **typed}
    if names_a_wall(given["surface"], given["wall_angle"], given["wall_height"], given["profile"]):
        return _wall_request(given)
    for key in ("height", "turn_radius"):
        if given[key] is not None:
            raise ParameterError(f"{key} is a lane off the globe (surface cylinder, cone, plane or profile); on the "
                                 "sphere give theta", key)
    if given["theta"] is None:
        raise ParameterError("give theta (the steady orbit's polar angle, deg)", "theta", missing=True)
    if given["machine"] is not None:
        _refuse_for_machine(given)
    ground = {k: given[k] for k in ("r", "diameter") if given[k] is not None}
    if "diameter" in ground and ground.get("r") is R:
        del ground["r"]                     # the default radius yields to a diameter
    run = decode_run({**(ground or {"r": R}), "g": given["g"], "mu": given["mu"]}, Keys(), _read,
                     {"g": G, "mu": INF, "max_g": INF})
    solver, periods, kick, options = _run_options(given)
    run = dataclasses.replace(run, solver=solver, periods=periods)
    rider = _machine_rider(given, run) if given["machine"] is not None else _paper_rider(given, run)
    return dataclasses.replace(rider, kick=kick), run, options


def _wall_request(given: Mapping) -> tuple[RiderRequest, Run, SimulationOptions]:
    """:func:`simulation_request` off the globe (docs/simulation.md, "On any
    ground"): the arena from its keywords, the lane by its height (on flat
    ground its turn radius), the paper's wheel by its tilt or ball by its
    spin or rate, inside or outside (not on flat ground)."""
    from deathsphere.requests.arena import arena, lane_key, refuse_above_top

    for key, why in (("theta", "theta is the sphere's polar angle"),
                     ("v_top", "vertical loops are the globe's")):
        if given[key] is not None:
            raise ParameterError(f"{why}: on another surface simulate the paper's wheel or ball on a lane by its "
                                 "height (on flat ground its turn_radius)", key)
    if given["vertical"] is not False:
        raise ParameterError("vertical loops are the globe's: on another surface the run starts on a horizontal "
                             "lane", "vertical")
    ground = arena(given["surface"], None if given["r"] is R else given["r"], given["diameter"], given["wall_angle"],
                   given["wall_height"], given["profile"])
    key = lane_key(ground)
    other = "turn_radius" if key == "height" else "height"
    if given[other] is not None:
        raise ParameterError(f"{other} is not a lane of the {ground.name}: give its {key}", other)
    if given[key] is None:
        raise ParameterError(f"on the {ground.name} give the lane's {key}", key, missing=True)
    if key == "height":
        refuse_above_top(ground, _read(key, given[key]))      # as every command does
    run = Run(ground=ground, g=_read("g", given["g"]), mu=_read("mu", given["mu"]))
    solver, periods, kick, options = _run_options(given)
    run = dataclasses.replace(run, solver=solver, periods=periods)
    if given["machine"] is not None:
        return dataclasses.replace(_machine_on_ground(given, ground, key), kick=kick), run, options
    kind = decode_paper_body(WHEEL if given["body"] is None else given["body"])
    if not kind.rolls:
        raise ParameterError("simulate covers a wheel or a sphere (a particle has no rolling dynamics)", "body")
    side = checked_choice("side", given["side"], SIDES)
    if side == "outside" and not hasattr(ground, "highest_lane"):
        # flat ground has one side: its underside has no lane a body rides in gravity
        raise ParameterError(f"the {ground.name} has one side, its top: leave side out (inside) on flat ground",
                             "side")
    a = _read("a", A if given["a"] is None else given["a"])
    k = kind.default_k if given["k"] is None else _read("k", given["k"])
    if not k > 0:
        raise ParameterError("simulate needs k > 0: at k = 0 the equations of motion are singular", "k")
    lane = decode_paper_lane({**given, "vertical": False}, kind, _read,
                             at=Height(_read(key, given[key])))
    if isinstance(kind, Wheel) and not isinstance(lane.by, Tilt):
        alpha = _tilt_on(ground, lane.at.height, lane.by, a, k, run.g, run.mu, side == "outside")
        lane = dataclasses.replace(lane, by=Tilt(alpha))
    rider = RiderRequest(body=PaperBody(kind=kind, side=side, a=a, k=k), lane=lane, kick=kick)
    return rider, run, options


def _machine_on_ground(given: Mapping, ground, key: str) -> RiderRequest:
    """A machine on a lane of ``ground`` (not the globe; beyond the paper:
    docs/machine.md, "On any ground") at its height (on flat ground its
    turn radius ``key``), by its tilt alpha, or its speed and branch (the tilt as ``ride`` lists them)."""
    from deathsphere.physics.machine_arrays import machine_arrays
    from deathsphere.physics.machine_dynamics import YAW_UNDETERMINED, yaw_is_determined
    from deathsphere.records.machine_presets import as_machine

    _refuse_for_machine(given)
    m = as_machine(given["machine"])
    if not yaw_is_determined(machine_arrays(m)):
        raise ParameterError(f"machine {m.name!r} cannot be simulated: {YAW_UNDETERMINED}; give it a yaw "
                             "inertia (--yaw-inertia) or spinning wheels (--spin-inertia)", "machine")
    held = [name for name in ("alpha", "speed", "com_speed") if given[name] is not None]
    if len(held) != 1:
        raise ParameterError(f"on the {ground.name} give one of the machine's tilt alpha, its contact's speed and "
                             "its centre of mass's com_speed" + (f" (got {' and '.join(held)})" if held else ""),
                             held[1] if len(held) > 1 else "alpha", missing=not held)
    lane = _read(key, given[key])
    if held[0] == "alpha":
        alpha = _read("alpha", given["alpha"])
    else:
        alpha = _machine_tilt_on(m, ground, lane, held[0], _read(held[0], given[held[0]]), given["branch"],
                                 _read("g", given["g"]))
    return RiderRequest(body=m, lane=Horizontal(at=Height(lane), by=Tilt(alpha)))


def _machine_tilt_on(m, ground, lane: float, held: str, speed: float, branch, g: float) -> float:
    """The tilt [deg] of a machine's lane on ``ground`` whose contact (held
    ``speed``) or centre of mass (``com_speed``) runs at ``speed``: the tilt
    number ``branch`` in increasing alpha of those ``ride`` lists there
    (docs/machine.md eqs. M12, M12r with MS2-MS4)."""
    from deathsphere.physics.machine_arrays import machine_arrays
    from deathsphere.physics.machine_lanes import contact_rate_on, orbits_for_rate_on, orbits_for_speed_on

    at, value = np.array([lane]), np.array([speed])
    if held == "com_speed":
        tilts, _ = orbits_for_speed_on(at, value, ground, np.array([g]), machine_arrays(m))
    else:
        tilts, _ = orbits_for_rate_on(at, contact_rate_on(at, value, ground), ground, np.array([g]), machine_arrays(m))
    tilts = np.sort(np.degrees(tilts[0][np.isfinite(tilts[0])]))
    if not tilts.size:
        raise ParameterError(f"no tilt alpha gives the {'centre of mass' if held == 'com_speed' else 'contact'} "
                             f"this speed on this lane of the {ground.name}", held)
    if isinstance(branch, bool) or not isinstance(branch, (int, np.integer)) or not 0 <= branch < tilts.size:
        raise ParameterError(f"branch must be one of the {tilts.size} tilts that give this speed "
                             f"(0..{tilts.size - 1}; got {branch!r})", "branch")
    return float(tilts[int(branch)])


def _tilt_on(ground, height: float, by, a: float, k: float, g: float, mu: float, outside: bool = False) -> float:
    """The tilt [deg] of a wheel's orbit on a lane of ``ground`` (inside or
    ``outside``) with this contact speed, centre speed or rate: root number
    ``branch`` of eq. S2 (docs/surfaces.md, "The wheel given its rate"; as
    ``orbit`` numbers them)."""
    from deathsphere.physics.revolution_tilt import wheel_tilts

    key = {ContactSpeed: "speed", ComSpeed: "com_speed", Rate: "omega"}[type(by)]
    target = by.omega if isinstance(by, Rate) else by.speed
    res = wheel_tilts(ground, height, a, k, g, mu=mu, outside=outside, **{key: target})
    alphas = np.asarray(res["alpha"], dtype=float).reshape(-1)
    found = alphas[np.isfinite(alphas)]
    what = "rate" if key == "omega" else "speed"
    if not found.size:
        status, reason = (int(np.ravel(res[name])[0]) for name in ("unsolved_status", "unsolved_reason"))
        raise ParameterError(f"no tilt alpha gives this {what} on this lane ({STATUS_LABELS[status]}: "
                             f"{REASON_TEXT[reason]})", key)
    branch = by.branch
    if isinstance(branch, bool) or not isinstance(branch, (int, np.integer)) or not 0 <= branch < found.size:
        raise ParameterError(f"branch must be one of the {found.size} tilts that give this {what} "
                             f"(0..{found.size - 1}; got {branch!r})", "branch")
    return float(np.degrees(found[int(branch)]))


def _read(key: str, raw) -> float:
    """One keyword's value: one value, checked against the registry."""
    return checked_scalar(key, raw)


def _run_options(given: Mapping) -> tuple[Solver, float, float, SimulationOptions]:
    """The checked solver, run length, kick and options, whatever rolls."""
    method = checked_choice("method", given["method"], METHODS_LOWER)
    kick, periods = checked_scalar("perturb", given["perturb"]), checked_scalar("periods", given["periods"])
    points = int(checked_scalar("points_per_period", given["points_per_period"]))
    solver = Solver(method=METHODS[METHODS_LOWER.index(method)], rtol=checked_scalar("rtol", given["rtol"]),
                    atol=checked_optional("atol", given["atol"]))
    frame = checked_choice("frame", given["frame"], FRAMES)
    options = SimulationOptions(points_per_period=points, frame=frame,
                                record_states=checked_flag("record_states", given["record_states"]),
                                max_steps=int(checked_scalar("max_steps", given["max_steps"])))
    return solver, periods, kick, options


def _paper_rider(given: Mapping, run: Run) -> RiderRequest:
    """A wheel or a sphere of the paper on the lane its keywords describe
    (decided by the decoder: which keys hold a body's orbit is its record's)."""
    setup = checked_setup(WHEEL if given["body"] is None else given["body"], given["side"],
                          A if given["a"] is None else given["a"], run.r, given["k"], run.g, run.mu)
    if not setup.body.rolls:
        raise ParameterError("simulate covers a wheel or a sphere (a particle has no rolling dynamics)")
    lane = decode_paper_lane({**given, "vertical": checked_flag("vertical", given["vertical"])}, setup.body, _read)
    if setup.k == 0:
        raise ParameterError("simulate needs k > 0: at k = 0 the equations of motion are singular")
    return RiderRequest(body=PaperBody(kind=setup.body, side=setup.side, a=setup.a, k=setup.k), lane=lane)


def _refuse_for_machine(given: Mapping) -> None:
    """What a machine's run does not take, refused by name: its body is the
    machine (its wheel radius its own) and it starts on a horizontal orbit."""
    if given["vertical"] is not False:
        raise ParameterError("vertical loops of a machine are not simulated (their steady values: ride with "
                             "vertical=True, 'deathsphere ride --vertical'); a machine's run starts on a "
                             "horizontal orbit", "vertical")
    refused = [name for name in ("body", "a", "k", "omega", "omega3", "v_top") if given[name] is not None]
    refused += ["side='outside'"] if given["side"] != "inside" else []
    if refused:
        raise ParameterError(f"with machine= the body is the machine (its wheel radius is its own): "
                             f"{', '.join(refused)} not allowed; give theta and alpha, speed or com_speed (and branch), "
                             "r or diameter, g, mu, perturb and the run's options", "machine")


def _machine_rider(given: Mapping, run: Run) -> RiderRequest:
    """A machine (beyond the paper; docs/machine.md) on a horizontal lane
    at theta, by its tilt, its contact's speed or its centre of mass's speed."""
    from deathsphere.physics.machine_arrays import machine_arrays
    from deathsphere.physics.machine_dynamics import YAW_UNDETERMINED, yaw_is_determined
    from deathsphere.records.machine_presets import as_machine

    m = as_machine(given["machine"])
    if not yaw_is_determined(machine_arrays(m)):
        raise ParameterError(f"machine {m.name!r} cannot be simulated: {YAW_UNDETERMINED}; give it a yaw "
                             "inertia (--yaw-inertia) or spinning wheels (--spin-inertia)", "machine")
    if not run.r > m.wheel_radius:
        raise ParameterError(f"the wheel (a = {m.wheel_radius:g} m) does not fit in a sphere of radius {run.r:g} m "
                             "(needs r > a)",
                             "r")
    # at theta, by its tilt, its contact's speed or its centre of mass's speed: decided by the decoder (as ride's)
    lane = decode_lane({key: given[key] for key in ("theta", "alpha", "speed", "com_speed")}, Keys(), _read,
                       run.ground)
    branch = given["branch"]
    if isinstance(lane.by, (ComSpeed, ContactSpeed)):
        lane = dataclasses.replace(lane, by=type(lane.by)(lane.by.speed, branch))
    elif isinstance(branch, bool) or branch != 0:
        raise ParameterError(f"branch picks one of the tilts that give a speed: it needs speed (got {branch!r})",
                             "branch")
    return RiderRequest(body=m, lane=lane)


def prepare_simulation(rider: RiderRequest, run: Run, options: SimulationOptions = SimulationOptions()):
    """The :class:`deathsphere.simulation.Simulation` of ``rider`` in ``run``
    (records from :func:`simulation_request`), not yet run: for streaming
    the time series chunk by chunk (``sim.chunks()``, then
    ``sim.summary()``), as the command line does.  A speed or rate is
    solved for its tilt here; bad input raises :class:`ParameterError`.

    Examples
    --------
    >>> sim = prepare_simulation(*simulation_request({"theta": 60, "alpha": 10, "periods": 0.1,
    ...                                               "points_per_period": 20}))
    >>> sum(len(chunk) for chunk in sim.chunks()), str(sim.summary()["status"][0])
    (3, 'completed')
    """
    from deathsphere import simulation

    if not isinstance(rider.body, PaperBody):
        starts = _machine_starts(rider, run)
    else:
        starts = _paper_starts(rider, run) if isinstance(run.ground, Sphere) else _wall_starts(rider, run)
    solver = run.solver or Solver()
    try:
        return simulation.Simulation(starts, periods=run.periods, points_per_period=options.points_per_period,
                                     method=solver.method, rtol=solver.rtol, atol=solver.atol, frame=options.frame,
                                     record_states=options.record_states, max_steps=options.max_steps)
    except ValueError as exc:  # the simulation's own checks (method, frame, tolerances)
        raise ParameterError(str(exc)) from None


def _paper_starts(rider: RiderRequest, run: Run):
    """The start of a wheel's or a sphere's run: its steady orbit kicked by ``rider.kick`` [deg]."""
    from deathsphere import simulation

    body, lane, kick = rider.body, rider.lane, 0.0 if rider.kick is None else rider.kick
    setup = Setup(body=body.kind, side=body.side, a=body.a, r=run.r, k=body.k, g=run.g, mu=run.mu)
    if isinstance(lane, Vertical):
        starts_of = partial(simulation.vertical_starts, setup, lane.theta, lane.v_top, perturb_deg=kick)
        return _started(starts_of, None)
    theta, by = lane.at.theta, lane.by
    speed = by.speed if isinstance(by, ComSpeed) else None
    contact = by.speed if isinstance(by, ContactSpeed) else None
    omega = by.omega if isinstance(by, Rate) else None
    omega3 = by.omega3 if isinstance(by, Spin) else None
    requested = {"speed": speed, "rate": omega, "omega3": omega3}
    if isinstance(body.kind, Wheel):
        alpha = by.alpha if isinstance(by, Tilt) else _tilt_for(setup, theta, speed, omega, by.branch, contact)
        starts_of = partial(simulation.horizontal_starts, setup, theta, params.reduce_angle(alpha),
                            perturb_deg=kick)
        return _echo_requested(_started(starts_of, alpha), **requested)
    starts_of = partial(simulation.horizontal_starts, setup, theta, omega3=omega3, omega=omega, branch=by.branch,
                        perturb_deg=kick)
    return _echo_requested(_started(starts_of, None), **requested)


def _wall_starts(rider: RiderRequest, run: Run):
    """The start of a wheel's or a ball's run off the globe: the lane's steady
    orbit (docs/surfaces.md S1-S7) kicked by ``rider.kick`` [deg]."""
    from deathsphere.simulation.ground_starts import ground_starts

    body, by = rider.body, rider.lane.by
    kick = 0.0 if rider.kick is None else rider.kick
    held = ({"alpha_deg": params.reduce_angle(by.alpha)} if isinstance(by, Tilt)
            else {"omega": by.omega} if isinstance(by, Rate) else {"omega3": by.omega3, "branch": by.branch})
    starts_of = partial(ground_starts, run.ground, body.kind, rider.lane.at.height, held, a=body.a, k=body.k, g=run.g,
                        mu=run.mu, perturb_deg=kick, outside=body.side == "outside")
    alpha = by.alpha if isinstance(by, Tilt) else None
    return _echo_requested(_started(starts_of, alpha), **{"rate": getattr(by, "omega", None),
                                                          "omega3": getattr(by, "omega3", None)})


def _started(starts_of, alpha):
    """``starts_of()``, its tilt echoed as given (``alpha``; None: its own):
    the reduction to (-180, 180] may change its last bits
    (10.123456789 -> 10.123456788999988)."""
    try:
        starts = starts_of()
    except ValueError as exc:  # the starts' own checks
        raise ParameterError(str(exc)) from None
    return starts if alpha is None else dataclasses.replace(starts, alpha_deg=np.full(len(starts), alpha))


def _echo_requested(starts, **requested):
    """``starts`` with the values the request fixed (the speed, Omega or
    omega3 it gave) echoed as given: recomputed from the tilt they were
    solved for, they come back a few ulps off (7 m/s as 6.999999999999994).
    Rows without an orbit keep their NaN."""
    given = {field: np.where(np.isfinite(getattr(starts, field)), value, getattr(starts, field))
             for field, value in requested.items() if value is not None}
    return dataclasses.replace(starts, **given) if given else starts


def _machine_starts(rider: RiderRequest, run: Run):
    """The start of a machine's run (beyond the paper; docs/machine.md eqs.
    M8, M12, M16-M19): its steady orbit at (theta, alpha), or at the tilt
    ``branch`` giving the centre of mass the speed, kicked by ``rider.kick``."""
    from deathsphere.physics.ground import Sphere
    from deathsphere.simulation.machine_starts import machine_ground_run, machine_ground_starts, machine_run, machine_starts

    m, by = rider.body, rider.lane.by
    kick = 0.0 if rider.kick is None else rider.kick
    if not isinstance(run.ground, Sphere):
        bodies = machine_ground_run(m, run.ground, run.g, rider.lane.at.height)
        starts_of = partial(machine_ground_starts, bodies, params.reduce_angle(by.alpha), perturb_deg=kick,
                            mu=run.mu)
        return _started(starts_of, by.alpha)
    theta = rider.lane.at.theta
    speed = by.speed if isinstance(by, ComSpeed) else None
    contact = by.speed if isinstance(by, ContactSpeed) else None
    alpha = (by.alpha if isinstance(by, Tilt)
             else _machine_tilt_for(m, theta, speed, by.branch, run.r, run.g, contact=contact))
    bodies = machine_run(m, Sphere(run.r), run.g)
    starts_of = partial(machine_starts, bodies, theta, params.reduce_angle(alpha), perturb_deg=kick, mu=run.mu)
    return _echo_requested(_started(starts_of, alpha), speed=speed)


def _machine_tilt_for(m, theta: float, speed, branch, r: float, g: float, contact=None) -> float:
    """The tilt [deg] of a machine's orbit at ``theta`` whose centre of mass
    runs at ``speed`` (or whose contact runs along the ground at
    ``contact``): the tilt number ``branch`` in increasing alpha of those
    eq. M12 (M12r) gives (as ``ride`` lists them)."""
    from deathsphere.api.rides import ride

    by = {"com_speed": speed} if contact is None else {"speed": contact}
    rows = ride(theta, machine=m, r=r, g=g, stability=False, **by)
    tilts = np.sort(np.asarray(rows["alpha_deg"], dtype=float))
    tilts = tilts[np.isfinite(tilts)]
    if not tilts.size:
        whose = "the centre of mass this speed" if contact is None else "the contact this speed"
        raise ParameterError(f"no tilt alpha gives {whose} at theta = {theta:g} deg "
                             f"({_no_tilt_why(rows, 'eq. M12 has no root')})", next(iter(by)))
    if isinstance(branch, bool) or not isinstance(branch, (int, np.integer)) or not 0 <= branch < tilts.size:
        raise ParameterError(f"branch must be one of the {tilts.size} tilts that give this speed "
                             f"(0..{tilts.size - 1}; got {branch!r})", "branch")
    return float(tilts[int(branch)])


def _no_tilt_why(rows, otherwise: str) -> str:
    """Why no tilt answers a request: the contact on the axis says so, else ``otherwise``."""
    reasons = [str(r) for r in np.asarray(rows["reason"], dtype=object).reshape(-1) if r]
    on_axis = [r for r in reasons if "on the vertical axis" in r]
    return "the contact is on the vertical axis: it does not move" if on_axis else otherwise


def _tilt_for(setup, theta: float, speed, omega, branch, contact=None) -> float:
    """The tilt [deg] of a wheel's orbit at ``theta`` with this centre
    speed, contact speed or rate: root number ``branch`` of eq. (29) (as
    ``orbit`` numbers them)."""
    rows = setup.orbit(theta, com_speed=speed, speed=contact, omega=omega, stability=False)
    found = [row for row in rows if row["branch"] is not None]
    what = "rate" if omega is not None else "speed"
    if not found:
        key = "com_speed" if speed is not None else "speed" if contact is not None else "omega"
        raise ParameterError(f"no tilt alpha gives this {what} at theta = {theta:g} deg "
                             f"({_no_tilt_why(rows, 'eq. 29 has no root')})", key)
    if isinstance(branch, bool) or not isinstance(branch, (int, np.integer)) or not 0 <= branch < len(found):
        raise ParameterError(f"branch must be one of the {len(found)} tilts that give this {what} "
                             f"(0..{len(found) - 1}; got {branch!r})", "branch")
    return float(found[int(branch)]["alpha_deg"])


#: the 3-D views that are loops of frames (the options of :func:`animation_options`)
LOOP_FORMATS = ("gif", "mp4")


def animation_options(output, *, loop_seconds=None, playback=None) -> dict:
    """The checked loop options of a 3-D view written to ``output``
    (``simulate --output run.gif --loop-seconds S --playback X``; beyond the
    paper, docs/simulation.md "3-D view"): ``loop_seconds``, the most
    seconds of loop, and ``playback``, simulated seconds per second of loop
    (None: the viewer's default, real time or the slow motion in which
    nothing aliases between frames).  Returns the keywords of
    :func:`deathsphere.viewer.write_view`.

    Raises
    ------
    ParameterError
        A value outside its range, or either given for an output that is
        not a .gif or .mp4 loop.
    """
    options = {"loop_seconds": None if loop_seconds is None else checked_scalar("loop_seconds", loop_seconds),
               "playback": None if playback is None else checked_scalar("playback", playback)}
    chosen = [name for name, value in options.items() if value is not None]
    ext = str(output).lower().rsplit(".", 1)[-1] if output is not None and "." in str(output) else ""
    if chosen and ext not in LOOP_FORMATS:
        got = "no output file" if output is None else f"the output is {str(output)!r}"
        raise ParameterError(f"{' and '.join(chosen)} shape{'s' if len(chosen) == 1 else ''} a .gif or .mp4 loop "
                             f"({got})", chosen[0])
    return options

