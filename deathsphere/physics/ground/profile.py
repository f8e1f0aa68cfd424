"""Any surface of revolution, from samples of its meridian (beyond the paper;
docs/surfaces.md, "Profiles").

The meridian is interpolated as a parametric cubic spline, rho(s) and z(s)
over the cumulative chord length s between the samples (scipy's
``CubicSpline``, not-a-knot ends): its slope and curvature are continuous,
and, unlike a spline of rho(z), it stays well conditioned where the wall
is nearly flat (the bottom of a bowl, whose meridian leaves the axis
horizontally).  A lane is given by its height, so z must rise along the
meridian: strictly from sample to sample, and the interpolated z(s) too
(checked on a fine table, so that a lane's height names one parallel).
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.ground.protocol import as_array

__all__ = ["Profile", "ProfileError", "KINK_DEG", "MIN_POINTS"]

#: The largest turn of the tangent [deg] between neighbouring chords: a
#: sharper corner is a kink, whose curvature the spline would smear into a
#: spike (a lane there would see a wall that is not the one sampled).
KINK_DEG = 30.0
#: The fewest samples of a meridian (a cubic needs four).
MIN_POINTS = 4
#: Samples of the fine table per interval between two rows (the inverse of
#: z(s) and the nearest point of the meridian start from it; Newton's
#: method then converges in a few steps).
_FINE = 32
_NEWTON = 4


def _length(a, b):
    """|(a, b)|: hypot for real numbers, sqrt(a^2 + b^2), analytic, for a complex step."""
    if np.iscomplexobj(a) or np.iscomplexobj(b):
        return np.sqrt(a * a + b * b)
    return np.hypot(a, b)


class ProfileError(ValueError):
    """Samples that are not a meridian a lane can be found on; the message
    is one line naming the row (the physics raises no API error: the
    readers and :func:`deathsphere.requests.arena.arena` turn it into the
    ParameterError of the option or file that gave the samples)."""


def _refuse(message: str):
    raise ProfileError(f"profile: {message}")


class Profile:
    """A surface of revolution about the z-axis whose meridian passes
    through the samples ``(rho[i], z[i])`` [m] (rho >= 0 from the axis, z
    up, from the lowest point upwards); the inside is the side the
    meridian's normal (-sin beta, cos beta) points to (a bowl's or a
    drum's interior).  A lane's height is z - z[0], from 0 to
    ``highest_lane`` = z[-1] - z[0].  Refuses, naming the row (1 = the
    first sample): fewer than :data:`MIN_POINTS` samples, a value that is
    not finite, a negative rho, z not rising strictly, a kink (the
    tangent turning by more than :data:`KINK_DEG` between neighbouring
    chords), or an interpolated meridian that turns down between rows."""

    name = "profile"
    #: S4 and S7 decide the fit only near the contact: the rim and the ball
    #: are checked against the whole meridian (docs/surfaces.md, S4g).
    local_fit_is_global = False

    def __init__(self, rho, z):
        from scipy.interpolate import CubicSpline

        rho, z = np.asarray(rho, dtype=float).reshape(-1), np.asarray(z, dtype=float).reshape(-1)
        if rho.size != z.size:
            _refuse(f"rho and z must have the same number of values (got {rho.size} and {z.size})")
        if rho.size < MIN_POINTS:
            _refuse(f"a meridian needs at least {MIN_POINTS} points (got {rho.size})")
        bad = ~(np.isfinite(rho) & np.isfinite(z))
        if bad.any():
            _refuse(f"row {np.flatnonzero(bad)[0] + 1}: rho and z must be finite numbers")
        if (rho < 0).any():
            i = np.flatnonzero(rho < 0)[0]
            _refuse(f"row {i + 1}: rho is the distance from the axis, >= 0 (got {rho[i]:g})")
        dz = np.diff(z)
        if (dz <= 0).any():
            i = np.flatnonzero(dz <= 0)[0] + 1
            _refuse(f"row {i + 1}: z must rise strictly from row to row, a lane being its height "
                    f"(got {z[i]:g} after {z[i - 1]:g})")
        chord = np.hypot(np.diff(rho), dz)
        heading = np.arctan2(dz, np.diff(rho))
        turn = np.degrees(np.abs(np.diff(heading)))
        if (turn > KINK_DEG).any():
            i = np.flatnonzero(turn > KINK_DEG)[0] + 1
            _refuse(f"row {i + 1}: the meridian turns by {turn[i - 1]:.3g} deg there, a kink (at most "
                    f"{KINK_DEG:g} deg between neighbouring segments; sample the bend more finely)")
        s = np.concatenate(([0.0], np.cumsum(chord)))
        self.rho_samples, self.z_samples = rho, z
        self._spline = CubicSpline(s, np.column_stack((rho, z)))
        self._d1, self._d2 = self._spline.derivative(1), self._spline.derivative(2)
        # the spline with its derivatives as one piecewise cubic of six columns
        # (rho, z, rho', z', rho'', z''), and z with z' as one of two: each
        # evaluated in one pass over the lanes (the interval found once)
        from scipy.interpolate import PPoly

        c = self._spline.c                                   # (4, m, 2): t^3, t^2, t, 1
        zero = np.zeros_like(c[0])
        slope = np.stack((zero, 3 * c[0], 2 * c[1], c[2]))
        bend = np.stack((zero, zero, 6 * c[0], 2 * c[1]))
        self._all = PPoly(np.concatenate((c, slope, bend), axis=2), s)
        self._z_dz = PPoly(np.stack((c[..., 1], slope[..., 1]), axis=2), s)
        self._s_end = float(s[-1])
        fine = np.concatenate([np.linspace(s[i], s[i + 1], _FINE, endpoint=False) for i in range(s.size - 1)]
                              + [s[-1:]])
        points = self._spline(fine)
        # the bottom of a bowl leaves the axis flat: z may rise from it only
        # to second order, and rho may dip below 0 by round-off
        rising = np.diff(points[:, 1]) > 0
        crossing = points[1:, 0] < -1e-9 * self._s_end
        if not rising.all() or crossing.any():
            j = int(np.searchsorted(s, fine[np.flatnonzero(~rising | crossing)[0]], side="right"))
            _refuse(f"between rows {j} and {j + 1} the interpolated meridian turns down or crosses the axis "
                    "(sample it more finely there)")
        self._fine_s, self._fine_rho, self._fine_z = fine, points[:, 0], points[:, 1]
        # max |z''| / min z' over the samples' fine table, for the stopping rule of Newton's method (_lane)
        dz_fine = np.abs(self._d1(fine)[:, 1])
        self._newton_scale = float(np.max(np.abs(self._d2(fine)[:, 1])) / max(np.min(dz_fine[dz_fine > 0]), 1e-300)
                                   if (dz_fine > 0).any() else np.inf)
        from scipy.spatial import cKDTree

        self._tree = cKDTree(points)
        from deathsphere.physics.ground.profile_arc import Arc

        # the meridian by arc length, and the spline in complex arithmetic (the two-wheeler's)
        self._arc = Arc(s, c)
        # the last lanes asked for and their spline values: a body's orbit asks
        # contact, normal, wall_angle and curvatures of the same heights in turn
        self._last = None
        self._last_nearest = None
        self._balls = None
        self._outward = None
        self._bend = None

    #: z of the lowest point [m].
    @property
    def lowest(self) -> float:
        return float(self.z_samples[0])

    @property
    def highest_lane(self) -> float:
        """The greatest height a lane can have [m] (the last sample's)."""
        return float(self.z_samples[-1] - self.z_samples[0])

    def __repr__(self) -> str:
        return f"Profile({self.rho_samples.size} points, rho {self.rho_samples.min():g}..{self.rho_samples.max():g} m, " \
               f"height {self.highest_lane:g} m)"

    # --- the meridian by its parameter -------------------------------------

    def _s_of_height(self, height):
        """The spline's parameter s at each height (z = lowest + height):
        a guess from the fine table, then Newton's method on z(s) (stopping
        once no step moves s by more than round-off); clipped to the
        meridian."""
        return self._lane(height)[0]

    def _lane(self, height):
        """(s, the point (rho, z), its first and second derivatives in s) at
        each height; the last heights' are kept (the same lanes are asked
        of every answer of an orbit in turn)."""
        height = np.asarray(height, dtype=float)
        last = self._last
        if last is not None and last[0].shape == height.shape and np.array_equal(last[0], height):
            return last[1]
        target = self.lowest + height
        s = np.interp(target, self._fine_z, self._fine_s)
        tol = 4 * np.finfo(float).eps * max(self._s_end, 1.0)
        for _ in range(_NEWTON):
            z_dz = self._z_dz(s)
            z, dz = z_dz[..., 0], z_dz[..., 1]
            ok = dz > 0
            step = np.where(ok, (z - target) / np.where(ok, dz, 1.0), 0.0)
            s = np.clip(s - step, 0.0, self._s_end)
            # Newton's error squares with each step: the next step would be
            # about (z'' / 2 z') step^2, below round-off once that is
            if not np.any(np.abs(step) * np.abs(step) * self._newton_scale > tol):
                break
        every = self._all(s)
        lane = (s, every[..., 0:2], every[..., 2:4], every[..., 4:6])
        self._last = (height.copy(), lane)
        return lane

    def _at(self, s):
        """(P, P', P'') at the spline's parameters s: scipy's, or for a complex s the same cubic by hand."""
        if np.iscomplexobj(s):
            return self._arc.derivatives(s)[:3]
        return self._spline(s), self._d1(s), self._d2(s)

    def _frame(self, s):
        d1 = self._at(s)[1]
        speed = _length(d1[..., 0], d1[..., 1])
        return d1[..., 0] / speed, d1[..., 1] / speed          # cos beta, sin beta

    def arc_length(self, height):
        """The meridian's arc length [m] from the lowest sample to the lane at ``height``."""
        return self._arc.length(self._lane(height)[0])

    def meridian(self, s):
        """The meridian at arc length ``s`` [m] from the lowest sample: (rho,
        z, beta, kappa, dkappa), kappa = d(beta)/ds, dkappa = d(kappa)/ds
        (the two-wheeler's generated equations take them; beyond the paper,
        docs/two-wheeler.md sec. 12; a complex step passes through)."""
        return self._arc.meridian(s)

    def contact(self, height):
        p = self._lane(height)[1]
        return np.maximum(p[..., 0], 0.0), p[..., 1]

    def wall_angle(self, height):
        d1 = self._lane(height)[2]
        return np.arctan2(d1[..., 1], d1[..., 0])

    def normal(self, height):
        d1 = self._lane(height)[2]
        speed = np.hypot(d1[..., 0], d1[..., 1])
        return -d1[..., 1] / speed, d1[..., 0] / speed

    def curvatures(self, height):
        _, p, d1, d2 = self._lane(height)
        speed = np.hypot(d1[..., 0], d1[..., 1])
        # d(beta)/ds: positive where the meridian bends towards the inside normal
        k_mer = (d1[..., 0] * d2[..., 1] - d1[..., 1] * d2[..., 0]) / speed ** 3
        rho = p[..., 0]
        on_axis = rho <= 1e-12 * max(self._s_end, 1.0)
        # Meusnier: sin(beta) / rho; on the axis the surface is umbilic
        k_par = np.where(on_axis, k_mer, d1[..., 1] / speed / np.where(on_axis, 1.0, rho))
        return k_mer, k_par

    # --- points off the surface ---------------------------------------------

    def _nearest(self, rho, z):
        """The parameter of the meridian's point nearest to each (rho, z):
        the fine table's nearest sample, then Newton's method on
        (P(s) - q) . P'(s) = 0 (for complex points, from the real parts'
        then in complex arithmetic)."""
        if np.iscomplexobj(rho) or np.iscomplexobj(z):
            rho, z = np.broadcast_arrays(np.asarray(rho, dtype=complex), np.asarray(z, dtype=complex))
            s, _ = self._nearest(rho.real, z.real)
            q = np.stack((rho, z), axis=-1)
            return self._arc.nearest(s + 0j, q), q
        rho, z = np.broadcast_arrays(np.asarray(rho, dtype=float), np.asarray(z, dtype=float))
        # the last points asked for: a contact's gradient and Hessian are asked of the same points in turn
        last = self._last_nearest
        if last is not None and last[0].shape == rho.shape and np.array_equal(last[0], rho) and np.array_equal(
                last[1], z):
            return last[2]
        out = self._nearest_real(rho, z)
        self._last_nearest = (rho.copy(), z.copy(), out)
        return out

    def _nearest_real(self, rho, z):
        q = np.stack((rho, z), axis=-1)
        _, index = self._tree.query(q.reshape(-1, 2))
        s = self._fine_s[index].reshape(rho.shape)
        for _ in range(_NEWTON):
            # the point and its two derivatives in one pass (the same numbers as three splines')
            every = self._all(s)
            p, d1, d2 = every[..., 0:2], every[..., 2:4], every[..., 4:6]
            diff = p - q
            f = np.sum(diff * d1, axis=-1)
            df = np.sum(d1 * d1, axis=-1) + np.sum(diff * d2, axis=-1)
            step = np.where(df > 0, f / np.where(df > 0, df, 1.0), 0.0)
            s = np.clip(s - step, 0.0, self._s_end)
        return s, q

    def tangent_ball_radius(self, height, outside=False):
        """The largest ball tangent to the wall at each lane that stays
        inside it (``outside``: outside it) [m], the lower of the table's
        two values about the lane (beyond the paper: docs/surfaces.md,
        S4g; :mod:`~deathsphere.physics.ground.profile_reach`)."""
        if self._balls is None:
            from deathsphere.physics.ground.profile_reach import tangent_ball_table

            def curvature(s):
                d1, d2 = self._d1(s), self._d2(s)
                return (d1[..., 0] * d2[..., 1] - d1[..., 1] * d2[..., 0]) / np.hypot(d1[..., 0], d1[..., 1]) ** 3

            self._balls = tangent_ball_table(self._spline, self._frame, curvature, self._s_end)
        s_table, r_in, r_out = self._balls
        s = self._lane(height)[0]
        step = s_table[1] - s_table[0]
        i = np.clip((s / step).astype(int), 0, s_table.size - 2)
        r = np.where(np.asarray(outside, dtype=bool), np.minimum(r_out[i], r_out[i + 1]),
                     np.minimum(r_in[i], r_in[i + 1]))
        return r

    def bend_bound(self):
        """A bound K [1/m] on the principal curvatures of the wall bending
        towards the inside (kappa_meridian, and sin(beta) / rho along the
        parallels): their largest on the fine table, a quarter added for
        the table's spacing (beyond the paper: docs/surfaces.md, S4g)."""
        if self._bend is None:
            d1, d2 = self._d1(self._fine_s), self._d2(self._fine_s)
            speed = np.hypot(d1[:, 0], d1[:, 1])
            k_mer = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / speed ** 3
            rho = self._fine_rho
            on_axis = rho <= 1e-9 * max(self._s_end, 1.0)
            k_par = np.where(on_axis, k_mer, d1[:, 1] / speed / np.where(on_axis, 1.0, rho))
            self._bend = 1.25 * float(max(np.max(k_mer), np.max(k_par), 0.0))
        return self._bend

    def bends_out(self, z_low, z_high):
        """Whether the meridian bends away from the inside (kappa_meridian
        <= 0, on the fine table) everywhere between the heights z_low and
        z_high [m] (the profile's own z; clipped to the wall; the table's
        points bracketing the range included): there the wall lies on the
        outer side of each of its tangent lines, so it holds whatever its
        tangent cone holds (beyond the paper: docs/surfaces.md, S4g)."""
        if self._outward is None:
            d1, d2 = self._d1(self._fine_s), self._d2(self._fine_s)
            bends_in = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) > 0
            self._outward = np.concatenate(([0], np.cumsum(bends_in)))
        lo = np.clip(np.searchsorted(self._fine_z, z_low, side="right") - 1, 0, self._fine_z.size - 1)
        hi = np.clip(np.searchsorted(self._fine_z, z_high, side="left"), 0, self._fine_z.size - 1)
        return self._outward[hi + 1] - self._outward[lo] == 0

    def offset(self, t):
        """The parallel surface a distance ``t`` [m] inside: the surface of
        revolution whose meridian is this one moved by t along its inward
        normal, evaluated from the spline itself
        (:class:`~deathsphere.physics.ground.profile_offset.ParallelProfile`;
        beyond the paper: docs/machine.md, "On a profile")."""
        from deathsphere.physics.ground.profile_offset import ParallelProfile

        return ParallelProfile(self, t)

    def spline_parameter(self, height):
        """The spline's chord parameter s of the lane at each ``height`` [m]."""
        return self._lane(height)[0]

    def spline_derivatives(self, s):
        """The spline and its first three derivatives at its chord parameter
        s (..., 2 each: rho, z), real or complex (a complex step passes
        through)."""
        return self._arc.derivatives(s)

    def knot_index(self, rho, z):
        """Where the foot of each (rho, z) on the meridian lies among the
        spline's knots (its samples): k at the k-th, linear between; the
        meridian's curvature is continuous there but its rate of change
        jumps (so an integration restarts at a whole number: docs/simulation.md)."""
        s = self.foot(rho, z)
        return np.interp(s, self._spline.x, np.arange(self._spline.x.size, dtype=float))

    def foot(self, rho, z):
        """The spline parameter of the meridian's point nearest to each (rho, z) (clipped to the meridian)."""
        return self._nearest(rho, z)[0]

    def clearance(self, rho, z):
        """A point's distance [m] from the interpolated meridian, positive
        on the inside: (q - P) . n at the nearest point P (past an end, the
        distance from the end's tangent line)."""
        s, q = self._nearest(rho, z)
        cos_b, sin_b = self._frame(s)
        diff = q - self._at(s)[0]
        return diff[..., 0] * -sin_b + diff[..., 1] * cos_b

    def implicit(self, x, y, z):
        """F = -clearance: the signed distance from the surface (F < 0 inside)."""
        x, y, z = np.broadcast_arrays(as_array(x), as_array(y), as_array(z))
        return -self.clearance(_length(x, y), z)

    def _radial(self, x, y):
        rho = _length(x, y)
        on_axis = rho == 0
        # on the axis the values are the limit along +x (as the cone's)
        return np.where(on_axis, 1.0, x / np.where(on_axis, 1.0, rho)), np.where(on_axis, 0.0, y / np.where(
            on_axis, 1.0, rho)), rho

    def gradient(self, x, y, z):
        """grad F = -n at the nearest point, lifted off the meridian plane:
        (sin beta rho-hat, -cos beta)."""
        x, y, z = np.broadcast_arrays(as_array(x), as_array(y), as_array(z))
        ux, uy, rho = self._radial(x, y)
        s, _ = self._nearest(rho, z)
        cos_b, sin_b = self._frame(s)
        return np.stack((sin_b * ux, sin_b * uy, -cos_b))

    def hessian(self, x, y, z):
        """The signed distance's second derivatives: kappa_m / (1 - c kappa_m)
        along the meridian's tangent (c the clearance, kappa_m the nearest
        point's meridian curvature), F_rho / rho = sin(beta) / rho along the
        parallel, 0 along the normal (docs/surfaces.md, "Profiles")."""
        x, y, z = np.broadcast_arrays(as_array(x), as_array(y), as_array(z))
        ux, uy, rho = self._radial(x, y)
        s, q = self._nearest(rho, z)
        p, d1, d2 = self._at(s)
        speed = _length(d1[..., 0], d1[..., 1])
        cos_b, sin_b = d1[..., 0] / speed, d1[..., 1] / speed
        k_mer = (d1[..., 0] * d2[..., 1] - d1[..., 1] * d2[..., 0]) / speed ** 3
        diff = q - p
        c = diff[..., 0] * -sin_b + diff[..., 1] * cos_b
        along = k_mer / (1.0 - c * k_mer)
        around = np.where(rho != 0, sin_b / np.where(rho != 0, rho, 1.0), along)
        t = np.stack((cos_b * ux, cos_b * uy, sin_b))
        phi = np.stack((-uy, ux, np.zeros_like(ux)))
        return along * t[:, None] * t[None, :] + around * phi[:, None] * phi[None, :]

