"""Frame geometry of the 3-D view: what to draw, from the simulated state.

It lives with the simulation, not the viewer, because it is physics (the
contact point, the contact force, the wheel's spin rate): the viewer only
draws what this hands it.

Beyond the paper: the states come from :mod:`deathsphere.simulation`
(exact equations of motion); how they are drawn is described in
``docs/simulation.md``, section "3-D view".  Pure numpy, vectorised over
samples; no drawing here.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics import dynamics as dyn

__all__ = ["frame_geometry", "spin_rate", "body_frames"]


def _unit(v):
    return v / np.sqrt(np.sum(v * v, axis=0))


def _dot(u, v):
    return np.sum(u * v, axis=0)


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
    ``g_load``    |d2c/dt2| / g: the centre's acceleration in g (eq. 36 on
                  a steady orbit)
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
    return {
        "centre": c, "axis": e1, "e3": e3, "contact": pvec,
        "spin": spin, "spoke": spoke,
        "force": force, "normal_force": force - friction, "friction_force": friction,
        "acceleration": accel, "g_load": np.sqrt(_dot(accel, accel)) / params.g,
    }


def body_frames(summary, states: dict) -> dict[int, dict]:
    """:func:`frame_geometry` of every body of a run, at all its samples.

    ``summary`` is the run's summary table (one row per body: ``input_row``,
    ``body``, ``side``, ``a_m``, ``r_m``, ``k``, ``g_m_s2``) and ``states``
    :meth:`deathsphere.simulation.Simulation.sample_states`.  Returns
    ``{input_row: {"t": (N,) sample times, **geometry}}`` for each body
    with samples (a body that could not start has none and no entry).
    """
    rows = np.asarray(states["input_row"])
    t_all = np.asarray(states["t_s"], dtype=np.float64)
    state = np.asarray(states["state"], dtype=np.float64)
    out = {}
    for i, row in enumerate(np.asarray(summary["input_row"]).tolist()):
        sel = np.flatnonzero(rows == row)
        if not sel.size:
            continue
        params = dyn.BodyParams(*(float(summary[name][i]) for name in ("a_m", "r_m", "k", "g_m_s2")),
                                summary["side"][i] == "outside", summary["body"][i] == "sphere")
        out[int(row)] = {"t": t_all[sel], **frame_geometry(t_all[sel], state[:, sel], params)}
    return out
