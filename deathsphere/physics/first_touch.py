"""The first instant a flight's gap to the ground is certainly crossed, on
any ground (beyond the paper; docs/show.md sec. 11, "A fall on a wall").

A scan of a flight's gap q(t) (its distance from the wall or the floor,
:mod:`deathsphere.physics.landing`) at evenly spaced instants brackets the
first sample with q <= 0; on a ground where q is not concave (a cone
leaning in, a profile) q may dip below zero and come back between two
samples, a graze the scan does not see.  What closes the gap: q is the
least of distances from a point (the wall's signed distance, the height
above the floor), each changing no faster than the point moves, so

    |dq/dt| <= max |v(t)| = max(|v0|, |v(T)|)      (|v(t)|^2 is convex in t)

and between samples q_i, q_j a step w apart q >= (q_i + q_j)/2 - L w/2.
Every interval before the bracket whose bound is not positive is split in
:data:`SPLIT` and sampled again (the branch and bound of the show's least
clearances), until every interval is certified clear or is shorter than
:data:`TOUCH_M` / L; the earliest sample found with q <= 0 is the new
bracket.  Where q is concave (the drum, a cone leaning out) no sample
before the bracket is at or below zero, so the bracket, and the landing,
are the scan's bit for bit.

Vectorised over flights: the intervals still open are one flat array (a
flight's index, its left end, width and end values); each round is one
call of the gap over all of them.
"""

from __future__ import annotations

import numpy as np

__all__ = ["SPLIT", "TOUCH_M", "first_crossing"]

#: Each interval kept is split into this many.
SPLIT = 8
#: An interval whose gap could dip by less than this [m] below its bound is
#: not split further: a graze that comes within a micrometre of the wall
#: without a sample at or past it is not a landing (far below what the
#: model of the fall resolves).
TOUCH_M = 1e-6
#: Rounds at most (each divides the intervals' width by SPLIT; 24 rounds
#: take a scan's step of a second below 1e-21 s).
MAX_ROUNDS = 24


def first_crossing(gap, ts, q, first, t0_gap, speed_bound):
    """(lo, hi) (n,): the bracket of each flight's first crossing of q = 0,
    certified (beyond the paper: the module docstring, docs/show.md sec.
    11, "A fall on a wall").

    gap(rows, t) -> q at the flights ``rows`` (k,) and times ``t`` (k,);
    ``ts`` (n, m) the scanned instants (evenly spaced, ts[:, 0] one step
    after the start), ``q`` (n, m) the gap there, ``first`` (n,) the index
    of each flight's first scanned q <= 0, ``t0_gap`` (n,) q at the start
    (the interval from the start is searched only where it is positive),
    ``speed_bound`` (n,) L [m/s]."""
    n, m = ts.shape
    rows = np.arange(n)
    hi = ts[rows, first].copy()
    lo = np.where(first > 0, ts[rows, np.maximum(first - 1, 0)], 0.0)
    step = ts[:, 1] - ts[:, 0] if m > 1 else ts[:, 0]
    # the scan's intervals before the bracket: [ts[k-1], ts[k]] for k < first, and [0, ts[0]] from a start inside
    left = np.concatenate((np.zeros((n, 1)), ts[:, :-1]), axis=1)
    ql = np.concatenate((t0_gap[:, None], q[:, :-1]), axis=1)
    k = np.arange(m)
    open_ = (k[None, :] < first[:, None]) & ((k[None, :] > 0) | (t0_gap[:, None] > 0))
    f, a = np.nonzero(open_)
    left, w = left[f, a], np.where(a > 0, step[f], ts[f, 0])
    cl, cr = ql[f, a], q[f, a]
    for _ in range(MAX_ROUNDS):
        if not f.size:
            break
        bound = 0.5 * (cl + cr) - 0.5 * speed_bound[f] * w
        keep = (bound <= 0.0) & (left < hi[f]) & (speed_bound[f] * w > TOUCH_M)
        f, left, w, cl, cr = f[keep], left[keep], w[keep] / SPLIT, cl[keep], cr[keep]
        if not f.size:
            break
        inner = left[:, None] + w[:, None] * np.arange(1, SPLIT)            # (k, SPLIT - 1)
        rows_in = np.repeat(f, SPLIT - 1)
        qi = gap(rows_in, inner.reshape(-1)).reshape(inner.shape)
        crossed = qi <= 0.0
        if crossed.any():
            j, c = np.nonzero(crossed)
            t_cross = inner[j, c]
            order = np.lexsort((t_cross, f[j]))
            fj, tj, wj = f[j][order], t_cross[order], w[j][order]
            head = np.concatenate(([True], fj[1:] != fj[:-1]))              # each flight's earliest crossing
            fj, tj, wj = fj[head], tj[head], wj[head]
            earlier = tj < hi[fj]
            hi[fj[earlier]], lo[fj[earlier]] = tj[earlier], tj[earlier] - wj[earlier]
        values = np.concatenate((cl[:, None], qi, cr[:, None]), axis=1)
        f = np.repeat(f, SPLIT)
        left = (left[:, None] + w[:, None] * np.arange(SPLIT)).reshape(-1)
        w = np.repeat(w, SPLIT)
        cl, cr = values[:, :-1].reshape(-1), values[:, 1:].reshape(-1)
    return lo, hi
