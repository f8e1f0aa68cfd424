"""The allowed (lane, alpha) region of a wheel on a drum, a cone, flat
ground or a profile as a figure, drawn with matplotlib from a
:class:`deathsphere.results.lane_map.LaneCurves` (this module computes
nothing): the globe's map (:mod:`deathsphere.render.map_figure`) with the
lane's height, or flat ground's turn radius, along x in place of theta.

The allowed region is filled between the interval ends of neighbouring
lanes; each boundary's points (root-found on every lane) are drawn as a
dotted trace in the globe's colours for the same conditions.
"""

from __future__ import annotations

import numpy as np

from deathsphere.render.figures import figure_format, import_matplotlib, save_figure
from deathsphere.render.map_figure import CURVES, FILL, STABILITY_STYLE, _region_quads

#: Off-globe boundary -> the globe's curve of the same condition (its colour)
#: and the legend's words.
STYLES = {
    "S4": ("eq0", "fit (S4)"),
    "S5": ("eq29", "floor (S5)"),
    "S2": ("eq29", r"$\Omega^2$ = 0 or pole (S2 = eq. 29)"),
    "S3": ("eq33", "contact (S3)"),
    "mu": ("mu", r"friction $\mu$ = {mu:g}"),
    "max_g": ("max_g", "load {max_g:g} g"),
    "stability": ("stability", "stability boundary (exact linearisation)"),
}
#: The floor's own colour (the globe has no floor).
FLOOR_COLOUR = "#7f8c8d"


def plot_lane_map(curves, *, output=None, title=None, dpi=200):
    """Figure of the allowed region in ``curves`` (a LaneCurves): filled
    where a tilt is feasible (docs/limits.md sec. 8), its boundaries traced.
    ``output`` a path ending in .png, .svg or .pdf, or None.  Returns the
    matplotlib Figure; raises PlotExtraMissing without matplotlib."""
    fmt = figure_format(output) if output is not None else None
    import_matplotlib()
    from matplotlib.collections import PolyCollection
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    fig = Figure(figsize=(7.5, 5.6), layout="constrained")
    ax = fig.add_subplot()
    quads = _region_quads(curves.x_m, curves.lo_deg, curves.hi_deg, curves.count)
    ax.add_collection(PolyCollection(quads, facecolors=FILL, edgecolors=FILL, linewidths=0.3, zorder=1))
    handles = [Patch(facecolor=FILL, edgecolor="#8aa9c4", lw=0.6, label="allowed")]
    shown = [np.asarray(curves.lo_deg)[np.isfinite(curves.lo_deg)],
             np.asarray(curves.hi_deg)[np.isfinite(curves.hi_deg)]]
    shown = np.concatenate(shown)
    lo_d = min(-5.0, float(np.min(shown)) - 5.0) if shown.size else -5.0
    hi_d = max(95.0, float(np.max(shown)) + 5.0) if shown.size else 95.0
    for name, (x, alpha) in curves.points.items():
        globe, words = STYLES[name]
        colour = FLOOR_COLOUR if name == "S5" else STABILITY_STYLE["color"] if name == "stability" else \
            CURVES[globe][2]["color"]
        keep = (alpha >= lo_d) & (alpha <= hi_d)
        if keep.any():
            ax.plot(x[keep], alpha[keep], ".", ms=1.6, color=colour, zorder=3)
            handles.append(Line2D([], [], ls="", marker="o", ms=4, color=colour,
                                  label=words.format(mu=curves.mu, max_g=curves.max_g)))
    ax.set_xlim(float(np.min(curves.x_m)), float(np.max(curves.x_m)))
    ax.set_ylim(lo_d, hi_d)
    ax.set_xlabel(curves.x_label)
    ax.set_ylabel(r"tilt of the wheel $\alpha$ [deg]")
    ax.grid(True, color="0.88", lw=0.5, zorder=0)
    ax.set_axisbelow(True)
    limits = []
    if np.isfinite(curves.mu):
        limits.append(rf"$\mu$ = {curves.mu:g}")
    if np.isfinite(curves.max_g):
        limits.append(f"max {curves.max_g:g} g")
    side = "outside" if curves.outside else "inside"
    default_title = (f"Horizontal orbits of a wheel {side} the {curves.ground_name}: a = {curves.a:g} m, "
                     f"k = {curves.k:g}" + (", " + ", ".join(limits) if limits else ""))
    ax.set_title(title or default_title, fontsize=11)
    ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.12), ncols=3, fontsize=8,
              frameon=False)
    if output is not None:
        save_figure(fig, output, fmt, dpi)
    return fig
