"""The single-contact machine's vertical loop inside a closed surface of
revolution (a dome closed below, an egg, an ellipsoid, a sphere sampled).

Beyond the paper: docs/machine.md sec. 10 solves the machine's loop on the
globe (eqs. M21-M24, :func:`deathsphere.physics.machine.vertical_loop`);
here it runs in a meridian plane of a ground whose meridian closes at both
ends (the loop's curve, :class:`~deathsphere.physics.meridian_loop.Loop`).
Derivation: docs/machine.md sec. 10, "Inside a closed profile" (eqs.
M25-M30).

The machine stays upright in the loop's plane, its up-axis along the
curve's inward normal n(s) at the contact P(s) (arc length s from the
meridian's lowest point, dT/ds = kappa n, dn/ds = -kappa T), so one
coordinate s says where it is and energy is exact:

    G = P + h n,   v_G = (1 - h kappa) sdot,   frame rate kappa sdot,
    wheels' spin relative to the frame -sdot / a                        (M25)
    (1/2) M(s) sdot^2 + m g z_G(s) = E,
    M = m (1 - h kappa)^2 + I_pitch kappa^2 + J (1 - 2 a kappa) / a^2    (M26)
    sddot = -(m g (1 - h kappa) sin(beta) + (1/2) M' sdot^2) / M          (M27)
    N/m = (1 - h kappa) kappa sdot^2 + g cos(beta)
    F/m = (1 - h kappa) sddot - h kappa' sdot^2 + g sin(beta)             (M28)

(kappa' the central difference of kappa on the loop's grid,
:func:`curvature_slope`: a cubic spline's own jumps at every sample) and
contact all round needs N > 0 (M29: N is linear in v_top^2); the
friction needed |F|/N, the load |a_G - g|/g, the lap time and the head's
clearance (M30).  Both halves of the loop are mirror images, so every
quantity is taken on the meridian (the other half's friction changes sign).
Everything broadcasts over the requests (v_top, g, mu, max_g and the
machine's arrays); the loop's grid is the last axis and the extreme points
are refined on the curve between grid points (no Python loop over
requests).  Units: m, s, rad, kg.  A request the loop cannot hold is a
status, never a NaN leaked or a warning.
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace

import numpy as np

from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.machine_arrays import MachineArrays
from deathsphere.physics.meridian_loop import Loop, refined_max, simpson, smooth_peak, turn
from deathsphere.physics.status import Reason, Status, first_failure

__all__ = ["machine_loop_on", "head_clearance_on", "curvature_slope"]


@dataclass(frozen=True)
class _Ride:
    """The requests as columns (n, 1) against the loop's grid, with the
    top's effective inertia M_top, its frame's stretch 1 - h kappa_top and
    the centre of mass's height there."""

    v_top: np.ndarray
    g: np.ndarray
    m: np.ndarray
    h: np.ndarray
    a: np.ndarray
    ip: np.ndarray
    js: np.ndarray
    m_top: np.ndarray
    stretch_top: np.ndarray
    zg_top: np.ndarray

    def rows(self, index) -> "_Ride":
        return _Ride(*(getattr(self, f.name)[index] for f in fields(self)))


def _inertia(rd: _Ride, kappa):
    """M(s) of eq. (M26) [kg]: the centre of mass, the frame's pitch and the wheels' spin relative to it."""
    stretch = 1.0 - rd.h * kappa
    return rd.m * stretch * stretch + rd.ip * kappa * kappa + rd.js * (1.0 - 2.0 * rd.a * kappa) / (rd.a * rd.a)


def _ride(loop: Loop, v_top, g, machine: MachineArrays) -> _Ride:
    """The requests as rows, the top's values computed once."""
    cols = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in
                                 (v_top, g, machine.mass, machine.com_height, machine.wheel_radius,
                                  machine.pitch_inertia, machine.spin_inertia)))
    v_top, g, m, h, a, ip, js = (c.reshape(-1, 1) for c in cols)
    _, z_t, beta_t, kappa_t, _ = loop.ground.meridian(np.array([loop.length]))
    stretch_t = 1.0 - h * kappa_t
    rd = _Ride(np.abs(v_top), g, m, h, a, ip, js, np.ones_like(v_top), stretch_t, z_t + h * np.cos(beta_t))
    return replace(rd, m_top=_inertia(rd, kappa_t))


def _state(rd: _Ride, z, beta, kappa, dkappa) -> dict:
    """Eqs. (M25)-(M29) at points of the meridian, per request (rows) and
    point (columns): ``fits`` (M25-M26), the contact's rate squared
    ``sdot2``, the contact force per mass ``normal`` and ``along`` (+s, up
    the meridian), the ``load`` [g], and N = ``slope`` v_top^2 + ``rest``."""
    stretch = 1.0 - rd.h * kappa
    inertia = _inertia(rd, kappa)
    fits = (stretch > SINGULAR) & (1.0 - rd.a * kappa > SINGULAR) & (inertia > 0) & (rd.stretch_top > SINGULAR)
    inertia = np.where(fits, inertia, 1.0)
    top = np.where(rd.stretch_top > SINGULAR, rd.stretch_top, 1.0)
    z_g = z + rd.h * np.cos(beta)
    # (M26): M sdot^2 = M_top sdot_top^2 + 2 m g (z_G,top - z_G), sdot_top = v_top / (1 - h kappa_top)
    per_v2 = rd.m_top / (top * top * inertia)
    gained = 2.0 * rd.m * rd.g * (rd.zg_top - z_g) / inertia
    sdot2 = per_v2 * rd.v_top ** 2 + gained
    d_inertia = (-2.0 * rd.m * rd.h * stretch + 2.0 * rd.ip * kappa - 2.0 * rd.js / rd.a) * dkappa   # dM/ds
    sddot = -(rd.m * rd.g * stretch * np.sin(beta) + 0.5 * d_inertia * sdot2) / inertia             # (M27)
    normal = stretch * kappa * sdot2 + rd.g * np.cos(beta)                                           # (M28)
    along = stretch * sddot - rd.h * dkappa * sdot2 + rd.g * np.sin(beta)
    return {"fits": fits, "stretch": stretch, "sdot2": sdot2, "normal": normal, "along": along,
            "load": np.hypot(normal, along) / rd.g, "slope": stretch * kappa * per_v2,
            "rest": stretch * kappa * gained + rd.g * np.cos(beta), "beta": beta, "kappa": kappa}


def curvature_slope(loop: Loop) -> np.ndarray:
    """kappa' [1/m^2] on the loop's grid as M27-M28 take it (beyond the
    paper: docs/machine.md, "Inside a closed profile"): the central
    difference of the curvature over the grid's step, the mirror through
    the axis continuing it past either end (kappa' = 0 there).  A cubic
    spline's own kappa' jumps at every sample (its third derivative is
    piecewise constant: on a sphere sampled at 2001 points by 8e-4 / r^2,
    a sawtooth the grid aliases); the difference is its mean over two grid
    steps, which keeps the curvature's change on every longer scale."""
    k = loop.kappa
    step = loop.s[1] - loop.s[0]
    mirrored = np.concatenate(([k[1]], k, [k[-2]]))
    return (mirrored[2:] - mirrored[:-2]) / (2.0 * step)


def _at(loop: Loop, rd: _Ride, s, slope) -> dict:
    """:func:`_state` at arc lengths s (n, m) off the grid, kappa' interpolated from ``slope`` on the grid."""
    s = np.asarray(s, dtype=float)
    _, z, beta, kappa, _ = loop.ground.meridian(s)
    return _state(rd, z, beta, kappa, np.interp(s, loop.s, slope))


def _top_speed_bound(st: dict):
    """The least v_top^2 for N > 0 at a point (M29): v_top^2 > -rest / slope
    where slope > 0 (the wall bends towards the centre); elsewhere speed
    does not help: an overhang (rest < 0) holds the machine at no speed
    (+inf), a floor gives no bound (-inf)."""
    bends = st["slope"] > 0
    flat = np.where(st["rest"] < 0, np.inf, -np.inf)
    return np.where(bends, -st["rest"] / np.where(bends, st["slope"], 1.0), flat)


def _descent(loop: Loop, s):
    """The loop's angle phi [rad] from the top of the point at arc length s on
    the descent, 0..pi (the top's wall angle is pi only to round-off)."""
    return np.clip(turn(loop.ground.meridian(np.asarray(s, dtype=float))[2]), 0.0, np.pi)


#: A bound of M29 without limit (+-inf) as a number golden section can compare.
_HUGE = np.finfo(float).max / 4


def _finite(bound):
    """M29's bound with +-inf clipped to +-:data:`_HUGE`."""
    return np.clip(bound, -_HUGE, _HUGE)


def _worst(st: dict):
    """mu = |F| / N where N > 0, else 0 (a point without contact is its own status)."""
    held = st["normal"] > 0
    return np.where(held, np.abs(st["along"]) / np.where(held, st["normal"], 1.0), 0.0)


#: Newton's steps on the foot of a point on the meridian (from the grid's nearest point: quadratic, 2-3 suffice).
_FOOT_STEPS = 5


def _distance_inside(loop: Loop, q_rho, q_z):
    """Points' (rho, z) distance [m] inside the loop's meridian, (q - P) . n
    at the foot P(s) where (P - q) . T = 0: the grid's nearest point, then
    Newton's steps on the arc length (d/ds (P - q) . T = 1 + kappa (P - q) . n).
    Brute force over the grid, not a search tree: a head near a sphere's
    centre is nearly equidistant from every point, a tree's worst case."""
    rho, z = loop.ground.meridian(loop.s)[:2]
    d2 = (q_rho[..., None] - rho) ** 2 + (q_z[..., None] - z) ** 2
    s = loop.s[np.argmin(d2, axis=-1)]
    for _ in range(_FOOT_STEPS):
        p_rho, p_z, beta, kappa, _ = loop.ground.meridian(s)
        d_rho, d_z = p_rho - q_rho, p_z - q_z
        along = d_rho * np.cos(beta) + d_z * np.sin(beta)
        slope = 1.0 + kappa * (-d_rho * np.sin(beta) + d_z * np.cos(beta))
        s = np.clip(s - np.where(slope > SINGULAR, along / np.where(slope > SINGULAR, slope, 1.0), 0.0),
                    0.0, loop.length)
    p_rho, p_z, beta, _, _ = loop.ground.meridian(s)
    return -(q_rho - p_rho) * np.sin(beta) + (q_z - p_z) * np.cos(beta)


def head_clearance_on(loop: Loop, head) -> tuple:
    """The least distance [m] inside the loop's curve of the rider's head
    round the loop (M30; beyond the paper): the head at ``head`` [m] along
    the inward normal n from the contact, H = P + head n in the loop's
    plane (past the axis, the mirror of a point of the meridian's side).
    Per value of ``head`` (any shape): (least clearance, the loop's angle
    phi [rad] from the top where it is least)."""
    head = np.asarray(head, dtype=float)
    values, where = np.unique(head.reshape(-1), return_inverse=True)     # one machine: one row of the grid

    rho, z, beta, _, _ = loop.ground.meridian(loop.s)
    q_rho = np.abs(rho[None, :] - values[:, None] * np.sin(beta)[None, :])     # past the axis: the mirror half
    q_z = z[None, :] + values[:, None] * np.cos(beta)[None, :]
    grid = _distance_inside(loop, q_rho, q_z)
    # the least between the grid's points: the parabola through the grid's least and its neighbours
    i = np.argmin(grid, axis=1)
    rows = np.arange(values.size)
    lo, hi = np.maximum(i - 1, 0), np.minimum(i + 1, loop.s.size - 1)
    inner = (i > 0) & (i < loop.s.size - 1)
    f0, fm, fp = grid[rows, i], grid[rows, lo], grid[rows, hi]
    curve = fm - 2.0 * f0 + fp
    bowl = inner & (curve > 0)
    shift = np.where(bowl, 0.5 * (fm - fp) / np.where(bowl, curve, 1.0), 0.0)
    least = f0 - 0.25 * (fm - fp) * shift
    s = loop.s[i] + shift * (loop.s[1] - loop.s[0])
    phi = _descent(loop, s)
    return least[where].reshape(head.shape), phi[where].reshape(head.shape)


def machine_loop_on(loop: Loop, v_top, g, machine: MachineArrays, mu=np.inf, max_g=np.inf) -> dict:
    """Everything about the machine's vertical loop inside ``loop`` per
    request, vectorised over the requests (``v_top`` [m/s] the centre of
    mass's speed at the top, ``g`` [m/s^2], ``machine`` its arrays, ``mu``
    the friction available, ``max_g`` the largest load allowed, broadcast
    to one shape); beyond the paper, eqs. (M25)-(M30) of docs/machine.md.

    Returns the keys of :func:`deathsphere.physics.machine.vertical_loop`
    with the same meanings (on a circle the same values): ``r_g`` the centre
    of mass's path's radius of curvature at the top ((1 - h kappa) / kappa),
    ``v_top_min`` (the largest bound of M29 round the loop), ``v_bottom``,
    ``omega_top`` / ``omega_bottom`` (the frame's rate kappa sdot),
    ``load_top``, ``load_bottom``, ``head_clearance`` (the least round the
    loop), ``mu_required`` (the most round the loop) and ``phi_worst``
    (where, from the top), ``status``, ``reason``; and ``period`` the lap
    time [s] (Simpson on the loop's grid), ``load_max`` the largest load
    round the loop [g] and ``phi_load_max`` where [rad].
    """
    v_top, g, mu, max_g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (v_top, g, mu, max_g)))
    shape = np.broadcast_shapes(v_top.shape, *(np.shape(x) for x in machine))
    v_top, g, mu, max_g = (np.broadcast_to(x, shape).reshape(-1) for x in (v_top, g, mu, max_g))
    arrays = machine.map(lambda x: np.broadcast_to(np.asarray(x, dtype=float), shape).reshape(-1))
    rd = _ride(loop, v_top, g, arrays)
    _, z, beta, kappa, _ = loop.ground.meridian(loop.s)
    slope = curvature_slope(loop)
    grid = _state(rd, z[None, :], beta[None, :], kappa[None, :], slope[None, :])
    # the grid's fit, and the tightest bend's between grid points (M25)
    fits = np.all(grid["fits"], axis=1) & (rd.a[:, 0] * loop.kappa_max < 1.0 - SINGULAR) & (
        rd.h[:, 0] * loop.kappa_max < 1.0 - SINGULAR)
    live = fits[:, None]

    def refine(values, quantity):
        return refined_max(loop, np.where(live, values, 0.0),
                           lambda rows, s: quantity(_at(loop, rd.rows(rows), s, slope)))

    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # the least top speed: the largest bound round the loop (the top's on a circle, g r_G)
        _, bound = refine(_finite(_top_speed_bound(grid)), lambda st: _finite(_top_speed_bound(st)))
        bound = np.where(bound >= _HUGE, np.inf, bound)
        # contact: N > 0 at its least round the loop (refined: the least need not be a grid point)
        _, least_neg = refine(-grid["normal"], lambda st: -st["normal"])
    contact = fits & (-least_neg > 0) & (np.min(grid["sdot2"], axis=1) > 0)
    held = contact[:, None]
    need = np.where(held, _worst(grid), 0.0)

    def need_at(rows, s):
        return _worst(_at(loop, rd.rows(rows), s, slope))

    # the most friction needed: the largest on the curve; where: the least-squares peak (a flat maximum's
    # argument moves by far more than its value with the curvature's ripple)
    _, mu_max = refined_max(loop, need, need_at)
    s_w = smooth_peak(loop, need, need_at)
    s_l, load_max = refined_max(loop, np.where(held, grid["load"], 0.0),
                                lambda rows, s: _at(loop, rd.rows(rows), s, slope)["load"])
    clearance, _ = head_clearance_on(loop, arrays.head_height)
    speed = np.sqrt(np.where(held, grid["sdot2"], 1.0))
    period = np.where(contact & (v_top > 0), 2.0 * simpson(1.0 / speed, loop.s[1] - loop.s[0]), np.nan)
    top = {key: val[:, -1] for key, val in grid.items()}
    bottom = {key: val[:, 0] for key, val in grid.items()}
    v_min = np.where(fits, np.sqrt(np.where(np.isfinite(bound), np.maximum(bound, 0.0), 0.0)), np.nan)
    v_min = np.where(fits & np.isinf(bound), np.inf, v_min)
    status, reason = first_failure([
        (~fits, Status.NO_FIT, Reason.MACHINE_LOOP_NO_FIT),
        (~(clearance > 0), Status.NO_FIT, Reason.MACHINE_LOOP_HEAD_HITS),
        (~contact & np.isinf(bound), Status.NO_CONTACT, Reason.MACHINE_LOOP_OVERHANG),
        # fast enough for every point that bends towards the centre: it leaves where the wall bends away
        (~contact & (v_top ** 2 > bound), Status.NO_CONTACT, Reason.MACHINE_LOOP_TOO_FAST),
        (~contact, Status.NO_CONTACT, Reason.MACHINE_LOOP_TOO_SLOW),
        (np.where(contact, mu_max, 0.0) > mu, Status.SLIPS, Reason.MACHINE_LOOP_SLIPS),
        (np.where(contact, load_max, 0.0) > max_g, Status.OVER_G, Reason.MACHINE_LOOP_OVER_G),
    ])
    nan = np.nan
    kappa_top, kappa_bottom = kappa[-1], kappa[0]
    sdot_b = np.sqrt(np.where(fits, np.maximum(bottom["sdot2"], 0.0), 0.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        r_g = np.where(fits & (kappa_top > 0), rd.stretch_top[:, 0] / kappa_top, nan)
    sdot_t = v_top / np.where(fits, rd.stretch_top[:, 0], 1.0)
    out = {
        "r_g": r_g,
        "v_top_min": v_min,
        "v_bottom": np.where(fits, bottom["stretch"] * sdot_b, nan),
        "omega_top": np.where(fits, kappa_top * sdot_t, nan),
        "omega_bottom": np.where(fits, kappa_bottom * sdot_b, nan),
        "load_top": np.where(fits, np.abs(top["normal"]) / g, nan),
        "load_bottom": np.where(fits, bottom["load"], nan),
        "head_clearance": clearance,
        "mu_required": np.where(contact, mu_max, nan),
        "phi_worst": np.where(contact, _descent(loop, s_w), nan),
        "status": status,
        "reason": reason,
        "period": period,
        "load_max": np.where(contact, load_max, nan),
        "phi_load_max": np.where(contact, _descent(loop, s_l), nan),
    }
    return {key: val.reshape(shape) for key, val in out.items()}
