"""Where a two-wheeler's run stands on a wall: the rear contact's lane (its
height above the ground's lowest point and its distance from the axis) and
the height of the wheels' lowest rim points above the floor, at the
coordinates of a run on any surface of revolution (beyond the paper;
docs/two-wheeler.md sec. 12.7).

These are what the run on a drum or a cone reports beside the globe's
columns and what its wall events watch: the rear contact passing the
wall's top (its height against the wall's highest lane) and a wheel
reaching the floor (the lower of the two rims' lowest points against the
ground's lowest point).  Vectors are in the inertial frame N (z down), as
in :mod:`~deathsphere.physics.two_wheeler.geometry`; heights are the
ground's (z up).
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.two_wheeler import geometry
from deathsphere.physics.two_wheeler.parameters import BicycleParameters

__all__ = ["rear_lane", "lowest_rim_height"]


def rear_lane(q, ground):
    """(height, rho) (...) of the rear contact at the coordinates q (8, ...)
    of a run on the surface of revolution ``ground``: q0 is the rear
    contact's arc length up the meridian, so (rho, z) = meridian(q0) and the
    height is z above the ground's lowest point [m] (beyond the paper;
    docs/two-wheeler.md sec. 12.7)."""
    rho, z = ground.meridian(np.asarray(q)[0])[:2]
    return np.asarray(z, float) - float(ground.lowest), np.asarray(rho, float)


def _lowest_on_rim(centre, normal, radius):
    """The height (z up) of the lowest point of the circle of ``radius``
    about ``centre`` (3, ...) in N in the plane normal to the unit
    ``normal`` (3, ...): the centre's height less radius times the length
    of the downward unit vector's part in the plane, sqrt(1 - n_z^2)."""
    in_plane = np.sqrt(np.clip(1.0 - normal[2] * normal[2], 0.0, 1.0))
    return -centre[2] - radius * in_plane


def lowest_rim_height(q, parameters: BicycleParameters, ground):
    """The height [m] (...) of the lower of the two wheels' lowest rim
    points above the ground's lowest point (the floor at the foot of a drum
    or a cone), at the coordinates q (8, ...): the rear rim in the plane
    normal to the lean frame's L.y about the rear wheel's centre, the front
    rim normal to the front frame's E.y about the front wheel's centre
    (beyond the paper; docs/two-wheeler.md sec. 12.7)."""
    p = parameters
    pts = geometry.points(q, p, ground)
    f = pts["frames"]
    rear = _lowest_on_rim(pts["rear_wheel"], f["L"][1], p.rR)
    front = _lowest_on_rim(pts["front_wheel"], f["E"][1], p.rF)
    return np.minimum(rear, front) - float(ground.lowest)
