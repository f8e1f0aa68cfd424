"""A lane's speed margin (beyond the paper; docs/show.md, "Speed margin"):
the band of speeds about the planned one in which the lane stays feasible
under the globe's mu and max_g, found on the statuses ``ride`` reports.

Horizontal lane: a speed of the contact is feasible when some tilt at that
height turns at its rate Omega = v / (r sin theta) with status ok (eq. M12r,
:func:`deathsphere.physics.machine_lanes.rate_is_feasible`).
Vertical lane: a top speed is feasible when its loop is ok (M22-M24,
:func:`deathsphere.physics.machine.vertical_loop`).  The speeds of a
geometric grid about the planned speed (1/16 to 16 times it) are tried at
once; the run of feasible speeds holding the planned one is bracketed there
and its two edges found by bisection on the bracket (a status is not a
continuous function: a bracketed bisection is the root finder that fits),
to :data:`RTOL` of the edge, every rider's edges of one kind of
lane in one physics call per step (their machines as arrays over riders)."""

from __future__ import annotations

import numpy as np

from deathsphere.physics.machine import vertical_loop
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.physics.machine_lanes import contact_rate, contact_rate_on, rate_is_feasible, rate_is_feasible_on
from deathsphere.requests.arena import is_globe
from deathsphere.physics.status import Status

#: The speeds tried, as multiples of the planned one.
GRID = np.geomspace(1 / 16, 16, 145)
#: Each edge is found to this, relative to itself: the bracket (GRID's
#: ratio, about 1.04) halved until it is half this narrow (about 30 steps).
RTOL = 1e-10
#: A two-wheeler's edges are found to the same RTOL, each bracket cut into
#: :data:`SECTIONS` + 1 at a step (seeking its steady turns costs some 0.15 s
#: a call on the globe however many speeds it takes, 0.4 s on a drum: a few
#: calls of many speeds, not thirty of one): five steps.
TWO_WHEELER_RTOL = RTOL
SECTIONS = 127
#: The most bisection steps (a bracket of the whole GRID halved to below RTOL).
MAX_STEPS = 64


def speeds_hold(lanes, globe, speeds) -> np.ndarray:
    """bool (n, k): lane i stays feasible at speeds[i, j] [m/s] (module
    docstring); the lanes share one kind: one physics call."""
    speeds = np.asarray(speeds, dtype=float)
    if lanes[0].body is not None:
        return np.stack([_two_wheeler_holds(lane, globe, row) for lane, row in zip(lanes, speeds)])
    machines = machine_arrays([lane.machine for lane in lanes]).expand(-1)        # (n, 1): one per lane
    ground = globe.ground
    if lanes[0].kind == "vertical":
        loops = vertical_loop(np.radians(90.0), speeds, ground, globe.g, machines, globe.mu, globe.max_g)
        return loops["status"] == Status.OK
    flat = machines.map(lambda x: np.broadcast_to(x, speeds.shape).reshape(-1))
    if not is_globe(ground):            # a drum or a cone: the lane by its height, the machine's physics on it
        height = np.broadcast_to(np.array([lane.height for lane in lanes])[:, None], speeds.shape).reshape(-1)
        omega = contact_rate_on(height, speeds.reshape(-1), ground)
        return rate_is_feasible_on(height, omega, ground, globe.g, flat, globe.mu, globe.max_g).reshape(speeds.shape)
    theta = np.broadcast_to(np.array([lane.theta for lane in lanes])[:, None], speeds.shape)
    omega = contact_rate(theta.reshape(-1), speeds.reshape(-1), ground)
    ok = rate_is_feasible(theta.reshape(-1), omega, ground, globe.g, flat, globe.mu, globe.max_g)
    return ok.reshape(speeds.shape)


def _two_wheeler_holds(lane, globe, speeds) -> np.ndarray:
    """bool (k,): the two-wheeler's lane has a steady turn with status ok at
    each rear contact speed [m/s] (ride's statuses, docs/two-wheeler.md sec. 8)."""
    from deathsphere.physics.two_wheeler.holds import turn_holds

    t, ground = lane.machine, globe.ground
    at = lane.theta if is_globe(ground) else lane.height
    return turn_holds(at, speeds, t.parameters(), ground, globe.g, t.head, globe.mu, globe.max_g)["holds"]


def _bands(lanes, globe, planned, rtol: float = RTOL) -> np.ndarray:
    """(n, 2) [m/s] low and high edges for lanes of one kind."""
    planned = np.asarray(planned, dtype=float)
    grid = planned[:, None] * GRID
    ok = speeds_hold(lanes, globe, np.concatenate((planned[:, None], grid), axis=1))
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
    if lanes[0].body is not None:
        return _sections(lanes, globe, planned, inside, outside, found, rtol)
    for _ in range(MAX_STEPS):
        # half the tolerance of the edge itself: the edge lies between inside and outside
        open_ = found & (np.abs(outside - inside) > 0.5 * rtol * np.abs(inside))
        if not open_.any():
            break
        mid = np.where(open_, 0.5 * (inside + outside), planned[:, None])
        good = speeds_hold(lanes, globe, mid)
        inside, outside = np.where(open_ & good, mid, inside), np.where(open_ & ~good, mid, outside)
    return np.where(found, inside, np.nan)


def _sections(lanes, globe, planned, inside, outside, found, rtol: float) -> np.ndarray:
    """:func:`_bands`'s edges by multisection: each open bracket (inside
    feasible, outside not) sampled at :data:`SECTIONS` points at once, the
    bracket narrowed to the first change from feasible to not counted from
    the inside (the run holding the planned speed), until it is narrower
    than ``rtol`` of its edge."""
    frac = np.arange(1, SECTIONS + 1) / (SECTIONS + 1)
    n = planned.size
    for _ in range(MAX_STEPS):
        open_ = found & (np.abs(outside - inside) > 0.5 * rtol * np.abs(inside))
        if not open_.any():
            break
        pts = inside[..., None] + (outside - inside)[..., None] * frac                  # (n, 2, SECTIONS)
        pts = np.where(open_[..., None], pts, planned[:, None, None])
        good = speeds_hold(lanes, globe, pts.reshape(n, -1)).reshape(pts.shape)
        first_bad = np.argmax(~good, axis=-1)                                         # SECTIONS: none bad
        first_bad = np.where((~good).any(axis=-1), first_bad, SECTIONS)
        take = np.clip(first_bad - 1, 0, SECTIONS - 1)[..., None]
        last_good = np.where(first_bad > 0, np.take_along_axis(pts, take, -1)[..., 0], inside)
        bad = np.where(first_bad < SECTIONS,
                       np.take_along_axis(pts, np.minimum(first_bad, SECTIONS - 1)[..., None], -1)[..., 0], outside)
        inside, outside = np.where(open_, last_good, inside), np.where(open_, bad, outside)
    return np.where(found, inside, np.nan)


def speed_bands(lanes, globe, planned) -> np.ndarray:
    """(n, 2) [m/s]: for each lane the run of feasible speeds (horizontal:
    the contact's, however the plan holds the lane; vertical: the centre of
    mass's at the top) holding the planned one,
    low and high; NaN where the planned speed itself is not feasible or an
    edge lies beyond 1/16..16 times it.  The lanes of one kind are searched
    together, whatever their machines."""
    planned = np.asarray(planned, dtype=float)
    out = np.full((len(lanes), 2), np.nan)
    groups = {}
    for i, lane in enumerate(lanes):
        groups.setdefault((lane.kind, lane.body is not None), []).append(i)
    for (_, two_wheeler), idx in groups.items():
        out[idx] = _bands([lanes[i] for i in idx], globe, planned[idx], TWO_WHEELER_RTOL if two_wheeler else RTOL)
        if two_wheeler:
            out[idx] = _unsearched(out[idx])
    return out


def _unsearched(band) -> np.ndarray:
    """A two-wheeler's band with an edge at the fastest turn its solver seeks
    (steady.MAX_SPEED, a rear wheel's 100 m/s) made NaN: the lane holds to
    there, and the edge itself lies beyond what is searched (as an edge
    beyond 16 times the planned speed is NaN)."""
    from deathsphere.physics.two_wheeler.steady import MAX_SPEED

    return np.where(band >= MAX_SPEED * (1.0 - 1e-8), np.nan, band)
