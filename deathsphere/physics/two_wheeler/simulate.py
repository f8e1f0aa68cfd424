"""The Whipple bicycle's nonlinear motion, integrated: from a steady turn
(or straight running), kicked in lean, lean rate or steer rate, with the
steer held by a steady torque, a simple rider, nothing, or locked (beyond
the paper; docs/two-wheeler.md sec. 10.1).

The state is the eight coordinates and the three independent speeds (lean
rate, rear wheel rate, steer rate); the five dependent speeds come from the
rolling constraints at every step (so those hold exactly) and the
accelerations from Kane's reduced equations.  The pitch is integrated from
its rate, so the front contact's holonomic constraint holds to the
integrator's tolerance: its residual is reported.

The rider's steer torque is T = T_0 + k_lean (lean - lean_0) + k_rate
lean', T_0 the turn's steady torque and lean_0 its lean: positive gains
steer into the fall.  Hands-free is T = 0.  A locked steer keeps its
steer rate zero: the lean and rear wheel rates are then the independent
speeds, their accelerations from the lean and rear wheel rows of Kane's
reduced equations (where the steer torque does not appear), and the
lock's torque is what the steer row then asks for.

The contact forces: the front contact's from the constraints' multipliers,
the total from the mass centre's acceleration (m a - m g), the rear's the
difference; the mass centre's acceleration by a central difference of its
position along the motion's second-order Taylor path (step 1e-4 s, relative
error ~1e-8 of the force).

The run's pieces live here, pure: its start (:func:`start`), its rates
(:func:`rates`), the contact forces at a state (:func:`state_forces`) and
the series and summary of a trajectory (:func:`records`); the integration,
its events and its statuses are the simulation's
(:mod:`deathsphere.simulation.two_wheeler`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics.two_wheeler import geometry, grounds, motion
from deathsphere.physics.two_wheeler.parameters import BicycleParameters

__all__ = ["Steering", "Kick", "Solver", "Run", "rider_torque", "lock_torque", "contact_forces", "start",
           "steer_torque", "rates", "state_forces", "records"]

#: The time step of the mass centre's acceleration by central differences (s).
_H = 1e-4


@dataclass(frozen=True)
class Steering:
    """How the steer is held (docs/two-wheeler.md sec. 10.1): the rider's
    torque T = ``torque0`` + ``k_lean`` (lean - ``lean0``) + ``k_rate``
    lean' (N m, N m/rad, N m s/rad; ``lean0`` None: the start's lean), or
    ``hands_free`` (T = 0), or ``locked`` (the steer held at the start's
    angle by whatever torque it takes)."""

    torque0: float = 0.0
    lean0: float | None = None
    k_lean: float = 0.0
    k_rate: float = 0.0
    hands_free: bool = False
    locked: bool = False


@dataclass(frozen=True)
class Kick:
    """What kicks the start off its steady turn: the lean (rad), the lean
    and steer rates (rad/s; the dependent speeds follow from the
    constraints)."""

    lean: float = 0.0
    lean_rate: float = 0.0
    steer_rate: float = 0.0


@dataclass(frozen=True)
class Solver:
    """How the motion is integrated: scipy's ``solve_ivp`` method, its
    tolerances (``atol`` None: = ``rtol``) and the rows reported."""

    method: str = "DOP853"
    rtol: float = 1e-10
    atol: float | None = None
    n_points: int = 200


def rider_torque(lean, lean_rate, torque0=0.0, lean0=0.0, k_lean=0.0, k_rate=0.0):
    """The rider's steer torque T = T_0 + k_lean (lean - lean_0) + k_rate
    lean' (N m; beyond the paper; docs/two-wheeler.md sec. 10.1)."""
    return torque0 + k_lean * (lean - lean0) + k_rate * lean_rate


def lock_torque(q, u_ind, values, ground=motion.FLAT):
    """(T, a, u): the torque a locked steer applies (N m), the lean and rear
    wheel accelerations a (2, ...) and the eight speeds at (q, u_ind)
    (u_ind's steer rate is zero on a locked steer): in Kane's reduced
    equations (:func:`motion.reduced_mass_and_forcing`) with the steer's
    acceleration zero, the lean and rear wheel rows, where the steer torque
    does not appear, give a, and the steer row then gives T (beyond the
    paper; docs/two-wheeler.md sec. 10.1)."""
    Mr, Fr, u = motion.reduced_mass_and_forcing(q, u_ind, values, 0.0, ground)
    a = np.linalg.solve(Mr[..., :2, :2], Fr[..., :2, None])
    T = (Mr[..., 2:, :2] @ a)[..., 0, 0] - Fr[..., 2]
    return T, np.moveaxis(a[..., 0], -1, 0), u


def _mass_centre(q, p: BicycleParameters, ground):
    pts = geometry.points(q, p, ground)
    m = p.mR + p.mB + p.mH + p.mF
    return (p.mR * pts["rear_wheel"] + p.mB * pts["rear_frame"] + p.mH * pts["front_frame"]
            + p.mF * pts["front_wheel"]) / m


def contact_forces(q, u, udot, lam, p: BicycleParameters, ground=motion.FLAT, g=STANDARD_GRAVITY):
    """(normal_rear, friction_rear, normal_front, friction_front), each per
    total mass (m/s^2; normal positive when pushing, friction the tangential
    part's magnitude), at the state (q, u) on ``ground`` under gravity ``g``
    with accelerations udot and the constraints' multipliers lam (beyond the
    paper; docs/two-wheeler.md sec. 8.2, 10.1)."""
    mass = p.mR + p.mB + p.mH + p.mF
    plus = _mass_centre(q + _H * u + 0.5 * _H**2 * udot, p, ground)
    minus = _mass_centre(q - _H * u + 0.5 * _H**2 * udot, p, ground)
    acc = (plus - 2 * _mass_centre(q, p, ground) + minus) / _H**2
    gravity = np.zeros_like(acc)
    gravity[2] = g
    total = acc - gravity
    pts = geometry.points(q, p, ground)
    Y = pts["frames"]["Y"]
    front = (lam[2] * Y[0] + lam[3] * Y[1] + lam[4] * Y[2]) / mass
    rear = total - front
    n_rear, n_front = grounds.of(ground).normals(pts, q[0])
    out = []
    for force, n in ((rear, n_rear), (front, n_front)):
        normal = np.sum(force * n, axis=0)
        out += [normal, np.linalg.norm(force - normal * n, axis=0)]
    return tuple(out)


def _residual(q, p, ground):
    h, _ = grounds.of(ground).holonomic(q, p)
    return np.abs(h[0])


@dataclass(frozen=True)
class Run:
    """What a run of a two-wheeler integrates with: the ``parameters``,
    their ``values`` under gravity ``g`` on ``ground``, the steer
    ``locked`` or held by the torque :func:`rider_torque` with ``gains``
    (T_0, lean_0, k_lean, k_rate) and the lean ``lean0`` the deviations are
    measured from."""

    parameters: BicycleParameters
    values: object
    ground: object
    g: float
    locked: bool
    gains: tuple
    lean0: float


def start(parameters: BicycleParameters, q0, u_ind0, *, ground=motion.FLAT, g=STANDARD_GRAVITY,
          steering=Steering(), kick=Kick()):
    """(run, y0): the :class:`Run` and the state (q, u_ind) (11,) it starts
    from: (q0, u_ind0) kicked by ``kick``, the pitch re-solved, a locked
    steer's rate zero (docs/two-wheeler.md sec. 10.1)."""
    values = motion.parameter_values(parameters, g, ground)
    q0 = np.array(q0, float)
    lean0 = float(q0[motion.LEAN]) if steering.lean0 is None else float(steering.lean0)
    q0[motion.LEAN] += kick.lean
    q0 = motion.pitch(q0, values, ground)
    u_ind0 = np.array(u_ind0, float) + np.array([kick.lean_rate, 0.0, kick.steer_rate])
    if steering.locked:
        u_ind0[2] = 0.0
    gains = (0.0, 0.0, 0.0, 0.0) if steering.hands_free else (steering.torque0, lean0, steering.k_lean,
                                                              steering.k_rate)
    run = Run(parameters, values, ground, g, bool(steering.locked), gains, lean0)
    return run, np.concatenate([q0, u_ind0])


def steer_torque(y, run: Run):
    """The steer torque at the state(s) y (11, ...) (N m; beyond the paper;
    docs/two-wheeler.md sec. 10.1)."""
    if run.locked:
        return lock_torque(y[:8], y[8:], run.values, run.ground)[0]
    return rider_torque(y[motion.LEAN], y[8], *run.gains)


def rates(y, run: Run):
    """dy/dt at the state y (11,): the coordinates' rates (the eight
    speeds) and the independent speeds' accelerations (Kane's reduced
    equations; beyond the paper; docs/two-wheeler.md sec. 10.1)."""
    q, u_ind = y[:8], y[8:]
    if run.locked:
        _, a, u = lock_torque(q, u_ind, run.values, run.ground)
        return np.concatenate([u, a, [0.0]])
    Mr, Fr, u = motion.reduced_mass_and_forcing(q, u_ind, run.values, steer_torque(y, run), run.ground)
    return np.concatenate([u, np.linalg.solve(Mr, Fr)])


def state_forces(y, run: Run):
    """:func:`contact_forces` (normal_rear, friction_rear, normal_front,
    friction_front) at the state y (11,) (beyond the paper;
    docs/two-wheeler.md sec. 10.1)."""
    q, u_ind = y[:8], y[8:]
    u = motion.dependent_speeds(q, u_ind, run.values, run.ground)
    udot, lam = motion.accelerations(q, u, run.values, steer_torque(y, run), run.ground)
    return contact_forces(q, u, udot, lam, run.parameters, run.ground, run.g)


def records(ts, Y, run: Run):
    """(series, summary) of the trajectory Y (11, n) at the times ts (n,):
    the series dict of (n,) arrays and the coordinates ``q`` (8, n), the
    summary's extremes and drifts (docs/two-wheeler.md sec. 10.1)."""
    p, values, ground, lean0 = run.parameters, run.values, run.ground, run.lean0
    q, u_ind = Y[:8], Y[8:]
    u = motion.dependent_speeds(q, u_ind, values, ground)
    T = steer_torque(Y, run)
    T = np.broadcast_to(T, ts.shape)
    udot, lam = motion.accelerations(q, u, values, T, ground)
    n_rear, f_rear, n_front, f_front = contact_forces(q, u, udot, lam, p, ground, run.g)
    E = motion.energy(q, u, values, ground)
    kinetic0 = grounds.of(ground).energy(q[:, :1], u[:, :1], values)[0][0]
    series = {"t": ts, "lean": q[motion.LEAN], "steer": q[motion.STEER], "heading": q[motion.HEADING],
              "theta_rear": grounds.of(ground).theta_rear(q),
              "lean_rate": u[motion.LEAN], "steer_rate": u[motion.STEER], "v_rear": np.abs(u[motion.REAR]) * p.rR,
              "steer_torque": T, "normal_rear": n_rear, "normal_front": n_front, "friction_rear": f_rear,
              "friction_front": f_front, "energy_drift": (E - E[0]) / kinetic0,
              "constraint_residual": _residual(q, values, ground), "q": q}
    summary = {"t_end": float(ts[-1]),
               "max_lean_deviation": float(np.max(np.abs(q[motion.LEAN] - lean0))),
               "final_lean_deviation": float(q[motion.LEAN, -1] - lean0),
               "max_energy_drift": float(np.max(np.abs(series["energy_drift"]))),
               "max_constraint_residual": float(np.max(series["constraint_residual"])),
               "min_normal_rear": float(np.min(n_rear)), "min_normal_front": float(np.min(n_front))}
    return series, summary
