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
"""

from __future__ import annotations

import importlib
from pathlib import Path

import numpy as np

from deathsphere.physics import region

EXTRA_HINT = "pip install 'deathsphere[plot]'"
FORMATS = ("png", "svg", "pdf")

#: name -> (legend label inside, legend label outside, matplotlib style)
CURVES = {
    "eq0": ("eq. (0): wheel fits", "eq. (81): wheel fits",
            dict(color="#c0392b", lw=1.6, ls="-")),
    "eq29": (r"eq. (29): $\Omega^2 = 0$ or $\Omega^2 \to \infty$", None,
             dict(color="#1f4e9c", lw=1.6, ls="--")),
    "eq33": ("eq. (33): normal force = 0", "eq. (83): normal force = 0",
             dict(color="#7b2d8e", lw=1.6, ls="-.")),
    "mu": (r"eq. (35): $\mu_{{\rm required}}$ = {mu:g}", None, dict(color="#1e8449", lw=1.4, ls=":")),
    "max_g": ("eq. (36): g-load = {max_g:g}", None, dict(color="#d35400", lw=1.4, ls=(0, (5, 2, 1, 2)))),
}
FILL = "#d6e4f0"


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


def plot_map(a, r, k, *, outside=False, mu=np.inf, max_g=np.inf, g=9.80665, output=None,
             alpha_range_deg=None, points=None, points_label="orbits", title=None, dpi=200):
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

    lo_d, hi_d = alpha_range_deg or ((-5.0, 275.0) if outside else (-5.0, 95.0))
    fig = Figure(figsize=(7.5, 5.6 if not outside else 7.0), layout="constrained")
    ax = fig.add_subplot()

    th = np.linspace(1e-4, np.pi - 1e-4, 1801)
    iv = region.allowed_alpha(th, a, r, k, g, outside=outside, mu=mu, max_g=max_g)
    quads = _region_quads(np.rad2deg(th), type(iv)(iv.theta, np.rad2deg(iv.lo), np.rad2deg(iv.hi),
                                                   iv.speed_min, iv.speed_max, iv.count))
    ax.add_collection(PolyCollection(quads, facecolors=FILL, edgecolors=FILL, linewidths=0.3, zorder=1))

    margin = np.deg2rad(10.0)
    curves = boundary_polylines(a, r, k, outside=outside, mu=mu, max_g=max_g,
                                alpha_range=(np.deg2rad(lo_d) - margin, np.deg2rad(hi_d) + margin))
    handles = [Patch(facecolor=FILL, edgecolor="#8aa9c4", lw=0.6, label="allowed")]
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
    default_title = (f"Horizontal orbits of a wheel {side} a sphere: a/r = {a / r:g}, k = {k:g}"
                     + (", " + ", ".join(limits) if limits else ""))
    ax.set_title(title or default_title, fontsize=11)
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncols=3,
              fontsize=8, frameon=False)
    if output is not None:
        fig.savefig(output, format=fmt, dpi=dpi)
    return fig
