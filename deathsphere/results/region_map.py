"""The allowed (theta, alpha) region of horizontal wheel orbits, sampled for
a map: McDonald (1993) figure "alpha_wh".  Plain data only; the views that
draw it are :mod:`deathsphere.render.charplot` (terminal) and
:mod:`deathsphere.render.map_figure` (matplotlib).

Two samplings, one per kind of view:

* :func:`cell_map` -> :class:`CellMap`, the region on a grid of cells: which
  cell centres are feasible orbits (status ``ok`` of
  :func:`deathsphere.physics.wheel.horizontal_orbit`, and load <= max_g),
  the stability verdict there, and where each boundary (eqs. (0)/(81),
  (29), (33)/(83), and the mu and load limits) crosses lines through the
  cells, root-found by :mod:`deathsphere.physics.region` along columns *and*
  rows so that steep stretches of a curve leave no gaps.
* :func:`curve_map` -> :class:`CurveMap`, the region as curves: the
  boundaries as polylines exact to ~1e-13 rad (:func:`boundary_polylines`),
  the allowed alpha intervals on a fine theta grid, and with stability the
  signed stability margin on a grid (:func:`stability_grid`) with its zero
  contour.

Stability (beyond the paper, docs/stability.md "Stability maps") is the
exact linearisation of :mod:`deathsphere.physics.stability`.  Angles are
in degrees except the boundary polylines (radians, as
:mod:`deathsphere.physics.region` gives them).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics import region
from deathsphere.physics.stability import Verdict, wheel_stability

#: Root samples per cell along each axis of a :class:`CellMap`.
SAMPLES_PER_CELL = 6
#: Default cell grid: 72 theta columns (an 80-column terminal map); rows
#: per side (alpha = 0..90 deg inside, 0..270 deg outside).
DEFAULT_COLUMNS = 72
DEFAULT_ROWS = {False: 19, True: 28}
CELL_ALPHA_RANGE_DEG = {False: (0.0, 90.0), True: (0.0, 270.0)}
#: Default alpha axis of a :class:`CurveMap` [deg].
CURVE_ALPHA_RANGE_DEG = {False: (-5.0, 95.0), True: (-5.0, 275.0)}
#: Thetas on which the allowed intervals are root-found for a CurveMap.
INTERVAL_THETAS = 1801
#: How far past the alpha axis the boundary curves are traced [deg].
CURVE_MARGIN_DEG = 10.0
#: How far past the alpha axis the stability margin is sampled [deg].
STABILITY_MARGIN_DEG = 1.0
#: Contour grid of :func:`boundary_polylines` (theta nodes, alpha nodes).
CONTOUR_RESOLUTION = (721, 481)
#: Extra to install for the contour tracer (contourpy comes with matplotlib).
PLOT_EXTRA_HINT = "pip install 'deathsphere[plot]'"


@dataclass
class MapSetup:
    """What a map was computed for: body radius ``a`` and sphere radius
    ``r`` [m], inertia factor ``k``, the side, ``mu``, ``max_g``, ``g``
    [m/s^2], whether stability is shown, and the alpha axis [deg]."""

    a: float
    r: float
    k: float
    outside: bool
    mu: float
    max_g: float
    g: float
    stability: bool
    alpha_range_deg: tuple


@dataclass
class CellMap(MapSetup):
    """The allowed region sampled on a grid of cells.

    Row i (top = largest alpha) and column j have their centres at
    ``alpha_deg[i]`` and ``theta_deg[j]``; the columns split 0..180 deg
    evenly and the rows are centred on ``alpha_range_deg`` (both ends
    included).  ``feasible[i, j]`` is the centre's verdict; with
    ``stability`` the feasible centres are split into ``unstable`` and
    ``unknown`` ones (None without stability; the rest are stable).

    The boundaries: each of ``samples`` theta lines per column
    (``sample_theta_deg``) holds the alphas where a curve crosses it
    (``alpha_roots_deg[name]``, NaN-padded, shape (columns * samples, m));
    each of ``samples`` alpha lines per row (``sample_alpha_deg``, top first)
    the thetas (``theta_roots_deg[name]``).  Curve names as in
    :func:`deathsphere.physics.region.boundary_alphas`.
    """

    theta_deg: np.ndarray
    alpha_deg: np.ndarray
    feasible: np.ndarray
    unstable: np.ndarray | None
    unknown: np.ndarray | None
    samples: int
    sample_theta_deg: np.ndarray
    sample_alpha_deg: np.ndarray
    alpha_roots_deg: dict = field(default_factory=dict)
    theta_roots_deg: dict = field(default_factory=dict)


def cell_map(a, r, k, *, outside=False, mu=np.inf, max_g=np.inf, g=STANDARD_GRAVITY, stability=False,
             resolution=(DEFAULT_COLUMNS, None), alpha_range_deg=None) -> CellMap:
    """The allowed (theta, alpha) region on a grid of cells.

    Parameters
    ----------
    a, r : float, [m]   wheel and sphere radii (only a/r matters)
    k : float, [-]      inertia factor
    outside : bool      wheel outside the sphere (sec. 3)
    mu, max_g : float   friction coefficient and load limits (inf: none)
    g : float, [m/s^2]
    stability : bool    also the linear stability at every feasible cell
        centre: one batched call of
        :func:`deathsphere.physics.stability.wheel_stability` (beyond the
        paper, docs/stability.md)
    resolution : (columns, rows)   cells along theta and alpha; rows None:
        19 inside, 28 outside
    alpha_range_deg : (lo, hi) centres of the bottom and top rows [deg]
        (default 0..90 inside, 0..270 outside, where the paper's allowed
        regions lie)
    """
    ncol, nrow = resolution
    nrow = nrow or DEFAULT_ROWS[bool(outside)]
    if ncol < 1 or nrow < 2:
        raise ValueError(f"a cell map needs >= 1 column and >= 2 rows, got {ncol} x {nrow}")
    lo_d, hi_d = alpha_range_deg or CELL_ALPHA_RANGE_DEG[bool(outside)]
    # rows are centred on lo_d .. hi_d inclusive, so alpha = lo_d and hi_d
    # (eq. 29's alpha = 0 and 90 deg inside) fall on rows
    alpha_c = np.linspace(hi_d, lo_d, nrow)
    dal = (hi_d - lo_d) / (nrow - 1)
    dth = 180.0 / ncol
    theta_c = (np.arange(ncol) + 0.5) * dth

    th_c, al_c = np.meshgrid(np.deg2rad(theta_c), np.deg2rad(alpha_c))
    ok = region.feasible(th_c, al_c, a, r, k, g, outside=outside, mu=mu, max_g=max_g)
    unstable = unknown = None
    if stability:
        verdict = wheel_stability(th_c[ok], al_c[ok], a, r, k, g, outside)["verdict"]
        unstable, unknown = np.zeros(ok.shape, dtype=bool), np.zeros(ok.shape, dtype=bool)
        unstable[ok] = verdict == Verdict.UNSTABLE
        unknown[ok] = verdict == Verdict.UNKNOWN

    # boundaries: alpha roots on sub-column lines, theta roots on sub-row lines
    sub = SAMPLES_PER_CELL
    a_top, a_bot = np.deg2rad(hi_d + dal / 2), np.deg2rad(lo_d - dal / 2)
    th_s = np.deg2rad((np.arange(ncol * sub) + 0.5) * dth / sub)
    al_s = np.linspace(a_top, a_bot, nrow * sub + 1)[:-1] - np.deg2rad(dal) / (2 * sub)
    win = (np.full(th_s.shape, a_bot), np.full(th_s.shape, a_top))
    by_col = region.boundary_alphas(th_s, a, r, k, outside=outside, mu=mu, max_g=max_g, window=win)
    by_row = region.boundary_thetas(al_s, a, r, k, outside=outside, mu=mu, max_g=max_g)
    return CellMap(a=a, r=r, k=k, outside=bool(outside), mu=mu, max_g=max_g, g=g, stability=bool(stability),
                   alpha_range_deg=(lo_d, hi_d), theta_deg=theta_c, alpha_deg=alpha_c, feasible=ok,
                   unstable=unstable, unknown=unknown, samples=sub,
                   sample_theta_deg=np.rad2deg(th_s), sample_alpha_deg=np.rad2deg(al_s),
                   alpha_roots_deg={name: np.rad2deg(v) for name, v in by_col.items()},
                   theta_roots_deg={name: np.rad2deg(v) for name, v in by_row.items()})


# ---------------------------------------------------------------------------
# curves


@dataclass
class CurveMap(MapSetup):
    """The allowed region as curves, for an alpha axis ``alpha_range_deg``.

    ``interval_theta_deg`` (n,) with ``interval_lo_deg``, ``interval_hi_deg``
    (n, m) and ``interval_count`` (n,): the allowed alpha intervals at each
    theta (:func:`deathsphere.physics.region.allowed_alpha`, NaN-padded).
    ``boundaries``: curve name -> list of (theta, alpha) polylines [rad]
    (:func:`boundary_polylines`).  With ``stability``: the margin grid
    (``margin`` (len(margin_alpha_deg), len(margin_theta_deg)), > 0 stable,
    < 0 unstable, NaN where not computed) and ``stability_lines``, its zero
    contour inside the allowed region as (theta_deg, alpha_deg) pieces;
    all four None without stability.
    """

    interval_theta_deg: np.ndarray
    interval_lo_deg: np.ndarray
    interval_hi_deg: np.ndarray
    interval_count: np.ndarray
    boundaries: dict
    margin_theta_deg: np.ndarray | None = None
    margin_alpha_deg: np.ndarray | None = None
    margin: np.ndarray | None = None
    stability_lines: list | None = None


def curve_map(a, r, k, *, outside=False, mu=np.inf, max_g=np.inf, g=STANDARD_GRAVITY, stability=False,
              resolution=0.25, alpha_range_deg=None) -> CurveMap:
    """The allowed (theta, alpha) region as curves, for a figure of the
    alpha axis ``alpha_range_deg`` [deg] (default -5..95 inside, -5..275
    outside).

    The boundary curves are contoured from the exact boundary functions of
    :mod:`deathsphere.physics.region` on a grid (which gives their
    topology: branches, folds, crossings) and every vertex is then moved
    onto the curve by Newton steps, so they are exact to ~1e-13 rad, not to
    the grid; they reach CURVE_MARGIN_DEG past the axis.  The allowed
    intervals are root-found on INTERVAL_THETAS thetas.

    With ``stability`` the signed margin of
    :func:`deathsphere.physics.stability.margin.stability_margin` is computed
    on a grid of ``resolution`` [deg] (a bit past the axis) and its zero
    contour is traced, each vertex bisected onto the zero along its grid
    edge, so the curve is exact at the vertices; features thinner than a
    cell (the tips of narrow tongues) are not resolved.  Needs contourpy
    (the ``plot`` extra).
    """
    lo_d, hi_d = alpha_range_deg or CURVE_ALPHA_RANGE_DEG[bool(outside)]
    th = np.linspace(1e-4, np.pi - 1e-4, INTERVAL_THETAS)
    iv = region.allowed_alpha(th, a, r, k, g, outside=outside, mu=mu, max_g=max_g)
    extra = {}
    if stability:
        th_d, al_d, margin, _ = stability_grid(
            a, r, k, g=g, outside=outside, mu=mu, max_g=max_g,
            alpha_range_deg=(lo_d - STABILITY_MARGIN_DEG, hi_d + STABILITY_MARGIN_DEG), resolution_deg=resolution)
        extra = dict(margin_theta_deg=th_d, margin_alpha_deg=al_d, margin=margin,
                     stability_lines=_stability_lines(th_d, al_d, margin, a, r, k, g, outside, mu, max_g,
                                                      resolution))
    margin_rad = np.deg2rad(CURVE_MARGIN_DEG)
    curves = boundary_polylines(a, r, k, outside=outside, mu=mu, max_g=max_g,
                                alpha_range=(np.deg2rad(lo_d) - margin_rad, np.deg2rad(hi_d) + margin_rad))
    return CurveMap(a=a, r=r, k=k, outside=bool(outside), mu=mu, max_g=max_g, g=g, stability=bool(stability),
                    alpha_range_deg=(lo_d, hi_d), interval_theta_deg=np.rad2deg(th),
                    interval_lo_deg=np.rad2deg(iv.lo), interval_hi_deg=np.rad2deg(iv.hi),
                    interval_count=iv.count, boundaries=curves, **extra)


def _contourpy():
    try:
        import contourpy
    except ImportError as exc:
        raise ImportError(f"tracing the boundary curves needs contourpy, which is not installed; "
                          f"install the extra: {PLOT_EXTRA_HINT}") from exc
    return contourpy


def _contours(values, th, al):
    """Zero contours of values (len(al), len(th)) as a list of (N, 2) arrays."""
    contourpy = _contourpy()
    gen = contourpy.contour_generator(th, al, values, line_type=contourpy.LineType.Separate)
    return [seg for seg in gen.lines(0.0) if len(seg) > 1]


def boundary_polylines(a, r, k, *, outside=False, mu=np.inf, max_g=np.inf,
                       alpha_range=None, resolution=CONTOUR_RESOLUTION):
    """Boundary curves as polylines: dict name -> list of (theta, alpha)
    arrays [rad], each vertex on its curve to ~1e-13 rad
    (:func:`deathsphere.physics.region.project_to_boundary`).  Curves ``mu``
    and ``max_g`` are cut (NaN) where the orbit is not otherwise feasible.
    ``alpha_range`` [rad] defaults to -10..100 deg inside, -10..280 outside.
    Needs contourpy (the ``plot`` extra)."""
    _contourpy()
    lo, hi = alpha_range if alpha_range is not None else np.deg2rad((-10.0, 280.0) if outside else (-10.0, 100.0))
    # grids offset from round numbers, so no grid node lies exactly on alpha = 0, 90 deg
    th = np.linspace(1e-4, np.pi - 1e-4, resolution[0])
    al = np.linspace(lo - 0.00123, hi + 0.00177, resolution[1])
    T, A = np.meshgrid(th, al)
    factors = region.boundary_factors(T, A, a, r, k, outside=outside, mu=mu, max_g=max_g)
    out = {}
    for name, values in factors.items():
        lines = []
        for index, val in enumerate(values):
            for seg in _contours(val, th, al):
                t, x, _ = region.project_to_boundary(name, index, seg[:, 0], seg[:, 1], a, r, k,
                                                     outside=outside, mu=mu, max_g=max_g)
                if name in ("mu", "max_g"):
                    orb_ok = region.feasible(t, x, a, r, k, outside=outside)
                    x = np.where(orb_ok, x, np.nan)
                    if not np.any(orb_ok):
                        continue
                lines.append((t, x))
        out[name] = lines
    return out


def _dilate(mask, cells):
    """mask grown by ``cells`` cells in every direction (8-neighbourhood)."""
    for _ in range(cells):
        p = np.pad(mask, 1)
        mask = np.zeros_like(mask)
        for di in (0, 1, 2):
            for dj in (0, 1, 2):
                mask = mask | p[di:di + mask.shape[0], dj:dj + mask.shape[1]]
    return mask


def stability_grid(a, r, k, *, g=STANDARD_GRAVITY, outside=False, mu=np.inf, max_g=np.inf,
                   alpha_range_deg=(-5.0, 95.0), resolution_deg=0.25):
    """The stability margin on a (theta, alpha) grid (beyond the paper,
    docs/stability.md): returns ``(theta_deg, alpha_deg, margin, allowed)``,
    margin (len(alpha_deg), len(theta_deg)) from
    :func:`deathsphere.physics.stability.margin.stability_margin` (> 0 stable, < 0 unstable),
    computed at the feasible nodes and two cells around them (NaN
    elsewhere and where no orbit exists); ``allowed`` the feasible nodes."""
    from deathsphere.physics.stability import stability_margin

    lo_d, hi_d = alpha_range_deg
    th_d = np.arange(0.5 * resolution_deg, 180.0, resolution_deg)
    # offset from round numbers: no node on alpha = 0 or 90 deg (eq. 29)
    al_d = np.arange(lo_d + 0.37 * resolution_deg, hi_d + resolution_deg, resolution_deg)
    T, A = np.meshgrid(np.deg2rad(th_d), np.deg2rad(al_d))
    allowed = region.feasible(T, A, a, r, k, g, outside=outside, mu=mu, max_g=max_g)
    near = _dilate(allowed, 2)
    margin = np.full(T.shape, np.nan)
    margin[near] = stability_margin(T[near], A[near], a, r, k, g, outside)
    return th_d, al_d, margin, allowed


def _refine_on_edges(seg, th_d, al_d, values, fun, steps=20):
    """Contour vertices (deg) moved onto the zero of ``fun(theta_deg,
    alpha_deg)`` by bisection along the grid edge each lies on (the
    contour interpolates linearly between two nodes of opposite sign; the
    margin is not linear across a cell, so the drawn curve would wiggle)."""
    t, x = seg[:, 0].copy(), seg[:, 1].copy()
    it = np.clip(np.searchsorted(th_d, t), 1, th_d.size - 1)
    ia = np.clip(np.searchsorted(al_d, x), 1, al_d.size - 1)
    tol = 1e-9 * (th_d[1] - th_d[0])
    on_theta = np.minimum(np.abs(t - th_d[it - 1]), np.abs(t - th_d[it])) <= tol   # edge along alpha
    i_t = np.where(np.abs(t - th_d[it - 1]) <= tol, it - 1, it)
    i_a = np.where(np.abs(x - al_d[ia - 1]) <= tol, ia - 1, ia)
    # bracket ends: (lo, hi) along the edge, and the value at lo
    lo = np.where(on_theta, al_d[ia - 1], th_d[it - 1])
    hi = np.where(on_theta, al_d[ia], th_d[it])
    v_lo = np.where(on_theta, values[ia - 1, i_t], values[i_a, it - 1])
    v_hi = np.where(on_theta, values[ia, i_t], values[i_a, it])
    ok = np.isfinite(v_lo) & np.isfinite(v_hi) & (np.sign(v_lo) * np.sign(v_hi) < 0)
    lo, hi, s_lo, fixed, on_theta = lo[ok], hi[ok], np.sign(v_lo[ok]), np.where(on_theta, t, x)[ok], on_theta[ok]
    for _ in range(steps):
        mid = 0.5 * (lo + hi)
        same = np.sign(fun(np.where(on_theta, fixed, mid), np.where(on_theta, mid, fixed))) == s_lo
        lo, hi = np.where(same, mid, lo), np.where(same, hi, mid)
    mid = 0.5 * (lo + hi)
    t[ok] = np.where(on_theta, fixed, mid)
    x[ok] = np.where(on_theta, mid, fixed)
    return np.column_stack((t, x))


def _stability_lines(th_d, al_d, margin, a, r, k, g, outside, mu, max_g, resolution_deg, densify=8):
    """Zero contours of the margin as (theta_deg, alpha_deg) pieces inside
    the allowed region.  Each contour segment is subdivided ``densify``
    times before the cut, so that a piece ends within 1/densify of a cell of
    the region's edge; pieces shorter than two cells (the unresolved tips of
    tongues thinner than a cell) are left out."""
    from deathsphere.physics.stability import stability_margin

    pieces = []
    for seg in _contours(np.ma.masked_invalid(margin), th_d, al_d):
        seg = _refine_on_edges(seg, th_d, al_d, margin,
                               lambda t, x: stability_margin(np.deg2rad(t), np.deg2rad(x), a, r, k, g, outside))
        s = np.linspace(0.0, len(seg) - 1, (len(seg) - 1) * densify + 1)
        t = np.interp(s, np.arange(len(seg)), seg[:, 0])
        x = np.interp(s, np.arange(len(seg)), seg[:, 1])
        ok = region.feasible(np.deg2rad(t), np.deg2rad(x), a, r, k, g, outside=outside, mu=mu, max_g=max_g)
        edges = np.flatnonzero(np.diff(np.concatenate(([0], ok.astype(int), [0]))))
        for start, stop in zip(edges[::2], edges[1::2]):
            tp, xp = t[start:stop], x[start:stop]
            if np.sum(np.hypot(np.diff(tp), np.diff(xp))) >= 2 * resolution_deg:
                pieces.append((tp, xp))
    return pieces
