"""A machine's parameters as arrays, the form the physics computes with
(beyond the paper; docs/machine.md sec. 1).

A machine record (:class:`deathsphere.records.machine.Machine`: one
motorcycle and rider) becomes arrays in one place, :func:`machine_arrays`,
as a quantity becomes a number once at the door; every physics function of
the machine takes these arrays with the ground it rolls on and gravity,
which belong to the run and never to the record.  Several records give
arrays over bodies (a show's riders on different machines): every field
broadcasts against the inputs like any other array.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = ["MachineArrays", "machine_arrays", "FIELDS"]


class MachineArrays(NamedTuple):
    """A machine's parameters, float64 arrays broadcasting against the
    inputs (the registry's names and units): ``mass`` [kg],
    ``com_height``, ``wheel_radius``, ``tyre_radius``, ``head_height`` [m]
    (along the up-axis above the contact, upright on flat ground),
    ``roll_inertia``, ``pitch_inertia``, ``yaw_inertia`` (principal, wheels
    locked, about the centre of mass) and ``spin_inertia`` (the wheels'
    polar moments) [kg m^2]."""

    mass: np.ndarray
    com_height: np.ndarray
    wheel_radius: np.ndarray
    tyre_radius: np.ndarray
    roll_inertia: np.ndarray
    pitch_inertia: np.ndarray
    yaw_inertia: np.ndarray
    spin_inertia: np.ndarray
    head_height: np.ndarray

    def map(self, fn) -> MachineArrays:
        """The arrays with ``fn`` applied to each (a reshape, an index)."""
        return MachineArrays(*(fn(x) for x in self))

    def flat(self, n: int) -> MachineArrays:
        """Each field broadcast to (n,) (one value per body)."""
        return self.map(lambda x: np.broadcast_to(x, (n,)))

    def take(self, index, n: int | None = None) -> MachineArrays:
        """The bodies ``index`` of arrays over bodies (``n`` bodies when a
        field may be a single value)."""
        if n is not None:
            return self.flat(n).map(lambda x: x[index])
        return self.map(lambda x: np.asarray(x)[index])

    def expand(self, axis) -> MachineArrays:
        """Each field with a new axis of one at ``axis`` (to broadcast
        against one more input axis)."""
        return self.map(lambda x: np.expand_dims(x, axis))


FIELDS = MachineArrays._fields


def machine_arrays(machines) -> MachineArrays:
    """The arrays of one machine record (0-d arrays) or of a sequence of
    them ((n,) arrays, one value per body); :class:`MachineArrays` are
    returned as they are.  A record is anything with the attributes
    :data:`FIELDS` (the registry's names).  Beyond the paper: docs/machine.md
    sec. 1, the machine's parameters."""
    if isinstance(machines, MachineArrays):
        return machines
    if isinstance(machines, (list, tuple)):
        return MachineArrays(*(np.array([float(getattr(m, f)) for m in machines], dtype=np.float64)
                               for f in FIELDS))
    return MachineArrays(*(np.asarray(float(getattr(machines, f)), dtype=np.float64) for f in FIELDS))
