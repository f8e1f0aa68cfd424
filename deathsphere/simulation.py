"""Simulate wheels and spheres rolling on a fixed sphere.

Beyond the paper: McDonald (1993) writes the Newton-Euler equations in
general form, eqs. (2)-(7b), and solves them only for steady orbits.  This
module integrates the exact equations of motion of
:mod:`deathsphere.physics.dynamics` with :func:`scipy.integrate.solve_ivp`,
starting on (or near) a steady orbit of the paper, and watches the contact
force as it goes.  Method, tolerances, perturbation, events and outputs are
described in ``docs/simulation.md``.

Use
---
1. Build the initial conditions (one or many bodies; arrays broadcast):

   * :func:`horizontal_starts` -- a steady horizontal orbit: a wheel given
     (theta, alpha), eqs. (8b), (11)-(13), (29); a sphere given (theta,
     omega3 and a branch) or (theta, Omega), eqs. (42), (55);
   * :func:`vertical_starts` -- a vertical orbit of a wheel given the cone
     angle theta and the speed of its centre (at the top by default),
     eqs. (26)-(28b), (82);

   optionally kicked off the steady orbit by ``perturb`` [rad] (see
   :func:`horizontal_starts`).  :meth:`Starts.concat` joins several sets.
2. :class:`Simulation` integrates all bodies at once (one state vector of
   9 n rows, one vectorised right-hand side) period by period:
   ``for chunk in sim.chunks(progress): ...`` yields :class:`Table` chunks
   of the time series (columns :data:`SERIES_COLUMNS`), then
   ``sim.summary()`` gives one row per body (columns
   :data:`SUMMARY_COLUMNS`).  :func:`simulate` does both and returns
   ``(series, summary)``.

Statuses (:data:`STATUSES`): ``completed`` (ran the requested time),
``contact_lost`` (the normal force fell to zero; terminal event),
``slips`` (the friction needed reached mu times the normal force; terminal
event), ``no_fit`` / ``no_orbit`` (no steady orbit to start from: nothing is
integrated), ``failed`` (the integrator gave up).

Angles are in degrees at this level (the CLI's units), except the
perturbation, which is in radians (a small number); lengths in m, rates in
rad/s, forces per unit mass in m/s^2.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import solve_ivp

from deathsphere.model import Setup, Table
from deathsphere.physics import dynamics as dyn
from deathsphere.physics import sphere as sph
from deathsphere.physics import vertical_orbit as vert
from deathsphere.physics import wheel
from deathsphere.physics.geometry import r_prime
from deathsphere.physics.status import REASON_TEXT, Status

__all__ = [
    "STATUSES", "SERIES_COLUMNS", "SUMMARY_COLUMNS", "METHODS", "FRAMES",
    "Starts", "horizontal_starts", "vertical_starts", "Simulation", "simulate", "concat_tables",
]

#: Final status of a body (summary column ``status``).
STATUSES = ("completed", "contact_lost", "slips", "no_fit", "no_orbit", "failed")

#: Time-series columns, one row per body and sample time (docs/simulation.md).
SERIES_COLUMNS = (
    "input_row", "t_s", "phi_deg", "theta_deg", "alpha_deg", "speed_m_s",
    "normal_per_mass_m_s2", "friction_per_mass_m_s2", "mu_required",
    "energy_drift", "constraint_residual",
)

#: Summary columns, one row per body (docs/simulation.md).
SUMMARY_COLUMNS = (
    "input_row", "body", "side", "orbit", "theta_deg", "alpha_deg", "a_m", "r_m", "k", "g_m_s2",
    "omega_rad_s", "omega3_rad_s", "speed_m_s", "period_s", "perturb_rad", "perturb_theta_rad",
    "mu_available", "status", "reason", "event_time_s", "event_phi_deg", "event_theta_deg",
    "event_alpha_deg", "periods_simulated", "max_theta_drift_deg", "max_alpha_drift_deg",
    "min_normal_per_mass_m_s2", "max_mu_required", "max_abs_energy_drift",
    "max_constraint_residual", "method", "rtol", "atol", "frame", "n_steps", "n_fev", "wall_time_s",
)

#: solve_ivp methods accepted.  The explicit Runge-Kutta methods are the
#: natural choice (the flow is not stiff); Radau/BDF get a block-diagonal
#: Jacobian sparsity pattern (bodies are independent).
METHODS = ("DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA")
#: explicit Runge-Kutta methods: they never use a vectorised right-hand side
#: (vectorized=True only made solve_ivp pass (9 n, 1) arrays)
_EXPLICIT = ("DOP853", "RK45", "RK23")
#: Frames the state is integrated in: "turning" (about the vertical at the
#: steady orbit's rate Omega, where a steady horizontal orbit is a fixed
#: point; vertical orbits are always integrated in the lab) or "lab".
FRAMES = ("turning", "lab")

#: internal samples per period at least (phi is unwrapped on them, extrema
#: are taken over them); output rows are every m-th of them.
_MIN_INTERNAL_PER_PERIOD = 16
#: event values (force / g) at or below this count as "reached zero" for
#: every body at an event (identical bodies reach zero together).
_EVENT_TOL = 1e-9
#: largest step, in units of 1/S (S = sqrt(|w|^2 + Omega^2 + g/a), the rate
#: scale of the body): keeps the nutation (frequencies ~ S) resolved when
#: the error estimate alone would allow huge steps (docs/simulation.md)
_MAX_STEP_RATES = 2.0
#: absolute tolerance on a sphere's axis-1 marker rows (no error control)
_MARKER_ATOL = 1e3

_REASONS = {
    "completed": "ran the requested time",
    "contact_lost": "the normal force fell to zero: the body leaves the surface",
    "slips": "the friction needed reached mu times the normal force: the body slips",
    "no_fit_vertical": "the wheel does not fit on this vertical circle (needs r sin(theta) > a inside)",
}


# --------------------------------------------------------------------------
# initial conditions


@dataclass(frozen=True)
class Starts:
    """Initial conditions of n bodies and what the summary reports about them.

    Arrays have shape (n,) (``state`` (9, n), ``frame`` (n, 3, 3)).
    ``frame[i]`` has the columns x', y', z' of the orbit's frame in lab
    components (paper, fig. 1-2: z' the orbit axis, x' towards the top);
    identity for horizontal orbits.  ``theta``, ``alpha`` [rad] are the
    steady (unperturbed) values the drift is measured from; ``rate`` [rad/s]
    the steady Omega (horizontal) or phidot at the start (vertical);
    ``turning`` [rad/s] the rate of the turning frame (Omega for horizontal
    orbits, 0 for vertical ones); ``period`` [s] the time one "period" of the
    run lasts; ``phi0`` [rad] the start azimuth in the orbit frame.
    ``status`` is '' for bodies that can be integrated, else 'no_fit' /
    'no_orbit' with ``reason``.
    """

    state: np.ndarray
    params: dyn.BodyParams
    frame: np.ndarray
    input_row: np.ndarray
    body: np.ndarray
    side: np.ndarray
    orbit: np.ndarray
    theta: np.ndarray
    alpha: np.ndarray
    rate: np.ndarray
    turning: np.ndarray
    period: np.ndarray
    phi0: np.ndarray
    speed: np.ndarray
    omega3: np.ndarray
    perturb: np.ndarray
    perturb_theta: np.ndarray
    mu: np.ndarray
    status: np.ndarray
    reason: np.ndarray

    def __len__(self) -> int:
        return int(self.input_row.size)

    @staticmethod
    def concat(parts: Sequence[Starts]) -> Starts:
        """One :class:`Starts` of all bodies of ``parts``, in order (their
        ``input_row`` values are kept)."""
        parts = list(parts)
        if not parts:
            raise ValueError("nothing to concatenate")
        out = {}
        for name in Starts.__dataclass_fields__:
            vals = [getattr(p, name) for p in parts]
            if name == "state":
                out[name] = np.concatenate(vals, axis=1)
            elif name == "params":
                out[name] = dyn.BodyParams(*(np.concatenate(x) for x in zip(*vals)))
            else:
                out[name] = np.concatenate(vals, axis=0)
        return Starts(**out)

    def select(self, index) -> Starts:
        """The bodies ``index`` (integer array or boolean mask)."""
        out = {}
        for name in Starts.__dataclass_fields__:
            v = getattr(self, name)
            if name == "state":
                out[name] = v[:, index]
            elif name == "params":
                out[name] = dyn.BodyParams(*(x[index] for x in v))
            else:
                out[name] = v[index]
        return Starts(**out)


def _check_setup(setup: Setup):
    if setup.body not in ("wheel", "sphere"):
        raise ValueError(f"simulation needs body wheel or sphere (got {setup.body!r})")
    if not setup.k > 0:
        raise ValueError(f"simulation needs an inertia factor k > 0 (got {setup.k:g}): "
                         "the equations of motion are singular at k = 0")


def _flat(*xs, dtype=float):
    arrs = np.broadcast_arrays(*(np.asarray(x, dtype=dtype) for x in xs))
    return [np.array(a, dtype=dtype).reshape(-1) for a in arrs]


def _input_rows(input_row, n):
    if input_row is None:
        return np.arange(1, n + 1, dtype=np.int64)
    rows = np.broadcast_to(np.asarray(input_row, dtype=np.int64), (n,)).copy()
    return rows


def _check_angles(theta_deg, perturb, perturb_theta):
    theta_deg = np.asarray(theta_deg, dtype=float)
    if not np.all(np.isfinite(theta_deg)) or np.any((theta_deg < 0) | (theta_deg > 180)):
        raise ValueError("theta must be finite and within 0..180 deg")
    for name, x in (("perturb", perturb), ("perturb_theta", perturb_theta)):
        if not np.all(np.isfinite(np.asarray(x, dtype=float))):
            raise ValueError(f"{name} must be finite (radians)")


def _wheel_geometry(theta, alpha, phi, a, r):
    """Contact point, centre, axis 1 and axis 3 of a wheel in the orbit frame.

    McDonald (1993) eqs. (11), (11a), (8b): with r_hat' = (cos phi, sin phi, 0)
    and z' = (0, 0, 1), p = r (sin(theta) r_hat' + cos(theta) z'),
    e1 = -sin(alpha) r_hat' - cos(alpha) z', e3 = cos(alpha) r_hat' - sin(alpha) z',
    c = p - a e3.  Shapes (3, n).
    """
    cp, sp = np.cos(phi), np.sin(phi)
    zero = np.zeros_like(cp)
    rhat = np.stack((cp, sp, zero))
    zhat = np.stack((zero, zero, np.ones_like(cp)))
    pvec = r * (np.sin(theta) * rhat + np.cos(theta) * zhat)
    e1 = -np.sin(alpha) * rhat - np.cos(alpha) * zhat
    e3 = np.cos(alpha) * rhat - np.sin(alpha) * zhat
    return pvec - a * e3, e1, e3


def _wheel_start(theta, alpha, phi, rate, d_theta, d_alpha, a, r):
    """State (orbit-frame components) of a wheel on the orbit (theta, alpha)
    moving at the rate ``rate`` about z', kicked by (d_theta, d_alpha).

    Angular velocity of the steady orbit, eq. (13):
    w = (r'/a) rate e1 - rate sin(alpha) e3, r' = r sin(theta) - a cos(alpha);
    the kick moves the contact point to theta + d_theta and tilts the wheel
    to alpha + d_alpha (about axis 2, the orbit's tangent) keeping w: rolling
    and contact hold exactly (docs/simulation.md, "Perturbation").
    """
    _, e1_0, e3_0 = _wheel_geometry(theta, alpha, phi, a, r)
    rp = r_prime(theta, alpha, a, r)
    w = (rp / a) * rate * e1_0 - rate * np.sin(alpha) * e3_0
    c, e1, _ = _wheel_geometry(theta + d_theta, alpha + d_alpha, phi, a, r)
    return np.concatenate((c, e1, w))


def _setup_status(orb):
    """('' | 'no_fit' | 'no_orbit', reason words) from a physics orbit dict:
    only fit and the existence of Omega decide whether a body can start;
    contact and friction are the simulation's business (events)."""
    code = np.asarray(orb["status"]).reshape(-1)
    words = REASON_TEXT[np.asarray(orb["reason"]).reshape(-1)]
    status = np.where(code == Status.NO_FIT, "no_fit", np.where(code == Status.NO_ORBIT, "no_orbit", ""))
    return status.astype(object), np.where(status == "", "", words).astype(object)


def _empty_starts_fields(n):
    return {"speed": np.full(n, np.nan), "omega3": np.full(n, np.nan)}


def horizontal_starts(setup: Setup, theta_deg, alpha_deg=None, *, omega3=None, omega=None, branch=0,
                      perturb=0.0, perturb_theta=0.0, phi_deg=0.0, input_row=None) -> Starts:
    """Bodies on steady horizontal orbits (McDonald 1993 secs. 2.2.2, 3-5).

    Parameters (arrays broadcast against each other; one body per element)
    ----------
    setup : :class:`deathsphere.model.Setup`   body (wheel | sphere), side,
        a, r, k, g [SI], mu (the friction available, for the ``slips`` event)
    theta_deg : [deg]  polar angle of the contact point (0..180)
    alpha_deg : [deg]  wheel: tilt of axis 3 below the orbit plane, eq. (11)
        (Omega from eq. 29, wheel state from eqs. 8b, 11-13)
    omega3 : [rad/s]   sphere: spin about axis 3; Omega is root ``branch``
        (0 slow, 1 fast) of eq. (55)
    omega : [rad/s]    sphere: the signed orbital rate Omega instead
    perturb : [rad]    the kick off the steady orbit.  Wheel: tilt by
        ``perturb`` about axis 2 (the orbit's tangent through the contact
        point), i.e. alpha -> alpha + perturb, keeping the contact point and
        the angular velocity.  Sphere: moves the contact point ``perturb``
        down the meridian (theta -> theta + perturb), keeping the angular
        velocity.  Rolling and contact hold exactly after the kick.
    perturb_theta : [rad]  wheel: also move the contact point down the
        meridian by this (alpha kept); sphere: added to ``perturb``
    phi_deg : [deg]    azimuth of the contact point at t = 0
    input_row : ints   labels of the bodies (default 1..n)

    Returns
    -------
    :class:`Starts`.  Bodies without a steady orbit (wheel does not fit,
    eqs. 0 / 81; Omega^2 <= 0, eq. 29; sphere: no real root of eq. 55) get
    status no_fit / no_orbit and are not integrated.  Contact and friction
    are not checked here: a body that has no contact (or slips) at t = 0
    stops there with status contact_lost (slips).

    Raises ValueError for invalid parameters (body particle, k = 0, theta
    outside 0..180 deg, missing alpha / omega3).
    """
    _check_setup(setup)
    _check_angles(theta_deg, perturb, perturb_theta)
    outside = setup.side == "outside"
    a, r, k, g = setup.a, setup.r, setup.k, setup.g
    if setup.body == "wheel":
        if alpha_deg is None:
            raise ValueError("a wheel's horizontal orbit needs alpha (deg)")
        th_d, al_d, d_al, d_th, ph_d = _flat(theta_deg, alpha_deg, perturb, perturb_theta, phi_deg)
        if not np.all(np.isfinite(al_d)):
            raise ValueError("alpha must be finite")
        n = th_d.size
        th, al, ph = np.deg2rad(th_d), np.deg2rad(al_d), np.deg2rad(ph_d)
        # fit (eqs. 0 / 81) and a real Omega (eq. 29) exactly as `deathsphere orbit` decides
        orb = wheel.horizontal_orbit(th, al, a, r, k, g, outside=outside)
        status, reason = _setup_status(orb)
        rate = np.where(status == "", orb["omega"], np.nan)
        ok = status == ""
        state = np.full((9, n), np.nan)
        if ok.any():
            state[:, ok] = _wheel_start(th[ok], al[ok], ph[ok], rate[ok], d_th[ok], d_al[ok], a, r)
        extra = _empty_starts_fields(n)
        extra["speed"] = np.where(ok, orb["v_cm"], np.nan)
        kick_alpha, kick_theta = d_al, d_th
    else:
        if (omega3 is None) == (omega is None):
            raise ValueError("a sphere's horizontal orbit needs exactly one of omega3 and omega (rad/s)")
        spin = omega3 if omega is None else omega
        th_d, sp, br, d1, d2, ph_d = _flat(theta_deg, spin, branch, perturb, perturb_theta, phi_deg)
        if not np.all(np.isfinite(sp)):
            raise ValueError("omega3 / omega must be finite")
        if not np.all(np.isin(br, (0, 1))):
            raise ValueError("branch must be 0 (slow root of eq. 55) or 1 (fast root)")
        n = th_d.size
        th, ph = np.deg2rad(th_d), np.deg2rad(ph_d)
        # eq. (55) and its statuses exactly as `deathsphere orbit` decides
        if omega is None:
            orb = sph.sphere_orbit(th, sp, a, r, k, g, outside, branch=br.astype(int))
        else:
            orb = sph.sphere_orbit_from_rate(th, sp, a, r, k, g, outside)
        status, reason = _setup_status(orb)
        rate = np.where(status == "", orb["omega"], np.nan)
        ok = status == ""
        state = np.full((9, n), np.nan)
        al = np.where(outside, th + np.pi / 2, th - np.pi / 2)   # equivalent alpha (sec. 4)
        extra = _empty_starts_fields(n)
        if ok.any():
            X0, om3 = dyn.sphere_orbit_state(th[ok], rate[ok], a, r, k, g, outside, ph[ok])
            Xk, _ = dyn.sphere_orbit_state(th[ok] + d1[ok] + d2[ok], rate[ok], a, r, k, g, outside, ph[ok])
            state[:, ok] = np.concatenate((Xk[dyn.C], Xk[dyn.E1], X0[dyn.W]))
            extra["omega3"][ok] = om3
        extra["speed"] = np.where(ok, orb["v_cm"], np.nan)
        kick_alpha, kick_theta = d1, d2
    params = dyn.BodyParams(*(np.full(n, v, dtype=float) for v in (a, r, k, g)),
                            np.full(n, outside), np.full(n, setup.body == "sphere"))
    ok = status == ""
    if ok.any():
        state[:, ok] = dyn.project(state[:, ok], dyn.BodyParams(*(x[ok] for x in params)))
    period = np.where(ok, 2 * np.pi / np.abs(np.where(ok, rate, 1.0)), np.nan)
    return Starts(
        state=state, params=params, frame=np.broadcast_to(np.eye(3), (n, 3, 3)).copy(),
        input_row=_input_rows(input_row, n), body=np.full(n, setup.body, dtype=object),
        side=np.full(n, setup.side, dtype=object), orbit=np.full(n, "horizontal", dtype=object),
        theta=th, alpha=al, rate=rate, turning=np.where(ok, rate, 0.0), period=period, phi0=ph,
        speed=extra["speed"], omega3=extra["omega3"], perturb=kick_alpha, perturb_theta=kick_theta,
        mu=np.full(n, setup.mu), status=status, reason=reason)


#: Orbit frame of vertical orbits: x' = up (phi = 0 at the top, paper fig. 2),
#: z' = lab x (horizontal), y' = z' x x' = -lab y.
VERTICAL_FRAME = np.array([[0.0, 0.0, 1.0],
                           [0.0, -1.0, 0.0],
                           [1.0, 0.0, 0.0]])


def vertical_starts(setup: Setup, theta_deg, speed, *, phi_start_deg=0.0, perturb=0.0, perturb_theta=0.0,
                    input_row=None) -> Starts:
    """Wheels on vertical orbits (McDonald 1993 sec. 2.2.1, eqs. 26-28b; sec. 3, eq. 82).

    The orbit's axis z' is horizontal; the wheel lies in the orbit plane
    (alpha = 0 inside, 180 deg outside); the contact point runs round the
    cone of angle theta about z' (90 deg: a vertical great circle), its
    azimuth phi measured from the top (paper, fig. 2).

    Parameters (broadcast)
    ----------
    setup : :class:`deathsphere.model.Setup` with body wheel
    theta_deg : [deg]  cone angle of the orbit about z'
    speed : [m/s]      speed of the wheel's centre at the start point, >= 0
        (the top speed v_top of ``deathsphere vertical`` when the start is
        the top); the wheel moves towards increasing phi
    phi_start_deg : [deg]  azimuth of the start point from the top (0: top,
        180: bottom)
    perturb : [rad]    tilt kick out of the orbit plane, alpha -> alpha +
        perturb about axis 2 (as for :func:`horizontal_starts`)
    perturb_theta : [rad]  contact point moved by this in cone angle

    The "period" of the run is the lap time (elliptic integral,
    :func:`deathsphere.physics.vertical_orbit.lap_time`) when the wheel inside
    keeps contact all the way round by eq. (28a), otherwise the fixed
    duration 2 pi sqrt(r'/g) (the lap time of a wheel at the contact limit
    speed sqrt(g r'), as if the speed were constant).  Status no_fit where
    the wheel does not fit (r sin(theta) <= a inside, theta = 0 or 180 deg
    outside).  A wheel without contact at the start (inside, too slow at
    the top: eq. 28a) stops at once with status contact_lost.
    """
    _check_setup(setup)
    if setup.body != "wheel":
        raise ValueError("vertical orbits are for a wheel (body wheel)")
    _check_angles(theta_deg, perturb, perturb_theta)
    th_d, v, ps_d, d_al, d_th = _flat(theta_deg, speed, phi_start_deg, perturb, perturb_theta)
    if not np.all(np.isfinite(v)) or np.any(v < 0):
        raise ValueError("speed must be finite and >= 0 m/s")
    if not np.all(np.isfinite(ps_d)):
        raise ValueError("phi_start must be finite")
    n = th_d.size
    outside = setup.side == "outside"
    a, r, k, g = setup.a, setup.r, setup.k, setup.g
    th, ph = np.deg2rad(th_d), np.deg2rad(ps_d)
    al = np.full(n, np.pi if outside else 0.0)
    fits = vert.vertical_fits(th, a, r, outside)
    rp = vert.vertical_r_prime(th, a, r, outside)
    rp_s = np.where(fits, rp, 1.0)
    rate = np.where(fits, v / rp_s, np.nan)
    # eq. (27): r' phidot0^2 at the top, from the start point
    v_top2 = v ** 2 - 2 * g * rp_s * (1 - np.cos(ph)) / (2 * k + 1)
    closes = fits & (not outside) & (v_top2 > g * rp_s)
    phidot0 = np.sqrt(np.where(closes, v_top2, g * rp_s)) / rp_s
    with np.errstate(invalid="ignore"):
        lap = vert.lap_time(th, phidot0, a, r, k, g)
    period = np.where(closes, lap, 2 * np.pi * np.sqrt(rp_s / g))
    period = np.where(fits, period, np.nan)
    status = np.where(fits, "", "no_fit").astype(object)
    reason = np.where(fits, "", _REASONS["no_fit_vertical"]).astype(object)
    state = np.full((9, n), np.nan)
    params = dyn.BodyParams(*(np.full(n, x, dtype=float) for x in (a, r, k, g)),
                            np.full(n, outside), np.zeros(n, dtype=bool))
    ok = fits
    if ok.any():
        local = _wheel_start(th[ok], al[ok], ph[ok], rate[ok], d_th[ok], d_al[ok], a, r)
        lab = np.concatenate([VERTICAL_FRAME @ local[s] for s in (dyn.C, dyn.E1, dyn.W)])
        state[:, ok] = dyn.project(lab, dyn.BodyParams(*(x[ok] for x in params)))
    return Starts(
        state=state, params=params, frame=np.broadcast_to(VERTICAL_FRAME, (n, 3, 3)).copy(),
        input_row=_input_rows(input_row, n), body=np.full(n, "wheel", dtype=object),
        side=np.full(n, setup.side, dtype=object), orbit=np.full(n, "vertical", dtype=object),
        theta=th, alpha=al, rate=rate, turning=np.zeros(n), period=period, phi0=ph,
        speed=v, omega3=np.full(n, np.nan), perturb=d_al, perturb_theta=d_th,
        mu=np.full(n, setup.mu), status=status, reason=reason)


# --------------------------------------------------------------------------
# the integration


def _wrap(x):
    """x wrapped into [-pi, pi)."""
    return (x + np.pi) % (2 * np.pi) - np.pi


@dataclass
class _Group:
    """The bodies integrated together right now (a subset of the run)."""

    idx: np.ndarray            # indices into the run's bodies
    params: dyn.BodyParams
    turning: np.ndarray
    mu: np.ndarray
    g: np.ndarray
    _cache: tuple = field(default=(None, None, None))
    _scalar: tuple | None = None

    def __post_init__(self):
        if self.idx.size == 1:      # (coefficients, g) for dyn.contact_values
            self._scalar = (dyn.scalar_coefficients(self.params), float(self.params.g[0]))

    def values(self, t, y):
        """(normal/g, (mu N - |F|)/g) per body at (t, y), cached for the
        repeated calls solve_ivp makes with one (t, y)."""
        last_t, last_y, vals = self._cache
        if last_y is not None and t == last_t and (y is last_y or np.array_equal(y, last_y)):
            return vals
        if self._scalar is not None and y.ndim == 1:
            try:          # one body: the same equations on Python floats
                n, fmag = dyn.contact_values(y.tolist(), *self._scalar)
                mu = float(self.mu[0])
                slip = mu * n - fmag if math.isfinite(mu) else 1.0
                vals = (np.array([n]) / self.g, np.array([slip]) / self.g)
                self._cache = (t, y, vals)
                return vals
            except (ZeroDivisionError, OverflowError, ValueError):
                pass
        state = np.asarray(y).reshape(9, -1)
        f = dyn.contact_force(state, self.params)
        n = f["normal"]
        finite = np.isfinite(self.mu)
        slip = np.where(finite, np.where(finite, self.mu, 0.0) * n - f["friction_magnitude"], 1.0)
        vals = (n / self.g, slip / self.g)
        self._cache = (t, y, vals)
        return vals

    def events(self):
        def contact_lost(t, y):
            return float(np.min(self.values(t, y)[0]))

        def slips(t, y):
            return float(np.min(self.values(t, y)[1]))

        for ev in (contact_lost, slips):
            ev.terminal = True
            ev.direction = -1
        return [contact_lost, slips]


@dataclass
class _Run:
    """Mutable bookkeeping of one run: per-body status, reason, accumulators
    (summary extrema, event data, unwrap carry) and solver counters."""

    status: np.ndarray
    reason: np.ndarray
    acc: dict
    counters: dict


class Simulation:
    """Integrate the exact equations of motion for a set of bodies (beyond
    the paper; docs/simulation.md).

    Parameters
    ----------
    starts : :class:`Starts` (from :func:`horizontal_starts`,
        :func:`vertical_starts`, :meth:`Starts.concat`)
    periods : float > 0   run length in periods of each body's orbit
        (:attr:`Starts.period`): body i runs for ``periods * period_i``
    points_per_period : int >= 1   output rows per period of the fastest body
        (all bodies share one time grid, dt = min(period) / points_per_period)
    method : one of :data:`METHODS` (solve_ivp), default DOP853
    rtol : float   solve_ivp's relative tolerance (default 1e-10)
    atol : float or None   dimensionless absolute tolerance, scaled per state
        component: atol * r on the centre [m], atol on axis 1 [-] (not
        controlled for a sphere, where axis 1 is a marker), atol * S on the
        angular velocity [rad/s], S = sqrt(|w|^2 + Omega^2 + g/a) at t = 0.
        Default: equal to rtol.  The step is also capped at 2 / max(S), so
        the nutation stays resolved where the error estimate alone would
        allow huge steps (a steady orbit in the turning frame).
    frame : "turning" (default) or "lab", see :data:`FRAMES`
    mu : float, array or None   friction available (None: ``starts.mu``,
        from the Setup); inf: no ``slips`` event
    project_each_period : bool   move the state back onto the constraints
        (:func:`deathsphere.physics.dynamics.project`) at every chunk
        boundary; off by default, so ``constraint_residual`` shows the
        integrator's true drift
    record_states : bool   also keep the full state (c, e1, w) at every
        output row, for :meth:`sample_states` (off by default: the time
        series and summary are the same either way)

    Iterate with :meth:`chunks` (streaming), then :meth:`summary`; or call
    :meth:`run`.
    """

    def __init__(self, starts: Starts, *, periods: float = 20.0, points_per_period: int = 100,
                 method: str = "DOP853", rtol: float = 1e-10, atol: float | None = None,
                 frame: str = "turning", mu=None, project_each_period: bool = False,
                 record_states: bool = False):
        if not (isinstance(periods, (int, float, np.integer, np.floating)) and math.isfinite(periods)
                and periods > 0):
            raise ValueError(f"periods must be a finite number > 0 (got {periods!r})")
        if isinstance(points_per_period, bool) or int(points_per_period) != points_per_period \
                or points_per_period < 1:
            raise ValueError(f"points_per_period must be an integer >= 1 (got {points_per_period!r})")
        if method not in METHODS:
            raise ValueError(f"method must be one of {' | '.join(METHODS)} (got {method!r})")
        if not (math.isfinite(rtol) and 0 < rtol < 1):
            raise ValueError(f"rtol must be within (0, 1) (got {rtol!r})")
        atol = rtol if atol is None else atol
        if not (math.isfinite(atol) and atol > 0):
            raise ValueError(f"atol must be > 0 (got {atol!r})")
        if frame not in FRAMES:
            raise ValueError(f"frame must be one of {' | '.join(FRAMES)} (got {frame!r})")
        if len(starts) == 0:
            raise ValueError("no bodies to simulate")
        mu_arr = starts.mu if mu is None else np.broadcast_to(np.asarray(mu, dtype=float), (len(starts),))
        if np.any(np.isnan(mu_arr)) or np.any(mu_arr < 0):
            raise ValueError("mu must be >= 0 (inf: no limit)")
        self.starts = starts
        self.periods = float(periods)
        self.points_per_period = int(points_per_period)
        self.method = method
        self.rtol = float(rtol)
        self.atol = float(atol)
        self.frame = frame
        self.mu = np.array(mu_arr, dtype=float)
        self.project_each_period = bool(project_each_period)
        ok = starts.status == ""
        self._ok = ok
        self.t_ref = float(np.min(starts.period[ok])) if ok.any() else 1.0
        self.oversample = -(-_MIN_INTERNAL_PER_PERIOD // self.points_per_period)   # ceil
        self.dt = self.t_ref / (self.points_per_period * self.oversample)
        self.t_end = np.where(ok, self.periods * np.where(ok, starts.period, 0.0), 0.0)
        self.j_max = int(math.ceil(float(np.max(self.t_end)) / self.dt - 1e-9)) if ok.any() else 0
        ends = np.unique(self.t_end[ok])
        if self.j_max and ends.size == 1:
            # the grid ends exactly at the (common) end time: 0.999 periods
            # are 0.999, not the 0.99 of the sample before, and 0.001 periods
            # are run rather than rounded to none
            self.dt = float(ends[0]) / self.j_max
        self.j_per_chunk = self.points_per_period * self.oversample
        self._tol = 1e-9 * self.dt
        self._frame_rate = np.where(frame == "turning", starts.turning, 0.0).astype(float)
        self._summary = None
        self.record_states = bool(record_states)
        self._state_parts = []

    @property
    def n_chunks(self) -> int:
        """Number of chunks :meth:`chunks` yields (one per period of the
        fastest body; for a progress bar)."""
        return max(1, -(-self.j_max // self.j_per_chunk))

    # ---- per-sample quantities -------------------------------------------------

    def _sample(self, idx, y, t, acc):
        """Time-series quantities of bodies ``idx`` at states y (9, m, nb)
        and times t (m,), in SI units and radians; advances the azimuth's
        unwrap carry ``acc["phi_frame"]``.  Returns a dict of (m, nb) arrays."""
        s = self.starts
        p = dyn.BodyParams(*(x[idx] for x in s.params))
        R = s.frame[idx]                                             # (nb, 3, 3)
        pvec = dyn.contact_point(y, p)                              # (3, m, nb)
        c, e1, w = y[dyn.C], y[dyn.E1], y[dyn.W]
        pl = np.einsum("bji,jmb->imb", R, pvec)                    # orbit-frame components
        zp = np.moveaxis(R[:, :, 2], 0, 1)[:, None, :]             # z' (3, 1, nb)
        theta = np.arctan2(np.hypot(pl[0], pl[1]), pl[2])
        # azimuth about z': unwrapped sample by sample from the carry; in the
        # turning frame the frame's own rotation Omega t is added afterwards
        raw = np.arctan2(pl[1], pl[0])
        prev = acc["phi_frame"][idx]
        phi_f = np.empty_like(raw)
        for i in range(raw.shape[0]):
            prev = prev + _wrap(raw[i] - prev)
            phi_f[i] = prev
        acc["phi_frame"][idx] = prev
        phi = phi_f + self._frame_rate[idx][None, :] * t[:, None]
        # tilt (eq. 11): z' = -cos(alpha) e1 - sin(alpha) e3; for a sphere the
        # equivalent alpha of sec. 4 (axis 3 along the radius)
        e3 = (pvec - c) / p.a
        e1h = e1 / np.sqrt(np.sum(e1 * e1, axis=0))
        z3 = np.sum(zp * e3, axis=0)
        z1 = np.sum(zp * e1h, axis=0)
        cos_sphere = np.where(p.outside, -1.0, 1.0) * np.sqrt(np.maximum(1.0 - z3 * z3, 0.0))
        al = np.arctan2(-z3, np.where(p.sphere, cos_sphere, -z1))
        alpha0 = s.alpha[idx]
        alpha = alpha0 + _wrap(al - alpha0)
        speed = np.sqrt(np.sum(np.cross(pvec - c, w, axis=0) ** 2, axis=0))   # |a e3 x w|, eq. (6)
        f = dyn.contact_force(y, p)
        drift = (dyn.energy(y, p) - acc["e0"][idx]) / acc["e_scale"][idx]
        res = dyn.constraint_residuals(y, p)
        resid = np.maximum(np.where(p.sphere, 0.0, np.abs(res["axis"])), np.abs(res["contact"]) / p.r)
        q = {
            "theta": theta, "phi": phi, "alpha": alpha, "speed": speed,
            "normal": f["normal"], "friction": f["friction_magnitude"], "mu": f["mu_required"],
            "drift": drift, "resid": resid,
        }
        if self.record_states:
            # the turning frame is at angle Omega t from the lab about +z
            ang = self._frame_rate[idx][None, :] * t[:, None]
            cos, sin = np.cos(ang), np.sin(ang)
            lab = np.array(y, dtype=float, copy=True)
            for rows in (dyn.C, dyn.E1, dyn.W):
                x, yy = y[rows][0], y[rows][1]
                lab[rows.start], lab[rows.start + 1] = cos * x - sin * yy, sin * x + cos * yy
            q["state"] = lab
        return q

    def _accumulate(self, idx, q, within, acc):
        """Fold samples ``q`` of bodies ``idx`` into the summary extrema,
        only where ``within`` (m, nb) (a body's samples up to its end time)."""
        th0, al0 = self.starts.theta[idx], self.starts.alpha[idx]
        reductions = (
            ("theta_drift", np.fmax, np.abs(q["theta"] - th0)),
            ("alpha_drift", np.fmax, np.abs(q["alpha"] - al0)),
            ("min_normal", np.fmin, q["normal"]),
            ("max_mu", np.fmax, q["mu"]),
            ("max_drift", np.fmax, np.abs(q["drift"])),
            ("max_resid", np.fmax, q["resid"]),
        )
        for key, op, v in reductions:
            acc[key][idx] = op(acc[key][idx], op.reduce(np.where(within, v, np.nan), axis=0))

    def _rows(self, idx, t, q, keep):
        """Long-format rows (time-major) of the samples where keep (m, nb)."""
        rows = self.starts.input_row[idx]
        if "state" in q:
            self._state_parts.append({
                "input_row": np.broadcast_to(rows[None, :], keep.shape)[keep].astype(np.int64),
                "t_s": np.broadcast_to(t[:, None], keep.shape)[keep],
                "state": q["state"][:, keep]})
        return {
            "input_row": np.broadcast_to(rows[None, :], keep.shape)[keep].astype(np.int64),
            "t_s": np.broadcast_to(t[:, None], keep.shape)[keep],
            "phi_deg": np.rad2deg(q["phi"][keep]),
            "theta_deg": np.rad2deg(q["theta"][keep]),
            "alpha_deg": np.rad2deg(q["alpha"][keep]),
            "speed_m_s": q["speed"][keep],
            "normal_per_mass_m_s2": q["normal"][keep],
            "friction_per_mass_m_s2": q["friction"][keep],
            "mu_required": q["mu"][keep],
            "energy_drift": q["drift"][keep],
            "constraint_residual": q["resid"][keep],
        }

    # ---- the run ----------------------------------------------------------------

    def chunks(self, progress: Callable[[int, int], None] | None = None) -> Iterator[Table]:
        """Run the simulation, yielding the time series chunk by chunk.

        Each chunk is a :class:`Table` with columns :data:`SERIES_COLUMNS`
        covering one period of the fastest body (the first also holds
        t = 0); rows are time-major (all bodies at one time, by
        ``input_row``); a body's rows stop at its end time or at its event
        (the event itself is its last row).  ``progress(done, total)`` is
        called after each chunk with counts of chunks (total =
        :attr:`n_chunks`).  Once the generator is exhausted :meth:`summary`
        is available.  Each call runs the simulation afresh.
        """
        s = self.starts
        n = len(s)
        wall0 = time.perf_counter()
        self._summary = None
        self._state_parts = []
        acc = {name: np.full(n, np.nan) for name in (
            "theta_drift", "alpha_drift", "min_normal", "max_mu", "max_drift", "max_resid",
            "event_t", "event_phi", "event_theta", "event_alpha", "t_done")}
        acc["phi_frame"] = s.phi0.astype(float).copy()
        acc["e0"] = np.full(n, np.nan)
        acc["e_scale"] = np.ones(n)
        status = s.status.copy()
        reason = s.reason.copy()
        ok = self._ok
        if ok.any():
            p_ok = dyn.BodyParams(*(x[ok] for x in s.params))
            e0 = dyn.energy(s.state[:, ok], p_ok)
            acc["e0"][ok] = e0
            # energy scale: kinetic energy + g r (per unit mass)
            acc["e_scale"][ok] = np.abs(e0 - p_ok.g * s.state[2, ok]) + p_ok.g * p_ok.r
        counters = {"n_steps": 0, "n_fev": 0}
        run = _Run(status, reason, acc, counters)

        active = np.flatnonzero(ok)
        y = s.state[:, active].copy()                                # (9, nA)
        t_cur = 0.0
        rows = []
        if active.size:
            # t = 0: every body's first row; bodies without contact (or
            # slipping) at the start stop there
            zero = np.zeros(1)
            q = self._sample(active, y[:, None, :], zero, acc)
            everything = np.ones((1, active.size), dtype=bool)
            self._accumulate(active, q, everything, acc)
            acc["t_done"][active] = 0.0
            rows.append(self._rows(active, zero, q, everything))
            keep = self._stop_at(active, 0.0, q, run)
            active, y = active[keep], y[:, keep]

        total = self.n_chunks
        for chunk in range(total):
            j0 = chunk * self.j_per_chunk
            j1 = min((chunk + 1) * self.j_per_chunk, self.j_max)
            t_b = j1 * self.dt
            if self.project_each_period and active.size and chunk > 0:
                y = dyn.project(y, dyn.BodyParams(*(x[active] for x in s.params)))
            while active.size and t_cur < t_b:
                active, y, t_cur = self._integrate(active, y, t_cur, t_b, j0, j1, run, rows)
            done = self.t_end[active] <= t_b + self._tol
            for i in active[done]:
                status[i], reason[i] = "completed", _REASONS["completed"]
            active, y = active[~done], y[:, ~done]
            yield _rows_table(rows)
            rows = []
            if progress is not None:
                progress(chunk + 1, total)
            if not active.size:
                if progress is not None and chunk + 1 < total:
                    progress(total, total)
                break
        for i in active:          # only if rounding left a body a hair short of its end
            status[i], reason[i] = "completed", _REASONS["completed"]
        self._summary = self._make_summary(status, reason, acc, counters, time.perf_counter() - wall0)

    def _record_event(self, i, j, name, t, q, run):
        run.status[i], run.reason[i] = name, _REASONS[name]
        run.acc["event_t"][i] = t
        run.acc["event_phi"][i] = q["phi"][-1, j]
        run.acc["event_theta"][i] = q["theta"][-1, j]
        run.acc["event_alpha"][i] = q["alpha"][-1, j]
        run.acc["t_done"][i] = t

    def _stop_at(self, active, t, q, run):
        """Bodies with no contact (normal <= 0) or slipping (mu N <= |F|) at
        the start stop there; returns the mask of those that go on."""
        normal, fric = q["normal"][-1], q["friction"][-1]
        mu = self.mu[active]
        finite = np.isfinite(mu)
        lost = ~(normal > 0)
        slip = ~lost & finite & ~(np.where(finite, mu, 0.0) * normal - fric > 0)
        for flag, name in ((lost, "contact_lost"), (slip, "slips")):
            for j in np.flatnonzero(flag):
                self._record_event(active[j], j, name, t, q, run)
        return ~(lost | slip)

    def _jac_sparsity(self, nA):
        """Block-diagonal sparsity of the Jacobian (bodies are independent)
        in the component-major state layout (row = component * nA + body)."""
        from scipy.sparse import coo_matrix

        comp = np.arange(9)
        body = np.arange(nA)
        rows = (comp[:, None, None] * nA + body[None, None, :])
        cols = (comp[None, :, None] * nA + body[None, None, :])
        rows, cols = np.broadcast_arrays(rows, cols)
        data = np.ones(rows.size)
        return coo_matrix((data, (rows.ravel(), cols.ravel())), shape=(9 * nA, 9 * nA)).tocsr()

    def _integrate(self, active, y, t_cur, t_b, j0, j1, run, rows):
        """One solve_ivp call for the bodies ``active`` from t_cur to t_b or
        to the first terminal event; samples the dense output on the grid.
        Returns the bodies still running, their state and the time reached."""
        s = self.starts
        nA = active.size
        p = dyn.BodyParams(*(x[active] for x in s.params))
        group = _Group(active, p, self._frame_rate[active], self.mu[active], p.g)
        fun = dyn.ode(p, self._frame_rate[active])
        w0 = s.state[dyn.W][:, active]
        scale_w = np.sqrt(np.sum(w0 * w0, axis=0) + s.rate[active] ** 2 + p.g / p.a)
        # a sphere's axis-1 rows are a body-fixed marker that does not enter
        # its dynamics: kept out of the error control (docs/simulation.md)
        marker = np.where(p.sphere, _MARKER_ATOL / self.atol, 1.0)
        atol = self.atol * np.concatenate((np.broadcast_to(p.r, (3, nA)), np.broadcast_to(marker, (3, nA)),
                                           np.broadcast_to(scale_w, (3, nA)))).reshape(-1)
        # resolve the body's own rotation and nutation even where the state
        # barely moves (a steady orbit in the turning frame): h <= 2 / S
        options = {"max_step": _MAX_STEP_RATES / float(np.max(scale_w))}
        if self.method in ("Radau", "BDF") and nA > 1:
            options["jac_sparsity"] = self._jac_sparsity(nA)
        sol = solve_ivp(fun, (t_cur, t_b), y.reshape(-1), method=self.method, rtol=self.rtol, atol=atol,
                        dense_output=True, events=group.events(), vectorized=self.method not in _EXPLICIT,
                        **options)
        run.counters["n_steps"] += max(len(sol.t) - 1, 0)
        run.counters["n_fev"] += int(sol.nfev)
        t_stop = float(sol.t[-1])
        end = self.t_end[active] + self._tol
        # the grid's samples in (t_cur, t_stop]
        j_lo = max(j0 + 1, int(math.floor(t_cur / self.dt + 1e-9)) + 1)
        js = np.arange(j_lo, j1 + 1)
        ts = js * self.dt
        sel = ts <= t_stop + self._tol
        js, ts = js[sel], np.minimum(ts[sel], t_stop)
        if ts.size:
            ys = sol.sol(ts).reshape(9, nA, ts.size).transpose(0, 2, 1)   # (9, m, nA)
            q = self._sample(active, ys, ts, run.acc)
            within = ts[:, None] <= end[None, :]
            self._accumulate(active, q, within, run.acc)
            keep = within & ((js % self.oversample == 0) | (js == self.j_max))[:, None]
            if keep.any():
                rows.append(self._rows(active, ts, q, keep))
            n_in = within.sum(axis=0)
            has = n_in > 0
            run.acc["t_done"][active[has]] = ts[n_in[has] - 1]
        if sol.status == -1:
            for i in active:
                run.status[i], run.reason[i] = "failed", f"integrator failed: {sol.message}"
                run.acc["event_t"][i] = t_stop
            return active[:0], y[:, :0], t_b
        if sol.status != 1:
            return active, sol.y[:, -1].reshape(9, nA), t_b
        # a terminal event: which bodies reached zero?
        fired = [len(te) > 0 for te in sol.t_events]
        k_fired = fired.index(True)
        t_ev = float(sol.t_events[k_fired][0])
        y_ev = np.asarray(sol.y_events[k_fired][0]).reshape(9, nA)
        vals = group.values(t_ev, y_ev.reshape(-1))
        q = self._sample(active, y_ev[:, None, :], np.array([t_ev]), run.acc)
        in_time = t_ev <= end
        self._accumulate(active, q, in_time[None, :], run.acc)
        stopped = np.zeros(nA, dtype=bool)
        for k_ev, name in enumerate(("contact_lost", "slips")):
            v = vals[k_ev]
            hit = (v <= _EVENT_TOL) & ~stopped
            if k_ev == k_fired:
                hit[np.argmin(v)] = True
            for j in np.flatnonzero(hit):
                stopped[j] = True
                if in_time[j]:
                    self._record_event(active[j], j, name, t_ev, q, run)
                else:   # the event came after the body's end time
                    run.status[active[j]], run.reason[active[j]] = "completed", _REASONS["completed"]
        emit = (stopped & in_time)[None, :]
        if emit.any():
            rows.append(self._rows(active, np.array([t_ev]), q, emit))
        return active[~stopped], y_ev[:, ~stopped], t_ev

    def _make_summary(self, status, reason, acc, counters, wall) -> Table:
        s = self.starts
        n = len(s)
        ok = self._ok
        nan = np.full(n, np.nan)
        period = s.period
        with np.errstate(invalid="ignore", divide="ignore"):
            done = np.where(ok, acc["t_done"] / np.where(ok, period, 1.0), nan)
        cols = {
            "input_row": s.input_row.astype(np.int64),
            "body": s.body, "side": s.side, "orbit": s.orbit,
            "theta_deg": np.rad2deg(s.theta), "alpha_deg": np.rad2deg(s.alpha),
            "a_m": s.params.a.astype(float), "r_m": s.params.r.astype(float),
            "k": s.params.k.astype(float), "g_m_s2": s.params.g.astype(float),
            "omega_rad_s": s.rate, "omega3_rad_s": s.omega3, "speed_m_s": s.speed, "period_s": period,
            "perturb_rad": s.perturb.astype(float), "perturb_theta_rad": s.perturb_theta.astype(float),
            "mu_available": np.where(np.isinf(self.mu), np.nan, self.mu),
            "status": status.astype(object), "reason": reason.astype(object),
            "event_time_s": acc["event_t"],
            "event_phi_deg": np.rad2deg(acc["event_phi"]),
            "event_theta_deg": np.rad2deg(acc["event_theta"]),
            "event_alpha_deg": np.rad2deg(acc["event_alpha"]),
            "periods_simulated": done,
            "max_theta_drift_deg": np.rad2deg(acc["theta_drift"]),
            "max_alpha_drift_deg": np.rad2deg(acc["alpha_drift"]),
            "min_normal_per_mass_m_s2": acc["min_normal"],
            "max_mu_required": acc["max_mu"],
            "max_abs_energy_drift": acc["max_drift"],
            "max_constraint_residual": acc["max_resid"],
            "method": np.full(n, self.method, dtype=object),
            "rtol": np.full(n, self.rtol), "atol": np.full(n, self.atol),
            "frame": np.full(n, self.frame, dtype=object),
            "n_steps": np.full(n, counters["n_steps"], dtype=np.int64),
            "n_fev": np.full(n, counters["n_fev"], dtype=np.int64),
            "wall_time_s": np.full(n, wall),
        }
        return Table({name: cols[name] for name in SUMMARY_COLUMNS})

    def summary(self) -> Table:
        """One row per body (:data:`SUMMARY_COLUMNS`); available once
        :meth:`chunks` has been exhausted (RuntimeError before)."""
        if self._summary is None:
            raise RuntimeError("the simulation has not been run to the end: exhaust chunks() or call run()")
        return self._summary

    def sample_states(self) -> dict:
        """The full state at every output row (beyond the paper;
        docs/simulation.md "3-D view"), for a run made with
        ``record_states=True``, once :meth:`chunks` has been exhausted.

        Returns a dict: ``input_row`` (N,), ``t_s`` (N,) and ``state`` (9, N),
        the state (c, e1, w) of :mod:`deathsphere.physics.dynamics` in lab
        components (a run in the turning frame is rotated back by Omega t),
        the rows in the order of the time series (time-major, then
        ``input_row``), so row j belongs to row j of the series.
        """
        if not self.record_states:
            raise RuntimeError("the simulation was made without record_states=True")
        self.summary()
        parts = self._state_parts
        if not parts:
            return {"input_row": np.zeros(0, dtype=np.int64), "t_s": np.zeros(0), "state": np.zeros((9, 0))}
        rows = np.concatenate([p["input_row"] for p in parts])
        t = np.concatenate([p["t_s"] for p in parts])
        state = np.concatenate([p["state"] for p in parts], axis=1)
        order = np.lexsort((rows, t))
        return {"input_row": rows[order], "t_s": t[order], "state": state[:, order]}

    def run(self, progress: Callable[[int, int], None] | None = None) -> tuple[Table, Table]:
        """Run to the end; returns ``(series, summary)``."""
        series = concat_tables(list(self.chunks(progress)))
        return series, self.summary()


def _rows_table(parts: list[dict]) -> Table:
    """One time-major Table from row blocks (sorted by time, then input_row)."""
    if not parts:
        return Table({name: np.zeros(0, dtype=np.int64 if name == "input_row" else float)
                      for name in SERIES_COLUMNS})
    cols = {name: np.concatenate([p[name] for p in parts]) for name in SERIES_COLUMNS}
    order = np.lexsort((cols["input_row"], cols["t_s"]))
    return Table({name: v[order] for name, v in cols.items()})


def concat_tables(tables: Sequence[Table]) -> Table:
    """Concatenate Tables with the same columns (e.g. the chunks of a run)."""
    tables = [t for t in tables if t is not None]
    if not tables:
        return _rows_table([])
    names = tables[0].names
    return Table({name: np.concatenate([t[name] for t in tables]) for name in names})


def simulate(starts: Starts, progress: Callable[[int, int], None] | None = None,
             **options) -> tuple[Table, Table]:
    """``Simulation(starts, **options).run(progress)``: the whole time series
    and the summary (beyond the paper; docs/simulation.md)."""
    return Simulation(starts, **options).run(progress)
