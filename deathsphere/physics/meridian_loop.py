"""The closed curve of a vertical loop inside a surface of revolution: the
meridian of a ground that meets the axis at its lowest and its highest
point, and its mirror through the axis (beyond the paper: docs/surfaces.md,
"S9-S12. A vertical loop inside a closed profile").

:func:`loop_closure` says whether a ground has one; :class:`Loop` samples
its half (the meridian, by arc length from the bottom) once, for every
request of a command (:mod:`deathsphere.physics.vertical_orbit_on`);
:func:`turn` is the loop's angle phi = pi - beta from the top, the turn of
its tangent.  :func:`golden_max` and :func:`bisect_zero` refine a point of
it between the grid's, every request its own bracket, in one pass of
numpy per step; :func:`refined_max` and :func:`smooth_peak` find a
quantity's largest value and its peak per request, :func:`simpson` the
lap's quadrature (the wheel's loop and the machine's,
:mod:`deathsphere.physics.machine_loop_on`, share them).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Loop", "loop_closure", "turn", "golden_max", "bisect_zero", "refined_max", "smooth_peak", "simpson",
           "AXIS_TURN_DEG", "AXIS_TOL", "INTERVALS", "GOLDEN_STEPS", "BISECT_STEPS"]

#: Intervals of the loop's grid on its half (Simpson's rule on the lap time;
#: the brackets of the refined points).  The lap time's quadrature error at
#: this grid is 9e-11 of the lap, against a grid of 16384 intervals, on a
#: sampled sphere and an ellipsoid (docs/surfaces.md, "Numerics").
INTERVALS = 1024
#: Steps of the golden section (a bracket of two grid intervals shrinks by
#: 0.618 a step: 32 steps leave 4e-7 of it, and a smooth maximum's value is
#: off by the square of that) and of the bisection (2^-36 of its bracket).
GOLDEN_STEPS = 32
BISECT_STEPS = 36
#: The largest angle [deg] the meridian's tangent may make with the
#: horizontal where it meets the axis: more, and the loop's curve and its
#: mirror meet at a corner (a curvature without bound: no wheel fits).
AXIS_TURN_DEG = 0.5
_INV_PHI = (np.sqrt(5.0) - 1.0) / 2.0
#: A meridian's end is on the axis when its rho is this close to 0,
#: relative to the ground's size: a lane is found from its height, and at
#: a closed end z rises only to second order in s, so round-off in z moves
#: the point along the meridian by ~sqrt(eps) of the size.
AXIS_TOL = 1e-6


def loop_closure(ground) -> str:
    """Why ``ground`` has no closed meridian loop, in words, or "" if it has
    (beyond the paper: docs/surfaces.md, "S9-S12"):
    a profile's meridian (``meridian``, ``arc_length``, a finite
    ``highest_lane``) that starts and ends on the axis, its tangent there
    horizontal within :data:`AXIS_TURN_DEG` (so that the mirrored halves join
    without a corner)."""
    top = float(getattr(ground, "highest_lane", np.inf))
    if not np.isfinite(top) or not hasattr(ground, "meridian"):
        return f"the {ground.name}'s meridian does not close over the top"
    length = float(ground.arc_length(np.array(top)))
    rho, _, beta, _, _ = ground.meridian(np.array([0.0, length]))
    tol = AXIS_TOL * max(length, 1.0)
    if rho[1] > tol:
        return f"the {ground.name}'s meridian ends {rho[1]:.6g} m from the axis: it does not close over the top"
    if rho[0] > tol:
        return (f"the {ground.name}'s meridian starts {rho[0]:.6g} m from the axis: the loop needs a meridian "
                "closed below as well (on the axis at its lowest point)")
    # the angles wrapped to (-pi, pi]: the top's beta is pi or -pi by round-off
    tilts = np.angle(np.exp(1j * np.array([beta[0], np.pi - beta[1]])))
    for end, angle in zip(("lowest", "highest"), tilts):
        if abs(np.degrees(angle)) > AXIS_TURN_DEG:
            return (f"the {ground.name}'s meridian meets the axis at its {end} point {abs(np.degrees(angle)):.3g} deg "
                    f"from the horizontal (at most {AXIS_TURN_DEG:g}): the loop and its mirror would meet at a corner")
    return ""


@dataclass(frozen=True)
class Loop:
    """The loop's half (the meridian) sampled once by arc length, bottom (s
    = 0) to top (s = ``length``): ``s``, ``z``, ``beta``, ``kappa`` on
    :data:`INTERVALS` + 1 points, ``kappa_max`` the curve's largest
    curvature (refined between the grid's points), ``height`` the top's
    height above the bottom.  Build it with :meth:`of`."""

    ground: object
    length: float
    s: np.ndarray
    z: np.ndarray
    beta: np.ndarray
    kappa: np.ndarray
    kappa_max: float
    height: float

    @classmethod
    def of(cls, ground, intervals: int = INTERVALS) -> "Loop":
        """The loop of ``ground`` (:func:`loop_closure` must say ""), on a grid of ``intervals`` (even)."""
        intervals = int(intervals) + int(intervals) % 2            # Simpson's rule takes pairs
        length = float(ground.arc_length(np.array(float(ground.highest_lane))))
        s = np.linspace(0.0, length, intervals + 1)
        _, z, beta, kappa, _ = ground.meridian(s)
        beta = np.unwrap(beta)                                      # 0 at the bottom to pi at the top
        i = int(np.argmax(kappa))
        lo, hi = s[max(i - 1, 0)], s[min(i + 1, intervals)]
        s_max = golden_max(lambda x: ground.meridian(x)[3], np.array(lo), np.array(hi))
        kappa_max = max(float(np.max(kappa)), float(ground.meridian(s_max)[3]))
        return cls(ground, length, s, z, beta, kappa, kappa_max, float(ground.highest_lane))

    @property
    def turns_one_way(self) -> bool:
        """True where the meridian bends one way all along (kappa > 0 on the
        grid): the loop's angle phi = pi - beta then names one point."""
        return bool(np.all(self.kappa > 0))

    def meridian(self, s):
        """(z, beta, kappa) at arc lengths s (any shape) [m, rad, 1/m]."""
        _, z, beta, kappa, _ = self.ground.meridian(np.asarray(s, dtype=float))
        return z, beta, kappa

    def arc_at(self, phi):
        """(Beyond the paper: docs/surfaces.md, "S9-S12".)  The arc length s of the loop's point at angle phi [rad] from the top
        (0..2 pi; past pi its mirror on the descent), where pi - beta(s) = phi:
        from the grid, then bisection on the spline.  phi names one point where
        the meridian bends one way (:attr:`turns_one_way`)."""
        phi = np.mod(np.asarray(phi, dtype=float), 2.0 * np.pi)
        descent = np.where(phi <= np.pi, phi, 2.0 * np.pi - phi)     # the mirror point's angle
        on_grid = turn(self.beta)                                     # falling from pi (bottom) to 0 (top) with s
        guess = np.interp(descent, on_grid[::-1], self.s[::-1])
        h = self.s[1] - self.s[0]
        s = bisect_zero(lambda x: descent - turn(self.meridian(x)[1]), np.clip(guess - 2 * h, 0.0, self.length),
                        np.clip(guess + 2 * h, 0.0, self.length))
        return np.where(descent >= on_grid[0], 0.0, np.where(descent <= on_grid[-1], self.length, s))


def turn(beta):
    """The loop's angle phi = pi - beta [rad] from the top (beyond the paper:
    docs/surfaces.md, "S9-S12"; the globe's azimuth phi of eq. 27 on a
    circle), on the descent 0 (top) .. pi (bottom): wrapped so that a wall
    angle given as -pi at the top (the same tangent as pi) is the top, not a
    full turn."""
    return np.mod(np.pi - np.asarray(beta, dtype=float) + np.pi / 2, 2 * np.pi) - np.pi / 2


def golden_max(f, lo, hi, steps: int = GOLDEN_STEPS):
    """The argument of f's largest value in [lo, hi], each element its own
    bracket (f unimodal there), by golden section (beyond the paper: the
    loop's refined points, docs/surfaces.md, "S9-S12", "Numerics")."""
    lo, hi = np.array(lo, dtype=float), np.array(hi, dtype=float)
    x1 = hi - _INV_PHI * (hi - lo)
    x2 = lo + _INV_PHI * (hi - lo)
    f1, f2 = f(x1), f(x2)
    for _ in range(steps):
        left = f1 >= f2                              # the largest value is in [lo, x2]
        hi = np.where(left, x2, hi)
        lo = np.where(left, lo, x1)
        x1n = np.where(left, hi - _INV_PHI * (hi - lo), x2)
        x2n = np.where(left, x1, lo + _INV_PHI * (hi - lo))
        x1, x2 = x1n, x2n
        new = np.where(left, x1, x2)
        f_new = f(new)
        f1, f2 = np.where(left, f_new, f2), np.where(left, f1, f_new)
    return 0.5 * (lo + hi)


def bisect_zero(f, lo, hi, steps: int = BISECT_STEPS):
    """A zero of f between lo (f <= 0) and hi (f > 0), each element its own
    bracket, by bisection (beyond the paper: docs/surfaces.md, "S9-S12",
    "Numerics")."""
    lo, hi = np.array(lo, dtype=float), np.array(hi, dtype=float)
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        up = f(mid) > 0
        hi, lo = np.where(up, mid, hi), np.where(up, lo, mid)
    return 0.5 * (lo + hi)


def refined_max(loop: Loop, values, at):
    """Per row, where a smooth quantity of the loop is largest (beyond the
    paper: the loop's refined points, docs/surfaces.md, "Numerics"):
    ``values`` its values on the loop's grid (rows x grid, no NaN),
    ``at(rows, s)`` its values for those rows at arc lengths s (rows x m).
    The grid's largest, refined by golden section on the curve between its
    neighbours when it is not at an end (the top and the bottom are points
    of the loop's mirror symmetry, where a smooth quantity is stationary:
    there the grid's point is the answer).  Returns (s, value) per row."""
    values = np.asarray(values, dtype=float)
    i = np.argmax(values, axis=1)
    last = loop.s.size - 1
    s = loop.s[i].astype(float)
    best = values[np.arange(values.shape[0]), i]
    inner = np.flatnonzero((i > 0) & (i < last))
    if inner.size:
        def f(x):
            return at(inner, x)

        refined = golden_max(f, loop.s[i[inner] - 1][:, None], loop.s[i[inner] + 1][:, None])[:, 0]
        value = f(refined[:, None])[:, 0]
        better = value > best[inner]                   # else the grid's point stays
        s[inner] = np.where(better, refined, s[inner])
        best[inner] = np.where(better, value, best[inner])
    return s, best


def simpson(y, h):
    """Simpson's rule over the last axis (an even number of intervals of
    width h; beyond the paper: the loop's lap time, docs/surfaces.md eq. S12)."""
    return h / 3.0 * (y[..., 0] + y[..., -1] + 4.0 * y[..., 1:-1:2].sum(axis=-1) + 2.0 * y[..., 2:-1:2].sum(axis=-1))


#: :func:`smooth_peak`'s fit: a polynomial of this degree over at most
#: :data:`_PEAK_WINDOW` grid intervals each side of the grid's largest value
#: and :data:`_PEAK_SHARE` of the peak's half-width, at least
#: :data:`_PEAK_LEAST` (a sharper peak is refined on the curve itself).
_PEAK_DEGREE = 8
_PEAK_WINDOW = 64
_PEAK_SHARE = 0.6
_PEAK_LEAST = 6


def smooth_peak(loop: Loop, values: np.ndarray, at) -> np.ndarray:
    """Per row, the arc length where ``values`` (rows x grid: the grid's
    values of a smooth function of s with one peak in the half-loop or at
    its ends; ``at(rows, s)`` its values for those rows at arc lengths s,
    rows x m) peaks (beyond the paper: docs/surfaces.md, "Numerics").

    A spline's curvature ripples at the spacing of its samples (by ~2e-7 of
    itself on a sphere sampled at 2001 points), and the argument of a flat
    maximum moves by about the square root of that: a least-squares
    polynomial (:data:`_PEAK_DEGREE`) over a window of the grid about the
    grid's largest value averages the ripple out.  The window spans
    :data:`_PEAK_SHARE` of the peak's half-width sqrt(f / |f''|) (from the
    grid's second difference), at most :data:`_PEAK_WINDOW` intervals each
    side; a peak too sharp for :data:`_PEAK_LEAST` intervals (a wheel near
    its least top speed, its worst point near the top) is refined by golden
    section on the curve itself, where the ripple matters less (f'' / f is
    large).  The loop's mirror through the axis continues the grid past
    either end (the top and the bottom are points of symmetry)."""
    n, last = values.shape[0], loop.s.size - 1
    h = loop.s[1] - loop.s[0]
    i = np.argmax(values, axis=1)
    rows = np.arange(n)

    def mirrored(j):
        j = np.abs(j)
        return np.where(j > last, 2 * last - j, j)

    f0 = values[rows, i]
    f2 = (values[rows, mirrored(i + 1)] - 2 * f0 + values[rows, mirrored(i - 1)]) / h ** 2
    curved = f2 < 0
    width = np.sqrt(np.where(curved, f0, 1.0) / np.where(curved, -f2, 1.0)) / h    # half-width [intervals]
    half = np.where(curved, np.minimum(np.floor(_PEAK_SHARE * width), _PEAK_WINDOW), _PEAK_WINDOW).astype(int)
    sharp = np.flatnonzero(half < _PEAK_LEAST)
    s_best = np.empty(n)
    if sharp.size:
        s_best[sharp] = refined_max(loop, values[sharp], lambda r, x: at(sharp[r], x))[0]
    fitted = np.flatnonzero(half >= _PEAK_LEAST)
    if fitted.size:
        s_best[fitted] = _fitted_peak(loop, values[fitted], i[fitted], half[fitted], mirrored)
    return s_best


def _fitted_peak(loop: Loop, values, i, half, mirrored):
    """:func:`_peak`'s least-squares fit, every row at once: a Chebyshev
    series of degree :data:`_PEAK_DEGREE` in u = (j - i) / half over the
    row's window |j - i| <= half (weights 1 inside, 0 outside, on the widest
    window's offsets), its stationary point nearest u = 0 by Newton's
    method.  Returns the arc lengths."""
    from numpy.polynomial import chebyshev

    h = loop.s[1] - loop.s[0]
    offsets = np.arange(-_PEAK_WINDOW, _PEAK_WINDOW + 1)
    u = offsets[None, :] / half[:, None]                        # (rows, offsets)
    inside = (np.abs(u) <= 1.0).astype(float)
    basis = chebyshev.chebvander(np.clip(u, -1.0, 1.0), _PEAK_DEGREE)         # (rows, offsets, degree + 1)
    window = values[np.arange(values.shape[0])[:, None], mirrored(i[:, None] + offsets[None, :])]
    normal = np.einsum("rj,rjp,rjq->rpq", inside, basis, basis)
    rhs = np.einsum("rj,rjp,rj->rp", inside, basis, window)
    c = np.linalg.solve(normal, rhs[..., None])[..., 0].T         # (degree + 1, rows): a series per row
    d1, d2 = chebyshev.chebder(c, 1), chebyshev.chebder(c, 2)
    x = np.zeros(values.shape[0])
    for _ in range(8):                                            # Newton's steps from the grid's largest
        slope, bend = chebyshev.chebval(x, d1, tensor=False), chebyshev.chebval(x, d2, tensor=False)
        x = np.clip(x - np.where(bend < 0, slope / np.where(bend < 0, bend, -1.0), 0.0), -1.0, 1.0)
    s = loop.s[i] + x * half * h
    # past an end: the mirror image of the point (the same point of the loop's other half)
    return np.where(s > loop.length, 2 * loop.length - s, np.abs(s))
