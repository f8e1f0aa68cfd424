"""Flat ground, the plane z = 0 (the two-wheeler's flat-ground turns)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from deathsphere.physics.ground.protocol import as_array

__all__ = ["Plane"]


@dataclass(frozen=True)
class Plane:
    """Flat ground, the plane z = ``level`` (0 unless it is a parallel
    surface, :meth:`offset`), normal up.  A lane on it is a circle of
    the contact about the turn's centre (radius ``rho``), not a height:
    :meth:`contact` takes that radius."""

    name: str = "plane"
    #: S4 (the wheel) and S7 (the ball) are the whole fit here, not only near
    #: the contact (docs/surfaces.md, S4g).
    local_fit_is_global = True
    level: float = 0.0

    @property
    def lowest(self) -> float:
        """z of the ground [m]."""
        return self.level

    def arc_length(self, rho):
        """The meridian's arc length [m] from the turn's centre: the lane's radius itself."""
        return as_array(rho) + 0.0

    def meridian(self, s):
        """The meridian at arc length ``s`` [m] from the turn's centre: (rho,
        z, beta, kappa, dkappa) = (s, 0, 0, 0, 0) (the two-wheeler's
        generated equations take them; beyond the paper, docs/two-wheeler.md
        sec. 12)."""
        s = np.asarray(s)
        zero = 0.0 * s
        return s + 0.0, zero + self.level, zero.copy(), zero.copy(), zero.copy()

    def contact(self, rho):
        rho = as_array(rho)
        return rho, np.zeros_like(rho) + self.level

    def wall_angle(self, rho):
        return np.zeros(np.shape(rho))

    def normal(self, rho):
        return np.zeros(np.shape(rho)), np.ones(np.shape(rho))

    def clearance(self, rho, z):
        """z - level: a point's height above the ground [m]."""
        return as_array(z) - self.level + 0.0 * as_array(rho)

    def curvatures(self, rho):
        z = np.zeros(np.shape(rho))
        return z, z.copy()

    def implicit(self, x, y, z):
        return self.level - np.broadcast_arrays(x, y, as_array(z))[2]

    def gradient(self, x, y, z):
        x, y, z = np.broadcast_arrays(x, y, as_array(z))
        return np.stack((np.zeros_like(x), np.zeros_like(y), -np.ones_like(z)))

    def hessian(self, x, y, z):
        shape = np.broadcast(x, y, z).shape
        return np.zeros((3, 3) + shape)

    def offset(self, t):
        """The parallel surface a distance ``t`` [m] above: the plane z = level + t."""
        return Plane(level=self.level + t)

    def quadric(self):
        """F = level - z as a quadric of revolution (a_rho, a_z, b_z, c)
        (as :meth:`Sphere.quadric <deathsphere.physics.ground.Sphere.quadric>`)."""
        return 0.0, 0.0, -1.0, np.asarray(self.level, dtype=float)
