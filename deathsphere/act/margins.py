"""A lane's speed margin (beyond the paper; docs/show.md, "Speed margin"):
the band of speeds about the planned one in which the lane stays feasible
under the globe's mu and max_g, found on ``ride``'s own statuses.

Horizontal lane: a speed is feasible when some tilt at that height gives it
with status ok (ride by speed, eq. M12).  Vertical lane: a top speed is
feasible when ``ride --vertical`` says ok (M22-M24).  The speeds of a
geometric grid about the planned speed (1/16 to 16 times it) are tried at
once; the run of feasible speeds holding the planned one is bracketed there
and its two edges found by bisection, both riders' edges in one call to
ride per step."""

from __future__ import annotations

import numpy as np

from deathsphere.api.rides import ride

#: The speeds tried, as multiples of the planned one.
GRID = np.geomspace(1 / 16, 16, 145)
#: Bisection steps on each edge: the edge to GRID's ratio (about 1.04) / 2**STEPS.
STEPS = 14


def feasible(lanes, globe, speeds) -> np.ndarray:
    """bool (n, k): lane i stays feasible at speeds[i, j] [m/s] (module
    docstring); the lanes share one kind and one machine: one call to ride."""
    speeds = np.asarray(speeds, dtype=float)
    lane = lanes[0]
    if lane.kind == "vertical":
        t = ride(90.0, vertical=True, v_top=speeds.reshape(-1), machine=lane.machine, r=globe.r, g=globe.g,
                 mu=globe.mu, max_g=globe.max_g)
        return (np.asarray(t["status"]).reshape(-1) == "ok").reshape(speeds.shape)
    theta = np.degrees([ln.theta for ln in lanes])[:, None]
    t = ride(np.broadcast_to(theta, speeds.shape).reshape(-1), speed=speeds.reshape(-1), machine=lane.machine,
             r=globe.r, g=globe.g, mu=globe.mu, max_g=globe.max_g, stability=False)
    ok = np.zeros(speeds.size, dtype=bool)
    rows = np.asarray(t["input_row"]).reshape(-1) - 1
    ok[rows[np.asarray(t["status"]).reshape(-1) == "ok"]] = True
    return ok.reshape(speeds.shape)


def _bands(lanes, globe, planned) -> np.ndarray:
    """(n, 2) [m/s] low and high edges for lanes of one kind and machine."""
    planned = np.asarray(planned, dtype=float)
    grid = planned[:, None] * GRID
    ok = feasible(lanes, globe, np.concatenate((planned[:, None], grid), axis=1))
    here, ok = ok[:, 0], ok[:, 1:]
    k = np.searchsorted(GRID, 1.0)                      # grid[:, k] is the first at or above the planned speed
    inside = np.full((planned.size, 2), np.nan)
    outside = np.full((planned.size, 2), np.nan)
    for i in np.flatnonzero(here):
        below = np.flatnonzero(~ok[i, :k])
        above = np.flatnonzero(~ok[i, k:]) + k
        if below.size:
            j = below[-1]
            inside[i, 0], outside[i, 0] = (grid[i, j + 1] if j + 1 < k else planned[i]), grid[i, j]
        if above.size:
            j = above[0]
            inside[i, 1], outside[i, 1] = (grid[i, j - 1] if j - 1 >= k else planned[i]), grid[i, j]
    found = np.isfinite(inside)
    if found.any():
        for _ in range(STEPS):
            mid = np.where(found, 0.5 * (inside + outside), planned[:, None])
            good = feasible(lanes, globe, mid)
            inside, outside = np.where(good, mid, inside), np.where(good, outside, mid)
    return np.where(found, inside, np.nan)


def speed_bands(lanes, globe, planned) -> np.ndarray:
    """(n, 2) [m/s]: for each lane the run of feasible speeds (horizontal:
    the centre of mass's; vertical: at the top) holding the planned one,
    low and high; NaN where the planned speed itself is not feasible or an
    edge lies beyond 1/16..16 times it.  The lanes of one kind and machine
    are searched together."""
    planned = np.asarray(planned, dtype=float)
    out = np.full((len(lanes), 2), np.nan)
    groups = {}
    for i, lane in enumerate(lanes):
        groups.setdefault((lane.kind, lane.machine), []).append(i)
    for idx in groups.values():
        out[idx] = _bands([lanes[i] for i in idx], globe, planned[idx])
    return out
