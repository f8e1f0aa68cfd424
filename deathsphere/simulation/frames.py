"""Frame geometry of the 3-D view: what to draw, from the simulated state.

It lives with the simulation, not the viewer, because it is physics (the
contact point, the contact force, the wheel's spin rate): the viewer only
draws what this hands it.

Beyond the paper: the states come from :mod:`deathsphere.simulation`
(exact equations of motion: the paper's bodies, or a machine's, eqs.
M16-M19, whose frame adds its centre of mass and the rider's head); how
they are drawn is described in ``docs/simulation.md``, section "3-D view".  Pure numpy, vectorised over
samples; no drawing here.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics import dynamics as dyn
from deathsphere.physics import machine_motion as mm
from deathsphere.records.paper_bodies import Ball
from deathsphere.requests.decode import paper_body_named
from deathsphere.simulation.bodies import MACHINE, MACHINE_ON_GROUND, ON_GROUND, PAPER, broadcast_params, model_of, take

__all__ = ["frame_geometry", "machine_frame_geometry", "ground_frame_geometry", "spin_rate", "body_frames", "refine_samples", "MAX_TURN_RAD",
           "MAX_MOVE_R"]

#: the most a body may turn between two frames of the view [rad]: a quarter
#: turn, past which a turning spoke or marker can be read as turning the
#: other way (aliasing)
MAX_TURN_RAD = 0.5 * np.pi
#: the most the body's centre may move between two frames, in units of r
MAX_MOVE_R = 0.02
#: 1 m/s = 3600 s/h / 1000 m/km
_KM_H_PER_M_S = 3.6
# frames are placed for these fractions of the bounds: the rates are known
# at the samples, and may peak between them
_TARGET = 0.75


def _unit(v):
    return v / np.sqrt(np.sum(v * v, axis=0))


def _dot(u, v):
    return np.sum(u * v, axis=0)


def _norm(v):
    return np.sqrt(_dot(v, v))


def _centre_speed(state, params):
    """|dc/dt| = |a e3 x w| (eq. 6), with a e3 = p - c."""
    return _norm(np.cross(dyn.contact_point(state, params) - state[dyn.C], state[dyn.W], axis=0))


def _params(params: dyn.BodyParams) -> dyn.BodyParams:
    # the flags as numpy booleans: dynamics negates them with ~, and ~True
    # is -2 (truthy) for a Python bool
    return params._replace(outside=np.asarray(params.outside, dtype=bool),
                           sphere=np.asarray(params.sphere, dtype=bool))


def spin_rate(state, params: dyn.BodyParams):
    """Rate [rad/s] at which a wheel turns about its axle relative to the
    contact direction e3, dpsi/dt = w.e1 - (de3/dt).u with u = e1 x e3.

    Beyond the paper (docs/simulation.md, "3-D view").  The state carries
    the axle e1 but not the wheel's angle about it, so a spoke is followed
    by integrating this rate.  de3/dt comes from the state alone:
    dc/dt = a e3 x w (eq. 6), de1/dt = w x e1, and e3 = s c_perp/|c_perp|
    (docs/dynamics.md sec. 2) gives (de3/dt).u = s (dc/dt.u - (c.e1)
    (de1/dt).u) / |c_perp|, the terms along e1 dropping out as u is normal
    to e1.  Shape (N,) for a state (9, N).  Wheels only (NaN for a sphere,
    whose state has no axle).
    """
    params = _params(params)
    c, e1, w = state[dyn.C], _unit(state[dyn.E1]), state[dyn.W]
    pvec = dyn.contact_point(state, params)
    e3 = (pvec - c) / params.a
    u = np.cross(e1, e3, axis=0)
    cdot = params.a * np.cross(e3, w, axis=0)
    e1dot = np.cross(w, e1, axis=0)
    c1 = _dot(c, e1)
    rho = np.sqrt(np.maximum(_dot(c, c) - c1 * c1, 0.0))
    s = np.where(params.outside, -1.0, 1.0)
    e3dot_u = s * (_dot(cdot, u) - c1 * _dot(e1dot, u)) / rho
    return np.where(params.sphere, np.nan, _dot(w, e1) - e3dot_u)


def frame_geometry(t, state, params: dyn.BodyParams, psi0=0.0):
    """Everything the 3-D view draws of one body at its samples.

    Beyond the paper: a pure function of the simulated state (c, e1, w) of
    :mod:`deathsphere.physics.dynamics` in lab components (from
    :meth:`deathsphere.simulation.Simulation.sample_states`); the
    construction is documented in ``docs/simulation.md``, "3-D view".

    Parameters
    ----------
    t : (N,) float   sample times [s], increasing (one body's samples)
    state : (9, N) float   lab-frame states at those times
    params : :class:`deathsphere.physics.dynamics.BodyParams`, scalars
        (or arrays broadcasting against (N,))
    psi0 : float   spin angle [rad] at the first sample

    Returns
    -------
    dict of float64 arrays (vectors (3, N), scalars (N,)):

    ``centre``    c [m]
    ``axis``      unit e1: the wheel's axle; for a sphere its body-fixed
                  marker (the state's axis-1 rows)
    ``e3``        unit vector from the centre to the contact point
    ``contact``   contact point p = c + a e3 [m] (on the sphere |p| = r)
    ``spin``      wheel: angle [rad] of the marked spoke about e1, measured
                  from e3 towards e1 x e3, unwrapped: psi0 plus the
                  trapezoid integral of :func:`spin_rate` over the samples
                  (exact on a steady orbit, where the rate is constant);
                  sphere: NaN
    ``spoke``     unit body-fixed direction to draw: wheel
                  cos(spin) e3 + sin(spin) e1 x e3; sphere: the marker e1
    ``force``     contact force per unit mass F/m [m/s^2] (eq. 2 solved
                  for F, :func:`deathsphere.physics.dynamics.contact_force`)
    ``normal_force``, ``friction_force``  its parts along and across the
                  contact normal (they add up to ``force``)
    ``acceleration``  d2c/dt2 = F/m - g z [m/s^2]
    ``accel_g``   |d2c/dt2| / g: the centre's acceleration in g (eq. 36 on
                  a steady orbit)
    ``load_g``    |F|/(m g): the load a rider feels, |a - g| / g (the
                  orbit's and ride's load_g; sqrt(1 + accel_g^2) on a
                  steady horizontal orbit)
    ``rate``      |w| [rad/s]: how fast the body turns (any way), which
                  bounds the angle it turns between two frames
    ``speed``     |dc/dt| = |a e3 x w| [m/s] (eq. 6); ``speed_km_h`` the same in km/h
    ``normal``, ``friction_magnitude``, ``mu_required``  of
                  :func:`deathsphere.physics.dynamics.contact_force`
    ``force_angle_deg``  angle [deg] between the contact force and the
                  normal pressing the body onto the sphere (tan of it is the
                  friction needed; 90 and more: the force pulls, no contact)
    """
    t = np.asarray(t, dtype=np.float64)
    state = np.asarray(state, dtype=np.float64)
    params = _params(params)
    c, e1 = state[dyn.C], _unit(state[dyn.E1])
    pvec = dyn.contact_point(state, params)
    e3 = (pvec - c) / params.a
    f = dyn.contact_force(state, params)
    force = f["force"]
    friction = f["friction"]
    rate = spin_rate(state, params)
    steps = 0.5 * (rate[1:] + rate[:-1]) * np.diff(t)
    spin = psi0 + np.concatenate((np.zeros(min(t.size, 1)), np.cumsum(steps)))
    u = np.cross(e1, e3, axis=0)
    spoke = np.where(params.sphere, e1, np.cos(spin) * e3 + np.sin(spin) * u)
    accel = force - np.asarray(params.g) * np.array([0.0, 0.0, 1.0])[:, None]
    speed = _centre_speed(state, params)
    return {
        "centre": c, "axis": e1, "e3": e3, "contact": pvec,
        "spin": spin, "spoke": spoke,
        "force": force, "normal_force": force - friction, "friction_force": friction,
        "acceleration": accel, "accel_g": np.sqrt(_dot(accel, accel)) / params.g,
        "load_g": np.sqrt(_dot(force, force)) / params.g,
        "rate": _norm(state[dyn.W]), "speed": speed, "speed_km_h": speed * _KM_H_PER_M_S,
        "normal": f["normal"], "friction_magnitude": f["friction_magnitude"], "mu_required": f["mu_required"],
        "force_angle_deg": np.degrees(np.arctan2(f["friction_magnitude"], f["normal"])),
    }


def machine_frame_geometry(t, state, params, psi0=0.0):
    """What the 3-D view draws of one machine at its samples (beyond the
    paper; docs/machine.md eqs. M16-M18, docs/simulation.md "3-D view").

    ``params`` is one body's :class:`~deathsphere.simulation.bodies.MachineRun`
    (or :class:`~deathsphere.simulation.bodies.MachineGroundRun` off the globe).
    The keys of :func:`frame_geometry`, with the machine's meanings where
    they differ: ``centre`` the wheel centre C, ``e3`` the unit vector from
    C towards the crown (the up-axis is -e3), ``contact`` P, ``spin`` the
    angle of the marked spoke from the wheels' spin s = w.e1 - psi
    relative to the frame (eq. M17), ``force`` F/m of eq. M18,
    ``acceleration`` that of the centre of mass, ``load_g`` |F|/(m g)
    (what the rider feels, ``ride``'s load_g), ``speed`` |dC/dt| (the
    drawn wheel's, which bounds the frames' spacing); and the frame and
    rider: ``com`` the centre of mass G = C - (h - a) e3, ``head`` the top
    of the head H = Q - (head - t) e3 (eq. M2) and ``rider_speed`` |dG/dt|
    [m/s] (``ride``'s v_cm, the speed the view reads out).
    """
    t = np.asarray(t, dtype=np.float64)
    state = np.asarray(state, dtype=np.float64)
    mp = params.machine
    geometry = params.geometry(np.shape(state)[1:])
    pts = mm.machine_points(state, mp, geometry)
    rates = mm.machine_rates(state, mp, geometry)
    f = mm.machine_contact_force(state, params.ground, params.g, mp, geometry)
    e1, e3 = pts["e1"], pts["e3"]
    rate = rates["spin"]
    steps = 0.5 * (rate[1:] + rate[:-1]) * np.diff(t)
    spin = psi0 + np.concatenate((np.zeros(min(t.size, 1)), np.cumsum(steps)))
    u = np.cross(e1, e3, axis=0)
    force, friction = f["force"], f["friction"]
    g = np.asarray(params.g, dtype=float)
    accel = force - g * np.array([0.0, 0.0, 1.0])[:, None]
    speed = _norm(rates["vC"])
    return {
        "centre": pts["C"], "axis": e1, "e3": e3, "contact": pts["P"],
        "spin": spin, "spoke": np.cos(spin) * e3 + np.sin(spin) * u,
        "force": force, "normal_force": force - friction, "friction_force": friction,
        "acceleration": accel, "load_g": _norm(force) / g,
        "rate": _norm(state[dyn.W]), "speed": speed, "speed_km_h": speed * _KM_H_PER_M_S,
        "normal": f["normal"], "friction_magnitude": f["friction_magnitude"], "mu_required": f["mu_required"],
        "force_angle_deg": np.degrees(np.arctan2(f["friction_magnitude"], f["normal"])),
        "com": pts["G"], "head": pts["H"], "rider_speed": _norm(rates["vG"]),
    }


def ground_frame_geometry(t, state, params, psi0=0.0):
    """What the 3-D view draws of one wheel or ball on a ground other than
    the globe (beyond the paper; docs/dynamics.md sec. 7, docs/simulation.md
    "3-D view"): the keys of :func:`frame_geometry`, from the equations on
    the ground (:mod:`deathsphere.physics.dynamics_on`: the contact, its
    force, the wheel's spin rate relative to the contact direction).
    ``params`` is one body's :class:`~deathsphere.simulation.bodies.GroundRun`."""
    from deathsphere.physics import dynamics_on as don

    t = np.asarray(t, dtype=np.float64)
    state = np.asarray(state, dtype=np.float64)
    body = params.body(np.shape(state)[1:])
    c, e1 = state[dyn.C], _unit(state[dyn.E1])
    e3, pvec = don.contact_on(state, body)
    f = don.contact_force_on(state, body)
    force, friction = f["force"], f["friction"]
    rate = don.spin_rate_on(state, body)
    steps = 0.5 * (rate[1:] + rate[:-1]) * np.diff(t)
    spin = psi0 + np.concatenate((np.zeros(min(t.size, 1)), np.cumsum(steps)))
    spoke = np.where(body.sphere, e1, np.cos(spin) * e3 + np.sin(spin) * np.cross(e1, e3, axis=0))
    g = float(np.reshape(params.g, -1)[0])
    accel = force - g * np.array([0.0, 0.0, 1.0])[:, None]
    speed = _norm(np.cross(pvec - c, state[dyn.W], axis=0))
    return {
        "centre": c, "axis": e1, "e3": e3, "contact": pvec,
        "spin": spin, "spoke": spoke,
        "force": force, "normal_force": force - friction, "friction_force": friction,
        "acceleration": accel, "accel_g": _norm(accel) / g, "load_g": _norm(force) / g,
        "rate": _norm(state[dyn.W]), "speed": speed, "speed_km_h": speed * _KM_H_PER_M_S,
        "normal": f["normal"], "friction_magnitude": f["friction_magnitude"], "mu_required": f["mu_required"],
        "force_angle_deg": np.degrees(np.arctan2(f["friction_magnitude"], f["normal"])),
    }


def _speed(state, params, model):
    """The drawn body's centre speed: the paper's |a e3 x w|, a machine's |dC/dt|."""
    if model is PAPER:
        return _centre_speed(state, params)
    return model.centre_speed(state, model.contact_point(state, params))


def _subdivisions(t, state, params, max_turn, max_move, model=PAPER):
    """How many frames each sample interval needs (>= 1): from the fastest
    turn |w| and centre speed at its two ends."""
    rate = _norm(state[dyn.W])
    speed = _speed(state, params, model)
    dt = np.diff(t)
    need = np.maximum(np.fmax(rate[1:], rate[:-1]) * dt / max_turn,
                      np.fmax(speed[1:], speed[:-1]) * dt / (max_move * np.asarray(params.r)))
    need = np.where(np.isfinite(need), need, 1.0)
    return np.maximum(1, np.ceil(need)).astype(np.int64)


def _integrate_between(t, state, params, n, batch=2000, model=PAPER):
    """States at the n_k - 1 evenly spaced times inside each interval k with
    n_k > 1, integrated afresh (solve_ivp, DOP853, lab frame) from the
    sample at its start; returns (times, states (9, M))."""
    from deathsphere.simulation.integrator import integrate   # scipy's integrate only when drawn

    ks = np.flatnonzero(n > 1)
    times, states = [], []
    for lo in range(0, ks.size, batch):
        k = ks[lo:lo + batch]
        nb = k.size
        dt = np.diff(t)[k]
        y0 = state[:, k]
        scale_w = np.sqrt(_dot(y0[dyn.W], y0[dyn.W]) + np.asarray(params.g) / np.asarray(params.a))
        pb = broadcast_params(params, nb)

        def fun(tau, y):
            # each interval runs in its own time tau in [0, 1], t = t_k + tau dt_k
            return (model.rhs(y.reshape(9, nb), pb) * dt).reshape(-1)

        # as the simulation's own error control (docs/simulation.md), the
        # sphere's marker rows left out of it
        marker = np.where(model.marker(pb), 1e3, 1e-10)
        atol = np.concatenate((np.broadcast_to(1e-10 * np.asarray(pb.r), (3, nb)), np.broadcast_to(marker, (3, nb)),
                               np.broadcast_to(1e-10 * scale_w, (3, nb)))).reshape(-1)
        max_step = 2.0 / float(np.max(scale_w * dt))
        # a drawing of a run already decided: no events, no statuses
        sol = integrate(fun, (0.0, 1.0), y0.reshape(-1), (), method="DOP853", rtol=1e-10, atol=atol,
                        dense_output=True, max_step=max_step).sol
        if sol.status != 0:
            raise RuntimeError(f"the view's frames could not be integrated: {sol.message}")
        for m in np.unique(n[k]):
            sel = np.flatnonzero(n[k] == m)
            tau = np.arange(1, m) / m
            y = sol.sol(tau).reshape(9, nb, tau.size)[:, sel, :]           # (9, s, m-1)
            times.append((t[k[sel], None] + tau[None, :] * dt[sel, None]).reshape(-1))
            states.append(y.reshape(9, -1))
    if not times:
        return np.zeros(0), np.zeros((9, 0))
    return np.concatenate(times), np.concatenate(states, axis=1)


def refine_samples(t, state, params: dyn.BodyParams, *, max_turn=MAX_TURN_RAD, max_move=MAX_MOVE_R):
    """Samples of one body close enough for the 3-D view: the given ones
    plus, inside every interval where the body would turn more than a part
    of ``max_turn`` [rad] or its centre move more than a part of
    ``max_move`` r, evenly spaced states integrated afresh from the sample
    at the interval's start (the equations of motion of
    :mod:`deathsphere.physics.dynamics`, or a machine's, eqs. M16-M19;
    not an interpolation).  The number
    of frames follows the fastest rotation and motion of each interval, so
    a run is sampled finely only where it moves fast.

    Beyond the paper (docs/simulation.md, "3-D view").  Returns (t (M,),
    state (9, M)), M >= N, increasing in time, holding the given samples
    (the last one, an event's, among them).  ``params``: the paper's body
    (:class:`~deathsphere.physics.dynamics.BodyParams`) or one machine
    (:class:`~deathsphere.simulation.bodies.MachineRun`).
    """
    model = model_of(params)
    if model is PAPER:
        params = _params(params)
    return _refine(t, state, params, model, max_turn, max_move)


def _refine(t, state, params, model, max_turn, max_move):
    """:func:`refine_samples` with the body model given."""
    t = np.asarray(t, dtype=np.float64)
    state = np.asarray(state, dtype=np.float64)
    if t.size < 2:
        return t, state
    n = _subdivisions(t, state, params, _TARGET * max_turn, _TARGET * max_move, model)
    extra_t, extra = _integrate_between(t, state, params, n, model=model)
    t_all = np.concatenate((t, extra_t))
    order = np.argsort(t_all, kind="stable")
    return t_all[order], np.concatenate((state, extra), axis=1)[:, order]


def body_frames(summary, states: dict, *, refine: bool = True, params=None) -> dict[int, dict]:
    """:func:`frame_geometry` of every body of a run, at all its samples
    and, with ``refine``, at the frames :func:`refine_samples` adds between
    them (so that no body turns more than a quarter turn, nor its centre
    moves more than 2 % of r, from one frame to the next).

    ``summary`` is the run's summary table (one row per body: ``input_row``,
    ``body``, ``side``, ``a_m``, ``r_m``, ``k``, ``g_m_s2``) and ``states``
    :meth:`deathsphere.simulation.Simulation.sample_states`.  Returns
    ``{input_row: {"t": (M,) frame times, "sample": (M,) bool (a sample
    of ``states``, i.e. a row of the time series), "bounds": (the most
    turn [rad], the most centre step [r]) between frames, **geometry}}``
    for each body with samples (a body that could not start has none and
    no entry).  ``params``: the run's per-body parameters
    (:attr:`deathsphere.simulation.Starts.params`, in the summary's order),
    needed for machines (:func:`machine_frame_geometry`: the summary does
    not hold a machine's inertias); the paper's bodies are read from the
    summary.
    """
    rows = np.asarray(states["input_row"])
    t_all = np.asarray(states["t_s"], dtype=np.float64)
    state = np.asarray(states["state"], dtype=np.float64)
    out = {}
    for i, row in enumerate(np.asarray(summary["input_row"]).tolist()):
        sel = np.flatnonzero(rows == row)
        if not sel.size:
            continue
        t, y = t_all[sel], state[:, sel]
        if params is not None and model_of(params) in (MACHINE, MACHINE_ON_GROUND, ON_GROUND):
            one = take(params, i)
            geometry = ground_frame_geometry if model_of(params) is ON_GROUND else machine_frame_geometry
        else:
            one = dyn.BodyParams(*(float(summary[name][i]) for name in ("a_m", "r_m", "k", "g_m_s2")),
                                 summary["side"][i] == "outside", isinstance(paper_body_named(summary["body"][i]), Ball))
            geometry = frame_geometry
        if refine:
            t, y = refine_samples(t, y, one)
        out[int(row)] = {"t": t, "sample": np.isin(t, t_all[sel]), "bounds": (MAX_TURN_RAD, MAX_MOVE_R),
                         **geometry(t, y, one)}
    return out
