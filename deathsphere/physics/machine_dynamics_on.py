"""Exact equations of motion of the single-contact machine on any ground
of revolution -- the globe, the wall of death's drum, the well of death's
cone, flat ground, whose parallel surfaces are quadrics, and a profile,
whose parallel surface is its meridian moved along its normal -- and the
linear stability of its steady lanes there (beyond the paper;
docs/machine.md, "On any ground", eqs. MG1-MG5, and "On a profile",
MP1-MP5).

The globe's equations (:mod:`deathsphere.physics.machine_dynamics`, eqs.
M16-M20) use the globe in one place: the tyre's crown point Q, the point of
the crown circle (centre C, radius a - t, in the wheel plane) that touches
the sphere of radius r - t, is found by projecting C on the wheel plane,
and the contact is P = Q + t Q/|Q|.  On any ground Q moves on the ground's
parallel surface at distance t (``ground.offset(t)``), given by a
function F, zero on it and negative inside, N = grad F: its quadric
(``quadric()``: a_rho (x^2 + y^2)/2 + a_z z^2/2 + b_z z + c), or on a
profile the signed distance from it through the point's foot on the
meridian (:mod:`deathsphere.physics.crown_surfaces`).  The crown circle touches it where F is
greatest on the circle::

    e3 = cos(phi) u + sin(phi) (u x e1),  u = the unit projection of N(C)
         on the wheel plane,  Q = C + (a - t) e3,  e2 = e3 x e1,
    N(Q) . e2 = 0                         (MG1: phi by Newton's method)
    P = Q + t N(Q)/|N(Q)|                 (MG2)

and the pitch constraint n . e2 = 0 (n = N/|N|) reacts with a couple
lambda (e2 x n) and the force lambda f, f = A (e2 - n (n.e2)) / |N| (A
F's Hessian at Q, a quadric's constant) at Q (MG3).  Its time derivatives follow from
MG1 order by order (a second-order Taylor jet, :class:`_Taylor`: phi's
rate and acceleration solve a linear equation each, of slope
dg/dphi = (a - t) e2.A e2 - N.e3, which is minus the fit's margin, MG4).
Everything else -- rolling, the frame's rate, Newton, Euler about G, the
wheels' axial balance, the 4x4 solve per body, the complex-step Jacobian
-- is the globe's code (:func:`~deathsphere.physics.machine_dynamics.rhs_of_geometry`,
:func:`~deathsphere.physics.machine_dynamics.reduced_jacobian`).  On the
sphere (A = I, b = 0) u is C's projection, phi = 0, and every equation is
the globe's (tested to 1e-12).

State (9, ...) as on the globe: the wheel centre C, the axle vector E, the
wheels' angular velocity w, lab components, in the ground's coordinates.
A ground with no parallel surface (``offset`` None: none of the package's)
is not analysed (:data:`NO_PARALLEL`).
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.crown_surfaces import QuadricCrown, crown_surface
from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.machine_arrays import MachineArrays
from deathsphere.physics.machine_dynamics import reduced_jacobian, rhs_of_geometry
from deathsphere.physics.machine_surface import contact_on, ride_orbit_on
from deathsphere.physics.stability.reduction import COMPLEX_STEP, spectrum_from_invariants
from deathsphere.physics.taylor import Taylor as _Taylor
from deathsphere.physics.taylor import tcos_sin as _tcos_sin
from deathsphere.physics.taylor import tcross as _tcross
from deathsphere.physics.taylor import tdot as _tdot
from deathsphere.physics.taylor import tunit as _tunit
from deathsphere.physics.taylor import with_coefficient as _with
from deathsphere.physics.vectors import cross as _cross
from deathsphere.physics.vectors import dot as _dot

__all__ = ["crown_quadric", "crown_geometry", "geometry_on", "machine_rhs_on", "machine_orbit_state_on",
           "machine_start_on", "machine_project_on", "machine_jacobian_on", "machine_stability_on", "NO_PARALLEL",
           "NEWTON_STEPS"]

#: Why a ground is not analysed: it answers no parallel surface (every ground of the package has one).
NO_PARALLEL = ("the machine's equations of motion move the tyre's crown point on the ground's parallel surface, "
               "and this ground gives none")

#: A Newton step [rad] after which phi is at round-off: quadratic
#: convergence leaves an error of about its square, and a complex step's
#: imaginary part's error shrinks by the real error at each step.
CONVERGED = 1e-10

#: Newton steps at most for the crown point's angle phi (MG1).  The start (the
#: projection of the normal at the wheel centre) is exact on the globe and
#: flat ground and within (a - t) / rho of the answer on a drum or a cone,
#: and the steps converge quadratically: 8 leave it at round-off (the loop
#: stops after a step below :data:`CONVERGED`: 1-4 steps in practice).
NEWTON_STEPS = 8


def crown_quadric(ground, t):
    """The quadric (a_rho, a_z, b_z, c) of ``ground``'s parallel surface a
    distance ``t`` [m] inside (MG1), each broadcast against t; None where
    it is no quadric (a profile's: :func:`crown_surface` takes either).
    Beyond the paper: docs/machine.md, "On any ground"."""
    surface = crown_surface(ground, t)
    return surface.quadric if isinstance(surface, QuadricCrown) else None


class _Crown:
    """The crown point's geometry on the ground's parallel surface (MG1-MG3;
    on a profile MP4-MP5), with the attributes and methods of
    :class:`~deathsphere.physics.machine_dynamics.GeometryRates` (h1, e3,
    Q, P, C, t; :meth:`rates`, :meth:`e3_second`, :meth:`pitch_reaction`).
    Built by :func:`crown_geometry` for one surface
    (:mod:`deathsphere.physics.crown_surfaces`).  The feet of C and Q on a
    profile's meridian are found once, at construction, and reused by the
    rates and accelerations at the same point."""

    surface = None

    def __init__(self, C, E, a, t):
        self.C, self.E, self.a_t, self.t = C, E, a - t, t
        self._foot_C = self.surface.foot(C)
        jet = self._jet(_Taylor(C), _Taylor(E), None)
        self.h1, self.e3, self.Q, self.P = jet["e1"].x0, jet["e3"].x0, jet["Q"].x0, jet["P"].x0
        self.N, self.e2 = jet["N"].x0, jet["e2"].x0

    def _frame(self, Cj: _Taylor, Ej: _Taylor, order):
        """e1 and the reference axes u, u x e1 of the wheel plane (MG1)."""
        e1 = _tunit(Ej)
        NC = self.surface.normal(Cj, self._foot_C, order or 0)
        u = _tunit(NC - e1 * _tdot(e1, NC))
        return e1, u, _tcross(u, e1)

    def _at(self, phi: _Taylor, e1, u, w):
        c, s = _tcos_sin(phi)
        e3 = u * c + w * s
        e2 = _tcross(e3, e1)
        return e3, e2

    def _jet(self, Cj: _Taylor, Ej: _Taylor, order):
        """The geometry as jets; phi solved to ``order`` (None: the value by
        Newton's method; 1 or 2: that derivative from the lower ones)."""
        e1, u, w = self._frame(Cj, Ej, order)
        surface, a_t = self.surface, self.a_t
        if order is None:
            phi0 = 0 * u.x0[0]
            foot = self._foot_C
            for _ in range(NEWTON_STEPS):
                c, s = np.cos(phi0), np.sin(phi0)
                e3 = u.x0 * c + w.x0 * s
                e2 = _cross(e3, e1.x0)
                Q = Cj.x0 + a_t * e3
                foot = surface.foot(Q, foot)
                N, He2 = surface.normal_and_hess(Q, e2, foot)
                slope = a_t * _dot(e2, He2) - _dot(N, e3)
                step = _dot(N, e2) / slope
                phi0 = phi0 - step
                # converged: the error left is about the step's square
                if np.all(np.abs(step) < CONVERGED):
                    break
            phi = _Taylor(phi0)
        else:
            phi = self._phi
            phi = _Taylor(phi.x0) if order == 1 else _Taylor(phi.x0, phi.x1)
        e3, e2 = self._at(phi, e1, u, w)
        Q = Cj + e3 * a_t
        if order is None:
            # the foot of the converged crown point (from the last step's)
            self._foot_Q = surface.foot(Q.x0, foot)
        foot = self._foot_Q
        N = surface.normal(Q, foot, order or 0)
        if order is not None:
            # MG1 differentiated: the residual's `order`-th coefficient is slope * phi_order + rest
            g = _tdot(N, e2)
            slope = a_t * _dot(e2.x0, surface.hess_dot(Q.x0, e2.x0, foot)) - _dot(N.x0, e3.x0)
            known = g.x1 if order == 1 else g.x2
            phi_k = -known / slope
            self._phi = _Taylor(phi.x0, phi_k) if order == 1 else _Taylor(phi.x0, phi.x1, phi_k)
            # phi_k enters each jet's `order`-th coefficient linearly, along de3/dphi = e2 (and de2/dphi = -e3)
            turn = e2.x0 * phi_k
            e3, e2 = _with(e3, order, turn), _with(e2, order, -e3.x0 * phi_k)
            Q = _with(Q, order, turn * a_t)
            N = _with(N, order, surface.hess_dot(Q.x0, turn, foot) * a_t)
        else:
            self._phi = phi
        return {"e1": e1, "e3": e3, "e2": e2, "Q": Q, "N": N, "P": Q + _tunit(N) * self.t}

    def rates(self, vC, Ed):
        """The first derivatives for dC/dt = vC, dE/dt = Ed (returns self)."""
        self.C1, self.E1 = vC, Ed
        jet = self._jet(_Taylor(self.C, vC), _Taylor(self.E, Ed), 1)
        self.h1_1, self.e3_1, self.P1 = jet["e1"].x1, jet["e3"].x1, jet["P"].x1
        return self

    def e3_second(self, C, E, Cdd, Edd):
        """d2e3/dt2 (3, k, ...) for second derivatives Cdd, Edd (3, k, ...)."""
        jet = self._jet(_Taylor(C, self.C1, Cdd), _Taylor(E, self.E1, Edd), 2)
        return jet["e3"].x2

    def outward(self):
        """The ground's outward unit normal at the contact (3, ...): the
        parallel surface's at Q, N/|N| (MG2)."""
        return self.N / np.sqrt(_dot(self.N, self.N))

    def residual(self):
        """F(Q)/|N(Q)| [m]: the crown point's distance outside its parallel
        surface, to first order (0 on the constraint; on a profile exactly)."""
        return self.surface.value(self.Q, self._foot_Q) / np.sqrt(_dot(self.N, self.N))

    def pitch_reaction(self):
        """The pitch constraint's reaction per unit multiplier (MG3): (k, f),
        k (4, ...) its column in the residual (Euler's rows: the couple
        e2 x n and the force f at Q about G, less the contact's share
        (P - G) x f; the axial row -((P - C) x f) . e1, f acting on the
        frame and not the wheels), f (3, ...) the force at Q."""
        e1, e3, N, P, C, Q = (x[:, 0] for x in (self.h1, self.e3, self.N, self.P, self.C, self.Q))
        e2 = _cross(e3, e1)
        sN = np.sqrt(_dot(N, N))
        n = N / sN
        foot = None if self._foot_Q is None else (self._foot_Q[0][0], tuple(d[0] for d in self._foot_Q[1]))
        f = self.surface.hess_dot(Q, e2 - n * _dot(n, e2), foot) / sN
        k_euler = _cross(e2, n) - self.t * _cross(n, f)
        k_axial = -_dot(_cross(P - C, f), e1)
        return np.concatenate((k_euler, k_axial[None]), axis=0), f


def crown_geometry(surface):
    """The crown point's geometry class for the parallel surface
    ``surface`` (a :mod:`~deathsphere.physics.crown_surfaces` surface from
    :func:`crown_surface`, or a quadric's coefficients from
    :func:`crown_quadric`): the ``geometry`` argument of
    :func:`~deathsphere.physics.machine_dynamics.rhs_of_geometry` (beyond
    the paper; docs/machine.md, MG1-MG3 and MP4-MP5)."""
    if isinstance(surface, tuple):
        surface = QuadricCrown(surface)
    return type("Crown", (_Crown,), {"surface": surface})


def geometry_on(ground, machine: MachineArrays):
    """The crown point's geometry class of ``machine`` on ``ground`` (MG1-MG3,
    on a profile MP4-MP5; beyond the paper, docs/machine.md, "On any
    ground"): the ``geometry`` argument of
    :mod:`deathsphere.physics.machine_motion`'s functions.  Raises
    ValueError on a ground without a parallel surface (:data:`NO_PARALLEL`)."""
    surface = crown_surface(ground, machine.tyre_radius)
    if surface is None:
        raise ValueError(NO_PARALLEL)
    return crown_geometry(surface)


def machine_rhs_on(state, ground, g, machine: MachineArrays, frame_rate=0.0, forces=False):
    """d(state)/dt of the machine's exact equations on ``ground`` (beyond the
    paper: docs/machine.md, MG1-MG3 (a profile: MP4-MP5) with eqs. M16-M19;
    the arguments and returns of
    :func:`~deathsphere.physics.machine_dynamics.machine_rhs`).  Raises
    ValueError on a ground without a parallel surface (:data:`NO_PARALLEL`)."""
    return rhs_of_geometry(state, g, machine, geometry_on(ground, machine), frame_rate, forces)


def _orbit_state(rho, z, sb, cb, alpha, g, p: MachineArrays):
    """State (9, ...) on the steady lane with contact (rho, z) and wall angle
    (sin, cos) = (sb, cb), tilt alpha, at azimuth 0, and Omega (MS1-MS4):
    C = P + t n + (a - t) u, e1 = (-sin alpha, 0, -cos alpha),
    w = Omega z + sigma Omega e1.  Complex inputs accepted (complex step)."""
    sa, ca = np.sin(alpha), np.cos(alpha)
    a, t, h = p.wheel_radius, p.tyre_radius, p.com_height
    hq = h - t
    rq, zq = rho - t * sb, z + t * cb                   # Q = P + t n, n = (-sin beta, cos beta)
    r_g = rq - hq * ca                                  # MS1
    d_r = t * sb + hq * ca                              # MS2
    d_z = -t * cb - hq * sa
    w = (a - t) + t * (sa * cb + ca * sb)               # MS3
    sigma = rho / w
    den = sa * (p.spin_inertia / p.mass * sigma + (p.yaw_inertia - p.pitch_inertia) / p.mass * ca) - d_z * r_g
    om = np.sqrt(g * d_r / den)                         # MS4
    zero = 0 * (sa + rho + a)
    C = np.stack((rq - (a - t) * ca + zero, zero, zq + (a - t) * sa + zero))
    E = np.stack((-sa + zero, zero, -ca + zero))
    W = np.stack((zero, zero, om + zero)) + sigma * om * E
    return np.concatenate((C, E, W)), om


def machine_orbit_state_on(height, alpha, ground, g, p: MachineArrays):
    """State (9, ...) of a machine on the steady lane at ``height`` [m] (on
    flat ground the turn radius) and tilt ``alpha`` [rad] on ``ground``, at
    azimuth 0, and its rate Omega [rad/s] (MS1-MS4; NaN where none); on the
    globe :func:`~deathsphere.physics.machine_dynamics.machine_orbit_state`
    at the lane's theta (beyond the paper; docs/machine.md, eqs. MS1-MS4)."""
    c = contact_on(height, ground)
    with np.errstate(invalid="ignore", divide="ignore"):
        return _orbit_state(c.rho, c.z, c.sin_beta, c.cos_beta, np.asarray(alpha, dtype=float), g, p)


def machine_start_on(height, alpha, d_alpha, ground, g, p: MachineArrays):
    """(state (9, ...), Omega) of a machine on the steady lane (height,
    alpha) kicked by a tilt d_alpha [rad] about its direction of travel
    through the crown point Q (beyond the paper; docs/machine.md, "On any
    ground"; as :func:`~deathsphere.physics.machine_motion.machine_start` on
    the globe): Q = P + t n depends on the lane only, so Q, the contact and
    w stay, the axle and the wheel centre take the tilt alpha + d_alpha."""
    X0, om = machine_orbit_state_on(height, alpha, ground, g, p)
    Xk, _ = machine_orbit_state_on(height, np.asarray(alpha) + d_alpha, ground, g, p)
    return np.concatenate((Xk[0:6], X0[6:9])), om


#: Newton steps of :func:`machine_project_on` (one is exact on the globe's
#: and flat ground's quadrics; a drum's or a cone's e3 moves a little with C).
PROJECT_STEPS = 3


def machine_project_on(state, ground, p: MachineArrays):
    """The state moved back onto its constraints (beyond the paper;
    docs/machine.md, "On any ground"): E normalised, then C shifted along
    the parallel surface's normal by -F(Q)/|N(Q)| (Newton's steps on
    F(Q) = 0), as :func:`~deathsphere.physics.machine_motion.machine_project`
    on the globe."""
    state = np.array(state, dtype=np.result_type(state, float), copy=True)
    state[3:6] = state[3:6] / np.sqrt(_dot(state[3:6], state[3:6]))
    geometry = geometry_on(ground, p)
    for _ in range(PROJECT_STEPS):
        crown = geometry(state[0:3], state[3:6], p.wheel_radius, p.tyre_radius)
        state[0:3] = state[0:3] - crown.residual() * crown.outward()
    return state


def machine_stability_on(height, alpha, ground, g, p: MachineArrays):
    """Exact linear stability of a machine's steady lanes on ``ground``
    (MG5, beyond the paper: docs/machine.md, "On any ground"): the keys of
    :func:`~deathsphere.physics.machine_dynamics.machine_stability`, NaN
    where the lane has no orbit, the wheel does not fit (MS6), or the
    ground has no parallel surface."""
    K, scale, Om = machine_jacobian_on(height, alpha, ground, g, p)
    ev, growth, slow, fast, verdict = spectrum_from_invariants(K, scale)
    return {"growth_rate": growth, "freq_slow": slow, "freq_fast": fast, "verdict": verdict,
            "eigenvalues": ev, "rate_scale": scale, "omega": Om}


def machine_jacobian_on(height, alpha, ground, g, p: MachineArrays):
    """The reduced Jacobian K (n, 4, 4), rate scale S [1/s] and Omega of a
    machine's steady lanes on ``ground`` (MG5; as
    :func:`~deathsphere.physics.machine_dynamics.machine_jacobian`): on the
    manifold |E| = 1, F(Q) = 0 less the phase and the family's two
    tangents, along the meridian's arc length (the contact moves along
    (cos beta, sin beta), the wall angle turns at the meridian's curvature)
    and the tilt (beyond the paper; docs/machine.md, "On any ground")."""
    height = np.asarray(height, dtype=float).reshape(-1)
    alpha = np.asarray(alpha, dtype=float).reshape(-1)
    n = height.size
    p = p.flat(n)
    g = np.broadcast_to(np.asarray(g, dtype=float), (n,))
    if ground.offset(0.0) is None:
        nan = np.full(n, np.nan)
        return np.full((n, 4, 4), np.nan), nan, nan.copy()
    a, t = p.wheel_radius, p.tyre_radius
    c = contact_on(height, ground)
    # the head at the centre of mass: its clearance is not the stability's business
    res = ride_orbit_on(height, alpha, ground, g, p._replace(head_height=p.com_height + 0 * a))
    ok = np.isfinite(res["omega"]) & (np.abs(c.rho) > SINGULAR * (a + np.abs(c.rho)))
    fits = np.sin(alpha) * c.cos_beta + np.cos(alpha) * c.sin_beta      # sin(alpha + beta)
    kappa = np.where(np.isfinite(c.kappa), c.kappa, 0.0)
    ok &= np.isfinite(c.kappa) & (fits * (1.0 - t * kappa) > (a - t) * kappa)   # MS6
    # a placeholder lane where there is none: the first ok one's, or the ground's lowest
    ref = int(np.flatnonzero(ok)[0]) if ok.any() else None
    pick = (lambda x: np.where(ok, x, x[ref])) if ref is not None else None
    if pick is None:
        nan = np.full(n, np.nan)
        return np.full((n, 4, 4), np.nan), nan, nan.copy()
    rho, z, sb, cb, al = (pick(np.broadcast_to(x, (n,))) for x in (c.rho, c.z, c.sin_beta, c.cos_beta, alpha))
    km, _ = ground.curvatures(height)
    km = pick(np.where(np.isfinite(np.broadcast_to(km, (n,))), km, 0.0))
    pp = p.map(lambda x: pick(np.broadcast_to(x, (n,))))
    gg = pick(g)
    geometry = crown_geometry(crown_surface(ground, pp.tyre_radius))
    X0, Om = _orbit_state(rho, z, sb, cb, al, gg, pp)
    step = COMPLEX_STEP
    ds = 1j * step
    # along the meridian's arc length: dP = (cos beta, sin beta) ds, d beta = kappa_meridian ds
    dlane = np.imag(_orbit_state(rho + ds * cb, z + ds * sb, sb + ds * km * cb, cb - ds * km * sb, al, gg, pp)[0]) / step
    dtilt = np.imag(_orbit_state(rho, z, sb, cb, al + ds, gg, pp)[0]) / step
    # gradients of the constraints |E|^2 = 1 and F(Q) = 0 in (C, E): 2E, and
    # (e3 maximises F on the crown circle, so its own change drops out)
    # dF/dC = N(Q), dF/dE = -(a - t) (N.e1) e3 / |E| (docs/machine.md, MG5)
    C, E = X0[0:3], X0[3:6]
    crown = geometry(C[:, None], E[:, None], pp.wheel_radius, pp.tyre_radius)
    e1, e3, N = crown.h1[:, 0], crown.e3[:, 0], crown.N[:, 0]
    grads = np.zeros((9, 2, n))
    grads[3:6, 0] = 2 * E
    grads[0:3, 1] = N
    grads[3:6, 1] = -(pp.wheel_radius - pp.tyre_radius) * _dot(N, e1) * e3 / np.sqrt(_dot(E, E))
    return reduced_jacobian(X0, Om, (dlane, dtilt), grads, ok, gg, pp, geometry)
