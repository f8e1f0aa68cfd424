"""Second-order Taylor jets: a value with its first and second time
derivatives, x(eps) = x0 + x1 eps + x2 eps^2 / 2, carried through +, -, *,
/, sqrt, dot, cross, cos and sin by Leibniz's rule (beyond the paper: the
arithmetic of the machine's crown point on any ground, docs/machine.md,
"On any ground", MG4).  A zero coefficient is None (no work).  Only
operations analytic in their arguments are used, so a complex step passes
through."""

from __future__ import annotations

import numpy as np

from deathsphere.physics.vectors import cross as _cross
from deathsphere.physics.vectors import dot as _dot

__all__ = ["Taylor", "tdiv", "tsqrt", "tdot", "tcross", "tunit", "tcos_sin", "with_coefficient", "component",
           "stack"]


def _sum(*terms):
    """The sum of the terms that are not None (a zero coefficient is None: no work); None if all are."""
    out = None
    for x in terms:
        if x is not None:
            out = x if out is None else out + x
    return out


def _times(f, x, y):
    """f(x, y) (a product), None where either factor is None (zero)."""
    return None if x is None or y is None else f(x, y)


def _mul(x, y):
    return x * y


def _neg(x):
    return None if x is None else -x


class Taylor:
    """x(eps) = x0 + x1 eps + x2 eps^2 / 2, truncated: a value and its first
    and second time derivatives.  Vectors carry a leading axis of 3; x2 may
    carry more trailing axes than x0 (the trial accelerations).  A zero
    coefficient is None (the value alone, or value and rate, cost only
    their own arithmetic)."""

    __slots__ = ("x0", "x1", "x2")
    __array_ufunc__ = None

    def __init__(self, x0, x1=None, x2=None):
        self.x0, self.x1, self.x2 = x0, x1, x2

    def __add__(self, o):
        if isinstance(o, Taylor):
            return Taylor(self.x0 + o.x0, _sum(self.x1, o.x1), _sum(self.x2, o.x2))
        return Taylor(self.x0 + o, self.x1, self.x2)

    __radd__ = __add__

    def __neg__(self):
        return Taylor(-self.x0, _neg(self.x1), _neg(self.x2))

    def __sub__(self, o):
        return self + (-o)

    def __mul__(self, o):
        if isinstance(o, Taylor):
            return _product(_mul, self, o)
        return Taylor(self.x0 * o, _times(_mul, self.x1, o), _times(_mul, self.x2, o))

    __rmul__ = __mul__


def _product(f, u: Taylor, v: Taylor) -> Taylor:
    """The jet of a bilinear product f (*, dot, cross): Leibniz's rule to second order."""
    twice = _times(f, u.x1, v.x1)
    return Taylor(f(u.x0, v.x0), _sum(_times(f, u.x1, v.x0), _times(f, u.x0, v.x1)),
                   _sum(_times(f, u.x2, v.x0), None if twice is None else 2 * twice, _times(f, u.x0, v.x2)))


def tdiv(x: Taylor, y: Taylor) -> Taylor:
    """x / y of two jets (the quotient rule to second order; beyond the paper: docs/machine.md, MG4)."""
    z0 = x.x0 / y.x0
    z1 = _times(_mul, _sum(x.x1, _neg(_times(_mul, z0, y.x1))), 1.0 / y.x0)
    two = _times(_mul, z1, y.x1)
    z2 = _sum(x.x2, None if two is None else -2 * two, _neg(_times(_mul, z0, y.x2)))
    return Taylor(z0, z1, _times(_mul, z2, 1.0 / y.x0))


def tsqrt(x: Taylor) -> Taylor:
    """sqrt(x) of a jet (beyond the paper: docs/machine.md, MG4)."""
    s0 = np.sqrt(x.x0)
    s1 = _times(_mul, x.x1, 0.5 / s0)
    sq = _times(_mul, s1, s1)
    return Taylor(s0, s1, _times(_mul, _sum(x.x2, None if sq is None else -2 * sq), 0.5 / s0))


def tdot(u: Taylor, v: Taylor) -> Taylor:
    """u . v of two vector jets (Leibniz's rule; beyond the paper: docs/machine.md, MG4)."""
    return _product(_dot, u, v)


def tcross(u: Taylor, v: Taylor) -> Taylor:
    """u x v of two vector jets (Leibniz's rule; beyond the paper: docs/machine.md, MG4)."""
    return _product(_cross, u, v)


def tunit(v: Taylor) -> Taylor:
    """v / |v| of a vector jet (beyond the paper: docs/machine.md, MG4)."""
    return tdiv(v, tsqrt(tdot(v, v)))


def tcos_sin(phi: Taylor):
    """(cos phi, sin phi) of an angle's jet (beyond the paper: docs/machine.md, MG4)."""
    c, s = np.cos(phi.x0), np.sin(phi.x0)
    p1, p2 = phi.x1, phi.x2
    sq = _times(_mul, p1, p1)
    return (Taylor(c, _times(_mul, -s, p1), _sum(_times(_mul, -s, p2), _times(_mul, -c, sq))),
            Taylor(s, _times(_mul, c, p1), _sum(_times(_mul, c, p2), _times(_mul, -s, sq))))


def with_coefficient(jet: Taylor, order: int, extra) -> Taylor:
    """``jet`` with ``extra`` added to its coefficient of ``order`` (1 or 2; beyond the paper: docs/machine.md, MG4)."""
    if order == 1:
        return Taylor(jet.x0, _sum(jet.x1, extra), jet.x2)
    return Taylor(jet.x0, jet.x1, _sum(jet.x2, extra))


def component(v: Taylor, i: int) -> Taylor:
    """The scalar jet of a vector jet's component ``i`` (its leading axis; beyond the paper: docs/machine.md)."""
    return Taylor(v.x0[i], None if v.x1 is None else v.x1[i], None if v.x2 is None else v.x2[i])


def _stacked(parts):
    if any(x is None for x in parts):
        return None
    return np.stack(np.broadcast_arrays(*parts))


def stack(parts) -> Taylor:
    """The vector jet (a leading axis) of scalar jets, each coefficient
    broadcast against the others' (None where every part's is; beyond the
    paper: docs/machine.md)."""
    parts = list(parts)
    out = [_stacked([getattr(p, k) for p in parts]) for k in ("x0", "x1", "x2")]
    for k, name in ((1, "x1"), (2, "x2")):
        if out[k] is None and any(getattr(p, name) is not None for p in parts):
            zero = [getattr(p, name) if getattr(p, name) is not None else 0 * p.x0 for p in parts]
            out[k] = np.stack(np.broadcast_arrays(*zero))
    return Taylor(*out)
