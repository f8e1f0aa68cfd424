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
* Newton: F + lambda f = m (d2G/dt2 + g z), F the contact force;
* Euler about G: dL_G/dt = (P - G) x F + lambda (e2 x n) + (Q - G) x lambda f,
  L_G = I_roll e2 (e2.omega_f) + I_pitch e1 (e1.omega_f) + I_yaw e3 (e3.omega_f) + J s e1,
  lambda (e2 x n) and lambda f, f = (e2 - (n.e2) n)/|Q| at the crown point,
  the ideal reaction of the constraint n.e2 = 0 (n = Q/|Q|) that holds the
  frame's pitch (:func:`_pitch_reaction`);
* the wheels' axial balance: J dw/dt . e1 = ((P - C) x F) . e1 (free axle).

The accelerations enter through d2G/dt2 and dL_G/dt affinely in (dw/dt,
lambda): the residual of the four equations is evaluated for four trial
accelerations (the geometry's derivatives written out in :class:`GeometryRates`,
the angular momentum's rate by first-order Taylor arithmetic, :class:`_Jet`)
and solved as a 4x4 linear system per body.  Only +, -, *, / and sqrt are
used, so a complex step differentiates the whole right-hand side exactly;
the stability's Jacobian differentiates the residual at the solved
accelerations instead (implicit function, :func:`_rhs_directional`).

Every function takes the state, the ground (the sphere,
:class:`~deathsphere.physics.ground.Sphere`, centred at the origin), gravity
g [m/s^2] and the machine's arrays
(:class:`~deathsphere.physics.machine_arrays.MachineArrays`), all
broadcasting against the trailing (body) axes of the state.  The equations
use the sphere's centre and not its radius, which the state holds (|Q| =
r - t).
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.ground import Sphere
from deathsphere.physics.machine import ride_orbit
from deathsphere.physics.machine_arrays import MachineArrays
from deathsphere.physics.stability.reduction import (
    COMPLEX_STEP,
    householder_complement,
    spectrum_from_invariants,
)
from deathsphere.physics.vectors import cross as _cross
from deathsphere.physics.vectors import dot as _dot
from deathsphere.physics.vectors import zcross

__all__ = ["GeometryRates", "yaw_is_determined", "YAW_UNDETERMINED", "machine_geometry", "machine_rhs", "machine_orbit_state",
           "machine_jacobian", "machine_stability", "rhs_of_geometry", "reduced_jacobian"]


class _Jet:
    """x(eps) = x0 + x1 eps, truncated: a value and its time derivative.
    Vectors carry a leading axis of 3."""

    __slots__ = ("x0", "x1")
    __array_ufunc__ = None

    def __init__(self, x0, x1):
        self.x0, self.x1 = x0, x1

    def __add__(self, o):
        if isinstance(o, _Jet):
            return _Jet(self.x0 + o.x0, self.x1 + o.x1)
        return _Jet(self.x0 + o, self.x1)

    __radd__ = __add__

    def __neg__(self):
        return _Jet(-self.x0, -self.x1)

    def __sub__(self, o):
        return self + (-o)

    def __mul__(self, o):
        if isinstance(o, _Jet):
            return _Jet(self.x0 * o.x0, self.x1 * o.x0 + self.x0 * o.x1)
        return _Jet(self.x0 * o, self.x1 * o)

    __rmul__ = __mul__


def _jdot(u: _Jet, v: _Jet) -> _Jet:
    return _Jet(_dot(u.x0, v.x0), _dot(u.x1, v.x0) + _dot(u.x0, v.x1))


def _jcross(u: _Jet, v: _Jet) -> _Jet:
    return _Jet(_cross(u.x0, v.x0), _cross(u.x1, v.x0) + _cross(u.x0, v.x1))


def machine_geometry(C, E, a, t):
    """The machine's geometry (eq. M16; docs/machine.md sec. 5): the unit
    axle e1, the unit vector e3 from the wheel centre towards the crown
    (the up-axis is -e3), the crown point Q and the contact point P (3, ...)
    from the wheel centre C and the axle vector E (3, ...)."""
    g = GeometryRates(C, E, a, t)
    return g.h1, g.e3, g.Q, g.P


class GeometryRates:
    """The geometry of :func:`machine_geometry` (eq. M16), and with
    :meth:`rates` its first time derivatives (suffix 1) for rates
    vC = dC/dt, Ed = dE/dt, the intermediate norms kept so that the second
    derivative of e3 for many trial accelerations (:meth:`e3_second`)
    reuses them."""

    __slots__ = ("C", "E", "a_t", "t", "C1", "E1", "sE", "sE1", "h1", "h1_1", "d", "d1", "cp", "cp1", "sc",
                 "sc1", "e3", "e3_1", "Q", "sQ", "P", "P1")

    def __init__(self, C, E, a, t):
        self.C, self.E, self.a_t, self.t = C, E, a - t, t
        self.sE = np.sqrt(_dot(E, E))
        self.h1 = E / self.sE
        self.d = _dot(C, self.h1)
        self.cp = C - self.h1 * self.d
        self.sc = np.sqrt(_dot(self.cp, self.cp))
        self.e3 = self.cp / self.sc
        self.Q = C + self.e3 * self.a_t
        self.sQ = np.sqrt(_dot(self.Q, self.Q))
        self.P = self.Q + self.Q * (t / self.sQ)

    def rates(self, vC, Ed):
        """The first derivatives for dC/dt = vC, dE/dt = Ed (returns self)."""
        C, E, t, Q, sQ = self.C, self.E, self.t, self.Q, self.sQ
        self.C1, self.E1 = vC, Ed
        self.sE1 = _dot(E, Ed) / self.sE
        self.h1_1 = (Ed - self.h1 * self.sE1) / self.sE
        self.d1 = _dot(vC, self.h1) + _dot(C, self.h1_1)
        self.cp1 = vC - (self.h1_1 * self.d + self.h1 * self.d1)
        self.sc1 = _dot(self.cp, self.cp1) / self.sc
        self.e3_1 = (self.cp1 - self.e3 * self.sc1) / self.sc
        Q1 = vC + self.e3_1 * self.a_t
        sQ1 = _dot(Q, Q1) / sQ
        self.P1 = Q1 + Q1 * (t / sQ) - Q * (t * sQ1 / (sQ * sQ))
        return self

    def e3_second(self, C, E, Cdd, Edd):
        """d2e3/dt2 for second derivatives Cdd, Edd (3, k, ...) of C and E
        (C, E with a matching axis of one): u s = v differentiated twice,
        u2 = (v2 - 2 u1 s1 - u0 s2) / s with s2 = (|v1|^2 + v0.v2 - s1^2) / s,
        for h1 = E/|E| and e3 = cperp/|cperp|, cperp = C - h1 (C.h1)."""
        sE2 = (_dot(self.E1, self.E1) - self.sE1 * self.sE1 + _dot(E, Edd)) / self.sE
        h1_2 = (Edd - 2 * self.h1_1 * self.sE1 - self.h1 * sE2) / self.sE
        d2 = _dot(Cdd, self.h1) + 2 * _dot(self.C1, self.h1_1) + _dot(C, h1_2)
        cp2 = Cdd - (h1_2 * self.d + 2 * self.h1_1 * self.d1 + self.h1 * d2)
        sc2 = (_dot(self.cp1, self.cp1) - self.sc1 * self.sc1 + _dot(self.cp, cp2)) / self.sc
        return (cp2 - 2 * self.e3_1 * self.sc1 - self.e3 * sc2) / self.sc

    def pitch_reaction(self):
        """The pitch constraint's reaction per unit multiplier (eq. M18; :func:`_pitch_reaction`)."""
        return _pitch_reaction(self)

    def outward(self):
        """The ground's outward unit normal at the contact, P/|P| (3, ...)."""
        return self.P / np.sqrt(_dot(self.P, self.P))


def _residuals(state, g, p: MachineArrays, Wd, geometry=GeometryRates):
    """The Euler and axial-balance residuals (4, k, ...) of the machine at
    ``state`` for k trial wheel accelerations ``Wd`` (3, k, ...) and zero
    pitch moment, with the contact forces F (3, k, ...) [N] they need, the
    rates dC/dt and dE/dt (3, ...) and the axle e1 (3, ...).  The residual
    is affine in (dw/dt, lambda): R = b + A dw/dt - k lambda, k the pitch
    reaction's column (the geometry's ``pitch_reaction``, returned with its
    force).  ``geometry``: the crown point's geometry class, ``geometry(C,
    E, a, t)`` with :class:`GeometryRates`' attributes and methods (the
    sphere's by default; any ground's, :mod:`deathsphere.physics.machine_dynamics_on`)."""
    C, E, W = state[0:3], state[3:6], state[6:9]
    a, t, h, m = p.wheel_radius, p.tyre_radius, p.com_height, p.mass
    add = (slice(None), None)  # a new axis after the vector axis: the k trials
    C_, E_, W_ = C[add], E[add], W[add]
    geo = geometry(C_, E_, a, t)
    # velocities (rolling): C moves as the wheel rolls on the contact P
    P_ = geo.P
    vC_ = -_cross(W_, P_ - C_)
    Ed_ = _cross(W_, E_)
    geo.rates(vC_, Ed_)
    vC, Edot = vC_[:, 0], Ed_[:, 0]
    # accelerations of C and E for each trial dw/dt
    Cdd = -_cross(Wd, P_ - C_) - _cross(W_, geo.P1 - vC_)
    Edd = _cross(Wd, E_) + _cross(W_, Ed_)
    e3dd = geo.e3_second(C_, E_, Cdd, Edd)
    Gdd = Cdd - (h - a) * e3dd
    F = m * (Gdd + g * np.stack((0 * Gdd[0], 0 * Gdd[0], 1.0 + 0 * Gdd[0])))
    # frame angular velocity and its rate (first-order jets: value, rate)
    e3d = _Jet(geo.e3_1, e3dd)                                    # de3/dt as a (first-order) jet
    h1j, e3j = _Jet(geo.h1, geo.h1_1), _Jet(geo.e3, geo.e3_1)
    Pj = _Jet(geo.P, geo.P1)
    e2j = _jcross(e3j, h1j)
    Wj = _Jet(W_, Wd)
    psi = -_jdot(e3d, e2j)
    spin = _jdot(Wj, h1j) - psi
    # the frame turns with w's components across the axle and psi about it
    # (omega_f = w - (w.e1) e1 + psi e1, with e1, e2, e3 orthonormal)
    L = (e2j * (_jdot(e2j, Wj) * p.roll_inertia) + e3j * (_jdot(e3j, Wj) * p.yaw_inertia)
         + h1j * (psi * p.pitch_inertia + spin * p.spin_inertia))
    Ldot = L.x1
    G = C_ - (h - a) * e3j.x0
    torque = _cross(Pj.x0 - G, F)
    euler = Ldot - torque                                         # = lambda k_E
    axial = p.spin_inertia * _dot(Wd, h1j.x0) - _dot(_cross(Pj.x0 - C_, F), h1j.x0)   # = lambda k_A
    R = np.concatenate((euler, axial[None]), axis=0)             # (4, k, ...)
    return R, F, vC, Edot, geo.pitch_reaction()


def _pitch_reaction(geo: GeometryRates):
    """The pitch constraint's reaction per unit multiplier (eq. M18):
    ``(k, f)`` with k (4, ...) its column in the residual (Euler's three
    rows, the axial row) and f (3, ...) the force it puts on the frame at
    the crown point.

    The neglected wheelbase holds n.e2 = 0 (n = Q/|Q| the sphere's normal
    through the crown point, e2 the frame's direction of travel), the limit
    of two tyres a wheelbase apart both on the sphere.  Its ideal reaction
    (the gradient of the constraint: no work on any motion that keeps it)
    is a couple lambda (e2 x n) and a force lambda (e2 - (n.e2) n)/|Q| at
    Q (docs/machine.md sec. 5).  With the contact force F_c = m (d2G/dt2 +
    g z) - f, Euler about G reads dL_G/dt - (P - G) x m (d2G/dt2 + g z) =
    lambda (1 + t/|Q|) (e2 x n) (P - Q = t n) and the wheels' axial
    balance J dw/dt.e1 - ((P - C) x m (d2G/dt2 + g z)).e1 = lambda
    ((P - C).e3)/|Q| (the rolling radius over |Q|)."""
    e1, e3, Q, sQ = geo.h1[:, 0], geo.e3[:, 0], geo.Q[:, 0], geo.sQ[0]
    n = Q / sQ
    e2 = _cross(e3, e1)
    k_euler = _cross(e2, n) * (1.0 + geo.t / sQ)
    k_axial = _dot(geo.P[:, 0] - geo.C[:, 0], e3) / sQ
    force = (e2 - n * _dot(n, e2)) / sQ
    return np.concatenate((k_euler, k_axial[None]), axis=0), force


def _trial_accelerations(shape, dtype):
    """The four trials (3, 4, ...): dw/dt = 0 and the three unit vectors."""
    Wd = np.zeros((3, 4) + shape, dtype=dtype)
    for i in range(3):
        Wd[i, i + 1] = 1.0
    return Wd


def _acceleration_system(state, g, p: MachineArrays, geometry=GeometryRates):
    """(A, b) of the accelerations: A (..., 4, 4) x = b (..., 4) for
    x = (dw/dt, lambda), from the residual at the four trials, with the forces
    of the trials (3, 4, ...) and the rates dC/dt, dE/dt, e1."""
    shape = np.broadcast_shapes(state.shape[1:], np.shape(p.wheel_radius), np.shape(g))
    Wd = _trial_accelerations(shape, state.dtype if np.iscomplexobj(state) else float)
    R, F, vC, Edot, (kcol, fpitch) = _residuals(state, g, p, Wd, geometry)
    base = R[:, 0]
    A = R[:, 1:] - base[:, None]                                  # (4, 3, ...) columns for dw/dt
    Afull = np.concatenate((A, -kcol[:, None]), axis=1)           # (4, 4, ...): R - lambda k = 0
    Am = np.moveaxis(Afull, (0, 1), (-2, -1))
    bm = np.moveaxis(-base, 0, -1)
    return Am, bm, F, vC, Edot, fpitch


def _turning(out, state, frame_rate):
    """Add the rates of a frame turning at ``frame_rate`` about +z:
    - Omega z x u for u = C, E, W (in place)."""
    fr = np.asarray(frame_rate)
    if np.any(fr != 0):
        for i in (0, 3, 6):
            out[i] = out[i] + fr * state[i + 1]
            out[i + 1] = out[i + 1] - fr * state[i]
    return out


def machine_rhs(state, ground, g, machine: MachineArrays, frame_rate=0.0, forces=False):
    """d(state)/dt of the machine's exact equations (module docstring;
    docs/machine.md eqs. M16-M19); ``state`` (9, ...) real or complex, inside
    the sphere ``ground``, gravity ``g`` [m/s^2], the machine's arrays.
    ``frame_rate`` [rad/s]: components in a frame turning at that rate about
    +z.  With ``forces`` also returns (F/m (3, ...), lambda / m): the contact
    force per unit mass and the pitch constraint's multiplier."""
    return rhs_of_geometry(state, g, machine, GeometryRates, frame_rate, forces)


def rhs_of_geometry(state, g, machine: MachineArrays, geometry, frame_rate=0.0, forces=False):
    """:func:`machine_rhs` for the crown point's ``geometry`` (a class as
    :class:`GeometryRates`): the one solve of eqs. M16-M19 that every
    ground's equations share."""
    state = np.asarray(state)
    Am, bm, F, vC, Edot, fpitch = _acceleration_system(state, g, machine, geometry)
    x = np.moveaxis(np.linalg.solve(Am, bm[..., None])[..., 0], -1, 0)   # (4, ...)
    Wdot = x[:3]
    out = _turning(np.concatenate((vC, Edot, Wdot)), state, frame_rate)
    if not forces:
        return out
    # m (d2G/dt2 + g z) for the solved accelerations (affine in dw/dt:
    # combine the trials), less the pitch reaction's force: the contact's
    Fsol = F[:, 0] + np.sum((F[:, 1:] - F[:, :1]) * Wdot[None], axis=1) - x[3] * fpitch
    return out, Fsol / machine.mass, x[3] / machine.mass


def _rhs_directional(X0, dirs, g, p: MachineArrays, frame_rate, step=COMPLEX_STEP, geometry=GeometryRates):
    """The Jacobian of :func:`machine_rhs` at the real states X0 (9, n)
    along ``dirs`` (9, d, n), exactly (complex step): the accelerations x =
    (dw/dt, lambda) solve A(X) x = b(X), so along dX, A dx = -dR/dX . dX with
    the residual R(X, x) held at the solved x.  One complex evaluation of
    the residual at that x replaces complex trials of all four (the same
    derivative, in a quarter of the second-order work)."""
    Am, bm, _, _, _, _ = _acceleration_system(X0, g, p, geometry)
    Ainv = np.linalg.inv(Am)                                      # (n, 4, 4): one LU for x and 4 directions
    x = (Ainv @ bm[..., None])[..., 0].T                          # (4, n)
    pc, gc = p.map(lambda v: np.asarray(v)[None]), np.asarray(g)[None]
    Xc = X0[:, None, :] + 1j * step * dirs                       # (9, d, n)
    R, _, vC, Edot, (kcol, _) = _residuals(Xc, gc, pc, x[:3, None, None, :], geometry)
    R = R[:, 0] - kcol * x[3][None, None, :]
    dR = np.imag(R) / step                                        # (4, d, n)
    dx = -Ainv[:, :3] @ dR.transpose(2, 0, 1)                   # (n, 3, d)
    out = np.concatenate((np.imag(vC) / step, np.imag(Edot) / step, dx.transpose(1, 2, 0)))
    return _turning(out, dirs, np.asarray(frame_rate)[None])


def machine_orbit_state(theta, alpha, ground, g, p: MachineArrays):
    """State (9, ...) of a machine placed on the steady horizontal orbit
    (theta, alpha) at azimuth 0, and its rate Omega (eq. M8; NaN where none):
    C = Q + (a - t) u, e1 = -sin(alpha) r-hat - cos(alpha) z,
    w = Omega z + s e1 with s = sigma Omega (eq. M4).  Complex theta, alpha
    accepted (complex step)."""
    theta, alpha = np.asarray(theta), np.asarray(alpha)
    st, ct, sa, ca = np.sin(theta), np.cos(theta), np.sin(alpha), np.cos(alpha)
    a, t, r, h = p.wheel_radius, p.tyre_radius, ground.radius, p.com_height
    hq = h - t
    r_g = (r - t) * st - hq * ca
    d_r = t * st + hq * ca
    d_z = t * ct - hq * sa
    w = (a - t) + t * (st * ca - ct * sa)
    sigma = r * st / w
    den = sa * (p.spin_inertia / p.mass * sigma + (p.yaw_inertia - p.pitch_inertia) / p.mass * ca) - d_z * r_g
    om2 = g * d_r / den
    om = np.sqrt(om2)
    zero = 0 * (st * sa + a)
    one = zero + 1.0
    cx = (r - t) * st - (a - t) * ca
    cz = (r - t) * ct + (a - t) * sa
    C = np.stack((cx, zero, cz))
    E = np.stack((-sa + zero, zero, -ca + zero))
    W = np.stack((0 * one, zero, om * one)) + sigma * om * E
    return np.concatenate((C, E, W)), om


#: Why a machine without yaw inertia and without spinning wheels has no
#: equations of motion (:func:`yaw_is_determined`).
YAW_UNDETERMINED = ("no yaw inertia and no spinning wheels: a turn about the up-axis moves no mass and the "
                    "equations of motion leave the yaw undetermined (the point-mass limit; docs/machine.md sec. 5)")


def yaw_is_determined(p: MachineArrays):
    """Whether eqs. M16-M19 determine the accelerations (beyond the paper;
    docs/machine.md sec. 5): a machine with I_yaw = 0 and J = 0 (the point
    mass on massless wheels of sec. 4) has nothing that resists or drives a
    turn about its up-axis -- it moves neither the centre of mass (on that
    axis) nor, to first order, the contact -- so the 4x4 system is singular
    and its yaw is arbitrary.  Its steady orbits (eq. M8) are well defined;
    their stability and motion are not.  Boolean array of the parameters'
    broadcast shape."""
    return (np.asarray(p.yaw_inertia) > 0) | (np.asarray(p.spin_inertia) > 0)


def machine_stability(theta, alpha, ground, g, p: MachineArrays):
    """Exact linear stability of a machine's steady horizontal orbits
    (docs/machine.md sec. 5): the eigenvalues of the reduced Jacobian of
    :func:`machine_jacobian`.  The equations are reversible, so the spectrum
    is symmetric under lambda -> -lambda and comes from the invariants of
    the 4x4 matrix (as the wheel's, docs/stability.md sec. 1).  Inputs 1-D
    of one length n (theta, alpha [rad]); orbits that do not exist (NaN
    Omega) or where the wheel does not fit give NaN.

    Returns dict: ``growth_rate`` [1/s], ``freq_slow``, ``freq_fast``
    [rad/s], ``verdict`` (int8), ``eigenvalues`` (n, 4), ``rate_scale``."""
    K, scale, Om = machine_jacobian(theta, alpha, ground, g, p)
    ev, growth, slow, fast, verdict = spectrum_from_invariants(K, scale)
    return {"growth_rate": growth, "freq_slow": slow, "freq_fast": fast, "verdict": verdict,
            "eigenvalues": ev, "rate_scale": scale, "omega": Om}


def machine_jacobian(theta, alpha, ground, g, p: MachineArrays):
    """The reduced Jacobian K (n, 4, 4) of a machine's steady horizontal
    orbits (docs/machine.md sec. 5): the Jacobian of :func:`machine_rhs` in
    the frame turning at Omega (complex step), on the 7-dimensional
    constraint manifold (|e1| = 1, |Q| = r - t) minus the three neutral
    directions (phase along the orbit; d/dtheta, d/dalpha of the family),
    in scaled coordinates; with the rate scale S [1/s] and Omega [rad/s]
    (NaN where there is no orbit)."""
    theta = np.asarray(theta, dtype=float).reshape(-1)
    alpha = np.asarray(alpha, dtype=float).reshape(-1)
    n = theta.size
    p = p.flat(n)
    r, g = (np.broadcast_to(np.asarray(x, dtype=float), (n,)) for x in (ground.radius, g))
    ground = Sphere(r)
    # the head at the centre of mass: its clearance is not the stability's business
    res = ride_orbit(theta, alpha, ground, g, p._replace(head_height=p.com_height))
    a, t = p.wheel_radius, p.tyre_radius
    ok = np.isfinite(res["omega"]) & (np.sin(theta - alpha) * (r - t) > (a - t))
    ok &= np.abs(np.sin(theta)) > SINGULAR
    th = np.where(ok, theta, np.pi / 2)
    al = np.where(ok, alpha, np.pi / 4)
    # a placeholder orbit that exists (theta 90, alpha 45 needs d_r > 0 and D > 0: true for h > t >= 0)
    X0, Om = machine_orbit_state(th, al, ground, g, p)
    Om = np.where(np.isfinite(Om), Om, 1.0)
    X0 = np.where(np.isfinite(X0), X0, 1.0)
    step = COMPLEX_STEP
    dth = np.imag(machine_orbit_state(th + 1j * step, al, ground, g, p)[0]) / step
    dal = np.imag(machine_orbit_state(th, al + 1j * step, ground, g, p)[0]) / step
    # gradients of the constraints |E|^2 = 1 and |Q|^2 = (r - t)^2 in (C, E):
    # 2E, and, with Q = (|cperp| + a - t) e3 + (C.e1) e1, d|Q|^2/dC = 2Q and
    # d|Q|^2/dE = -2 (a - t) (C.e1) e3 / |E| (docs/machine.md sec. 5)
    C, E = X0[0:3], X0[3:6]
    e1, e3, Q, _ = machine_geometry(C, E, a, t)
    grads = np.zeros((9, 2, n))
    grads[3:6, 0] = 2 * E
    grads[0:3, 1] = 2 * Q
    grads[3:6, 1] = -2 * (a - t) * _dot(C, e1) * e3 / np.sqrt(_dot(E, E))
    return reduced_jacobian(X0, Om, (dth, dal), grads, ok, g, p, GeometryRates)


def reduced_jacobian(X0, Om, family, grads, ok, g, p: MachineArrays, geometry):
    """The reduced Jacobian K (n, 4, 4), the rate scale S [1/s] and Omega
    (NaN where not ``ok``) of the steady states X0 (9, n) turning at Om:
    the Jacobian of the right-hand side for ``geometry`` in the frame
    turning at Omega, on the manifold of the two constraints whose
    gradients are ``grads`` (9, 2, n), minus the three neutral directions
    (the phase along the orbit, about z; the two tangents ``family`` (9, n)
    each of the family of steady states), in scaled coordinates
    (docs/machine.md sec. 5).  Shared by every ground."""
    n = X0.shape[1]
    a = np.broadcast_to(p.wheel_radius, (n,))
    W = X0[6:9]
    S = np.sqrt(np.sum(W * W, axis=0) + Om ** 2 + g / a)
    D = np.empty((9, n))
    D[0:3], D[3:6], D[6:9] = a, 1.0, S
    A = np.zeros((9, 5, n))
    A[:, 0:2] = grads * D[:, None, :]
    for blk in (slice(0, 3), slice(3, 6), slice(6, 9)):
        A[blk, 2] = zcross(X0[blk]) / D[blk]
    A[:, 3] = family[0] / D
    A[:, 4] = family[1] / D
    A *= 1.0 / np.sqrt(np.einsum("ikn,ikn->kn", A, A))[None]
    Y = householder_complement(A)                                  # (9, 4, n)
    dirs = Y * D[:, None, :]                                        # (9, 4, n)
    JdX = _rhs_directional(X0, dirs, g, p, Om, geometry=geometry)   # (9, 4, n)
    K = np.einsum("ijn,ikn->njk", Y, JdX / D[:, None, :])
    K = np.where(ok[:, None, None], K, np.nan)
    scale = np.where(ok, S, np.nan)
    return K, scale, np.where(ok, Om, np.nan)
