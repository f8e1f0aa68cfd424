"""What a body model gives the integrator's driver (beyond the paper;
docs/simulation.md, "Bodies").

A body model is an adapter over a body's physics functions (which stay in
:mod:`deathsphere.physics`, pure and vectorised): it says what the state
is, and for per-body parameters ``p`` it gives the right-hand side, the
contact forces, the energy, the projection back onto the constraints, the
terminal events and what the series records.  The simulation layer owns
the protocol because the events carry the run's statuses
(:class:`~deathsphere.simulation.status.RunStatus`), which physics does not
know of.  Implemented by :data:`deathsphere.simulation.bodies.PAPER` (the
paper's wheel and sphere), :data:`~deathsphere.simulation.bodies.MACHINE`
(a machine) and :data:`deathsphere.simulation.two_wheeler.TWO_WHEELER`
(the Whipple two-wheeler).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Protocol, runtime_checkable

import numpy as np

from deathsphere.simulation.event import Event

__all__ = ["Body"]


@runtime_checkable
class Body(Protocol):
    """The protocol of a body model."""

    #: the model's name
    name: str
    #: the state's rows, by name, and their units
    state_names: tuple[str, ...]
    state_units: tuple[str, ...]
    #: the series' columns beyond the ones every body of the model shares
    series_extras: tuple[str, ...]

    def ode(self, p, frame_rate) -> Callable:
        """The right-hand side f(t, y) of the bodies ``p`` (in a frame
        turning at ``frame_rate`` about the vertical, where the model has
        one), for solve_ivp."""

    def contact_force(self, y, p) -> dict:
        """The contact forces per unit mass at the states y: at least
        ``normal`` and ``friction_magnitude`` (m/s^2)."""

    def energy(self, y, p) -> np.ndarray:
        """The energy per unit mass at the states y (J/kg)."""

    def project(self, y, p) -> np.ndarray:
        """The states y moved back onto the constraints."""

    def terminal_events(self, p, mu) -> Sequence[Event]:
        """The terminal events of the bodies ``p`` with friction ``mu``
        available, for one solve_ivp call."""
