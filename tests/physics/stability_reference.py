"""Reference implementation of the exact stability of horizontal wheel
orbits (deathsphere.physics.stability.horizontal.wheel_stability) as first written:
complex-step Jacobian on four directions, complement of the neutral
directions by a complete QR, eigenvalues by ``np.linalg.eigvals`` of the
reduced 4x4 Jacobian.  The fast path must reproduce its verdicts and
frequencies (tests/physics/test_stability_fast.py); benchmarks/bench_stability.py
times both.
"""

import numpy as np

from deathsphere.physics import dynamics as dyn
from deathsphere.physics.geometry import SINGULAR, fits_inside, fits_outside
from deathsphere.physics.stability.horizontal import (
    CHUNK,
    empty_result,
    stability_result,
)
from deathsphere.physics.stability.reduction import COMPLEX_STEP
from deathsphere.physics.stability.verdict import STABLE_TOL, UNSTABLE_TOL, Verdict
from deathsphere.physics.vectors import dot, zcross
from deathsphere.physics.wheel import omega_squared


def _complex_step_ref(fun, x0, dx, h=COMPLEX_STEP):
    """Directional derivative of ``fun`` at x0 along dx by complex step."""
    return np.imag(fun(x0 + 1j * h * dx)) / h


def _reduce_ref(K, scale):
    """Growth rate, frequencies and verdict from stacked reduced Jacobians."""
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
    with np.errstate(invalid="ignore", divide="ignore"):
        rel = growth / scale
    verdict = np.full(growth.shape, Verdict.UNKNOWN, dtype=np.int8)
    verdict[np.nan_to_num(rel, nan=np.inf) <= STABLE_TOL] = Verdict.STABLE
    verdict[np.nan_to_num(rel, nan=-np.inf) >= UNSTABLE_TOL] = Verdict.UNSTABLE
    return ev, growth, slow, fast, verdict



def _orthonormal_complement_ref(A, dim):
    """Orthonormal basis (n, dim, dim - A.shape[-1]) of the complement of the
    column span of the stacked (n, dim, q) matrices A (assumed full rank)."""
    q = A.shape[-1]
    Q, _ = np.linalg.qr(A, mode="complete")
    return Q[..., q:]



def _wheel_linearisation_ref(theta, alpha, a, r, k, g, outside):
    """Reduced 4x4 Jacobians of the wheel's flow about steady orbits."""
    shape = theta.shape
    n = theta.size
    th, al, a, r, k, g, out = (x.reshape(-1) for x in (theta, alpha, a, r, k, g, outside))
    om2 = omega_squared(th, al, a, r, k, g)
    fits = np.where(out, fits_outside(th, al), fits_inside(th, al, a, r))
    ok = fits & (np.nan_to_num(om2, nan=-1.0) > SINGULAR * g / r)
    # placeholders where no orbit exists keep the algebra finite (NaN later)
    th_s = np.where(ok, th, np.pi / 2)
    al_s = np.where(ok, al, np.pi / 4)
    r_s = np.where(ok, r, 10.0 * a)
    out_s = np.where(ok, out, False)
    p = dyn.BodyParams(a, r_s, k, g, out_s, np.zeros(n, dtype=bool))
    X0, Om = dyn.wheel_orbit_state(th_s, al_s, a, r_s, k, g, out_s)
    # neutral directions: phase, d/dtheta, d/dalpha (complex step)
    dth = np.imag(dyn.wheel_orbit_state(th_s + 1j * COMPLEX_STEP, al_s, a, r_s, k, g, out_s)[0]) / COMPLEX_STEP
    dal = np.imag(dyn.wheel_orbit_state(th_s, al_s + 1j * COMPLEX_STEP, a, r_s, k, g, out_s)[0]) / COMPLEX_STEP
    c, e1, w = X0[dyn.C], X0[dyn.E1], X0[dyn.W]
    gen = np.concatenate((zcross(c), zcross(e1), zcross(w)))
    # scaling: lengths by a, rates by S
    S = np.sqrt(dot(w, w) + Om ** 2 + g / a)
    D = np.concatenate((np.broadcast_to(a, (3, n)), np.ones((3, n)),
                        np.broadcast_to(S, (3, n))))
    V = np.stack((gen, dth, dal), axis=-1) / D[..., None]          # (9, n, 3)
    # constraint gradients (scaled: grad_x~ = D grad_x)
    e3 = dyn.contact_geometry(X0, p).e3
    pvec = c + a * e3
    c1 = dot(c, e1)
    n1 = np.concatenate((np.zeros((3, n)), e1, np.zeros((3, n))))
    n2 = np.concatenate((pvec, -a * c1 * e3, np.zeros((3, n))))
    Nrm = np.stack((n1, n2), axis=-1) * D[..., None]
    A = np.moveaxis(np.concatenate((Nrm, V), axis=-1), 0, 1)          # (n, 9, 5)
    # normalise columns for a well-conditioned QR
    A = A / np.linalg.norm(A, axis=1, keepdims=True)
    Wb = _orthonormal_complement_ref(A, 9)                                 # (n, 9, 4)
    # J~ W by complex step, all 4 directions at once
    dX = np.moveaxis(Wb, 0, 1) * D[:, :, None]                         # (9, n, 4)
    pc = dyn.BodyParams(*(x[:, None] for x in p))
    JdX = _complex_step_ref(lambda x: dyn.rhs(x, pc, Om[:, None]), X0[:, :, None], dX)
    JW = np.moveaxis(JdX / D[:, :, None], 1, 0)                        # (n, 9, 4)
    K = np.einsum("nij,nik->njk", Wb, JW)
    K = np.where(ok[:, None, None], K, np.nan)
    scale = np.where(ok, S, np.nan)
    basis = Wb * np.moveaxis(D, 0, 1)[:, :, None]
    return K, scale, np.where(ok, Om, np.nan), shape, basis, X0



def wheel_stability_ref(theta, alpha, a, r, k, g, outside=False):
    """The exact stability of wheel orbits as first written (eigvals of the
    reduced 4x4 Jacobian, complete QR for the complement), kept as the
    reference for the fast path."""
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (theta, alpha, a, r, k, g)))
    outside = np.broadcast_to(np.asarray(outside, dtype=bool), theta.shape)
    dyn.body_params(a, r, k, g, outside)          # validation only
    if theta.size == 0:
        return empty_result(theta.shape, 4)
    shape = theta.shape
    flat = [x.reshape(-1) for x in (theta, alpha, a, r, k, g, outside)]
    parts = []
    for i in range(0, theta.size, CHUNK):       # bounded memory; vectorised within
        K, scale, Om, _, _, _ = _wheel_linearisation_ref(*(x[i:i + CHUNK] for x in flat))
        parts.append((*_reduce_ref(K, scale), scale, Om))
    ev, growth, slow, fast, verdict, scale, Om = (np.concatenate(z) for z in zip(*parts))
    return stability_result(shape, ev, growth, slow, fast, verdict, scale, Om)
