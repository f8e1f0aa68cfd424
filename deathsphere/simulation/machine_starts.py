"""Initial conditions of simulated machines (a motorcycle and rider; beyond
the paper: docs/machine.md sec. 5, docs/simulation.md "Bodies").

:func:`machine_starts` puts machines on steady horizontal orbits (theta,
alpha) inside the sphere, eq. M8, optionally kicked in tilt, as a
:class:`~deathsphere.simulation.starts.Starts` that the same
:class:`~deathsphere.simulation.Simulation` integrates with the machine's
equations of motion (M16-M19).
"""

from __future__ import annotations

import math

import numpy as np

from deathsphere.physics.ground import Sphere
from deathsphere.physics.machine import ride_orbit
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.physics.machine_motion import machine_start
from deathsphere.simulation.bodies import MachineRun, take
from deathsphere.simulation.starts import Starts, start_status
from deathsphere.simulation.status import RunStatus

__all__ = ["machine_starts", "machine_run", "machine_ground_run", "machine_ground_starts"]


def machine_run(machine, ground: Sphere, g: float, n: int = 1) -> MachineRun:
    """:class:`MachineRun` of n copies of one machine record (or of its
    :class:`~deathsphere.physics.machine_arrays.MachineArrays`) in the globe
    ``ground`` under gravity ``g`` (docs/machine.md sec. 1, beyond the
    paper)."""
    arrays = machine_arrays(machine).map(lambda x: np.full(n, float(x)))
    return MachineRun(arrays, np.full(n, float(ground.radius)), np.full(n, float(g)),
                      np.full(n, getattr(machine, "name", "custom"), dtype=object))


def machine_starts(bodies: MachineRun, theta_deg, alpha_deg, *, perturb_deg=0.0, mu=math.inf,
                   input_row=None) -> Starts:
    """Machines on steady horizontal orbits (beyond the paper; docs/machine.md
    eqs. M8, M16).

    Parameters (one body per element of ``bodies``; the angles broadcast
    against them)
    ----------
    bodies : :class:`~deathsphere.simulation.bodies.MachineRun` (:func:`machine_run`)
    theta_deg : [deg]  polar angle of the contact point (0..180)
    alpha_deg : [deg]  tilt of the up-axis above the orbit plane (lean from
        the vertical = 90 - alpha)
    perturb_deg : [deg]  the kick: the machine tilted by this about its
        direction of travel through the crown point Q, keeping Q (so the
        contact point) and the angular velocity (lab components): the
        geometry of tilt alpha + perturb_deg with the w of alpha
        (:func:`deathsphere.physics.machine_motion.machine_start`)
    mu : friction available (inf: no ``slips`` event)

    Bodies without a steady orbit (the wheel or the head does not fit,
    eq. M10 and M11's clearance; Omega^2 <= 0 or undefined, eq. M8) get
    status no_fit / no_orbit, with the reason ``ride`` gives, and are not
    integrated; contact and friction are the run's events.
    """
    n = int(np.size(bodies.a))
    th_d, al_d, kick = (np.broadcast_to(np.asarray(x, dtype=float), (n,)).copy()
                        for x in (theta_deg, alpha_deg, perturb_deg))
    if not np.all(np.isfinite(th_d)) or np.any((th_d < 0) | (th_d > 180)):
        raise ValueError("theta must be finite and within 0..180 deg")
    if not np.all(np.isfinite(al_d)) or not np.all(np.isfinite(kick)):
        raise ValueError("alpha and perturb_deg must be finite (degrees)")
    th, al, d_al = np.deg2rad(th_d), np.deg2rad(al_d), np.deg2rad(kick)
    b = bodies
    orb = ride_orbit(th, al, b.ground, b.g, b.machine)
    status, reason = start_status(orb)
    ok = status == RunStatus.PENDING
    rate = np.where(ok, orb["omega"], np.nan)
    state = np.full((9, n), np.nan)
    if ok.any():
        one = take(b, ok)
        state[:, ok], _ = machine_start(th[ok], al[ok], d_al[ok], one.ground, one.g, one.machine)
    period = np.where(ok, 2 * np.pi / np.where(ok, rate, 1.0), np.nan)
    rows = (np.arange(1, n + 1, dtype=np.int64) if input_row is None
            else np.broadcast_to(np.asarray(input_row, dtype=np.int64), (n,)).copy())
    return Starts(
        state=state, params=b, frame=np.broadcast_to(np.eye(3), (n, 3, 3)).copy(), input_row=rows,
        body=np.full(n, "machine", dtype=object), side=np.full(n, "inside", dtype=object),
        orbit=np.full(n, "horizontal", dtype=object), theta=th, alpha=al, theta_deg=th_d, alpha_deg=al_d,
        rate=rate, turning=np.where(ok, rate, 0.0), period=period, phi0=np.zeros(n),
        speed=np.where(ok, orb["v_cm"], np.nan), omega3=np.full(n, np.nan), perturb_deg=kick,
        perturb_theta_deg=np.zeros(n), mu=np.broadcast_to(np.asarray(mu, dtype=float), (n,)).copy(),
        status=status, reason=reason)


def machine_ground_run(machine, ground, g: float, lane, n: int = 1):
    """:class:`~deathsphere.simulation.bodies.MachineGroundRun` of n copies
    of one machine record on ``ground`` (not the globe) under gravity ``g``,
    starting on ``lane`` [m] (its height; on flat ground the turn radius),
    broadcast to n (beyond the paper; docs/machine.md, "On any ground")."""
    from deathsphere.simulation.bodies import MachineGroundRun

    arrays = machine_arrays(machine).map(lambda x: np.full(n, float(x)))
    lane = np.broadcast_to(np.asarray(lane, dtype=float), (n,)).copy()
    rho, z = ground.contact(np.clip(lane, 0.0, getattr(ground, "highest_lane", np.inf)))
    return MachineGroundRun(arrays, np.full(n, float(g)), np.full(n, getattr(machine, "name", "custom"), dtype=object),
                            np.broadcast_to(np.asarray(rho, dtype=float), (n,)).copy(),
                            np.broadcast_to(np.asarray(z, dtype=float) - ground.lowest, (n,)).copy(), lane, ground)


def machine_ground_starts(bodies, alpha_deg, *, perturb_deg=0.0, mu=math.inf, input_row=None) -> Starts:
    """Machines on steady lanes of a ground other than the globe (beyond the
    paper; docs/machine.md, "On any ground"): ``bodies`` a
    :class:`~deathsphere.simulation.bodies.MachineGroundRun`
    (:func:`machine_ground_run`, its lanes), at tilt ``alpha_deg``, kicked
    by ``perturb_deg`` about the direction of travel through the crown
    point (:func:`~deathsphere.physics.machine_dynamics_on.machine_start_on`).
    Lanes without a steady orbit (eqs. MS1-MS7: no_fit, no_orbit) get that
    status and ``ride``'s reason and are not integrated."""
    from deathsphere.physics.machine_dynamics_on import machine_start_on
    from deathsphere.physics.machine_surface import ride_orbit_on

    n = int(np.size(bodies.a))
    al_d, kick = (np.broadcast_to(np.asarray(x, dtype=float), (n,)).copy() for x in (alpha_deg, perturb_deg))
    if not np.all(np.isfinite(al_d)) or not np.all(np.isfinite(kick)):
        raise ValueError("alpha and perturb_deg must be finite (degrees)")
    b = bodies
    al, d_al = np.deg2rad(al_d), np.deg2rad(kick)
    orb = ride_orbit_on(b.lane, al, b.ground, b.g, b.machine)
    status, reason = start_status(orb)
    ok = status == RunStatus.PENDING
    rate = np.where(ok, orb["omega"], np.nan)
    state = np.full((9, n), np.nan)
    if ok.any():
        one = take(b, ok)
        state[:, ok], _ = machine_start_on(one.lane, al[ok], d_al[ok], one.ground, one.g, one.machine)
    period = np.where(ok, 2 * np.pi / np.where(ok, rate, 1.0), np.nan)
    rows = (np.arange(1, n + 1, dtype=np.int64) if input_row is None
            else np.broadcast_to(np.asarray(input_row, dtype=np.int64), (n,)).copy())
    return Starts(
        state=state, params=b, frame=np.broadcast_to(np.eye(3), (n, 3, 3)).copy(), input_row=rows,
        body=np.full(n, "machine", dtype=object), side=np.full(n, "inside", dtype=object),
        orbit=np.full(n, "horizontal", dtype=object), theta=np.full(n, np.nan), alpha=al,
        theta_deg=np.full(n, np.nan), alpha_deg=al_d,
        rate=rate, turning=np.where(ok, rate, 0.0), period=period, phi0=np.zeros(n),
        speed=np.where(ok, orb["v_cm"], np.nan), omega3=np.full(n, np.nan), perturb_deg=kick,
        perturb_theta_deg=np.zeros(n), mu=np.broadcast_to(np.asarray(mu, dtype=float), (n,)).copy(),
        status=status, reason=reason)
