"""Timing the vertical riders through the other lanes, and the drift of a
rider whose speedometer reads 1 % off (beyond the paper; docs/show.md,
"Timing" and "Drift").

Phase: a vertical rider's phase only shifts his loop in time (psi(t) with
phase psi_k is the loop from the top shifted by the time t_k it takes to
reach psi_k).  With :data:`PHASE_STEPS` shifts a lap apart by T/PHASE_STEPS
and the act sampled at the same step, each shift's positions are those of
the free loop rolled by whole samples, so every candidate phase is tried
against every other lane (the horizontal lanes and the vertical riders
already timed, in plan order) with one table of distances.  The phase with
the greatest sampled least clearance is taken; the windows are the runs of
candidate phases whose sampled least clearance is at least min_clearance
(to the step's resolution: the chosen phase's pairs are then found to 1 mm
by :mod:`deathsphere.act.pairs`).

Drift: rider A's clock runs 1 +- error times the plan's (his lane unchanged,
only its timing).  Two horizontal lanes of one rate then drift apart in
azimuth at error |Omega| and the first relative azimuth, either way, at
which they come closer than min_clearance gives the time exactly; a pair
searched over time is searched forwards from t = 0 over (1/error + 1) of the
longer lap (the slip has then covered a whole lap) for the first time the
clearance falls below min_clearance, with the same Lipschitz bound as the
pairs (no dip deeper than 1 mm missed).  Two horizontal lanes of different
rates already sweep every relative azimuth: a clear pair stays clear."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from deathsphere.act.envelope import overlap_clearance, segments_clearance
from deathsphere.act.lipschitz import refine_intervals
from deathsphere.act.pairs import SAME_RATE_RTOL, TOLERANCE_M, is_geometric

#: Candidate phases per lap of a vertical rider (and samples per lap of the act).
PHASE_STEPS = 180
#: The speed error of the drift (1 %).
DRIFT_ERROR = 0.01
#: The drift's first samples are this far apart in clearance [m]: a pair
#: rarely comes near min_clearance, so coarse samples decide most of the
#: time, and the bound refines where it does.
DRIFT_FIRST_STEP_M = 0.25
#: Act samples per slice of the phase search (memory stays bounded).
SLICE = 2048
#: Points along each axis of the overlap's integral in the phase search:
#: it ranks phases sampled a step apart, so a coarser integral (a few mm)
#: than the pairs' will do, at a quarter of the cost.
PHASE_AXIS_POINTS = 17


def _segments(lane, t):
    k = lane.kinematics(t)
    return k["contact"], k["head"]


def phase_clearances(lane, others, duration: float, steps: int = PHASE_STEPS):
    """(phases [deg] (steps,), least sampled clearance [m] (steps,)) of the
    vertical ``lane`` against ``others`` over [0, duration] for each phase
    of the lap's time grid (module docstring)."""
    phases, each = phase_clearances_each(lane, others, duration, steps)
    return phases, each.min(axis=0)


def phase_clearances_each(lane, others, duration: float, steps: int = PHASE_STEPS):
    """(phases [deg] (steps,), least sampled clearance [m] (len(others),
    steps)): :func:`phase_clearances` against each of ``others`` apart."""
    period = lane.period_s
    dt = period / steps
    free = replace(lane, phase=0.0)
    k = np.arange(steps)
    p0, p1 = _segments(free, k * dt)
    phases = np.degrees(free.kinematics(k * dt)["psi"]) % 360.0
    least = np.full((len(others), steps), np.inf)
    times = np.arange(int(math.ceil(duration / dt)) + 1) * dt
    for o, other in enumerate(others):
        # a two-wheeler's envelope is several segments: the least over them
        for q0, q1 in ([_segments(other, times)] if other.body is None else other.segment_ends(times)):
            radii = 0.5 * (lane.width_m + other.width_m)
            for start in range(0, times.size, SLICE):
                j = np.arange(start, min(start + SLICE, times.size))
                idx = (j[None, :] + k[:, None]) % steps                 # (steps, slice): the loop shifted by k
                c = overlap_clearance(p0[:, idx], p1[:, idx], q0[:, None, j], q1[:, None, j], radii,
                                      PHASE_AXIS_POINTS)
                least[o] = np.minimum(least[o], c.min(axis=1))
    return phases, least


def _windows(phases, safe) -> list[tuple[float, float]]:
    """The runs of safe candidate phases, (from, to) [deg], a run across the
    lap's end joined."""
    if safe.all():
        return [(0.0, 360.0)]
    if not safe.any():
        return []
    start = int(np.argmin(safe))                                     # begin at an unsafe phase
    order = np.roll(np.arange(safe.size), -start)
    runs, current = [], None
    for i in order:
        if safe[i]:
            current = [i, i] if current is None else [current[0], i]
        elif current is not None:
            runs.append(current)
            current = None
    if current is not None:
        runs.append(current)
    return [(float(phases[a]), float(phases[b])) for a, b in runs]


def auto_phases(lanes, duration: float, min_clearance: float, timed=None):
    """({name: phase [deg]}, {name: windows}, {name: riders in the way})
    for every vertical lane, in plan order, each against the horizontal
    lanes and the vertical lanes timed before it (module docstring).  The
    riders in the way of a lane with no safe phase are those still closer
    than min_clearance at the phase taken (the best there is), in plan
    order; none when it has a window.  ``timed()``, if given, is called
    after each vertical lane is timed (a progress bar's step)."""
    lanes = list(lanes)
    phases, windows, in_the_way = {}, {}, {}
    for i, lane in enumerate(lanes):
        if lane.kind != "vertical":
            continue
        others = [o for j, o in enumerate(lanes) if j != i and (o.kind == "horizontal" or j < i)]
        in_the_way[lane.name] = []
        if not others:
            windows[lane.name] = [(0.0, 360.0)]
            phases[lane.name] = math.degrees(lane.phase) % 360.0
            if timed is not None:
                timed()
            continue
        cand, each = phase_clearances_each(lane, others, duration)
        least = each.min(axis=0)
        best = int(np.argmax(least))
        phases[lane.name] = float(cand[best])
        windows[lane.name] = _windows(cand, least >= min_clearance)
        if not windows[lane.name]:
            in_the_way[lane.name] = [o.name for o, c in zip(others, each[:, best]) if c < min_clearance]
        lanes[i] = replace(lane, phase=math.radians(cand[best]))
        if timed is not None:
            timed()
    return phases, windows, in_the_way


def first_below(f, lo: float, hi: float, lipschitz: float, level: float, tol: float = TOLERANCE_M,
                first_step: float = DRIFT_FIRST_STEP_M) -> float:
    """The first x in [lo, hi] with f(x) < level, for a vectorised f changing
    at most at ``lipschitz`` (no dip below level - tol missed); inf if none.
    The first samples are ``first_step`` / lipschitz apart (only where f
    comes within first_step / 2 of the level are they refined)."""
    n = max(2, int(math.ceil((hi - lo) * lipschitz / first_step)))
    x = np.linspace(lo, hi, n + 1)
    c = f(x)
    below = np.flatnonzero(c < level)
    hit = float(x[below[0]]) if below.size else math.inf

    def before_hit(left, bound):            # reads the first time found so far, round by round
        return (bound < level - tol) & (left < hit)

    for inner, ci in refine_intervals(f, x, c, (hi - lo) / n, lipschitz, before_hit):
        under = ci < level
        if under.any():
            hit = min(hit, float(inner[under].min()))
    return hit


def drift_time(a, b, min_clearance: float, error: float = DRIFT_ERROR) -> float:
    """Time [s] until the pair (a, b) first comes closer than min_clearance
    with a's clock 1 + error or 1 - error times the plan's, the sooner of
    the two; inf: never (module docstring)."""
    from deathsphere.act.envelope import clearance

    if is_geometric(a, b):
        return math.inf
    if a.kind == b.kind == "horizontal":
        meridian_b = b.at_angle(np.zeros(1))
        start = a.phase - b.phase
        rate = abs(a.rate) * error
        if rate <= SAME_RATE_RTOL:
            return math.inf
        soonest = math.inf
        for sense in (1.0, -1.0):
            def apart(x, sense=sense):
                return clearance(a.at_angle(start + sense * x), meridian_b, a.width_m, b.width_m, a.segments,
                                 b.segments)
            soonest = min(soonest, first_below(apart, 0.0, 2 * math.pi, a.reach, min_clearance) / rate)
        return soonest
    horizon = (1.0 / error + 1.0) * max(a.period_s, b.period_s)
    radii = 0.5 * (a.width_m + b.width_m)
    soonest = math.inf
    for clock in (1.0 + error, 1.0 - error):
        def gap(t, clock=clock):
            return segments_clearance(a.segment_ends(t, clock), b.segment_ends(t), radii)
        lipschitz = clock * a.speed_bound() + b.speed_bound()
        soonest = min(soonest, first_below(gap, 0.0, min(horizon, soonest), lipschitz, min_clearance))
    return soonest
