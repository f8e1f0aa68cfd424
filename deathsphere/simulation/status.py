"""Final statuses of a simulated body (beyond the paper; docs/simulation.md, "Events").

Every body of a run ends in one :class:`RunStatus`; the summary's ``status``
column holds its :attr:`RunStatus.label` and ``reason`` the words.  These
are the simulation's own statuses, beside
:class:`deathsphere.physics.status.Status` of steady orbits: ``no_fit`` and
``no_orbit`` are decided there (no steady orbit to start from), the others
by what happens during the integration.
"""

from __future__ import annotations

from enum import IntEnum

import numpy as np

__all__ = ["RunStatus", "STATUSES", "RUN_LABELS", "ENDED_EARLY", "ENDED_EARLY_LABELS", "NO_FIT_VERTICAL_REASON", "failed_reason", "status_labels"]


class RunStatus(IntEnum):
    """How the run of one body ended (int8 codes in the per-body arrays)."""

    #: no final status yet: the body can be integrated (or is being)
    PENDING = 0
    #: ran the requested time
    COMPLETED = 1
    #: the normal force fell to zero (terminal event)
    CONTACT_LOST = 2
    #: the friction needed reached mu times the normal force (terminal event)
    SLIPS = 3
    #: the body does not fit on the orbit: nothing is integrated
    NO_FIT = 4
    #: no steady orbit to start from (Omega^2 <= 0, no root of eq. 55)
    NO_ORBIT = 5
    #: the integrator gave up
    FAILED = 6
    #: the body's lowest point reached the floor at the wall's foot (a drum's
    #: or a cone's; terminal event)
    HITS_FLOOR = 7
    #: the contact passed the wall's top edge (terminal event)
    OVER_THE_TOP = 8

    @property
    def label(self) -> str:
        """The text of the summary's ``status`` column ('' while pending)."""
        return "" if self is RunStatus.PENDING else self.name.lower()

    @property
    def reason(self) -> str:
        """The reason words of a status that has fixed ones; '' for
        ``no_fit`` / ``no_orbit`` (their words come from the orbit's
        physics) and ``failed`` (:func:`failed_reason`)."""
        return _FIXED_REASONS.get(self, "")


_FIXED_REASONS = {
    RunStatus.COMPLETED: "ran the requested time",
    RunStatus.CONTACT_LOST: "the normal force fell to zero: the body leaves the surface",
    RunStatus.SLIPS: "the friction needed reached mu times the normal force: the body slips",
    RunStatus.HITS_FLOOR: "the body's lowest point reached the floor at the foot of the wall",
    RunStatus.OVER_THE_TOP: "the contact passed the wall's top edge: the body leaves the wall",
}

#: Reason of a wheel that does not fit on a vertical circle.
NO_FIT_VERTICAL_REASON = "the wheel does not fit on this vertical circle (needs r sin(theta) > a inside)"

#: Final statuses (summary column ``status``), in code order.
STATUSES = tuple(s.label for s in RunStatus if s is not RunStatus.PENDING)

#: the statuses of a run that ended before its time, at an event time
#: (the summary's event time; ``failed``: where the integrator gave up)
ENDED_EARLY = (RunStatus.CONTACT_LOST, RunStatus.SLIPS, RunStatus.FAILED, RunStatus.HITS_FLOOR,
               RunStatus.OVER_THE_TOP)
ENDED_EARLY_LABELS = tuple(s.label for s in ENDED_EARLY)

#: label of every code, indexable by an int8 code array
RUN_LABELS = np.array([s.label for s in RunStatus], dtype=object)


def failed_reason(message: str) -> str:
    """Reason words of a ``failed`` body: the integrator's own message."""
    return f"integrator failed: {message}"


def status_labels(codes) -> np.ndarray:
    """Object array of the status texts of int8 :class:`RunStatus` codes."""
    return RUN_LABELS[np.asarray(codes, dtype=np.int8)]
