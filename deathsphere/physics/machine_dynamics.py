"""Exact equations of motion of a machine (single-contact gyrostat) rolling
inside a fixed sphere, and the linear stability of its steady horizontal
orbits (beyond the paper; docs/machine.md sec. 5, eqs. M16-M20).

State (9, ...), as for the wheel (:mod:`deathsphere.physics.dynamics`): the
wheel centre C [m], the axle e1 (unit), the wheels' angular velocity w
[rad/s], lab components.  Geometry: e3 is the unit projection of C on the
wheel plane (away from the sphere's centre), the crown point Q = C + (a-t) e3
moves on the sphere of radius r - t, the contact is P = Q + t Q/|Q|; the
frame's axes are (e1, e2 = e3 x e1, e3 = -u) -- its pitch held by the
neglected wheelbase (the up-axis stays the line from the contact through
the wheel centre); the centre of mass is G = C - (h - a) e3.

Equations (docs/machine.md sec. 5):

* rolling: dC/dt = -w x (P - C);  de1/dt = w x e1;
* frame rate: omega_f = w - (w.e1) e1 + psi e1,  psi = -(de3/dt).e2;
* wheels' spin relative to the frame: s = w.e1 - psi;
* Newton: F = m (d2G/dt2 + g z);
* Euler about G: dL_G/dt = (P - G) x F + M_p e1,
  L_G = I_roll e2 (e2.omega_f) + I_pitch e1 (e1.omega_f) + I_yaw e3 (e3.omega_f) + J s e1,
  M_p the pitch moment of the constraint that holds the frame's pitch;
* the wheels' axial balance: J dw/dt . e1 = ((P - C) x F) . e1 (free axle).

The accelerations enter through d2G/dt2 and dL_G/dt affinely in (dw/dt,
M_p): the four equations are assembled from five evaluations by
second-order Taylor arithmetic (:class:`_Jet`) and solved as a 4x4 linear
system per body.  Only +, -, *, / and sqrt are used, so a complex step
differentiates the whole right-hand side exactly (the stability's
Jacobian).
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.machine import ride_orbit
from deathsphere.physics.stability.reduction import COMPLEX_STEP, householder_complement, spectrum
from deathsphere.physics.vectors import zcross

__all__ = ["MachineParams", "machine_rhs", "machine_orbit_state", "machine_stability"]


class MachineParams(tuple):
    """(a, t, r, h, g, mass, I_roll, I_pitch, I_yaw, J) as arrays broadcasting
    against the trailing (body) axes of a state."""

    __slots__ = ()
    _fields = ("a", "t", "r", "h", "g", "mass", "roll", "pitch", "yaw", "spin")

    def __new__(cls, a, t, r, h, g, mass, roll, pitch, yaw, spin):
        return super().__new__(cls, tuple(np.asarray(x, dtype=float) for x in
                                          (a, t, r, h, g, mass, roll, pitch, yaw, spin)))

    def __getattr__(self, name):
        try:
            return self[MachineParams._fields.index(name)]
        except ValueError:
            raise AttributeError(name) from None


class _Jet:
    """x(eps) = x0 + x1 eps + x2 eps^2 / 2, truncated (x1, x2: first and
    second time derivatives; x2 None: a first-order jet, whose products
    skip the second order).  Vectors carry a leading axis of 3."""

    __slots__ = ("x0", "x1", "x2")
    __array_ufunc__ = None

    def __init__(self, x0, x1, x2=None):
        self.x0, self.x1, self.x2 = x0, x1, x2

    def __add__(self, o):
        if isinstance(o, _Jet):
            x2 = None if self.x2 is None or o.x2 is None else self.x2 + o.x2
            return _Jet(self.x0 + o.x0, self.x1 + o.x1, x2)
        return _Jet(self.x0 + o, self.x1, self.x2)

    __radd__ = __add__

    def __neg__(self):
        return _Jet(-self.x0, -self.x1, None if self.x2 is None else -self.x2)

    def __sub__(self, o):
        return self + (-o)

    def __rsub__(self, o):
        return (-self) + o

    def __mul__(self, o):
        if isinstance(o, _Jet):
            x2 = (None if self.x2 is None or o.x2 is None
                  else self.x2 * o.x0 + 2 * self.x1 * o.x1 + self.x0 * o.x2)
            return _Jet(self.x0 * o.x0, self.x1 * o.x0 + self.x0 * o.x1, x2)
        return _Jet(self.x0 * o, self.x1 * o, None if self.x2 is None else self.x2 * o)

    __rmul__ = __mul__

    def __truediv__(self, o):
        if isinstance(o, _Jet):
            q0 = self.x0 / o.x0
            q1 = (self.x1 - q0 * o.x1) / o.x0
            q2 = (None if self.x2 is None or o.x2 is None
                  else (self.x2 - 2 * q1 * o.x1 - q0 * o.x2) / o.x0)
            return _Jet(q0, q1, q2)
        return _Jet(self.x0 / o, self.x1 / o, None if self.x2 is None else self.x2 / o)

    def __rtruediv__(self, o):
        q0 = o / self.x0
        q1 = -q0 * self.x1 / self.x0
        return _Jet(q0, q1, None if self.x2 is None else (-2 * q1 * self.x1 - q0 * self.x2) / self.x0)

    def __getitem__(self, i):
        return _Jet(self.x0[i], self.x1[i], None if self.x2 is None else self.x2[i])


def _jsqrt(x: _Jet) -> _Jet:
    s0 = np.sqrt(x.x0)
    s1 = x.x1 / (2 * s0)
    return _Jet(s0, s1, None if x.x2 is None else (x.x2 - 2 * s1 * s1) / (2 * s0))


def _jdot(u: _Jet, v: _Jet) -> _Jet:
    x2 = (None if u.x2 is None or v.x2 is None
          else np.sum(u.x2 * v.x0 + 2 * u.x1 * v.x1 + u.x0 * v.x2, axis=0))
    return _Jet(np.sum(u.x0 * v.x0, axis=0), np.sum(u.x1 * v.x0 + u.x0 * v.x1, axis=0), x2)


def _cross(u, v):
    return np.stack((u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]))


def _jcross(u: _Jet, v: _Jet) -> _Jet:
    x2 = (None if u.x2 is None or v.x2 is None
          else _cross(u.x2, v.x0) + 2 * _cross(u.x1, v.x1) + _cross(u.x0, v.x2))
    return _Jet(_cross(u.x0, v.x0), _cross(u.x1, v.x0) + _cross(u.x0, v.x1), x2)


def _dot(u, v):
    return np.sum(u * v, axis=0)


def _geometry(C, E, a, t):
    """(e1 unit, e3, Q, P) from C and E, on jets or arrays (the same lines)."""
    jet = isinstance(C, _Jet)
    dot = _jdot if jet else _dot
    sqrt = _jsqrt if jet else np.sqrt
    h1 = E / sqrt(dot(E, E))
    cperp = C - h1 * dot(C, h1)
    e3 = cperp / sqrt(dot(cperp, cperp))
    Q = C + e3 * (a - t)
    P = Q + Q * (t / sqrt(dot(Q, Q)))
    return h1, e3, Q, P


def machine_rhs(state, p: MachineParams, frame_rate=0.0, forces=False):
    """d(state)/dt of the machine's exact equations (module docstring);
    ``state`` (9, ...) real or complex.  ``frame_rate`` [rad/s]: components
    in a frame turning at that rate about +z.  With ``forces`` also returns
    (F/m (3, ...), M_p / m)."""
    state = np.asarray(state)
    C, E, W = state[0:3], state[3:6], state[6:9]
    a, t, h, g, m = p.a, p.t, p.h, p.g, p.mass
    # velocities (rolling): P from the geometry, C moves as the wheel rolls on P
    h1, e3, Q, P = _geometry(C, E, a, t)
    vC = -_cross(W, P - C)
    Edot = _cross(W, E)
    shape = np.broadcast_shapes(C.shape[1:], np.shape(a))
    # five evaluations: dw/dt = 0 and the three unit vectors (M_p enters linearly)
    k = 4
    Wd = np.zeros((3, k) + shape, dtype=state.dtype if np.iscomplexobj(state) else float)
    for i in range(3):
        Wd[i, i + 1] = 1.0
    add = (slice(None), None)  # a new axis after the vector axis: the k trials
    C_, E_, W_, vC_, Ed_, P_ = (x[add] for x in (C, E, W, vC, Edot, P))
    # first-order rates of the geometry (P dot) from a jet with zero second coefficients
    h1j, e3j, Qj, Pj = _geometry(_Jet(C_, vC_), _Jet(E_, Ed_), a, t)
    Pdot = Pj.x1
    # accelerations of C and E for each trial dw/dt
    Cdd = -_cross(Wd, P_ - C_) - _cross(W_, Pdot - vC_)
    Edd = _cross(Wd, E_) + _cross(W_, Ed_)
    h1j, e3j, Qj, Pj = _geometry(_Jet(C_, vC_, Cdd), _Jet(E_, Ed_, Edd), a, t)
    Gdd = Cdd - (h - a) * e3j.x2
    F = m * (Gdd + g * np.stack((0 * Gdd[0], 0 * Gdd[0], 1.0 + 0 * Gdd[0])))
    # frame angular velocity and its rate (first-order jets: value, rate)
    e3d = _Jet(e3j.x1, e3j.x2)                                    # de3/dt as a (first-order) jet
    h1j, e3j = _Jet(h1j.x0, h1j.x1), _Jet(e3j.x0, e3j.x1)         # first order from here on
    e2j = _jcross(e3j, h1j)
    Wj = _Jet(W_, Wd)
    psi = -_jdot(e3d, e2j)
    w1 = _jdot(Wj, h1j)
    omf = Wj - h1j * w1 + h1j * psi
    spin = w1 - psi
    L = (e2j * (_jdot(e2j, omf) * p.roll) + h1j * (_jdot(h1j, omf) * p.pitch)
         + e3j * (_jdot(e3j, omf) * p.yaw) + h1j * (spin * p.spin))
    Ldot = L.x1
    G = C_ - (h - a) * e3j.x0
    torque = _cross(Pj.x0 - G, F)
    euler = Ldot - torque                                         # = M_p e1
    axial = p.spin * _dot(Wd, h1j.x0) - _dot(_cross(Pj.x0 - C_, F), h1j.x0)
    R = np.concatenate((euler, axial[None]), axis=0)             # (4, k, ...)
    base = R[:, 0]
    A = R[:, 1:] - base[:, None]                                  # (4, 3, ...) columns for dw/dt
    Mcol = -h1j.x0[:, 0]                                          # the M_p column: -e1 in euler, 0 in axial
    Mcol = np.concatenate((Mcol, np.zeros_like(Mcol[:1])), axis=0)
    Afull = np.concatenate((A, Mcol[:, None]), axis=1)            # (4, 4, ...)
    Am = np.moveaxis(Afull, (0, 1), (-2, -1))
    bm = np.moveaxis(-base, 0, -1)[..., None]
    x = np.linalg.solve(Am, bm)[..., 0]                           # (..., 4)
    x = np.moveaxis(x, -1, 0)
    Wdot = x[:3]
    out = np.concatenate((vC, Edot, Wdot))
    fr = np.asarray(frame_rate)
    if np.any(fr != 0):
        for i in (0, 3, 6):          # - Omega z x u for u = C, E, W
            out[i] = out[i] + fr * state[i + 1]
            out[i + 1] = out[i + 1] - fr * state[i]
    if not forces:
        return out
    # the force for the solved accelerations (affine in dw/dt: combine the trials)
    Fsol = F[:, 0] + np.sum((F[:, 1:] - F[:, :1]) * Wdot[None], axis=1)
    return out, Fsol / m, x[3] / m


def machine_orbit_state(theta, alpha, p: MachineParams):
    """State (9, ...) of a machine placed on the steady horizontal orbit
    (theta, alpha) at azimuth 0, and its rate Omega (eq. M8; NaN where none):
    C = Q + (a - t) u, e1 = -sin(alpha) r-hat - cos(alpha) z,
    w = Omega z + s e1 with s = sigma Omega (eq. M4).  Complex theta, alpha
    accepted (complex step)."""
    theta, alpha = np.asarray(theta), np.asarray(alpha)
    st, ct, sa, ca = np.sin(theta), np.cos(theta), np.sin(alpha), np.cos(alpha)
    a, t, r, h = p.a, p.t, p.r, p.h
    hq = h - t
    r_g = (r - t) * st - hq * ca
    d_r = t * st + hq * ca
    d_z = t * ct - hq * sa
    w = (a - t) + t * (st * ca - ct * sa)
    sigma = r * st / w
    den = sa * (p.spin / p.mass * sigma + (p.yaw - p.pitch) / p.mass * ca) - d_z * r_g
    om2 = p.g * d_r / den
    om = np.sqrt(om2)
    zero = 0 * (st * sa + a)
    one = zero + 1.0
    cx = (r - t) * st - (a - t) * ca
    cz = (r - t) * ct + (a - t) * sa
    C = np.stack((cx, zero, cz))
    E = np.stack((-sa + zero, zero, -ca + zero))
    W = np.stack((0 * one, zero, om * one)) + sigma * om * E
    return np.concatenate((C, E, W)), om


def _params_flat(p: MachineParams, n):
    return MachineParams(*(np.broadcast_to(x, (n,)) for x in p))


def machine_stability(theta, alpha, p: MachineParams):
    """Exact linear stability of a machine's steady horizontal orbits
    (docs/machine.md sec. 5): the Jacobian of :func:`machine_rhs` in the
    frame turning at Omega (complex step), on the 7-dimensional constraint
    manifold (|e1| = 1, |Q| = r - t) minus the three neutral directions
    (phase along the orbit; d/dtheta, d/dalpha of the family), leaving 4
    eigenvalues.  Inputs 1-D of one length n (theta, alpha [rad]); orbits
    that do not exist (NaN Omega) or where the wheel does not fit give NaN.

    Returns dict: ``growth_rate`` [1/s], ``freq_slow``, ``freq_fast``
    [rad/s], ``verdict`` (int8), ``eigenvalues`` (n, 4), ``rate_scale``."""
    theta = np.asarray(theta, dtype=float).reshape(-1)
    alpha = np.asarray(alpha, dtype=float).reshape(-1)
    n = theta.size
    p = _params_flat(p, n)
    res = ride_orbit(theta, alpha, p.r, p.g, p.mass, p.h, p.a, p.t, p.pitch, p.yaw, p.spin, p.h)
    ok = np.isfinite(res["omega"]) & (np.sin(theta - alpha) * (p.r - p.t) > (p.a - p.t))
    ok &= np.abs(np.sin(theta)) > SINGULAR
    th = np.where(ok, theta, np.pi / 2)
    al = np.where(ok, alpha, np.pi / 4)
    # a placeholder orbit that exists (theta 90, alpha 45 needs d_r > 0 and D > 0: true for h > t >= 0)
    X0, Om = machine_orbit_state(th, al, p)
    Om = np.where(np.isfinite(Om), Om, 1.0)
    X0 = np.where(np.isfinite(X0), X0, 1.0)
    step = COMPLEX_STEP
    dth = np.imag(machine_orbit_state(th + 1j * step, al, p)[0]) / step
    dal = np.imag(machine_orbit_state(th, al + 1j * step, p)[0]) / step
    C, E, W = X0[0:3], X0[3:6], X0[6:9]
    a, t = p.a, p.t
    S = np.sqrt(np.sum(W * W, axis=0) + Om ** 2 + p.g / a)
    D = np.empty((9, n))
    D[0:3], D[3:6], D[6:9] = a, 1.0, S
    # constraint gradients by complex step of |E|^2 and |Q|^2 in each of the 6 position components
    grads = np.zeros((9, 2, n))
    for i in range(6):
        dX = np.zeros((6, n), dtype=complex)
        dX[i] = 1j * step
        Cc, Ec = C + dX[0:3], E + dX[3:6]
        _, _, Q, _ = _geometry(Cc, Ec, a, t)
        grads[i, 0] = np.imag(np.sum(Ec * Ec, axis=0)) / step
        grads[i, 1] = np.imag(np.sum(Q * Q, axis=0)) / step
    A = np.zeros((9, 5, n))
    A[:, 0:2] = grads * D[:, None, :]
    for blk in (slice(0, 3), slice(3, 6), slice(6, 9)):
        A[blk, 2] = zcross(X0[blk]) / D[blk]
    A[:, 3] = dth / D
    A[:, 4] = dal / D
    A *= 1.0 / np.sqrt(np.einsum("ikn,ikn->kn", A, A))[None]
    Y = householder_complement(A)                                  # (9, 4, n)
    dirs = Y * D[:, None, :]                                        # (9, 4, n)
    pc = MachineParams(*(x[None, :] for x in p))
    Xc = X0[:, None, :] + 1j * step * dirs
    JdX = np.imag(machine_rhs(Xc, pc, Om[None, :])) / step           # (9, 4, n)
    K = np.einsum("ijn,ikn->njk", Y, JdX / D[:, None, :])
    K = np.where(ok[:, None, None], K, np.nan)
    scale = np.where(ok, S, np.nan)
    ev, growth, slow, fast, verdict = spectrum(K, scale)
    return {"growth_rate": growth, "freq_slow": slow, "freq_fast": fast, "verdict": verdict,
            "eigenvalues": ev, "rate_scale": scale, "omega": np.where(ok, Om, np.nan)}
