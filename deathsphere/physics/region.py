"""The allowed (theta, alpha) region of steady horizontal wheel orbits.

McDonald (1993), figure "alpha_wh" and sec. 2.2.2: for a wheel of radius a
inside a sphere of radius r (inertia factor k), a steady horizontal orbit at
polar angle theta and tilt alpha exists where the wheel fits, eq. (0),
Omega^2 of eq. (29) is positive, and the contact force presses the wheel
onto the wall, eq. (33); outside the sphere (sec. 3) the fit is eq. (81) and
the contact condition eq. (83).  This module computes the boundary curves of
that region, the intervals of alpha allowed at each theta (optionally also
limited by a friction coefficient mu and a largest load max_g on the rider,
load_g = sqrt(1 + accel_g^2): see :func:`centre_accel_limit`), the speed range
over each interval, the highest orbit possible, and every tilt alpha giving a
prescribed speed or rotation rate.

Method (docs/limits.md, beyond the paper).  Every boundary is the zero set of
a trigonometric polynomial in (theta, alpha): with C = cos(alpha),
S = sin(alpha), s = sin(theta), c = cos(theta), r' = r s - a C (eq. 8b) and
D = (2k+1) r' + k a C (the bracket of eq. 29),

=========================  ===============================  ==========
boundary                   function                         degree in alpha
=========================  ===============================  ==========
fit, eq. (0) / (81)        sin(theta - alpha) - a/r  /  sin(alpha - theta)   1
Omega^2 = 0 or pole (29)   C,  S,  D                        1 each
contact, eq. (33) / (83)   P_N = r' C s - c S D             2
friction, eq. (35)         P_F -+ mu P_N,  P_F = r' C c + s S D             2 each
load, eqs. (32), (36)      r' C -+ G S D, G = sqrt(max_g^2 - 1)   2 each
speed v_cm, eq. (29)       g r'^2 C - v^2 S D               3
=========================  ===============================  ==========

since Omega^2 = g C / (S D), normal force per mass = +-g P_N / (S D) and
F_theta / m = -g P_F / (S D) (eq. 32).  All their zeros are found by
:mod:`deathsphere.physics.trig_roots` (companion-matrix eigenvalues, then
bisection on sign changes: none of odd multiplicity can be missed).

Angles are in radians, lengths in metres, g in m/s^2, speeds in m/s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics.geometry import SINGULAR, r_prime, too_big_inside
from deathsphere.physics.status import Status
from deathsphere.physics.trig_roots import MERGE_TOL, TWO_PI, TrigPoly2, sorted_union
from deathsphere.physics.trig_roots import roots_in as _roots_in
from deathsphere.physics.wheel import horizontal_orbit, omega_squared_denominator

__all__ = [
    "AlphaIntervals",
    "HighestOrbit",
    "fit_interval",
    "alpha_window",
    "boundary_alphas",
    "boundary_thetas",
    "boundary_factors",
    "project_to_boundary",
    "allowed_alpha",
    "feasible",
    "highest_orbit",
    "solve_alpha",
]

def _basis(a, r, k):
    """The building blocks C, S, s, c, r', D, S D of the module docstring."""
    C = TrigPoly2([[0.5, 0.0, 0.5]])
    S = TrigPoly2([[0.5j, 0.0, -0.5j]])
    s = TrigPoly2([[0.5j], [0.0], [-0.5j]])
    c = TrigPoly2([[0.5], [0.0], [0.5]])
    rp = r * s - a * C
    D = (2 * k + 1) * rp + k * a * C
    return C, S, s, c, rp, D, S * D


def _functions(a, r, k, g, mu=np.inf, max_g=np.inf, outside=False):
    """Boundary functions whose zero sets bound the region (module docstring)."""
    C, S, s, c, rp, D, SD = _basis(a, r, k)
    fit = (S * c - C * s) if outside else (s * C - c * S - a / r)
    P_N = rp * C * s - c * SD
    out = {"eq0": [fit], "eq29": [C, S, D], "eq33": [P_N]}
    if np.isfinite(mu):
        P_F = rp * C * c + s * SD
        out["mu"] = [P_F - mu * P_N, P_F + mu * P_N]
    if np.isfinite(max_g):
        RC = rp * C
        accel = centre_accel_limit(max_g)
        out["max_g"] = [RC - accel * SD, RC + accel * SD]
    return out


# ---------------------------------------------------------------------------
# parameters
# ---------------------------------------------------------------------------

def _check(a, r, k, g, outside, mu=np.inf, max_g=np.inf):
    for name, val in (("a", a), ("r", r), ("k", k), ("g", g)):
        if not np.isscalar(val) and np.ndim(val) != 0:
            raise ValueError(f"{name} must be a scalar, got shape {np.shape(val)}")
        if not math.isfinite(float(val)):
            raise ValueError(f"{name} must be finite, got {val}")
    a, r, k, g = float(a), float(r), float(k), float(g)
    if a <= 0:
        raise ValueError(f"wheel radius a must be > 0, got {a}")
    if r <= 0:
        raise ValueError(f"sphere radius r must be > 0, got {r}")
    if too_big_inside(a, r, outside):
        raise ValueError(f"a wheel inside needs r > a, got a = {a}, r = {r}")
    if k < 0:
        raise ValueError(f"inertia factor k must be >= 0, got {k}")
    if g <= 0:
        raise ValueError(f"gravity g must be > 0, got {g}")
    mu, max_g = float(mu), float(max_g)
    if math.isnan(mu) or mu < 0:
        raise ValueError(f"friction coefficient mu must be >= 0 (inf: no limit), got {mu}")
    if math.isnan(max_g) or max_g <= 0:
        raise ValueError(f"max_g must be > 0 (inf: no limit), got {max_g}")
    return a, r, k, g, bool(outside), mu, max_g


def centre_accel_limit(max_g: float) -> float:
    """The centre's acceleration in g (eq. 36's accel_g) that a limit
    ``max_g`` on the load allows: the load a rider feels is |F| / (m g) =
    sqrt(1 + accel_g^2) on a horizontal orbit (eq. 32: F/m = g z-hat -
    r' Omega^2 r'-hat, two orthogonal parts), so load_g <= max_g is accel_g
    <= sqrt(max_g^2 - 1) (0 for max_g <= 1: every orbit's load exceeds 1).
    Beyond the paper; the region's limit curves and feasibility test take
    max_g through here (its two leaves, the one conversion), so
    that the region, ``limits`` and ``map`` limit the load ``orbit``
    reports (docs/limits.md)."""
    return math.inf if math.isinf(max_g) else math.sqrt(max(max_g * max_g - 1.0, 0.0))


def _theta_1d(theta):
    t = np.asarray(theta, dtype=float)
    if not np.all(np.isfinite(t)):
        raise ValueError("theta must be finite")
    return t, t.reshape(-1)


# ---------------------------------------------------------------------------
# public API
# ---------------------------------------------------------------------------

def fit_interval(theta, a, r, outside=False):
    """Open interval (lo, hi) of alpha in which the wheel fits [rad].

    Inside, eq. (0): theta - pi + asin(a/r) < alpha < theta - asin(a/r).
    Outside, eq. (81): theta < alpha < theta + pi.  Arrays broadcast with
    theta; every other tilt is these plus a multiple of 2 pi.
    """
    theta = np.asarray(theta, dtype=float)
    if outside:
        return theta.copy(), theta + np.pi
    e = math.asin(a / r)
    return theta - np.pi + e, theta - e


def alpha_window(theta, outside=False):
    """Default search window for alpha [rad], one full period containing the
    fit interval of eqs. (0)/(81) for 0 < theta < pi: [-pi, pi) inside,
    [0, 2 pi) outside (beyond the paper: a convention of this package)."""
    theta = np.asarray(theta, dtype=float)
    lo = np.full(theta.shape, 0.0 if outside else -np.pi)
    return lo, lo + TWO_PI


def boundary_alphas(theta, a, r, k, outside=False, mu=np.inf, max_g=np.inf, window=None):
    """Every alpha on each boundary curve of the allowed region, at each theta.

    Boundaries (McDonald 1993, figure "alpha_wh"): ``eq0`` fit, eq. (0)
    (eq. (81) outside); ``eq29`` where Omega^2 of eq. (29) changes sign
    (cos alpha = 0, sin alpha = 0, or (2k+1) r' + k a cos alpha = 0);
    ``eq33`` where the normal force of eq. (32) vanishes, the edge of
    eq. (33) (eq. (83) outside); with finite ``mu`` also ``mu``, where
    mu_required of eq. (35) equals mu, and with finite ``max_g``, ``max_g``
    where the load load_g equals max_g (these two: beyond the paper).

    ``mu`` and ``max_g`` curves are kept only where the orbit is real and in
    contact (elsewhere mu_required and the load are not physical).

    Parameters
    ----------
    theta : array_like, [rad]
    a, r : float, [m];  k : float, [-]
    window : (lo, hi) arrays broadcastable to theta, [rad], hi - lo <= 2 pi;
        default :func:`alpha_window`.

    Returns
    -------
    dict name -> float array of shape theta.shape + (m,), sorted along the
    last axis, NaN-padded; each alpha solves its equation to ~1e-14 rad.
    """
    a, r, k, _, outside, mu, max_g = _check(a, r, k, 1.0, outside, mu, max_g)
    t, t1 = _theta_1d(theta)
    lo, hi = alpha_window(t1, outside) if window is None else (
        np.broadcast_to(np.asarray(window[0], dtype=float), t.shape).reshape(-1),
        np.broadcast_to(np.asarray(window[1], dtype=float), t.shape).reshape(-1))
    n = t1.size
    out = {}
    for name, funcs in _functions(a, r, k, 1.0, mu, max_g, outside).items():
        roots = sorted_union([_roots_in(f.in_alpha(t1), lo, hi) for f in funcs], n)
        if name in ("mu", "max_g") and roots.size:
            orb = horizontal_orbit(t1[:, None], np.where(np.isfinite(roots), roots, 0.0),
                                   a, r, k, 1.0, outside)
            physical = np.isfinite(orb["normal"]) & (orb["normal"] > 0)
            roots = sorted_union([np.where(physical, roots, np.nan)], n)
        out[name] = roots.reshape(t.shape + (roots.shape[1],))
    return out


def boundary_thetas(alpha, a, r, k, outside=False, mu=np.inf, max_g=np.inf, window=(0.0, np.pi)):
    """Every theta on each boundary curve at each alpha: the companion of
    :func:`boundary_alphas` along lines of constant alpha -- the same
    boundaries, eqs. (0)/(81), (29), (33)/(83) and the mu (eq. 35) and load
    (eq. 36) limits, with the same names and NaN-padded layout -- for
    renderers that need the curves where they are steep in theta.  Default
    window: 0 <= theta <= pi [rad]."""
    a, r, k, _, outside, mu, max_g = _check(a, r, k, 1.0, outside, mu, max_g)
    al, a1 = _theta_1d(alpha)
    n = a1.size
    lo = np.broadcast_to(np.asarray(window[0], dtype=float), al.shape).reshape(-1)
    hi = np.broadcast_to(np.asarray(window[1], dtype=float), al.shape).reshape(-1)
    out = {}
    for name, funcs in _functions(a, r, k, 1.0, mu, max_g, outside).items():
        roots = sorted_union([_roots_in(f.in_theta(a1), lo, hi) for f in funcs], n)
        if name in ("mu", "max_g") and roots.size:
            orb = horizontal_orbit(np.where(np.isfinite(roots), roots, 1.0), a1[:, None],
                                   a, r, k, 1.0, outside)
            physical = np.isfinite(orb["normal"]) & (orb["normal"] > 0)
            roots = sorted_union([np.where(physical, roots, np.nan)], n)
        out[name] = roots.reshape(al.shape + (roots.shape[1],))
    return out


def boundary_factors(theta, alpha, a, r, k, outside=False, mu=np.inf, max_g=np.inf):
    """Values at (theta, alpha) of the functions whose zero sets are the
    boundaries (module docstring table), broadcast.

    Returns dict name -> list of arrays, one per factor: ``eq0`` [fit],
    ``eq29`` [cos alpha, sin alpha, D] (Omega^2 of eq. (29) has the sign of
    their product), ``eq33`` [P_N], ``mu`` [P_F - mu P_N, P_F + mu P_N],
    ``max_g`` [r' C - G S D, r' C + G S D].  For contouring renderers, with
    :func:`project_to_boundary` to put the contour's vertices on the curve.
    """
    a, r, k, _, outside, mu, max_g = _check(a, r, k, 1.0, outside, mu, max_g)
    return {name: [f(theta, alpha) for f in funcs]
            for name, funcs in _functions(a, r, k, 1.0, mu, max_g, outside).items()}


def project_to_boundary(name, factor, theta, alpha, a, r, k, outside=False, mu=np.inf,
                        max_g=np.inf, max_step=0.05, iterations=30):
    """Move points (theta, alpha) [rad] onto the zero set of one boundary
    factor (see :func:`boundary_factors`; eqs. (0), (29), (33), (35), (36))
    by Newton steps along the gradient, each step at most ``max_step`` rad.
    Beyond the paper: a rendering aid (docs/limits.md, sec. 7).

    Returns ``(theta, alpha, ok)``: ``ok`` is False where the iteration did
    not reach |f| <= 1e-13 |grad f| (the point is then left where it was).
    """
    a, r, k, _, outside, mu, max_g = _check(a, r, k, 1.0, outside, mu, max_g)
    f = _functions(a, r, k, 1.0, mu, max_g, outside)[name][factor]
    ft, fa = f.d_theta(), f.d_alpha()
    th0, al0 = np.broadcast_arrays(np.asarray(theta, dtype=float), np.asarray(alpha, dtype=float))
    th, al = th0.astype(float).copy(), al0.astype(float).copy()
    ok = np.zeros(th.shape, dtype=bool)
    for _ in range(iterations):
        val, gt, ga = f(th, al), ft(th, al), fa(th, al)
        g2 = gt * gt + ga * ga
        ok = np.abs(val) <= 1e-13 * np.sqrt(g2)
        if np.all(ok):
            break
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(g2 > 0, val / np.where(g2 > 0, g2, 1.0), 0.0)
        dt, da = -step * gt, -step * ga
        length = np.hypot(dt, da)
        shrink = np.where(length > max_step, max_step / np.where(length > 0, length, 1.0), 1.0)
        th = np.where(ok, th, th + shrink * dt)
        al = np.where(ok, al, al + shrink * da)
    th = np.where(ok, th, th0)
    al = np.where(ok, al, al0)
    return th, al, ok


@dataclass(frozen=True)
class AlphaIntervals:
    """Intervals of alpha giving a feasible orbit, per theta (rad, m/s).

    ``lo``, ``hi``, ``speed_min``, ``speed_max`` have shape theta.shape + (m,),
    NaN-padded beyond ``count`` (shape theta.shape).  Each interval is open,
    lo < alpha < hi; the speed v_cm = |r'| Omega ranges over the open interval
    (speed_min, speed_max) (inf where Omega diverges at an end; an end value is
    a bound, not attained).
    """

    theta: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    speed_min: np.ndarray
    speed_max: np.ndarray
    count: np.ndarray

    def intervals(self, index=()):
        """List of (lo, hi, speed_min, speed_max) tuples for one theta."""
        index = np.index_exp[index] if not isinstance(index, tuple) else index
        n = int(self.count[index])
        return [(float(self.lo[index][j]), float(self.hi[index][j]),
                 float(self.speed_min[index][j]), float(self.speed_max[index][j]))
                for j in range(n)]

    def contains(self, alpha):
        """True where alpha lies in an interval.  ``alpha`` has shape
        theta.shape, or theta.shape followed by more axes (several alphas
        per theta)."""
        alpha = np.asarray(alpha, dtype=float)
        extra = max(alpha.ndim - self.theta.ndim, 0)
        shape = self.theta.shape + (1,) * extra + self.lo.shape[-1:]
        lo, hi = self.lo.reshape(shape), self.hi.reshape(shape)
        inside = (alpha[..., None] > lo) & (alpha[..., None] < hi)
        return np.any(inside, axis=-1)


def _feasible_at(t, alpha, a, r, k, g, outside, mu, max_g):
    orb = horizontal_orbit(t, alpha, a, r, k, g, outside, mu)
    ok = orb["status"] == Status.OK
    if np.isfinite(max_g):
        ok &= orb["accel_g"] <= centre_accel_limit(max_g)
    return ok


def feasible(theta, alpha, a, r, k, g=STANDARD_GRAVITY, outside=False, mu=np.inf, max_g=np.inf):
    """True where (theta, alpha) is a feasible orbit: status ``ok`` of
    :func:`deathsphere.physics.wheel.horizontal_orbit` (eqs. (0)/(81), (29),
    (33)/(83), (35) with mu) and load load_g <= max_g."""
    a, r, k, g, outside, mu, max_g = _check(a, r, k, g, outside, mu, max_g)
    return _feasible_at(theta, alpha, a, r, k, g, outside, mu, max_g)


def _speed_sq(t, alpha, a, r, k, g):
    """v_cm^2 = g r'^2 cos(alpha) / (sin(alpha) D) (eq. 29), inf at a pole,
    clipped at 0."""
    rp = r_prime(t, alpha, a, r)
    den = omega_squared_denominator(t, alpha, a, r, k)
    num = g * rp * rp * np.cos(alpha)
    pole = np.abs(den) <= SINGULAR * ((2 * k + 1) * r + (k + 1) * a)
    with np.errstate(divide="ignore", invalid="ignore"):
        v2 = num / np.where(pole, 1.0, den)
    v2 = np.where(pole, np.inf, v2)
    return np.maximum(v2, 0.0)


def allowed_alpha(theta, a, r, k, g=STANDARD_GRAVITY, outside=False, mu=np.inf, max_g=np.inf):
    """Intervals of alpha where a steady horizontal orbit is feasible.

    Feasible means: the wheel fits (eq. (0); eq. (81) outside), Omega^2 of
    eq. (29) is > 0, the normal force is positive (eq. (33); eq. (83)
    outside), mu_required of eq. (35) <= ``mu`` and the load of eq. (36)
    <= ``max_g`` — exactly status ``ok`` of
    :func:`deathsphere.physics.wheel.horizontal_orbit` plus the load test.
    The limits mu and max_g are beyond the paper (docs/limits.md).

    Method: all crossings of every boundary inside the fit interval are
    found (module docstring); the fit interval is cut at them, each piece is
    tested at its midpoint and neighbouring feasible pieces are merged.  The
    speed range of a piece is taken over its ends and the interior zeros of
    d(v_cm^2)/d alpha.

    Parameters
    ----------
    theta : array_like, [rad];  a, r : float, [m];  k : float, [-];
    g : float, [m/s^2];  outside : bool;  mu : float, [-] (inf: no limit);
    max_g : float, [-] (inf: no limit).

    Returns
    -------
    AlphaIntervals (angles in rad, speeds in m/s).
    """
    a, r, k, g, outside, mu, max_g = _check(a, r, k, g, outside, mu, max_g)
    t, t1 = _theta_1d(theta)
    n = t1.size
    lo, hi = fit_interval(t1, a, r, outside)
    funcs = _functions(a, r, k, g, mu, max_g, outside)
    cuts = [_roots_in(f.in_alpha(t1), lo, hi)
            for name, fs in funcs.items() if name != "eq0" for f in fs]
    b = sorted_union([lo[:, None], hi[:, None]] + cuts, n)
    # merge coincident cuts, so that no zero-width piece splits an interval
    dup = np.zeros(b.shape, dtype=bool)
    dup[:, 1:] = np.diff(b, axis=1) <= MERGE_TOL
    b = sorted_union([np.where(dup, np.nan, b)], n)
    cell_lo, cell_hi = b[:, :-1], b[:, 1:]
    valid = np.isfinite(cell_lo) & np.isfinite(cell_hi)
    mid = np.where(valid, 0.5 * (cell_lo + cell_hi), 0.0)
    feas = valid & _feasible_at(t1[:, None], mid, a, r, k, g, outside, mu, max_g)
    prev = np.zeros_like(feas)
    prev[:, 1:] = feas[:, :-1]
    nxt = np.zeros_like(feas)
    nxt[:, :-1] = feas[:, 1:]
    start, end = feas & ~prev, feas & ~nxt
    count = np.sum(start, axis=1)
    m = int(np.max(count, initial=0))
    out_lo = np.full((n, m), np.nan)
    out_hi = np.full((n, m), np.nan)
    rs, cs = np.nonzero(start)
    out_lo[rs, np.cumsum(start, axis=1)[rs, cs] - 1] = cell_lo[rs, cs]
    re, ce = np.nonzero(end)
    out_hi[re, np.cumsum(end, axis=1)[re, ce] - 1] = cell_hi[re, ce]
    vmin, vmax = _speed_range(t1, out_lo, out_hi, lo, hi, a, r, k, g)
    shape = t.shape + (m,)
    return AlphaIntervals(theta=t, lo=out_lo.reshape(shape), hi=out_hi.reshape(shape),
                          speed_min=vmin.reshape(shape), speed_max=vmax.reshape(shape),
                          count=count.reshape(t.shape))


def _speed_functions(a, r, k, g):
    C, S, s, c, rp, D, SD = _basis(a, r, k)
    num = g * rp * rp * C
    return num, SD


def _speed_range(t1, ilo, ihi, lo, hi, a, r, k, g):
    """Infimum and supremum of v_cm over each open interval (ilo, ihi)."""
    n, m = ilo.shape
    if m == 0:
        return np.full((n, 0), np.nan), np.full((n, 0), np.nan)
    num, SD = _speed_functions(a, r, k, g)
    dv = num.d_alpha() * SD - num * SD.d_alpha()          # numerator of d(v^2)/d alpha
    crit = _roots_in(dv.in_alpha(t1), lo, hi)             # (n, K)
    valid = np.isfinite(ilo)
    safe_lo = np.where(valid, ilo, 0.0)
    safe_hi = np.where(valid, ihi, 0.0)
    v_lo = _speed_sq(t1[:, None], safe_lo, a, r, k, g)
    v_hi = _speed_sq(t1[:, None], safe_hi, a, r, k, g)
    vmin = np.minimum(v_lo, v_hi)
    vmax = np.maximum(v_lo, v_hi)
    if crit.shape[1]:
        vc = _speed_sq(t1[:, None], np.where(np.isfinite(crit), crit, 0.0), a, r, k, g)  # (n, K)
        within = (np.isfinite(crit)[:, None, :]
                  & (crit[:, None, :] > safe_lo[:, :, None])
                  & (crit[:, None, :] < safe_hi[:, :, None]))
        vmin = np.minimum(vmin, np.min(np.where(within, vc[:, None, :], np.inf), axis=2))
        vmax = np.maximum(vmax, np.max(np.where(within, vc[:, None, :], -np.inf), axis=2))
    vmin = np.where(valid, np.sqrt(vmin), np.nan)
    vmax = np.where(valid, np.sqrt(vmax), np.nan)
    return vmin, vmax


# ---------------------------------------------------------------------------
# the highest orbit possible
# ---------------------------------------------------------------------------

@dataclass(frozen=True)
class HighestOrbit:
    """The smallest theta at which a feasible tilt exists (beyond the paper).

    ``theta`` [rad] is the infimum of feasible polar angles, located to
    ``theta_bracket = (infeasible, feasible)``; ``alpha_lo``, ``alpha_hi``
    [rad] the first allowed interval at the feasible end of the bracket,
    ``alpha`` its midpoint (the limiting tilt), ``speed_min``, ``speed_max``
    [m/s] the speed range over it and ``speed`` the limit, as theta -> theta*,
    of the least speed of a feasible orbit: inf when the highest orbit is
    reached only at unbounded speed (e.g. friction limit alone: alpha -> 0),
    0 when the wheel's centre tends to the axis (r' -> 0).  ``found`` is False, and the numbers
    NaN, when no theta of the scan is feasible.
    """

    found: bool
    theta: float
    alpha: float
    alpha_lo: float
    alpha_hi: float
    speed: float
    speed_min: float
    speed_max: float
    theta_bracket: tuple


def highest_orbit(a, r, k, g=STANDARD_GRAVITY, outside=False, mu=np.inf, max_g=np.inf,
                  n_theta=2048, xtol=1e-11):
    """The highest orbit possible: the smallest theta with a feasible alpha.

    Beyond the paper (docs/limits.md).  Feasibility at one theta is decided
    exactly by :func:`allowed_alpha` (all alpha boundaries found).  In theta
    the first feasible point of ``n_theta`` midpoints of (0, pi) is found
    by a scan of every :data:`_SCAN_STRIDE`-th of them and then of the ones
    just before the first feasible scan point; the change infeasible ->
    feasible is then bisected to ``xtol`` rad, :data:`_BISECTION_LEVELS`
    levels per vectorised call (every point those levels can visit).  A
    feasible island narrower than _SCAN_STRIDE pi/n_theta (0.7 deg) in theta
    lying below the first feasible scan point could be missed (none exists
    for the equations here; the docs give the closed form that the tests
    check).

    Parameters
    ----------
    a, r : float, [m];  k : float, [-];  g : float, [m/s^2];  outside : bool;
    mu : float, [-] friction available (inf: no limit);
    max_g : float, [-] largest load load_g allowed (inf: no limit).

    Returns
    -------
    HighestOrbit
    """
    a, r, k, g, outside, mu, max_g = _check(a, r, k, g, outside, mu, max_g)

    def feasible_at(theta):
        return np.asarray(allowed_alpha(theta, a, r, k, g, outside, mu, max_g).count).reshape(-1) > 0

    grid = (np.arange(n_theta) + 0.5) * (np.pi / n_theta)
    j = _first_feasible(grid, feasible_at)
    if j is None:
        nan = float("nan")
        return HighestOrbit(False, nan, nan, nan, nan, nan, nan, nan, (nan, nan))
    lo = 0.0 if j == 0 else float(grid[j - 1])
    hi = float(grid[j])
    while hi - lo > xtol:
        # the next _BISECTION_LEVELS levels of bisection decided at once:
        # one call on 2^levels - 1 points costs little more than on one
        points = _bisection_points(lo, hi, _BISECTION_LEVELS)
        ok = dict(zip(points, feasible_at(np.array(points))))
        for _ in range(_BISECTION_LEVELS):
            if hi - lo <= xtol:
                break
            mid = 0.5 * (lo + hi)
            if ok[mid]:
                hi = mid
            else:
                lo = mid
    at = allowed_alpha(hi, a, r, k, g, outside, mu, max_g)
    alo, ahi, vmin, vmax = at.intervals()[0]
    alpha = 0.5 * (alo + ahi)
    speed = _limit_speed(lo, hi, vmin, a, r, k, g, outside, mu, max_g)
    if np.isfinite(speed) and np.isfinite(vmax) and (ahi - alo) < 1e-6:
        speed = float(np.sqrt(_speed_sq(hi, alpha, a, r, k, g)))
    return HighestOrbit(True, 0.5 * (lo + hi), alpha, alo, ahi, speed, vmin, vmax, (lo, hi))


#: highest_orbit scans every _SCAN_STRIDE-th theta of its grid first.
_SCAN_STRIDE = 8
#: levels of the bisection of highest_orbit evaluated per call.
_BISECTION_LEVELS = 5


def _bisection_points(lo, hi, levels):
    """Every midpoint bisection of (lo, hi) can visit in ``levels`` steps,
    computed as bisection computes them (so the results match exactly)."""
    if levels == 0:
        return []
    mid = 0.5 * (lo + hi)
    return _bisection_points(lo, mid, levels - 1) + [mid] + _bisection_points(mid, hi, levels - 1)


def _first_feasible(grid, feasible_at):
    """Index of the first point of ``grid`` where ``feasible_at`` holds,
    from a scan of every _SCAN_STRIDE-th point and of the points before
    the first feasible one found; None when no scanned point is feasible."""
    coarse = np.arange(_SCAN_STRIDE - 1, grid.size + _SCAN_STRIDE - 1, _SCAN_STRIDE).clip(max=grid.size - 1)
    coarse = np.unique(coarse)
    hit = np.nonzero(feasible_at(grid[coarse]))[0]
    if hit.size == 0:
        return None
    end = int(coarse[hit[0]])
    start = 0 if hit[0] == 0 else int(coarse[hit[0] - 1]) + 1
    fine = np.nonzero(feasible_at(grid[start:end]))[0] if end > start else np.empty(0, int)
    return start + int(fine[0]) if fine.size else end


def _limit_speed(lo, hi, vmin_near, a, r, k, g, outside, mu, max_g):
    """Limit of the least speed as theta -> theta* from the feasible side,
    from its scaling between distances d and 1e4 d above theta*: growth by
    more than 10 means it diverges (inf), a fall by more than 10 that it
    tends to 0 (r' -> 0 at a corner), else the value nearest theta*."""
    d = max(hi - lo, 1e-300)
    far = allowed_alpha(lo + 1e4 * d, a, r, k, g, outside, mu, max_g)
    if far.count == 0:
        return float(vmin_near)
    v_far = far.intervals()[0][2]
    if not np.isfinite(vmin_near):
        return float("inf")
    if vmin_near > 10.0 * v_far:
        return float("inf")
    if vmin_near < 0.1 * v_far:
        return 0.0
    return float(vmin_near)


# ---------------------------------------------------------------------------
# tilt for a given speed or rotation rate
# ---------------------------------------------------------------------------

#: A root of the speed or rate equation is reported only where the forward
#: model (:func:`~deathsphere.physics.wheel.horizontal_orbit`) at it gives the
#: target back to this relative tolerance (docs/limits.md, "Bank angle for a
#: given speed").  Loose on purpose: next to a pole of eq. (29) v_cm changes
#: so fast with alpha that a root exact to the last bit of alpha reproduces
#: the target only to ~1e-4; a false root (0/0 at a singular point) gives NaN.
ROOT_MATCH_RTOL = 1e-3


def solve_alpha(theta, a, r, k, g=STANDARD_GRAVITY, speed=None, omega=None, outside=False,
                mu=np.inf, alpha_range=None):
    """Every tilt alpha at which eq. (29) gives the centre speed
    v_cm = |r'| Omega = ``speed`` [m/s], or the rotation rate ``omega``
    [rad/s] (give exactly one), at polar angle ``theta`` [rad].

    The zeros of g r'^2 cos(alpha) - v^2 sin(alpha) D (speed) or
    g cos(alpha) - Omega^2 sin(alpha) D (rate), trigonometric polynomials of
    degree 3 and 2 (at most 6 and 4 tilts per period), are all found as
    described in the module docstring; each is reported with every quantity
    of :func:`deathsphere.physics.wheel.horizontal_orbit` (with ``mu``), so
    its status says whether it is a feasible orbit.  Tangent (double) roots,
    where the speed is exactly a local extremum of v_cm(alpha), are not
    reported; nor is a zero at which the forward model does not give the
    target back to :data:`ROOT_MATCH_RTOL` (a singular point of eq. (29),
    where the polynomial vanishes but Omega is undefined).

    Parameters
    ----------
    theta : array_like
        Polar angle [rad].
    speed, omega : array_like
        Broadcast with theta, > 0.
    alpha_range : (lo, hi), optional
        [rad], hi - lo <= 2 pi; default the fit interval of eq. (0) (eq. (81)
        outside), which keeps every root that fits; pass e.g. (-pi, pi) to
        see the others too (status ``no_fit``).

    Returns
    -------
    dict with ``alpha`` (shape + (m,), rad, sorted, NaN-padded), ``count``
    (shape) and the keys of ``horizontal_orbit`` at each root (padding: NaN,
    status ``invalid``).
    """
    if (speed is None) == (omega is None):
        raise ValueError("give exactly one of speed and omega")
    a, r, k, g, outside, mu, _ = _check(a, r, k, g, outside, mu)
    target = np.asarray(speed if speed is not None else omega, dtype=float)
    if not np.all(np.isfinite(target)) or np.any(target <= 0):
        raise ValueError(f"{'speed' if speed is not None else 'omega'} must be finite and > 0")
    t, tg = np.broadcast_arrays(np.asarray(theta, dtype=float), target)
    shape = t.shape
    _, t1 = _theta_1d(t)
    tg = tg.reshape(-1)
    C, S, s, c, rp, D, SD = _basis(a, r, k)
    A = g * rp * rp * C if speed is not None else g * C + 0.0 * SD
    B = SD + 0.0 * A
    A = A + 0.0 * B
    h = A.in_alpha(t1) - (tg * tg)[:, None] * B.in_alpha(t1)
    if alpha_range is None:
        lo, hi = fit_interval(t1, a, r, outside)
    else:
        lo = np.broadcast_to(np.asarray(alpha_range[0], dtype=float), shape).reshape(-1)
        hi = np.broadcast_to(np.asarray(alpha_range[1], dtype=float), shape).reshape(-1)
        if np.any(hi - lo > TWO_PI) or np.any(hi < lo):
            raise ValueError("alpha_range must satisfy lo <= hi <= lo + 2 pi")
    roots = _roots_in(h, lo, hi)
    m = roots.shape[1]
    found = np.isfinite(roots)
    orb = horizontal_orbit(t1[:, None], np.where(found, roots, 0.0), a, r, k, g, outside, mu)
    # A zero of h is a tilt giving the target only where eq. (29) is defined
    # there and gives it back: h vanishes also where its numerator and the
    # denominator of eq. (29) vanish together (the poles at theta = 0 or 180
    # deg, alpha = 0 for a huge rate), and the forward model is NaN there.
    got = orb["v_cm"] if speed is not None else orb["omega"]
    with np.errstate(invalid="ignore"):
        found &= np.abs(got - tg[:, None]) <= ROOT_MATCH_RTOL * tg[:, None]
    order = np.argsort(~found, axis=1, kind="stable")       # kept roots first, still increasing
    found = np.take_along_axis(found, order, axis=1)
    roots = np.where(found, np.take_along_axis(roots, order, axis=1), np.nan)
    orb = {key: np.take_along_axis(np.broadcast_to(val, roots.shape), order, axis=1) for key, val in orb.items()}
    out = {"alpha": roots.reshape(shape + (m,)), "count": np.sum(found, axis=1).reshape(shape)}
    for key, val in orb.items():
        if key in ("status", "reason"):
            val = np.where(found, val, Status.INVALID if key == "status" else 0).astype(np.int8)
        else:
            val = np.where(found, val, np.nan)
        out[key] = val.reshape(shape + (m,))
    return out
