"""The body dynamics a simulation integrates, as one pluggable object
(beyond the paper; docs/simulation.md, "Bodies").

The runner, the events, the time series, the summary and the 3-D view's
frames ask a *body model* for everything that depends on what rolls: the
right-hand side, the contact point and force, the tilt's axes, the speed,
the energy, the constraints.  Two models:

* :data:`PAPER` -- the paper's wheel and sphere, :mod:`deathsphere.physics.dynamics`
  (parameters :class:`~deathsphere.physics.dynamics.BodyParams`);
* :data:`MACHINE` -- a machine (motorcycle and rider), the exact equations
  M16-M19 of :mod:`deathsphere.physics.machine_dynamics` (parameters
  :class:`MachineRun`: the machines' arrays, the globe and gravity).

Both states are (C, e1, w) in the same 9 rows, so the integrator's driver
is the same.  :func:`model_of` picks the model from the parameters' type.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from deathsphere.physics import dynamics as dyn
from deathsphere.physics import machine_motion as mm
from deathsphere.physics.ground import Sphere
from deathsphere.physics.machine_arrays import MachineArrays
from deathsphere.physics.machine_dynamics import machine_rhs
from deathsphere.physics.vectors import dot as _dot
from deathsphere.simulation.events import ContactEvents

__all__ = ["STATE_NAMES", "STATE_UNITS", "MachineRun", "PAPER", "MACHINE", "model_of", "take", "concat_params", "broadcast_params"]


#: the state's 9 rows, the same for both models: the wheel's (or ball's)
#: centre C, its axis 1 e1 and its angular velocity w, lab (or turning) components
STATE_NAMES = ("c_x", "c_y", "c_z", "e1_x", "e1_y", "e1_z", "w_x", "w_y", "w_z")
STATE_UNITS = ("m", "m", "m", "1", "1", "1", "rad/s", "rad/s", "rad/s")


def _contact_events(model, p, mu):
    """:class:`deathsphere.simulation.events.ContactEvents` of the bodies p."""
    return ContactEvents(p, np.asarray(mu, dtype=float), p.g, model)


class MachineRun(NamedTuple):
    """Per-body parameters of simulated machines: the machines' arrays
    ``machine`` (:class:`~deathsphere.physics.machine_arrays.MachineArrays`,
    (n,) each; docs/machine.md sec. 1), and the run's: the globe's radius
    ``r`` [m] and gravity ``g`` [m/s^2] (n,), with each machine's ``name``
    (object)."""

    machine: MachineArrays
    r: np.ndarray
    g: np.ndarray
    name: np.ndarray

    @property
    def a(self) -> np.ndarray:
        """The wheel radius [m], by the name the runner shares with the paper's bodies."""
        return self.machine.wheel_radius

    @property
    def ground(self) -> Sphere:
        """The globe the machines roll in."""
        return Sphere(self.r)


def _broadcast(x, n: int):
    if isinstance(x, tuple):
        return type(x)(*(_broadcast(y, n) for y in x))
    return np.broadcast_to(x, (n,))


def broadcast_params(params, n: int):
    """Per-body parameters (either kind) with every array broadcast to n bodies."""
    return _broadcast(params, n)


def _take(x, index):
    if isinstance(x, tuple):
        return type(x)(*(_take(y, index) for y in x))
    return np.asarray(x)[index]


def _concat(xs):
    if isinstance(xs[0], tuple):
        return type(xs[0])(*(_concat(ys) for ys in zip(*xs)))
    return np.concatenate([np.asarray(x) for x in xs])


def take(params, index):
    """The bodies ``index`` of per-body parameters (either kind; beyond the paper)."""
    return _take(params, index)


def concat_params(parts):
    """Per-body parameters of one kind, joined in order (beyond the paper)."""
    kinds = {type(p) for p in parts}
    if len(kinds) != 1:
        raise ValueError("one run simulates one kind of body (wheels and spheres, or machines)")
    return _concat(list(parts))


class _Paper:
    """The paper's wheel and sphere (:mod:`deathsphere.physics.dynamics`)."""

    name = "paper"
    state_names, state_units = STATE_NAMES, STATE_UNITS
    #: series and summary columns beyond the shared ones
    series_extras: tuple = ()
    summary_extras: tuple = ()
    #: (summary column, reduction, series column) folded over the samples
    extremes: tuple = ()

    def summary_echo(self, p) -> dict:
        return {}


    def fall_note(self, p, theta, alpha):
        """No words beyond the status's own for the paper's bodies (their
        stability is the orbit's columns; docs/stability.md)."""
        return np.full(int(np.size(theta)), "", dtype=object)

    def ode(self, p, frame_rate):
        return dyn.ode(p, frame_rate)

    def rhs(self, y, p):
        return dyn.rhs(y, p)

    def terminal_events(self, p, mu):
        """Contact lost and slips (:mod:`deathsphere.simulation.events`)."""
        return _contact_events(self, p, mu)

    def scalar_events(self, p):
        """(coefficients, g) of the one-body float path of the events, or None."""
        return dyn.scalar_coefficients(p), float(np.reshape(p.g, -1)[0])

    def contact_values(self, y, scalar):
        return dyn.contact_values(y, *scalar)

    def contact_force(self, y, p):
        return dyn.contact_force(y, p)

    def contact_point(self, y, p):
        return dyn.contact_point(y, p)

    def marker(self, p):
        """Rows 3-5 carry a marker outside the dynamics (a sphere's)."""
        return np.asarray(p.sphere, dtype=bool)

    def project(self, y, p):
        return dyn.project(y, p)

    def energy(self, y, p):
        return dyn.energy(y, p)

    def energy_scale(self, y, p, e0):
        """The drift's scale: the kinetic part of e0 plus g r."""
        return np.abs(e0 - p.g * y[2]) + p.g * p.r

    def tilt_angle(self, y, p, pvec, zp):
        """atan2 of the tilt (eq. 11): z' = -cos(alpha) e1 - sin(alpha) e3;
        a sphere's equivalent alpha of sec. 4 (axis 3 along the radius)."""
        c, e1 = y[dyn.C], y[dyn.E1]
        e3 = (pvec - c) / p.a
        e1h = e1 / np.sqrt(np.sum(e1 * e1, axis=0))
        z3 = np.sum(zp * e3, axis=0)
        z1 = np.sum(zp * e1h, axis=0)
        cos_sphere = np.where(p.outside, -1.0, 1.0) * np.sqrt(np.maximum(1.0 - z3 * z3, 0.0))
        return np.arctan2(-z3, np.where(p.sphere, cos_sphere, -z1))

    def centre_speed(self, y, pvec):
        """|a e3 x w| (eq. 6), a e3 = p - c."""
        return np.sqrt(np.sum(np.cross(pvec - y[dyn.C], y[dyn.W], axis=0) ** 2, axis=0))

    def residual(self, y, p):
        res = dyn.constraint_residuals(y, p)
        return np.maximum(np.where(p.sphere, 0.0, np.abs(res["axis"])), np.abs(res["contact"]) / p.r)

    def extras(self, y, p) -> dict:
        return {}


class _Machine:
    """A machine: eqs. M16-M19 (:mod:`deathsphere.physics.machine_dynamics`)."""

    name = "machine"
    state_names, state_units = STATE_NAMES, STATE_UNITS
    #: appended to the wheel's columns: the centre of mass's speed and the
    #: head's clearance from the globe (r - |H|), as ``ride`` names them
    series_extras = ("v_cm_m_s", "head_clearance_m")
    summary_extras = ("machine", "min_head_clearance_m")
    extremes = (("min_head_clearance_m", np.fmin, "head_clearance_m"),)

    def summary_echo(self, p: MachineRun) -> dict:
        return {"machine": np.asarray(p.name, dtype=object)}

    def fall_note(self, p: MachineRun, theta, alpha):
        """Words appended to the reason of a body whose run ended in a fall
        (contact lost, slips): why, when its steady orbit (theta, alpha
        [rad]) is unstable -- the linearisation's growth rate
        (docs/machine.md sec. 5) -- and that a rider steers.  '' where the
        orbit is stable or not analysed."""
        from deathsphere.physics.machine_dynamics import machine_stability, yaw_is_determined
        from deathsphere.physics.stability.verdict import Verdict

        n = int(np.size(theta))
        notes = np.full(n, "", dtype=object)
        mp = p.machine.flat(n)
        ok = np.isfinite(theta) & np.isfinite(alpha) & np.broadcast_to(yaw_is_determined(mp), (n,))
        if not ok.any():
            return notes
        idx = np.flatnonzero(ok)
        r, g = (np.broadcast_to(np.asarray(x, dtype=float), (n,))[idx] for x in (p.r, p.g))
        st = machine_stability(np.asarray(theta, dtype=float)[idx], np.asarray(alpha, dtype=float)[idx],
                               Sphere(r), g, mp.take(idx))
        for i, verdict, rate in zip(idx, st["verdict"], st["growth_rate"]):
            if verdict == Verdict.UNSTABLE:
                notes[i] = (f"; its steady orbit is unstable (growth rate {rate:.3g} /s with the steering "
                            "locked; docs/machine.md sec. 5): a kick grows until the machine falls -- a rider "
                            "holds such a lap by steering")
        return notes

    def ode(self, p: MachineRun, frame_rate):
        n = int(np.size(p.a))
        mp, ground, g = p.machine, p.ground, np.asarray(p.g)
        fr = np.broadcast_to(np.asarray(frame_rate, dtype=float), (n,))
        mcol, gcol = mp.map(lambda x: np.asarray(x)[:, None]), g[:, None]

        def fun(t, y):
            y = np.asarray(y)
            if y.ndim == 1:
                return machine_rhs(y.reshape(9, n), ground, g, mp, fr).reshape(-1)
            m = y.shape[1]
            return machine_rhs(y.reshape(9, n, m), ground, gcol, mcol, fr[:, None]).reshape(9 * n, m)

        return fun

    def rhs(self, y, p: MachineRun):
        return machine_rhs(y, p.ground, p.g, p.machine)

    def terminal_events(self, p: MachineRun, mu):
        """Contact lost and slips, on eq. M18's contact force."""
        return _contact_events(self, p, mu)

    def scalar_events(self, p):
        return None

    def contact_values(self, y, scalar):
        """Not reached: with :meth:`scalar_events` None the events take the
        vector path (:meth:`contact_force`) for a machine."""
        raise TypeError("a machine's events use its contact force, not the paper's scalar path")

    def contact_force(self, y, p: MachineRun):
        return mm.machine_contact_force(y, p.ground, p.g, p.machine)

    def contact_point(self, y, p: MachineRun):
        return mm.machine_points(y, p.machine)["P"]

    def marker(self, p):
        return np.zeros(np.shape(p.a), dtype=bool)

    def project(self, y, p: MachineRun):
        return mm.machine_project(y, p.ground, p.machine)

    def energy(self, y, p: MachineRun):
        return mm.machine_energy(y, p.g, p.machine)[0]

    def energy_scale(self, y, p: MachineRun, e0):
        return np.abs(mm.machine_energy(y, p.g, p.machine)[1]) + p.g * p.r

    def tilt_angle(self, y, p: MachineRun, pvec, zp):
        """The tilt of the up-axis -e3 above the orbit plane (docs/machine.md
        sec. 1), on the paper's convention z' = -cos(alpha) e1 - sin(alpha) e3."""
        pts = mm.machine_points(y, p.machine)
        return np.arctan2(-np.sum(zp * pts["e3"], axis=0), -np.sum(zp * pts["e1"], axis=0))

    def centre_speed(self, y, pvec):
        """The wheel centre's speed |dC/dt| = |w x (P - C)| (eq. M16)."""
        return np.sqrt(np.sum(np.cross(y[6:9], pvec - y[0:3], axis=0) ** 2, axis=0))

    def residual(self, y, p: MachineRun):
        res = mm.machine_residuals(y, p.ground, p.machine)
        return np.maximum(np.abs(res["axis"]), np.abs(res["contact"]) / p.r)

    def extras(self, y, p: MachineRun) -> dict:
        mp = p.machine
        vG = mm.machine_rates(y, mp)["vG"]
        H = mm.machine_points(y, mp)["H"]
        return {"v_cm_m_s": np.sqrt(_dot(vG, vG)), "head_clearance_m": p.r - np.sqrt(_dot(H, H))}


PAPER = _Paper()
MACHINE = _Machine()


def model_of(params):
    """The body model of per-body parameters (beyond the paper):
    :data:`MACHINE` for :class:`MachineRun` (docs/machine.md eqs.
    M16-M19), else :data:`PAPER` (eqs. 2-7b in general form)."""
    return MACHINE if isinstance(params, MachineRun) else PAPER
