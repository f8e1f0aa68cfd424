"""The Whipple bicycle's equations of motion, derived with
sympy.physics.mechanics (Kane's method), on flat ground, inside a sphere,
and inside any surface of revolution given as data (beyond the paper;
docs/two-wheeler.md sec. 2-4 and 12).

This module needs sympy, which the shipped package does not: it only
derives.  ``deathsphere.codegen`` turns the derivation into the numpy code
of ``_generated.py`` (``python tools/generate_two_wheeler.py --write``), and
the test that checks the shipped code against a fresh derivation imports
both.

What is derived, for each surface (docs/two-wheeler.md sec. 3)
--------------------------------------------------------------
* Kane's equations of the bicycle with all eight generalised speeds
  u = q' free: ``mass_matrix`` (8x8) and ``forcing`` (8), gravity and a
  steer torque included.  The rolling constraints are then imposed on them
  numerically (``linear.py`` and docs/two-wheeler.md sec. 4):
  Kane's equations of the constrained system are A^T (M u' - f) = 0 with
  u = A u_ind, which is the same as M u' - f = B^T lambda, B u = 0.
* ``constraint_matrix`` B (5x8): the velocity of the rear wheel's contact
  point along the two tangent directions and the front wheel's contact
  point's full velocity (its normal component is the time derivative of the
  holonomic constraint), each linear in u; and ``constraint_bias`` = B' u.
* ``holonomic``: the front contact on the surface, a function of lean,
  pitch and steer only, and its derivative with respect to pitch.
* ``energy``: kinetic and potential energy.

On a surface of revolution (``"revolution"``, docs/two-wheeler.md sec. 12)
the meridian enters as undefined functions of the rear contact's arc
length s = q0 (rho(s), z(s), the wall angle beta(s), its curvature
kappa(s) = beta'(s) and kappa'(s)), differentiated by the chain rule
(rho' = cos beta, z' = sin beta, beta' = kappa) and then replaced by plain
symbols: the generated code takes the meridian at the rear contact as
arguments, which the ground record evaluates at run time.  The front
contact is the rim point at the angle psi (an argument too) in the front
wheel's plane; the run time finds psi where the rim is tangent to the
surface from the ground's implicit function, so no holonomic constraint is
derived: ``front_rim`` gives the front wheel's centre and plane (and their
pitch derivatives) from which it is evaluated, and the equations carry
what the bias of the rolling constraints needs of psi's rate.
"""

from __future__ import annotations

import time
from contextlib import contextmanager
from dataclasses import dataclass

import sympy as sm
import sympy.physics.mechanics as me

from deathsphere.physics.two_wheeler.generalized_forces import kanes_equations
from deathsphere.physics.two_wheeler.parameters import PARAMETER_NAMES
from deathsphere.physics.two_wheeler.substitution import xreplace

__all__ = ["SURFACES", "COORDINATES", "MERIDIAN", "RIM_ANGLE", "Derivation", "derive"]

#: The surfaces: flat ground, the inside of a sphere of radius r, and the
#: inside of any surface of revolution, its meridian as data.
SURFACES = ("flat", "sphere", "revolution")

#: The meridian at the rear contact, the revolution's arguments after Table 1's
#: (z up, as the ground protocol's; kappa = d beta / ds, dkappa = d kappa / ds).
MERIDIAN = ("rho_R", "z_R", "beta_R", "kappa_R", "dkappa_R")
#: The front rim's angle from E.z towards E.x of the rim point that touches, the last argument.
RIM_ANGLE = "psi_F"

#: The generalised coordinates, per surface, in the order of q.
COORDINATES = {
    "flat": ("x", "y", "heading", "lean", "pitch", "rear_angle", "steer", "front_angle"),
    "sphere": ("theta", "azimuth", "heading", "lean", "pitch", "rear_angle", "steer", "front_angle"),
    "revolution": ("s", "azimuth", "heading", "lean", "pitch", "rear_angle", "steer", "front_angle"),
}

#: Index of each named coordinate in q (the same for both surfaces from 2 on).
HEADING, LEAN, PITCH, REAR, STEER, FRONT = 2, 3, 4, 5, 6, 7


@dataclass
class Derivation:
    """The symbolic equations of one surface (docs/two-wheeler.md sec. 3)."""

    surface: str
    q: list                 # dynamicsymbols
    u: list
    parameters: list        # sympy symbols, PARAMETER_NAMES order (+ r on the sphere)
    steer_torque: sm.Symbol
    mass_matrix: sm.Matrix
    forcing: sm.Matrix
    constraint_matrix: sm.Matrix
    constraint_bias: sm.Matrix
    holonomic: sm.Expr | None        # None on a revolution: evaluated from the ground at run time
    holonomic_dpitch: sm.Expr | None
    kinetic: sm.Expr
    potential: sm.Expr
    front_contact: sm.Matrix
    seconds: float
    # a revolution's: d(B u)/d psi (5), the velocity of the front frame's point at Q (3) and the front
    # frame's angular velocity (3) in N (psi's rate from them), and the front wheel's centre, E.x, E.z and
    # their pitch derivatives in N (18)
    constraint_dpsi: sm.Matrix | None = None
    front_point_velocity: sm.Matrix | None = None
    front_frame_rate: sm.Matrix | None = None
    front_rim: sm.Matrix | None = None


class _Meridian:
    """The meridian at the rear contact as undefined functions of its arc
    length s = q0, and the chain rule that differentiates them."""

    def __init__(self, s):
        self.s = s
        self.rho, self.z, self.beta, self.kappa, self.dkappa = (sm.Function(n)(s) for n in MERIDIAN)
        self._rules = {self.rho.func: sm.cos(self.beta), self.z.func: sm.sin(self.beta),
                       self.beta.func: self.kappa, self.kappa.func: self.dkappa}
        self.symbols = sm.symbols(MERIDIAN, real=True)

    def chain(self, expr):
        """expr with every derivative of the meridian's functions in s replaced (beyond kappa' none occurs)."""
        def rule(d):
            out = self._rules[d.expr.func]
            for _ in range(d.derivative_count - 1):
                out = self.chain(sm.diff(out, self.s))
            return out

        def is_meridian(e):
            return isinstance(e, sm.Derivative) and e.expr.func in self._rules and e.variables[0] == self.s

        return expr.replace(is_meridian, rule)

    def plain(self, expr):
        """expr with the functions of s replaced by the plain symbols of MERIDIAN."""
        return xreplace(expr, dict(zip((self.rho, self.z, self.beta, self.kappa, self.dkappa), self.symbols)))


def _surface_frame(surface, N, O, q, r, meridian=None):
    """The tangent frame T at the rear contact (T.z the outward normal:
    down on flat ground, away from the sphere's centre, out of a
    revolution's wall) and the rear contact point P."""
    if surface == "flat":
        T = N
        P = O.locatenew("P", q[0] * N.x + q[1] * N.y)
    elif surface == "revolution":
        # turned by the azimuth about N.z, then by beta about the new y: T.x = cos(beta) rho-hat + sin(beta) up
        # is the meridian's tangent up the wall, T.z = sin(beta) rho-hat + cos(beta) N.z (N.z down) the
        # outward normal; on the sphere beta = pi - theta, the sphere's frame
        T = N.orientnew("T", "Body", (q[1], meridian.beta, 0), "ZYX")
        A = N.orientnew("A", "Axis", (q[1], N.z))
        P = O.locatenew("P", meridian.rho * A.x - meridian.z * A.z)
    else:
        # P = r (sin th cos az, sin th sin az, -cos th) in N (z down): theta is
        # the polar angle from the upward vertical, 0 at the top.
        T = N.orientnew("T", "Body", (q[1], sm.pi - q[0], 0), "ZYX")
        P = O.locatenew("P", r * T.z)
    return T, P


def _front_contact(surface, O, Fc, a, N, rF, r):
    """The front rim's point farthest from the sphere's centre (on flat
    ground: the lowest) and the holonomic constraint putting it on the
    surface (docs/two-wheeler.md sec. 3.2)."""
    if surface == "flat":
        na = N.z.dot(a)
        k = N.z - na * a
        norm_k = sm.sqrt(1 - na**2)
        contact = Fc.locatenew("Q", rF / norm_k * k)
        return contact, Fc.pos_from(O).dot(N.z) + rF * norm_k
    d = Fc.pos_from(O)
    da = d.dot(a)
    dd = d.dot(d)
    norm_perp = sm.sqrt(dd - da**2)
    contact = Fc.locatenew("Q", rF / norm_perp * (d - da * a))
    # |Q - O|^2 = (d.a)^2 + (|d_perp| + rF)^2 = r^2
    return contact, (dd + 2 * rF * norm_perp + rF**2 - r**2) / (2 * r)


def _jacobian(rows: sm.Matrix, by: list) -> sm.Matrix:
    """``rows.jacobian(by)`` for ``by`` functions of time, differentiated by
    plain symbols put in their place: sympy differentiates by a function
    through a substitution per derivative, by a symbol directly, to the same
    expressions (the generated code is unchanged) in a third of the time."""
    symbols = [sm.Dummy() for _ in by]
    jacobian = xreplace(rows, dict(zip(by, symbols))).jacobian(symbols)
    return xreplace(jacobian, dict(zip(symbols, by)))


@contextmanager
def _free_symbols_remembered():
    """Within the block (the whole derivation), a sympy expression's free
    symbols computed once per node.  Every derivative sympy takes asks its
    expression for its free symbols, which sympy finds by walking the whole
    subtree each time; a Jacobian of the rolling constraints takes a
    derivative of every node of their expressions, so the same subtrees were
    walked once per ancestor (and Kane's dot products and the meridian's
    chain rule ask as often).  The sets are the same (an expression is
    immutable), so are the derivatives; each call still gets a fresh set,
    as sympy's does, and sympy's own property is put back on leaving."""
    walk = sm.Basic.free_symbols
    seen = {}

    def free_symbols(self):
        try:
            return set(seen[id(self)][1])
        except KeyError:
            found = walk.fget(self)
            seen[id(self)] = (self, frozenset(found))   # self kept alive: its id stays its own
            return found

    sm.Basic.free_symbols = property(free_symbols, doc=walk.__doc__)
    try:
        yield
    finally:
        sm.Basic.free_symbols = walk


def derive(surface: str = "flat") -> Derivation:
    """Kane's equations of the Whipple bicycle on ``surface`` (beyond the
    paper; docs/two-wheeler.md sec. 3)."""
    if surface not in SURFACES:
        raise ValueError(f"surface must be one of {SURFACES}, not {surface!r}")
    start = time.perf_counter()
    with _free_symbols_remembered():
        derivation = _derive(surface)
    derivation.seconds = time.perf_counter() - start
    return derivation


def _derive(surface: str) -> Derivation:
    start = time.perf_counter()
    p = sm.symbols(PARAMETER_NAMES, real=True)
    P_ = dict(zip(PARAMETER_NAMES, p))
    w, c, lam, g, rR, rF = (P_[k] for k in ("w", "c", "lam", "g", "rR", "rF"))
    r = sm.Symbol("r", positive=True)
    steer_torque = sm.Symbol("T_steer", real=True)
    q = list(me.dynamicsymbols(" ".join(f"q_{n}" for n in COORDINATES[surface])))
    u = list(me.dynamicsymbols(" ".join(f"u_{n}" for n in COORDINATES[surface])))
    qd = [qi.diff() for qi in q]
    to_u = dict(zip(qd, u))

    N = me.ReferenceFrame("N")          # inertial, z down
    O = me.Point("O")                   # the sphere's centre / the origin
    O.set_vel(N, 0)
    meridian = _Meridian(q[0]) if surface == "revolution" else None

    # the chain rule of the meridian's functions (nothing to do on flat ground and the sphere)
    chain = meridian.chain if meridian else None

    T, P = _surface_frame(surface, N, O, q, r, meridian)
    Y = T.orientnew("Y", "Axis", (q[HEADING], T.z))     # heading
    L = Y.orientnew("L", "Axis", (q[LEAN], Y.x))        # lean, positive to the right
    C = L.orientnew("C", "Axis", (q[PITCH], L.y))       # rear frame (pitch 0 upright)
    WR = C.orientnew("WR", "Axis", (q[REAR], C.y))
    s = sm.sin(lam) * C.x + sm.cos(lam) * C.z           # steer axis, pointing down
    E = C.orientnew("E", "Axis", (q[STEER], s))         # front frame
    WF = E.orientnew("WF", "Axis", (q[FRONT], E.y))
    for frame, parent in ((T, N), (Y, T), (L, Y), (C, L), (WR, C), (E, C), (WF, E)):
        frame.set_ang_vel(parent, _vector_map(frame.ang_vel_in(parent), chain).xreplace(to_u))

    P.set_vel(N, _vector_map(P.pos_from(O).dt(N), chain).xreplace(to_u))
    Rc = P.locatenew("Rc", -rR * L.z)                   # rear wheel centre
    Bo = Rc.locatenew("Bo", P_["xB"] * C.x + (P_["zB"] + rR) * C.z)
    S = Rc.locatenew("S", (w + c) * C.x + rR * C.z)     # steer axis meets the ground
    Fc = S.locatenew("Fc", -c * E.x - rF * E.z)         # front wheel centre
    Ho = S.locatenew("Ho", (P_["xH"] - w - c) * E.x + P_["zH"] * E.z)
    Rc.v2pt_theory(P, N, L)
    for point in (Bo, S):
        point.v2pt_theory(Rc, N, C)
    for point in (Fc, Ho):
        point.v2pt_theory(S, N, E)
    psi = sm.Symbol(RIM_ANGLE, real=True)
    if surface == "revolution":
        # the rim point at psi from E.z towards E.x: found at run time where the rim is tangent to the ground
        Q, holonomic = Fc.locatenew("Q", rF * (sm.sin(psi) * E.x + sm.cos(psi) * E.z)), None
    else:
        Q, holonomic = _front_contact(surface, O, Fc, E.y, N, rF, r)

    # material points of the wheels at the contacts
    rear_slip = Rc.vel(N) + WR.ang_vel_in(N).cross(P.pos_from(Rc))
    front_slip = Fc.vel(N) + WF.ang_vel_in(N).cross(Q.pos_from(Fc))
    rows = [rear_slip.dot(Y.x), rear_slip.dot(Y.y)] + [front_slip.dot(e) for e in (Y.x, Y.y, Y.z)]
    rows = sm.Matrix(rows)
    B = _jacobian(rows, u)
    # the rows are B(q) u, so their total derivative at u' = 0 is B' u (on a revolution, psi's part apart)
    slopes = _jacobian(rows, q)
    bias = (slopes.applyfunc(chain) if chain else slopes) * sm.Matrix(u)

    def inertia(frame, xx, yy, zz, xz=0):
        return me.inertia(frame, xx, yy, zz, 0, 0, xz)

    bodies = [
        me.RigidBody("rear_frame", Bo, C, P_["mB"],
                     (inertia(C, P_["IBxx"], P_["IByy"], P_["IBzz"], P_["IBxz"]), Bo)),
        me.RigidBody("rear_wheel", Rc, WR, P_["mR"], (inertia(C, P_["IRxx"], P_["IRyy"], P_["IRxx"]), Rc)),
        me.RigidBody("front_frame", Ho, E, P_["mH"],
                     (inertia(E, P_["IHxx"], P_["IHyy"], P_["IHzz"], P_["IHxz"]), Ho)),
        me.RigidBody("front_wheel", Fc, WF, P_["mF"], (inertia(E, P_["IFxx"], P_["IFyy"], P_["IFxx"]), Fc)),
    ]
    loads = [(b.masscenter, b.mass * g * N.z) for b in bodies]
    loads += [(E, steer_torque * s), (C, -steer_torque * s)]
    mass_matrix, forcing = kanes_equations(N, q, u, bodies, loads)
    kinetic = xreplace(sum(b.kinetic_energy(N) for b in bodies), to_u)
    potential = -sum(b.mass * g * b.masscenter.pos_from(O).dot(N.z) for b in bodies)
    if surface != "revolution":
        parameters = list(p) + ([r] if surface == "sphere" else [])
        return Derivation(
            surface=surface, q=q, u=u, parameters=parameters, steer_torque=steer_torque,
            mass_matrix=mass_matrix, forcing=forcing,
            constraint_matrix=B, constraint_bias=bias,
            holonomic=holonomic, holonomic_dpitch=sm.diff(holonomic, q[PITCH]),
            kinetic=kinetic, potential=potential,
            front_contact=Q.pos_from(O).to_matrix(N),
            seconds=time.perf_counter() - start,
        )
    plain = meridian.plain

    def matrix(x):
        return plain(sm.Matrix(x).applyfunc(chain))

    centre = Fc.pos_from(O)
    rim = [centre.to_matrix(N), E.x.to_matrix(N), E.z.to_matrix(N)]
    rim += [m.diff(q[PITCH]) for m in rim]
    return Derivation(
        surface=surface, q=q, u=u, parameters=list(p) + list(meridian.symbols) + [psi], steer_torque=steer_torque,
        mass_matrix=matrix(mass_matrix), forcing=matrix(forcing),
        constraint_matrix=matrix(B), constraint_bias=matrix(bias),
        holonomic=None, holonomic_dpitch=None,
        kinetic=plain(chain(kinetic)), potential=plain(chain(potential)),
        front_contact=matrix(Q.pos_from(O).to_matrix(N)),
        seconds=time.perf_counter() - start,
        constraint_dpsi=matrix(rows.diff(psi)),
        front_point_velocity=matrix((Fc.vel(N) + E.ang_vel_in(N).cross(Q.pos_from(Fc))).to_matrix(N)),
        front_frame_rate=matrix(E.ang_vel_in(N).to_matrix(N)),
        front_rim=matrix(sm.Matrix.vstack(*rim)),
    )


def _vector_map(vector, f):
    """The vector with f applied to each of its components (a sympy Vector's measure numbers)."""
    if f is None or vector == 0:
        return vector
    return me.Vector([(m.applyfunc(f), frame) for m, frame in vector.args])
