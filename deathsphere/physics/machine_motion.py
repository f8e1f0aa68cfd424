"""What a machine's state says, for a simulation of its exact equations of
motion (beyond the paper; docs/machine.md sec. 5, eqs. M16-M19): its points
(contact, crown, centre of mass, head), the frame's rate and the wheels'
spin, the contact force, the energy, the constraints, and the start on a
steady orbit kicked in tilt.

State (9, ...), ground, gravity and the machine's arrays as
:mod:`deathsphere.physics.machine_dynamics` (C, E, W;
:class:`~deathsphere.physics.machine_arrays.MachineArrays`), each function
taking those it needs; every function is vectorised over the trailing
(body) axes and loops over no body.  ``geometry`` (where taken): the crown
point's geometry class, the globe's :class:`GeometryRates` by default, any
ground's from :func:`deathsphere.physics.machine_dynamics_on.crown_geometry`
(docs/machine.md, "On any ground").
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.machine_arrays import MachineArrays
from deathsphere.physics.machine_dynamics import (
    GeometryRates,
    machine_geometry,
    machine_orbit_state,
    rhs_of_geometry,
)
from deathsphere.physics.vectors import cross
from deathsphere.physics.vectors import dot as _dot
from deathsphere.physics.vectors import norm as _norm

__all__ = ["machine_points", "machine_rates", "machine_contact_force", "machine_energy", "machine_residuals",
           "machine_project", "machine_start"]


def machine_points(state, p: MachineArrays, geometry=GeometryRates) -> dict:
    """The machine's axes and points from a state (eq. M16's geometry):
    ``e1`` the unit axle, ``e3`` the unit vector from the wheel centre
    towards the crown (the up-axis is -e3), ``C`` the wheel centre, ``Q``
    the crown point, ``P`` the contact point, ``G`` = C - (h - a) e3 the
    centre of mass and ``H`` = Q - (head - t) e3 the top of the rider's head
    (eq. M2).  Vectors (3, ...)."""
    state = np.asarray(state)
    C = state[0:3]
    a, t = p.wheel_radius, p.tyre_radius
    geo = geometry(C, state[3:6], a, t)
    e1, e3, Q, P = geo.h1, geo.e3, geo.Q, geo.P
    return {"e1": e1, "e3": e3, "C": C, "Q": Q, "P": P, "G": C - (p.com_height - a) * e3,
            "H": Q - (p.head_height - t) * e3}


def machine_rates(state, p: MachineArrays, geometry=GeometryRates) -> dict:
    """First-order rates of a state (eqs. M16-M17): ``vC`` = dC/dt (rolling),
    ``e3dot`` = de3/dt, ``vG`` = dG/dt, ``omega_f`` the frame's angular
    velocity, ``psi`` its rate about the axle, ``spin`` s = w.e1 - psi the
    wheels' spin relative to the frame, and the frame axes ``e1``, ``e2``,
    ``e3``."""
    state = np.asarray(state)
    C, E, W = state[0:3], state[3:6], state[6:9]
    geo = geometry(C, E, p.wheel_radius, p.tyre_radius)
    e1, e3 = geo.h1, geo.e3
    vC = -cross(W, geo.P - C)
    Edot = cross(W, E)
    e3dot = geo.rates(vC, Edot).e3_1
    e2 = cross(e3, e1)
    psi = -_dot(e3dot, e2)
    w1 = _dot(W, e1)
    omega_f = W - (w1 - psi) * e1
    return {"vC": vC, "e3dot": e3dot, "vG": vC - (p.com_height - p.wheel_radius) * e3dot, "omega_f": omega_f,
            "psi": psi,
            "spin": w1 - psi, "e1": e1, "e2": e2, "e3": e3}


def machine_contact_force(state, ground, g, p: MachineArrays, geometry=GeometryRates) -> dict:
    """The contact force per unit mass from eq. M18, F/m = d2G/dt2 + g z
    less the pitch constraint's force lambda f/m, with the same keys as :func:`deathsphere.physics.dynamics.contact_force`:
    ``force`` (3, ...), ``normal`` (the part pressing tyre and sphere
    together, -F.n with n the ground's outward normal at P, P/|P| on the
    globe; > 0 while contact holds), ``friction``
    (3, ...) the tangential part, ``friction_magnitude`` and ``mu_required``
    (NaN where normal <= 0)."""
    state = np.asarray(state)
    _, force, _ = rhs_of_geometry(state, g, p, geometry, forces=True)
    geo = geometry(state[0:3], state[3:6], p.wheel_radius, p.tyre_radius)
    n = geo.outward()
    fn = _dot(force, n)
    friction = force - fn * n
    normal = -fn
    fmag = _norm(friction)
    ok = normal > 0
    with np.errstate(divide="ignore", invalid="ignore"):
        mu = np.where(ok, fmag / np.where(ok, normal, 1.0), np.nan)
    return {"force": force, "normal": normal, "friction": friction, "friction_magnitude": fmag,
            "mu_required": mu}


def machine_energy(state, g, p: MachineArrays, geometry=GeometryRates):
    """(energy, kinetic energy) per unit mass [J/kg] (beyond the paper):
    T = m |dG/dt|^2 / 2 + omega_f . I . omega_f / 2 + J s (e1 . omega_f) + J s^2 / 2
    (the locked inertia I holds the wheels' polar moments, so their spin
    relative to the frame adds the last two terms), E = T + m g G_z.

    Conserved: the contact rolls and the pitch constraint's reaction is
    ideal (docs/machine.md sec. 5), so its drift is the integrator's error."""
    state = np.asarray(state)
    rt = machine_rates(state, p, geometry)
    om = rt["omega_f"]
    o1, o2, o3 = _dot(rt["e1"], om), _dot(rt["e2"], om), _dot(rt["e3"], om)
    s = rt["spin"]
    rot = (p.roll_inertia * o2 * o2 + p.pitch_inertia * o1 * o1 + p.yaw_inertia * o3 * o3
           + p.spin_inertia * s * (2 * o1 + s))
    kinetic = 0.5 * _dot(rt["vG"], rt["vG"]) + 0.5 * rot / p.mass
    G = state[0:3] - (p.com_height - p.wheel_radius) * rt["e3"]
    return kinetic + g * G[2], kinetic


def machine_residuals(state, ground, p: MachineArrays) -> dict:
    """The residuals of eq. M16's constraints (beyond the paper): ``axis``
    |E| - 1 [-], ``contact`` |Q| - (r - t) [m] (the crown point on the
    sphere of radius r - t)."""
    state = np.asarray(state)
    Q = machine_geometry(state[0:3], state[3:6], p.wheel_radius, p.tyre_radius)[2]
    return {"axis": _norm(state[3:6]) - 1.0, "contact": _norm(Q) - (ground.radius - p.tyre_radius)}


def machine_project(state, ground, p: MachineArrays):
    """The state moved back onto eq. M16's constraints (beyond the paper): E normalised, then C
    shifted along Q/|Q| by (r - t) - |Q|, which keeps e3 and puts the crown
    point exactly on its sphere (as :func:`deathsphere.physics.dynamics.project`)."""
    state = np.array(state, dtype=np.result_type(state, float), copy=True)
    state[3:6] = state[3:6] / _norm(state[3:6])
    Q = machine_geometry(state[0:3], state[3:6], p.wheel_radius, p.tyre_radius)[2]
    qn = _norm(Q)
    state[0:3] = state[0:3] + ((ground.radius - p.tyre_radius) - qn) * Q / qn
    return state


def machine_start(theta, alpha, d_alpha, ground, g, p: MachineArrays):
    """(state (9, ...), Omega) of a machine on the steady orbit (theta,
    alpha) (eq. M8, :func:`machine_orbit_state`) kicked by a tilt d_alpha
    [rad] about the direction of travel through the crown point Q: Q, hence
    the contact point P, and the angular velocity w stay, the axle and the
    wheel centre take the tilt alpha + d_alpha.  Contact holds exactly and
    rolling identically (dC/dt follows from w); the state is off the family
    of steady orbits, since w is that of alpha."""
    X0, om = machine_orbit_state(theta, alpha, ground, g, p)
    Xk, _ = machine_orbit_state(theta, np.asarray(alpha) + d_alpha, ground, g, p)
    return np.concatenate((Xk[0:6], X0[6:9])), om
