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
  :class:`MachineRun`: the machines' arrays, the globe and gravity);
* :data:`ON_GROUND` -- the paper's wheel and ball on any other ground (the
  drum, the cone, flat ground, a profile): the same equations with the
  ground's contact, :mod:`deathsphere.physics.dynamics_on` (parameters
  :class:`GroundRun`), and two more events, the floor and the wall's top;
* :data:`MACHINE_ON_GROUND` -- a machine on the drum, the cone, a profile or flat
  ground: eqs. M16-M19 with the crown point on the ground's parallel
  surface, :mod:`deathsphere.physics.machine_dynamics_on` (parameters
  :class:`MachineGroundRun`), with the wall's events.

All states are (C, e1, w) in the same 9 rows, so the integrator's driver
is the same.  :func:`model_of` picks the model from the parameters' type.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from deathsphere.physics import dynamics as dyn
from deathsphere.physics import dynamics_on as don
from deathsphere.physics import machine_motion as mm
from deathsphere.physics.ground import Ground, Sphere
from deathsphere.physics.machine_arrays import MachineArrays
from deathsphere.physics.machine_dynamics import machine_rhs, rhs_of_geometry
from deathsphere.physics.vectors import dot as _dot
from deathsphere.simulation.events import ContactEvents
from deathsphere.simulation.status import RunStatus

__all__ = ["STATE_NAMES", "STATE_UNITS", "MachineRun", "GroundRun", "MachineGroundRun", "PAPER", "MACHINE", "ON_GROUND",
           "MACHINE_ON_GROUND", "model_of",
           "take", "concat_params", "broadcast_params"]


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

    def geometry(self, shape=None):
        """The crown point's geometry class in the globe (eq. M16), as
        :meth:`MachineGroundRun.geometry` on any other ground."""
        from deathsphere.physics.machine_dynamics import GeometryRates

        return GeometryRates


class GroundRun(NamedTuple):
    """Per-body parameters of the paper's wheels and balls on a ground other
    than the globe (beyond the paper; docs/simulation.md, "Bodies"): radius
    ``a`` [m], inertia factor ``k``, gravity ``g`` [m/s^2], ``sphere`` (a
    ball), ``r`` the start lane's distance from the axis rho_P [m] (the
    run's length: the centre's tolerance, the energy's scale, the
    constraint's residual, as the globe's radius is there), ``height`` the
    start contact's height above the ground's lowest point [m] (on flat
    ground 0: its lane is the turn radius ``r``) (n,) each, the
    ``ground`` record, one for the whole run, and ``outside`` (n,) bool,
    the bodies on the ground's far side (F > 0: round the outside of a
    drum, on a cone's or a dome's roof; docs/dynamics.md sec. 7,
    "Outside"), False inside."""

    a: np.ndarray
    k: np.ndarray
    g: np.ndarray
    sphere: np.ndarray
    r: np.ndarray
    height: np.ndarray
    ground: Ground
    outside: np.ndarray = np.False_

    def body(self, shape=None) -> don.GroundBody:
        """The bodies as :mod:`deathsphere.physics.dynamics_on` takes them
        (their arrays broadcast to ``shape``, as a state's trailing axes)."""
        arrays = (self.a, self.k, self.g, self.sphere, np.asarray(self.outside, dtype=bool))
        if shape is not None:
            arrays = tuple(np.broadcast_to(x, shape) for x in arrays)
        return don.GroundBody(self.ground, *arrays)


class MachineGroundRun(NamedTuple):
    """Per-body parameters of machines on a ground other than the globe
    (beyond the paper; docs/machine.md, "On any ground"): the machines'
    arrays ``machine``, gravity ``g`` [m/s^2], each machine's ``name``,
    ``r`` the start lane's distance from the axis rho_P [m] (the run's
    length, as :class:`GroundRun`'s), ``height`` the start contact's height
    above the ground's lowest point [m], ``lane`` the start lane as the
    ground takes it (its height; on flat ground the turn radius) [m] (n,)
    each, and the ``ground`` record, one for the whole run."""

    machine: MachineArrays
    g: np.ndarray
    name: np.ndarray
    r: np.ndarray
    height: np.ndarray
    lane: np.ndarray
    ground: Ground

    @property
    def a(self) -> np.ndarray:
        """The wheel radius [m], by the name the runner shares with the paper's bodies."""
        return self.machine.wheel_radius

    def geometry(self, shape=None):
        """The crown point's geometry class on the ground (its parallel
        surface for the machines' tyres, broadcast to ``shape``)."""
        from deathsphere.physics.machine_dynamics_on import geometry_on

        mp = self.machine if shape is None else self.machine.map(lambda x: np.broadcast_to(x, shape))
        return geometry_on(self.ground, mp)


def _shared(x) -> bool:
    """A field that is one record for every body (a run's ground), kept
    whole when bodies are taken, broadcast or joined."""
    return not isinstance(x, (np.ndarray, np.generic, int, float, bool, list)) and isinstance(x, Ground)


def _broadcast(x, n: int):
    if _shared(x):
        return x
    if isinstance(x, tuple):
        return type(x)(*(_broadcast(y, n) for y in x))
    return np.broadcast_to(x, (n,))


def broadcast_params(params, n: int):
    """Per-body parameters (either kind) with every array broadcast to n bodies."""
    return _broadcast(params, n)


def _take(x, index):
    if _shared(x):
        return x
    if isinstance(x, tuple):
        return type(x)(*(_take(y, index) for y in x))
    x = np.asarray(x)
    # a field left at its scalar default (GroundRun.outside) holds for every body
    return x if x.ndim == 0 else x[index]


def _concat(xs):
    if _shared(xs[0]):
        if any(x != xs[0] for x in xs[1:]):
            raise ValueError("one run rides one ground")
        return xs[0]
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
        raise ValueError("one run simulates one kind of body (wheels and spheres, on the globe or another "
                         "ground, or machines)")
    return _concat(list(parts))


def _polar_angle(pl):
    """arctan2(|pl_xy|, pl_z): the angle from z' of a point pl (3, ...) [rad]."""
    return np.arctan2(np.hypot(pl[0], pl[1]), pl[2])


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

    def polar_angle(self, pl):
        """The contact's polar angle theta [rad] from its orbit-frame components pl (3, ...)."""
        return _polar_angle(pl)

    def wall_conditions(self, p) -> tuple:
        """No events beyond contact and slipping: the globe has no floor or top."""
        return ()

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

    def polar_angle(self, pl):
        """The contact's polar angle theta [rad] from its orbit-frame components pl (3, ...)."""
        return _polar_angle(pl)

    def wall_conditions(self, p) -> tuple:
        """No events beyond contact and slipping in the globe."""
        return ()

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


def _per_sample(fn, y, p: GroundRun):
    """fn(states, bodies) of :mod:`deathsphere.physics.dynamics_on` at states
    y (9, ...) whose last axis is the bodies: the bodies' arrays broadcast
    to the states' trailing shape."""
    return fn(y, p.body(np.shape(y)[1:]))


def _kinks_under_contacts(model, p):
    """On a profile, y -> where each body's contact lies among the spline's
    knots (:meth:`Profile.knot_index`), y the runner's flat state: the
    integrator restarts where one crosses a knot, at which the right-hand
    side has a kink (docs/simulation.md, "On any ground").  None on a ground
    without knots."""
    index = getattr(p.ground, "knot_index", None)
    if index is None:
        return None
    n = int(np.size(p.a))

    def at(y):
        point = model.contact_point(np.asarray(y, dtype=float).reshape(9, n), p)
        return index(np.hypot(point[0], point[1]), point[2])

    return at


class _OnGround(_Paper):
    """The paper's wheel and ball on any ground but the globe (beyond the
    paper; docs/dynamics.md sec. 7): the equations of
    :mod:`deathsphere.physics.dynamics_on`, the paper's tilt, speed and
    energy scale as on the globe (inside or outside: ``GroundRun.outside``,
    as the globe's side), and the wall's events: the floor and the top."""

    name = "on_ground"
    off_globe = True
    #: the contact's height above the ground's lowest point and its distance
    #: from the axis (on flat ground the turn radius), as ``orbit`` names them
    series_extras = ("height_m", "rho_contact_m")
    summary_extras = ("surface", "height_m", "max_height_drift_m", "max_rho_drift_m")
    extremes = (("max_height_drift_m", np.fmax, "height_drift_m"), ("max_rho_drift_m", np.fmax, "rho_drift_m"))

    def summary_echo(self, p: GroundRun) -> dict:
        n = int(np.size(p.a))
        return {"surface": np.full(n, p.ground.name, dtype=object), "height_m": np.asarray(p.height, dtype=float)}

    def polar_angle(self, pl):
        """No polar angle off the globe (the lane is its height): NaN, as
        ``orbit``'s theta_deg on these surfaces."""
        return np.full(np.shape(pl)[1:], np.nan)

    def wall_conditions(self, p: GroundRun) -> tuple:
        """(status, condition [m]) of the wall's ends, each > 0 while the
        body is on the wall: where the wall rises from a floor (its foot a
        circle off the axis: the drum, the cone; a bowl meets the axis and
        has none), the body's lowest point above it (docs/surfaces.md S5);
        where the wall has a top, the contact below it.  Flat ground has
        neither."""
        ground, out = p.ground, []
        top = float(getattr(ground, "highest_lane", np.inf))
        if hasattr(ground, "highest_lane") and float(ground.contact(0.0)[0]) > 0:
            out.append((RunStatus.HITS_FLOOR,
                        lambda y: don.lowest_point_on(y, p.body()) - ground.lowest))
        if np.isfinite(top):
            out.append((RunStatus.OVER_THE_TOP,
                        lambda y: top - (don.contact_on(y, p.body())[1][2] - ground.lowest)))
        return tuple(out)

    def ode(self, p: GroundRun, frame_rate):
        n = int(np.size(p.a))
        fr = np.broadcast_to(np.asarray(frame_rate, dtype=float), (n,))
        flat, column = p.body((n,)), p.body((n, 1))

        def fun(t, y):
            y = np.asarray(y)
            if y.ndim == 1:
                return don.rhs_on(y.reshape(9, n), flat, fr).reshape(-1)
            m = y.shape[1]
            return don.rhs_on(y.reshape(9, n, m), column, fr[:, None]).reshape(9 * n, m)

        return fun

    def rhs(self, y, p: GroundRun):
        return _per_sample(don.rhs_on, y, p)

    def scalar_events(self, p):
        return None

    def contact_values(self, y, scalar):
        """Not reached: with :meth:`scalar_events` None the events take the
        vector path (:meth:`contact_force`)."""
        raise TypeError("the events on a ground use its contact force, not the globe's scalar path")

    def contact_force(self, y, p: GroundRun):
        return _per_sample(don.contact_force_on, y, p)

    def contact_point(self, y, p: GroundRun):
        return _per_sample(don.contact_on, y, p)[1]

    def kinks(self, p: GroundRun):
        """The contacts' places among a profile's knots, from a flat state
        (:func:`_kinks_under_contacts`); None on another ground."""
        return _kinks_under_contacts(self, p)

    def project(self, y, p: GroundRun):
        return _per_sample(don.project_on, y, p)

    def energy(self, y, p: GroundRun):
        return _per_sample(don.energy_on, y, p)

    def residual(self, y, p: GroundRun):
        """The larger of |e1| - 1 (a wheel's axis) and the contact's gap to
        the surface in units of the lane's radius."""
        axis = np.abs(np.sqrt(np.sum(y[3:6] ** 2, axis=0)) - 1.0)
        gap = np.abs(_per_sample(don.gap_on, y, p)) / p.r
        return np.maximum(np.where(p.sphere, 0.0, axis), gap)

    def extras(self, y, p: GroundRun) -> dict:
        pvec = self.contact_point(y, p)
        height, rho = pvec[2] - p.ground.lowest, np.hypot(pvec[0], pvec[1])
        return {"height_m": height, "rho_contact_m": rho, "height_drift_m": np.abs(height - p.height),
                "rho_drift_m": np.abs(rho - p.r)}


class _MachineOnGround(_Machine):
    """A machine on the drum, the cone, a profile or flat ground (beyond the paper;
    docs/machine.md, "On any ground"): eqs. M16-M19 with the crown point on
    the ground's parallel surface (MG1-MG3), the globe's machine's series
    and the wall's: the contact's height and distance from the axis, the
    floor and the wall's top as events."""

    name = "machine_on_ground"
    off_globe = True
    series_extras = ("v_cm_m_s", "head_clearance_m", "height_m", "rho_contact_m")
    summary_extras = ("machine", "min_head_clearance_m", "surface", "height_m", "max_height_drift_m",
                      "max_rho_drift_m")
    extremes = (("min_head_clearance_m", np.fmin, "head_clearance_m"),
                ("max_height_drift_m", np.fmax, "height_drift_m"), ("max_rho_drift_m", np.fmax, "rho_drift_m"))

    def summary_echo(self, p: MachineGroundRun) -> dict:
        n = int(np.size(p.a))
        return {"machine": np.asarray(p.name, dtype=object), "surface": np.full(n, p.ground.name, dtype=object),
                "height_m": np.asarray(p.height, dtype=float)}

    def polar_angle(self, pl):
        """No polar angle off the globe (the lane is its height): NaN."""
        return np.full(np.shape(pl)[1:], np.nan)

    def _points(self, y, p: MachineGroundRun):
        return mm.machine_points(y, p.machine, p.geometry(np.shape(y)[1:]))

    def wall_conditions(self, p: MachineGroundRun) -> tuple:
        """(status, condition [m]), each > 0 while the machine is on the
        wall: where the wall rises from a floor, the tyre's lowest point
        above it (the crown circle's lowest point, a tyre radius lower:
        eq. MS7); where the wall has a top, the contact below it."""
        ground, out = p.ground, []
        top = float(getattr(ground, "highest_lane", np.inf))
        mp = p.machine

        def tyre_low(y):
            e1z = y[5] / np.sqrt(_dot(y[3:6], y[3:6]))
            return (y[2] - (mp.wheel_radius - mp.tyre_radius) * np.sqrt(np.maximum(1.0 - e1z * e1z, 0.0))
                    - mp.tyre_radius - ground.lowest)

        if hasattr(ground, "highest_lane") and float(ground.contact(0.0)[0]) > 0:
            out.append((RunStatus.HITS_FLOOR, tyre_low))
        if np.isfinite(top):
            out.append((RunStatus.OVER_THE_TOP, lambda y: top - (self._points(y, p)["P"][2] - ground.lowest)))
        return tuple(out)

    def fall_note(self, p: MachineGroundRun, theta, alpha):
        """As on the globe (the lane's linearisation on its ground, docs/machine.md, "On any ground")."""
        from deathsphere.physics.machine_dynamics import yaw_is_determined
        from deathsphere.physics.machine_dynamics_on import machine_stability_on
        from deathsphere.physics.stability.verdict import Verdict

        n = int(np.size(alpha))
        notes = np.full(n, "", dtype=object)
        mp = p.machine.flat(n)
        ok = np.isfinite(alpha) & np.broadcast_to(yaw_is_determined(mp), (n,))
        if not ok.any():
            return notes
        idx = np.flatnonzero(ok)
        st = machine_stability_on(np.asarray(p.lane, dtype=float)[idx], np.asarray(alpha, dtype=float)[idx], p.ground,
                                  np.broadcast_to(np.asarray(p.g, dtype=float), (n,))[idx], mp.take(idx))
        for i, verdict, rate in zip(idx, st["verdict"], st["growth_rate"]):
            if verdict == Verdict.UNSTABLE:
                notes[i] = (f"; its steady lane is unstable (growth rate {rate:.3g} /s with the steering "
                            "locked; docs/machine.md, \"On any ground\"): a kick grows until the machine falls -- a "
                            "rider holds such a lap by steering")
        return notes

    def ode(self, p: MachineGroundRun, frame_rate):
        n = int(np.size(p.a))
        mp, g = p.machine, np.asarray(p.g)
        fr = np.broadcast_to(np.asarray(frame_rate, dtype=float), (n,))
        mcol, gcol = mp.map(lambda x: np.asarray(x)[:, None]), g[:, None]
        flat, column = p.geometry((n,)), p.geometry((n, 1))

        def fun(t, y):
            y = np.asarray(y)
            if y.ndim == 1:
                return rhs_of_geometry(y.reshape(9, n), g, mp, flat, fr).reshape(-1)
            m = y.shape[1]
            return rhs_of_geometry(y.reshape(9, n, m), gcol, mcol, column, fr[:, None]).reshape(9 * n, m)

        return fun

    def rhs(self, y, p: MachineGroundRun):
        return rhs_of_geometry(y, p.g, p.machine, p.geometry(np.shape(y)[1:]))

    def contact_force(self, y, p: MachineGroundRun):
        return mm.machine_contact_force(y, p.ground, p.g, p.machine, p.geometry(np.shape(y)[1:]))

    def contact_point(self, y, p: MachineGroundRun):
        return self._points(y, p)["P"]

    def kinks(self, p: MachineGroundRun):
        """As the paper's bodies' (:func:`_kinks_under_contacts`)."""
        return _kinks_under_contacts(self, p)

    def project(self, y, p: MachineGroundRun):
        from deathsphere.physics.machine_dynamics_on import machine_project_on

        return machine_project_on(y, p.ground, p.machine)

    def energy(self, y, p: MachineGroundRun):
        return mm.machine_energy(y, p.g, p.machine, p.geometry(np.shape(y)[1:]))[0]

    def energy_scale(self, y, p: MachineGroundRun, e0):
        return np.abs(mm.machine_energy(y, p.g, p.machine, p.geometry(np.shape(y)[1:]))[1]) + p.g * p.r

    def tilt_angle(self, y, p: MachineGroundRun, pvec, zp):
        pts = self._points(y, p)
        return np.arctan2(-np.sum(zp * pts["e3"], axis=0), -np.sum(zp * pts["e1"], axis=0))

    def residual(self, y, p: MachineGroundRun):
        crown = p.geometry(np.shape(y)[1:])(y[0:3], y[3:6], p.machine.wheel_radius, p.machine.tyre_radius)
        axis = np.abs(np.sqrt(_dot(y[3:6], y[3:6])) - 1.0)
        return np.maximum(axis, np.abs(crown.residual()) / p.r)

    def extras(self, y, p: MachineGroundRun) -> dict:
        mp = p.machine
        geometry = p.geometry(np.shape(y)[1:])
        vG = mm.machine_rates(y, mp, geometry)["vG"]
        pts = mm.machine_points(y, mp, geometry)
        H, P = pts["H"], pts["P"]
        height, rho = P[2] - p.ground.lowest, np.hypot(P[0], P[1])
        clearance = np.asarray(p.ground.clearance(np.hypot(H[0], H[1]), H[2]), dtype=float)
        return {"v_cm_m_s": np.sqrt(_dot(vG, vG)), "head_clearance_m": clearance, "height_m": height,
                "rho_contact_m": rho, "height_drift_m": np.abs(height - p.height), "rho_drift_m": np.abs(rho - p.r)}


PAPER = _Paper()
MACHINE = _Machine()
ON_GROUND = _OnGround()
MACHINE_ON_GROUND = _MachineOnGround()


def model_of(params):
    """The body model of per-body parameters (beyond the paper):
    :data:`MACHINE` for :class:`MachineRun` (docs/machine.md eqs.
    M16-M19), :data:`ON_GROUND` for :class:`GroundRun` (docs/dynamics.md
    sec. 7), else :data:`PAPER` (eqs. 2-7b in general form)."""
    if isinstance(params, MachineRun):
        return MACHINE
    if isinstance(params, MachineGroundRun):
        return MACHINE_ON_GROUND
    return ON_GROUND if isinstance(params, GroundRun) else PAPER
