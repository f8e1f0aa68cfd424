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
from scipy.integrate import solve_ivp

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
              t_eval=None, dense_output: bool = False, vectorized: bool = False, **options) -> Solved:
    """Integrate y' = fun(t, y) over ``t_span`` from ``y0`` with
    solve_ivp (``method``, ``rtol``, ``atol``, ``t_eval``, ``dense_output``,
    ``vectorized`` and the ``options`` passed through as they are), stopping
    at the first terminal event of ``events`` (none: an empty sequence)."""
    # no events: None, solve_ivp's own default (no event bookkeeping at all)
    sol = solve_ivp(fun, t_span, y0, method=method, t_eval=t_eval, events=list(events) or None, rtol=rtol,
                    atol=atol, dense_output=dense_output, vectorized=vectorized, **options)
    # the earliest event that fired (solve_ivp records at most one terminal
    # event per call; the earliest, and the first on a tie, if ever more)
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
