"""The allowed (lane, alpha) region off the globe on a terminal: the
allowed intervals of alpha on a few of the map's lanes, as a rich table
(the figure is :mod:`deathsphere.render.lane_map_figure`; this module
computes nothing)."""

from __future__ import annotations

import numpy as np

#: Lanes shown on a terminal, evenly picked from the map's.
SHOWN_LANES = 13


def lane_map_text(curves, lanes: int = SHOWN_LANES, unit=None):
    """A rich Table of ``curves`` (a LaneCurves): one row per picked lane,
    its allowed alpha intervals [deg] ("none" where no tilt is feasible)
    and, with stability, their parts where the orbit is linearly stable
    (the exact linearisation; "none" where every allowed tilt is unstable).
    With ``unit`` (a :class:`~deathsphere.render.display_units.DisplayUnit`,
    the one the lanes were typed in) the lane in it follows the lane in m."""
    from rich.markup import escape

    from deathsphere.render.lane_charplot import lane_label, where_on
    from rich.table import Table as RichTable

    n = curves.x_m.size
    pick = np.unique(np.round(np.linspace(0, n - 1, min(lanes, n))).astype(int))
    limits = [f"mu = {curves.mu:g}" if np.isfinite(curves.mu) else "",
              f"max {curves.max_g:g} g" if np.isfinite(curves.max_g) else ""]
    limits = ", ".join(x for x in limits if x)
    what = "Stability of allowed" if curves.stable is not None else "Allowed"
    # escaped: rich reads "[m]" and "[deg]" as markup tags and would drop the units
    table = RichTable(title=escape(f"{what} tilts of a wheel {where_on(curves.ground_name, curves.outside)}: a = {curves.a:g} m, "
                            f"k = {curves.k:g}" + (f", {limits}" if limits else "")))
    table.add_column(escape(curves.x_label), justify="right")
    if unit is not None:
        table.add_column(escape(lane_label(curves, unit)), justify="right")
    table.add_column(escape("allowed alpha [deg]"))
    if curves.stable is not None:
        table.add_column(escape("stable alpha [deg]"))
    for i in pick:
        spans = [f"{curves.lo_deg[i, j]:.2f} .. {curves.hi_deg[i, j]:.2f}" for j in range(int(curves.count[i]))]
        lane = [f"{curves.x_m[i]:.4g}"] + ([] if unit is None else [f"{unit.of(curves.x_m[i]):.4g}"])
        row = [*lane, ",  ".join(spans) or "none"]
        if curves.stable is not None:
            lo, hi = curves.stable
            row.append(",  ".join(f"{lo[i, j]:.2f} .. {hi[i, j]:.2f}" for j in range(lo.shape[1])
                                  if np.isfinite(lo[i, j])) or "none")
        table.add_row(*row)
    return table
