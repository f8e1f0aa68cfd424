"""The front wheel's contact on any surface of revolution: the rim point
where the rim is tangent to the ground, found from the ground's implicit
function F (F = 0 on the surface, F < 0 inside; beyond the paper,
docs/two-wheeler.md sec. 12.2).

The rim is Q(psi) = c + r (sin psi e_x + cos psi e_z) about the wheel's
centre c in the plane of its frame's E.x, E.z (psi = 0 is E.z, the
wheel's "down").  The rim point that touches a concave arena is the one
where F along the rim is greatest, so the tangency condition is

    G(psi) = grad F(Q) . Q_psi = 0,   Q_psi = r (cos psi e_x - sin psi e_z),

found by Newton's method with G_psi = Q_psi^T H Q_psi - r grad F . d (d the
unit rim direction, H the Hessian of F).  On the sphere and flat ground the
first guess, the gradient at the centre in the wheel's plane, is already the
root (the farthest point from the centre, the lowest point).

Vectors here are in the two-wheeler's inertial frame N (z down), arrays
(3, ...) with a trailing batch; the ground answers in its own coordinates (z
up), so positions and derivatives are mirrored in z at the boundary.
Complex steps pass through: Newton in real arithmetic from the real parts,
then one step in complex arithmetic, which gives the imaginary part exactly
(G vanishes at the real root, so the step is -i eps G_eps / G_psi).
"""

from __future__ import annotations

import numpy as np

__all__ = ["implicit", "gradient", "hessian", "rim_angle", "rim_angle_rate", "rim_point"]

#: Newton steps at most: quadratic convergence from the gradient's guess reaches float64 in 3 or 4.
_NEWTON = 12
#: A step below this (rad) leaves the angle at rounding.
_SETTLED = 1e-15
_MIRROR = np.array([1.0, 1.0, -1.0])


def _mirror(v):
    """A vector in N from the ground's coordinates, or back (z negated)."""
    return v * _MIRROR.reshape((3,) + (1,) * (np.ndim(v) - 1))


def implicit(ground, x):
    """F at the points x (3, ...) of N (beyond the paper; docs/two-wheeler.md sec. 12.2)."""
    return ground.implicit(x[0], x[1], -x[2])


def gradient(ground, x):
    """grad F (3, ...) in N at the points x (3, ...) of N (beyond the paper; docs/two-wheeler.md sec. 12.2)."""
    return _mirror(ground.gradient(x[0], x[1], -x[2]))


def hessian(ground, x):
    """The Hessian of F (3, 3, ...) in N at the points x (3, ...) of N (beyond the paper;
    docs/two-wheeler.md sec. 12.2)."""
    h = ground.hessian(x[0], x[1], -x[2])
    flip = _MIRROR.reshape((3, 1) + (1,) * (np.ndim(x) - 1)) * _MIRROR.reshape((1, 3) + (1,) * (np.ndim(x) - 1))
    return h * flip


def _dot(a, b):
    return np.sum(a * b, axis=0)


def rim_point(centre, e_x, e_z, radius, psi):
    """(Q, Q_psi): the rim point at psi and its derivative in psi (beyond the paper;
    docs/two-wheeler.md sec. 12.2)."""
    s, c = np.sin(psi), np.cos(psi)
    return centre + radius * (s * e_x + c * e_z), radius * (c * e_x - s * e_z)


def _newton_step(ground, centre, e_x, e_z, radius, psi):
    Q, Q_psi = rim_point(centre, e_x, e_z, radius, psi)
    grad = gradient(ground, Q)
    H = hessian(ground, Q)
    G = _dot(grad, Q_psi)
    G_psi = _dot(Q_psi, np.einsum("ij...,j...->i...", H, Q_psi)) - _dot(grad, Q - centre)
    ok = G_psi != 0
    return np.where(ok, G / np.where(ok, G_psi, 1.0), 0.0)


def rim_angle(ground, centre, e_x, e_z, radius):
    """The rim angle psi (...) of the rim point that touches ``ground``
    (where F along the rim is greatest), by Newton's method on the
    tangency condition from the gradient of F at the centre seen in the
    wheel's plane (beyond the paper; docs/two-wheeler.md sec. 12.2)."""
    real = [np.real(v) for v in (centre, e_x, e_z)]
    radius_r = np.real(radius)
    guess = gradient(ground, real[0])
    psi = np.arctan2(_dot(guess, real[1]), _dot(guess, real[2]))
    for _ in range(_NEWTON):
        step = _newton_step(ground, *real, radius_r, psi)
        psi = psi - step
        if not np.any(np.abs(step) > _SETTLED):
            break
    if any(np.iscomplexobj(v) for v in (centre, e_x, e_z, radius)):
        psi = psi - _newton_step(ground, centre, e_x, e_z, radius, psi + 0j)
    return psi


def rim_angle_rate(ground, centre, e_x, e_z, radius, psi, point_velocity, frame_rate):
    """psi's rate: the tangency G(q, psi) = 0 held along the motion, so
    psi' = -G' / G_psi with G' = Q_psi^T H v + grad F . (omega x Q_psi), v
    the velocity of the front frame's point at Q and omega the front
    frame's angular velocity (Q_psi is fixed in that frame; beyond the
    paper, docs/two-wheeler.md sec. 12.2)."""
    Q, Q_psi = rim_point(centre, e_x, e_z, radius, psi)
    grad = gradient(ground, Q)
    H = hessian(ground, Q)
    HQ = np.einsum("ij...,j...->i...", H, Q_psi)
    G_psi = _dot(Q_psi, HQ) - _dot(grad, Q - centre)
    G_dot = _dot(HQ, point_velocity) + _dot(grad, np.cross(frame_rate, Q_psi, axis=0))
    # G_psi vanishes only where the rim osculates the surface (no isolated contact): a rate of 0 there
    ok = G_psi != 0
    return np.where(ok, -G_dot / np.where(ok, G_psi, 1.0), 0.0)
