"""The wall of death: a vertical drum (beyond the paper; docs/surfaces.md)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Cylinder"]


@dataclass(frozen=True)
class Cylinder:
    """A vertical circular drum of radius ``radius`` [m] about the z-axis,
    its wall rising from the floor z = 0 to ``wall_height`` [m] (inf: no
    top).  A lane's height is the contact's height above the floor, on the
    wall: 0 <= height <= wall_height.  The wall angle is pi/2 everywhere;
    the inside is the drum's interior (rho < radius)."""

    radius: float
    wall_height: float = math.inf
    name: str = "cylinder"

    #: z of the floor [m].
    lowest = 0.0

    @property
    def highest_lane(self) -> float:
        """The greatest height a lane can have [m] (the wall's top)."""
        return self.wall_height

    def contact(self, height):
        height = np.asarray(height, dtype=float)
        return np.full(height.shape, float(self.radius)), height + 0.0

    def wall_angle(self, height):
        return np.full(np.shape(height), np.pi / 2)

    def normal(self, height):
        # exactly (-1, 0): (-sin beta, cos beta) at beta = pi/2 without cos's 6e-17
        shape = np.shape(height)
        return np.full(shape, -1.0), np.zeros(shape)

    def curvatures(self, height):
        shape = np.shape(height)
        return np.zeros(shape), np.full(shape, 1.0 / self.radius)

    def clearance(self, rho, z):
        """radius - rho: a point's distance from the wall inside [m]."""
        return self.radius - np.asarray(rho, dtype=float) + 0.0 * np.asarray(z, dtype=float)

    def implicit(self, x, y, z):
        x, y, _ = np.broadcast_arrays(x, y, np.asarray(z, dtype=float))
        return 0.5 * (x * x + y * y - self.radius * self.radius)

    def gradient(self, x, y, z):
        x, y, z = np.broadcast_arrays(np.asarray(x, dtype=float), y, np.asarray(z, dtype=float))
        return np.stack((x + 0.0, y + 0.0, np.zeros_like(z)))

    def hessian(self, x, y, z):
        shape = np.broadcast(x, y, z).shape
        h = np.diag([1.0, 1.0, 0.0]).reshape((3, 3) + (1,) * len(shape))
        return np.broadcast_to(h, (3, 3) + shape)

    def offset(self, t):
        """The parallel surface a distance ``t`` [m] inside: the coaxial
        drum of radius radius - t (the same wall height)."""
        return Cylinder(self.radius - t, self.wall_height)

    def quadric(self):
        """F = (x^2 + y^2 - radius^2) / 2 as a quadric of revolution
        (a_rho, a_z, b_z, c) (:meth:`Sphere.quadric <deathsphere.physics.ground.Sphere.quadric>`)."""
        return 1.0, 0.0, 0.0, -0.5 * np.asarray(self.radius, dtype=float) ** 2
