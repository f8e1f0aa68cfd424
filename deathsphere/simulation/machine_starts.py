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

__all__ = ["machine_starts", "machine_run"]


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
