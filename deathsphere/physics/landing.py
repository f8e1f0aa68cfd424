"""Where a centre of mass flying freely meets any arena: the wall or the
floor (beyond the paper; docs/show.md sec. 6 and 11, "A fall on a wall").

The globe's flight ends on the sphere, a quartic in time solved in closed
form (:func:`deathsphere.physics.fall.ballistic_landing`).  On any other
ground the flight ends where the ground protocol says the point has left
the inside: its ``clearance(rho, z)`` (the distance from the wall, positive
inside) reaches zero, or its height above the floor ``z - lowest`` does.
Between the two the gap

    q(t) = min(clearance(rho(t), z(t)), z(t) - lowest),
    x(t) = x0 + v0 t - g t^2/2 z-hat

is what this module follows; nothing here names a surface.

Why a scan and a bisection find the one landing: on the drum q is concave
in t.  z(t) - lowest is a concave parabola; rho(t) = |(x0 + v0 t)_horizontal|
is the norm of an affine function of t, convex, so radius - rho(t) is
concave; the least of concave functions is concave.  On a cone leaning out
(wall angle beta <= 90 deg) the clearance (radius - rho) sin(beta) +
z cos(beta) is concave for the same reasons (sin, cos >= 0).  A concave q
with q(0) >= 0 is >= 0 on one interval from t = 0 and negative after, so
the first scanned instant with q <= 0 brackets the only crossing.  On a
cone leaning in or a profile q need not be concave: a graze between two
scanned instants (shorter than T / :data:`SCAN`) is found by q's
Lipschitz bound, |dq/dt| <= the point's greatest speed
(:mod:`deathsphere.physics.first_touch`), which on a concave q finds
nothing the scan had not.

Vectorised over a trailing batch axis n: positions and velocities (3, n),
g broadcast to (n,); the scan is (3, n, SCAN), the bisection steps each
over every flight; nothing loops over flights.
"""

from __future__ import annotations

import numpy as np

__all__ = ["landing_on", "SCAN"]

#: Instants of the scan of each flight (the bisection then finds the crossing to the last bit).
SCAN = 64
#: A start within this (relative to the start's distance from the axis plus 1 m) of the wall or
#: the floor is on it; beyond it outside, the flight is not flown (STARTS_OUTSIDE).
ON_SURFACE = 1e-9
_BISECTIONS = 64
_Z = np.array([0.0, 0.0, 1.0])


def _gap(ground, x):
    """q of the module docstring at points x (3, ...) [m]; and which bounds it: True where the floor does."""
    wall = np.asarray(ground.clearance(np.hypot(x[0], x[1]), x[2]), dtype=float)
    floor = x[2] - ground.lowest
    return np.minimum(wall, floor), floor <= wall


def _at(x0, v0, g, t):
    """The centre of mass (3, n, ...) at the times t (n, ...) after the start."""
    extra = (1,) * (np.ndim(t) - 1)
    x0, v0 = x0.reshape(x0.shape + extra), v0.reshape(v0.shape + extra)
    return x0 + v0 * t - 0.5 * g.reshape(g.shape + extra) * t * t * _Z.reshape((3, 1) + extra)


def landing_on(x0, v0, ground, g):
    """Where and when a centre of mass flying freely from ``x0`` with
    velocity ``v0`` first meets ``ground``'s wall or its floor (beyond the
    paper; the module docstring, docs/show.md sec. 11).

    x0, v0 : (3, n) [m], [m/s] in the ground's frame (z up, the floor at
    z = ``ground.lowest``); ``ground`` any ground of the protocol
    (:mod:`deathsphere.physics.ground.protocol`: its ``clearance`` and
    ``lowest``, its ``gradient`` for the wall's normal); g [m/s^2] > 0,
    broadcast to (n,).

    The flight lasts at most T, the time its height takes to reach the
    floor (T = (v_z + sqrt(v_z^2 + 2 g (z0 - lowest))) / g, where q <= 0
    for certain); :data:`SCAN` instants of [0, T] bracket the first with
    q <= 0 and bisection finds it.  A start on the wall or the floor moving
    inward flies (the scan starts after t = 0); moving outward it lands at
    once (t ~ 0).

    Returns dict: ``t_land`` (n,) [s], ``x_land`` (3, n) [m], ``v_land``
    (3, n) [m/s], ``impact_speed`` (n,) [m/s], ``impact_normal`` (n,) [m/s]
    (the velocity's component along the outward normal of what it meets:
    -v_z on the floor, along the ground's gradient on the wall),
    ``on_floor`` (n,) bool, int8 ``status`` (the codes of
    :mod:`deathsphere.physics.fall`: LANDS; STARTS_OUTSIDE where the start
    is outside the wall or below the floor; NOT_FLOWN where an input is
    not finite or g not positive: then NaN and on_floor False).
    """
    from deathsphere.physics.fall import LANDS, NOT_FLOWN, STARTS_OUTSIDE
    from deathsphere.physics.first_touch import first_crossing

    x0 = np.asarray(x0, dtype=float)
    v0 = np.asarray(v0, dtype=float)
    x0, v0 = np.broadcast_arrays(x0.reshape(3, -1), v0.reshape(3, -1))
    n = x0.shape[1]
    g = np.broadcast_to(np.asarray(g, dtype=float), (n,))
    bad = ~(np.isfinite(x0).all(axis=0) & np.isfinite(v0).all(axis=0) & (g > 0) & np.isfinite(g))
    x0, v0 = np.where(bad, 0.0, x0), np.where(bad, 0.0, v0)
    g = np.where(bad, 1.0, g)
    bad = bad | ~np.isfinite(_gap(ground, x0[:, :, None])[0][:, 0])     # a start the ground cannot place
    x0 = np.where(bad, 0.0, x0)
    q0, _ = _gap(ground, x0)
    tol = ON_SURFACE * (np.hypot(x0[0], x0[1]) + np.abs(x0[2]) + 1.0)
    outside = ~bad & (q0 < -tol)
    depth = np.maximum(x0[2] - ground.lowest, 0.0)
    t_max = (v0[2] + np.sqrt(v0[2] * v0[2] + 2.0 * g * depth)) / g
    t_max = np.where(t_max > 0, t_max, 0.0) * (1.0 + 1e-12) + 1e-300
    frac = np.linspace(0.0, 1.0, SCAN + 1)[1:]
    ts = t_max[:, None] * frac                                         # (n, SCAN)
    q, _ = _gap(ground, _at(x0, v0, g, ts))
    below = q <= 0.0
    below[:, -1] = True                                                # by T he is on the floor
    first = np.argmax(below, axis=1)
    # a graze between scanned instants, where q is not concave, found by its Lipschitz bound (first_touch.py)
    fastest = np.maximum(np.sqrt(np.sum(v0 * v0, axis=0)),
                         np.sqrt(v0[0] ** 2 + v0[1] ** 2 + (v0[2] - g * t_max) ** 2)) * (1.0 + 1e-9)
    lo, hi = first_crossing(lambda rows, t: _gap(ground, _at(x0[:, rows], v0[:, rows], g[rows], t))[0],
                            ts, q, first, np.where(~bad & (q0 > tol), q0, -1.0), fastest)
    for _ in range(_BISECTIONS):                                       # bisection steps, each over every flight
        mid = 0.5 * (lo + hi)
        inside = _gap(ground, _at(x0, v0, g, mid))[0] > 0.0
        lo = np.where(inside, mid, lo)
        hi = np.where(inside, hi, mid)
    t = hi
    x_land = _at(x0, v0, g, t)
    v_land = v0 - g * t * _Z[:, None]
    _, on_floor = _gap(ground, x_land)
    # the bisection's end is a rounding past the floor: a landing on it is on it
    x_land[2] = np.where(on_floor, ground.lowest, x_land[2])
    grad = np.asarray(ground.gradient(x_land[0], x_land[1], x_land[2]), dtype=float)
    size = np.sqrt(np.sum(grad * grad, axis=0))
    wall_normal = np.sum(grad * v_land, axis=0) / np.where(size > 0, size, 1.0)
    normal = np.where(on_floor, -v_land[2], wall_normal)
    speed = np.sqrt(np.sum(v_land * v_land, axis=0))
    gone = bad | outside
    nan = np.full(n, np.nan)
    status = np.where(bad, NOT_FLOWN, np.where(outside, STARTS_OUTSIDE, LANDS)).astype(np.int8)
    return {"t_land": np.where(gone, nan, t), "x_land": np.where(gone, np.nan, x_land),
            "v_land": np.where(gone, np.nan, v_land), "impact_speed": np.where(gone, nan, speed),
            "impact_normal": np.where(gone, nan, normal), "on_floor": on_floor & ~gone, "status": status}
