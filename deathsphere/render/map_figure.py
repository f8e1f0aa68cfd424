"""The allowed (theta, alpha) region of horizontal wheel orbits as a figure --
McDonald (1993) figure "alpha_wh" -- drawn with matplotlib from a
:class:`deathsphere.results.region_map.CurveMap` (this module computes
nothing: the curves, intervals and stability margin come with the map).

The boundary curves are drawn as given (exact to ~1e-13 rad); the allowed
region is filled between the interval ends of neighbouring thetas.  With
stability (beyond the paper, docs/stability.md "Stability maps") the
allowed region is split into its stable part and its unstable part (where
the margin is negative, clipped to the allowed region) and the stability
boundary is drawn.

matplotlib is optional (:mod:`deathsphere.render.figures`).
"""

from __future__ import annotations

import numpy as np

from deathsphere.constants import BOUNDARY_LABELS
from deathsphere.render.figures import figure_format, import_matplotlib, save_figure

#: name -> (legend label inside, legend label outside, matplotlib style)
CURVES = {
    "eq0": (*BOUNDARY_LABELS["eq0"], dict(color="#c0392b", lw=1.6, ls="-")),
    "eq29": (*BOUNDARY_LABELS["eq29"], dict(color="#1f4e9c", lw=1.6, ls="--")),
    "eq33": (*BOUNDARY_LABELS["eq33"], dict(color="#7b2d8e", lw=1.6, ls="-.")),
    "mu": (BOUNDARY_LABELS["mu"][0] + " ({mu:g})", None, dict(color="#1e8449", lw=1.4, ls=":")),
    "max_g": (BOUNDARY_LABELS["max_g"][0] + " ({max_g:g})", None,
              dict(color="#d35400", lw=1.4, ls=(0, (5, 2, 1, 2)))),
}
FILL = "#d6e4f0"
#: with ``stability``: the allowed region's stable part keeps FILL, the
#: unstable part is UNSTABLE_FILL, the boundary between them STABILITY_STYLE.
UNSTABLE_FILL = "#f5cfca"
STABILITY_STYLE = dict(color="black", lw=1.3, ls="-")
STABILITY_LABEL = "stability boundary (exact linearisation)"


def _region_quads(iv_theta, iv_lo, iv_hi, iv_count):
    """Quadrilaterals filling the allowed intervals between neighbouring
    thetas (intervals matched when they overlap)."""
    quads = []
    for i in range(iv_theta.size - 1):
        for j in range(int(iv_count[i])):
            a0, b0 = iv_lo[i, j], iv_hi[i, j]
            for jj in range(int(iv_count[i + 1])):
                a1, b1 = iv_lo[i + 1, jj], iv_hi[i + 1, jj]
                if a1 < b0 and a0 < b1:
                    quads.append([(iv_theta[i], a0), (iv_theta[i + 1], a1),
                                  (iv_theta[i + 1], b1), (iv_theta[i], b0)])
    return quads


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


def plot_map(curves, *, output=None, points=None, points_label="orbits", title=None, dpi=200):
    """Figure of the allowed (theta, alpha) region in ``curves``, McDonald
    (1993) figure "alpha_wh" (a/r = 0.1 there), with the boundaries of eqs.
    (0), (29), (33) (eqs. (81), (83) outside) and, when the map has them,
    the limits mu and max_g; with ``curves.stability`` the stable and
    unstable parts of the allowed region shaded differently and the
    boundary between them drawn (exact linearisation, beyond the paper:
    docs/stability.md).  The alpha axis is ``curves.alpha_range_deg``.

    Parameters
    ----------
    curves : CurveMap  (:func:`deathsphere.results.region_map.curve_map`)
    output : path ending in .png, .svg or .pdf, or None (no file written)
    points : optional (theta_deg, alpha_deg) pairs to mark (e.g. Table 1)
    title : str or None (a default naming the setup);  dpi : int

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    PlotExtraMissing  when matplotlib is not installed
    ValueError        for an output name that is not .png/.svg/.pdf
    """
    fmt = figure_format(output) if output is not None else None
    import_matplotlib()
    from matplotlib.collections import PolyCollection
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch
    from matplotlib.path import Path as MplPath

    a, r, k, mu, max_g = curves.a, curves.r, curves.k, curves.mu, curves.max_g
    outside, stability = curves.outside, curves.stability
    lo_d, hi_d = curves.alpha_range_deg
    fig = Figure(figsize=(7.5, 5.6 if not outside else 7.0), layout="constrained")
    ax = fig.add_subplot()

    quads = _region_quads(curves.interval_theta_deg, curves.interval_lo_deg, curves.interval_hi_deg,
                          curves.interval_count)
    ax.add_collection(PolyCollection(quads, facecolors=FILL, edgecolors=FILL, linewidths=0.3, zorder=1))
    handles = [Patch(facecolor=FILL, edgecolor="#8aa9c4", lw=0.6,
                     label="allowed, stable" if stability else "allowed")]
    if stability:
        th_d, al_d = curves.margin_theta_deg, curves.margin_alpha_deg
        field = _extend(curves.margin, 2)
        if np.any(field < 0):
            clip = MplPath.make_compound_path(*(MplPath(np.vstack((q, q[:1])), closed=True) for q in quads))
            fill = ax.contourf(th_d, al_d, np.ma.masked_invalid(field), levels=[np.nanmin(field) - 1.0, 0.0],
                               colors=[UNSTABLE_FILL], zorder=1.5, antialiased=True)
            fill.set_clip_path(clip, ax.transData)
            handles.append(Patch(facecolor=UNSTABLE_FILL, edgecolor="#c98a82", lw=0.6,
                                 label="allowed, unstable"))
        lines = curves.stability_lines
        for t, x in lines:
            ax.plot(t, x, zorder=2.5, **STABILITY_STYLE)
        if lines:
            handles.append(Line2D([], [], label=STABILITY_LABEL, **STABILITY_STYLE))

    for name, segs in curves.boundaries.items():
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
        save_figure(fig, output, fmt, dpi)
    return fig
