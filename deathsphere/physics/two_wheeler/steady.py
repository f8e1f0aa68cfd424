"""Steady turns of the Whipple bicycle: inside a sphere, the bicycle turning
about the vertical axis through the sphere's centre at a constant rate, every
coordinate but the azimuth and the wheel angles constant; on flat ground, a
circle of given curvature (beyond the paper; docs/two-wheeler.md sec. 8).

A steady turn has heading pi/2 (the rear contact runs along its parallel,
the rider's right towards the floor; the mirror image runs the other way
with lean and steer negated) and three conditions on (lean, steer, rate):

* kinematic: the heading stays constant on the sphere (the front axle lies in
  the meridian plane of the front contact), on flat ground the heading rate
  is the curvature times the speed: ``condition(lean, steer) = 0``;
* Kane's lean row: G_lean + w^2 H_lean = 0, w the rear wheel rate: Kane's
  equations are quadratic in the speeds, and every speed of a steady turn is
  proportional to w, so each row is G(q) + w^2 H(q);
* the steer row gives the steady steer torque T = G_steer + w^2 H_steer.

The rear wheel row then holds by itself (power balance: the height, the
kinetic energy and the steer angle are constant).  So at a lane every turn
is a point of one curve lean -> (steer, w^2, T); a speed or a torque picks
isolated points on it, found by a scan in lean and refined by Newton's
method in (lean, steer).
"""

from __future__ import annotations

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics.status import Reason, Status, first_failure
from deathsphere.physics.two_wheeler import geometry, grounds, motion
from deathsphere.physics.two_wheeler.parameters import BicycleParameters

__all__ = ["LEAN_GRID", "MAX_SPEED", "POLE", "REASONS", "turn_status", "configuration", "turn_coefficients", "solve_steer",
           "lean_curve", "turns_for_speed", "turns_for_torque", "turn_state"]

#: The scan in lean (rad): 0.5 degree steps, up to 89 degrees either side.
LEAN_GRID = np.deg2rad(np.arange(-89.0, 89.0 + 1e-9, 0.5))
#: Complex step for derivatives inside Newton's method.
_STEP = 1e-30
_NEWTON = 30
#: Turns faster than this (rear contact, m/s) are not sought: where the lean
#: row's speed coefficient vanishes the torque equation has roots at
#: unbounded speeds (1e7 m/s), the limit of gyroscopic balance, not a lane.
MAX_SPEED = 100.0
_TOL = 1e-12
#: The rear wheel rate (rad/s) a steady turn's speed part H is evaluated at: far above any ridden (a few
#: hundred), so that G + w^2 H at it is dominated by w^2 H and H's rounding is its own, not gravity's.
_RATE = 1024.0


def configuration(lane, lean, steer, parameters: BicycleParameters, ground):
    """q (8, ...) of a steady turn on ``ground``: a Sphere, lane = theta
    (rear contact's polar angle from the upward vertical); a Plane, lane =
    the path's curvature (ignored here); heading pi/2, pitch from the
    holonomic constraint (beyond the paper; docs/two-wheeler.md sec. 8)."""
    return _configuration(lane, lean, steer, parameters, ground)[0]


def _configuration(lane, lean, steer, parameters, ground):
    """configuration's q and where its pitch holds (:func:`_pitch_holds`)."""
    lane, lean, steer = np.broadcast_arrays(*(np.asarray(x) for x in (lane, lean, steer)))
    dtype = np.result_type(lane, lean, steer, float)
    q = np.zeros((8,) + lane.shape, dtype=dtype)
    grounds.of(ground).place(q, lane)
    q[motion.HEADING] = np.pi / 2
    q[motion.LEAN], q[motion.STEER] = lean, steer
    # Newton's pitch can run away where no configuration exists (lean near 90
    # degrees, a vanishing wheel base): those are masked by _pitch_holds
    # (the configuration is kinematic: any gravity in the arguments gives the same)
    p = motion.parameter_values(parameters, STANDARD_GRAVITY, ground)
    with np.errstate(over="ignore", invalid="ignore"):
        q = motion.pitch(q, p, ground)
    # where it ran away, pitch 0: finite, and _pitch_holds still says no (unless pitch 0 itself holds)
    holds = _pitch_holds(q, p, ground)
    q[motion.PITCH] = np.where(holds, q[motion.PITCH], 0.0)
    if not holds.all():
        holds[~holds] = _pitch_holds(q[:, ~holds], p, ground)
    return q, holds


def _pitch_holds(q, p, ground):
    """Where Newton's pitch converged (|constraint| below 1e-10 m, pitch
    within a radian): elsewhere the configuration does not exist."""
    pitch = q[motion.PITCH].real
    finite = np.isfinite(pitch) & (np.abs(pitch) < 1.0)
    h, _ = grounds.of(ground).holonomic(np.where(finite, q.real, 0.0), p)
    return finite & (np.abs(h[0]) < 1e-10)


def _condition(lane, q, p, ground):
    """The kinematic condition per unit rear wheel rate: sphere, the heading
    rate; flat, heading rate minus curvature times forward speed."""
    u = motion.dependent_speeds(q, np.stack(np.broadcast_arrays(0.0, -1.0, 0.0 * q[0])), p, ground)
    return grounds.of(ground).heading_condition(u, lane)


def turn_coefficients(lane, lean, steer, parameters: BicycleParameters, ground, g=STANDARD_GRAVITY):
    """(condition, G, H) at (lane, lean, steer) on ``ground`` under gravity
    ``g``: Kane's reduced equations of a steady turn are G + w^2 H (rows
    lean, rear wheel, steer; no steer torque), w the rear wheel rate (beyond
    the paper; docs/two-wheeler.md sec. 8)."""
    on = grounds.of(ground)
    p = motion.parameter_values(parameters, g, ground)
    q, holds = _configuration(lane, lean, steer, parameters, ground)
    q1 = q.reshape(8, -1)
    n = q1.shape[1]
    unit = np.zeros((3, n))
    unit[1] = _RATE
    u, A = motion.full_speeds(q1, unit, p, ground)
    condition = on.heading_condition(u, np.broadcast_to(lane, np.shape(q)[1:]).ravel()) / _RATE
    # at rest the accelerations vanish (B' u = 0): G = -A^T f(q, 0), gravity alone; at the wheel rate _RATE
    # G + _RATE^2 H, whose speed part then outweighs gravity's (H is not a small difference of large numbers)
    rest = on.forcing_at_rest(q1, p, 0.0)
    M, f, B, bias = on.equations(q1, u, p, 0.0)
    dep = np.moveaxis(B, (0, 1), (-2, -1))[..., list(motion.DEPENDENT)]
    a = np.zeros((n, 8), dtype=np.result_type(u, bias))
    a[:, list(motion.DEPENDENT)] = -np.linalg.solve(dep, np.moveaxis(bias, 0, -1)[..., None])[..., 0]
    force = np.einsum("ij...,...j->...i", M, a) - np.moveaxis(f, 0, -1)
    G = -np.einsum("...ij,i...->j...", A, rest)
    H = (np.einsum("...ij,...i->j...", A, force) - G) / _RATE**2
    shape = np.shape(q)[1:]
    return tuple(np.where(holds.ravel(), x, np.nan).reshape(x.shape[:-1] + shape) for x in (condition, G, H))


def _initial_steer(lane, lean, parameters, ground):
    """The flat-ground guess: tan(steer) = w kappa cos(lean) / cos(lam),
    kappa the geodesic curvature of the lane (-cot(theta)/r on the sphere;
    at the poles the guess is a quarter turn, and Newton's step then says no)."""
    kappa = grounds.of(ground).curvature(lane)
    return np.arctan(parameters.w * kappa * np.cos(lean) / np.cos(parameters.lam))


def solve_steer(lane, lean, parameters: BicycleParameters, ground, steer=None):
    """The steer of a steady turn at each lean (the kinematic condition, by
    Newton's method, its slope by a complex step renewed every third step,
    from the flat-ground guess); NaN where it does not converge below 1e-12 rad or leaves
    |steer| < 80 degrees (beyond the paper; docs/two-wheeler.md sec. 8)."""
    lane, lean = np.broadcast_arrays(np.asarray(lane, float), np.asarray(lean, float))
    p = motion.parameter_values(parameters, STANDARD_GRAVITY, ground)       # kinematic: any gravity
    delta = _initial_steer(lane, lean, parameters, ground) if steer is None else np.array(steer, float)
    delta = np.array(np.broadcast_to(delta, lane.shape), dtype=float)
    step = np.full(lane.shape, np.inf)
    slope = np.zeros(lane.shape)
    active = np.isfinite(delta)
    for k in range(_NEWTON):
        # only the unconverged points are evaluated: the equations cost per point
        idx = np.nonzero(active)
        if idx[0].size == 0:
            break
        # a complex step (value and slope) every third iteration, real chord steps between: half the cost
        fresh = k % 3 == 0
        q, holds = _configuration(lane[idx], lean[idx], delta[idx] + (1j * _STEP if fresh else 0.0), parameters,
                                  ground)
        c = _condition(lane[idx], q, p, ground)
        if fresh:
            slope[idx] = c.imag / _STEP
        c = c.real
        ok = (np.abs(slope[idx]) > 1e-300) & np.isfinite(c) & holds
        d = np.where(ok, c / np.where(ok, slope[idx], 1.0), np.inf)
        step[idx] = d
        delta[idx] = np.where(ok, np.clip(delta[idx] - np.where(ok, d, 0.0), -1.5, 1.5), np.nan)
        active[idx] = ok & (np.abs(d) > 1e-14)
    good = np.isfinite(delta) & (np.abs(step) < 1e-12) & (np.abs(np.nan_to_num(delta)) < np.deg2rad(80.0))
    return np.where(good, delta, np.nan)


def lean_curve(lane, parameters: BicycleParameters, ground, g=STANDARD_GRAVITY, lean=LEAN_GRID):
    """Every steady turn of each lane on ``ground`` under gravity ``g`` as a
    function of lean: steer, G, H on the grid ``lean`` (lanes (n,), result
    (n, m); G and H (3, n, m)) (beyond the paper; docs/two-wheeler.md sec. 8)."""
    lane = np.asarray(lane, float).reshape(-1)
    L = np.broadcast_to(lean, (lane.size, np.size(lean)))
    X = np.broadcast_to(lane[:, None], L.shape)
    steer = solve_steer(X.ravel(), L.ravel(), parameters, ground).reshape(L.shape)
    ok = np.isfinite(steer)
    # the coefficients where the steer exists only (a quarter of the grid has no configuration)
    G, H = np.full((2, 3) + L.shape, np.nan)
    _, G[:, ok], H[:, ok] = turn_coefficients(X[ok], L[ok], steer[ok], parameters, ground, g)
    return {"lean": np.array(L), "steer": steer, "G": G, "H": H}


def _target(G, H, w2, torque, lanes=slice(None)):
    """The function whose zeros are the turns: for a speed (w2 given) the
    lean row; for a torque, G_s H_l - G_l H_s - T H_l (w2 eliminated); G, H
    taken at ``lanes`` (an index along their axis 1)."""
    if torque is None:
        return G[0][lanes] + w2 * H[0][lanes]
    return (G[2] * H[0] - G[0] * H[2])[lanes] - torque * H[0][lanes]


def _brackets(f, lean, steer, lanes):
    """Brackets of the zeros of f (n, m) sampled on the lean curve (lean,
    steer: (distinct lanes, m), row i's at ``lanes[i]``): sign changes, and
    near tangencies where a parabola through a local minimum of |f| and its
    neighbours crosses zero between samples (two zeros closer than a step).
    Returns (row, lean0, steer0) starting points, the steer interpolated
    along the curve."""
    fin = np.isfinite(f)
    sign = np.sign(f)
    change = fin[:, :-1] & fin[:, 1:] & (sign[:, :-1] != sign[:, 1:])
    rows, cols = np.nonzero(change)
    a, b = f[rows, cols], f[rows, cols + 1]
    frac = a / (a - b)
    at = lanes[rows]
    start = [lean[at, cols] + frac * (lean[at, cols + 1] - lean[at, cols])]
    start_steer = [steer[at, cols] + frac * (steer[at, cols + 1] - steer[at, cols])]
    out_rows = [rows]
    # tangencies: |f| locally smallest without a sign change (the parabola only there)
    size = np.abs(f)
    near = fin[:, 1:-1] & fin[:, :-2] & fin[:, 2:] & (sign[:, :-2] == sign[:, 1:-1]) & (sign[:, 1:-1] == sign[:, 2:])
    near &= (size[:, 1:-1] <= size[:, :-2]) & (size[:, 1:-1] <= size[:, 2:])
    r2, c2 = np.nonzero(near)
    f0, f1, f2 = f[r2, c2], f[r2, c2 + 1], f[r2, c2 + 2]
    curv = f0 - 2 * f1 + f2
    with np.errstate(invalid="ignore", divide="ignore"):
        vertex = f1 - (f2 - f0) ** 2 / (8 * curv)
        x = 0.5 * (f0 - f2) / curv
    crossing = (np.sign(vertex) != np.sign(f1)) & np.isfinite(x) & (np.abs(x) <= 1)
    r2, c2, vertex, x, curv = r2[crossing], c2[crossing], vertex[crossing], x[crossing], curv[crossing]
    at = lanes[r2]
    h = lean[at, c2 + 2] - lean[at, c2 + 1]
    for side in (-1, 1):
        # the two zeros of the parabola, either side of its vertex
        disc = np.sqrt(np.maximum(-2 * vertex / curv, 0.0))
        start.append(lean[at, c2 + 1] + (x + side * disc) * h)
        start_steer.append(steer[at, c2 + 1])
        out_rows.append(r2)
    return np.concatenate(out_rows), np.concatenate(start), np.concatenate(start_steer)


def _residual(lane, lean, steer, w2, torque, parameters, ground, g, slopes):
    """(condition, target) at (lean, steer) and, with ``slopes``, their
    Jacobian (m, 2, 2) in (lean, steer) by complex steps (both in one
    batch; else None)."""
    if not slopes:
        c, G, H = turn_coefficients(lane, lean, steer, parameters, ground, g)
        return c, _target(G, H, w2, torque), None
    m = lean.size
    c, G, H = turn_coefficients(np.concatenate([lane, lane]), np.concatenate([lean + 1j * _STEP, lean + 0j]),
                                np.concatenate([steer + 0j, steer + 1j * _STEP]), parameters, ground, g)
    both = _target(G, H, None if w2 is None else np.concatenate([w2, w2]),
                   None if torque is None else np.concatenate([torque, torque]))
    c, c_s, t, t_s = c[:m], c[m:], both[:m], both[m:]
    jacobian = np.stack([np.stack([c.imag, c_s.imag], -1), np.stack([t.imag, t_s.imag], -1)], -2) / _STEP
    return c.real, t.real, jacobian


def _refine(lane, lean, steer, w2, torque, parameters, ground, g):
    """Newton's method in (lean, steer) on (condition, target), iterating
    only the unconverged turns; once a step is below 1e-4 rad the Jacobian
    is kept (chord steps), renewed every third step; returns lean, steer,
    converged."""
    lean, steer = np.array(lean, float), np.array(steer, float)
    size = np.full(lean.shape, np.inf)
    active = np.ones(lean.shape, bool)
    jacobian = np.zeros(lean.shape + (2, 2))
    residual = np.zeros((2,) + lean.shape)
    for k in range(_NEWTON):
        idx = np.nonzero(active)[0]
        if idx.size == 0:
            break
        # complex steps cost twice the points, in complex arithmetic: a chord step is a fifth of a Newton step;
        # close to the root it converges to the same one (far from it, on a steep curve, it may not)
        fresh = (size[idx] > 1e-4) | (k % 3 == 0)
        for at, slopes in ((idx[fresh], True), (idx[~fresh], False)):
            if at.size:
                *value, J = _residual(lane[at], lean[at], steer[at], None if w2 is None else w2[at],
                                      None if torque is None else torque[at], parameters, ground, g, slopes)
                residual[:, at] = value
                if slopes:
                    jacobian[at] = J
        c, t = residual[:, idx]
        (j00, j01), (j10, j11) = np.moveaxis(jacobian[idx], (-2, -1), (0, 1))
        det = j00 * j11 - j01 * j10
        ok = np.abs(det) > 0
        det = np.where(ok, det, 1.0)
        d_lean = np.where(ok, (j11 * c - j01 * t) / det, np.nan)
        d_steer = np.where(ok, (j00 * t - j10 * c) / det, np.nan)
        moving = np.isfinite(d_lean) & np.isfinite(d_steer)
        lean[idx] -= np.clip(np.where(moving, d_lean, 0.0), -0.1, 0.1)
        steer[idx] -= np.clip(np.where(moving, d_steer, 0.0), -0.1, 0.1)
        size[idx] = np.where(moving, np.abs(d_lean) + np.abs(d_steer), np.inf)
        active[idx] = moving & (size[idx] > _TOL)
    return lean, steer, size < 1e-10


def _solve(lane, curve, lanes, w2, torque, parameters, ground, g):
    """All turns of each lane picked by a speed (w2) or a torque, (n, k)
    NaN-padded lean and steer, sorted by lean, duplicates merged; the lean
    curve is that of the distinct lanes, lane i's at ``lanes[i]``."""
    n = np.size(lane)
    # one lean curve per distinct lane serves all its speeds or torques
    f = _target(curve["G"], curve["H"], w2[:, None] if torque is None else None,
                None if torque is None else torque[:, None], lanes)
    rows, start, steer0 = _brackets(f, curve["lean"], curve["steer"], lanes)
    lane_r = np.asarray(lane, float)[rows]
    ok0 = np.isfinite(steer0) & np.isfinite(start)
    rows, start, steer0, lane_r = rows[ok0], start[ok0], steer0[ok0], lane_r[ok0]
    lean, steer, conv = _refine(lane_r, start, steer0, w2[rows] if torque is None else None,
                                None if torque is None else torque[rows], parameters, ground, g)
    _, G, H = turn_coefficients(lane_r, np.where(conv, lean, 0.0), np.where(conv, steer, 0.0), parameters, ground, g)
    with np.errstate(invalid="ignore", divide="ignore"):
        rate2 = -G[0] / H[0]
    keep = conv & np.isfinite(rate2) & (rate2 > 0) & (rate2 * parameters.rR**2 < MAX_SPEED**2)
    if torque is None:
        # the speed turn_state will recover from the lean row must be the one asked for
        keep &= np.abs(rate2 - w2[rows]) <= 1e-6 * w2[rows]
    keep &= np.abs(lean) < np.pi / 2
    rows, lean, steer = rows[keep], lean[keep], steer[keep]
    order = np.lexsort((lean, rows))
    rows, lean, steer = rows[order], lean[order], steer[order]
    dup = np.zeros(rows.size, bool)
    dup[1:] = (rows[1:] == rows[:-1]) & (np.abs(lean[1:] - lean[:-1]) < 1e-9)
    rows, lean, steer = rows[~dup], lean[~dup], steer[~dup]
    counts = np.bincount(rows, minlength=n)
    k = max(int(counts.max(initial=0)), 1)
    slot = np.arange(rows.size) - np.repeat(np.cumsum(counts) - counts, counts)
    L, S = np.full((n, k), np.nan), np.full((n, k), np.nan)
    L[rows, slot], S[rows, slot] = lean, steer
    return L, S, counts


#: Why a lane has no row: the ``reason`` codes (:class:`~deathsphere.physics.status.Reason`)
#: of :func:`turns_for_speed` and :func:`turns_for_torque`.
REASONS = {"ok": Reason.NONE, "lane": Reason.TURN_BAD_LANE, "speed": Reason.TURN_BAD_SPEED,
           "torque": Reason.TURN_BAD_TORQUE, "none": Reason.TURN_NONE}
#: Lanes closer to a pole than this (rad) are refused: the sphere's coordinates are singular there.
POLE = grounds.POLE


def _turns(lane, value, kind, parameters, ground, g, head):
    """The common body of turns_for_speed and turns_for_torque: lanes that
    cannot be computed are replaced by a harmless one and blanked after."""
    on = grounds.of(ground)
    lane, value = (np.array(x, float).reshape(-1) for x in np.broadcast_arrays(lane, value))
    good_lane = on.lane_ok(lane)
    good_value = np.isfinite(value) & ((value > 0) if kind == "speed" else True)
    good = good_lane & good_value
    lane[~good] = on.harmless_lane
    value[~good] = 1.0
    unique, inverse = np.unique(lane, return_inverse=True)
    curve = lean_curve(unique, parameters, ground, g)
    if kind == "speed":
        L, S, counts = _solve(lane, curve, inverse, (value / parameters.rR) ** 2, None, parameters, ground, g)
    else:
        L, S, counts = _solve(lane, curve, inverse, None, value, parameters, ground, g)
    L[~good], S[~good], counts[~good] = np.nan, np.nan, 0
    out = turn_state(np.broadcast_to(lane[:, None], L.shape), L, S, parameters, ground, g, head)
    reason = np.where(counts > 0, REASONS["ok"], REASONS["none"])
    reason = np.where(good_value, reason, REASONS[kind])
    reason = np.where(good_lane, reason, REASONS["lane"]).astype(np.int8)
    return out | {"count": counts, "reason": reason}


def turns_for_speed(lane, speed, parameters: BicycleParameters, ground, g=STANDARD_GRAVITY, head=(0.3, -1.7)):
    """Every steady turn of each lane (theta on a Sphere ``ground``,
    curvature on a Plane) under gravity ``g`` at the rear contact's speed ``speed`` (m/s, what a rear-wheel
    speedometer reads): (n, k) NaN-padded arrays of :func:`turn_state`, sorted
    by lean, ``count`` (n,) and ``reason`` (n,: int8 Reason codes, NONE where
    a turn was found, else why not, :data:`REASONS`) (beyond the paper;
    docs/two-wheeler.md sec. 8)."""
    return _turns(lane, speed, "speed", parameters, ground, g, head)


def turns_for_torque(lane, torque, parameters: BicycleParameters, ground, g=STANDARD_GRAVITY, head=(0.3, -1.7)):
    """Every steady turn of each lane held with the steer torque ``torque``
    (N m; 0: hands-free), as :func:`turns_for_speed` (beyond the paper;
    docs/two-wheeler.md sec. 8)."""
    return _turns(lane, torque, "torque", parameters, ground, g, head)


def turn_state(lane, lean, steer, parameters: BicycleParameters, ground, g=STANDARD_GRAVITY, head=(0.3, -1.7)):
    """Everything about the steady turn at (lane, lean, steer) on ``ground``
    under gravity ``g``, any shape,
    NaN in gives NaN out (beyond the paper; docs/two-wheeler.md sec. 8):
    ``omega`` (rad/s, about the vertical; on flat ground the heading rate),
    ``pitch``, ``steer_torque`` (N m), speeds ``v_rear``, ``v_front``,
    ``v_cm`` (m/s), per wheel ``normal_*`` and ``friction_*`` (the contact
    force per total mass, m/s^2: along the inward normal, positive when
    pushing; the tangential part's magnitude), ``mu_required_*``,
    ``load_g`` (|total contact force| / weight), ``head_clearance`` (m,
    r - |head|; on flat ground the head's height above it), ``theta_rear``, ``theta_front``
    (polar angles of the contacts from the upward vertical), ``contact``
    (1 where both normal forces push, 0 where a wheel would lift), ``q``,
    ``u``.
    """
    lane, lean, steer = np.broadcast_arrays(*(np.asarray(x, float) for x in (lane, lean, steer)))
    shape = lane.shape
    lane, lean, steer = lane.ravel(), lean.ravel(), steer.ravel()
    # only the turns given are computed: a NaN-padded table of turns is mostly padding
    given = np.nonzero(np.isfinite(lean) & np.isfinite(steer) & np.isfinite(lane))[0]
    if given.size:
        valid, out = _turn_state(lane[given], lean[given], steer[given], parameters, ground, g, head)
    else:
        # none: an upright turn gives the names and shapes
        valid, out = _turn_state(np.array([grounds.of(ground).upright_lane]), np.zeros(1), np.zeros(1),
                                 parameters, ground, g, head)
    full = {}
    for k, v in out.items():
        x = np.full(v.shape[:-1] + lane.shape, np.nan)
        x[..., given] = np.where(valid, v, np.nan)[..., :given.size]
        full[k] = x.reshape(v.shape[:-1] + shape)
    full["lean"], full["steer"] = lean.reshape(shape), steer.reshape(shape)
    return full


def _turn_state(lane0, lean0, steer0, p, ground, g, head):
    """turn_state's quantities at finite (lane, lean, steer) (m,), and
    where they are a turn (the lean row gives a positive w^2)."""
    on = grounds.of(ground)
    values = motion.parameter_values(p, g, ground)
    _, G, H = turn_coefficients(lane0, lean0, steer0, p, ground, g)
    with np.errstate(invalid="ignore", divide="ignore"):
        w2 = -G[0] / H[0]
    valid = np.isfinite(w2) & (w2 > 0)
    w2 = np.where(valid, w2, 0.0)
    torque = G[2] + w2 * H[2]
    q = configuration(lane0, lean0, steer0, p, ground)
    u_ind = np.stack([np.zeros_like(w2), -np.sqrt(w2), np.zeros_like(w2)])
    u = motion.dependent_speeds(q, u_ind, values, ground)
    _, lam = motion.accelerations(q, u, values, torque, ground)
    pts = geometry.points(q, p, ground, head)
    Y = pts["frames"]["Y"]
    v_rear = np.sqrt(w2) * p.rR
    omega, clearance, theta_front, swept = on.turn(u, pts, v_rear)
    n_rear, n_front = on.normals(pts, w2)
    bodies = ((p.mB, "rear_frame"), (p.mR, "rear_wheel"), (p.mH, "front_frame"), (p.mF, "front_wheel"))
    mass = sum(m for m, _ in bodies)
    # every point turns about the vertical axis: velocity z x swept(x), acceleration -omega swept(x)
    momentum_rate = sum(-m * omega * swept(pts[k]) for m, k in bodies)
    gravity = np.stack([np.zeros_like(w2), np.zeros_like(w2), g * mass * np.ones_like(w2)])
    total = momentum_rate - gravity                         # the contact forces on the bicycle
    front = lam[2] * Y[0] + lam[3] * Y[1] + lam[4] * Y[2]
    rear = total - front
    g_cm = sum(m * pts[k] for m, k in bodies) / mass
    out = {"omega": omega, "pitch": q[motion.PITCH], "steer_torque": torque, "v_rear": v_rear,
           "v_front": np.linalg.norm(swept(pts["Q"]), axis=0), "v_cm": np.linalg.norm(swept(g_cm), axis=0),
           "load_g": np.linalg.norm(total, axis=0) / (mass * g), "head_clearance": clearance,
           "theta_rear": on.theta_rear(q), "theta_front": theta_front,
           "rear_tangential_check": np.stack([np.sum(rear * Y[0], 0) - lam[0], np.sum(rear * Y[1], 0) - lam[1]])}
    for name, force, n in (("rear", rear, n_rear), ("front", front, n_front)):
        normal = np.sum(force * n, axis=0)
        tangential = np.linalg.norm(force - normal * n, axis=0)
        out[f"normal_{name}"] = normal / mass
        out[f"friction_{name}"] = tangential / mass
        with np.errstate(divide="ignore", invalid="ignore"):
            out[f"mu_required_{name}"] = np.where(normal > 0, tangential / np.where(normal > 0, normal, 1.0), np.inf)
    # both wheels must push on the surface for the turn to be ridden
    out["contact"] = ((out["normal_rear"] > 0) & (out["normal_front"] > 0)).astype(float)
    out["q"], out["u"] = q, u
    return valid, out


def turn_status(found, head_clearance, contact, mu_rear, mu_front, load, mu=np.inf, max_g=np.inf, why_none=None):
    """Status and reason codes (int8, :mod:`deathsphere.physics.status`) of
    steady turns, in the order every body's statuses take (docs/contract.md):
    no_orbit where no turn was ``found`` (``why_none``: the lane's reason
    code, default TURN_NONE), no_fit where the rider's head reaches the
    globe (head_clearance <= 0), no_contact where a wheel would lift
    (``contact`` false), slips where a wheel needs more friction than ``mu``
    (the reason names which), over_g where the load exceeds ``max_g``.
    Arrays broadcast; beyond the paper (docs/two-wheeler.md sec. 8)."""
    found = np.asarray(found, dtype=bool)
    why_none = Reason.TURN_NONE if why_none is None else why_none
    head_hits = found & ~(np.asarray(head_clearance) > 0)
    lifts = found & ~np.asarray(contact, dtype=bool)
    with np.errstate(invalid="ignore"):
        rear, front = np.asarray(mu_rear) > mu, np.asarray(mu_front) > mu
        over = np.asarray(load) > max_g
    return first_failure([
        (~found, Status.NO_ORBIT, why_none),
        (head_hits, Status.NO_FIT, Reason.TURN_HEAD_HITS),
        (lifts, Status.NO_CONTACT, Reason.TURN_WHEEL_LIFTS),
        (rear & front, Status.SLIPS, Reason.TURN_SLIPS_BOTH),
        (rear, Status.SLIPS, Reason.TURN_SLIPS_REAR),
        (front, Status.SLIPS, Reason.TURN_SLIPS_FRONT),
        (over, Status.OVER_G, Reason.TURN_OVER_G),
    ])

