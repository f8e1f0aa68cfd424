"""The terminal events of a run: contact lost and slipping, and on a wall
the floor and the wall's top (beyond the paper; docs/simulation.md, "Events").

Both are functions of the state through the contact force of the body
model (:mod:`deathsphere.simulation.bodies`: the paper's bodies'
:func:`deathsphere.physics.dynamics.contact_force`, a machine's eq. M18): the normal force N / g
(``contact_lost`` where it falls to zero) and (mu N - |F_friction|) / g
(``slips`` where it does, only for a finite mu).  The bodies integrated
together share one solve_ivp call, so each event is the least value over
them; :data:`EVENT_TOL` decides which others reached zero at the same time.
A body model on a wall adds its own conditions (``model.wall_conditions``:
the body's lowest point above the floor, the contact below the wall's top,
in metres), after these two.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from deathsphere.physics import dynamics as dyn
from deathsphere.simulation.event import Event
from deathsphere.simulation.status import RunStatus

__all__ = ["ContactEvents", "EVENT_STATUSES", "EVENT_TOL", "stopped_at_start"]

#: the status each event ends a body with, in the order of
#: :meth:`ContactEvents.events` and :meth:`ContactEvents.values`
EVENT_STATUSES = (RunStatus.CONTACT_LOST, RunStatus.SLIPS)

#: event values (force / g) at or below this count as "reached zero" for
#: every body at an event (identical bodies reach zero together).
EVENT_TOL = 1e-9


@dataclass
class ContactEvents:
    """The terminal events of the bodies integrated together right now (a
    subset of the run), for :func:`scipy.integrate.solve_ivp`: a sequence
    of :class:`Event` (in the order of :data:`EVENT_STATUSES`) whose values
    per body :meth:`values` gives."""

    params: dyn.BodyParams
    mu: np.ndarray
    g: np.ndarray
    model: object              # the body model (simulation.bodies) of params
    _cache: tuple = field(default=(None, None, None))
    _scalar: tuple | None = None
    _events: list = field(default_factory=list)
    #: the model's (status, condition(state) [m]) pairs beyond contact and slipping
    _walls: tuple = ()

    def __post_init__(self):
        if self.mu.size == 1:      # the model's one-body float path, if it has one
            self._scalar = self.model.scalar_events(self.params)
        self._walls = tuple(self.model.wall_conditions(self.params))
        self._events = self.events()

    def __len__(self):
        return len(self._events)

    def __getitem__(self, k):
        return self._events[k]

    def values(self, t, y):
        """(normal/g, (mu N - |F|)/g) per body at (t, y), cached for the
        repeated calls solve_ivp makes with one (t, y)."""
        last_t, last_y, vals = self._cache
        if last_y is not None and t == last_t and (y is last_y or np.array_equal(y, last_y)):
            return vals
        if self._scalar is not None and y.ndim == 1 and not self._walls:
            try:          # one body: the same equations on Python floats
                n, fmag = self.model.contact_values(y.tolist(), self._scalar)
                mu = float(self.mu[0])
                slip = mu * n - fmag if math.isfinite(mu) else 1.0
                vals = (np.array([n]) / self.g, np.array([slip]) / self.g)
                self._cache = (t, y, vals)
                return vals
            except (ZeroDivisionError, OverflowError, ValueError):
                pass
        state = np.asarray(y).reshape(9, -1)
        f = self.model.contact_force(state, self.params)
        n = f["normal"]
        finite = np.isfinite(self.mu)
        slip = np.where(finite, np.where(finite, self.mu, 0.0) * n - f["friction_magnitude"], 1.0)
        vals = (n / self.g, slip / self.g) + tuple(condition(state) for _, condition in self._walls)
        self._cache = (t, y, vals)
        return vals

    def events(self) -> list[Event]:
        """The terminal events (least value over the bodies), in the order
        of :data:`EVENT_STATUSES`, then the model's wall conditions."""
        def least(k):
            return lambda t, y: float(np.min(self.values(t, y)[k]))

        statuses = EVENT_STATUSES + tuple(status for status, _ in self._walls)
        return [Event(least(k), status) for k, status in enumerate(statuses)]


def stopped_at_start(normal, friction, mu):
    """Masks (lost, slip) of bodies with no contact (N <= 0) or slipping
    (mu N <= |F|) at the start, where no event can fire: from the normal
    force and the friction magnitude per unit mass and the mu available."""
    finite = np.isfinite(mu)
    lost = ~(normal > 0)
    slip = ~lost & finite & ~(np.where(finite, mu, 0.0) * normal - friction > 0)
    return lost, slip
