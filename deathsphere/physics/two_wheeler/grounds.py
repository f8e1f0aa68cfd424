"""The grounds the two-wheeler's equations are generated for, and what the
equations ask of each: the one place a ground record
(:mod:`deathsphere.physics.ground`) picks its generated functions and its
terms (beyond the paper; docs/two-wheeler.md sec. 3 and 8).

The derivation writes one set of functions per ground: flat ground
(:class:`~deathsphere.physics.ground.Plane`, q = x, y, heading, ...) and the
inside of a sphere (:class:`~deathsphere.physics.ground.Sphere`, q = theta,
azimuth, heading, ...; its radius appended to the parameters).
:func:`of` gives, for a ground record, an object with those functions
(``equations``, ``holonomic``, ``energy``, ``front_contact``,
``constraint_matrix``, ``forcing_at_rest``) and the few places where the
two grounds' kinematics differ, each written once here.  Vectors are arrays
(3, ...) in the inertial frame N (z down) with a trailing batch, as in
:mod:`~deathsphere.physics.two_wheeler.geometry`.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.ground import Plane, Sphere
from deathsphere.physics.two_wheeler import _generated

__all__ = ["POLE", "OnPlane", "OnSphere", "of"]

#: Lanes closer to a pole than this (rad) are refused: the sphere's coordinates are singular there.
POLE = 1e-6
#: The heading's index in q.
_HEADING = 2


def _horizontal(v):
    return np.stack([v[0], v[1], np.zeros_like(v[2])])


class OnPlane:
    """Flat ground: a lane is the path's curvature kappa [1/m]; the rear
    contact is (x, y) = (q0, q1)."""

    #: The derivation's name of the ground (its generated functions' prefix).
    surface = "flat"
    equations = staticmethod(_generated.flat_equations)
    holonomic = staticmethod(_generated.flat_holonomic)
    energy = staticmethod(_generated.flat_energy)
    front_contact = staticmethod(_generated.flat_front_contact)
    constraint_matrix = staticmethod(_generated.flat_constraint_matrix)
    forcing_at_rest = staticmethod(_generated.flat_forcing_at_rest)
    #: The coordinates of a steady turn in the turning frame besides lean and steer (none: x, y and the
    #: heading drop out).
    turning_coordinates = ()
    #: A lane that always has a configuration, put where a lane cannot be computed (blanked after).
    harmless_lane = 0.1
    #: The lane of upright straight running.
    upright_lane = 0.0

    def __init__(self, ground: Plane):
        self.ground = ground

    def values(self) -> tuple:
        """The ground's parameters after Table 1's in the generated code's arguments: none."""
        return ()

    def place(self, q, lane):
        """q's ground coordinates for the lane: on flat ground the turn's place is anywhere (x = y = 0)."""

    def lane_ok(self, lane):
        """Where a lane can be computed: a finite curvature."""
        return np.isfinite(lane)

    def curvature(self, lane):
        """The lane's geodesic curvature (1/m): the path's curvature itself."""
        return lane

    def heading_condition(self, u, lane):
        """The kinematic condition of a steady turn per unit rear wheel rate: the heading rate is the
        curvature times the forward speed."""
        return u[_HEADING] - lane * u[1]

    def tangent_frame(self, q, one, zero):
        """The tangent frame T at the rear contact: N itself."""
        return tuple(np.stack(v) for v in ((one, zero, zero), (zero, one, zero), (zero, zero, one)))

    def rear_contact(self, q, frames):
        """The rear contact P in N."""
        return np.stack([q[0], q[1], np.zeros_like(q[0])])

    def farthest(self, front, q):
        """The direction the front contact lies in from the front wheel's centre, before its part along
        the axle is taken out: down (towards N.z)."""
        return np.stack([np.zeros_like(q[0])] * 2 + [np.ones_like(q[0])])

    def normals(self, points, like):
        """The unit normals (n_rear, n_front) at the contacts pointing into the ground (the push's
        direction is their opposite): N.z's opposite, up, at both."""
        n = np.stack([np.zeros_like(like), np.zeros_like(like), -np.ones_like(like)])
        return n, n

    def theta_rear(self, q):
        """The rear contact's polar angle from the upward vertical: pi (below) on flat ground."""
        return np.full(np.shape(q[0]), np.pi)

    def turn(self, u, points, v_rear):
        """(omega, head clearance, theta_front, swept) of a steady turn: the rate about the vertical
        (the heading rate), the head's clearance (+inf: no globe), the front contact's polar angle (pi)
        and swept(x), the horizontal offset whose z-cross is the velocity of the point x."""
        omega = u[_HEADING]
        Y = points["frames"]["Y"]

        def swept(x):
            # omega (x - centre), the centre P + Y.y / kappa: regular at kappa = 0 (straight)
            return omega * _horizontal(x - points["P"]) - v_rear * Y[1]

        return omega, np.full_like(v_rear, np.inf), np.full_like(v_rear, np.pi), swept


class OnSphere:
    """The inside of a sphere of radius r centred at O: a lane is the rear
    contact's polar angle theta = q0 from the upward vertical (docs/two-wheeler.md sec. 3.1)."""

    surface = "sphere"
    equations = staticmethod(_generated.sphere_equations)
    holonomic = staticmethod(_generated.sphere_holonomic)
    energy = staticmethod(_generated.sphere_energy)
    front_contact = staticmethod(_generated.sphere_front_contact)
    constraint_matrix = staticmethod(_generated.sphere_constraint_matrix)
    forcing_at_rest = staticmethod(_generated.sphere_forcing_at_rest)
    #: theta and the heading stay in the turning frame (the azimuth drops out: the sphere's symmetry).
    turning_coordinates = (0, _HEADING)
    harmless_lane = np.pi / 2
    upright_lane = np.pi / 2

    def __init__(self, ground: Sphere):
        self.ground = ground

    def values(self) -> tuple:
        """The sphere's radius r, after Table 1's parameters in the generated code's arguments."""
        return (self.ground.radius,)

    def place(self, q, lane):
        q[0] = lane

    def lane_ok(self, lane):
        """Where a lane can be computed: a finite theta off the poles."""
        return np.isfinite(lane) & (lane > POLE) & (lane < np.pi - POLE)

    def curvature(self, lane):
        """The parallel's geodesic curvature -cot(theta)/r (1/m); at the poles a quarter turn's worth."""
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.nan_to_num(-np.cos(lane) / (self.ground.radius * np.sin(lane)), posinf=1e300, neginf=-1e300)

    def heading_condition(self, u, lane):
        """The kinematic condition of a steady turn per unit rear wheel rate: the heading stays constant."""
        return u[_HEADING]

    def tangent_frame(self, q, one, zero):
        th, az = q[0], q[1]
        Tz = np.stack([np.sin(th) * np.cos(az), np.sin(th) * np.sin(az), -np.cos(th)])
        Ty = np.stack([-np.sin(az), np.cos(az), zero])
        return np.cross(Ty, Tz, axis=0), Ty, Tz

    def rear_contact(self, q, frames):
        return self.ground.radius * frames["T"][2]

    def farthest(self, front, q):
        """Away from the sphere's centre O."""
        return front

    def normals(self, points, like):
        """Outwards, away from the centre: -T.z at the rear, along -Q at the front."""
        return -points["frames"]["T"][2], -points["Q"] / np.linalg.norm(points["Q"], axis=0)

    def theta_rear(self, q):
        return q[0]

    def turn(self, u, points, v_rear):
        """The rate about the vertical through the centre (the azimuth's), the head's clearance r - |head|,
        the front contact's polar angle and swept(x) = omega x, horizontal."""
        omega = u[1]
        Q = points["Q"]
        clearance = self.ground.radius - np.linalg.norm(points["head"], axis=0)
        theta_front = np.arccos(np.clip(-Q[2] / np.linalg.norm(Q, axis=0), -1, 1))

        def swept(x):
            return omega * _horizontal(x)

        return omega, clearance, theta_front, swept


#: The ground records the equations are generated for, and what each asks.
_ON = {Plane: OnPlane, Sphere: OnSphere}


def of(ground) -> OnPlane | OnSphere:
    """What the two-wheeler's equations need of ``ground`` (a
    :class:`~deathsphere.physics.ground.Plane` or
    :class:`~deathsphere.physics.ground.Sphere`; beyond the paper,
    docs/two-wheeler.md sec. 3): its generated functions and terms."""
    on = _ON.get(type(ground))
    if on is None:
        raise TypeError(f"the two-wheeler's equations are generated for flat ground (Plane) and the inside of a "
                        f"sphere (Sphere): not {ground!r}")
    return on(ground)
