"""Exact equations of motion of a wheel or sphere rolling on a fixed sphere.

Beyond the paper: McDonald (1993) writes the Newton-Euler equations in general
form, eqs. (2)-(7b), and then only solves them for steady circular orbits.
This module integrates them for *any* motion.  The derivation (state, contact
geometry, elimination and recovery of the contact force) is in
``docs/dynamics.md``.

State
-----
A state is a float (or complex, for complex-step derivatives) array of shape
``(9, ...)``: rows 0-2 are the centre ``c`` of the body [m] (origin at the
centre of the fixed sphere, z up), rows 3-5 the unit vector ``e1`` (the wheel
axis; for a sphere a body-fixed marker that does not enter the dynamics),
rows 6-8 the angular velocity ``w`` of the body [rad/s], all in lab (or
turning-frame) Cartesian components.  Trailing axes index bodies; every
parameter broadcasts against them.  The velocity of the centre is not carried:
it is ``a e3 x w`` (eq. 6), so rolling without slipping holds identically.

Contact geometry (docs/dynamics.md sec. 2): for a wheel ``e3`` is the unit
projection of ``c`` on the wheel plane, ``e3 = s c_perp/|c_perp|`` with
``c_perp = c - (c.e1) e1``, s = +1 inside (rim point farthest from the
sphere's centre) and s = -1 outside (nearest); for a sphere ``e3 = s c/|c|``.
The contact point is ``p = c + a e3`` and the contact condition ``|p| = r``.

Equations (eqs. 2, 3, 6, 7b in general form, force eliminated as in eq. 4)::

    dc/dt  = a e3 x w
    de1/dt = w x e1
    M dw/dt = e3 x (de3/dt x w) + (g/a) e3 x z - k w1 (w x e1)   [wheel]
    M = k (1 + e1 e1^T) + 1 - e3 e3^T      (wheel; sphere: k 1 + 1 - e3 e3^T)

with w1 = w.e1; the last (gyroscopic) term is absent for a sphere.  M is
inverted in closed form, M^-1 = e1e1/(2k+1) + e2e2/(k+1) + e3e3/k for a wheel.
The contact force is recovered from eq. (2), F/m = d2c/dt2 + g z.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from deathsphere.physics.geometry import SINGULAR, r_prime, too_big_inside
from deathsphere.physics.sphere import centre_distance, omega3_from_rate
from deathsphere.physics.vectors import cross, dot, norm, zcross
from deathsphere.physics.wheel import omega_squared

N_STATE = 9
#: slices of the state rows
C, E1, W = slice(0, 3), slice(3, 6), slice(6, 9)


class BodyParams(NamedTuple):
    """Parameters of the rolling body, numpy arrays broadcastable against the
    trailing (body) axes of a state.

    a [m] body radius, r [m] radius of the fixed sphere, k [-] inertia factor
    (wheel: I11 = 2 k m a^2, I22 = I33 = k m a^2, eq. 1; sphere: I = k m a^2,
    eq. 41), g [m/s^2], outside (bool) body on the outside of the sphere,
    sphere (bool) the body is a sphere rather than a wheel.
    """

    a: np.ndarray
    r: np.ndarray
    k: np.ndarray
    g: np.ndarray
    outside: np.ndarray
    sphere: np.ndarray


def body_params(a, r, k, g, outside=False, sphere=False) -> BodyParams:
    """Validated :class:`BodyParams` (beyond the paper; see docs/dynamics.md).

    Raises ValueError for non-finite values, a <= 0, k <= 0 (the equations of
    motion are singular at k = 0: M has eigenvalue k), g <= 0, or r <= a for
    a body inside the sphere.  Arrays are broadcast to one shape.
    """
    a, r, k, g = (np.asarray(x, dtype=float) for x in (a, r, k, g))
    outside = np.asarray(outside, dtype=bool)
    sphere = np.asarray(sphere, dtype=bool)
    a, r, k, g, outside, sphere = np.broadcast_arrays(a, r, k, g, outside, sphere)
    for name, x in (("a", a), ("r", r), ("k", k), ("g", g)):
        if not np.all(np.isfinite(x)):
            raise ValueError(f"{name} must be finite")
    if np.any(a <= 0):
        raise ValueError("body radius a must be > 0")
    if np.any(r <= 0):
        raise ValueError("sphere radius r must be > 0")
    if np.any(k <= 0):
        raise ValueError("inertia factor k must be > 0 for the equations of motion")
    if np.any(g <= 0):
        raise ValueError("g must be > 0")
    if np.any(too_big_inside(a, r, outside)):
        raise ValueError("a body inside the sphere needs r > a")
    return BodyParams(a, r, k, g, outside, sphere)


class ContactGeometry(NamedTuple):
    """Where the body touches the sphere, from a state (docs/dynamics.md
    sec. 2).  Vectors are (3, ...) arrays.

    ``c``, ``e1``, ``w`` the state's rows; ``e1_unit`` e1/|e1|; ``c_axial``
    c.e1_unit [m]; ``c_perp`` c - c_axial e1_unit for a wheel (c for a
    sphere) [m]; ``rho`` |c_perp| [m]; ``n`` c_perp/rho; ``e3`` s n, the unit
    vector from the centre to the contact point [-]; ``wheel`` (bool) the
    body is a wheel; ``s`` +1 inside, -1 outside.
    """

    c: np.ndarray
    e1: np.ndarray
    w: np.ndarray
    e1_unit: np.ndarray
    c_axial: np.ndarray
    c_perp: np.ndarray
    rho: np.ndarray
    n: np.ndarray
    e3: np.ndarray
    wheel: np.ndarray
    s: np.ndarray


def contact_geometry(state, p: BodyParams) -> ContactGeometry:
    """Contact direction e3 and the quantities it is built from, for states
    (9, ...) (beyond the paper; docs/dynamics.md sec. 2): for a wheel e3 is
    the unit projection of c on the wheel plane, times s; for a sphere s c/|c|."""
    state = np.asarray(state)
    c, e1, w = state[C], state[E1], state[W]
    wheel = ~p.sphere
    e1h = e1 / norm(e1)
    c1 = dot(c, e1h)
    cperp = c - np.where(wheel, c1, 0.0) * e1h
    rho = norm(cperp)
    s = np.where(p.outside, -1.0, 1.0)
    n = cperp / rho
    return ContactGeometry(c, e1, w, e1h, c1, cperp, rho, n, s * n, wheel, s)


def _coefficients(p: BodyParams):
    """Per-body constants of the equations (:func:`equations_by_component`), computed once:
    (a, g/a, s, wheel, k wheel, 1/(k+1), 1/k, wheel (1/(2k+1) - 1/(k+1)))
    with wheel = 1.0 for a wheel, 0.0 for a sphere and s = -1 outside, +1
    inside (docs/dynamics.md eq. D5)."""
    a, k, g = p.a, p.k, p.g
    wheel = np.where(p.sphere, 0.0, 1.0)
    s = np.where(p.outside, -1.0, 1.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        inv_k = np.where(k > 0, 1.0 / np.where(k > 0, k, 1.0), np.nan)
    return (a, g / a, s, wheel, wheel * k, 1.0 / (k + 1), inv_k,
            wheel * (1.0 / (2 * k + 1) - 1.0 / (k + 1)))


def equations_by_component(c0, c1, c2, x0, x1, x2, w0, w1, w2, coef, sqrt, accel=False):
    """The equations of motion written once, component by component.

    Beyond the paper (docs/dynamics.md, eqs. D1-D5; McDonald 1993 eqs. 2, 3,
    6, 7b in general form).  Only +, -, *, / and ``sqrt`` are used, so the
    same lines run on Python floats (``math.sqrt``: the one-body fast path of
    the simulator), Python complex numbers (``cmath.sqrt``: complex-step
    derivatives of one orbit) and numpy arrays of any shape, real or complex
    (``np.sqrt``: many bodies at once).  (c, x = e1, w) are the state's
    components; ``coef`` is :func:`_coefficients`.  Returns the 9 rates
    (dc/dt, de1/dt, dw/dt); with ``accel`` also d2c/dt2, e3 and de3/dt
    (3 each).
    """
    a, ga, s, wheel, kw, ik1, ik, d1 = coef
    ne = sqrt(x0 * x0 + x1 * x1 + x2 * x2)
    h0, h1, h2 = x0 / ne, x1 / ne, x2 / ne                     # e1 unit
    cw = (c0 * h0 + c1 * h1 + c2 * h2) * wheel                 # c.e1 (wheel only)
    q0, q1, q2 = c0 - cw * h0, c1 - cw * h1, c2 - cw * h2      # c_perp
    rho = sqrt(q0 * q0 + q1 * q1 + q2 * q2)
    n0, n1, n2 = q0 / rho, q1 / rho, q2 / rho
    u0, u1, u2 = s * n0, s * n1, s * n2                        # e3
    # dc/dt = a e3 x w (eq. 6); de1/dt = w x e1
    v0, v1, v2 = a * (u1 * w2 - u2 * w1), a * (u2 * w0 - u0 * w2), a * (u0 * w1 - u1 * w0)
    f0, f1, f2 = w1 * x2 - w2 * x1, w2 * x0 - w0 * x2, w0 * x1 - w1 * x0
    m0, m1, m2 = w1 * h2 - w2 * h1, w2 * h0 - w0 * h2, w0 * h1 - w1 * h0   # d(e1 unit)/dt
    # rate of the contact direction e3 (not a body vector)
    t = (v0 * h0 + v1 * h1 + v2 * h2 + c0 * m0 + c1 * m1 + c2 * m2) * wheel
    p0, p1, p2 = v0 - (t * h0 + cw * m0), v1 - (t * h1 + cw * m1), v2 - (t * h2 + cw * m2)
    pn = n0 * p0 + n1 * p1 + n2 * p2
    sr = s / rho
    d0, dd1, d2 = sr * (p0 - n0 * pn), sr * (p1 - n1 * pn), sr * (p2 - n2 * pn)   # de3/dt
    # M dw/dt = e3 x (de3/dt x w) + (g/a) e3 x z - k w1 (w x e1)
    y0, y1, y2 = dd1 * w2 - d2 * w1, d2 * w0 - d0 * w2, d0 * w1 - dd1 * w0
    kw1 = kw * (w0 * h0 + w1 * h1 + w2 * h2)
    b0 = u1 * y2 - u2 * y1 + ga * u1 - kw1 * m0
    b1 = u2 * y0 - u0 * y2 - ga * u0 - kw1 * m1
    b2 = u0 * y1 - u1 * y0 - kw1 * m2
    # closed-form inverse of M (eq. D5)
    r3 = u0 * b0 + u1 * b1 + u2 * b2
    r1 = d1 * (h0 * b0 + h1 * b1 + h2 * b2)
    r3k = r3 * ik
    a0 = (b0 - u0 * r3) * ik1 + u0 * r3k + r1 * h0
    a1 = (b1 - u1 * r3) * ik1 + u1 * r3k + r1 * h1
    a2 = (b2 - u2 * r3) * ik1 + u2 * r3k + r1 * h2
    if not accel:
        return v0, v1, v2, f0, f1, f2, a0, a1, a2
    # d2c/dt2 = a (de3/dt x w + e3 x dw/dt)
    g0 = a * (y0 + u1 * a2 - u2 * a1)
    g1 = a * (y1 + u2 * a0 - u0 * a2)
    g2 = a * (y2 + u0 * a1 - u1 * a0)
    return v0, v1, v2, f0, f1, f2, a0, a1, a2, g0, g1, g2, u0, u1, u2, d0, dd1, d2


def _motion(state, p: BodyParams):
    """Time derivatives in the lab frame and the acceleration of the centre
    (numpy arrays of shape (3, ...)): (cdot, e1dot, wdot, cddot, e3, e3dot)."""
    out = equations_by_component(*state[:9], _coefficients(p), np.sqrt, accel=True)
    return tuple(np.stack(np.broadcast_arrays(*out[i:i + 3])) for i in range(0, 18, 3))


def rhs(state, params: BodyParams, frame_rate=0.0):
    """Right-hand side d(state)/dt of the exact equations of motion.

    Eqs. (2), (3), (6), (7b) of McDonald (1993) in general form (beyond the
    paper: docs/dynamics.md).  ``state`` has shape (9, ...); returns the same
    shape.  ``frame_rate`` [rad/s] (broadcastable) is the rate Omega of a frame
    turning about +z in which the state's components are taken; the steady
    horizontal orbit of rate Omega is then a fixed point.  Complex input is
    supported (complex-step differentiation).
    """
    state = np.asarray(state)
    out = list(equations_by_component(*state[:9], _coefficients(params), np.sqrt))
    if np.any(np.asarray(frame_rate) != 0):
        fr = np.asarray(frame_rate)
        for i in (0, 3, 6):          # - Omega z x u for u = c, e1, w
            out[i] = out[i] + fr * state[i + 1]
            out[i + 1] = out[i + 1] - fr * state[i]
    return np.stack(np.broadcast_arrays(*out))


class _Dual:
    """Forward-mode derivative (value v, directional derivatives d) for
    :func:`equations_by_component` (beyond the paper; docs/dynamics.md sec. 5): v has
    the bodies' shape (..., n), d an extra leading axis of directions
    (m, ..., n); +, -, *, / follow the product and quotient rules.  Numpy
    defers to it (``__array_ufunc__ = None``), so coefficient arrays
    combine from either side."""

    __slots__ = ("v", "d")
    __array_ufunc__ = None

    def __init__(self, v, d):
        self.v = v
        self.d = d

    def __add__(self, o):
        if type(o) is _Dual:
            return _Dual(self.v + o.v, self.d + o.d)
        return _Dual(self.v + o, self.d)

    __radd__ = __add__

    def __sub__(self, o):
        if type(o) is _Dual:
            return _Dual(self.v - o.v, self.d - o.d)
        return _Dual(self.v - o, self.d)

    def __rsub__(self, o):
        return _Dual(o - self.v, -self.d)

    def __mul__(self, o):
        if type(o) is _Dual:
            return _Dual(self.v * o.v, self.d * o.v + self.v * o.d)
        return _Dual(self.v * o, self.d * o)

    __rmul__ = __mul__

    def __truediv__(self, o):
        if type(o) is _Dual:
            inv = 1.0 / o.v
            q = self.v * inv
            return _Dual(q, (self.d - q * o.d) * inv)
        inv = 1.0 / o
        return _Dual(self.v * inv, self.d * inv)

    def __rtruediv__(self, o):
        inv = 1.0 / self.v
        q = o * inv
        return _Dual(q, (-q * inv) * self.d)

    def __neg__(self):
        return _Dual(-self.v, -self.d)


def _dual_sqrt(x):
    s = np.sqrt(x.v)
    return _Dual(s, x.d * (0.5 / s))


def jvp(state, directions, params: BodyParams, frame_rate=0.0):
    """Jacobian-vector products of :func:`rhs`: J(state) @ directions.

    Beyond the paper (docs/dynamics.md sec. 5): forward-mode
    differentiation of the same lines (:func:`equations_by_component`) with value and
    derivatives carried separately (:class:`_Dual`), exact to round-off like
    a complex step but ~3x cheaper for several directions, since the value
    is computed once and in real arithmetic.  ``state`` (9, ..., n) real,
    ``directions`` (9, m, ..., n) (m directions per body); returns
    (9, m, ..., n).  ``frame_rate`` as for :func:`rhs`.
    """
    state = np.asarray(state, dtype=float)
    directions = np.asarray(directions, dtype=float)
    out = equations_by_component(*(_Dual(state[i], directions[i]) for i in range(9)), _coefficients(params), _dual_sqrt)
    d = [o.d if type(o) is _Dual else np.zeros_like(directions[0]) for o in out]
    fr = np.asarray(frame_rate)
    if np.any(fr != 0):
        for i in (0, 3, 6):          # - Omega z x u for u = c, e1, w
            d[i] = d[i] + fr * directions[i + 1]
            d[i + 1] = d[i + 1] - fr * directions[i]
    return np.stack(np.broadcast_arrays(*d))


def scalar_rates(y, coef, frame_rate=0.0):
    """d(state)/dt of ONE body, its state given as 9 Python floats; returns
    a tuple of 9 floats.  The same equations as :func:`rhs` (both run
    :func:`equations_by_component`), on floats: ~40x less per call than numpy on
    9-element arrays (beyond the paper; docs/simulation.md).  ``coef`` is
    :func:`scalar_coefficients`, ``frame_rate`` [rad/s] as for :func:`rhs`.
    Raises ZeroDivisionError at a singular state (where :func:`rhs` warns)."""
    out = equations_by_component(*y, coef, math.sqrt)
    if not frame_rate:
        return out
    fr = frame_rate
    v0, v1, v2, f0, f1, f2, a0, a1, a2 = out
    return (v0 + fr * y[1], v1 - fr * y[0], v2, f0 + fr * y[4], f1 - fr * y[3], f2,
            a0 + fr * y[7], a1 - fr * y[6], a2)


def ode(params: BodyParams, frame_rate=0.0):
    """A ``fun(t, y)`` for :func:`scipy.integrate.solve_ivp` (beyond the paper).

    ``y`` is the state of n bodies flattened from shape (9, n) (C order), so
    ``y.reshape(9, n)`` recovers it; with ``vectorized=True`` solve_ivp passes
    (9 n, m) arrays, which are handled too.  ``params`` fields must broadcast
    against shape (n,).  For one body and a 1-D float ``y`` the equations run
    on Python floats (:func:`scalar_rates`, the same lines as :func:`rhs`);
    a singular state falls back to numpy.
    """
    shape = np.broadcast_shapes(*(np.shape(x) for x in params),
                                np.shape(frame_rate))
    n = int(np.prod(shape))
    p_flat = BodyParams(*(np.broadcast_to(x, shape).reshape(-1) for x in params))
    fr = np.broadcast_to(np.asarray(frame_rate, dtype=float), shape).reshape(-1)
    p_col = BodyParams(*(x[:, None] for x in p_flat))

    def fun(t, y):
        y = np.asarray(y)
        if y.ndim == 1:
            return rhs(y.reshape(9, n), p_flat, fr).reshape(-1)
        m = y.shape[1]
        return rhs(y.reshape(9, n, m), p_col, fr[:, None]).reshape(9 * n, m)

    if n != 1:
        return fun
    coef1, fr1 = scalar_coefficients(p_flat), float(fr[0])

    def fun_one(t, y):
        if type(y) is np.ndarray and y.ndim == 1 and y.dtype == np.float64:
            try:
                return np.array(scalar_rates(y.tolist(), coef1, fr1))
            except (ZeroDivisionError, OverflowError, ValueError):
                pass
        return fun(t, y)

    return fun_one


# --------------------------------------------------------------------------
# invariants, constraints, contact force

def contact_point(state, params: BodyParams):
    """Contact point p = c + a e3 [m], shape (3, ...) (eq. 00 with e3 of
    docs/dynamics.md sec. 2)."""
    e3 = contact_geometry(state, params).e3
    return np.asarray(state)[C] + params.a * e3


def energy(state, params: BodyParams):
    """Energy per unit mass [J/kg] (beyond the paper, cf. eq. 27):
    |dc/dt|^2/2 + (k a^2/2)(|w|^2 + w1^2 [wheel only]) + g c_z.

    Conserved by the exact flow (the rolling contact force does no work).
    """
    state = np.asarray(state)
    c, e1, w, e1h, c1, cperp, rho, n, e3, wheel, s = contact_geometry(state, params)
    v = params.a * cross(e3, w)
    w1 = dot(w, e1h)
    rot = dot(w, w) + np.where(wheel, w1 * w1, 0.0)
    return 0.5 * dot(v, v) + 0.5 * params.k * params.a ** 2 * rot + params.g * c[2]


def constraint_residuals(state, params: BodyParams):
    """Residuals of the constraints (beyond the paper; docs/dynamics.md sec. 4).

    Returns a dict of arrays over the bodies:

    ``axis``         |e1| - 1 [-]
    ``contact``      |p| - r [m], p = c + a e3 the contact point
    ``contact_rate`` d|p|/dt [m/s] computed from the equations of motion
                     (zero identically: the flow is tangent to the contact
                     surface; a check of the geometry, eq. D6)
    ``slip``         |v_cm - a e3 x w| [m/s] with v_cm = dc/dt of :func:`rhs`;
                     zero by construction (rolling is built into the state,
                     eq. 6), reported so a simulator can log it uniformly.
    """
    state = np.asarray(state)
    cdot, _, _, _, e3, e3dot = _motion(state, params)
    c, e1, w = state[C], state[E1], state[W]
    pvec = c + params.a * e3
    pn = norm(pvec)
    pdot = cdot + params.a * e3dot
    slip = cdot - params.a * cross(e3, w)
    return {
        "axis": norm(e1) - 1.0,
        "contact": pn - params.r,
        "contact_rate": dot(pvec, pdot) / pn,
        "slip": norm(slip),
    }


def contact_force(state, params: BodyParams):
    """Contact force of the sphere on the body, per unit mass, from a state.

    Eq. (2) solved for F: F/m = d2c/dt2 + g z, with d2c/dt2 from the exact
    equations (beyond the paper; it reduces to eqs. 30/32 and 57 on steady
    orbits).  Returns a dict:

    ``force``     (3, ...) F/m [m/s^2], lab components
    ``normal``    component pressing body and sphere together [m/s^2]
                  (-F.n inside, +F.n outside, n = p/|p| the outward normal at
                  the contact point); > 0 means contact holds
    ``friction``  (3, ...) tangential part of F/m [m/s^2]
    ``friction_magnitude`` |friction| [m/s^2]
    ``mu_required`` |friction| / normal, NaN where normal <= 0
    """
    state = np.asarray(state)
    F0, F1, F2, normal, r0, r1, r2, fmag = _contact_force(
        *state[:9], _coefficients(params), params.g, np.sqrt)
    force = np.stack(np.broadcast_arrays(F0, F1, F2))
    fric = np.stack(np.broadcast_arrays(r0, r1, r2))
    normal, fmag = np.broadcast_arrays(normal, fmag)
    ok = normal > 0
    with np.errstate(divide="ignore", invalid="ignore"):
        mu = np.where(ok, fmag / np.where(ok, normal, 1.0), np.nan)
    return {"force": force, "normal": normal, "friction": fric,
            "friction_magnitude": fmag, "mu_required": mu}


def _contact_force(c0, c1, c2, x0, x1, x2, w0, w1, w2, coef, g, sqrt):
    """:func:`contact_force` written once for floats, complex numbers and
    numpy arrays (as :func:`equations_by_component`): F/m = d2c/dt2 + g z (eq. 2), its
    normal part -s F.n (s = +1 inside, -1 outside; n = p/|p|) and its
    tangential part.  Returns (F (3), normal, friction (3), |friction|)."""
    out = equations_by_component(c0, c1, c2, x0, x1, x2, w0, w1, w2, coef, sqrt, accel=True)
    F0, F1, F2 = out[9], out[10], out[11] + g
    a, s = coef[0], coef[2]
    p0, p1, p2 = c0 + a * out[12], c1 + a * out[13], c2 + a * out[14]      # contact point
    pn = sqrt(p0 * p0 + p1 * p1 + p2 * p2)
    n0, n1, n2 = p0 / pn, p1 / pn, p2 / pn
    fn = F0 * n0 + F1 * n1 + F2 * n2
    r0, r1, r2 = F0 - fn * n0, F1 - fn * n1, F2 - fn * n2
    return F0, F1, F2, -s * fn, r0, r1, r2, sqrt(r0 * r0 + r1 * r1 + r2 * r2)


def contact_values(y, coef, g):
    """(normal, |friction|) per unit mass [m/s^2] of ONE body from its state
    as 9 Python floats (the simulator's event functions; beyond the paper,
    docs/simulation.md): :func:`_contact_force` on floats.  ``coef`` is
    :func:`scalar_coefficients`.  Raises ZeroDivisionError at a singular
    state (the caller then takes the numpy path)."""
    out = _contact_force(*y, coef, g, math.sqrt)
    return out[3], out[7]


def scalar_coefficients(params: BodyParams):
    """:func:`_coefficients` of ONE body as a tuple of Python floats (for the
    scalar paths; ``params`` fields of size 1)."""
    return tuple(float(np.reshape(x, -1)[0]) for x in _coefficients(params))


def project(state, params: BodyParams):
    """Return the state moved back onto the constraint surface (beyond the
    paper, docs/dynamics.md sec. 4): e1 renormalised, then c shifted along the
    contact normal by r - |p| so that |p| = r exactly (e3 is unchanged by this
    shift).  For a simulator that wants to remove integration drift."""
    state = np.array(state, dtype=np.result_type(state, float), copy=True)
    e1 = state[E1]
    state[E1] = e1 / norm(e1)
    pvec = contact_point(state, params)
    pn = norm(pvec)
    state[C] = state[C] + (params.r - pn) * pvec / pn
    return state


def state_from_contact(p_hat, e1, w, params: BodyParams):
    """State with contact point r * p_hat, axis e1 and angular velocity w.

    Beyond the paper (docs/dynamics.md sec. 2, eq. D2): for a wheel
    e3 = s p_perp/|p_perp| (s = +1 inside, -1 outside) with p_perp the
    projection of p on the wheel plane, then c = p - a e3; for a sphere
    c = p - a e3 with e3 = s p_hat.  Inputs (3, ...) arrays (p_hat and e1
    are normalised here).  No check that the wheel fits (|p_perp| > a
    inside).
    """
    p_hat = np.asarray(p_hat)
    e1 = np.asarray(e1)
    p_hat = p_hat / norm(p_hat)
    e1 = e1 / norm(e1)
    pvec = params.r * p_hat
    pperp = pvec - dot(pvec, e1) * e1
    e3_wheel = np.where(params.outside, -1.0, 1.0) * pperp / norm(pperp)
    e3_sphere = np.where(params.outside, -1.0, 1.0) * p_hat
    e3 = np.where(params.sphere, e3_sphere, e3_wheel)
    c = pvec - params.a * e3
    return np.concatenate(np.broadcast_arrays(c, e1, np.asarray(w)))


# --------------------------------------------------------------------------
# steady horizontal orbits

def wheel_orbit_state(theta, alpha, a, r, k, g, outside=False, phi=0.0):
    """State of a wheel placed exactly on the steady horizontal orbit
    (theta, alpha), and its rate Omega.

    McDonald (1993) eqs. (11)-(13), (8b), (29): contact point at polar angle
    theta and azimuth phi, e1 = -sin(alpha) r_hat - cos(alpha) z,
    e3 = cos(alpha) r_hat - sin(alpha) z (r_hat horizontal, towards the
    contact point), c = p - a e3 (so the centre is at distance
    r' = r sin(theta) - a cos(alpha) from the axis), and
    w = (r'/a) Omega e1 - Omega sin(alpha) e3 (eq. 13) with
    Omega = +sqrt(Omega^2) of eq. (29).  Same formulas outside (sec. 3).

    Inputs broadcast; angles [rad], lengths [m], g [m/s^2].  Returns
    ``(state, Omega)`` with state shape (9, ...) and Omega [rad/s]; NaN where
    Omega^2 <= 0 or undefined.  Complex theta/alpha are accepted (complex
    step).  Whether the wheel fits / keeps contact is not checked here (see
    :func:`deathsphere.physics.wheel.horizontal_orbit`).
    """
    theta, alpha, a, r, k, g, phi = np.broadcast_arrays(
        *(np.asarray(x) for x in (theta, alpha, a, r, k, g, phi)))
    om2 = omega_squared(theta, alpha, a, r, k, g)
    # Omega^2 within round-off of 0 (alpha = 90 deg) is no orbit, as in
    # wheel.horizontal_orbit
    ok = np.nan_to_num(np.real(om2), nan=-1.0) > SINGULAR * np.real(g / r)
    omega = np.where(ok, np.sqrt(np.where(ok, om2, 1.0)), np.nan)
    cp, sp = np.cos(phi), np.sin(phi)
    zero = np.zeros_like(cp)
    rhat = np.stack((cp, sp, zero))
    zhat = np.stack((zero, zero, np.ones_like(cp)))
    st, ct = np.sin(theta), np.cos(theta)
    sa, ca = np.sin(alpha), np.cos(alpha)
    pvec = r * (st * rhat + ct * zhat)
    e1 = -sa * rhat - ca * zhat
    e3 = ca * rhat - sa * zhat
    c = pvec - a * e3
    rp = r_prime(theta, alpha, a, r)
    w = (rp / a) * omega * e1 - omega * sa * e3
    return np.concatenate((c, e1, w)), omega


def sphere_orbit_state(theta, omega, a, r, k, g, outside=False, phi=0.0):
    """State of a sphere on the steady horizontal orbit of polar angle theta
    and rate omega = Omega, and its spin omega3.

    McDonald (1993) eqs. (42), (44), (55): the centre at distance
    r' = r - a (inside) or r + a (outside) from the origin on the ray of polar
    angle theta and azimuth phi; e3 (centre to contact) = +/- that ray;
    w = -(1/a) e3 x v_cm + omega3 e3 (eq. 6a) with v_cm = Omega z x c and
    omega3 from eq. (55) (:func:`deathsphere.physics.sphere.omega3_from_rate`).
    The e1 rows hold a body-fixed marker (the paper's axis 1 at t = 0).

    Returns ``(state, omega3)``; NaN where Omega = 0.
    """
    theta, omega, a, r, k, g, outside, phi = np.broadcast_arrays(
        *(np.asarray(x) for x in (theta, omega, a, r, k, g)),
        np.asarray(outside, dtype=bool), np.asarray(phi))
    rp = centre_distance(a, r, outside)
    omega3 = omega3_from_rate(theta, omega, a, r, k, g, outside)
    cp, sp = np.cos(phi), np.sin(phi)
    zero = np.zeros_like(cp)
    rhat = np.stack((cp, sp, zero))
    zhat = np.stack((zero, zero, np.ones_like(cp)))
    chat = np.sin(theta) * rhat + np.cos(theta) * zhat
    c = rp * chat
    s = np.where(outside, -1.0, 1.0)
    e3 = s * chat
    v = omega * zcross(c)
    w = -cross(e3, v) / a + omega3 * e3
    e2 = np.stack((-sp, cp, zero))
    e1 = cross(e2, e3)
    return np.concatenate((c, e1, w)), omega3


# --------------------------------------------------------------------------
# vertical orbits

def vertical_orbit_state(theta, phidot_top, a, r):
    """State of a wheel at the top of a vertical orbit (sec. 2.2.1).

    McDonald (1993) eqs. (26)-(27), alpha = 0, beta = pi/2: the orbit lies in
    the vertical plane y = r cos(theta); at the top (phi = 0) the contact
    point is p = (0, r cos(theta), r sin(theta)), e1 = y_hat (the wheel in the
    orbit plane), e3 = z_hat, c = p - a z_hat (distance r' = r sin(theta) - a
    from the orbit's centre, eq. 8b with alpha = 0) and
    w = (r'/a) phidot_top e1 (rolling, eq. 13 with alpha = 0); the centre
    moves towards -x.  Complex theta / phidot_top accepted (complex step).
    Returns shape (9, ...).  The lap time is
    :func:`deathsphere.physics.vertical_orbit.lap_time`.
    """
    theta, phidot_top, a, r = np.broadcast_arrays(*(np.asarray(x) for x in (theta, phidot_top, a, r)))
    rp = r_prime(theta, 0.0, a, r)
    zero = np.zeros_like(rp)
    c = np.stack((zero, r * np.cos(theta), rp))
    e1 = np.stack((zero, zero + 1.0, zero))
    w = np.stack((zero, rp * phidot_top / a, zero))
    return np.concatenate((c, e1, w))
