"""Kane's equations of a system whose generalised speeds are the
coordinates' rates (u = q'), formed from the partial velocities
(beyond the paper; docs/two-wheeler.md sec. 3 and 5).

The same sums, in the same order, with the same substitutions, as
``sympy.physics.mechanics.KanesMethod(N, q, u, kd_eqs=q' - u)``'s
``kanes_equations`` followed by its ``mass_matrix`` and ``forcing``, so the
expressions are identical (the regeneration test compares the printed code
byte for byte).  What differs is the cost of the substitutions: sympy's
``msubs`` rebuilds every node of an expression from its rebuilt arguments
(q' -> u, q'' -> u', u' -> 0), and the rebuilding is not a no-op -- a
number times a sum is distributed when rebuilt, so ``xreplace``, which
leaves untouched what holds nothing to swap, would print different code.
The bicycle's expressions share most of their subtrees, which ``msubs``
rebuilds once per occurrence; ``_Swap`` rebuilds each distinct subtree once
and remembers the result, the same rebuild.  Like the derivation, this
needs sympy.
"""

from __future__ import annotations

import sympy as sm
import sympy.physics.mechanics as me
from sympy.physics.mechanics.functions import _f_list_parser

__all__ = ["kanes_equations"]


class _Swap:
    """``msubs(expr, swaps)`` (sympy.physics.mechanics) with each distinct
    subtree rebuilt once: a node found in ``swaps`` is replaced, a leaf or a
    derivative is kept, any other node is rebuilt from its rebuilt
    arguments."""

    def __init__(self, *swaps):
        self.swaps = {k: v for d in swaps for k, v in d.items()}
        self.memo = {}

    def expr(self, e):
        try:
            return self.memo[e]
        except KeyError:
            pass
        if e in self.swaps:
            out = self.swaps[e]
        elif not e.args or e.is_Derivative:
            out = e
        else:
            out = e.func(*(self.expr(a) for a in e.args))
        self.memo[e] = out
        return out

    def __call__(self, x):
        if isinstance(x, (sm.MatrixBase, me.Vector, me.Dyadic)):
            return x.applyfunc(self.expr)
        return self.expr(x)


def kanes_equations(N, q, u, bodies, loads):
    """The mass matrix M and forcing f of Kane's equations M u' = f of
    rigid ``bodies`` under ``loads`` (pairs of a point and a force or a frame
    and a torque), with u = q' (beyond the paper; docs/two-wheeler.md
    sec. 3): Fr = the loads dotted with the partial velocities, Fr* =
    -(M u' + the rest) from the bodies' momenta, as sympy's KanesMethod."""
    t = me.dynamicsymbols._t
    qd = [qi.diff(t) for qi in q]
    to_u = dict(zip(qd, u))
    ud = [ui.diff(t) for ui in u]
    ud_zero = dict.fromkeys(ud, 0)
    qdd_to_ud = {k.diff(t): v.diff(t).xreplace(to_u) for k, v in to_u.items()}
    qdd_to_ud.update(to_u)
    by_u, rebuild, at_rest, by_ud = _Swap(to_u), _Swap(), _Swap(ud_zero), _Swap(qdd_to_ud)
    o = len(u)

    # generalised active forces
    velocities, forces = _f_list_parser(loads, N)
    velocities = [by_u(v) for v in velocities]
    forces = [by_u(f) for f in forces]
    partials = me.partial_velocity(velocities, u, N)
    fr = sm.zeros(o, 1)
    for i in range(o):
        fr[i] = sum(partials[j][i].dot(forces[j]) for j in range(len(forces)))

    # generalised inertia forces, -(M u' + non_mm)
    def at_rest_rebuilt(x):
        return rebuild(at_rest(x))

    mm = sm.zeros(o, o)
    non_mm = sm.zeros(o, 1)
    for body in bodies:
        linear, angular = me.partial_velocity(
            [by_u(v) for v in (body.masscenter.vel(N), body.frame.ang_vel_in(N))], u, N)
        m = rebuild(body.mass)
        inertia = rebuild(body.central_inertia)
        vel = rebuild(body.masscenter.vel(N))
        omega = rebuild(body.frame.ang_vel_in(N))
        acc = at_rest_rebuilt(body.masscenter.acc(N))
        inertial_force = m.diff(t) * vel + m * acc
        inertial_torque = rebuild((inertia.dt(body.frame).dot(omega))
                                  + at_rest(inertia.dot(body.frame.ang_acc_in(N)))
                                  + (omega.cross(inertia.dot(omega))))
        for j in range(o):
            tmp_vel = rebuild(linear[j])
            tmp_ang = rebuild(inertia.dot(angular[j]))
            for k in range(o):
                mm[j, k] += m * tmp_vel.dot(linear[k])
                mm[j, k] += tmp_ang.dot(angular[k])
            non_mm[j] += inertial_force.dot(linear[j])
            non_mm[j] += inertial_torque.dot(angular[j])
    mm = rebuild(by_ud(mm))
    non_mm = _Swap(ud_zero)(by_ud(non_mm))
    f_d = -(fr - non_mm)
    return sm.Matrix([mm, sm.Matrix()]), -sm.Matrix([f_d, sm.Matrix()])
