"""Terminal character plot of the allowed (lane, alpha) region of a wheel
off the globe (a drum, a cone, flat ground, a profile): the globe's
``map`` chart (:mod:`deathsphere.render.charplot`) with the lane's height
above the floor (on flat ground the turn radius) along x in place of
theta.  Drawn from a :class:`deathsphere.results.lane_map.LaneCurves`;
this module computes nothing.

Each column is one of the map's lanes (the lane nearest the column's
middle); a cell is shaded where its alpha lies in an allowed interval of
that lane, and a boundary's character replaces the shading where one of
its points on that lane falls in the cell:

    #  S4   the wheel fits (eq. 0 on the globe)
    f  S5   the rim reaches the floor
    =  S2   Omega^2 = 0 or a pole (eq. 29 on the globe)
    *  S3   the normal force vanishes (eq. 33 on the globe)
    m       mu_required = mu         (only with a friction limit)
    g       load = max_g             (only with a load limit)
    .       allowed (with stability: allowed and stable)
    x       allowed but linearly unstable (only with stability)
"""

from __future__ import annotations

import math
import textwrap
from dataclasses import dataclass, field

import numpy as np

from deathsphere.render.charplot import MIN_WIDTH, SHADE, UNSTABLE, CharGrid

#: Boundary name -> (character, legend text), in drawing order (later wins).
MARKS = {"S2": ("=", "S2: Omega^2 = 0 or a pole"), "S5": ("f", "S5: the rim reaches the floor"),
         "S4": ("#", "S4: the wheel fits"), "S3": ("*", "S3: normal force = 0"),
         "mu": ("m", "mu_required = mu"), "max_g": ("g", "load = max_g")}
#: Legend texts outside (the convex side).
OUTSIDE_TEXT = {"S4": "S4: the wheel fits outside", "S3": "S3: normal force = 0 (outside)"}
#: Fewest rows of the chart.
MIN_ROWS = 13
#: Fewest lanes drawn as a chart (fewer: the lanes' table says it all).
MIN_LANES = 24
_LEFT = 6            # " -90 |"


@dataclass
class LaneCharMap(CharGrid):
    """The map off the globe over (lane, alpha): column j is the lane
    ``x_m[j]`` (its height, on flat ground its turn radius)."""

    x_m: np.ndarray = field(kw_only=True)


def drawable(curves) -> bool:
    """Whether ``curves`` has lanes enough, in increasing order, for a chart."""
    x = np.asarray(curves.x_m, dtype=float)
    return x.size >= MIN_LANES and bool(np.all(np.diff(x) > 0))


def _alpha_range(curves):
    """The chart's alpha span [deg]: the allowed intervals' extent out to
    multiples of 30 deg (the boundaries beyond it are not drawn); where no
    tilt is allowed on any lane, the fit's (S4), else -90 .. 90."""
    values = np.concatenate([curves.lo_deg[np.isfinite(curves.lo_deg)], curves.hi_deg[np.isfinite(curves.hi_deg)]])
    if values.size == 0 and "S4" in curves.points:
        values = np.asarray(curves.points["S4"][1], dtype=float)
        values = values[np.isfinite(values)]
    if values.size == 0:
        return -90.0, 90.0
    lo = 30.0 * math.floor(float(values.min()) / 30.0 + 1e-9)
    hi = 30.0 * math.ceil(float(values.max()) / 30.0 - 1e-9)
    return lo, hi if hi > lo else lo + 30.0


def _rows(lo, hi):
    """Rows of the chart for the span [lo, hi] deg: the coarsest step that
    divides 30 deg (so that the ticks fall on rows) and still gives at least
    MIN_ROWS rows (a narrow band of tilts gets fine rows)."""
    span = hi - lo
    step = next((d for d in (30.0, 15.0, 10.0, 5.0, 2.5, 2.0) if span / d + 1 >= MIN_ROWS), 1.0)
    return int(round(span / step)) + 1


def where_on(ground_name: str, outside: bool) -> str:
    """"inside the cone", "outside the drum"; flat ground has one side."""
    if ground_name == "plane":
        return "on flat ground"
    return f"{'outside' if outside else 'inside'} the {ground_name}"


def _ticks(x0, x1):
    """A few round values of x in [x0, x1]."""
    span = x1 - x0
    raw = span / 5 if span > 0 else 1.0
    step = 10.0 ** math.floor(math.log10(raw))
    step *= next(m for m in (1, 2, 5, 10) if m * step >= raw)
    first = math.ceil(x0 / step - 1e-9) * step
    return np.arange(first, x1 + 1e-9 * max(span, 1.0), step)


def _label(v):
    return f"{0.0 if abs(v) < 1e-12 else v:g}"


def lane_label(curves, unit=None) -> str:
    """The lanes' axis name in ``unit`` (a
    :class:`~deathsphere.render.display_units.DisplayUnit`; None: metres)."""
    return curves.x_label if unit is None else curves.x_label.replace("[m]", f"[{unit.name}]")


def lane_char_map(curves, width: int, unit=None) -> LaneCharMap:
    """The chart of ``curves`` in ``width`` characters (>= MIN_WIDTH), for
    :func:`drawable` curves; the lanes' axis in ``unit`` (a
    :class:`~deathsphere.render.display_units.DisplayUnit`, the one typed:
    ft for ``--wall-height 12ft``; None: metres)."""
    if width < MIN_WIDTH:
        raise ValueError(f"width must be >= {MIN_WIDTH} characters, got {width}")
    x = np.asarray(curves.x_m, dtype=float)
    ncol = width - _LEFT - 2
    x0, x1 = float(x[0]), float(x[-1])
    centres = x0 + (np.arange(ncol) + 0.5) / ncol * (x1 - x0)
    lane = np.clip(np.searchsorted(x, centres), 1, x.size - 1)
    lane = np.where(np.abs(x[lane - 1] - centres) <= np.abs(x[lane] - centres), lane - 1, lane)   # nearest
    lo_d, hi_d = _alpha_range(curves)
    rows = _rows(lo_d, hi_d)
    alpha = np.linspace(hi_d, lo_d, rows)                   # top row = largest alpha
    dal = (hi_d - lo_d) / (rows - 1)

    a = alpha[:, None, None]
    lo, hi = curves.lo_deg[lane][None], curves.hi_deg[lane][None]
    allowed = np.any((a > lo) & (a < hi), axis=-1)      # open: a boundary is not an orbit
    grid = np.where(allowed, SHADE, " ").astype("<U1")
    if curves.stable is not None:
        s_lo, s_hi = curves.stable[0][lane][None], curves.stable[1][lane][None]
        stable = np.any((a > s_lo) & (a < s_hi), axis=-1)
        grid[allowed & ~stable] = UNSTABLE

    legend = {}
    for name, (ch, text) in MARKS.items():
        if name not in curves.points:
            continue
        px, pa = (np.asarray(v, dtype=float) for v in curves.points[name])
        i = np.floor((hi_d + dal / 2 - pa) / dal)
        on_chart = np.isfinite(i) & (i >= 0) & (i < rows)
        point_lane = np.searchsorted(x, px[on_chart]).clip(0, x.size - 1)
        # every column that shows a point's lane (a lane may fill several columns)
        p, j = np.nonzero(point_lane[:, None] == lane[None, :])
        if p.size:
            grid[i[on_chart][p].astype(int), j] = ch
            legend[ch] = OUTSIDE_TEXT.get(name, text) if curves.outside else text

    title = (("Stability of allowed" if curves.stable is not None else "Allowed")
             + f" tilts of a wheel {where_on(curves.ground_name, curves.outside)}: a = {curves.a:g} m, k = {curves.k:g}")
    limits = [f"mu = {curves.mu:g}" if np.isfinite(curves.mu) else "",
              f"max g = {curves.max_g:g}" if np.isfinite(curves.max_g) else ""]
    limits = ", ".join(v for v in limits if v)
    if limits:
        title += f", {limits}"
    lines = [*textwrap.wrap(title, width), "alpha [deg]"]
    row0 = len(lines)
    for i in range(rows):
        on_tick = abs(alpha[i] / 30.0 - round(alpha[i] / 30.0)) < 1e-9
        label = _label(round(alpha[i], 1)) if on_tick or i in (0, rows - 1) else ""
        lines.append(f"{label:>{_LEFT - 2}} |" + "".join(grid[i]))
    lines.append(" " * (_LEFT - 1) + "+" + "-" * ncol)
    per = 1.0 if unit is None else unit.per_api_unit
    # round values in the unit shown, each centred under the column whose centre is
    # nearest it (column j's centre is x0 + (j + 1/2) / ncol of the span, in metres)
    values = _ticks(x0 * per, x1 * per)
    cols = np.clip(np.round((values / per - x0) / (x1 - x0) * ncol - 0.5), 0, ncol - 1).astype(int) \
        if x1 > x0 else np.zeros(values.size, int)
    ticks = [" "] * (ncol + 2)
    for value, col in zip(values, cols):
        s = _label(float(np.round(value, 10)))
        start = min(max(col - len(s) // 2, 0), ncol + 2 - len(s))
        ticks[start:start + len(s)] = list(s)
    lines.append(" " * _LEFT + "".join(ticks).rstrip())
    lines.append(" " * (_LEFT - 1) + lane_label(curves, unit).center(ncol).rstrip())
    shades = [f"{SHADE} allowed, stable", f"{UNSTABLE} allowed, unstable"] if curves.stable is not None \
        else [f"{SHADE} allowed"]
    line = " "
    for item in [f"{ch} {text}" for ch, text in legend.items()] + shades:
        if len(line) + len(item) + 3 > width:
            lines.append(line.rstrip())
            line = " "
        line += item + "   "
    lines.append(line.rstrip())
    return LaneCharMap(lines=lines, cells=["".join(row) for row in grid], x_m=x[lane], alpha_deg=alpha,
                       row0=row0, col0=_LEFT, legend=legend)
