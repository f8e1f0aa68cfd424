"""The ground a body rolls on: one small protocol for every arena.

Beyond the paper, which has one ground, the sphere.  A ground is a fixed
surface of revolution about the vertical z-axis (or the flat plane z = 0).
Physics functions take a ground record and arrays; they never take "a
radius" or the name of a surface.  (The habit of SymBRiM's ground
interface, ``GroundBase.get_normal(position)``: the body asks the ground
where its contact can be and which way the surface faces there.)

A lane on a surface of revolution is a parallel, given by the contact's
``height`` above the surface's lowest point (``lowest`` is that point's z
in the ground's own coordinates: -r for the globe, centred at the origin;
0 for the drum and the cone, whose floor is the plane z = 0).  In the
contact's meridian plane (unit vectors rho-hat horizontal outwards, z-hat
up) every ground answers, vectorised over heights:

* ``contact(height)``: the contact point (rho, z) [m];
* ``wall_angle(height)``: beta [rad], the meridian's angle from the
  horizontal at the contact, the meridian's tangent pointing up the wall
  being (cos beta, sin beta) (0 a floor, pi/2 a vertical wall, over pi/2
  an overhang; on the sphere beta = pi - theta);
* ``normal(height)``: the unit normal (n_rho, n_z) = (-sin beta, cos beta)
  pointing into the concave side, the side a rider rides ("inside");
* ``curvatures(height)``: the principal curvatures (kappa_meridian,
  kappa_parallel) [1/m] of the surface at the contact, positive where it
  bends towards that normal (for a surface of revolution the parallel's
  normal curvature is Meusnier's sin(beta) / rho);
* ``clearance(rho, z)``: the distance [m] of a point of the meridian plane
  from the surface, positive on the inside (a rider's head clearance);
* ``highest_lane``: the greatest height a lane can have [m];
* ``implicit(x, y, z)``, ``gradient(x, y, z)``, ``hessian(x, y, z)``: a
  function F with the surface at F = 0 (F < 0 on the inside) and its first
  and second derivatives, for the equations of motion and for finding a
  contact from a position (complex points pass: a complex step's
  imaginary part is the derivative along it);
* ``arc_length(height)`` and ``meridian(s)``: the meridian by its arc
  length s from the lowest point (on flat ground, from the turn's centre):
  (rho, z, beta, kappa, dkappa) with kappa = d(beta)/ds the meridian's
  curvature and dkappa its rate, analytic in s (the two-wheeler's
  generated equations read the rear contact's meridian so,
  docs/two-wheeler.md sec. 12).
* ``offset(t)``: the parallel surface a distance t [m] inside (the
  surface a torus tyre's crown circle's centre moves on), a ground of the
  same kind, exact for the globe, the drum, the cone and flat ground,
  whose ``quadric()`` is the implicit function as a quadric of
  revolution, (a_rho, a_z, b_z, c) with
  F = a_rho (x^2 + y^2) / 2 + a_z z^2 / 2 + b_z z + c (constant second
  derivatives: the machine's equations of motion, docs/machine.md); for a
  profile a :class:`~deathsphere.physics.ground.profile_offset.ParallelProfile`,
  the meridian moved by t along its normal, which answers a point's
  ``foot`` on the meridian and its distance inside instead (docs/machine.md,
  "On a profile").

* ``local_fit_is_global``: True where the wheel's S4 and the ball's S7,
  tested at the contact, are the whole fit (the globe, the drum, the cone,
  flat ground: proved in docs/surfaces.md, S4g); False for a profile, which
  answers ``tangent_ball_radius(height, outside)`` (the largest ball
  tangent at the lane inside the wall) and ``bends_out(z_low, z_high)``
  (the meridian bending away from the inside between two heights) for the
  rim's and the ball's global check (``physics/rim_fit.py``).

Implementations: :class:`Sphere` (the globe, and the one place the paper's
theta and a height convert), :class:`Cylinder` (the wall of death),
:class:`Cone` (the well of death, a board track), :class:`Plane` (flat
ground, whose lane is a turn radius rather than a height).
"""

from __future__ import annotations

from typing import Protocol, runtime_checkable

import numpy as np

__all__ = ["Ground", "meridian_frame", "as_array"]


@runtime_checkable
class Ground(Protocol):
    """What every ground answers (module docstring); arrays in, arrays out."""

    name: str

    def contact(self, height): ...

    def wall_angle(self, height): ...

    def normal(self, height): ...

    def curvatures(self, height): ...

    def clearance(self, rho, z): ...

    def implicit(self, x, y, z): ...

    def gradient(self, x, y, z): ...

    def hessian(self, x, y, z): ...


def meridian_frame(beta):
    """The tangent up the meridian (cos beta, sin beta) and the inward
    normal (-sin beta, cos beta) at wall angle beta [rad], each as a pair of
    arrays (rho, z components): the frame that splits a contact force into
    friction along the wall and the normal push (docs/surfaces.md)."""
    beta = np.asarray(beta, dtype=float)
    s, c = np.sin(beta), np.cos(beta)
    return (c, s), (-s, c)


def as_array(x):
    """x as a float64 array, or complex128 where it is complex: a ground's
    answers pass a complex step through (the two-wheeler's derivatives are
    taken by one; beyond the paper, docs/two-wheeler.md sec. 12)."""
    x = np.asarray(x)
    return np.asarray(x, dtype=np.result_type(x.dtype, np.float64))
