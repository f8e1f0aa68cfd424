"""The well of death and the banked track: a cone about the vertical axis
(beyond the paper; docs/surfaces.md)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from deathsphere.physics.ground.protocol import as_array

__all__ = ["Cone"]


def _radius(x, y):
    """The distance from the axis: hypot for real points; sqrt(x^2 + y^2), analytic, for a complex step
    (the two-wheeler's front contact takes the implicit function's derivatives by one)."""
    if np.iscomplexobj(x) or np.iscomplexobj(y):
        return np.sqrt(x * x + y * y)
    return np.hypot(x, y)


@dataclass(frozen=True)
class Cone:
    """A cone about the z-axis: its wall meets the floor z = 0 on the circle
    of radius ``radius`` [m] and rises at ``wall_angle`` beta [rad] from the
    horizontal (0 < beta < pi): pi/2 is the drum, under pi/2 it leans out
    (a well of death at about 80 degrees, a board track at 45), over pi/2
    it leans in.  The contact at height h above the floor is at
    rho = radius + h cot(beta); a lane runs from the floor up to
    ``wall_height`` [m] (inf: no top) and, leaning in, below the apex."""

    radius: float
    wall_angle_rad: float
    wall_height: float = math.inf
    name: str = "cone"
    #: S4 (the wheel) and S7 (the ball) are the whole fit here, not only near
    #: the contact (docs/surfaces.md, S4g).
    local_fit_is_global = True

    #: z of the floor [m].
    lowest = 0.0

    @property
    def apex_height(self) -> float:
        """The height where a wall leaning in meets the axis [m] (inf when it leans out or is vertical)."""
        if self.wall_angle_rad <= math.pi / 2:
            return math.inf
        return self.radius * math.tan(math.pi - self.wall_angle_rad)

    @property
    def highest_lane(self) -> float:
        """The greatest height a lane can have [m]: the wall's top, or the apex."""
        return min(self.wall_height, self.apex_height)

    def _cot(self) -> float:
        # cos/sin, exactly 0 for the upright wall (cos(pi/2) is 6e-17)
        if self.wall_angle_rad == math.pi / 2:
            return 0.0
        return math.cos(self.wall_angle_rad) / math.sin(self.wall_angle_rad)

    def _sin(self) -> float:
        return 1.0 if self.wall_angle_rad == math.pi / 2 else math.sin(self.wall_angle_rad)

    def arc_length(self, height):
        """The meridian's arc length [m] from the floor's edge up the wall: height / sin(beta)."""
        return as_array(height) / self._sin()

    def meridian(self, s):
        """The meridian at arc length ``s`` [m] from the lowest point: (rho,
        z, beta, kappa, dkappa), kappa = d(beta)/ds and dkappa = d(kappa)/ds
        (the two-wheeler's generated equations take them; beyond the paper,
        docs/two-wheeler.md sec. 12).  Analytic in s, so a complex step
        passes through."""
        s = np.asarray(s)
        zero = 0.0 * s
        cos_beta = self._cot() * self._sin()
        return self.radius + s * cos_beta, s * self._sin(), zero + self.wall_angle_rad, zero, zero.copy()

    def contact(self, height):
        height = as_array(height)
        return self.radius + height * self._cot(), height + 0.0

    def wall_angle(self, height):
        return np.full(np.shape(height), float(self.wall_angle_rad))

    def normal(self, height):
        shape = np.shape(height)
        cos_beta = 0.0 if self.wall_angle_rad == math.pi / 2 else math.cos(self.wall_angle_rad)
        return np.full(shape, -math.sin(self.wall_angle_rad)), np.full(shape, cos_beta)

    def curvatures(self, height):
        rho, _ = self.contact(height)
        safe = np.where(rho > 0, rho, 1.0)
        # Meusnier: the parallel's normal curvature sin(beta) / rho; the generator is straight
        return np.zeros(np.shape(rho)), np.where(rho > 0, math.sin(self.wall_angle_rad) / safe, np.inf)

    def clearance(self, rho, z):
        """The distance [m] of a point inside from the cone's generator line
        through (radius, 0): (p - (radius, 0)) . n with n the inward normal
        (the distance to the wall wherever the foot of the perpendicular
        lies on it)."""
        n_rho, n_z = -math.sin(self.wall_angle_rad), math.cos(self.wall_angle_rad)
        return (as_array(rho) - self.radius) * n_rho + as_array(z) * n_z

    def implicit(self, x, y, z):
        """F = (rho - radius) sin(beta) - z cos(beta): the signed distance
        from the generator (F < 0 inside)."""
        x, y, z = np.broadcast_arrays(as_array(x), y, as_array(z))
        return -self.clearance(_radius(x, y), z)

    def _rho(self, x, y):
        x, y = np.broadcast_arrays(as_array(x), as_array(y))
        rho = _radius(x, y)
        # on the axis the cone's function is not differentiable: its values
        # there are the limit along +x (the axis is never a contact)
        on_axis = rho == 0
        return np.where(on_axis, 1.0, x), np.where(on_axis, 0.0, y), np.where(on_axis, 1.0, rho)

    def gradient(self, x, y, z):
        x, y, z = np.broadcast_arrays(as_array(x), y, as_array(z))
        xs, ys, rho = self._rho(x, y)
        s, c = math.sin(self.wall_angle_rad), math.cos(self.wall_angle_rad)
        return np.stack((s * xs / rho, s * ys / rho, np.full(z.shape, -c)))

    def hessian(self, x, y, z):
        x, y, z = np.broadcast_arrays(as_array(x), y, as_array(z))
        xs, ys, rho = self._rho(x, y)
        s = math.sin(self.wall_angle_rad)
        ux, uy = xs / rho, ys / rho
        zero = np.zeros(x.shape)
        hxx, hxy, hyy = s * (1 - ux * ux) / rho, -s * ux * uy / rho, s * (1 - uy * uy) / rho
        return np.stack((np.stack((hxx, hxy, zero)), np.stack((hxy, hyy, zero)), np.stack((zero, zero, zero))))

    def offset(self, t):
        """The parallel surface a distance ``t`` [m] inside: the cone of
        the same wall angle whose generator is moved by t along the inward
        normal (-sin beta, cos beta), so that it meets the floor's plane at
        radius - t / sin(beta) (its apex moved along the axis by
        -t / cos(beta)); the same wall height."""
        return Cone(self.radius - t / math.sin(self.wall_angle_rad), self.wall_angle_rad, self.wall_height)

    def quadric(self):
        """The cone as a quadric of revolution (a_rho, a_z, b_z, c) (as
        :meth:`Sphere.quadric <deathsphere.physics.ground.Sphere.quadric>`):
        F = ((x^2 + y^2) s^2 - (radius s + z c)^2) / 2, s, c = sin, cos of
        the wall angle.  It is (rho s - radius s - z c) (rho s + radius s +
        z c) / 2, the generator's signed distance times rho s on the wall:
        the same zero set, sign and normal near the wall as :meth:`implicit`,
        and its second derivatives constant (the equations of motion of a
        tyre's crown point need no third derivative)."""
        s = math.sin(self.wall_angle_rad)
        c = 0.0 if self.wall_angle_rad == math.pi / 2 else math.cos(self.wall_angle_rad)
        r = np.asarray(self.radius, dtype=float)
        return s * s, -c * c, -r * s * c, -0.5 * (r * s) ** 2
