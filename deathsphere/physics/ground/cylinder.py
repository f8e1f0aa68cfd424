"""The wall of death: a vertical drum (beyond the paper; docs/surfaces.md)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from deathsphere.physics.ground.protocol import as_array

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
    #: S4 (the wheel) and S7 (the ball) are the whole fit here, not only near
    #: the contact (docs/surfaces.md, S4g).
    local_fit_is_global = True

    #: z of the floor [m].
    lowest = 0.0

    @property
    def highest_lane(self) -> float:
        """The greatest height a lane can have [m] (the wall's top)."""
        return self.wall_height

    def arc_length(self, height):
        """The meridian's arc length [m] from the floor's edge up the wall: the height itself."""
        return as_array(height) + 0.0

    def meridian(self, s):
        """The meridian at arc length ``s`` [m] from the lowest point: (rho,
        z, beta, kappa, dkappa), kappa = d(beta)/ds and dkappa = d(kappa)/ds
        (the two-wheeler's generated equations take them; beyond the paper,
        docs/two-wheeler.md sec. 12).  Analytic in s, so a complex step
        passes through."""
        s = np.asarray(s)
        zero = 0.0 * s
        return zero + self.radius, s + 0.0, zero + np.pi / 2, zero, zero.copy()

    def contact(self, height):
        height = as_array(height)
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
        return self.radius - as_array(rho) + 0.0 * as_array(z)

    def implicit(self, x, y, z):
        x, y, _ = np.broadcast_arrays(x, y, as_array(z))
        return 0.5 * (x * x + y * y - self.radius * self.radius)

    def gradient(self, x, y, z):
        x, y, z = np.broadcast_arrays(as_array(x), y, as_array(z))
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
