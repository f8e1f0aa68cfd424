"""The one call of :func:`scipy.integrate.solve_ivp` for rigid bodies
(beyond the paper; docs/simulation.md, "Method").

Every body's run goes through :func:`integrate`: the paper's bodies and the
machines (period by period, from :class:`deathsphere.simulation.runner.Simulation`)
and the two-wheeler (one call, :mod:`deathsphere.simulation.two_wheeler`); so
does the 3-D view's re-integration between recorded samples
(:mod:`deathsphere.simulation.frames`, without events).
It returns the solution with the terminal :class:`Event` that stopped it,
if one did, so that every caller reads the event the same way.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.integrate import OdeSolution, solve_ivp

from deathsphere.simulation.event import Event

__all__ = ["Solved", "integrate", "past_at_start"]


@dataclass(frozen=True)
class Solved:
    """One integration: solve_ivp's solution ``sol`` and, when a terminal
    event stopped it, that event, its index in the events given, its time
    and state (``event`` None, ``t_event`` nan otherwise)."""

    sol: object
    event: Event | None = None
    k_event: int = -1
    t_event: float = np.nan
    y_event: np.ndarray | None = None


def integrate(fun: Callable, t_span, y0, events: Sequence[Event], *, method: str, rtol: float, atol,
              t_eval=None, dense_output: bool = False, vectorized: bool = False, kinks: Callable | None = None,
              **options) -> Solved:
    """Integrate y' = fun(t, y) over ``t_span`` from ``y0`` with
    solve_ivp (``method``, ``rtol``, ``atol``, ``t_eval``, ``dense_output``,
    ``vectorized`` and the ``options`` passed through as they are), stopping
    at the first terminal event of ``events`` (none: an empty sequence).

    ``kinks(y)``: where fun is not smooth, a continuous index per body that
    is a whole number at each kink (a profile's spline knot under the
    contact); the integration is then restarted wherever a body's index
    crosses a whole number, so that no step straddles a kink (an embedded
    error estimate does not see one: docs/simulation.md, "On any ground").
    The pieces' dense outputs are joined into one."""
    if kinks is None or t_eval is not None:
        return _events_of(_piece(fun, t_span, y0, events, method, rtol, atol, t_eval, dense_output, vectorized,
                                 options), events)
    t0, t_end, y = float(t_span[0]), float(t_span[1]), np.asarray(y0, dtype=float)
    pieces = []
    while True:
        crossing = _next_kink(kinks, fun, t0, y, t_end - t0)
        sol = _piece(fun, (t0, t_end), y, [*events, crossing], method, rtol, atol, None, dense_output,
                     vectorized, options)
        at_kink = sol.status == 1 and len(sol.t_events[-1]) > 0 and not any(
            len(times) and times[0] < sol.t_events[-1][0] for times in sol.t_events[:-1])
        if at_kink and not sol.t[-1] > t0:
            # a kink found where the piece starts (a root the start's side misread):
            # this piece goes on without the kinks' event
            sol = _piece(fun, (t0, t_end), y, events, method, rtol, atol, None, dense_output, vectorized,
                         options)
            at_kink = False
        if not at_kink:
            pieces.append(sol)
            break
        # the step that found the kink straddled it: it is taken again from its
        # start up to the kink, which solve_ivp then never steps past
        t_kink = float(sol.t[-1])
        head = _without_last_step(sol)
        redo = _piece(fun, (float(sol.t[-2]), t_kink), sol.y[:, -2], events, method, rtol, atol, None,
                      dense_output, vectorized, options)
        pieces += [head, redo] if head is not None else [redo]
        if redo.status != 0:     # an event of its own before the kink, or a failure
            break
        t0, y = float(redo.t[-1]), np.asarray(redo.y[:, -1], dtype=float)
    return _events_of(_joined(pieces), events)


def _without_last_step(sol):
    """A solve_ivp result less its last step (None when it took one)."""
    if len(sol.t) <= 2:
        return None
    out = type(sol)(**dict(sol))
    out.t, out.y = sol.t[:-1], sol.y[:, :-1]
    if sol.sol is not None:
        out.sol = OdeSolution(sol.sol.ts[:-1], sol.sol.interpolants[:-1])
    return out


def _piece(fun, t_span, y0, events, method, rtol, atol, t_eval, dense_output, vectorized, options):
    """The one solve_ivp call."""
    # no events: None, solve_ivp's own default (no event bookkeeping at all)
    return solve_ivp(fun, t_span, y0, method=method, t_eval=t_eval, events=list(events) or None, rtol=rtol,
                     atol=atol, dense_output=dense_output, vectorized=vectorized, **options)


def _next_kink(kinks, fun, t0, y0, span):
    """The event of the next kink from (t0, y0): each body's index leaving
    the interval between whole numbers it is heading into (a body on a
    whole number goes the way its index moves, read a step of 1e-9 of the
    span ahead), the least over the bodies; terminal, falling through 0."""
    u0 = np.atleast_1d(np.asarray(kinks(y0), dtype=float))
    ahead = np.atleast_1d(np.asarray(kinks(y0 + 1e-9 * span * np.asarray(fun(t0, y0), dtype=float).reshape(
        np.shape(y0))), dtype=float))
    lower = np.floor(u0)
    on_whole = np.abs(u0 - np.round(u0)) <= 1e-9
    lower = np.where(on_whole, np.where(ahead >= u0, np.round(u0), np.round(u0) - 1.0), lower)
    finite = np.isfinite(u0)
    lower = np.where(finite, lower, 0.0)

    def inside(t, y):
        u = np.atleast_1d(np.asarray(kinks(y), dtype=float))
        gap = np.minimum(u - lower, lower + 1.0 - u)
        return float(np.min(np.where(finite & np.isfinite(u), gap, 1.0)))

    inside.terminal, inside.direction = True, -1.0
    return inside


def _joined(pieces):
    """One solve_ivp result from consecutive pieces: their steps, one dense
    output, the counts summed, the last piece's status and events."""
    if len(pieces) == 1:
        return pieces[0]
    last = pieces[-1]
    out = type(last)(**dict(last))
    out.t = np.concatenate([p.t if i == 0 else p.t[1:] for i, p in enumerate(pieces)])
    out.y = np.concatenate([p.y if i == 0 else p.y[:, 1:] for i, p in enumerate(pieces)], axis=1)
    if last.sol is not None:
        ts = np.concatenate([p.sol.ts if i == 0 else p.sol.ts[1:] for i, p in enumerate(pieces)])
        out.sol = OdeSolution(ts, [f for p in pieces for f in p.sol.interpolants])
    for count in ("nfev", "njev", "nlu"):
        setattr(out, count, sum(int(getattr(p, count)) for p in pieces))
    return out


def _events_of(sol, events: Sequence[Event]) -> Solved:
    # the earliest event that fired (solve_ivp records at most one terminal
    # event per call; the earliest, and the first on a tie, if ever more)
    if sol.t_events is not None and len(sol.t_events) > len(events):
        sol.t_events, sol.y_events = sol.t_events[:len(events)], sol.y_events[:len(events)]
    k_event, t_event = -1, np.nan
    for k, times in enumerate(sol.t_events or ()):
        if len(times) and not t_event <= times[0]:
            k_event, t_event = k, float(times[0])
    if k_event < 0:
        return Solved(sol)
    return Solved(sol, events[k_event], k_event, t_event, np.asarray(sol.y_events[k_event][0]))


def past_at_start(events: Sequence[Event], t0, y0) -> int:
    """The index of the event already at or below zero at (t0, y0) (the
    least value), or -1: such an event is no crossing, and solve_ivp would
    never see it."""
    start = [e(t0, y0) for e in events]
    return int(np.argmin(start)) if min(start) <= 0 else -1
