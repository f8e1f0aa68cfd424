"""The ground a body rolls on: one small protocol for every arena.

Beyond the paper, which has one ground, the sphere.  A ground is a fixed
surface of revolution about the vertical z-axis (or the flat plane z = 0),
centred as the show's globe is: the sphere's centre at the origin, z up.
Physics functions take a ground record and arrays; they never take "a
radius" or the name of a surface.  (The habit of SymBRiM's ground
interface, ``GroundBase.get_normal(position)``: the body asks the ground
where its contact can be and which way the surface faces there.)

A lane on a surface of revolution is a parallel, given by the contact's
``height`` above the surface's lowest point.  In the contact's meridian
plane (unit vectors rho-hat horizontal outwards, z-hat up) every ground
answers, vectorised over heights:

* ``contact(height)``: the contact point (rho, z) [m];
* ``wall_angle(height)``: beta [rad], the meridian's angle from the
  horizontal at the contact (0 a floor, pi/2 a vertical wall, over pi/2 an
  overhang; on the sphere beta = pi - theta);
* ``normal(height)``: the unit normal (n_rho, n_z) pointing into the
  concave side, the side a rider rides ("inside");
* ``curvatures(height)``: the principal curvatures (kappa_meridian,
  kappa_parallel) [1/m] of the surface at the contact, positive where it
  bends towards that normal;
* ``implicit(x, y, z)``, ``gradient(x, y, z)``, ``hessian(x, y, z)``: a
  function F with the surface at F = 0 (F < 0 on the inside) and its first
  and second derivatives, for the equations of motion and for finding a
  contact from a position.

The sphere's polar angle theta of the paper is one more way to name a lane
there: :meth:`Sphere.theta` and :meth:`Sphere.height` convert, and are the
one place the conversion is written.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np

__all__ = ["Ground", "Sphere", "Plane"]


@runtime_checkable
class Ground(Protocol):
    """What every ground answers (module docstring); arrays in, arrays out."""

    name: str

    def contact(self, height): ...

    def wall_angle(self, height): ...

    def normal(self, height): ...

    def curvatures(self, height): ...

    def implicit(self, x, y, z): ...

    def gradient(self, x, y, z): ...

    def hessian(self, x, y, z): ...


@dataclass(frozen=True)
class Sphere:
    """The globe of McDonald (1993): a sphere of radius ``radius`` [m]
    centred at the origin.  A lane's height is the contact's height above
    the floor (the sphere's lowest point), 0 <= height <= 2 radius."""

    radius: float
    name: str = "sphere"

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

    def contact(self, height):
        theta = self.theta(height)
        return self.radius * np.sin(theta), self.radius * np.cos(theta)

    def wall_angle(self, height):
        return np.pi - self.theta(height)

    def normal(self, height):
        theta = self.theta(height)
        return -np.sin(theta), -np.cos(theta)

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


@dataclass(frozen=True)
class Plane:
    """Flat ground, the plane z = 0, normal up.  A lane on it is a circle of
    the contact about the turn's centre (radius ``rho``), not a height:
    :meth:`contact` takes that radius."""

    name: str = "plane"

    def contact(self, rho):
        rho = np.asarray(rho, dtype=float)
        return rho, np.zeros_like(rho)

    def wall_angle(self, rho):
        return np.zeros(np.shape(rho))

    def normal(self, rho):
        return np.zeros(np.shape(rho)), np.ones(np.shape(rho))

    def curvatures(self, rho):
        z = np.zeros(np.shape(rho))
        return z, z.copy()

    def implicit(self, x, y, z):
        return -np.broadcast_arrays(x, y, np.asarray(z, dtype=float))[2]

    def gradient(self, x, y, z):
        x, y, z = np.broadcast_arrays(x, y, np.asarray(z, dtype=float))
        return np.stack((np.zeros_like(x), np.zeros_like(y), -np.ones_like(z)))

    def hessian(self, x, y, z):
        shape = np.broadcast(x, y, z).shape
        return np.zeros((3, 3) + shape)
