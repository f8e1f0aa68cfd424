"""Exact linear stability of steady orbits of the paper's wheel and ball on
any ground (beyond the paper; docs/stability.md, "On any ground").

As :mod:`~deathsphere.physics.stability.horizontal` does on the sphere: the
flow of :mod:`deathsphere.physics.dynamics_on` in the frame turning with the
orbit, linearised by forward-mode derivatives (``jvp_on``), restricted to
the complement of the constraint normals, the rotation about the vertical
and the steady family's directions; the family is moved along the meridian
(d/ds = cos(beta) d/drho + sin(beta) d/dz, the ball's wall angle turning
at d beta/ds = kappa_meridian) by complex steps of the closed-form states.
On the outside the same reduction holds with the flow's contact taken on
the other side (docs/dynamics.md sec. 7, "Outside"): the steady states,
the constraint normals and the family are written with e3, whatever its
side.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics import dynamics_on as don
from deathsphere.physics.stability.reduction import (
    COMPLEX_STEP,
    householder_complement,
    spectrum,
    spectrum_from_invariants,
)
from deathsphere.physics.stability.horizontal import stability_result
from deathsphere.physics.vectors import dot, zcross

__all__ = ["wheel_stability_on", "wheel_reduced_jacobian_on", "ball_stability_on"]


def _flat(*xs):
    xs = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in xs))
    return xs[0].shape, [x.reshape(-1) for x in xs]


def _reduced(X0, A, D, p, Om):
    """K = Y^T D^-1 J D Y on the complement Y of the scaled columns A."""
    A = A * (1.0 / np.sqrt(np.einsum("ikn,ikn->kn", A, A)))[None]
    Y = householder_complement(A)
    JdX = don.jvp_on(X0, Y * D[:, None, :], don.GroundBody(p.ground, *(x[None] for x in p[1:])), Om)
    return np.einsum("ijn,ikn->njk", Y, JdX / D[:, None, :])


def wheel_stability_on(ground, height, alpha, a, k, g, outside=False):
    """Beyond the paper (docs/stability.md): exact linear stability of a wheel's steady orbits at lane ``height``
    [m] and tilt ``alpha`` [rad] on any ground, inside or ``outside`` (bools,
    broadcast): the dict of
    :func:`~deathsphere.physics.stability.horizontal.wheel_stability`
    (4 nutation eigenvalues in the turning frame, growth rate, verdict).
    The steady state is the same on both sides (eqs. 11-13, 29: alpha fixes
    e3, the centre a behind the contact); the side enters through the
    contact's e3 against grad F (docs/dynamics.md sec. 7, "Outside")."""
    red = wheel_reduced_jacobian_on(ground, height, alpha, a, k, g, outside)
    ok, Om = red["ok"], red["omega"]
    scale = np.where(ok, red["scale"], np.nan)
    ev, growth, slow, fast, verdict = spectrum_from_invariants(red["K"], scale)
    return stability_result(red["shape"], ev, growth, slow, fast, verdict, scale, np.where(ok, Om, np.nan))


def wheel_reduced_jacobian_on(ground, height, alpha, a, k, g, outside=False):
    """Beyond the paper (docs/stability.md, "On any ground"): the reduced
    Jacobian of :func:`wheel_stability_on`, flat over the broadcast orbits
    (n,): ``K`` (n, 4, 4) (NaN where no orbit), ``ok`` (n,) where the
    orbit exists, ``scale`` its rate scale [rad/s], ``omega`` Omega
    [rad/s], ``shape`` the broadcast shape (the stability map's signed
    margin is taken from K's invariants, as on the globe)."""
    shape, (h, al, a, k, g, out) = _flat(height, alpha, a, k, g, outside)
    out = out != 0
    n = h.size
    rho, z = ground.contact(h)
    beta = ground.wall_angle(h)
    X0, Om = don.wheel_state_at(rho, z, al, a, k, g)
    ok = np.isfinite(Om)
    Om_s = np.where(ok, Om, 1.0)
    step = 1j * COMPLEX_STEP
    ds = np.imag(don.wheel_state_at(rho + step * np.cos(beta), z + step * np.sin(beta), al, a, k, g)[0]) / COMPLEX_STEP
    da = np.imag(don.wheel_state_at(rho, z, al + step, a, k, g)[0]) / COMPLEX_STEP
    p = don.ground_body(ground, a, k, g, outside=out)
    X0 = np.where(ok, X0, np.nan_to_num(X0))
    c, e1, w = X0[0:3], X0[3:6], X0[6:9]
    e3, pt = don.contact_on(X0, p)
    G = ground.gradient(*pt)
    S = np.sqrt(dot(w, w) + Om_s ** 2 + g / a)
    D = np.empty((9, n))
    D[0:3], D[3:6], D[6:9] = a, 1.0, S
    A = np.zeros((9, 5, n))
    A[3:6, 0] = e1 * D[3:6]                                   # |e1| = 1
    A[0:3, 1] = G * D[0:3]                                    # F(p) = 0: d/dc and d/de1
    A[3:6, 1] = -a * dot(G, e1) * e3 * D[3:6]
    for blk in (slice(0, 3), slice(3, 6), slice(6, 9)):      # rotation about the vertical
        A[blk, 2] = zcross(X0[blk]) / D[blk]
    A[:, 3] = np.nan_to_num(ds) / D
    A[:, 4] = np.nan_to_num(da) / D
    K = _reduced(X0, A, D, p, Om_s)
    K = np.where(ok[:, None, None], K, np.nan)
    return {"K": K, "ok": ok, "scale": S, "omega": Om, "shape": shape}


def ball_stability_on(ground, height, omega, a, k, g, outside=False):
    """Exact linear stability of a ball's steady orbits of rate ``omega``
    [rad/s] at lane ``height`` [m] on any ground, inside or ``outside`` (bools,
    broadcast; beyond the paper, docs/stability.md): the dict of
    :func:`~deathsphere.physics.stability.horizontal.sphere_stability`
    (one nutation pair, in ``freq_fast``; for a ball in a vertical drum
    the bobbing of the golfer's dilemma, docs/dynamics.md eq. G9)."""
    shape, (h, Om, a, k, g, out) = _flat(height, omega, a, k, g, outside)
    out = out != 0
    n = h.size
    rho, z = ground.contact(h)
    beta = ground.wall_angle(h)
    kappa = ground.curvatures(h)[0]
    ok = np.isfinite(Om) & (Om != 0) & (np.abs(np.sin(beta)) > 1e-12)
    Om_s = np.where(ok, Om, 1.0)
    X0, _ = don.ball_state_at(rho, z, beta, Om_s, a, k, g, outside=out)
    step = 1j * COMPLEX_STEP
    ds = np.imag(don.ball_state_at(rho + step * np.cos(beta), z + step * np.sin(beta), beta + step * kappa,
                                   Om_s, a, k, g, outside=out)[0]) / COMPLEX_STEP
    dom = np.imag(don.ball_state_at(rho, z, beta, Om_s + step, a, k, g, outside=out)[0]) / COMPLEX_STEP
    p = don.ground_body(ground, a, k, g, sphere=True, outside=out)
    e3, _ = don.contact_on(X0, p)
    w = X0[6:9]
    S = np.sqrt(dot(w, w) + Om_s ** 2 + g / a)
    # the marker rows e1 are held fixed: 6 active rows, 4 removed, 2 left
    D = np.empty((9, n))
    D[0:3], D[3:6], D[6:9] = a, 1.0, S
    A = np.zeros((9, 7, n))
    A[3:6, 0:3] = np.eye(3)[:, :, None]                        # the marker does not enter
    A[0:3, 3] = e3 * D[0:3]                                   # distance a from the surface
    for blk in (slice(0, 3), slice(6, 9)):
        A[blk, 4] = zcross(X0[blk]) / D[blk]
    A[0:3, 5], A[6:9, 5] = ds[0:3] / D[0:3], ds[6:9] / D[6:9]
    A[0:3, 6], A[6:9, 6] = dom[0:3] / D[0:3], dom[6:9] / D[6:9]
    K = _reduced(X0, A, D, p, Om_s)
    K = np.where(ok[:, None, None], K, np.nan)
    scale = np.where(ok, S, np.nan)
    ev, growth, slow, fast, verdict = spectrum(K, scale)
    return stability_result(shape, ev, growth, slow, fast, verdict, scale, np.where(ok, Om, np.nan))
