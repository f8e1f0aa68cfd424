"""3-vectors stored along axis 0 of an array, (3, ...): the small vector
algebra of the equations of motion and their linearisation (beyond the
paper; docs/dynamics.md sec. 2).

Every product is bilinear (no complex conjugation), so complex-step
derivatives pass through unchanged, and :func:`norm` is the square root of
the bilinear square for the same reason.
"""

import numpy as np

__all__ = ["dot", "cross", "zcross", "norm", "contract"]


def dot(u, v):
    """u . v over axis 0 (bilinear).

    Beyond the paper: vector algebra over batches (docs/machine.md sec. 3-5 use it).
    """
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def cross(u, v):
    """u x v over axis 0.

    Beyond the paper: vector algebra over batches (docs/machine.md sec. 3-5 use it).
    """
    return np.stack((u[1] * v[2] - u[2] * v[1],
                     u[2] * v[0] - u[0] * v[2],
                     u[0] * v[1] - u[1] * v[0]))


def zcross(u):
    """z x u: the generator of rotations about the vertical.

    Beyond the paper: vector algebra over batches (docs/machine.md sec. 3-5 use it).
    """
    return np.stack((-u[1], u[0], np.zeros_like(u[2])))


def norm(u):
    """sqrt(u . u): analytic, so complex-step derivatives work.

    Beyond the paper: vector algebra over batches (docs/machine.md sec. 3-5 use it).
    """
    return np.sqrt(dot(u, u))


def contract(u, v):
    """sum_i u[i] v[i] over axis 0, of any length (the other axes broadcast),
    added in index order.

    This is ``np.einsum("i...,i...->...", u, v)`` with a fixed order of
    summation: einsum's order depends on the shapes and strides, so one
    orbit's result would change in its last bits with the number of orbits
    evaluated beside it (the chunk size); here it does not.

    Beyond the paper: vector algebra over batches (docs/machine.md sec. 3-5 use it).
    """
    total = u[0] * v[0]
    for i in range(1, len(u)):
        total = total + u[i] * v[i]
    return total
