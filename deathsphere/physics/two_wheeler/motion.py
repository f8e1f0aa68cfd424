"""The Whipple bicycle's constrained motion, numerically, from the
generated equations (beyond the paper; docs/two-wheeler.md sec. 4).

The generated code (``_generated.py``) gives Kane's equations with all
eight speeds free, M u' = f, and the rolling constraints B u = 0.  Here they
are imposed: the pitch from the front contact's holonomic constraint, the
five dependent speeds from the three independent ones (lean rate, rear
wheel rate, steer rate), and the accelerations either of the whole system
with the contact forces' multipliers, or of Kane's reduced equations
A^T (M u' - f) = 0.

Arrays carry the coordinate (or speed) index on axis 0 and a batch on the
trailing axes, and every step (Newton's iteration included) is analytic, so
complex-step derivatives pass through.
"""

from __future__ import annotations

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics.ground import Plane
from deathsphere.physics.two_wheeler import grounds
from deathsphere.physics.two_wheeler.parameters import BicycleParameters

__all__ = ["FLAT", "INDEPENDENT", "DEPENDENT", "HEADING", "LEAN", "PITCH", "REAR", "STEER", "parameter_values", "pitch",
           "dependent_speeds", "full_speeds", "accelerations", "reduced_residual", "reduced_mass_and_forcing", "energy",
           "state_rates"]

#: Indices in q and u (both grounds): heading 2, lean 3, pitch 4, rear wheel 5, steer 6, front wheel 7.
HEADING, LEAN, PITCH, REAR, STEER = 2, 3, 4, 5, 6
#: The independent speeds (lean rate, rear wheel rate, steer rate) and the dependent ones.
INDEPENDENT = (LEAN, REAR, STEER)
DEPENDENT = (0, 1, 2, PITCH, 7)

#: Newton iterations for the pitch, at most: quadratic convergence from the
#: upright pitch reaches float64 in 5 for leans and steers below 1 rad.
_NEWTON = 8
#: Flat ground, the ground of the functions below when none is given.
FLAT = Plane()


def parameter_values(parameters: BicycleParameters, g=STANDARD_GRAVITY, ground=FLAT) -> tuple:
    """The generated code's parameter tuple: Table 1 of Meijaard et al.
    (2007) in order, the run's gravity ``g`` (m/s^2) in its slot, then the
    ground's parameters (the sphere's radius; beyond the paper;
    docs/two-wheeler.md sec. 1)."""
    return parameters.values(g) + grounds.of(ground).values()


def pitch(q, p, ground=FLAT):
    """q with its pitch solved from the front contact's holonomic constraint
    by Newton's method from the given pitch (beyond the paper;
    docs/two-wheeler.md sec. 3.2)."""
    holonomic = grounds.of(ground).holonomic
    q = np.array(q, dtype=np.result_type(q, float), copy=True)
    if np.iscomplexobj(q) or any(np.iscomplexobj(x) for x in p):
        # a complex step: the real parts' Newton in real arithmetic (the same iterates), then one complex
        # step from that root gives the imaginary part exactly (h = i e g there, so the step is -i e g / h')
        q[PITCH] = pitch(q.real, tuple(np.real(x) for x in p), ground)[PITCH]
        h, dh = holonomic(q, p)
        q[PITCH] -= h[0] / dh[0]
        return q
    shape = q.shape[1:]
    q = q.reshape(8, -1)
    # parameters that vary along the batch follow its points
    varying = [np.broadcast_to(x, shape).reshape(-1) if np.ndim(x) else None for x in p]
    # each point iterates until settled: after a step below 1e-8 rad the next leaves it at rounding (points
    # where no pitch exists iterate to the end; the callers mask them)
    active = np.arange(q.shape[1])
    settled = np.zeros(q.shape[1], bool)
    for _ in range(_NEWTON):
        if active.size == 0:
            break
        h, dh = holonomic(q[:, active], tuple(x if v is None else v[active] for x, v in zip(p, varying)))
        step = h[0] / dh[0]
        q[PITCH, active] -= step
        last = settled[active]
        with np.errstate(invalid="ignore"):
            settled[active] = np.abs(step.real) < 1e-8
        active = active[~last]
    return q.reshape((8,) + shape)


def _split(B):
    """B (5, 8, ...) -> its dependent (..., 5, 5) and independent (..., 5, 3) columns, batch first."""
    B = np.moveaxis(B, (0, 1), (-2, -1))
    return B[..., list(DEPENDENT)], B[..., list(INDEPENDENT)]


def _null_space(B):
    """A (..., 8, 3) with u = A u_ind satisfying B u = 0."""
    dep, ind = _split(B)
    A = np.zeros(dep.shape[:-2] + (8, 3), dtype=dep.dtype)
    A[..., list(INDEPENDENT), :] = np.eye(3)
    A[..., list(DEPENDENT), :] = -np.linalg.solve(dep, ind)
    return A


def dependent_speeds(q, u_ind, p, ground=FLAT):
    """All eight speeds from the three independent ones (lean, rear wheel,
    steer rates) through the rolling constraints B u = 0 (beyond the paper;
    docs/two-wheeler.md sec. 3.3)."""
    dep, ind = _split(grounds.of(ground).constraint_matrix(q, p))
    u_ind = np.moveaxis(np.asarray(u_ind), 0, -1)
    # one right-hand side, B_ind u_ind, rather than the null space's three
    rhs = np.einsum("...ij,...j->...i", ind, np.broadcast_to(u_ind, ind.shape[:-2] + u_ind.shape[-1:]))
    u = np.zeros(dep.shape[:-2] + (8,), dtype=np.result_type(dep, u_ind))
    u[..., list(INDEPENDENT)] = u_ind
    u[..., list(DEPENDENT)] = -np.linalg.solve(dep, rhs[..., None])[..., 0]
    return np.moveaxis(u, -1, 0)


def full_speeds(q, u_ind, p, ground=FLAT):
    """(u, A): the eight speeds and the null-space map A (..., 8, 3) of the
    rolling constraints at q (beyond the paper; docs/two-wheeler.md sec. 4)."""
    B = grounds.of(ground).constraint_matrix(q, p)
    A = _null_space(B)
    u = np.einsum("...ij,j...->i...", A, u_ind)
    return u, A


def accelerations(q, u, p, steer_torque=0.0, ground=FLAT):
    """(u', lambda): the accelerations of all eight speeds and the
    multipliers of the five rolling constraints, from M u' - f = B^T lambda,
    B u' = -B' u (beyond the paper; docs/two-wheeler.md sec. 4)."""
    M, f, B, bias = grounds.of(ground).equations(q, u, p, steer_torque)
    M = np.moveaxis(M, (0, 1), (-2, -1))
    Bt = np.moveaxis(B, (0, 1), (-2, -1))
    n = M.shape[:-2]
    K = np.zeros(n + (13, 13), dtype=np.result_type(M, Bt))
    K[..., :8, :8] = M
    K[..., :8, 8:] = -np.swapaxes(Bt, -1, -2)
    K[..., 8:, :8] = Bt
    rhs = np.concatenate([np.moveaxis(f, 0, -1), -np.moveaxis(bias, 0, -1)], axis=-1)
    x = np.linalg.solve(K, rhs[..., None])[..., 0]
    x = np.moveaxis(x, -1, 0)
    return x[:8], x[8:]


def _constrained(q, u_ind, p, steer_torque, ground):
    """(u, A, M, f, a) at (q, u_ind): the eight speeds u = A u_ind, Kane's
    M and f, and the acceleration a the constraints add (B a = -B' u, zero
    in the independent speeds), so that u' = A u_ind' + a."""
    u, A = full_speeds(q, u_ind, p, ground)
    M, f, B, bias = grounds.of(ground).equations(q, u, p, steer_torque)
    dep, _ = _split(B)
    a = np.zeros(A.shape[:-1], dtype=np.result_type(A, bias))
    a[..., list(DEPENDENT)] = -np.linalg.solve(dep, np.moveaxis(bias, 0, -1)[..., None])[..., 0]
    return u, A, M, f, a


def reduced_residual(q, u_ind, udot_ind, p, steer_torque=0.0, ground=FLAT):
    """Kane's equations of the constrained bicycle, A^T (M u' - f) with
    u = A u_ind and u' = A u_ind' + a (B a = -B' u), for the independent
    speeds (lean, rear wheel, steer): shape (3, ...) (beyond the paper;
    docs/two-wheeler.md sec. 4)."""
    u, A, M, f, a = _constrained(q, u_ind, p, steer_torque, ground)
    udot = np.einsum("...ij,j...->...i", A, udot_ind) + a
    M = np.moveaxis(M, (0, 1), (-2, -1))
    force = np.einsum("...ij,...j->...i", M, udot) - np.moveaxis(f, 0, -1)
    return np.moveaxis(np.einsum("...ij,...i->...j", A, force), -1, 0)


def energy(q, u, p, ground=FLAT):
    """Kinetic plus potential energy, J (beyond the paper;
    docs/two-wheeler.md sec. 6)."""
    kinetic, potential = grounds.of(ground).energy(q, u, p)
    return kinetic[0] + potential[0]


def state_rates(x, p, steer_torque=0.0, ground=FLAT):
    """d/dt of the state x = (q, u) (16, ...): q' = u and u' from
    :func:`accelerations` (beyond the paper; docs/two-wheeler.md sec. 4)."""
    q, u = x[:8], x[8:]
    udot, _ = accelerations(q, u, p, steer_torque, ground)
    return np.concatenate([u, udot])


def reduced_mass_and_forcing(q, u_ind, p, steer_torque=0.0, ground=FLAT):
    """(A^T M A, A^T (f - M a), u): Kane's reduced equations solved form,
    A^T M A u_ind' = A^T (f - M a), batch first (..., 3, 3), (..., 3), and
    the eight speeds (beyond the paper; docs/two-wheeler.md sec. 4)."""
    u, A, M, f, a = _constrained(q, u_ind, p, steer_torque, ground)
    M = np.moveaxis(M, (0, 1), (-2, -1))
    At = np.swapaxes(A, -1, -2)
    force = np.moveaxis(f, 0, -1) - np.einsum("...ij,...j->...i", M, a)
    return At @ M @ A, np.einsum("...ij,...j->...i", At, force), u
