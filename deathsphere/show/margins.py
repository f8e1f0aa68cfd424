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

import math

import numpy as np

from deathsphere.api.rides import ride

#: The speeds tried, as multiples of the planned one.
GRID = np.geomspace(1 / 16, 16, 145)
#: Bisection steps on each edge: the edge to GRID's ratio (about 1.04) / 2**STEPS.
STEPS = 14


def feasible(lane, globe, speeds) -> np.ndarray:
    """bool per speed [m/s]: the lane stays feasible at that speed (module docstring)."""
    speeds = np.asarray(speeds, dtype=float).reshape(-1)
    if lane.kind == "vertical":
        t = ride(90.0, vertical=True, v_top=speeds, machine=lane.machine, r=globe.r, g=globe.g, mu=globe.mu,
                 max_g=globe.max_g)
        return np.asarray(t["status"]).reshape(-1) == "ok"
    t = ride(math.degrees(lane.theta), speed=speeds, machine=lane.machine, r=globe.r, g=globe.g, mu=globe.mu,
             max_g=globe.max_g, stability=False)
    ok = np.zeros(speeds.size, dtype=bool)
    rows = np.asarray(t["input_row"]).reshape(-1) - 1
    ok[rows[np.asarray(t["status"]).reshape(-1) == "ok"]] = True
    return ok


def speed_band(lane, globe, speed: float) -> tuple[float, float]:
    """(low, high) [m/s]: the run of feasible speeds holding ``speed``; NaN
    where ``speed`` itself is not feasible, or an edge lies beyond the grid."""
    if not feasible(lane, globe, [speed])[0]:
        return math.nan, math.nan
    grid = speed * GRID
    ok = feasible(lane, globe, grid)
    k = int(np.searchsorted(grid, speed))
    below = np.flatnonzero(~ok[:k])
    above = np.flatnonzero(~ok[k:]) + k
    # brackets (feasible, infeasible) for each edge; NaN where the grid found none
    lo_in, lo_out = (grid[below[-1] + 1] if below[-1] + 1 < k else speed, grid[below[-1]]) if below.size else (
        math.nan, math.nan)
    hi_in, hi_out = (grid[above[0] - 1] if above[0] - 1 >= k else speed, grid[above[0]]) if above.size else (
        math.nan, math.nan)
    inside, outside = np.array([lo_in, hi_in]), np.array([lo_out, hi_out])
    found = np.isfinite(inside)
    if found.any():
        for _ in range(STEPS):
            mid = 0.5 * (inside + outside)
            good = feasible(lane, globe, np.where(found, mid, speed))
            inside, outside = np.where(good, mid, inside), np.where(good, outside, mid)
    edge = np.where(found, inside, np.nan)
    return float(edge[0]), float(edge[1])
