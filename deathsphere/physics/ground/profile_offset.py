"""The parallel surface of a profile: the surface a distance t inside it
(beyond the paper; docs/machine.md, "On a profile", eqs. MP1-MP3).

A profile's meridian is the spline P(s) = (rho(s), z(s)) over its chord
parameter s, with the inward unit normal n(s) = (-z', rho') / |P'|.  The
parallel meridian at distance t is

    Q(s) = P(s) + t n(s)                                      (MP1)

exact for any meridian, and its normal at s is n(s) again (Q' = P' (1 -
t kappa) is parallel to P'), so the two meridians share their normal
lines: a point's foot on the parallel meridian is its foot on the profile,
the s that solves (q - P(s)) . P'(s) = 0 (MP2), and its distance inside
the parallel surface is (q - P(s)) . n(s) - t.  Everything is evaluated
from the profile's own cubic pieces (no resampled curve), in complex
arithmetic too (a complex step passes through), valid where t is below
the meridian's radius of curvature on the inside (t kappa < 1, where the
parallel meridian has no cusp).
"""

from __future__ import annotations

import numpy as np

__all__ = ["ParallelProfile", "FOOT_STEPS"]

#: Newton steps at most for a foot (MP2).  From a foot close by (the last
#: one, or the profile's own nearest point) the steps converge
#: quadratically; the loop stops once a step is at round-off (after one
#: more in complex arithmetic, which makes the complex step's part exact).
FOOT_STEPS = 8


def _length(a, b):
    """|(a, b)|, analytic for a complex step."""
    return np.sqrt(a * a + b * b)


class ParallelProfile:
    """The parallel surface a distance ``t`` [m] inside ``profile`` (MP1-MP3;
    ``t`` broadcasts against the points asked of it, one tyre radius per
    body).  Its points by the profile's spline parameter s, the foot of any
    point, and a point's distance inside it."""

    name = "parallel profile"

    def __init__(self, profile, t):
        self.profile = profile
        self.t = np.asarray(t, dtype=float)
        self._tol = 4 * np.finfo(float).eps * max(float(profile._s_end), 1.0)
        self._last_real = None

    def derivatives(self, s):
        """(P, P', P'', P''') of the profile's spline at s (..., 2 each: rho, z; real or complex s)."""
        return self.profile.spline_derivatives(s)

    def point(self, s):
        """Q(s) = P(s) + t n(s) (MP1): (rho, z) of the parallel meridian at the spline's parameter s."""
        p, d1 = self.derivatives(s)[:2]
        speed = _length(d1[..., 0], d1[..., 1])
        return p[..., 0] - self.t * d1[..., 1] / speed, p[..., 1] + self.t * d1[..., 0] / speed

    def contact(self, height):
        """(rho, z) of the parallel surface over the profile's lane at ``height`` [m] (along its normal)."""
        return self.point(self.profile.spline_parameter(height))

    def foot(self, rho, z, start=None):
        """The spline parameter of the foot of each point (rho, z) (MP2):
        Newton's method on (q - P(s)) . P'(s) = 0 from ``start`` (default:
        the profile's nearest point of its real part), in complex
        arithmetic where the point is complex."""
        return self.foot_and_derivatives(rho, z, start)[0]

    def foot_and_derivatives(self, rho, z, start=None):
        """(s, the spline's derivatives at s, as :meth:`derivatives`) of the
        foot of each point (rho, z) (:meth:`foot`; the derivatives at the
        foot come with it, for the normal's jets there)."""
        rho, z = np.asarray(rho), np.asarray(z)
        complex_step = np.iscomplexobj(rho) or np.iscomplexobj(z)
        if start is None:
            start = self._real_foot(np.real(rho), np.real(z))
        s = start + (0j if complex_step else 0.0)
        for i in range(FOOT_STEPS):
            every = self.profile.spline_derivatives(s)
            p, d1, d2, _ = every
            dr, dz = p[..., 0] - rho, p[..., 1] - z
            f = dr * d1[..., 0] + dz * d1[..., 1]
            df = d1[..., 0] * d1[..., 0] + d1[..., 1] * d1[..., 1] + dr * d2[..., 0] + dz * d2[..., 1]
            step = f / df
            # quadratic convergence: once a step is at round-off, s is the foot to round-off (a real
            # point keeps the s its derivatives were evaluated at; a complex step's part needs the step)
            if not np.any(np.abs(step) > self._tol):
                if not complex_step:
                    return s, every
                if i > 0:
                    s = s - step
                    return s, self.derivatives(s)
            s = s - step
        return s, self.derivatives(s)

    def _real_foot(self, rho, z):
        """The profile's nearest point of each real point; the last answer
        reused where these points are the last ones broadcast, to within
        round-off (a complex step's real parts are the real state's, once
        per direction)."""
        last = self._last_real
        if last is not None:
            try:
                # a start only (Newton's steps follow): the same points to well within the steps' reach
                near = self._tol * 1e3
                same = (np.max(np.abs(np.broadcast_to(last[0], rho.shape) - rho), initial=0.0) < near
                        and np.max(np.abs(np.broadcast_to(last[1], z.shape) - z), initial=0.0) < near)
            except ValueError:
                same = False
            if same:
                return np.broadcast_to(last[2], rho.shape)
        s = self.profile.foot(rho, z)
        self._last_real = (rho, z, s)
        return s

    def clearance(self, rho, z, foot=None):
        """A point's distance [m] inside the parallel surface (MP3):
        (q - P(s)) . n(s) - t at its foot s."""
        s = self.foot(rho, z) if foot is None else foot
        p, d1 = self.derivatives(s)[:2]
        speed = _length(d1[..., 0], d1[..., 1])
        return ((rho - p[..., 0]) * -d1[..., 1] + (z - p[..., 1]) * d1[..., 0]) / speed - self.t
