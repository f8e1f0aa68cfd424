"""The least clearance of every pair of riders over the act (beyond the
paper; docs/show.md, "Clearance").

No minimum is missed between samples: a clearance c(t) changes no faster
than L, the greatest relative speed of the two envelopes (each point of a
rider's segment moves at most at his lane's rate times its distance from
the rotation axis: :meth:`Lane.speed_bound`), so between samples c_i and
c_j a step dt apart c >= (c_i + c_j)/2 - L dt/2.  Every interval whose bound
is below the least sample so far (less :data:`TOLERANCE_M`) is split and
sampled again, until none is left: the least sample is then within 1 mm of
the true least clearance (branch and bound on a Lipschitz bound).

Two horizontal lanes of one rate turn as one rigid body: their clearance is
constant, taken at t = 0.  Two horizontal lanes of different rates sweep every relative azimuth
(their angle apart grows linearly in time), so their least clearance is the
geometric one over the relative azimuth (found the same way, with the
distance from the axis bounding the rate), whatever the phases: ``basis``
'geometric'; it happens first at the time the lanes reach that angle apart.
Every other pair is searched over the act's times: ``basis`` 'act'."""

from __future__ import annotations

import math

import numpy as np

from deathsphere.act.envelope import clearance, overlap_clearance, segments_clearance
from deathsphere.act.lipschitz import refine_intervals

#: Every least clearance is found to this [m].
TOLERANCE_M = 1e-3
#: Clearances closer than this [m] are equal (the earliest is reported).
TIE_M = 1e-9
#: The first samples are this far apart in clearance (L dt) [m].
FIRST_STEP_M = 0.05
#: Periods are commensurate when n_i T_i agree to this relative tolerance
#: for whole numbers of laps n_i of at most :data:`MAX_LAPS`.
COMMENSURATE_RTOL = 1e-3
MAX_LAPS = 24
#: Pair-samples evaluated at once by :func:`least_clearances`.
BATCH_SAMPLES = 1 << 20
#: Two rates [rad/s] closer than this (relative) are the same.
SAME_RATE_RTOL = COMMENSURATE_RTOL


def minimise(f, lo: float, hi: float, lipschitz: float, tol: float = TOLERANCE_M):
    """(c, x): the least value of f over [lo, hi] to ``tol`` and where, for a
    vectorised f whose rate of change is at most ``lipschitz`` (module
    docstring).  Samples f at about (hi - lo) L / FIRST_STEP_M points first."""
    x = np.linspace(lo, hi, _samples(hi - lo, lipschitz) + 1)
    return refine(f, x, f(x), lipschitz, tol)


def _samples(span: float, lipschitz: float) -> int:
    return max(2, int(math.ceil(span * lipschitz / FIRST_STEP_M)))


def refine(f, x, c, lipschitz: float, tol: float = TOLERANCE_M):
    """(c, x): the least value of f to ``tol`` and where, given its samples c
    at the evenly spaced x (branch and bound: module docstring)."""
    k = int(np.argmax(c <= c.min() + TIE_M))               # the first of equal least samples
    best, where = float(c[k]), float(x[k])

    def below_best(left, bound):            # reads the least found so far, round by round
        return bound < best - tol

    for inner, ci in refine_intervals(f, x, c, float(x[1] - x[0]), lipschitz, below_best):
        k = np.unravel_index(int(np.argmin(ci)), ci.shape)
        if ci[k] < best - TIE_M:
            best, where = float(ci[k]), float(inner[k])
    return best, where


def is_geometric(a, b) -> bool:
    """Two horizontal lanes of different (signed) rates: every relative azimuth."""
    return a.kind == b.kind == "horizontal" and abs(a.rate - b.rate) > SAME_RATE_RTOL * max(abs(a.rate), abs(b.rate))


def common_period(periods, rtol: float = COMMENSURATE_RTOL, max_laps: int = MAX_LAPS) -> float | None:
    """The least T = n_1 T_1 that is a whole number (<= max_laps) of every
    period to ``rtol``, or None (not commensurate)."""
    periods = [float(p) for p in periods]
    if not periods:
        return None
    for n1 in range(1, max_laps + 1):
        span = n1 * periods[0]
        laps = [span / p for p in periods]
        if all(round(q) >= 1 and round(q) <= max_laps and abs(q - round(q)) <= rtol * q for q in laps):
            return span
    return None


def is_rigid(a, b) -> bool:
    """Two horizontal lanes of one rate: the pair turns as one rigid body
    about the vertical, its clearance constant in time."""
    return a.kind == b.kind == "horizontal" and not is_geometric(a, b)


def act_pairs(lanes) -> list[tuple[int, int]]:
    """The pairs (i < j) searched over the act's times (not geometric)."""
    n = len(lanes)
    return [(i, j) for i in range(n) for j in range(i + 1, n) if not is_geometric(lanes[i], lanes[j])]


def _clearance_at(a, b, clock_a=1.0):
    radii = 0.5 * (a.width_m + b.width_m)

    def f(t):
        return segments_clearance(a.segment_ends(t, clock_a), b.segment_ends(t), radii)
    return f


def least_clearances(lanes, pairs, duration: float) -> list[tuple[float, float]]:
    """[(least clearance [m], when [s])] of the pairs (i, j) of ``lanes``
    searched over the act's times [0, duration]: every lane sampled once on
    one grid fine enough for the fastest pair, chunk by chunk, all pairs'
    distances at once, then each pair refined (:func:`refine`)."""
    rigid = [p for p in pairs if is_rigid(lanes[p[0]], lanes[p[1]])]
    if rigid:
        moving = [p for p in pairs if p not in rigid]
        found = dict(zip(moving, least_clearances(lanes, moving, duration)))
        return [found[p] if p in found else least_clearance(lanes[p[0]], lanes[p[1]], duration)[:2] for p in pairs]
    if not pairs:
        return []
    bound = [lane.speed_bound() for lane in lanes]
    fastest = max(bound[i] + bound[j] for i, j in pairs)
    n = _samples(float(duration), fastest)
    best = [(math.inf, math.nan)] * len(pairs)
    for start in range(0, n, CHUNK_SAMPLES):
        x = _grid_part(float(duration), n, start, min(start + CHUNK_SAMPLES, n))
        found = _chunk_clearances(lanes, pairs, x, bound)
        # each chunk's least is found to the tolerance: the act's is the least of theirs (the earliest of equal ones)
        best = [new if new[0] < old[0] - TIE_M else old for old, new in zip(best, found)]
    return best


#: Act samples held at once by :func:`least_clearances` (memory stays
#: bounded however long the act: the act is searched chunk by chunk).
CHUNK_SAMPLES = 1 << 16


def _grid_part(duration: float, n: int, start: int, stop: int) -> np.ndarray:
    """Samples start..stop of np.linspace(0, duration, n + 1), bit for bit,
    without building the whole grid."""
    x = np.arange(start, stop + 1, dtype=float) * (duration / n)
    if stop == n:
        x[-1] = duration
    return x


def _chunk_clearances(lanes, pairs, x, bound) -> list[tuple[float, float]]:
    """[(least clearance, when)] of the pairs over the evenly spaced times x:
    every lane sampled once, the pairs' distances in batches, each refined."""
    several = [p for p in pairs if lanes[p[0]].body is not None or lanes[p[1]].body is not None]
    if several:
        # a two-wheeler's envelope is several segments: its pairs one by one, the others batched as before
        simple = [p for p in pairs if p not in several]
        found = dict(zip(simple, _chunk_clearances(lanes, simple, x, bound)))
        for i, j in several:
            f = _clearance_at(lanes[i], lanes[j])
            found[(i, j)] = deepest(f, *refine(f, x, f(x), bound[i] + bound[j]), float(x[0]), float(x[-1]),
                                    bound[i] + bound[j], 0.5 * (lanes[i].width_m + lanes[j].width_m))
        return [found[p] for p in pairs]
    ends = [lane.ends(x) for lane in lanes]
    out = []
    per_batch = max(1, BATCH_SAMPLES // x.size)
    for start in range(0, len(pairs), per_batch):
        batch = pairs[start:start + per_batch]
        first, second = np.array([i for i, _ in batch]), np.array([j for _, j in batch])
        stack = [np.stack([ends[k][e] for k in idx], axis=1) for idx in (first, second) for e in (0, 1)]
        radii = np.array([0.5 * (lanes[i].width_m + lanes[j].width_m) for i, j in batch])
        c = overlap_clearance(*stack, radii[:, None])
        out += [deepest(_clearance_at(lanes[i], lanes[j]), *refine(_clearance_at(lanes[i], lanes[j]), x, c[p],
                                                                   bound[i] + bound[j]),
                        float(x[0]), float(x[-1]), bound[i] + bound[j], radii[p])
                for p, (i, j) in enumerate(batch)]
    return out


def least_clearance(a, b, duration: float, *, clock_a: float = 1.0) -> tuple[float, float, str]:
    """(least clearance [m], when [s], basis) of the lanes a and b over the
    act [0, duration] (``clock_a`` scales a's time); the geometric least
    clearance for two horizontal lanes of different rates (module docstring)."""
    if is_rigid(a, b) and clock_a == 1.0:
        return float(_clearance_at(a, b)(np.zeros(1))[0]), 0.0, "act"
    if is_geometric(a, b) and clock_a == 1.0:
        meridian_b = b.at_angle(np.zeros(1))

        def apart(delta):
            return clearance(a.at_angle(delta), meridian_b, a.width_m, b.width_m, a.segments, b.segments)

        # phi_a - phi_b = delta0 + (Omega_a - Omega_b) t; a point moves its reach per radian at most
        c, delta = deepest(apart, *minimise(apart, 0.0, 2 * math.pi, a.reach), 0.0, 2 * math.pi, a.reach,
                           0.5 * (a.width_m + b.width_m))
        rel = a.rate - b.rate
        t = ((delta - (a.phase - b.phase)) / rel) % (2 * math.pi / abs(rel))
        return c, t, "geometric"
    lipschitz = clock_a * a.speed_bound() + b.speed_bound()
    f = _clearance_at(a, b, clock_a)
    c, t = deepest(f, *minimise(f, 0.0, float(duration), lipschitz), 0.0, float(duration), lipschitz,
                   0.5 * (a.width_m + b.width_m))
    return c, t, "act"


#: Samples per round of the search for an overlap's depth, and its rounds.
DEPTH_SAMPLES = 65
DEPTH_ROUNDS = 5


def deepest(f, c: float, x: float, lo: float, hi: float, lipschitz: float, radii: float) -> tuple[float, float]:
    """(c, x) of an overlap's deepest point: the least clearance c at x
    (found by :func:`refine`, whose bound holds for the axes' distance),
    searched again, when below zero, for the depth along the bodies, whose
    rate of change has no such bound (:func:`overlap_clearance`).  The
    window is 2 radii / lipschitz either side of x (twice the least time
    the axes' distance needs to climb from zero to the radii), sampled and
    narrowed round by round about the least sample; not certified as the
    clearance is.  Returns the deeper of the two; a clearance that is not
    an overlap is returned as it is."""
    if not c < 0 or lipschitz <= 0:
        return c, x
    half = 2.0 * radii / lipschitz
    a, b = max(lo, x - half), min(hi, x + half)
    best_c, best_x = c, x
    for _ in range(DEPTH_ROUNDS):
        grid = np.linspace(a, b, DEPTH_SAMPLES)
        values = f(grid)
        k = int(np.argmin(values))
        if values[k] < best_c - TIE_M:
            best_c, best_x = float(values[k]), float(grid[k])
        step = (b - a) / (DEPTH_SAMPLES - 1)
        a, b = max(lo, best_x - 2 * step), min(hi, best_x + 2 * step)
    return best_c, best_x


def contact_angles(lane, t: float, ground) -> tuple[float, float]:
    """theta and phi [deg] of the lane's contact at time t on the globe
    ``ground`` (phi 0..360); on a drum or a cone theta is NaN (it is the
    globe's: a lane there is its height)."""
    p = lane.kinematics(np.array([t]))["contact"][:, 0]
    if not hasattr(ground, "theta"):
        return math.nan, math.degrees(math.atan2(p[1], p[0])) % 360.0
    theta = math.degrees(math.acos(max(-1.0, min(1.0, p[2] / ground.radius))))
    return theta, math.degrees(math.atan2(p[1], p[0])) % 360.0


def where_closest(a, b, t: float, ground) -> dict:
    """Where the pair (a, b) is at time t on ``ground``: the
    heights [m] above the floor of both contacts ('height_a', 'height_b')
    and of the point of closest approach, midway between the closest points
    of the two envelopes' axes ('height', with its azimuth 'phi' [deg],
    0..360)."""
    from deathsphere.act.envelope import segment_distance

    now = np.array([t])
    # the segments of the two envelopes that come closest (a single-contact machine has one)
    (p0, p1), (q0, q1) = min(((e, f) for e in a.segment_ends(now) for f in b.segment_ends(now)),
                             key=lambda ef: float(segment_distance(*ef[0], *ef[1])[0][0]))
    _, s, u = segment_distance(p0, p1, q0, q1)
    mid = 0.5 * (p0 + s * (p1 - p0) + q0 + u * (q1 - q0))[:, 0]
    low = float(ground.lowest)               # the floor's z: -r on the globe, 0 on a drum or a cone
    contact_a, contact_b = a.ends(now)[0], b.ends(now)[0]      # each envelope's first segment starts at its contact
    return {"height_a": float(contact_a[2, 0]) - low, "height_b": float(contact_b[2, 0]) - low,
            "height": float(mid[2]) - low,
            "phi": math.degrees(math.atan2(mid[1], mid[0])) % 360.0}


def clearance_verdict(c: float, min_clearance: float) -> str:
    """'collision' below zero, 'conflict' below the crew's least clearance, else 'clear'."""
    return "collision" if c < 0 else "conflict" if c < min_clearance else "clear"


def act_duration(lanes, duration: float | None) -> tuple[float, bool]:
    """(the act's duration [s], commensurate): the common period of the
    lanes in a pair searched over time, when commensurate; else
    ``duration`` (None: ValueError).  With no such pair (every pair rigid or
    geometric) the common period of all lanes, else ``duration``, else the
    longest lap (the falls' times are drawn over it)."""
    involved = sorted({k for pair in act_pairs(lanes) for k in pair})
    if not involved:
        # nothing depends on the clock: the common period of all, else the plan's duration, else the longest lap
        common = common_period([lane.period_s for lane in lanes])
        if common is not None:
            return common, True
        return (float(duration) if duration is not None else max(lane.period_s for lane in lanes)), False
    common = common_period([lanes[k].period_s for k in involved])
    if common is not None:
        return common, True
    if duration is None:
        more = ", ..." if len(involved) > 4 else ""
        shown = ", ".join(f"{lanes[k].name} {lanes[k].period_s:.4g} s" for k in involved[:4])
        raise ValueError(f"the riders' laps are not commensurate to {COMMENSURATE_RTOL:g} within {MAX_LAPS} laps "
                         f"({shown}{more}): give the act's length in seconds, e.g. duration = 60 in the plan's "
                         "[globe]")
    return float(duration), False
