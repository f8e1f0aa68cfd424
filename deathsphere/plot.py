"""The allowed (theta, alpha) region of horizontal wheel orbits as a figure --
McDonald (1993) figure "alpha_wh" -- drawn with matplotlib.

matplotlib is optional (``pip install 'deathsphere[plot]'``) and imported
only when a figure is made; without it :func:`plot_map` raises
:class:`PlotExtraMissing`, an ImportError naming the extra.

The boundary curves are contoured from the exact boundary functions of
:mod:`deathsphere.physics.region` on a grid (which gives their topology:
branches, folds, crossings) and every vertex is then moved onto the curve
by Newton steps (:func:`deathsphere.physics.region.project_to_boundary`), so
the drawn curves are exact to ~1e-13 rad, not to the grid.  The allowed
region is filled between the root-found interval ends of
:func:`deathsphere.physics.region.allowed_alpha` on a fine theta grid.

With ``stability=True`` (beyond the paper, docs/stability.md "Stability
maps") the allowed region is split into its stable and unstable parts by
the exact linear stability of each orbit: the signed margin of
:func:`deathsphere.physics.stability.margin.stability_margin` (> 0 stable, < 0 unstable) is
computed on a grid of ``stability_resolution_deg`` (0.25 deg), its zero
contour is drawn (each vertex bisected onto the zero along its grid edge,
so the curve is exact at the vertices; features thinner than a cell, e.g.
the tips of narrow tongues, are not resolved) and the negative part is
filled, clipped to the allowed region.
"""

from __future__ import annotations

import importlib
from pathlib import Path

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics import region

EXTRA_HINT = "pip install 'deathsphere[plot]'"
FORMATS = ("png", "svg", "pdf")

#: name -> (legend label inside, legend label outside, matplotlib style)
CURVES = {
    "eq0": (*region.BOUNDARY_LABELS["eq0"], dict(color="#c0392b", lw=1.6, ls="-")),
    "eq29": (*region.BOUNDARY_LABELS["eq29"], dict(color="#1f4e9c", lw=1.6, ls="--")),
    "eq33": (*region.BOUNDARY_LABELS["eq33"], dict(color="#7b2d8e", lw=1.6, ls="-.")),
    "mu": (region.BOUNDARY_LABELS["mu"][0] + " ({mu:g})", None, dict(color="#1e8449", lw=1.4, ls=":")),
    "max_g": (region.BOUNDARY_LABELS["max_g"][0] + " ({max_g:g})", None,
              dict(color="#d35400", lw=1.4, ls=(0, (5, 2, 1, 2)))),
}
FILL = "#d6e4f0"
#: with ``stability``: the allowed region's stable part keeps FILL, the
#: unstable part is UNSTABLE_FILL, the boundary between them STABILITY_STYLE.
UNSTABLE_FILL = "#f5cfca"
STABILITY_STYLE = dict(color="black", lw=1.3, ls="-")
STABILITY_LABEL = "stability boundary (exact linearisation)"


class PlotExtraMissing(ImportError):
    """matplotlib is not installed: the ``plot`` extra is needed."""


def _matplotlib():
    """Import matplotlib (Agg backend unless one is chosen) or raise
    :class:`PlotExtraMissing` with the install hint."""
    try:
        mpl = importlib.import_module("matplotlib")
    except ImportError as exc:
        raise PlotExtraMissing(
            f"plotting needs matplotlib, which is not installed; install the extra: {EXTRA_HINT}"
        ) from exc
    return mpl


def _format(output):
    suffix = Path(output).suffix.lower().lstrip(".")
    if suffix not in FORMATS:
        raise ValueError(f"output must end in .png, .svg or .pdf, got {str(output)!r}")
    return suffix


def _contours(values, th, al):
    """Zero contours of values (len(al), len(th)) as a list of (N, 2) arrays."""
    import contourpy

    gen = contourpy.contour_generator(th, al, values, line_type=contourpy.LineType.Separate)
    return [seg for seg in gen.lines(0.0) if len(seg) > 1]


def boundary_polylines(a, r, k, *, outside=False, mu=np.inf, max_g=np.inf,
                       alpha_range=None, resolution=(721, 481)):
    """Boundary curves as polylines: dict name -> list of (theta, alpha)
    arrays [rad].  Curves ``mu`` and ``max_g`` are cut (NaN) where the orbit
    is not otherwise feasible.  Needs contourpy (a matplotlib dependency)."""
    _matplotlib()
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


def _region_quads(iv_theta, iv):
    """Quadrilaterals filling the allowed intervals between neighbouring
    thetas (intervals matched when they overlap)."""
    quads = []
    for i in range(iv_theta.size - 1):
        for j in range(int(iv.count[i])):
            a0, b0 = iv.lo[i, j], iv.hi[i, j]
            for jj in range(int(iv.count[i + 1])):
                a1, b1 = iv.lo[i + 1, jj], iv.hi[i + 1, jj]
                if a1 < b0 and a0 < b1:
                    quads.append([(iv_theta[i], a0), (iv_theta[i + 1], a1),
                                  (iv_theta[i + 1], b1), (iv_theta[i], b0)])
    return quads


def _dilate(mask, cells):
    """mask grown by ``cells`` cells in every direction (8-neighbourhood)."""
    for _ in range(cells):
        p = np.pad(mask, 1)
        mask = np.zeros_like(mask)
        for di in (0, 1, 2):
            for dj in (0, 1, 2):
                mask = mask | p[di:di + mask.shape[0], dj:dj + mask.shape[1]]
    return mask


def _extend(values, cells):
    """NaN cells next to finite ones get the mean of their finite
    4-neighbours, ``cells`` times: the field then reaches past the edge of
    the orbits' existence (eq. 0 / 29), so that a fill clipped to the
    allowed region leaves no gap there."""
    for _ in range(cells):
        p = np.pad(values, 1, constant_values=np.nan)
        nbrs = np.stack([p[:-2, 1:-1], p[2:, 1:-1], p[1:-1, :-2], p[1:-1, 2:]])
        count = np.sum(np.isfinite(nbrs), axis=0)
        total = np.sum(np.nan_to_num(nbrs, nan=0.0), axis=0)
        fill = np.isnan(values) & (count > 0)
        values = np.where(fill, total / np.maximum(count, 1), values)
    return values


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
    tongues thinner than a cell) are not drawn."""
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


def plot_map(a, r, k, *, outside=False, mu=np.inf, max_g=np.inf, g=STANDARD_GRAVITY, output=None,
             alpha_range_deg=None, points=None, points_label="orbits", title=None, dpi=200,
             stability=False, stability_resolution_deg=0.25):
    """Figure of the allowed (theta, alpha) region, McDonald (1993) figure
    "alpha_wh" (a/r = 0.1 there), with the boundaries of eqs. (0), (29),
    (33) (eqs. (81), (83) outside) and, when given, the limits mu and max_g.

    Parameters
    ----------
    a, r : float, [m];  k : float, [-];  outside : bool;  mu, max_g : float
    output : path ending in .png, .svg or .pdf, or None (no file written)
    alpha_range_deg : (lo, hi) of the alpha axis [deg] (default -5..95
        inside, -5..275 outside)
    points : optional (theta_deg, alpha_deg) pairs to mark (e.g. Table 1)
    stability : bool   shade the stable and unstable parts of the allowed
        region differently and draw the boundary between them (exact
        linearisation, beyond the paper: docs/stability.md), from a grid of
        ``stability_resolution_deg`` [deg]

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    PlotExtraMissing  when matplotlib is not installed
    ValueError        for an output name that is not .png/.svg/.pdf
    """
    fmt = _format(output) if output is not None else None
    _matplotlib()
    from matplotlib.collections import PolyCollection
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    from matplotlib.path import Path as MplPath

    lo_d, hi_d = alpha_range_deg or ((-5.0, 275.0) if outside else (-5.0, 95.0))
    fig = Figure(figsize=(7.5, 5.6 if not outside else 7.0), layout="constrained")
    ax = fig.add_subplot()

    th = np.linspace(1e-4, np.pi - 1e-4, 1801)
    iv = region.allowed_alpha(th, a, r, k, g, outside=outside, mu=mu, max_g=max_g)
    quads = _region_quads(np.rad2deg(th), type(iv)(iv.theta, np.rad2deg(iv.lo), np.rad2deg(iv.hi),
                                                   iv.speed_min, iv.speed_max, iv.count))
    ax.add_collection(PolyCollection(quads, facecolors=FILL, edgecolors=FILL, linewidths=0.3, zorder=1))
    handles = [Patch(facecolor=FILL, edgecolor="#8aa9c4", lw=0.6,
                     label="allowed, stable" if stability else "allowed")]
    if stability:
        th_d, al_d, margin, _ = stability_grid(a, r, k, g=g, outside=outside, mu=mu, max_g=max_g,
                                               alpha_range_deg=(lo_d - 1.0, hi_d + 1.0),
                                               resolution_deg=stability_resolution_deg)
        field = _extend(margin, 2)
        if np.any(field < 0):
            clip = MplPath.make_compound_path(*(MplPath(np.vstack((q, q[:1])), closed=True) for q in quads))
            fill = ax.contourf(th_d, al_d, np.ma.masked_invalid(field), levels=[np.nanmin(field) - 1.0, 0.0],
                               colors=[UNSTABLE_FILL], zorder=1.5, antialiased=True)
            fill.set_clip_path(clip, ax.transData)
            handles.append(Patch(facecolor=UNSTABLE_FILL, edgecolor="#c98a82", lw=0.6,
                                 label="allowed, unstable"))
        lines = _stability_lines(th_d, al_d, margin, a, r, k, g, outside, mu, max_g, stability_resolution_deg)
        for t, x in lines:
            ax.plot(t, x, zorder=2.5, **STABILITY_STYLE)
        if lines:
            handles.append(Line2D([], [], label=STABILITY_LABEL, **STABILITY_STYLE))

    margin = np.deg2rad(10.0)
    curves = boundary_polylines(a, r, k, outside=outside, mu=mu, max_g=max_g,
                                alpha_range=(np.deg2rad(lo_d) - margin, np.deg2rad(hi_d) + margin))
    for name, segs in curves.items():
        label_in, label_out, style = CURVES[name]
        label = ((label_out or label_in) if outside else label_in).format(mu=mu, max_g=max_g)
        for t, x in segs:
            ax.plot(np.rad2deg(t), np.rad2deg(x), zorder=3, solid_capstyle="butt", **style)
        if segs:
            handles.append(Line2D([], [], label=label, **style))
    if points is not None:
        pts = np.asarray(points, dtype=float).reshape(-1, 2)
        ax.plot(pts[:, 0], pts[:, 1], "o", ms=4, mfc="black", mec="white", mew=0.6, zorder=4)
        handles.append(Line2D([], [], ls="", marker="o", ms=4, mfc="black", mec="white",
                              label=points_label))

    ax.set_xlim(0, 180)
    ax.set_ylim(lo_d, hi_d)
    ax.set_xticks(np.arange(0, 181, 15))
    step = 15 if hi_d - lo_d <= 120 else 30
    ax.set_yticks(np.arange(np.ceil(lo_d / step) * step, hi_d + 1e-9, step))
    ax.set_xlabel(r"polar angle of the orbit $\theta$ [deg]  (90 = equator)")
    ax.set_ylabel(r"tilt of the wheel $\alpha$ [deg]")
    ax.grid(True, color="0.88", lw=0.5, zorder=0)
    ax.set_axisbelow(True)
    side = "outside" if outside else "inside"
    limits = []
    if np.isfinite(mu):
        limits.append(rf"$\mu$ = {mu:g}")
    if np.isfinite(max_g):
        limits.append(f"max {max_g:g} g")
    default_title = (("Stability of h" if stability else "H")
                     + f"orizontal orbits of a wheel {side} a sphere: a/r = {a / r:g}, k = {k:g}"
                     + (", " + ", ".join(limits) if limits else ""))
    ax.set_title(title or default_title, fontsize=11)
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncols=3,
              fontsize=8, frameon=False)
    if output is not None:
        fig.savefig(output, format=fmt, dpi=dpi)
    return fig
