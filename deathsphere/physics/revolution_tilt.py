"""The wheel's tilt for a given rate or speed on any surface of revolution.

Beyond the paper: McDonald (1993) solves eq. (29) for the rate at a given
tilt on the sphere; :func:`deathsphere.physics.region.solve_alpha` inverts
it there.  Off the globe the torque balance is the same equation with the
contact's distance from the axis rho_P in place of r sin(theta)
(docs/surfaces.md S1, S2), so the tilts giving a rate Omega are the zeros of

    f(alpha) = g cos(alpha) - Omega^2 sin(alpha) D,
    D = (2k+1) r' + k a cos(alpha) = (2k+1) rho_P - (k+1) a cos(alpha),

a trigonometric polynomial of degree 2 in alpha, and those giving the
centre's speed v_cm = |r'| Omega the zeros of g r'^2 cos(alpha) - v^2
sin(alpha) D (degree 3), r' = rho_P - a cos(alpha).  The contact's speed v
along the ground fixes the rate Omega = v / rho_P (the contact runs round
the parallel of radius rho_P), and a period T the rate 2 pi / T.

Every zero is found as on the globe (:mod:`deathsphere.physics.trig_roots`:
companion-matrix eigenvalues, then bisection on sign changes), in the
window where the rim fits along the lane (S4): inside
asin(a kappa_parallel) - beta < alpha < pi - asin(a kappa_parallel) - beta,
outside pi - beta < alpha < 2 pi - beta (on the sphere, beta = pi - theta,
eqs. 0 and 81 exactly).  Each root is a row, with every quantity of
:func:`deathsphere.physics.revolution.wheel_orbit` at it (its status says
whether the wheel clears the floor, presses on the wall, holds by friction);
a root the forward model does not give back to
:data:`~deathsphere.physics.region.ROOT_MATCH_RTOL` is dropped, as on the
globe.  A request with no root says why (``unsolved_status``,
``unsolved_reason``): the lane is off the wall, the rim fits at no tilt
there (a kappa_parallel >= 1), the contact is on the axis (a contact speed
moves no orbit there), or S2 has no root in the fit window.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.region import ROOT_MATCH_RTOL
from deathsphere.physics.revolution import lane, wheel_orbit
from deathsphere.physics.status import Reason, Status
from deathsphere.physics.trig_roots import roots_in

__all__ = ["wheel_tilts", "fit_window", "tilt_polynomial"]

# cos(alpha) and sin(alpha) as coefficient rows of exp(i j alpha), j = -1, 0, 1
_COS = np.array([0.5, 0.0, 0.5], dtype=complex)
_SIN = np.array([0.5j, 0.0, -0.5j], dtype=complex)


def _times(p, q):
    """Product of trigonometric polynomials given as coefficient rows
    (n, 2N+1) and (n or 1, 2M+1): a row-wise convolution (a loop over the
    few harmonics of q, not over orbits)."""
    p, q = np.atleast_2d(p), np.atleast_2d(q)
    n = max(p.shape[0], q.shape[0])
    out = np.zeros((n, p.shape[1] + q.shape[1] - 1), dtype=complex)
    for j in range(q.shape[1]):
        out[:, j:j + p.shape[1]] += p * q[:, j:j + 1]
    return out


def _plus(p, q):
    """Sum of coefficient rows of possibly different degrees (centred)."""
    p, q = np.atleast_2d(p), np.atleast_2d(q)
    if p.shape[1] < q.shape[1]:
        p, q = q, p
    pad = (p.shape[1] - q.shape[1]) // 2
    return p + np.pad(q, ((0, 0), (pad, pad)))


def tilt_polynomial(rho, a, k, g, omega=None, com_speed=None):
    """Coefficient rows (n, 2N+1) of exp(i j alpha), j = -N..N, whose zeros
    are the tilts of S2 (docs/surfaces.md) giving the rate ``omega`` (N = 2)
    or the centre's speed ``com_speed`` (N = 3) on lanes of radius ``rho``;
    1-D arrays of one length (give exactly one target)."""
    rho, a, k, g = (np.asarray(x, dtype=float)[:, None] for x in (rho, a, k, g))
    ones = np.ones_like(rho)
    cos, sin = ones * _COS, ones * _SIN
    D = _plus((2 * k + 1) * rho * np.array([[0, 1, 0]]), -(k + 1) * a * cos)        # (2k+1) r' + k a C
    SD = _times(sin, D)
    if com_speed is None:
        w = np.asarray(omega, dtype=float)[:, None]
        return _plus(g * cos, -(w * w) * SD)
    v = np.asarray(com_speed, dtype=float)[:, None]
    rp = _plus(rho * np.array([[0, 1, 0]]), -a * cos)                                # S1
    return _plus(g * _times(_times(rp, rp), cos), -(v * v) * SD)


def fit_window(where, a, outside):
    """(lo, hi, empty): the tilts at which the rim fits along the lane, S4
    (docs/surfaces.md): inside a kappa_parallel < sin(alpha + beta), outside
    sin(alpha + beta) < 0; ``empty`` where no tilt fits (inside, a
    kappa_parallel >= 1)."""
    beta = np.arctan2(where["sin_beta"], where["cos_beta"])
    bend = a * where["kappa_parallel"]
    empty = ~outside & (bend >= 1)
    e = np.arcsin(np.clip(bend, -1.0, 1.0))
    lo = np.where(outside, np.pi - beta, e - beta)
    hi = np.where(outside, 2 * np.pi - beta, np.pi - e - beta)
    return lo, hi, empty


def wheel_tilts(ground, height, a, k, g, *, omega=None, speed=None, com_speed=None, period=None,
                outside=False, mu=np.inf):
    """Every tilt alpha at which the wheel on ``ground`` orbits at the rate
    ``omega`` [rad/s], the contact's speed ``speed`` [m/s] (Omega = v /
    rho_P), the centre's speed ``com_speed`` [m/s] (v_cm = |r'| Omega) or
    the period ``period`` [s] (Omega = 2 pi / T); give exactly one
    (docs/surfaces.md S2, "The wheel given its rate").  Beyond the paper:
    eq. (29) solved for alpha on any ground, as
    :func:`deathsphere.physics.region.solve_alpha` on the globe.

    height : [m] the lane (the turn radius on flat ground); a [m], k [-],
    g [m/s^2], outside, mu broadcast with it and the target.

    Returns a dict: ``alpha`` (shape + (m,), rad, increasing, NaN-padded),
    ``count`` (shape), the keys of
    :func:`~deathsphere.physics.revolution.wheel_orbit` at each root
    (padding NaN, status ``invalid``), and ``unsolved_status``,
    ``unsolved_reason`` (shape): a request's status and reason when it has
    no root (``ok`` and none where it has one); ``lane``: the lane's
    ``height``, ``rho_contact``, ``z_contact``, ``wall_angle`` (shape; NaN
    off the wall).
    """
    given = [(name, value) for name, value in (("omega", omega), ("speed", speed), ("com_speed", com_speed),
                                               ("period", period)) if value is not None]
    if len(given) != 1:
        raise ValueError("give exactly one of omega, speed, com_speed and period")
    kind, target = given[0]
    arrays = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (height, target, a, k, g, mu)),
                                 np.asarray(outside, dtype=bool))
    shape = arrays[0].shape
    height, target, a, k, g, mu, outside = (x.reshape(-1) for x in arrays)
    where = lane(ground, height)
    with np.errstate(invalid="ignore"):
        usable = np.isfinite(target) & (target > 0)
    on_axis = np.zeros(height.shape, dtype=bool)
    safe = np.where(usable, target, 1.0)
    if kind == "speed":
        on_axis = where["rho"] <= 0
        rate = safe / np.where(on_axis, 1.0, where["rho"])
    elif kind == "period":
        rate = 2 * np.pi / safe
    else:
        rate = safe
    lo, hi, empty = fit_window(where, a, outside)
    solvable = usable & ~where["off_wall"] & ~empty & ~on_axis
    if kind == "com_speed":
        h = tilt_polynomial(where["rho"], a, k, g, com_speed=rate)
    else:
        h = tilt_polynomial(where["rho"], a, k, g, omega=rate)
    h = np.where(solvable[:, None], h, 0.0)           # a zero row has no candidate roots
    roots = roots_in(h, np.where(solvable, lo, 0.0), np.where(solvable, hi, 0.0))
    if roots.shape[1] == 0:
        roots = np.full((height.size, 1), np.nan)
    found = np.isfinite(roots)
    orbit = wheel_orbit(ground, height[:, None], np.where(found, roots, 0.0), a[:, None], k[:, None], g[:, None],
                        outside=outside[:, None], mu=mu[:, None])
    got = orbit["v_cm"] if kind == "com_speed" else orbit["omega"]
    want = (safe if kind == "com_speed" else rate)[:, None]
    with np.errstate(invalid="ignore"):
        found &= np.abs(got - want) <= ROOT_MATCH_RTOL * want
    order = np.argsort(~found, axis=1, kind="stable")          # kept roots first, still increasing
    found = np.take_along_axis(found, order, axis=1)
    roots = np.where(found, np.take_along_axis(roots, order, axis=1), np.nan)
    m = roots.shape[1]
    out = {"alpha": roots.reshape(shape + (m,)), "count": np.sum(found, axis=1).reshape(shape)}
    for key, value in orbit.items():
        value = np.take_along_axis(np.broadcast_to(value, roots.shape), order, axis=1)
        if key in ("status", "reason"):
            value = np.where(found, value, Status.INVALID if key == "status" else Reason.NONE).astype(np.int8)
        else:
            value = np.where(found, value, np.nan)
        out[key] = value.reshape(shape + (m,))
    status = np.where(where["off_wall"] | empty, Status.NO_FIT, Status.NO_ORBIT)
    reason = np.select([where["off_wall"], on_axis, empty], [Reason.LANE_OFF_WALL, Reason.LANE_ON_AXIS,
                                                             Reason.NO_TILT_FITS_LANE],
                       Reason.SURFACE_NO_ALPHA)
    solved = out["count"].reshape(-1) > 0
    out["unsolved_status"] = np.where(solved, Status.OK, status).astype(np.int8).reshape(shape)
    out["unsolved_reason"] = np.where(solved, Reason.NONE, reason).astype(np.int8).reshape(shape)
    # the lane itself, whether or not a tilt rides it (none off the wall)
    off = where["off_wall"]
    out["lane"] = {"height": height.reshape(shape),
                   **{name: np.where(off, np.nan, where[key]).reshape(shape)
                      for name, key in (("rho_contact", "rho"), ("z_contact", "z"), ("wall_angle", "wall_angle"))}}
    return out
