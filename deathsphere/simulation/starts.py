"""Initial conditions of simulated bodies (beyond the paper; docs/simulation.md,
"Initial conditions" and "Perturbation").

A :class:`Starts` holds the state vectors of n bodies and what the summary
reports about them.  :func:`horizontal_starts` puts bodies on steady
horizontal orbits of the paper (a wheel given (theta, alpha), eqs. (8b),
(11)-(13), (29); a sphere given (theta, omega3 and a branch) or (theta,
Omega), eqs. (42), (55)); :func:`vertical_starts` puts wheels on vertical
orbits (eqs. (26)-(28b), (82)).  Both can kick the body off the steady orbit
by a small angle (``perturb_deg``).

Every angle is in degrees at the builders' interface, as on the command
line (the kicks too); the :class:`Starts` fields used by the integrator
are in radians, and the angles given are kept in degrees for the summary.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from deathsphere.model import Setup
from deathsphere.physics import dynamics as dyn
from deathsphere.physics import sphere as sph
from deathsphere.physics import vertical_orbit as vert
from deathsphere.physics import wheel
from deathsphere.physics.geometry import r_prime
from deathsphere.physics.status import REASON_TEXT, Status
from deathsphere.records.paper_bodies import WHEEL, Ball, Wheel
from deathsphere.simulation.bodies import MachineRun, concat_params, take
from deathsphere.simulation.status import NO_FIT_VERTICAL_REASON, RunStatus

__all__ = ["Starts", "horizontal_starts", "vertical_starts", "VERTICAL_FRAME", "wheel_geometry", "wheel_start",
           "start_status"]


@dataclass(frozen=True)
class Starts:
    """Initial conditions of n bodies and what the summary reports about them.

    Arrays have shape (n,) (``state`` (9, n), ``frame`` (n, 3, 3)).
    ``frame[i]`` has the columns x', y', z' of the orbit's frame in lab
    components (paper, fig. 1-2: z' the orbit axis, x' towards the top);
    identity for horizontal orbits.  ``theta``, ``alpha`` [rad] are the
    steady (unperturbed) values the drift is measured from, and
    ``theta_deg``, ``alpha_deg`` the same in degrees as given (the summary
    echoes them: 60 stays 60, not 59.99999999999999); ``rate`` [rad/s]
    the steady Omega (horizontal) or phidot at the start (vertical);
    ``turning`` [rad/s] the rate of the turning frame (Omega for horizontal
    orbits, 0 for vertical ones); ``period`` [s] the time one "period" of the
    run lasts; ``phi0`` [rad] the start azimuth in the orbit frame;
    ``perturb_deg``, ``perturb_theta_deg`` [deg] the kicks as given.
    ``status`` holds int8 :class:`~deathsphere.simulation.status.RunStatus`
    codes: PENDING for bodies that can be integrated, else NO_FIT /
    NO_ORBIT with ``reason``.
    """

    state: np.ndarray
    params: dyn.BodyParams | MachineRun
    frame: np.ndarray
    input_row: np.ndarray
    body: np.ndarray
    side: np.ndarray
    orbit: np.ndarray
    theta: np.ndarray
    alpha: np.ndarray
    theta_deg: np.ndarray
    alpha_deg: np.ndarray
    rate: np.ndarray
    turning: np.ndarray
    period: np.ndarray
    phi0: np.ndarray
    speed: np.ndarray
    omega3: np.ndarray
    perturb_deg: np.ndarray
    perturb_theta_deg: np.ndarray
    mu: np.ndarray
    status: np.ndarray
    reason: np.ndarray

    def __len__(self) -> int:
        return int(self.input_row.size)

    @property
    def pending(self) -> np.ndarray:
        """Mask of the bodies that can be integrated (a steady orbit to start from)."""
        return self.status == RunStatus.PENDING

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
                out[name] = concat_params(vals)
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
                out[name] = take(v, index)
            else:
                out[name] = v[index]
        return Starts(**out)


def _check_setup(setup: Setup):
    if not setup.body.rolls:
        raise ValueError(f"simulation needs body wheel or sphere (got {setup.body.word!r})")
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


def _check_angles(theta_deg, perturb_deg, perturb_theta_deg):
    theta_deg = np.asarray(theta_deg, dtype=float)
    if not np.all(np.isfinite(theta_deg)) or np.any((theta_deg < 0) | (theta_deg > 180)):
        raise ValueError("theta must be finite and within 0..180 deg")
    for name, x in (("perturb_deg", perturb_deg), ("perturb_theta_deg", perturb_theta_deg)):
        if not np.all(np.isfinite(np.asarray(x, dtype=float))):
            raise ValueError(f"{name} must be finite (degrees)")


def wheel_geometry(theta, alpha, phi, a, r):
    """Centre, axis 1 and axis 3 of a wheel in the orbit frame, shapes (3, n).

    McDonald (1993) eqs. (11), (11a), (8b): with r_hat' = (cos phi, sin phi, 0)
    and z' = (0, 0, 1), p = r (sin(theta) r_hat' + cos(theta) z'),
    e1 = -sin(alpha) r_hat' - cos(alpha) z', e3 = cos(alpha) r_hat' - sin(alpha) z',
    c = p - a e3.  Angles [rad], lengths [m].
    """
    cp, sp = np.cos(phi), np.sin(phi)
    zero = np.zeros_like(cp)
    rhat = np.stack((cp, sp, zero))
    zhat = np.stack((zero, zero, np.ones_like(cp)))
    pvec = r * (np.sin(theta) * rhat + np.cos(theta) * zhat)
    e1 = -np.sin(alpha) * rhat - np.cos(alpha) * zhat
    e3 = np.cos(alpha) * rhat - np.sin(alpha) * zhat
    return pvec - a * e3, e1, e3


def wheel_start(theta, alpha, phi, rate, d_theta, d_alpha, a, r):
    """State (c, e1, w) in orbit-frame components, shape (9, n), of a wheel
    on the orbit (theta, alpha) moving at the rate ``rate`` about z', kicked
    by (d_theta, d_alpha) [rad].

    Angular velocity of the steady orbit, McDonald (1993) eq. (13):
    w = (r'/a) rate e1 - rate sin(alpha) e3, r' = r sin(theta) - a cos(alpha);
    the kick moves the contact point to theta + d_theta and tilts the wheel
    to alpha + d_alpha (about axis 2, the orbit's tangent) keeping w: rolling
    and contact hold exactly (docs/simulation.md, "Perturbation").
    """
    _, e1_0, e3_0 = wheel_geometry(theta, alpha, phi, a, r)
    rp = r_prime(theta, alpha, a, r)
    w = (rp / a) * rate * e1_0 - rate * np.sin(alpha) * e3_0
    c, e1, _ = wheel_geometry(theta + d_theta, alpha + d_alpha, phi, a, r)
    return np.concatenate((c, e1, w))


def start_status(orb):
    """(RunStatus codes, reason words) from a physics orbit dict: only fit
    and the existence of Omega decide whether a body can start; contact and
    friction are the simulation's business (events)."""
    code = np.asarray(orb["status"]).reshape(-1)
    words = REASON_TEXT[np.asarray(orb["reason"]).reshape(-1)]
    status = np.where(code == Status.NO_FIT, RunStatus.NO_FIT,
                      np.where(code == Status.NO_ORBIT, RunStatus.NO_ORBIT, RunStatus.PENDING)).astype(np.int8)
    return status, np.where(status == RunStatus.PENDING, "", words).astype(object)


@dataclass
class _Horizontal:
    """The body-specific part of :func:`horizontal_starts` (radians, and the
    angles in degrees as given)."""

    theta: np.ndarray
    alpha: np.ndarray
    theta_deg: np.ndarray
    alpha_deg: np.ndarray
    phi: np.ndarray
    rate: np.ndarray
    state: np.ndarray
    status: np.ndarray
    reason: np.ndarray
    speed: np.ndarray
    omega3: np.ndarray
    kick_alpha: np.ndarray   # [deg]
    kick_theta: np.ndarray   # [deg]


def _wheel_horizontal(setup, theta_deg, alpha_deg, perturb_deg, perturb_theta_deg, phi_deg, outside):
    """A wheel on the orbit (theta, alpha): Omega from eq. (29), fit (eqs. 0 /
    81) and a real Omega exactly as ``deathsphere orbit`` decides."""
    a, r, k, g = setup.a, setup.r, setup.k, setup.g
    if alpha_deg is None:
        raise ValueError("a wheel's horizontal orbit needs alpha (deg)")
    th_d, al_d, kick_al, kick_th, ph_d = _flat(theta_deg, alpha_deg, perturb_deg, perturb_theta_deg, phi_deg)
    d_al, d_th = np.deg2rad(kick_al), np.deg2rad(kick_th)
    if not np.all(np.isfinite(al_d)):
        raise ValueError("alpha must be finite")
    n = th_d.size
    th, al, ph = np.deg2rad(th_d), np.deg2rad(al_d), np.deg2rad(ph_d)
    orb = wheel.horizontal_orbit(th, al, a, r, k, g, outside=outside)
    status, reason = start_status(orb)
    ok = status == RunStatus.PENDING
    rate = np.where(ok, orb["omega"], np.nan)
    state = np.full((9, n), np.nan)
    if ok.any():
        state[:, ok] = wheel_start(th[ok], al[ok], ph[ok], rate[ok], d_th[ok], d_al[ok], a, r)
    return _Horizontal(theta=th, alpha=al, theta_deg=th_d, alpha_deg=al_d, phi=ph, rate=rate, state=state,
                       status=status, reason=reason, speed=np.where(ok, orb["v_cm"], np.nan),
                       omega3=np.full(n, np.nan),
                       kick_alpha=kick_al, kick_theta=kick_th)


def _sphere_horizontal(setup, theta_deg, omega3, omega, branch, perturb_deg, perturb_theta_deg, phi_deg,
                       outside):
    """A sphere on the orbit theta given its spin (root ``branch`` of eq. 55)
    or Omega, with eq. (55)'s statuses exactly as ``deathsphere orbit``
    decides; both kicks move the contact point down the meridian."""
    a, r, k, g = setup.a, setup.r, setup.k, setup.g
    if (omega3 is None) == (omega is None):
        raise ValueError("a sphere's horizontal orbit needs exactly one of omega3 and omega (rad/s)")
    spin = omega3 if omega is None else omega
    th_d, sp, br, kick1, kick2, ph_d = _flat(theta_deg, spin, branch, perturb_deg, perturb_theta_deg, phi_deg)
    d1, d2 = np.deg2rad(kick1), np.deg2rad(kick2)
    if not np.all(np.isfinite(sp)):
        raise ValueError("omega3 / omega must be finite")
    if not np.all(np.isin(br, (0, 1))):
        raise ValueError("branch must be 0 (slow root of eq. 55) or 1 (fast root)")
    n = th_d.size
    th, ph = np.deg2rad(th_d), np.deg2rad(ph_d)
    if omega is None:
        orb = sph.sphere_orbit(th, sp, a, r, k, g, outside, branch=br.astype(int))
    else:
        orb = sph.sphere_orbit_from_rate(th, sp, a, r, k, g, outside)
    status, reason = start_status(orb)
    ok = status == RunStatus.PENDING
    rate = np.where(ok, orb["omega"], np.nan)
    state = np.full((9, n), np.nan)
    al = np.where(outside, th + np.pi / 2, th - np.pi / 2)   # equivalent alpha (sec. 4)
    om3_all = np.full(n, np.nan)
    if ok.any():
        X0, om3 = dyn.sphere_orbit_state(th[ok], rate[ok], a, r, k, g, outside, ph[ok])
        Xk, _ = dyn.sphere_orbit_state(th[ok] + d1[ok] + d2[ok], rate[ok], a, r, k, g, outside, ph[ok])
        state[:, ok] = np.concatenate((Xk[dyn.C], Xk[dyn.E1], X0[dyn.W]))
        om3_all[ok] = om3
    bank_deg = th_d + np.where(outside, 90.0, -90.0)
    return _Horizontal(theta=th, alpha=al, theta_deg=th_d, alpha_deg=bank_deg, phi=ph, rate=rate, state=state,
                       status=status, reason=reason, speed=np.where(ok, orb["v_cm"], np.nan), omega3=om3_all,
                       kick_alpha=kick1, kick_theta=kick2)


def horizontal_starts(setup: Setup, theta_deg, alpha_deg=None, *, omega3=None, omega=None, branch=0,
                      perturb_deg=0.0, perturb_theta_deg=0.0, phi_deg=0.0, input_row=None) -> Starts:
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
    perturb_deg : [deg]  the kick off the steady orbit.  Wheel: tilt by
        ``perturb_deg`` about axis 2 (the orbit's tangent through the contact
        point), i.e. alpha -> alpha + perturb_deg, keeping the contact point
        and the angular velocity.  Sphere: moves the contact point
        ``perturb_deg`` down the meridian (theta -> theta + perturb_deg),
        keeping the angular velocity.  Rolling and contact hold exactly
        after the kick.
    perturb_theta_deg : [deg]  wheel: also move the contact point down
        the meridian by this (alpha kept); sphere: added to ``perturb_deg``
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
    _check_angles(theta_deg, perturb_deg, perturb_theta_deg)
    outside = setup.side == "outside"
    if isinstance(setup.body, Wheel):
        h = _wheel_horizontal(setup, theta_deg, alpha_deg, perturb_deg, perturb_theta_deg, phi_deg, outside)
    else:
        h = _sphere_horizontal(setup, theta_deg, omega3, omega, branch, perturb_deg, perturb_theta_deg, phi_deg,
                               outside)
    n = h.theta.size
    params = dyn.BodyParams(*(np.full(n, v, dtype=float) for v in (setup.a, setup.r, setup.k, setup.g)),
                            np.full(n, outside), np.full(n, isinstance(setup.body, Ball)))
    ok = h.status == RunStatus.PENDING
    state = h.state
    if ok.any():
        state[:, ok] = dyn.project(state[:, ok], dyn.BodyParams(*(x[ok] for x in params)))
    period = np.where(ok, 2 * np.pi / np.abs(np.where(ok, h.rate, 1.0)), np.nan)
    return Starts(
        state=state, params=params, frame=np.broadcast_to(np.eye(3), (n, 3, 3)).copy(),
        input_row=_input_rows(input_row, n), body=np.full(n, setup.body.word, dtype=object),
        side=np.full(n, setup.side, dtype=object), orbit=np.full(n, "horizontal", dtype=object),
        theta=h.theta, alpha=h.alpha, theta_deg=h.theta_deg, alpha_deg=h.alpha_deg, rate=h.rate,
        turning=np.where(ok, h.rate, 0.0), period=period,
        phi0=h.phi, speed=h.speed, omega3=h.omega3, perturb_deg=h.kick_alpha, perturb_theta_deg=h.kick_theta,
        mu=np.full(n, setup.mu), status=h.status, reason=h.reason)


#: Orbit frame of vertical orbits: x' = up (phi = 0 at the top, paper fig. 2),
#: z' = lab x (horizontal), y' = z' x x' = -lab y.
VERTICAL_FRAME = np.array([[0.0, 0.0, 1.0],
                           [0.0, -1.0, 0.0],
                           [1.0, 0.0, 0.0]])


def _vertical_period(th, v, ph, rp_s, fits, a, r, k, g, outside):
    """The run's "period" of vertical orbits [s]: the lap time (elliptic
    integral) where an inside wheel keeps contact all the way round by
    eq. (28a), else 2 pi sqrt(r'/g); NaN where the wheel does not fit."""
    # eq. (27): r' phidot0^2 at the top, from the start point
    v_top2 = v ** 2 - 2 * g * rp_s * (1 - np.cos(ph)) / (2 * k + 1)
    closes = fits & (not outside) & (v_top2 > g * rp_s)
    phidot0 = np.sqrt(np.where(closes, v_top2, g * rp_s)) / rp_s
    with np.errstate(invalid="ignore"):
        lap = vert.lap_time(th, phidot0, a, r, k, g)
    period = np.where(closes, lap, 2 * np.pi * np.sqrt(rp_s / g))
    return np.where(fits, period, np.nan)


def vertical_starts(setup: Setup, theta_deg, speed, *, phi_start_deg=0.0, perturb_deg=0.0,
                    perturb_theta_deg=0.0, input_row=None) -> Starts:
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
    perturb_deg : [deg]  tilt kick out of the orbit plane, alpha ->
        alpha + perturb_deg about axis 2 (as for :func:`horizontal_starts`)
    perturb_theta_deg : [deg]  contact point moved by this in cone angle

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
    if not isinstance(setup.body, Wheel):
        raise ValueError("vertical orbits are for a wheel (body wheel)")
    _check_angles(theta_deg, perturb_deg, perturb_theta_deg)
    th_d, v, ps_d, kick_al, kick_th = _flat(theta_deg, speed, phi_start_deg, perturb_deg, perturb_theta_deg)
    d_al, d_th = np.deg2rad(kick_al), np.deg2rad(kick_th)
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
    period = _vertical_period(th, v, ph, rp_s, fits, a, r, k, g, outside)
    status = np.where(fits, RunStatus.PENDING, RunStatus.NO_FIT).astype(np.int8)
    reason = np.where(fits, "", NO_FIT_VERTICAL_REASON).astype(object)
    state = np.full((9, n), np.nan)
    params = dyn.BodyParams(*(np.full(n, x, dtype=float) for x in (a, r, k, g)),
                            np.full(n, outside), np.zeros(n, dtype=bool))
    ok = fits
    if ok.any():
        local = wheel_start(th[ok], al[ok], ph[ok], rate[ok], d_th[ok], d_al[ok], a, r)
        lab = np.concatenate([VERTICAL_FRAME @ local[s] for s in (dyn.C, dyn.E1, dyn.W)])
        state[:, ok] = dyn.project(lab, dyn.BodyParams(*(x[ok] for x in params)))
    return Starts(
        state=state, params=params, frame=np.broadcast_to(VERTICAL_FRAME, (n, 3, 3)).copy(),
        input_row=_input_rows(input_row, n), body=np.full(n, WHEEL.word, dtype=object),
        side=np.full(n, setup.side, dtype=object), orbit=np.full(n, "vertical", dtype=object),
        theta=th, alpha=al, theta_deg=th_d, alpha_deg=np.full(n, 180.0 if outside else 0.0), rate=rate,
        turning=np.zeros(n), period=period, phi0=ph,
        speed=v, omega3=np.full(n, np.nan), perturb_deg=kick_al, perturb_theta_deg=kick_th,
        mu=np.full(n, setup.mu), status=status, reason=reason)
