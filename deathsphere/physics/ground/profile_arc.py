"""A profile's meridian by its arc length, and its spline evaluated in
complex arithmetic (beyond the paper; docs/surfaces.md, "Profiles", and
docs/two-wheeler.md sec. 12).

The profile's spline (:class:`~deathsphere.physics.ground.profile.Profile`)
is parametrised by its chord length t, not its arc length s.  Here the
piecewise cubic is evaluated by hand from its coefficients, so that a
complex t (a complex step) passes through, and the arc length is its
speed's integral, S(t) = S(t_k) + the Gauss-Legendre sum over the piece
from its knot t_k to t (12 points: the speed of a piece without a kink is
a smooth function, integrated to rounding), inverted by Newton's method
(dS/dt is the speed), from the knots' arc lengths interpolated.  Derivatives in s follow from those in t divided by
the speed:

    beta = the angle of P', kappa = (rho' z'' - z' rho'') / v^3,
    dkappa/ds = [(rho' z''' - z' rho''') / v^3
                 - 3 (rho' z'' - z' rho'') (rho' rho'' + z' z'') / v^5] / v,

v = |P'|.  The angle is written with arctan (analytic) on the branch the
real parts pick, so that it too passes a complex step.
"""

from __future__ import annotations

import numpy as np

__all__ = ["Arc"]

#: Gauss-Legendre points per piece.
_GAUSS = 12
#: Newton steps for t(s) and for a point's nearest meridian point.
_NEWTON = 6


class Arc:
    """The piecewise cubic of breaks ``x`` (m + 1) and coefficients ``c``
    (4, m, 2: t^3 .. 1 per piece, columns rho and z), evaluated in real or
    complex arithmetic, with its arc length (beyond the paper;
    docs/two-wheeler.md sec. 12)."""

    def __init__(self, x, c):
        self.x, self.c = np.asarray(x, dtype=float), np.asarray(c, dtype=float)
        self._pieces = np.ascontiguousarray(self.c.transpose(1, 0, 2).reshape(self.c.shape[1], 8))
        self._nodes, self._weights = np.polynomial.legendre.leggauss(_GAUSS)
        pieces = np.arange(self.x.size - 1)
        self._knot_s = np.concatenate(([0.0], np.cumsum(self._piece_length(self.x[1:], pieces))))
        # the last arc lengths asked for and their meridian: a body's equations ask it of the same lane in turn
        self._last = None

    def piece(self, t):
        """The piece of each t, from its real part."""
        return np.clip(np.searchsorted(self.x, np.real(t), side="right") - 1, 0, self.x.size - 2)

    def derivatives(self, t, k=None):
        """(P, P', P'', P''') at t (..., 2 each: rho, z), on the pieces ``k`` (default: t's own)."""
        k = self.piece(t) if k is None else k
        dt = (t - self.x[k])[..., None]
        # one gather of the piece's four coefficients (of two columns each)
        every = self._pieces[k]
        a, b, c, d = every[..., 0:2], every[..., 2:4], every[..., 4:6], every[..., 6:8]
        return (((a * dt + b) * dt + c) * dt + d, (3 * a * dt + 2 * b) * dt + c, 6 * a * dt + 2 * b, 6 * a + 0 * dt)

    def _speed(self, t, k):
        d1 = self.derivatives(t, k)[1]
        return np.sqrt(d1[..., 0] * d1[..., 0] + d1[..., 1] * d1[..., 1])

    def _piece_length(self, t, k):
        """The arc length from piece k's knot to t along it (Gauss-Legendre)."""
        start = self.x[k]
        half = 0.5 * (t - start)
        tau = start[..., None] + half[..., None] * (1.0 + self._nodes)
        return half * np.sum(self._weights * self._speed(tau, k[..., None]), axis=-1)

    def length(self, t):
        """S(t): the meridian's arc length from its first point to t [m]."""
        t = np.asarray(t)
        k = self.piece(t)
        return self._knot_s[k] + self._piece_length(t, k)

    def parameter(self, s):
        """t(s): the spline's parameter at arc length s, by Newton's method from the fine table's guess."""
        s = np.asarray(s)
        # the first guess: the knots' arc lengths interpolated (the chord is within a few per cent of the arc)
        t = np.interp(np.real(s), self._knot_s, self.x) + 0 * s
        for _ in range(_NEWTON):
            k = self.piece(t)
            step = (self._knot_s[k] + self._piece_length(t, k) - s) / self._speed(t, k)
            t = t - step
            # quadratic convergence: once a step is 1e-8 of the length, the next is at rounding
            if not np.any(np.abs(step) > 1e-8 * max(float(self._knot_s[-1]), 1.0)):
                k = self.piece(t)
                return t - (self._knot_s[k] + self._piece_length(t, k) - s) / self._speed(t, k)
        return t

    def meridian(self, s):
        """(rho, z, beta, kappa, dkappa) at arc length s (docstring of the module)."""
        s = np.asarray(s)
        last = self._last
        if last is not None and last[0].shape == s.shape and last[0].dtype == s.dtype and np.array_equal(last[0], s):
            return last[1]
        out = self._meridian(s)
        self._last = (s.copy(), out)
        return out

    def _meridian(self, s):
        p, d1, d2, d3 = self.derivatives(self.parameter(s))
        r1, z1, r2, z2, r3, z3 = d1[..., 0], d1[..., 1], d2[..., 0], d2[..., 1], d3[..., 0], d3[..., 1]
        v = np.sqrt(r1 * r1 + z1 * z1)
        cross = r1 * z2 - z1 * r2
        kappa = cross / v ** 3
        dkappa = ((r1 * z3 - z1 * r3) / v ** 3 - 3 * cross * (r1 * r2 + z1 * z2) / v ** 5) / v
        return p[..., 0], p[..., 1], angle(r1, z1), kappa, dkappa

    def nearest(self, t, q):
        """Newton's steps on (P(t) - q) . P'(t) = 0 from t (complex arithmetic where q is complex)."""
        for _ in range(_NEWTON):
            p, d1, d2, _ = self.derivatives(t)
            diff = p - q
            f = np.sum(diff * d1, axis=-1)
            df = np.sum(d1 * d1, axis=-1) + np.sum(diff * d2, axis=-1)
            t = t - f / df
        return t


def angle(c, s):
    """The angle of the vector (c, s) from the first axis, as arctan2 for real
    vectors, and analytic (arctan on the branch the real parts pick) for
    complex ones."""
    if not (np.iscomplexobj(c) or np.iscomplexobj(s)):
        return np.arctan2(s, c)
    steep = np.abs(np.real(s)) > np.abs(np.real(c))
    flat_angle = np.arctan(s / np.where(steep, 1.0, c)) + np.where(np.real(c) < 0, np.where(np.real(s) < 0, -np.pi,
                                                                                           np.pi), 0.0)
    steep_angle = np.where(np.real(s) > 0, np.pi / 2, -np.pi / 2) - np.arctan(c / np.where(steep, s, 1.0))
    return np.where(steep, steep_angle, flat_angle)
