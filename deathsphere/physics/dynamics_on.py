"""Exact equations of motion of the paper's wheel and ball rolling without
slipping inside ANY ground of :mod:`deathsphere.physics.ground`.

Beyond the paper (docs/dynamics.md, "On any surface of revolution"): the
Newton-Euler equations (2), (3), (6), (7b) of McDonald (1993) hold on any
fixed surface; only the contact direction e3 and its rate change.  They are
found from the ground's protocol alone (``implicit``, ``gradient``,
``hessian`` of F, F = 0 on the surface, F < 0 inside), never from its class:

* wheel: e3 in the wheel plane where the rim is tangent to the surface,
  (e1 x e3) . grad F(c + a e3) = 0 (eq. G1), solved by vectorised Newton
  steps in the angle of e3 in the wheel plane;
* ball: e3 the outward normal at the foot p of the perpendicular from the
  centre, c + a e3 = p, e3 = grad F(p)/|grad F(p)| (eq. G4).

The state is the (9, ...) array of :mod:`deathsphere.physics.dynamics`.
The body is inside (on the side F < 0) or, with ``outside``, outside (F >
0): there e3, from the centre to the contact, points against grad F, the
wheel's contact is the rim's point of least F and the ball's e3 = -grad
F/|grad F| (docs/dynamics.md sec. 7, "Outside"); nothing else in the
equations knows the side, as on the sphere (eq. D5's s only sets e3).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from deathsphere.physics import dynamics as dyn
from deathsphere.physics.dynamics import _Dual, _dual_sqrt
from deathsphere.physics.status import mu_required

__all__ = ["GroundBody", "ground_body", "rhs_on", "jvp_on", "rhs_jvp_on", "ode_on", "energy_on", "contact_on",
           "contact_force_on", "gap_on", "project_on", "lowest_point_on", "spin_rate_on", "wheel_orbit_state_on",
           "ball_orbit_state_on"]

#: Newton steps at most for the contact (quadratic convergence: 3-5 suffice)
NEWTON_STEPS = 12
#: the relative step of the central difference of the hessian along a
#: perturbation (the third derivative of F, in the Jacobian only): error
#: ~ step^2 of the curvature's relative variation, exact on quadrics
HESSIAN_STEP = 1e-5


class GroundBody(NamedTuple):
    """A wheel or ball on a ground: ``ground`` (the protocol), arrays ``a``
    [m], ``k`` [-], ``g`` [m/s^2], ``sphere`` (bool, a ball) and ``outside``
    (bool, the body on the side F > 0) broadcast against the bodies."""

    ground: object
    a: np.ndarray
    k: np.ndarray
    g: np.ndarray
    sphere: np.ndarray
    outside: np.ndarray = np.False_


def ground_body(ground, a, k, g, sphere=False, outside=False) -> GroundBody:
    """Validated :class:`GroundBody` (beyond the paper): a > 0, k > 0, g > 0 finite."""
    a, k, g = (np.asarray(x, dtype=float) for x in (a, k, g))
    sphere, outside = np.asarray(sphere, dtype=bool), np.asarray(outside, dtype=bool)
    a, k, g, sphere, outside = np.broadcast_arrays(a, k, g, sphere, outside)
    for name, x in (("a", a), ("k", k), ("g", g)):
        if not np.all(np.isfinite(x)) or np.any(x <= 0):
            raise ValueError(f"{name} must be finite and > 0")
    return GroundBody(ground, a, k, g, sphere, outside)


def _side(p: GroundBody):
    """+1 inside, -1 outside: the sign of e3 . grad F at the contact."""
    return np.where(p.outside, -1.0, 1.0)


def _coef(p: GroundBody):
    # the per-body constants of dynamics.py's equations, inside (s = +1)
    return dyn._coefficients(dyn.BodyParams(p.a, np.inf, p.k, p.g, False, p.sphere))


# ---------------------------------------------------------------- vectors as 3-tuples (arrays or duals)

def _dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def _cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def _lin(*terms):
    """sum of s_i u_i for pairs (s_i, u_i)."""
    out = None
    for s, u in terms:
        su = (s * u[0], s * u[1], s * u[2])
        out = su if out is None else (out[0] + su[0], out[1] + su[1], out[2] + su[2])
    return out


def _mat_vec(H, u):
    return tuple(H[i][0] * u[0] + H[i][1] * u[1] + H[i][2] * u[2] for i in range(3))


def _is_dual(x):
    return type(x) is _Dual


def _gradient(ground, p):
    """grad F at p; for duals its derivative H dp (exact)."""
    if not _is_dual(p[0]):
        G = ground.gradient(*p)
        return G[0], G[1], G[2]
    pv = [x.v for x in p]
    G, H = ground.gradient(*pv), ground.hessian(*pv)
    return tuple(_Dual(G[i], H[i, 0] * p[0].d + H[i, 1] * p[1].d + H[i, 2] * p[2].d) for i in range(3))


def _hessian(ground, p):
    """Hessian of F at p, nested 3x3; for duals its derivative along dp by a
    central difference of the hessian (the protocol has no third derivative;
    exact where the hessian is constant)."""
    if not _is_dual(p[0]):
        H = ground.hessian(*p)
        return tuple(tuple(H[i, j] for j in range(3)) for i in range(3))
    pv = [x.v for x in p]
    H = ground.hessian(*pv)
    d = [x.d for x in p]
    dn = np.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
    G = ground.gradient(*pv)
    hn = np.sqrt(np.sum(H * H, axis=(0, 1)))
    # a length over which the hessian varies: the curvature radius |grad F| / |H|
    length = np.sqrt(G[0] ** 2 + G[1] ** 2 + G[2] ** 2) / np.where(hn > 0, hn, 1.0)
    step = HESSIAN_STEP * length / np.where(dn > 0, dn, 1.0)
    Hp = ground.hessian(*(pv[i] + step * d[i] for i in range(3)))
    Hm = ground.hessian(*(pv[i] - step * d[i] for i in range(3)))
    dH = (Hp - Hm) / (2.0 * step)
    return tuple(tuple(_Dual(H[i, j], dH[i, j]) for j in range(3)) for i in range(3))


def _value(u):
    return tuple(x.v if _is_dual(x) else x for x in u)


# ---------------------------------------------------------------- contact

def _wheel_newton(ground, c, h, u, a, sqrt):
    """One Newton step of the tangency G1 in the angle of e3 in the wheel
    plane: returns (e3, G, G') with G = t . grad F(p), t = h x e3."""
    t = _cross(h, u)
    p = _lin((1.0, c), (a, u))
    G = _gradient(ground, p)
    H = _hessian(ground, p)
    gt = _dot(t, G)
    gp = a * _dot(t, _mat_vec(H, t)) - _dot(u, G)          # dG/dpsi, < 0 at the rim's outermost point
    delta = -gt / gp
    e3 = _lin((1.0 / sqrt(1.0 + delta * delta), u), (delta / sqrt(1.0 + delta * delta), t))
    return e3, G, H


def _ball_newton(ground, c, u, a, sqrt, side=1.0):
    """One Newton step of G4, side n(c + a e3) = e3 (side +1 inside, -1
    outside): (1 - side a P H / |grad F|) delta = side n - e3 solved by
    Cramer's rule, e3 <- (e3 + delta)/|e3 + delta|."""
    p = _lin((1.0, c), (a, u))
    G = _gradient(ground, p)
    H = _hessian(ground, p)
    gn = sqrt(_dot(G, G))
    n = (G[0] / gn, G[1] / gn, G[2] / gn)
    r = _lin((side, n), (-1.0, u))
    # A = 1 - side (a/|G|) (1 - n n^T) H
    Hn = [[H[i][j] - n[i] * _dot(n, (H[0][j], H[1][j], H[2][j])) for j in range(3)] for i in range(3)]
    A = [[(1.0 if i == j else 0.0) - side * (a / gn) * Hn[i][j] for j in range(3)] for i in range(3)]
    delta = _solve3(A, r)
    v = _lin((1.0, u), (1.0, delta))
    vn = sqrt(_dot(v, v))
    return (v[0] / vn, v[1] / vn, v[2] / vn), G, H


def _solve3(A, b):
    """A^-1 b for nested 3x3 A by Cramer's rule (+, -, *, / only: duals pass)."""
    c0 = _cross((A[0][1], A[1][1], A[2][1]), (A[0][2], A[1][2], A[2][2]))
    c1 = _cross((A[0][2], A[1][2], A[2][2]), (A[0][0], A[1][0], A[2][0]))
    c2 = _cross((A[0][0], A[1][0], A[2][0]), (A[0][1], A[1][1], A[2][1]))
    det = _dot((A[0][0], A[1][0], A[2][0]), c0)
    return (_dot(c0, b) / det, _dot(c1, b) / det, _dot(c2, b) / det)


def _contact_values(ground, c, h, a, ball, side=1.0):
    """e3 (values) on the ground by Newton steps, vectorised: wheel from the
    projection of side grad F(c) on the wheel plane (the sphere's closed
    form), ball from the normal direction side grad F(c) (side +1 inside,
    -1 outside: e3 points from the centre to the surface)."""
    G0 = ground.gradient(*c)
    G0 = (side * G0[0], side * G0[1], side * G0[2])
    gh = _dot(G0, h)
    uw = _lin((1.0, G0), (-np.where(ball, 0.0, gh), h))
    un = np.sqrt(_dot(uw, uw))
    u = (uw[0] / un, uw[1] / un, uw[2] / un)
    for _ in range(NEWTON_STEPS):
        # one kind of body per batch as a rule: step only the kind present
        ew = _wheel_newton(ground, c, h, u, a, np.sqrt)[0] if not np.all(ball) else u
        eb = _ball_newton(ground, c, u, a, np.sqrt, side)[0] if np.any(ball) else u
        new = tuple(np.where(ball, eb[i], ew[i]) for i in range(3))
        change = np.max(np.abs(np.stack(np.broadcast_arrays(*(new[i] - u[i] for i in range(3))))))
        u = new
        if not change > 4e-16:
            break
    return u


def _contact(ground, c, h, a, ball, wheel_flag, sqrt, side=1.0):
    """e3, grad F(p), hessian at p: the values converged, then one more
    Newton step in the input's own arithmetic (for duals the step carries
    the implicit-function derivative of e3 exactly)."""
    e0 = _contact_values(ground, _value(c), _value(h), a, ball, side)
    if _is_dual(h[0]):
        # back onto the perturbed wheel plane before the last step
        eh = _dot(e0, h) * wheel_flag
        e0 = _lin((1.0, e0), (-1.0 * eh, h))
        en = sqrt(_dot(e0, e0))
        e0 = (e0[0] / en, e0[1] / en, e0[2] / en)
    ew = _wheel_newton(ground, c, h, e0, a, sqrt)[0] if not np.all(ball) else e0
    eb = _ball_newton(ground, c, e0, a, sqrt, side)[0] if np.any(ball) else e0
    e3 = tuple(_pick(ball, eb[i], ew[i]) for i in range(3))
    # the surface's derivatives at the contact itself (for duals they move with e3)
    p = _lin((1.0, c), (a, e3))
    return e3, _gradient(ground, p), _hessian(ground, p)


def _pick(cond, x, y):
    if not np.any(cond):
        return y
    if np.all(cond):
        return x
    f = np.where(cond, 1.0, 0.0)
    return f * x + (1.0 - f) * y


# ---------------------------------------------------------------- equations

def _equations(state, p: GroundBody, sqrt, accel=False):
    """The equations of motion on the ground (docs/dynamics.md eqs. G1-G6),
    for arrays or duals; returns the 9 rates, with ``accel`` also d2c/dt2,
    e3, de3/dt and grad F at the contact (3 each)."""
    a, ga, _s, wheel, kw, ik1, ik, d1 = _coef(p)
    ball = p.sphere
    side = _side(p)
    c, x, w = tuple(state[0:3]), tuple(state[3:6]), tuple(state[6:9])
    ne = sqrt(_dot(x, x))
    h = (x[0] / ne, x[1] / ne, x[2] / ne)
    e3, G, H = _contact(p.ground, c, h, a, ball, wheel, sqrt, side)
    v = _lin((a, _cross(e3, w)))                              # eq. 6
    f = _cross(w, x)
    m = _cross(w, h)                                          # d(e1 unit)/dt
    # wheel (G3): de3/dt = lam t + mu h
    t = _cross(h, e3)
    mu = -_dot(e3, m)
    Ht = _mat_vec(H, _lin((1.0, v), (a * mu, h)))
    lam = (_dot(_cross(m, e3), G) + _dot(t, Ht)) / (_dot(e3, G) - a * _dot(t, _mat_vec(H, t)))
    dw = _lin((lam, t), (mu, h))
    # ball (G5): e3 = side n(c + a e3), so (1 - side a S) de3/dt = side S v,
    # S = (1 - n n^T) H / |grad F| (side +1 inside, -1 outside)
    gn = sqrt(_dot(G, G))
    n = (G[0] / gn, G[1] / gn, G[2] / gn)
    Hv = _mat_vec(H, v)
    rb = _lin((side / gn, Hv), (-side * _dot(n, Hv) / gn, n))
    Hn = [[H[i][j] - n[i] * _dot(n, (H[0][j], H[1][j], H[2][j])) for j in range(3)] for i in range(3)]
    A = [[(1.0 if i == j else 0.0) - side * (a / gn) * Hn[i][j] for j in range(3)] for i in range(3)]
    db = _solve3(A, rb)
    d = tuple(_pick(ball, db[i], dw[i]) for i in range(3))
    # M dw/dt = e3 x (de3/dt x w) + (g/a) e3 x z - k w1 (w x e1)   (D4, D5)
    y = _cross(d, w)
    kw1 = kw * _dot(w, h)
    ey = _cross(e3, y)
    b = (ey[0] + ga * e3[1] - kw1 * m[0], ey[1] - ga * e3[0] - kw1 * m[1], ey[2] - kw1 * m[2])
    r3 = _dot(e3, b)
    r1 = d1 * _dot(h, b)
    r3k = r3 * ik
    acc = tuple((b[i] - e3[i] * r3) * ik1 + e3[i] * r3k + r1 * h[i] for i in range(3))
    out = (*v, *f, *acc)
    if not accel:
        return out
    ea = _cross(e3, acc)
    cdd = tuple(a * (y[i] + ea[i]) for i in range(3))
    return out + cdd + e3 + d + G


def _stack(xs):
    return np.stack(np.broadcast_arrays(*xs))


def _turning(out, state, frame_rate):
    out = list(out)
    fr = np.asarray(frame_rate)
    if np.any(fr != 0):
        for i in (0, 3, 6):          # - Omega z x u for u = c, e1, w
            out[i] = out[i] + fr * state[i + 1]
            out[i + 1] = out[i + 1] - fr * state[i]
    return out


def rhs_on(state, p: GroundBody, frame_rate=0.0):
    """d(state)/dt on the ground (beyond the paper; docs/dynamics.md,
    "On any surface of revolution"), states (9, ...); ``frame_rate`` [rad/s]
    the rate of a frame turning about +z (a steady orbit is a fixed point)."""
    state = np.asarray(state, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = _equations(state, p, np.sqrt)
    return _stack(_turning(out, state, frame_rate))


def jvp_on(state, directions, p: GroundBody, frame_rate=0.0):
    """J(state) @ directions of :func:`rhs_on` (beyond the paper; docs/dynamics.md sec. 7) by forward-mode derivatives
    (``dynamics._Dual``), state (9, ..., n), directions (9, m, ..., n);
    the contact's derivative by the implicit-function theorem (one Newton
    step in duals from the converged contact), the hessian's along a
    perturbation by a central difference (exact on quadrics)."""
    state = np.asarray(state, dtype=float)
    directions = np.asarray(directions, dtype=float)
    X = np.array([_Dual(state[i], directions[i]) for i in range(9)], dtype=object)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = _equations(X, p, _dual_sqrt)
    dd = [o.d if _is_dual(o) else np.zeros_like(directions[0]) for o in out]
    return _stack(_turning(dd, directions, frame_rate))


def rhs_jvp_on(state, directions, p: GroundBody):
    """(:func:`rhs_on`, :func:`jvp_on`) of one pass of forward-mode
    derivatives (beyond the paper; docs/dynamics.md sec. 7): the rates
    (9, ..., n) and J(state) @ directions (9, m, ..., n), the values carried
    by the same dual numbers as the derivatives (a state and its tangent
    vectors stepped together, as the vertical loop's Floquet monodromy
    does: docs/stability.md, "A vertical loop inside a closed profile")."""
    state = np.asarray(state, dtype=float)
    directions = np.asarray(directions, dtype=float)
    X = np.array([_Dual(state[i], directions[i]) for i in range(9)], dtype=object)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = _equations(X, p, _dual_sqrt)
    values = _stack([o.v if _is_dual(o) else o for o in out])
    dd = _stack([o.d if _is_dual(o) else np.zeros_like(directions[0]) for o in out])
    return np.broadcast_to(values, state.shape), dd


def ode_on(p: GroundBody, frame_rate=0.0):
    """``fun(t, y)`` for the integrator, y the flattened (9, n) state (beyond the paper; docs/dynamics.md sec. 7)."""
    n = int(np.prod(np.broadcast_shapes(np.shape(p.a), np.shape(frame_rate)))) or 1
    pf = GroundBody(p.ground, *(np.broadcast_to(x, (n,)) for x in p[1:]))
    fr = np.broadcast_to(np.asarray(frame_rate, dtype=float), (n,))

    def fun(t, y):
        return rhs_on(np.asarray(y).reshape(9, n), pf, fr).reshape(-1)

    return fun


# ---------------------------------------------------------------- invariants and the contact force

def _motion(state, p):
    state = np.asarray(state, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = _equations(state, p, np.sqrt, accel=True)
    return [_stack(out[i:i + 3]) for i in range(0, 21, 3)]


def contact_on(state, p: GroundBody):
    """(e3, contact point p = c + a e3) on the ground, (3, ...) each (docs/dynamics.md eqs. G1, G4)."""
    state = np.asarray(state, dtype=float)
    c = tuple(state[0:3])
    x = tuple(state[3:6])
    ne = np.sqrt(_dot(x, x))
    e3 = _stack(_contact_values(p.ground, c, tuple(xi / ne for xi in x), p.a, p.sphere, _side(p)))
    return e3, state[0:3] + p.a * e3


def energy_on(state, p: GroundBody):
    """Energy per unit mass [J/kg] (beyond the paper), as :func:`dynamics.energy` with the
    ground's e3: |v|^2/2 + (k a^2/2)(|w|^2 + w1^2 [wheel]) + g c_z."""
    state = np.asarray(state, dtype=float)
    e3, _ = contact_on(state, p)
    w = state[6:9]
    v = p.a * np.cross(e3, w, axis=0)
    e1 = state[3:6] / np.sqrt(np.sum(state[3:6] ** 2, axis=0))
    w1 = np.sum(w * e1, axis=0)
    rot = np.sum(w * w, axis=0) + np.where(p.sphere, 0.0, w1 * w1)
    return 0.5 * np.sum(v * v, axis=0) + 0.5 * p.k * p.a ** 2 * rot + p.g * state[2]


def gap_on(state, p: GroundBody):
    """Beyond the paper (docs/dynamics.md sec. 7): the contact point's signed distance from the surface [m], to first
    order F/|grad F| (negative on the inside's side, positive on the outside's): the holonomic constraint's
    residual."""
    _, pt = contact_on(state, p)
    G = p.ground.gradient(*pt)
    return p.ground.implicit(*pt) / np.sqrt(np.sum(G * G, axis=0))


def contact_force_on(state, p: GroundBody):
    """Contact force per unit mass F/m = d2c/dt2 + g z (eq. 2): dict with
    ``force`` (3, ...), ``normal`` (-F . n inside, +F . n outside, n the
    outward unit normal grad F/|grad F|; > 0 while contact holds),
    ``friction`` (3, ...), ``friction_magnitude`` and ``mu_required``
    (eq. 35: |friction| / normal, NaN where normal <= 0)."""
    _, _, _, cdd, e3, _, G = _motion(state, p)
    F = cdd + np.array([0.0, 0.0, 1.0]).reshape((3,) + (1,) * (cdd.ndim - 1)) * p.g
    n = G / np.sqrt(np.sum(G * G, axis=0))
    fn = np.sum(F * n, axis=0)
    fr = F - fn * n
    fmag = np.sqrt(np.sum(fr * fr, axis=0))
    normal = -_side(p) * fn
    return {"force": F, "normal": normal, "friction": fr, "friction_magnitude": fmag,
            "mu_required": mu_required(normal, fmag)}


#: passes of :func:`project_on` (each moves the contact onto the surface to
#: first order in the gap; the gap after two is round-off)
PROJECT_PASSES = 2


def project_on(state, p: GroundBody):
    """The state moved back onto the constraints (beyond the paper;
    docs/dynamics.md sec. 7, as :func:`dynamics.project` on the globe): e1
    renormalised, then the centre moved along the surface's unit normal by
    the gap F/|grad F| at the contact, twice (a translation along the normal
    keeps e3 to first order: the second pass removes the rest)."""
    state = np.array(state, dtype=float, copy=True)
    state[3:6] = state[3:6] / np.sqrt(np.sum(state[3:6] ** 2, axis=0))
    for _ in range(PROJECT_PASSES):
        _, pt = contact_on(state, p)
        G = p.ground.gradient(*pt)
        gn = np.sqrt(np.sum(G * G, axis=0))
        state[0:3] = state[0:3] - (p.ground.implicit(*pt) / gn) * (G / gn)
    return state


def lowest_point_on(state, p: GroundBody):
    """z [m] of the body's lowest point (beyond the paper; the floor test of
    docs/surfaces.md S5 along a run): a ball's c_z - a; a wheel's rim, the
    circle of radius a about c normal to e1, c_z - a sqrt(1 - e1_z^2)."""
    state = np.asarray(state, dtype=float)
    e1z = state[5] / np.sqrt(np.sum(state[3:6] ** 2, axis=0))
    reach = np.where(p.sphere, 1.0, np.sqrt(np.maximum(1.0 - e1z * e1z, 0.0)))
    return state[2] - p.a * reach


def spin_rate_on(state, p: GroundBody):
    """A wheel's rate [rad/s] about its axle relative to the contact
    direction, w . e1 - (de3/dt) . (e1 x e3) (beyond the paper; docs/simulation.md
    "3-D view", as :func:`deathsphere.simulation.frames.spin_rate` on the
    globe), de3/dt from the equations on the ground (G3); NaN for a ball."""
    _, _, _, _, e3, de3, _ = _motion(state, p)
    state = np.asarray(state, dtype=float)
    e1 = state[3:6] / np.sqrt(np.sum(state[3:6] ** 2, axis=0))
    u = np.cross(e1, e3, axis=0)
    rate = np.sum(state[6:9] * e1, axis=0) - np.sum(de3 * u, axis=0)
    return np.where(p.sphere, np.nan, rate)


# ---------------------------------------------------------------- steady orbits on any ground

def _frame(phi):
    cp, sp = np.cos(phi), np.sin(phi)
    zero = np.zeros_like(cp)
    return np.stack((cp, sp, zero)), np.stack((zero, zero, np.ones_like(cp)))


def wheel_state_at(rho, z, alpha, a, k, g, phi=0.0):
    """State and rate of a wheel on the steady orbit with contact (rho, z)
    and tilt alpha: eqs. (11)-(13), (29) with r' = rho - a cos(alpha), the
    same formulas as :func:`dynamics.wheel_orbit_state` (the torque balance
    about the centre involves only r', alpha and Omega; the rim's tangent
    -phi-hat is tangent to every surface of revolution).  Complex inputs
    pass (the family's derivatives).  Omega NaN where eq. (29) has none."""
    from deathsphere.physics.wheel import _omega_squared
    rho, z, alpha, a, k, g, phi = np.broadcast_arrays(*(np.asarray(x) for x in (rho, z, alpha, a, k, g, phi)))
    sa, ca = np.sin(alpha), np.cos(alpha)
    rp = rho - a * ca
    with np.errstate(divide="ignore", invalid="ignore"):
        om2 = _omega_squared(rp, sa, ca, a, np.real(rho), k, g)
    ok = np.nan_to_num(np.real(om2), nan=-1.0) > 0
    omega = np.where(ok, np.sqrt(np.where(ok, om2, 1.0)), np.nan)
    rhat, zhat = _frame(phi)
    e1 = -sa * rhat - ca * zhat
    e3 = ca * rhat - sa * zhat
    c = rho * rhat + z * zhat - a * e3
    w = (rp / a) * omega * e1 - omega * sa * e3
    return np.concatenate((c, e1, w)), omega


def wheel_orbit_state_on(ground, height, alpha, a, k, g, phi=0.0):
    """(state, Omega) of a wheel on the steady orbit at lane ``height`` [m]
    and tilt ``alpha`` [rad] of any ground (beyond the paper: eq. 29 with
    r' = rho_P - a cos(alpha); docs/dynamics.md)."""
    rho, z = ground.contact(height)
    return wheel_state_at(rho, z, alpha, a, k, g, phi)


def ball_state_at(rho, z, beta, omega, a, k, g, phi=0.0, outside=False):
    """(state, omega3) of a ball on the steady orbit of rate ``omega`` with
    contact (rho, z) at wall angle beta: e3 = side (sin(beta) r-hat -
    cos(beta) z) (the outward normal inside, side +1; the inward one
    outside, side -1), c = p - a e3, w = -e3 x v / a + omega3 e3 with
    v = Omega z x c, and the ball's law
    k a omega3 Omega sin(beta) = (k+1) Omega^2 r_C cos(beta) - g sin(beta)
    (McDonald 1993 eq. 55 with r_C = rho - side a sin(beta) the centre's
    distance from the axis; docs/dynamics.md eq. G8, docs/surfaces.md S6:
    the same law on both sides).  Complex inputs pass."""
    rho, z, beta, omega, a, k, g, phi, outside = np.broadcast_arrays(
        *(np.asarray(x) for x in (rho, z, beta, omega, a, k, g, phi, outside)))
    side = np.where(outside, -1.0, 1.0)
    sb, cb = np.sin(beta), np.cos(beta)
    rhat, zhat = _frame(phi)
    e3 = side * (sb * rhat - cb * zhat)
    c = rho * rhat + z * zhat - a * e3
    rc = rho - side * a * sb
    with np.errstate(divide="ignore", invalid="ignore"):
        omega3 = ((k + 1) * omega ** 2 * rc * cb - g * sb) / (k * a * omega * sb)
    v = omega * np.stack((-c[1], c[0], np.zeros_like(c[2])))
    w = -np.cross(e3, v, axis=0) / a + omega3 * e3
    e2 = np.stack((-np.sin(phi), np.cos(phi), np.zeros_like(c[2])))
    e1 = np.cross(e2, e3, axis=0)
    return np.concatenate((c, e1, w)), omega3


def ball_orbit_state_on(ground, height, omega, a, k, g, phi=0.0, outside=False):
    """(state, omega3) of a ball on the steady orbit of rate ``omega``
    [rad/s] at lane ``height`` [m] of any ground (beyond the paper;
    docs/dynamics.md eq. G8), inside or ``outside``."""
    rho, z = ground.contact(height)
    return ball_state_at(rho, z, ground.wall_angle(height), omega, a, k, g, phi, outside)
