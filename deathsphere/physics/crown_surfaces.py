"""The surface a machine's tyre crown point moves on: the ground's parallel
surface a tyre radius inside, as the crown's geometry asks of it (beyond
the paper; docs/machine.md, "On any ground", MG1-MG4, and "On a profile",
MP1-MP5).

The crown geometry (:mod:`deathsphere.physics.machine_dynamics_on`) needs
of the parallel surface a function F, zero on it and negative inside, at
points X near it: its gradient N = grad F as a second-order Taylor jet
when X is one (the crown's rates and accelerations), its Hessian times a
vector H v (the slope of Newton's method for the crown's angle, the pitch
constraint's force), and F itself (the constraint's residual).  Two kinds:

* :class:`QuadricCrown` -- a quadric of revolution (the globe, a drum, a
  cone, flat ground): N = A X + b, H = A constant (MG1).
* :class:`MeridianCrown` -- a profile's parallel surface by its meridian
  (:class:`~deathsphere.physics.ground.profile_offset.ParallelProfile`):
  F the signed distance from it, N the unit normal at the point's foot on
  the meridian, its jets by differentiating the foot's condition (MP4).

Each answers ``foot(X, start)`` (the foot's spline parameter; None for a
quadric, which needs none), so that the crown's geometry finds the foot of
a point once and reuses it for the rates and accelerations at that point.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.taylor import Taylor

__all__ = ["QuadricCrown", "MeridianCrown", "crown_surface"]


class QuadricCrown:
    """The parallel surface as the quadric F = a_rho (x^2 + y^2)/2 + a_z z^2/2
    + b_z z + c (``quadric`` = (a_rho, a_z, b_z, c), each broadcasting
    against the points; MG1)."""

    def __init__(self, quadric):
        self.quadric = quadric

    def foot(self, X, start=None):
        """None: a quadric's gradient needs no foot."""
        return None

    def normal(self, X, foot=None, order=None):
        """N = grad F (3, ...) at the point X (3, ...), an array or a jet (every order: N is linear in X)."""
        a_rho, a_z, b_z, _ = self.quadric
        if isinstance(X, Taylor):
            return Taylor(self.normal(X.x0), None if X.x1 is None else self.hess_dot(None, X.x1),
                          None if X.x2 is None else self.hess_dot(None, X.x2))
        return np.stack((a_rho * X[0], a_rho * X[1], a_z * X[2] + b_z + 0 * X[2]))

    def hess_dot(self, X, v, foot=None):
        """A v (3, ...) for the quadric's constant Hessian A = diag(a_rho, a_rho, a_z)."""
        a_rho, a_z = self.quadric[0], self.quadric[1]
        return np.stack((a_rho * v[0], a_rho * v[1], a_z * v[2]))

    def normal_and_hess(self, X, v, foot=None):
        """(N(X), H v)."""
        return self.normal(X), self.hess_dot(X, v)

    def value(self, X, foot=None):
        """F at the point X (3, ...)."""
        a_rho, a_z, b_z, c = self.quadric
        return 0.5 * a_rho * (X[0] ** 2 + X[1] ** 2) + 0.5 * a_z * X[2] ** 2 + b_z * X[2] + c


def _unit_jet(v0, v1, v2):
    """The unit vector of a 2-vector v (2, ...) and its norm, each with its
    first and second rates (None where v's are): s = |v|, u = v / s,
    s1 = v0.v1 / s, u1 = (v1 - u s1) / s, s2 = (|v1|^2 + v0.v2 - s1^2) / s,
    u2 = (v2 - 2 u1 s1 - u s2) / s."""
    s0 = np.sqrt(v0[0] * v0[0] + v0[1] * v0[1])
    u0 = v0 / s0
    s1 = s2 = u1 = u2 = None
    if v1 is not None:
        s1 = (v0[0] * v1[0] + v0[1] * v1[1]) / s0
        u1 = (v1 - u0 * s1) / s0
    if v2 is not None:
        s2 = (v1[0] * v1[0] + v1[1] * v1[1] + v0[0] * v2[0] + v0[1] * v2[1] - s1 * s1) / s0
        u2 = (v2 - 2 * u1 * s1 - u0 * s2) / s0
    return (u0, u1, u2), (s0, s1, s2)


def _join(xy, z):
    """The 3-vector (3, ...) of a horizontal part xy (2, ...) and a vertical z, broadcast."""
    out = np.empty((3,) + np.broadcast_shapes(xy.shape[1:], np.shape(z)), dtype=np.result_type(xy, z))
    out[0:2] = xy
    out[2] = z
    return out


class MeridianCrown:
    """A profile's parallel surface (``parallel``: a
    :class:`~deathsphere.physics.ground.profile_offset.ParallelProfile`) as
    F = -(the distance inside it), the signed distance: at a point X of
    distance rho from the axis, foot s on the meridian (MP2), with the
    meridian's unit tangent (cos beta, sin beta) there,

        N = (sin beta rho-hat, -cos beta),  |N| = 1           (MP4)

    (the outward normal of the profile at the foot, lifted off the
    meridian's plane).  Its jets: the foot's condition G(s, q) = (P(s) -
    q) . P'(s) = 0 differentiated in time at q = (rho, z),

        s1 = q1 . T / G_s,
        s2 = (q2 . T + 2 s1 q1 . A - (3 T . A + D . B) s1^2) / G_s,

    with D = P - q, T, A, B = P', P'', P''' at the foot and
    G_s = T . T + D . A; the tangent then moves as T + A s1 eps + (A s2 +
    B s1^2) eps^2 / 2 and rho-hat with X.  H v is the first-order jet of N
    along v."""

    def __init__(self, parallel):
        self.parallel = parallel

    def foot(self, X, start=None):
        """The foot of the point X (3, ...): its spline parameter (X.shape[1:])
        and the spline's derivatives there, Newton's method from the foot
        ``start`` (MP2)."""
        return self.parallel.foot_and_derivatives(np.sqrt(X[0] * X[0] + X[1] * X[1]), X[2],
                                                  None if start is None else start[0])

    def normal(self, X, foot, order=None):
        """N (MP4) at the point X with its foot ``foot``: an array for an
        array X, a jet for a jet, to ``order`` (default: X's highest
        coefficient; the higher terms are not computed).  Written out
        (the unit vectors' jets by :func:`_unit_jet`) rather than in jet
        arithmetic: the crown's Newton steps ask it many times."""
        if not isinstance(X, Taylor):
            return self.normal(Taylor(X), foot, 0).x0
        top = order if order is not None else (2 if X.x2 is not None else 1 if X.x1 is not None else 0)
        x0 = X.x0
        x1 = X.x1 if top >= 1 else None
        x2 = X.x2 if top >= 2 else None
        # rho-hat and rho = |(x, y)| with their rates
        (u0, u1, u2), (r0, r1, r2) = _unit_jet(x0[0:2], None if x1 is None else x1[0:2],
                                               None if x2 is None else x2[0:2])
        p, d1, d2, d3 = foot[1]
        tr, tz, ar, az, br, bz = d1[..., 0], d1[..., 1], d2[..., 0], d2[..., 1], d3[..., 0], d3[..., 1]
        dr, dz = p[..., 0] - r0, p[..., 1] - x0[2]
        g_s = tr * tr + tz * tz + dr * ar + dz * az
        bend = np.stack((ar, az))
        t1 = t2 = None
        if x1 is not None:
            s1 = (r1 * tr + x1[2] * tz) / g_s
            t1 = bend * s1
        if x2 is not None:
            s2 = (r2 * tr + x2[2] * tz + 2 * s1 * (r1 * ar + x1[2] * az)
                  - (3 * (tr * ar + tz * az) + dr * br + dz * bz) * s1 * s1) / g_s
            t2 = bend * s2 + np.stack((br, bz)) * (s1 * s1)
        (c0, c1, c2), _ = _unit_jet(np.stack((tr, tz)), t1, t2)       # (cos beta, sin beta) and rates
        n0 = _join(c0[1] * u0, -c0[0])
        n1 = None if x1 is None else _join(c1[1] * u0 + c0[1] * u1, -c1[0])
        n2 = None if x2 is None else _join(c2[1] * u0 + 2 * c1[1] * u1 + c0[1] * u2, -c2[0])
        return Taylor(n0, n1, n2)

    def hess_dot(self, X, v, foot):
        """H v (3, ...): the first derivative of N along v at the point X."""
        return self.normal(Taylor(X, v), foot, 1).x1

    def normal_and_hess(self, X, v, foot):
        """(N(X), H v) in one pass."""
        jet = self.normal(Taylor(X, v), foot, 1)
        return jet.x0, jet.x1

    def value(self, X, foot):
        """F = -(the distance inside the parallel surface) (MP3) at the point X (3, ...)."""
        return -self.parallel.clearance(np.sqrt(X[0] * X[0] + X[1] * X[1]), X[2], foot[0])


def crown_surface(ground, t):
    """The crown point's surface on ``ground`` for tyre radius ``t`` [m]:
    its parallel surface ``ground.offset(t)``, a :class:`QuadricCrown` where
    that has a quadric (the globe, a drum, a cone, flat ground; its
    coefficients broadcast against t), else a :class:`MeridianCrown` (a
    profile); None for a ground with no parallel surface (beyond the paper;
    docs/machine.md, "On any ground")."""
    parallel = ground.offset(t)
    if parallel is None:
        return None
    quadric = getattr(parallel, "quadric", None)
    if quadric is not None:
        return QuadricCrown(tuple(np.asarray(x, dtype=float) for x in quadric()))
    return MeridianCrown(parallel)
