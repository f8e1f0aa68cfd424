"""The Whipple bicycle's equations of motion, derived with
sympy.physics.mechanics (Kane's method), on flat ground or inside a sphere
(beyond the paper; docs/two-wheeler.md sec. 2-4).

This module needs sympy, which the shipped package does not: it is the
generator of ``_generated.py`` and the test that checks the shipped code
against a fresh derivation imports it.  Run

    python tools/generate_two_wheeler.py --write

to rewrite ``_generated.py``.

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
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path

import sympy as sm
import sympy.physics.mechanics as me

from deathsphere.physics.two_wheeler.parameters import PARAMETER_NAMES

__all__ = ["SURFACES", "COORDINATES", "GENERATED", "Derivation", "derive", "generated_functions", "generated_source"]

#: The surfaces: flat ground, and the inside of a sphere of radius r.
SURFACES = ("flat", "sphere")

#: The generalised coordinates, per surface, in the order of q.
COORDINATES = {
    "flat": ("x", "y", "heading", "lean", "pitch", "rear_angle", "steer", "front_angle"),
    "sphere": ("theta", "azimuth", "heading", "lean", "pitch", "rear_angle", "steer", "front_angle"),
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
    holonomic: sm.Expr
    holonomic_dpitch: sm.Expr
    kinetic: sm.Expr
    potential: sm.Expr
    front_contact: sm.Matrix
    seconds: float


def _surface_frame(surface, N, O, q, r):
    """The tangent frame T at the rear contact (T.z the outward normal:
    down on flat ground, away from the sphere's centre) and the rear
    contact point P."""
    if surface == "flat":
        T = N
        P = O.locatenew("P", q[0] * N.x + q[1] * N.y)
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


def derive(surface: str = "flat") -> Derivation:
    """Kane's equations of the Whipple bicycle on ``surface`` (beyond the
    paper; docs/two-wheeler.md sec. 3)."""
    if surface not in SURFACES:
        raise ValueError(f"surface must be one of {SURFACES}, not {surface!r}")
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
    T, P = _surface_frame(surface, N, O, q, r)
    Y = T.orientnew("Y", "Axis", (q[HEADING], T.z))     # heading
    L = Y.orientnew("L", "Axis", (q[LEAN], Y.x))        # lean, positive to the right
    C = L.orientnew("C", "Axis", (q[PITCH], L.y))       # rear frame (pitch 0 upright)
    WR = C.orientnew("WR", "Axis", (q[REAR], C.y))
    s = sm.sin(lam) * C.x + sm.cos(lam) * C.z           # steer axis, pointing down
    E = C.orientnew("E", "Axis", (q[STEER], s))         # front frame
    WF = E.orientnew("WF", "Axis", (q[FRONT], E.y))
    for frame, parent in ((T, N), (Y, T), (L, Y), (C, L), (WR, C), (E, C), (WF, E)):
        frame.set_ang_vel(parent, frame.ang_vel_in(parent).xreplace(to_u))

    P.set_vel(N, P.pos_from(O).dt(N).xreplace(to_u))
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
    Q, holonomic = _front_contact(surface, O, Fc, E.y, N, rF, r)

    # material points of the wheels at the contacts
    rear_slip = Rc.vel(N) + WR.ang_vel_in(N).cross(P.pos_from(Rc))
    front_slip = Fc.vel(N) + WF.ang_vel_in(N).cross(Q.pos_from(Fc))
    rows = [rear_slip.dot(Y.x), rear_slip.dot(Y.y)] + [front_slip.dot(e) for e in (Y.x, Y.y, Y.z)]
    rows = sm.Matrix(rows)
    B = rows.jacobian(u)
    # the rows are B(q) u, so their total derivative at u' = 0 is B' u
    bias = rows.jacobian(q) * sm.Matrix(u)

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
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=[a - b for a, b in zip(qd, u)])
    kane.kanes_equations(bodies, loads)
    kinetic = sum(b.kinetic_energy(N) for b in bodies).xreplace(to_u)
    potential = -sum(b.mass * g * b.masscenter.pos_from(O).dot(N.z) for b in bodies)
    parameters = list(p) + ([r] if surface == "sphere" else [])
    return Derivation(
        surface=surface, q=q, u=u, parameters=parameters, steer_torque=steer_torque,
        mass_matrix=kane.mass_matrix, forcing=kane.forcing,
        constraint_matrix=B, constraint_bias=bias,
        holonomic=holonomic, holonomic_dpitch=sm.diff(holonomic, q[PITCH]),
        kinetic=kinetic, potential=potential,
        front_contact=Q.pos_from(O).to_matrix(N),
        seconds=time.perf_counter() - start,
    )


# -- the generator of _generated.py -------------------------------------------------------------

GENERATED = Path(__file__).with_name("_generated.py")

_HEADER = '''"""Numeric equations of motion of the Whipple bicycle: GENERATED, do not edit.

Printed by ``python tools/generate_two_wheeler.py --write``
from the Kane's-method derivation in ``derivation.py`` (sympy {version}):
common subexpressions eliminated (sympy.cse), then printed as numpy code.
Beyond the paper; docs/two-wheeler.md sec. 3-5 documents the coordinates,
the constraints and every sign.

Every function takes q (8, ...) and, where it needs them, u (8, ...) -- the
generalised coordinates and speeds, a trailing batch axis broadcast -- the
parameters p in PARAMETER_NAMES order (then the sphere's radius r), each a
float or an array broadcasting against the batch.  Only functions analytic in their
arguments are used (sin, cos, sqrt, powers), so complex-step derivatives
pass through.
"""

import functools
import math

import numpy

SURFACES = {surfaces!r}

#: Bytes of each temporary per block of the batch: a function's thousand
#: temporaries then stay in the processor's cache, which halves the time per
#: state of a large batch.
BLOCK_BYTES = 32768


def _batch(*arrays):
    """The broadcast batch shape and result dtype of the arguments."""
    arrays = [a for a in arrays if not isinstance(a, (float, int))]
    shape = numpy.broadcast_shapes(*(numpy.shape(a)[1:] if numpy.ndim(a) else () for a in arrays))
    return shape, numpy.result_type(float, *arrays)


def _in_blocks(rows):
    """Evaluate a function of (``rows`` arrays (k, *batch), p, then arguments
    per state) over its batch in blocks of BLOCK_BYTES per temporary, the
    outputs joined along the batch."""
    def decorate(function):
        @functools.wraps(function)
        def blocked(*args):
            arrays, p, columns = [numpy.asarray(a) for a in args[:rows]], args[rows], args[rows + 1:]
            others = [x for x in (*p, *columns) if not isinstance(x, (float, int))]
            batch = numpy.broadcast_shapes(*(a.shape[1:] for a in arrays), *(numpy.shape(x) for x in others))
            size = math.prod(batch)
            block = max(BLOCK_BYTES // numpy.result_type(float, *arrays, *others).itemsize, 1)
            if size <= block:
                return function(*args)
            arrays = [numpy.broadcast_to(a, a.shape[:1] + batch).reshape(-1, size) for a in arrays]
            # the arguments that vary along the batch, flattened, and those that do not
            p, columns = ([(x, False) if numpy.ndim(x) == 0 else (numpy.broadcast_to(x, batch).reshape(size), True)
                           for x in xs] for xs in (p, columns))
            parts = []
            for start in range(0, size, block):
                cut = slice(start, start + block)
                parts.append(function(*(a[:, cut] for a in arrays), tuple(x[cut] if varies else x for x, varies in p),
                                      *(x[cut] if varies else x for x, varies in columns)))
            if not isinstance(parts[0], tuple):
                return numpy.concatenate(parts, axis=-1).reshape(parts[0].shape[:-1] + batch)
            return tuple(numpy.concatenate(out, axis=-1).reshape(out[0].shape[:-1] + batch) for out in zip(*parts))
        return blocked
    return decorate
'''


def _printer():
    from sympy.printing.numpy import NumPyPrinter

    return NumPyPrinter({"fully_qualified_modules": True, "inline": True})


def _plain(derivation: Derivation):
    """Replace q(t), u(t) by plain symbols q0.., u0.. for printing."""
    n = len(derivation.q)
    qs = sm.symbols(f"q0:{n}")
    us = sm.symbols(f"u0:{n}")
    return dict(zip(derivation.q, qs)) | dict(zip(derivation.u, us)), qs, us


def _function(name, doc, args, unpack, outputs, printer):
    """Source of one function: CSE over every output, then the outputs
    assembled into arrays of shape (rows, cols, *batch) or (rows, *batch).

    ``outputs`` is a list of (shape, sympy Matrix, symmetric)."""
    flat = []
    for shape, matrix, symmetric in outputs:
        for i in range(shape[0]):
            for j in range(shape[1] if len(shape) == 2 else 1):
                if symmetric and j < i:
                    continue
                flat.append(matrix[i, j] if len(shape) == 2 else matrix[i])
    replacements, reduced = sm.cse(flat, symbols=sm.numbered_symbols("x"), order="none")
    lines = [f"@_in_blocks({args.index('p')})", f"def {name}({', '.join(args)}):", f'    """{doc}"""']
    lines += [f"    {line}" for line in unpack]
    lines += [f"    {sym} = {printer.doprint(expr)}" for sym, expr in replacements]
    it = iter(reduced)
    names = []
    for k, (shape, matrix, symmetric) in enumerate(outputs):
        out = f"out{k}"
        names.append(out)
        lines.append(f"    {out} = numpy.zeros({tuple(shape)} + shape, dtype=dtype)")
        for i in range(shape[0]):
            for j in range(shape[1] if len(shape) == 2 else 1):
                if symmetric and j < i:
                    continue
                expr = next(it)
                if expr == 0:
                    continue
                index = f"{i}, {j}" if len(shape) == 2 else f"{i}"
                lines.append(f"    {out}[{index}] = {printer.doprint(expr)}")
                if symmetric and j > i:
                    lines.append(f"    {out}[{j}, {i}] = {out}[{i}, {j}]")
    lines.append(f"    return {', '.join(names)}")
    return "\n".join(lines) + "\n"


def generated_functions(derivation: Derivation) -> str:
    """The numeric functions of one surface, as Python source (beyond the
    paper; docs/two-wheeler.md sec. 5)."""
    printer = _printer()
    plain, qs, us = _plain(derivation)
    params = [str(s) for s in derivation.parameters]
    unpack_q = [f"{', '.join(map(str, qs))}, = q"]
    unpack_u = [f"{', '.join(map(str, us))}, = u"]
    unpack_p = [f"{', '.join(params)}, = p"]
    s = derivation.surface

    def sub(m):
        return sm.Matrix(m).xreplace(plain)

    T = derivation.steer_torque
    parts = [
        _function(f"{s}_equations",
                  "Kane's equations with all eight speeds free, M u' = f, and the rolling "
                  "constraints B u = 0 with B' u: returns M (8, 8), f (8), B (5, 8), B' u (5).",
                  ["q", "u", "p", str(T)],
                  unpack_q + unpack_u + unpack_p + ["shape, dtype = _batch(q, u, " + str(T) + ", *p)"],
                  [((8, 8), sub(derivation.mass_matrix), True), ((8,), sub(derivation.forcing), False),
                   ((5, 8), sub(derivation.constraint_matrix), False),
                   ((5,), sub(derivation.constraint_bias), False)], printer),
        _function(f"{s}_holonomic",
                  "The front contact's holonomic constraint h(q) = 0 and dh/dpitch: returns "
                  "(h, dh/dpitch), each of shape (1, ...).",
                  ["q", "p"], unpack_q + unpack_p + ["shape, dtype = _batch(q, *p)"],
                  [((1,), sub([derivation.holonomic]), False),
                   ((1,), sub([derivation.holonomic_dpitch]), False)], printer),
        _function(f"{s}_energy",
                  "Kinetic and potential energy: returns (T, V), each of shape (1, ...).",
                  ["q", "u", "p"], unpack_q + unpack_u + unpack_p + ["shape, dtype = _batch(q, u, *p)"],
                  [((1,), sub([derivation.kinetic]), False),
                   ((1,), sub([derivation.potential]), False)], printer),
        _function(f"{s}_front_contact",
                  "The front contact point in the inertial frame N (z down): shape (3, ...).",
                  ["q", "p"], unpack_q + unpack_p + ["shape, dtype = _batch(q, *p)"],
                  [((3,), sub(derivation.front_contact), False)], printer),
        # the dependent speeds need B alone, a twentieth of the equations' cost
        _function(f"{s}_constraint_matrix",
                  "The rolling constraints' matrix B (5, 8) of B u = 0 alone, as in "
                  f"{s}_equations.",
                  ["q", "p"], unpack_q + unpack_p + ["shape, dtype = _batch(q, *p)"],
                  [((5, 8), sub(derivation.constraint_matrix), False)], printer),
        # a steady turn's speed-free part (gravity, the steer torque) without the speeds' terms
        _function(f"{s}_forcing_at_rest",
                  "The forcing f (8) of Kane's equations at rest (u = 0): gravity and the steer torque.",
                  ["q", "p", str(T)], unpack_q + unpack_p + ["shape, dtype = _batch(q, " + str(T) + ", *p)"],
                  [((8,), sub(derivation.forcing).xreplace({x: 0 for x in us}), False)], printer),
    ]
    return "\n\n".join(parts)


def generated_source(surfaces=SURFACES, derivations=None) -> str:
    """The whole text of ``_generated.py`` (beyond the paper;
    docs/two-wheeler.md sec. 5)."""
    derivations = derivations or {s: derive(s) for s in surfaces}
    text = _HEADER.format(version=sm.__version__, surfaces=tuple(surfaces))
    for s in surfaces:
        text += "\n\n" + generated_functions(derivations[s])
    return text
