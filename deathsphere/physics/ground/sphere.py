"""The globe of McDonald (1993): a sphere centred at the origin."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Sphere"]


@dataclass(frozen=True)
class Sphere:
    """The globe of McDonald (1993): a sphere of radius ``radius`` [m]
    centred at the origin.  A lane's height is the contact's height above
    the floor (the sphere's lowest point), 0 <= height <= 2 radius."""

    radius: float
    name: str = "sphere"
    #: S4 (the wheel) and S7 (the ball) are the whole fit here, not only near
    #: the contact (docs/surfaces.md, S4g).
    local_fit_is_global = True

    @property
    def lowest(self) -> float:
        """z of the floor [m]."""
        return -self.radius

    @property
    def highest_lane(self) -> float:
        """The greatest height a lane can have [m] (the top)."""
        return 2.0 * self.radius

    def theta(self, height):
        """The paper's polar angle theta [rad] of the contact at ``height``
        [m] above the floor: theta = arccos(height / r - 1) (height outside
        [0, 2 r] is clipped to the poles)."""
        return np.arccos(np.clip(np.asarray(height, dtype=float) / self.radius - 1.0, -1.0, 1.0))

    def height(self, theta):
        """The contact's height [m] above the floor at polar angle theta
        [rad]: r (1 + cos theta)."""
        return self.radius * (1.0 + np.cos(theta))

    def arc_length(self, height):
        """The meridian's arc length [m] from the floor to the lane at ``height``: r (pi - theta)."""
        return self.radius * (np.pi - self.theta(height))

    def meridian(self, s):
        """The meridian at arc length ``s`` [m] from the lowest point: (rho,
        z, beta, kappa, dkappa), kappa = d(beta)/ds and dkappa = d(kappa)/ds
        (the two-wheeler's generated equations take them; beyond the paper,
        docs/two-wheeler.md sec. 12).  Analytic in s, so a complex step
        passes through."""
        beta = np.asarray(s) / self.radius
        one = np.ones_like(beta)
        return (self.radius * np.sin(beta), -self.radius * np.cos(beta), beta, one / self.radius, 0.0 * beta)

    def contact(self, height):
        theta = self.theta(height)
        return self.radius * np.sin(theta), self.radius * np.cos(theta)

    def wall_angle(self, height):
        return np.pi - self.theta(height)

    def normal(self, height):
        theta = self.theta(height)
        return -np.sin(theta), -np.cos(theta)

    def clearance(self, rho, z):
        """r - |(rho, z)|: the distance of a point inside from the sphere [m]."""
        return self.radius - np.hypot(rho, z)

    def curvatures(self, height):
        k = np.full(np.shape(height), 1.0 / self.radius)
        return k, k.copy()

    def implicit(self, x, y, z):
        return 0.5 * (x * x + y * y + z * z - self.radius * self.radius)

    def gradient(self, x, y, z):
        return np.stack(np.broadcast_arrays(x, y, z))

    def hessian(self, x, y, z):
        shape = np.broadcast(x, y, z).shape
        return np.broadcast_to(np.eye(3).reshape((3, 3) + (1,) * len(shape)), (3, 3) + shape)

    def offset(self, t):
        """The parallel surface a distance ``t`` [m] inside (a tyre's crown
        circle's centre moves on it): the concentric sphere of radius r - t."""
        return Sphere(self.radius - t)

    def quadric(self):
        """F = (x^2 + y^2 + z^2 - r^2) / 2 as a quadric of revolution
        (a_rho, a_z, b_z, c): F = a_rho (x^2 + y^2) / 2 + a_z z^2 / 2 + b_z z + c."""
        return 1.0, 1.0, 0.0, -0.5 * np.asarray(self.radius, dtype=float) ** 2
