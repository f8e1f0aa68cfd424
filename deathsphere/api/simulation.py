"""The exact equations of motion, integrated: ``simulate``."""

from __future__ import annotations

import dataclasses

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
    sphere_radius,
)
from deathsphere.params import ParameterError
from deathsphere.table import Table

#: solve_ivp's methods and the frames :func:`simulate` integrates in
#: (as in :mod:`deathsphere.simulation`, named here so that a call is
#: checked before scipy is imported).
METHODS = ("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA")


METHODS_LOWER = tuple(m.lower() for m in METHODS)


FRAMES = ("turning", "lab")


def simulate(theta, alpha=None, *, body: str | None = None, side: str = "inside", a=None, r=R, k=None, g=G,
             mu=INF, omega3=None, omega=None, branch: int = 0, vertical: bool = False, v_top=None, perturb=0.0,
             periods=20.0, points_per_period=100, method: str = "DOP853", rtol: float = 1e-10,
             atol: float | None = None, frame: str = "turning", max_steps=1_000_000, speed=None,
             diameter=None, machine=None) -> tuple[Table, Table]:
    """Integrate the exact equations of motion from a steady orbit: ``deathsphere simulate``.

    Beyond the paper (docs/simulation.md): the Newton-Euler equations of a
    body rolling without slipping, eqs. (2)-(7b) in general form, are
    integrated with scipy's solve_ivp from the steady orbit of :func:`orbit`
    (or, with ``vertical``, of :func:`vertical`), optionally kicked off it.

    Parameters
    ----------
    theta : float
        Polar angle of the contact point [deg] (vertical: the cone angle).
    alpha : float, optional
        Wheel: tilt of the steady orbit [deg].
    speed, omega : float, optional
        Wheel: instead of ``alpha``, the centre speed [m/s] or the orbital
        rate [rad/s] of the steady orbit; its tilt is the root ``branch``
        (0 first, in increasing alpha) of eq. (29) solved for it.
    diameter : float, optional
        The sphere's diameter instead of ``r``.
    body : {"wheel", "sphere"}, default wheel
    side, a, r, k, g, mu : as for :func:`orbit` (k > 0; a default 0.3 m);
        the run stops with ``slips`` when the friction needed exceeds ``mu``.
    machine : Machine or str, optional
        Simulate a machine (motorcycle and rider, :class:`deathsphere.Machine`
        or a preset's name) instead of the paper's body: its exact equations
        of motion, docs/machine.md eqs. M16-M19, from its steady orbit (eq.
        M8) at theta and ``alpha`` (the up-axis's tilt) or ``speed`` (the
        centre of mass's, the tilt ``branch`` in increasing alpha, eq. M12);
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
    """
    return prepare_simulation(theta, alpha, body=body, side=side, a=a, r=r, k=k, g=g, mu=mu, omega3=omega3,
                              omega=omega, branch=branch, vertical=vertical, v_top=v_top, perturb=perturb,
                              periods=periods, points_per_period=points_per_period, method=method, rtol=rtol,
                              atol=atol, frame=frame, max_steps=max_steps, speed=speed, diameter=diameter,
                              machine=machine).run()


def prepare_simulation(theta, alpha=None, *, body: str | None = None, side: str = "inside", a=None, r=R, k=None,
                       g=G, mu=INF, omega3=None, omega=None, branch: int = 0, vertical: bool = False, v_top=None,
                       perturb=0.0, periods=20.0, points_per_period=100, method: str = "DOP853",
                       rtol: float = 1e-10, atol: float | None = None, frame: str = "turning",
                       record_states: bool = False, max_steps=1_000_000, speed=None, diameter=None, machine=None):
    """The validated :class:`deathsphere.simulation.Simulation` behind
    :func:`simulate` (same parameters), not yet run: for streaming the time
    series chunk by chunk (``sim.chunks()``, then ``sim.summary()``), as the
    command line does; ``record_states`` keeps the full states for the 3-D
    view.  Bad input raises :class:`ParameterError`.

    Examples
    --------
    >>> sim = prepare_simulation(60, 10, periods=0.1, points_per_period=20)
    >>> sum(len(chunk) for chunk in sim.chunks()), str(sim.summary()["status"][0])
    (3, 'completed')
    """
    from deathsphere import simulation

    if theta is None:
        raise ParameterError("give theta (the steady orbit's polar angle, deg)", "theta", missing=True)
    if machine is not None:
        if vertical is not False:
            raise ParameterError("vertical loops of a machine are not simulated (their steady values: ride with "
                                 "vertical=True, 'deathsphere ride --vertical'); a machine's run starts on a "
                                 "horizontal orbit", "vertical")
        refused = [name for name, v in (("body", body), ("a", a), ("k", k), ("omega", omega), ("omega3", omega3),
                                        ("v_top", v_top)) if v is not None]
        refused += ["side='outside'"] if side != "inside" else []
        if refused:
            raise ParameterError(f"with machine= the body is the machine (its wheel radius is its own): "
                                 f"{', '.join(refused)} not allowed; give theta and alpha or speed (and branch), "
                                 "r or diameter, g, mu, perturb and the run's options", "machine")
        return _prepare_machine(theta, alpha, speed, branch, machine, sphere_radius(r, diameter), g, mu,
                                _run_options(perturb, periods, points_per_period, method, rtol, atol, frame,
                                             record_states, max_steps))
    setup = checked_setup("wheel" if body is None else body, side, A if a is None else a,
                          sphere_radius(r, diameter), k, g, mu)
    theta = checked_scalar("theta", theta)
    alpha, omega3, omega, v_top, speed = (
        None if v is None else checked_scalar(name, v) for name, v in
        (("alpha", alpha), ("omega3", omega3), ("omega", omega), ("v_top", v_top), ("speed", speed)))
    vertical = checked_flag("vertical", vertical)
    run = _run_options(perturb, periods, points_per_period, method, rtol, atol, frame, record_states, max_steps)
    perturb = run.pop("perturb")
    requested = {"speed": speed, "rate": omega, "omega3": omega3}
    if setup.body == "wheel" and not vertical and alpha is None and (speed is not None or omega is not None):
        # a wheel given its speed or rate: the tilt of that orbit (eq. 29 solved), the root ``branch``
        alpha = _tilt_for(setup, theta, speed, omega, branch)
        omega = None
    elif isinstance(branch, bool) or branch not in (0, 1):
        raise ParameterError(f"branch must be 0 (slow root of eq. 55) or 1 (fast root) (got {branch!r})")
    elif speed is not None:
        raise ParameterError("speed is an input for a wheel's horizontal orbit", "speed")
    # which inputs each kind of run takes (the command line's rules, in words
    # naming the parameters of this function)
    if setup.body == "particle":
        raise ParameterError("simulate covers a wheel or a sphere (a particle has no rolling dynamics)")
    if vertical:
        if setup.body != "wheel" or alpha is not None or v_top is None:
            raise ParameterError("vertical=True simulates a wheel: give theta and v_top (no alpha)")
    elif v_top is not None:
        raise ParameterError("v_top is for vertical orbits (vertical=True)")
    elif setup.body == "wheel" and (alpha is None or omega3 is not None or omega is not None):
        raise ParameterError("a wheel's steady orbit needs alpha (deg) or its speed or rate (no omega3)")
    elif setup.body == "sphere" and (alpha is not None or (omega3 is None) == (omega is None)):
        raise ParameterError("a sphere's steady orbit needs exactly one of omega3 and omega (no alpha)")
    if setup.k == 0:
        raise ParameterError("simulate needs k > 0: at k = 0 the equations of motion are singular")
    try:
        if vertical:
            starts = simulation.vertical_starts(setup, theta, v_top, perturb_deg=perturb)
        elif setup.body == "wheel":
            starts = simulation.horizontal_starts(setup, theta, params.reduce_angle(alpha), perturb_deg=perturb)
            # the tilt is echoed as given (the reduction to (-180, 180] may
            # change its last bits: 10.123456789 -> 10.123456788999988)
            starts = dataclasses.replace(starts, alpha_deg=np.full(len(starts), alpha))
        else:
            starts = simulation.horizontal_starts(setup, theta, omega3=omega3, omega=omega, branch=branch,
                                                  perturb_deg=perturb)
        sim = simulation.Simulation(_echo_requested(starts, **requested), **run)
    except ValueError as exc:  # the simulation's own checks (method, frame, tolerances)
        raise ParameterError(str(exc)) from None
    return sim


def _echo_requested(starts, **requested):
    """``starts`` with the values the request fixed (the speed, Omega or
    omega3 it gave) echoed as given: recomputed from the tilt they were
    solved for, they come back a few ulps off (7 m/s as 6.999999999999994).
    Rows without an orbit keep their NaN."""
    given = {field: np.where(np.isfinite(getattr(starts, field)), value, getattr(starts, field))
             for field, value in requested.items() if value is not None}
    return dataclasses.replace(starts, **given) if given else starts


def _run_options(perturb, periods, points_per_period, method, rtol, atol, frame, record_states, max_steps) -> dict:
    """The checked kick and :class:`deathsphere.simulation.Simulation` options, whatever rolls."""
    method = checked_choice("method", method, METHODS_LOWER)
    return {"perturb": checked_scalar("perturb", perturb), "periods": checked_scalar("periods", periods),
            "points_per_period": int(checked_scalar("points_per_period", points_per_period)),
            "method": METHODS[METHODS_LOWER.index(method)], "rtol": checked_scalar("rtol", rtol),
            "atol": checked_optional("atol", atol), "frame": checked_choice("frame", frame, FRAMES),
            "record_states": checked_flag("record_states", record_states),
            "max_steps": int(checked_scalar("max_steps", max_steps))}


def _prepare_machine(theta, alpha, speed, branch, machine, r, g, mu, run: dict):
    """:func:`prepare_simulation` of a machine (beyond the paper; docs/machine.md
    eqs. M8, M12, M16-M19): its steady orbit at (theta, alpha), or at the
    tilt ``branch`` giving the centre of mass the ``speed``."""
    from deathsphere import simulation
    from deathsphere.physics.ground import Sphere
    from deathsphere.physics.machine_arrays import machine_arrays
    from deathsphere.physics.machine_dynamics import YAW_UNDETERMINED, yaw_is_determined
    from deathsphere.records.machine_presets import as_machine
    from deathsphere.simulation.machine_starts import machine_run, machine_starts

    m = as_machine(machine)
    if not yaw_is_determined(machine_arrays(m)):
        raise ParameterError(f"machine {m.name!r} cannot be simulated: {YAW_UNDETERMINED}; give it a yaw "
                             "inertia (--yaw-inertia) or spinning wheels (--spin-inertia)", "machine")
    theta = checked_scalar("theta", theta)
    r, g, mu = checked_scalar("r", r), checked_scalar("g", g), checked_scalar("mu", mu)
    if not r > m.wheel_radius:
        raise ParameterError(f"the wheel (a = {m.wheel_radius:g} m) does not fit in a sphere of radius {r:g} m "
                             "(needs r > a)",
                             "r")
    if (alpha is None) == (speed is None):
        raise ParameterError("a machine's steady orbit needs exactly one of alpha (deg) and speed (its centre of "
                             "mass's, m/s)", "alpha", missing=alpha is None)
    if speed is not None:
        speed = checked_scalar("speed", speed)
        alpha = _machine_tilt_for(m, theta, speed, branch, r, g)
    elif isinstance(branch, bool) or branch != 0:
        raise ParameterError(f"branch picks one of the tilts that give a speed: it needs speed (got {branch!r})",
                             "branch")
    else:
        alpha = checked_scalar("alpha", alpha)
    perturb = run.pop("perturb")
    bodies = machine_run(m, Sphere(r), g)
    try:
        starts = machine_starts(bodies, theta, params.reduce_angle(alpha), perturb_deg=perturb, mu=mu)
        # the tilt is echoed as given, as a wheel's
        starts = dataclasses.replace(starts, alpha_deg=np.full(len(starts), alpha))
        return simulation.Simulation(_echo_requested(starts, speed=speed), **run)
    except ValueError as exc:
        raise ParameterError(str(exc)) from None


def _machine_tilt_for(m, theta: float, speed: float, branch, r: float, g: float) -> float:
    """The tilt [deg] of a machine's orbit at ``theta`` whose centre of mass
    runs at ``speed``: the tilt number ``branch`` in increasing alpha of
    those eq. M12 gives (as ``ride`` lists them)."""
    from deathsphere.api.rides import ride

    rows = ride(theta, speed=speed, machine=m, r=r, g=g, stability=False)
    tilts = np.sort(np.asarray(rows["alpha_deg"], dtype=float))
    tilts = tilts[np.isfinite(tilts)]
    if not tilts.size:
        raise ParameterError(f"no tilt alpha gives the centre of mass this speed at theta = {theta:g} deg "
                             "(eq. M12 has no root)", "speed")
    if isinstance(branch, bool) or not isinstance(branch, (int, np.integer)) or not 0 <= branch < tilts.size:
        raise ParameterError(f"branch must be one of the {tilts.size} tilts that give this speed "
                             f"(0..{tilts.size - 1}; got {branch!r})", "branch")
    return float(tilts[int(branch)])


def _tilt_for(setup, theta: float, speed, omega, branch) -> float:
    """The tilt [deg] of a wheel's orbit at ``theta`` with this speed or rate:
    root number ``branch`` of eq. (29) (as ``orbit`` numbers them)."""
    rows = setup.orbit(theta, speed=speed, omega=omega, stability=False)
    found = [row for row in rows if row["branch"] is not None]
    what = "speed" if speed is not None else "rate"
    if not found:
        raise ParameterError(f"no tilt alpha gives this {what} at theta = {theta:g} deg (eq. 29 has no root)",
                             "speed" if speed is not None else "omega")
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

