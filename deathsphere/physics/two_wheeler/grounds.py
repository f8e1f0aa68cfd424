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

from deathsphere.physics.ground import Cone, Cylinder, Plane, Profile, Sphere
from deathsphere.physics.two_wheeler import _generated, rim_contact
from deathsphere.physics.two_wheeler.parameters import PARAMETER_NAMES

__all__ = ["POLE", "OnPlane", "OnSphere", "OnRevolution", "of"]

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

    def farthest(self, front, q, frames=None, rF=None):
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
        (the heading rate), the head's clearance (its height above the ground, as the single-contact
        machine's there; N.z is down), the front contact's polar angle (pi) and swept(x), the horizontal
        offset whose z-cross is the velocity of the point x."""
        omega = u[_HEADING]
        Y = points["frames"]["Y"]
        head = points["head"]
        clearance = self.ground.clearance(np.hypot(head[0], head[1]), -head[2]) + 0.0 * v_rear

        def swept(x):
            # omega (x - centre), the centre P + Y.y / kappa: regular at kappa = 0 (straight)
            return omega * _horizontal(x - points["P"]) - v_rear * Y[1]

        return omega, clearance, np.full_like(v_rear, np.pi), swept


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

    def farthest(self, front, q, frames=None, rF=None):
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


#: The front wheel's radius's place in the parameters.
_RF = PARAMETER_NAMES.index("rF")
#: The least distance of a lane from the axis (m): on the axis the azimuth is undefined.
AXIS = 1e-6


class OnRevolution:
    """The inside of any surface of revolution about the vertical axis, the
    ground as data (docs/two-wheeler.md sec. 12): the ground record answers
    the meridian at the rear contact (``meridian(s)``, s = q0 its arc length
    from the lowest point) and the implicit function whose greatest value on
    the front rim is the front contact (:mod:`.rim_contact`); one generated
    module serves every such ground.  A lane is a height above the lowest
    point, as the ground protocol's (on flat ground, a
    :class:`~deathsphere.physics.ground.Plane`, the turn's radius).  It also
    takes the sphere and flat ground, whose own closed forms
    (:class:`OnSphere`, :class:`OnPlane`) it agrees with to 1e-12: build it
    explicitly, ``OnRevolution(Sphere(r))``, and pass it where a ground goes."""

    surface = "revolution"
    #: s and the heading stay in the turning frame (the azimuth drops out: the symmetry about the axis).
    turning_coordinates = (0, _HEADING)

    def __init__(self, ground):
        self.ground = ground
        # a lane every ground of the kind has (a configuration exists there): half-way up, or 1 m out on flat
        # ground
        top = getattr(ground, "highest_lane", np.inf)
        self.harmless_lane = self.upright_lane = 0.5 * top if np.isfinite(top) else 1.0

    def values(self) -> tuple:
        """The ground's parameters after Table 1's in the generated code's arguments: none (the meridian and
        the rim angle are appended per state, from the ground record)."""
        return ()

    # --- the generated functions, the meridian and the rim angle supplied --------------------------------

    def _meridian(self, q):
        return tuple(self.ground.meridian(q[0]))

    def _rim(self, q, p):
        """(the meridian's arguments, psi, the front rim's 18 rows) at q."""
        m = self._meridian(q)
        rim = _generated.revolution_front_rim(q, p + m + (0.0,))
        psi = rim_contact.rim_angle(self.ground, rim[0:3], rim[3:6], rim[6:9], p[_RF])
        return m, psi, rim

    def equations(self, q, u, p, steer_torque):
        """M, f, B, B' u as the sphere's and flat ground's: B' u with psi's part, d(B u)/d psi times psi's
        rate (the rim point that touches moves round the rim as the wheel tilts)."""
        m, psi, rim = self._rim(q, p)
        M, f, B, bias, dpsi, velocity, rate = _generated.revolution_equations(q, u, p + m + (psi,), steer_torque)
        psi_rate = rim_contact.rim_angle_rate(self.ground, rim[0:3], rim[3:6], rim[6:9], p[_RF], psi, velocity, rate)
        return M, f, B, bias + dpsi * psi_rate

    def holonomic(self, q, p):
        """(h, dh/dpitch), each (1, ...): h = F(Q) / |grad F(Q)|, about the front contact's distance from the
        surface (m), and its pitch derivative at the rim angle held (the envelope theorem: psi's own change
        moves F only to second order at the touching point)."""
        _, psi, rim = self._rim(q, p)
        rF = p[_RF]
        Q, _ = rim_contact.rim_point(rim[0:3], rim[3:6], rim[6:9], rF, psi)
        dQ, _ = rim_contact.rim_point(rim[9:12], rim[12:15], rim[15:18], rF, psi)
        grad = rim_contact.gradient(self.ground, Q)
        size = np.sqrt(np.sum(grad * grad, axis=0))
        return (rim_contact.implicit(self.ground, Q) / size)[None], (np.sum(grad * dQ, axis=0) / size)[None]

    def energy(self, q, u, p):
        return _generated.revolution_energy(q, u, p + self._meridian(q) + (0.0,))

    def front_contact(self, q, p):
        m, psi, _ = self._rim(q, p)
        return _generated.revolution_front_contact(q, p + m + (psi,))

    def constraint_matrix(self, q, p):
        m, psi, _ = self._rim(q, p)
        return _generated.revolution_constraint_matrix(q, p + m + (psi,))

    def forcing_at_rest(self, q, p, steer_torque):
        return _generated.revolution_forcing_at_rest(q, p + self._meridian(q) + (0.0,), steer_torque)

    # --- lanes ----------------------------------------------------------------------------------------

    def place(self, q, lane):
        """q0 = the lane's arc length up the meridian."""
        q[0] = self.ground.arc_length(lane)

    def lane_ok(self, lane):
        """Where a lane can be computed: a finite height on the wall (0 to the highest lane), off the axis."""
        lane = np.asarray(lane, float)
        top = getattr(self.ground, "highest_lane", np.inf)
        ok = np.isfinite(lane) & (lane >= 0) & (lane <= top)
        rho = self.ground.meridian(self.ground.arc_length(np.where(ok, lane, 0.0)))[0]
        return ok & (rho > AXIS)

    def curvature(self, lane):
        """The parallel's geodesic curvature cos(beta) / rho (1/m)."""
        rho, _, beta, _, _ = self.ground.meridian(self.ground.arc_length(lane))
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.nan_to_num(np.cos(beta) / rho, posinf=1e300, neginf=-1e300)

    def heading_condition(self, u, lane):
        """The kinematic condition of a steady turn per unit rear wheel rate: the heading stays constant."""
        return u[_HEADING]

    # --- the frames and points, numerically -----------------------------------------------------------

    def tangent_frame(self, q, one, zero):
        """T.x up the meridian, T.y along the azimuth, T.z the outward normal (the sphere's frame there)."""
        beta = self.ground.meridian(q[0])[2] + zero
        c, s = np.cos(beta), np.sin(beta)
        ca, sa = np.cos(q[1]), np.sin(q[1])
        return (np.stack([c * ca, c * sa, -s * one]), np.stack([-sa, ca, zero]), np.stack([s * ca, s * sa, c * one]))

    def rear_contact(self, q, frames):
        rho, z = self.ground.meridian(q[0])[:2]
        return np.stack([rho * np.cos(q[1]), rho * np.sin(q[1]), -z + 0.0 * q[1]])

    def farthest(self, front, q, frames, rF):
        """Towards the rim point where the rim is tangent to the ground (:mod:`.rim_contact`)."""
        E = frames["E"]
        psi = rim_contact.rim_angle(self.ground, front, E[0], E[2], rF)
        return np.sin(psi) * E[0] + np.cos(psi) * E[2]

    def normals(self, points, like):
        """The inward normals (the push's direction): -T.z at the rear, down grad F at the front."""
        grad = rim_contact.gradient(self.ground, points["Q"])
        return -points["frames"]["T"][2], -grad / np.sqrt(np.sum(grad * grad, axis=0))

    def theta_rear(self, q):
        """The rear contact's polar angle about the ground's origin from the upward vertical (the sphere's
        theta)."""
        rho, z = self.ground.meridian(q[0])[:2]
        return np.arctan2(rho, z)

    def turn(self, u, points, v_rear):
        """The rate about the vertical axis (the azimuth's), the head's clearance from the ground, the front
        contact's polar angle about the origin and swept(x) = omega x, horizontal."""
        omega = u[1]
        Q, head = points["Q"], points["head"]
        clearance = self.ground.clearance(np.hypot(head[0], head[1]), -head[2])
        theta_front = np.arccos(np.clip(-Q[2] / np.linalg.norm(Q, axis=0), -1, 1))

        def swept(x):
            return omega * _horizontal(x)

        return omega, clearance, theta_front, swept


#: The ground records the equations are generated for, and what each asks.
_ON = {Plane: OnPlane, Sphere: OnSphere, Cylinder: OnRevolution, Cone: OnRevolution, Profile: OnRevolution}
_KINDS = (OnPlane, OnSphere, OnRevolution)


def of(ground) -> OnPlane | OnSphere | OnRevolution:
    """What the two-wheeler's equations need of ``ground`` (a
    :class:`~deathsphere.physics.ground.Plane`, a
    :class:`~deathsphere.physics.ground.Sphere`, a drum or a cone, or one
    of this module's classes given as the ground, e.g.
    ``OnRevolution(Sphere(r))`` for the general path on the globe; beyond
    the paper, docs/two-wheeler.md sec. 3 and 12; a profile too): its
    generated functions and terms."""
    if isinstance(ground, _KINDS):
        return ground
    on = _ON.get(type(ground))
    if on is None:
        raise TypeError(f"the two-wheeler's equations are generated for flat ground (Plane), the inside of a "
                        f"sphere (Sphere) and the inside of a drum (Cylinder), a cone (Cone) or a profile (Profile): "
                        f"not {ground!r}")
    return on(ground)
