"""Reduction of a linearised flow to the directions that can grow, and its
spectrum (beyond the paper; docs/stability.md sec. 1).

The Jacobian of the equations of motion about a steady orbit is taken by
exact derivatives (complex step, or the forward mode of
:func:`deathsphere.physics.dynamics.jvp`), restricted to an orthonormal
complement of the neutral directions (constraint normals, symmetries, the
family of steady orbits) and read off: growth rate, nutation frequencies,
verdict.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.stability.verdict import verdict_from_growth
from deathsphere.physics.vectors import contract

__all__ = ["COMPLEX_STEP", "complex_step", "spectrum", "characteristic_invariants",
           "spectrum_from_invariants", "orthonormal_complement", "householder_complement"]

#: complex step (relative); any h << sqrt(eps) works for a complex step
COMPLEX_STEP = 1e-30


def complex_step(fun, x0, dx, h=COMPLEX_STEP):
    """Directional derivative of ``fun`` at x0 along dx by complex step
    (exact to round-off for analytic ``fun``).

    Beyond the paper: the reduction of docs/stability.md sec. 1.
    """
    return np.imag(fun(x0 + 1j * h * dx)) / h


def spectrum(K, scale):
    """Eigenvalues ``ev`` (n, m), growth rate (largest real part), nutation
    frequencies (slow, fast: |imaginary parts|, pairs averaged; slow is NaN
    for m = 2) and verdict of stacked reduced Jacobians K (n, m, m), m = 2 or
    4, with rate scales ``scale`` (n,).  Returns (ev, growth, slow, fast,
    verdict).

    Beyond the paper: the reduction of docs/stability.md sec. 1.
    """
    finite = np.all(np.isfinite(K), axis=(-2, -1)) & np.isfinite(scale)
    ev = np.linalg.eigvals(np.where(finite[:, None, None], K, 0.0))   # (n, m)
    ev = np.where(finite[:, None], ev, np.nan)
    growth = np.max(ev.real, axis=-1)
    im = np.sort(np.abs(ev.imag), axis=-1)
    m = K.shape[-1]
    if m == 4:
        slow = 0.5 * (im[:, 0] + im[:, 1])
        fast = 0.5 * (im[:, 2] + im[:, 3])
    else:
        slow = np.full(im.shape[0], np.nan)
        fast = 0.5 * (im[:, 0] + im[:, 1])
    return ev, growth, slow, fast, verdict_from_growth(growth, scale)


def characteristic_invariants(K):
    """e2, e4 of the characteristic polynomial lambda^4 + e2 lambda^2 + e4 of
    stacked 4x4 matrices K (n, 4, 4) of a reversible flow (odd coefficients
    vanish): e2 = (tr(K)^2 - tr(K^2))/2, the sum of the principal 2x2 minors,
    and e4 = det K.

    Beyond the paper: the reduction of docs/stability.md sec. 1.
    """
    tr = np.trace(K, axis1=-2, axis2=-1)
    # contract, not einsum: einsum's order of summation in a full contraction
    # changes with the number of orbits, and with it an orbit's last bits
    n = len(K)
    e2 = 0.5 * (tr * tr - contract(K.reshape(n, -1).T, np.swapaxes(K, 1, 2).reshape(n, -1).T))
    return e2, np.linalg.det(K)


def spectrum_from_invariants(K, scale):
    """:func:`spectrum` for stacked 4x4 reduced Jacobians, from invariants
    instead of an eigenvalue solver (beyond the paper; docs/stability.md
    sec. 1).  The flow is reversible, so the spectrum is symmetric under
    lambda -> -lambda: the characteristic polynomial is
    lambda^4 + e2 lambda^2 + e4 with e2 = (tr(K)^2 - tr(K^2))/2 (the sum of
    the principal 2x2 minors) and e4 = det K; the odd coefficients vanish up
    to round-off and are dropped.  The roots x = lambda^2 of
    x^2 + e2 x + e4 = 0 are taken in the cancellation-free form
    q = -(e2 + sign(e2) sqrt(e2^2 - 4 e4))/2, x = q and e4/q; the
    eigenvalues are +/- sqrt(x).  A stable orbit (both x real and negative)
    gets growth rate 0 exactly."""
    finite = np.all(np.isfinite(K), axis=(-2, -1)) & np.isfinite(scale)
    K = np.where(finite[:, None, None], K, 0.0)
    e2, e4 = characteristic_invariants(K)
    sq = np.sqrt((e2 * e2 - 4.0 * e4).astype(complex))
    q = -0.5 * (e2 + np.where(e2 >= 0, 1.0, -1.0) * sq)
    nz = q != 0
    x2 = np.where(nz, e4 / np.where(nz, q, 1.0), 0.0)
    l1, l2 = np.sqrt(q), np.sqrt(x2)
    ev = np.stack((l1, -l1, l2, -l2), axis=-1)
    ev = np.where(finite[:, None], ev, np.nan)
    growth = np.where(finite, np.maximum(np.abs(l1.real), np.abs(l2.real)), np.nan)
    f1, f2 = np.abs(l1.imag), np.abs(l2.imag)
    slow = np.where(finite, np.minimum(f1, f2), np.nan)
    fast = np.where(finite, np.maximum(f1, f2), np.nan)
    return ev, growth, slow, fast, verdict_from_growth(growth, scale)


def orthonormal_complement(A, dim):
    """Orthonormal basis (n, dim, dim - A.shape[-1]) of the complement of the
    column span of the stacked (n, dim, q) matrices A (assumed full rank).

    Beyond the paper: the reduction of docs/stability.md sec. 1.
    """
    q = A.shape[-1]
    Q, _ = np.linalg.qr(A, mode="complete")
    return Q[..., q:]


def householder_complement(A):
    """Orthonormal basis (dim, dim - q, n) of the complement of the column
    span of the component-major stack A (dim, q, n) (assumed full rank):
    Householder reflections H_0 ... H_{q-1} triangularise A, and the last
    dim - q columns of Q = H_0 ... H_{q-1} span the complement (the complete
    QR of :func:`orthonormal_complement`, up to signs).  Every operation
    runs on contiguous n-vectors, ~2x faster than a batched LAPACK QR for
    9 x 5 (beyond the paper; docs/stability.md sec. 1)."""
    dim, q, n = A.shape
    R = A.copy()
    vs = []
    for j in range(q):
        x = R[j:, j]                                             # (dim - j, n)
        nx = np.sqrt(contract(x, x))                             # fixed order: see above
        v = x.copy()
        v[0] += np.where(x[0] >= 0, nx, -nx)
        vn = np.sqrt(contract(v, v))
        v[0] = np.where(vn > 0, v[0], 1.0)                       # a zero column: any unit v
        v *= 1.0 / np.where(vn > 0, vn, 1.0)
        if j + 1 < q:
            sub = R[j:, j + 1:]
            sub -= 2.0 * v[:, None, :] * np.einsum("in,ikn->kn", v, sub)[None]
        vs.append(v)
    Y = np.zeros((dim, dim - q, n))
    for i in range(dim - q):
        Y[q + i, i] = 1.0
    for j in reversed(range(q)):
        sub = Y[j:]
        sub -= 2.0 * vs[j][:, None, :] * np.einsum("in,ikn->kn", vs[j], sub)[None]
    return Y

