"""A wheel's vertical loop inside a closed surface of revolution (a dome
closed below, an egg, an ellipsoid, a sphere sampled).

Beyond the paper: McDonald (1993) sec. 2.2.1 solves the vertical loop on the
sphere only (eqs. 26-28b, :mod:`deathsphere.physics.vertical_orbit`).  Here
the loop runs in a meridian plane (the paper's theta = 90 deg: through the
axis) of a ground whose meridian meets the axis at its lowest and its
highest point; the loop's curve is that meridian and its mirror through the
axis, a closed curve.  Derivation: docs/surfaces.md, "S9-S12. A vertical
loop inside a closed profile".

The meridian is read by arc length s from its lowest point (``ground.meridian``:
rho, z, the wall angle beta and the curvature kappa = d beta / d s).  Going
round from the top down the side rho > 0, the loop's angle phi = pi - beta
(:func:`~deathsphere.physics.meridian_loop.turn`) is the turn of its tangent from the top (on a circle: the
centre's azimuth from the top, the globe's phi).  The wheel (radius a, I = 2 k m a^2 about its
axle, the paper's k) rolls in the loop's plane; its centre runs on the
curve's inner parallel at distance a, of curvature kappa_C = kappa / (1 - a
kappa) and height z_C = z + a cos(beta):

    v^2 = v_top^2 + 2 g (z_C,top - z_C) / (2k+1)                       (S9)
    N/m = v^2 kappa_C + g cos(beta)                                    (S10)
    F/m = -(2k/(2k+1)) g sin(beta)   along the path                    (S11)
    T   = 2 int_0^L (1 - a kappa) ds / v                               (S12)

Both halves of the loop are mirror images, so every quantity is taken on
the first (the descent); the friction along the path changes sign on the
second.  Everything broadcasts over the requests (v_top, a, k, g, mu of one
shape); the loop's curve is sampled once
(:class:`~deathsphere.physics.meridian_loop.Loop`), its grid the last
axis of the arrays, and the worst point, the least top speed, the largest
acceleration and the first slip are refined on the curve itself between
grid points (golden section and bisection: no Python loop over requests).
Units: m, s, rad.  A request the loop cannot hold is a status, never a NaN
leaked or a warning (:mod:`deathsphere.physics.status`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.meridian_loop import Loop, bisect_zero, refined_max, simpson, smooth_peak, turn
from deathsphere.physics.status import Reason, Status, first_failure, mu_required

__all__ = ["vertical_loop_on", "loop_points_on", "top_speed_on"]

@dataclass(frozen=True)
class _Request:
    """The requests' parameters as columns (n, 1) against the grid, and the centre's top height."""

    v_top: np.ndarray
    a: np.ndarray
    k: np.ndarray
    g: np.ndarray
    z_top: np.ndarray


def _request(loop: Loop, v_top, a, k, g) -> _Request:
    v_top, a, k, g = (np.asarray(x, dtype=float).reshape(-1, 1) for x in np.broadcast_arrays(v_top, a, k, g))
    return _Request(np.abs(v_top), a, k, g, loop.z[-1] + a * np.cos(loop.beta[-1]))


def _state(req: _Request, z, beta, kappa) -> dict:
    """Eqs. (S9)-(S11) at points of the loop's first half, per request (rows) and point (columns)."""
    a, k, g = req.a, req.k, req.g
    stretch = 1.0 - a * kappa                         # ds_C / ds: the centre's path is the inner parallel
    fits = stretch > SINGULAR
    kappa_c = kappa / np.where(fits, stretch, 1.0)
    z_c = z + a * np.cos(beta)
    v2 = req.v_top ** 2 + 2.0 * g * (req.z_top - z_c) / (2.0 * k + 1.0)
    normal = v2 * kappa_c + g * np.cos(beta)
    along = -(2.0 * k / (2.0 * k + 1.0)) * g * np.sin(beta)
    tangential = g * np.sin(beta) / (2.0 * k + 1.0)   # dv/dt on the descent
    return {"stretch": stretch, "kappa_c": kappa_c, "v2": v2, "normal": normal, "along": along,
            "accel": np.hypot(v2 * kappa_c, tangential)}


def _at(loop: Loop, req: _Request, s) -> dict:
    """:func:`_state` at arc lengths s (n, m) off the grid."""
    z, beta, kappa = loop.meridian(s)
    out = _state(req, z, beta, kappa)
    out["beta"] = beta
    return out


def _top_speed_bound(state, beta, req: _Request):
    """The least v_top^2 for N > 0 at a point: from (S10), v_top^2 >
    -g cos(beta) / kappa_C - (v^2 - v_top^2) wherever kappa_C > 0; where the
    wall does not bend towards the centre (kappa_C <= 0) speed does not
    help: an overhang there (cos(beta) < 0) holds the wheel at no speed
    (+inf), a floor gives no lower bound (-inf)."""
    rise = state["v2"] - req.v_top ** 2                          # what the wheel gains from the top down, by (S9)
    bends = state["kappa_c"] > 0
    flat = np.where(np.cos(beta) < 0, np.inf, -np.inf)
    return np.where(bends, -req.g * np.cos(beta) / np.where(bends, state["kappa_c"], 1.0) - rise, flat)


def _subset(req: _Request, rows) -> _Request:
    return _Request(*(getattr(req, name)[rows] for name in ("v_top", "a", "k", "g", "z_top")))


def _refined_max(loop: Loop, req: _Request, values: np.ndarray, quantity):
    """Per request, where ``quantity(state, beta)`` (its grid values ``values``,
    rows x grid) is largest, refined on the curve between grid points
    (:func:`~deathsphere.physics.meridian_loop.refined_max`).
    Returns (s, state there, value)."""
    def at(rows, x):
        st = _at(loop, _subset(req, rows), x)
        return quantity(st, st["beta"])

    s, _ = refined_max(loop, values, at)
    st = _at(loop, req, s[:, None])
    return s, {key: val[:, 0] for key, val in st.items()}, quantity(st, st["beta"])[:, 0]


def _peak(loop: Loop, req: _Request, values: np.ndarray, quantity) -> np.ndarray:
    """Per request, the arc length where ``values`` (rows x grid: the grid's
    values of ``quantity(state, beta)``) peaks, the ripple of the spline's
    curvature averaged out (:func:`~deathsphere.physics.meridian_loop.smooth_peak`)."""
    def at(rows, x):
        st = _at(loop, _subset(req, rows), x)
        return quantity(st, st["beta"])

    return smooth_peak(loop, values, at)


def vertical_loop_on(loop: Loop, v_top, a, k, g, mu=np.inf) -> dict:
    """Everything about a wheel's vertical loop inside ``loop`` per request,
    vectorised over the requests (v_top [m/s] the centre's speed at the top,
    a [m], k [-] (the paper's: I = 2 k m a^2), g [m/s^2], mu [-], broadcast
    to one shape); beyond the paper, eqs. (S9)-(S12) of docs/surfaces.md.

    Returns the keys of :func:`deathsphere.physics.vertical_orbit.vertical_orbit`
    with the same meanings, theta = 90 deg: ``r_prime`` the centre path's
    radius of curvature at the top, ``omega`` the top rate v_top kappa_C,top
    (the turn of its tangent per second), ``v_min`` / ``omega_min`` the
    least top speed and rate with N > 0 all round, ``period`` the lap time
    (S12, Simpson), ``accel`` the centre's largest acceleration round the
    lap, ``normal``, ``friction``, ``mu_required``, ``phi_worst`` at the worst
    point (where mu = |F|/N peaks, found where sin(beta)/N peaks so that it
    is defined for k = 0 as on the globe), ``mu_top`` (0: at the top the
    path is level), ``normal_top``, ``normal_bottom``, ``phi_leave`` (NaN:
    inside), ``phi_slip`` (where mu_required first exceeds mu going round
    from the top), ``contact``, ``status`` / ``reason`` (no_fit where a
    kappa_max >= 1, VERTICAL_LOOP_NO_FIT; no_contact where N <= 0 somewhere,
    VERTICAL_LOOP_OVERHANG where no top speed holds the wheel (the wall
    overhangs where it bends away from the centre; ``v_min`` is then inf),
    VERTICAL_LOOP_TOO_FAST where v_top is above ``v_min`` and the wheel
    leaves the wall where it bends away from the centre, else
    VERTICAL_LOOP_TOO_SLOW; slips).  Lap quantities are NaN without contact.
    """
    v_top, a, k, g, mu = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (v_top, a, k, g, mu)))
    shape = v_top.shape
    req = _request(loop, v_top, a, k, g)
    mu = mu.reshape(-1)
    grid = _state(req, loop.z[None, :], loop.beta[None, :], loop.kappa[None, :])
    fits = (req.a[:, 0] * loop.kappa_max < 1.0 - SINGULAR) & np.all(grid["stretch"] > SINGULAR, axis=1)
    beta = loop.beta[None, :]
    top, bottom = {key: val[:, -1] for key, val in grid.items()}, {key: val[:, 0] for key, val in grid.items()}
    g1 = req.g[:, 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        # the least top speed: the largest bound round the loop (the top's on a circle, g r')
        _, _, bound = _refined_max(loop, req, _top_speed_bound(grid, beta, req),
                                   lambda st, b: _top_speed_bound(st, b, req))
        # contact: N > 0 at its least round the loop (refined: the least need not be a grid point)
        _, low, _ = _refined_max(loop, req, -grid["normal"], lambda st, b: -st["normal"])
    n_least = np.minimum(low["normal"], np.min(grid["normal"], axis=1))
    contact = fits & (n_least > 0) & (np.min(grid["v2"], axis=1) > 0)
    safe = np.where(contact[:, None], grid["normal"], 1.0)
    # the worst point: mu = c g sin(beta) / N, located where sin(beta) / N peaks
    shape_w = np.where(contact[:, None], np.abs(np.sin(beta)) / safe, 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        s_w = _peak(loop, req, shape_w, lambda st, b: np.abs(np.sin(b)) / np.where(
            st["normal"] > 0, st["normal"], np.inf))
        worst = {key: val[:, 0] for key, val in _at(loop, req, s_w[:, None]).items()}
        _, peak, _ = _refined_max(loop, req, np.where(contact[:, None], grid["accel"], 0.0),
                                  lambda st, b: st["accel"])
    friction = np.abs(worst["along"])
    mu_max = np.where(contact, mu_required(np.where(contact, worst["normal"], np.nan), friction), np.nan)
    phi_worst = np.where(contact, turn(worst["beta"]), np.nan)
    # the lap time (S12): twice the half's, by Simpson's rule on the grid
    speed = np.sqrt(np.where(contact[:, None], grid["v2"], 1.0))
    period = np.where(contact & (req.v_top[:, 0] > 0),
                      2.0 * simpson(grid["stretch"] / speed, loop.s[1] - loop.s[0]), np.nan)
    phi_slip = _slip(loop, req, grid, contact, mu)
    r_prime = _top_radius(top["kappa_c"], fits)
    v_min = np.where(fits, np.sqrt(np.maximum(bound, 0.0)), np.nan)
    status, reason = first_failure([
        (~fits, Status.NO_FIT, Reason.VERTICAL_LOOP_NO_FIT),
        (~contact & np.isinf(bound), Status.NO_CONTACT, Reason.VERTICAL_LOOP_OVERHANG),
        # fast enough for every point that bends towards the centre: it leaves where the wall bends away
        (~contact & (req.v_top[:, 0] ** 2 > bound), Status.NO_CONTACT, Reason.VERTICAL_LOOP_TOO_FAST),
        (~contact, Status.NO_CONTACT, Reason.VERTICAL_LOOP_TOO_SLOW),
        (mu_max > mu, Status.SLIPS, Reason.SLIPS),
    ])
    v_bottom = np.where(contact, np.sqrt(np.where(contact, bottom["v2"], 0.0)), np.nan)
    accel = np.where(contact, peak["accel"], np.nan)
    out = {
        "r_prime": r_prime,
        "omega": np.where(fits, req.v_top[:, 0] * top["kappa_c"], np.nan),
        "omega_bottom": np.where(contact, v_bottom * bottom["kappa_c"], np.nan),
        "omega_min": np.where(fits, v_min * top["kappa_c"], np.nan),
        "period": period,
        "v_cm": np.where(fits, req.v_top[:, 0], np.nan),
        "v_bottom": v_bottom,
        "v_min": v_min,
        "spin": np.where(fits, req.v_top[:, 0] / req.a[:, 0], np.nan),
        "accel": accel,
        "accel_g": accel / g1,
        "normal": np.where(contact, worst["normal"], np.nan),
        "friction": np.where(contact, friction, np.nan),
        "mu_required": mu_max,
        "phi_worst": phi_worst,
        "mu_top": np.where(fits, 0.0, np.nan),
        "normal_top": np.where(fits, top["normal"], np.nan),
        "normal_bottom": np.where(fits, bottom["normal"], np.nan),
        "phi_leave": np.full(v_top.size, np.nan),
        "phi_slip": phi_slip,
        "contact": contact,
        "status": status,
        "reason": reason,
    }
    return {key: val.reshape(shape) for key, val in out.items()}


def _top_radius(kappa_c_top, fits):
    """The centre path's radius of curvature at the top [m] (r - a on a sphere), NaN where the wheel does not fit."""
    ok = fits & (kappa_c_top > 0)
    return np.where(ok, 1.0 / np.where(ok, kappa_c_top, 1.0), np.nan)


def _slip(loop: Loop, req: _Request, grid: dict, contact, mu):
    """phi [rad] where rolling first needs more than mu going round from the
    top (the second half mirrors the first, so the first crossing is on the
    descent), by bisection on the curve between the grid's points; NaN where
    it never slips or there is no contact."""
    need = np.where(contact[:, None], np.abs(grid["along"]) / np.where(contact[:, None], grid["normal"], 1.0), 0.0)
    over = need[:, ::-1] > mu[:, None]                            # from the top (the grid's last point) down
    slips = contact & over.any(axis=1)
    phi = np.full(mu.size, np.nan)
    rows = np.flatnonzero(slips)
    if rows.size == 0:
        return phi
    sub = _subset(req, rows)
    j = np.argmax(over[rows], axis=1)                             # the first point past mu, counted from the top
    last = loop.s.size - 1
    past = loop.length - loop.s[last - j]                         # distances from the top: mu exceeded here,
    before = loop.length - loop.s[np.minimum(last - j + 1, last)]  # not yet here (or the top itself)

    def excess(d):
        st = _at(loop, sub, (loop.length - d)[:, None])
        normal = st["normal"][:, 0]
        held = normal > 0
        return np.where(held, np.abs(st["along"][:, 0]) / np.where(held, normal, 1.0) - mu[rows], 1.0)

    d = np.where(j == 0, 0.0, bisect_zero(excess, before, past))
    phi[rows] = turn(loop.meridian(loop.length - d)[1])
    return phi


def top_speed_on(loop: Loop, phi, v, a, k, g):
    """The top speed [m/s] of the loop whose centre runs at ``v`` [m/s] at
    angle ``phi`` [rad] from the top, by (S9) (beyond the paper:
    docs/surfaces.md): v_top^2 = v^2 - 2 g (z_C,top - z_C) / (2k+1).  NaN
    where v is below a wheel's starting from rest at the top (no top speed
    gives it) or the wheel does not fit.  Arrays of one shape (phi a point
    each); a meridian that bends one way (:meth:`~deathsphere.physics.meridian_loop.Loop.arc_at`)."""
    phi, v, a, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (phi, v, a, k, g)))
    req = _request(loop, np.zeros(v.shape), a, k, g)
    st = _at(loop, req, loop.arc_at(phi.reshape(-1))[:, None])
    gained = st["v2"][:, 0]                                      # v^2 from rest at the top
    top2 = v.reshape(-1) ** 2 - gained
    # round-off in a speed read back leaves the top a hair below 0
    top2 = np.where(top2 >= -1e-9 * (v.reshape(-1) ** 2 + np.abs(gained)), np.maximum(top2, 0.0), np.nan)
    fits = req.a[:, 0] * loop.kappa_max < 1.0 - SINGULAR
    return np.where(fits, np.sqrt(np.where(np.isnan(top2), 0.0, top2)) + np.where(np.isnan(top2), np.nan, 0.0),
                    np.nan).reshape(v.shape)


def loop_points_on(loop: Loop, phi, v_top, a, k, g, mu=np.inf) -> dict:
    """The loop point by point (beyond the paper: eqs. S9-S11 of
    docs/surfaces.md) at its angles phi [rad] from the top, 0..2 pi
    (rows: requests; columns: the points; phi a 1-D grid), the keys of
    :func:`deathsphere.physics.vertical_orbit.vertical_profile` (``along``
    the friction along the path, negative on the descent; ``meridional`` 0:
    the loop lies in a meridian plane).  phi names a point only on a loop
    whose meridian turns one way (kappa > 0): the caller refuses another.
    The point at phi on the descent is where pi - beta = phi, found by
    bisection on beta(s) from the grid; the ascent mirrors it."""
    phi = np.asarray(phi, dtype=float).reshape(-1)
    s = loop.arc_at(phi)
    req = _request(loop, v_top, a, k, g)
    st = _at(loop, req, np.broadcast_to(s, (req.v_top.shape[0], s.size)))
    fits = (req.a * loop.kappa_max < 1.0 - SINGULAR)
    normal = st["normal"]
    sign = np.where(phi <= np.pi, 1.0, -1.0)
    along = sign * st["along"]
    friction = np.abs(along)
    mu_col = np.broadcast_to(np.asarray(mu, dtype=float), v_top.shape if np.ndim(v_top) else (1,)).reshape(-1, 1)
    need = mu_required(np.where(fits, normal, np.nan), friction)
    speed = np.sqrt(np.maximum(st["v2"], 0.0))
    status, reason = first_failure([
        (np.broadcast_to(~fits, normal.shape), Status.NO_FIT, Reason.VERTICAL_LOOP_NO_FIT),
        (~(normal > 0) | ~(st["v2"] >= 0), Status.NO_CONTACT, Reason.VERTICAL_LOOP_TOO_SLOW),
        (need > mu_col, Status.SLIPS, Reason.SLIPS),
    ])
    nan = np.broadcast_to(~fits, normal.shape)
    return {
        "phi": np.broadcast_to(phi, normal.shape),
        "omega": np.where(nan, np.nan, speed * st["kappa_c"]),
        "v_cm": np.where(nan, np.nan, speed),
        "accel": np.where(nan, np.nan, st["accel"]),
        "along": np.where(nan, np.nan, along),
        "radial": np.where(nan, np.nan, -normal),
        "meridional": np.where(nan, np.nan, 0.0 * normal),
        "friction": np.where(nan, np.nan, friction),
        "normal": np.where(nan, np.nan, normal),
        "mu_required": need,
        "status": status,
        "reason": reason,
    }
