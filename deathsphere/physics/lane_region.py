"""The allowed tilts of a wheel on a lane of any ground, and the lowest and
highest lanes a rider's friction and load allow.

Beyond the paper (docs/limits.md sec. 8, docs/surfaces.md S1-S5).  On the
globe (:mod:`deathsphere.physics.region`) every boundary of the region of
steady orbits is a trigonometric polynomial in (theta, alpha).  On any
surface of revolution the lane's geometry -- the contact's distance rho
from the axis, the wall angle beta, the parallel's curvature kappa_parallel
= sin(beta) / rho and the lane's height above the floor -- is a set of
numbers per lane, not a polynomial in a polar angle, but every boundary is
still a trigonometric polynomial in alpha, with coefficients per lane.
With C = cos(alpha), S = sin(alpha), r' = rho - a C (S1), D = (2k+1) r' +
k a C (the bracket of eq. 29, S2):

=========================  ======================================  ==========
boundary                   function                                degree
=========================  ======================================  ==========
fit, S4 (eq. 0 / 81)       sin(alpha + beta) - a kappa_parallel   1
floor, S5                  (z_P - z_lowest) + 2 a S               1
Omega^2 = 0 or pole (S2)   C,  S,  D                              1 each
contact, S3 (eq. 33)       P_N = r' C sin(beta) + cos(beta) S D   2
friction, S3 (eq. 35)      P_F -+ mu P_N, P_F = r' C cos(beta) - sin(beta) S D   2 each
load (eqs. 32, 36)         r' C -+ G S D                          2 each
extrema of v_cm            (g r'^2 C)' S D - g r'^2 C (S D)'      5
=========================  ======================================  ==========

since Omega^2 = g C / (S D), N/m = g P_N / (S D) and f/m = g P_F / (S D)
(S3).  On the sphere (rho = r sin(theta), beta = pi - theta) these are the
globe's functions.  Their zeros are found by
:func:`deathsphere.physics.trig_roots.roots_in` (no zero of odd
multiplicity missed), each piece between zeros is tested at its midpoint by
:func:`deathsphere.physics.revolution.wheel_orbit` (status ``ok``, the one
predicate ``orbit --surface`` reports) and the load limit, and feasible
neighbours merge: the globe's method, lane by lane, vectorised over lanes.

Angles in radians, lengths in metres, g in m/s^2, speeds in m/s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from deathsphere.physics.region import centre_accel_limit
from deathsphere.physics.revolution import lane, wheel_orbit
from deathsphere.physics.status import Status
from deathsphere.physics.trig_roots import MERGE_TOL, roots_in, sorted_union

__all__ = ["LaneIntervals", "LaneRange", "allowed_alpha_on", "lane_range", "lane_boundaries",
           "LANE_SCAN", "LANE_XTOL", "feasible_on", "fit_window"]


class _RowPoly:
    """A real trigonometric polynomial in alpha with one row of coefficients
    per lane: h (n, 2N+1), h[:, j] the coefficient of exp(i (j - N) alpha).
    Products are convolutions along the rows (a loop over the few harmonics,
    never over lanes)."""

    __slots__ = ("h",)

    def __init__(self, h):
        self.h = np.asarray(h, dtype=complex)

    @property
    def deg(self):
        return (self.h.shape[1] - 1) // 2

    def _padded(self, N):
        d = N - self.deg
        return np.pad(self.h, ((0, 0), (d, d)))

    def _lift(self, x):
        if isinstance(x, _RowPoly):
            return x
        x = np.asarray(x, dtype=complex)
        return _RowPoly(np.broadcast_to(x.reshape(-1, 1), (self.h.shape[0], 1)))

    def __add__(self, other):
        other = self._lift(other)
        N = max(self.deg, other.deg)
        return _RowPoly(self._padded(N) + other._padded(N))

    __radd__ = __add__

    def __neg__(self):
        return _RowPoly(-self.h)

    def __sub__(self, other):
        return self + (-self._lift(other))

    def __rsub__(self, other):
        return self._lift(other) - self

    def __mul__(self, other):
        if not isinstance(other, _RowPoly):
            factor = np.asarray(other, dtype=complex)
            return _RowPoly(self.h * (factor.reshape(-1, 1) if factor.ndim else factor))
        a, b = self.h, other.h
        out = np.zeros((a.shape[0], a.shape[1] + b.shape[1] - 1), dtype=complex)
        for j in range(b.shape[1]):
            out[:, j:j + a.shape[1]] += a * b[:, j:j + 1]
        return _RowPoly(out)

    __rmul__ = __mul__

    def d_alpha(self):
        q = np.arange(-self.deg, self.deg + 1)
        return _RowPoly(self.h * (1j * q)[None, :])


@dataclass(frozen=True)
class _Lane:
    """A lane's geometry as flat arrays (n,), from the ground (S0)."""

    height: np.ndarray
    off_wall: np.ndarray
    rho: np.ndarray
    sin_beta: np.ndarray
    cos_beta: np.ndarray
    kappa_parallel: np.ndarray
    lift: np.ndarray            # the contact's height above the ground's lowest z


def _lane(ground, height) -> _Lane:
    where = lane(ground, np.asarray(height, dtype=float).reshape(-1))
    return _Lane(height=where["height"], off_wall=where["off_wall"], rho=where["rho"],
                 sin_beta=where["sin_beta"], cos_beta=where["cos_beta"],
                 kappa_parallel=where["kappa_parallel"], lift=where["z"] - ground.lowest)


def _basis(ln: _Lane, a, k):
    n = ln.rho.size
    one = np.ones((n, 1))
    C = _RowPoly(np.hstack([0.5 * one, 0 * one, 0.5 * one]))
    S = _RowPoly(np.hstack([0.5j * one, 0 * one, -0.5j * one]))
    rp = C * (-a) + ln.rho                                           # S1
    D = rp * (2 * k + 1) + C * (k * a)                               # S2's bracket
    return C, S, rp, D, S * D


def _functions(ln: _Lane, a, k, mu, max_g):
    """The boundary functions on each lane (module docstring), by name."""
    C, S, rp, D, SD = _basis(ln, a, k)
    P_N = rp * C * ln.sin_beta + SD * ln.cos_beta
    out = {"S4": [S * ln.cos_beta + C * ln.sin_beta - a * ln.kappa_parallel],
           "S5": [S * (2 * a) + ln.lift], "S2": [C, S, D], "S3": [P_N]}
    if math.isfinite(mu):
        P_F = rp * C * ln.cos_beta - SD * ln.sin_beta
        out["mu"] = [P_F - P_N * mu, P_F + P_N * mu]
    if math.isfinite(max_g):
        G = centre_accel_limit(max_g)
        out["max_g"] = [rp * C - SD * G, rp * C + SD * G]
    return out


def fit_window(ln: _Lane, a, outside):
    """The open interval of alpha where S4 holds [rad] (eq. 0 / 81 on the
    sphere): inside sin(alpha + beta) > a kappa_parallel, outside
    sin(alpha + beta) < 0; NaN where no tilt fits (a kappa_parallel >= 1)."""
    beta = np.arctan2(ln.sin_beta, ln.cos_beta)
    if outside:
        return np.pi - beta, 2 * np.pi - beta
    x = a * ln.kappa_parallel
    fits = x < 1.0
    e = np.arcsin(np.clip(x, -1.0, 1.0))
    lo = np.where(fits, e - beta, np.nan)
    return lo, np.where(fits, np.pi - e - beta, np.nan)


@dataclass(frozen=True)
class LaneIntervals:
    """Intervals of alpha giving a feasible orbit, per lane (rad, m/s), as
    :class:`deathsphere.physics.region.AlphaIntervals` with the lane's
    ``height`` in place of theta: ``lo``, ``hi``, ``speed_min``,
    ``speed_max`` of shape height.shape + (m,), NaN-padded beyond ``count``."""

    height: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    speed_min: np.ndarray
    speed_max: np.ndarray
    count: np.ndarray

    def intervals(self, index=()):
        """List of (lo, hi, speed_min, speed_max) for one lane."""
        index = np.index_exp[index] if not isinstance(index, tuple) else index
        return [(float(self.lo[index][j]), float(self.hi[index][j]), float(self.speed_min[index][j]),
                 float(self.speed_max[index][j])) for j in range(int(self.count[index]))]


def feasible_on(ground, height, alpha, a, k, g, outside, mu, max_g):
    """True where (height, alpha) is a feasible orbit: status ``ok`` of the
    wheel on the ground (docs/surfaces.md S1-S5; eqs. (29), (33), (35) with
    the surface's split of the force), the predicate of ``orbit --surface``,
    and its load within max_g (eqs. 32, 36).  Beyond the paper."""
    orb = wheel_orbit(ground, height, alpha, a, k, g, outside, mu)
    ok = orb["status"] == Status.OK
    if math.isfinite(max_g):
        with np.errstate(invalid="ignore"):
            ok &= orb["accel_g"] <= centre_accel_limit(max_g)
    return ok


def _speed_sq(ln_rho, alpha, a, k, g):
    """v_cm^2 = g r'^2 cos(alpha) / (sin(alpha) D) (S2), inf at a pole,
    clipped at 0 (rows of lanes, columns of tilts)."""
    cos_a, sin_a = np.cos(alpha), np.sin(alpha)
    rp = ln_rho[:, None] - a * cos_a
    den = sin_a * ((2 * k + 1) * rp + k * a * cos_a)
    scale = (2 * k + 1) * np.maximum(ln_rho, a)[:, None] + (k + 1) * a
    pole = np.abs(den) <= 1e-12 * scale
    v2 = np.where(pole, np.inf, g * rp * rp * cos_a / np.where(pole, 1.0, den))
    return np.maximum(v2, 0.0)


def allowed_alpha_on(ground, height, a, k, g, outside=False, mu=np.inf, max_g=np.inf) -> LaneIntervals:
    """Intervals of alpha where the wheel has a feasible steady orbit on the
    lane(s) ``height`` [m] of ``ground`` (the turn radius on flat ground):
    it fits (S4) above the floor (S5), Omega^2 of S2 (eq. 29) is > 0, it
    keeps contact (S3, eq. 33), mu_required (eq. 35) <= ``mu`` and load_g
    <= ``max_g``.  Beyond the paper; method: the module docstring and
    docs/limits.md sec. 8.  a [m], k [-], g [m/s^2] scalars; ``height``
    any shape.  A lane off the wall has no interval."""
    a, k, g, mu, max_g = float(a), float(k), float(g), float(mu), float(max_g)
    h = np.asarray(height, dtype=float)
    ln = _lane(ground, h)
    n = ln.rho.size
    lo, hi = fit_window(ln, a, outside)
    usable = np.isfinite(lo) & ~ln.off_wall
    lo, hi = np.where(usable, lo, 0.0), np.where(usable, hi, 0.0)
    cuts = [roots_in(f.h, lo, hi) for name, fs in _functions(ln, a, k, mu, max_g).items() if name != "S4"
            for f in fs]
    b = sorted_union([lo[:, None], hi[:, None]] + cuts, n)
    dup = np.zeros(b.shape, dtype=bool)
    dup[:, 1:] = np.diff(b, axis=1) <= MERGE_TOL
    b = sorted_union([np.where(dup, np.nan, b)], n)
    cell_lo, cell_hi = b[:, :-1], b[:, 1:]
    valid = np.isfinite(cell_lo) & np.isfinite(cell_hi) & usable[:, None]
    mid = np.where(valid, 0.5 * (cell_lo + cell_hi), 0.0)
    lane_h = np.where(usable, ln.height, 0.0)
    feas = valid & feasible_on(ground, lane_h[:, None], mid, a, k, g, outside, mu, max_g)
    prev = np.zeros_like(feas)
    prev[:, 1:] = feas[:, :-1]
    nxt = np.zeros_like(feas)
    nxt[:, :-1] = feas[:, 1:]
    start, end = feas & ~prev, feas & ~nxt
    count = np.sum(start, axis=1)
    m = int(np.max(count, initial=0))
    out_lo, out_hi = np.full((n, m), np.nan), np.full((n, m), np.nan)
    rs, cs = np.nonzero(start)
    out_lo[rs, np.cumsum(start, axis=1)[rs, cs] - 1] = cell_lo[rs, cs]
    re, ce = np.nonzero(end)
    out_hi[re, np.cumsum(end, axis=1)[re, ce] - 1] = cell_hi[re, ce]
    vmin, vmax = _speed_range(ln, out_lo, out_hi, lo, hi, a, k, g)
    shape = h.shape + (m,)
    return LaneIntervals(height=h, lo=out_lo.reshape(shape), hi=out_hi.reshape(shape),
                         speed_min=vmin.reshape(shape), speed_max=vmax.reshape(shape), count=count.reshape(h.shape))


def _speed_range(ln, ilo, ihi, lo, hi, a, k, g):
    """Infimum and supremum of v_cm over each open interval: its ends and the
    interior zeros of d(v_cm^2)/d alpha (degree 5)."""
    n, m = ilo.shape
    if m == 0:
        return np.full((n, 0), np.nan), np.full((n, 0), np.nan)
    C, S, rp, D, SD = _basis(ln, a, k)
    num = rp * rp * C * g
    crit = roots_in((num.d_alpha() * SD - num * SD.d_alpha()).h, lo, hi)
    valid = np.isfinite(ilo)
    safe_lo, safe_hi = np.where(valid, ilo, 0.0), np.where(valid, ihi, 0.0)
    v_lo, v_hi = _speed_sq(ln.rho, safe_lo, a, k, g), _speed_sq(ln.rho, safe_hi, a, k, g)
    vmin, vmax = np.minimum(v_lo, v_hi), np.maximum(v_lo, v_hi)
    if crit.shape[1]:
        vc = _speed_sq(ln.rho, np.where(np.isfinite(crit), crit, 0.0), a, k, g)
        within = (np.isfinite(crit)[:, None, :] & (crit[:, None, :] > safe_lo[:, :, None])
                  & (crit[:, None, :] < safe_hi[:, :, None]))
        vmin = np.minimum(vmin, np.min(np.where(within, vc[:, None, :], np.inf), axis=2))
        vmax = np.maximum(vmax, np.max(np.where(within, vc[:, None, :], -np.inf), axis=2))
    return np.where(valid, np.sqrt(vmin), np.nan), np.where(valid, np.sqrt(vmax), np.nan)


def lane_boundaries(ground, height, a, k, outside=False, mu=np.inf, max_g=np.inf):
    """Every alpha on each boundary of the allowed region at each lane
    (beyond the paper: eqs. (0), (29), (33), (35) on any ground, docs/limits.md
    sec. 8), for the map (the globe's :func:`deathsphere.physics.region.boundary_alphas`
    with lanes in place of theta): dict name (``S4`` fit, ``S5`` floor,
    ``S2`` Omega^2 = 0 or pole, ``S3`` contact, ``mu``, ``max_g``) -> array
    height.shape + (m,) [rad], sorted, NaN-padded; searched over the full
    turn [-pi, pi) (outside [0, 2 pi)), the fit's zeros included.  The
    ``mu`` and ``max_g`` curves are kept only where the orbit is real and
    in contact; the floor's only where it binds (alpha < 0)."""
    h = np.asarray(height, dtype=float)
    ln = _lane(ground, h)
    n = ln.rho.size
    lo = np.full(n, 0.0 if outside else -np.pi)
    hi = lo + 2 * np.pi - 1e-12
    out = {}
    for name, funcs in _functions(ln, float(a), float(k), float(mu), float(max_g)).items():
        roots = sorted_union([roots_in(f.h, lo, hi) for f in funcs], n)
        if roots.size:
            safe = np.where(np.isfinite(roots), roots, 0.5)
            if name in ("mu", "max_g"):
                orb = wheel_orbit(ground, np.where(ln.off_wall, 0.0, ln.height)[:, None], safe, a, k, 1.0,
                                  outside)
                with np.errstate(invalid="ignore"):
                    keep = np.isfinite(orb["normal"]) & (orb["normal"] > 0)
                roots = sorted_union([np.where(keep, roots, np.nan)], n)
            elif name == "S5":
                roots = sorted_union([np.where(safe < 0, roots, np.nan)], n)
        roots = np.where(ln.off_wall[:, None], np.nan, roots) if roots.size else roots
        out[name] = roots.reshape(h.shape + (roots.shape[1],))
    return out


# ---------------------------------------------------------------------------
# the lowest and the highest lane
# ---------------------------------------------------------------------------

#: Lanes of the grid of :func:`lane_range` (every 8th scanned first).
LANE_SCAN = 2048
#: :func:`lane_range` bisects a change of feasibility to this fraction of
#: the ground's length scale.
LANE_XTOL = 1e-10
#: Bisection levels decided per vectorised call.
_LEVELS = 5


@dataclass(frozen=True)
class LaneRange:
    """The lowest and the highest lane with a feasible tilt (beyond the paper).

    ``lowest``, ``highest`` [m]: the infimum and supremum of feasible lane
    heights (on flat ground turn radii); ``highest`` is inf when every lane
    scanned up to ``scan_top`` is feasible on a wall with no top (no highest
    lane from mu and max_g).  ``lowest_bound``, ``highest_bound``: what ends
    the range there -- ``floor`` (height 0), ``top`` (the ground's highest
    lane: the wall's top, a cone's apex, a profile's last sample),
    ``limits`` (the fit, contact, friction or load: a change of feasibility
    between lanes, bisected) or ``none`` (no top).  ``found`` is False when
    no scanned lane is feasible."""

    found: bool
    lowest: float
    highest: float
    lowest_bound: str
    highest_bound: str
    scan_top: float


def _length(ground, a):
    """The ground's length scale [m]: its radius, else its widest lane's
    distance from the axis (a profile), else the wheel's radius."""
    for name in ("radius", "r"):
        value = getattr(ground, name, None)
        if isinstance(value, (int, float)) and math.isfinite(value) and value > 0:
            return float(value)
    top = float(getattr(ground, "highest_lane", math.inf))
    if math.isfinite(top):
        rho, _ = ground.contact(np.linspace(0.0, top, 33))
        return max(float(np.max(rho)), float(a))
    return float(a)


def _scan_heights(top, scale):
    """LANE_SCAN lanes from the floor to the top; with no top, lanes
    h = scale u / (1 - u) for u uniform in (0, 1) (up to ~2000 scale)."""
    u = (np.arange(LANE_SCAN) + 0.5) / LANE_SCAN
    if math.isfinite(top):
        return top * u
    return scale * u / (1.0 - u)


def _bisect(feasible_at, inside, outside, xtol):
    """The change of feasibility between lane ``inside`` (feasible) and
    ``outside`` (not), bisected to ``xtol``, _LEVELS levels per call."""
    while abs(inside - outside) > xtol:
        points = _points(inside, outside, _LEVELS)
        ok = dict(zip(points, feasible_at(np.array(points))))
        for _ in range(_LEVELS):
            if abs(inside - outside) <= xtol:
                break
            mid = 0.5 * (inside + outside)
            if ok[mid]:
                inside = mid
            else:
                outside = mid
    return inside


def _points(x, y, levels):
    if levels == 0:
        return []
    mid = 0.5 * (x + y)
    return _points(x, mid, levels - 1) + [mid] + _points(mid, y, levels - 1)


def _feasible_lanes(heights, feasible_at):
    """Indices of the grid's feasible lanes that decide its ends: every
    _STRIDE-th lane is scanned, then the lanes between the first feasible
    one found and the scanned lane before it, and between the last and the
    scanned lane after it (the globe's scan, sec. 4, at both ends)."""
    n = heights.size
    coarse = np.unique(np.arange(_STRIDE - 1, n + _STRIDE - 1, _STRIDE).clip(max=n - 1))
    found = coarse[feasible_at(heights[coarse])]
    if found.size == 0:
        return found
    first, last = int(found[0]), int(found[-1])
    below = np.arange(max(first - _STRIDE + 1, 0), first)
    above = np.arange(last + 1, min(last + _STRIDE, n))
    fine = np.concatenate([below, above])
    fine_ok = fine[feasible_at(heights[fine])] if fine.size else fine
    return np.union1d(found, fine_ok).astype(int)


#: lane_range scans every _STRIDE-th lane of its grid first.
_STRIDE = 8


def lane_range(ground, a, k, g, outside=False, mu=np.inf, max_g=np.inf) -> LaneRange:
    """The lowest and the highest lane on ``ground`` with a feasible tilt
    within ``mu`` and ``max_g`` (beyond the paper; docs/limits.md sec. 8).

    Feasibility of a lane is decided exactly by :func:`allowed_alpha_on`.
    Its ends are checked first (the floor, height 0, and the top, the
    ground's highest lane); between them every 8th lane of a grid of
    :data:`LANE_SCAN` is scanned, then the lanes next to the first and the
    last feasible one found, and each change from infeasible to feasible
    there is bisected to :data:`LANE_XTOL` times the ground's length scale.  With no top (a drum or a cone given no wall
    height, flat ground) the scan reaches ~2000 radii and a feasible last
    lane means no highest lane.  An island of feasible lanes narrower than
    the scan's spacing below the first (or above the last) feasible lane
    scanned (8 grid spacings) could be missed."""
    top = float(getattr(ground, "highest_lane", math.inf))
    scale = _length(ground, a)

    def feasible_at(heights):
        return np.asarray(allowed_alpha_on(ground, heights, a, k, g, outside, mu, max_g).count).reshape(-1) > 0

    heights = _scan_heights(top, scale)
    ends = np.array([0.0] + ([top] if math.isfinite(top) else []))
    ok_ends = feasible_at(ends)
    hit = _feasible_lanes(heights, feasible_at)
    nan = math.nan
    if hit.size == 0 and not ok_ends.any():
        return LaneRange(False, nan, nan, "", "", float(heights[-1]))
    xtol = LANE_XTOL * scale
    if ok_ends[0]:
        lowest, low_bound = 0.0, "floor"
    else:
        first = int(hit[0]) if hit.size else None
        inside = float(heights[first]) if first is not None else top
        below = float(heights[first - 1]) if first else 0.0
        lowest, low_bound = _bisect(feasible_at, inside, below, xtol), "limits"
        if lowest <= xtol:       # feasible down to the floor, not on it (the bottom of a bowl: rho = 0)
            lowest, low_bound = 0.0, "floor"
    if math.isfinite(top) and ok_ends[-1]:
        highest, high_bound = top, "top"
    elif not math.isfinite(top) and hit.size and hit[-1] == heights.size - 1:
        highest, high_bound = math.inf, "none"
    else:
        last = int(hit[-1]) if hit.size else None
        inside = float(heights[last]) if last is not None else 0.0
        above = float(heights[last + 1]) if last is not None and last + 1 < heights.size else top
        highest, high_bound = _bisect(feasible_at, inside, above, xtol), "limits"
    return LaneRange(True, lowest, highest, low_bound, high_bound, float(heights[-1]))
