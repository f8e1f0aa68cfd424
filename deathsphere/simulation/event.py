"""One terminal event of a run, as a record (beyond the paper;
docs/simulation.md, "Events").

:func:`scipy.integrate.solve_ivp` takes event callables carrying
``terminal`` and ``direction`` attributes; an :class:`Event` is such a
callable, and also says what the event means: the :class:`RunStatus` it
ends a body with and, through it, the reason words.  Every body's events
are instances (the paper's bodies and the machines, the two-wheeler).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from deathsphere.simulation.status import RunStatus

__all__ = ["Event"]


@dataclass(frozen=True)
class Event:
    """A condition g(t, y) whose zero ends a body with ``status``.

    ``terminal`` and ``direction`` are solve_ivp's: the integration stops
    at the zero, which counts only when g falls through it (-1: a force
    reaching zero from above)."""

    condition: Callable
    status: RunStatus
    terminal: bool = True
    direction: float = -1.0

    def __call__(self, t, y):
        return self.condition(t, y)

    @property
    def reason(self) -> str:
        """The reason words of the status this event ends a body with."""
        return self.status.reason
