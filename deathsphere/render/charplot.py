"""Terminal character plot of the allowed (theta, alpha) region of horizontal
wheel orbits -- McDonald (1993) figure "alpha_wh" in 80 columns -- drawn
from a :class:`deathsphere.results.region_map.CellMap` (this module computes
nothing: the cells' verdicts and the boundary crossings come with the map).

theta runs along x from 0 to 180 deg, alpha up y.  The boundary curves are
drawn with one character each and the allowed region is shaded:

    #  eq. (0)   the wheel fits (eq. (81) outside)
    =  eq. (29)  Omega^2 = 0 (alpha = 90 deg) or a pole (alpha = 0, r' = -k a cos(alpha)/(2k+1))
    *  eq. (33)  the normal force vanishes (eq. (83) outside)
    m  mu_required = mu        (only with a friction limit)
    g  load = max_g          (only with a load limit)
    .  allowed: a feasible orbit at the cell's centre
    x  allowed but linearly unstable (only with stability)
    ?  allowed, stability unknown (only with stability; rare)

A cell is shaded when its centre is feasible; a boundary character
replaces the shading where a curve crosses the cell (a root on one of the
map's sample lines through it).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from deathsphere.constants import BOUNDARY_LABELS

#: Character and legend text of each boundary, in drawing order (later wins).
MARKS = {name: (ch, BOUNDARY_LABELS[name][0])
         for name, ch in (("eq29", "="), ("eq0", "#"), ("eq33", "*"), ("mu", "m"), ("max_g", "g"))}
SHADE = "."
UNSTABLE = "x"
UNKNOWN = "?"
OUTSIDE_MARKS = {name: BOUNDARY_LABELS[name][1] for name in ("eq0", "eq33")}

#: rich styles for :func:`to_rich`.
STYLES = {"=": "bold blue", "#": "bold red", "*": "bold magenta", "m": "bold green",
          "g": "bold yellow", SHADE: "cyan", UNSTABLE: "red", UNKNOWN: "yellow"}

_LEFT = 6            # "  90 |"
#: Narrowest map drawn [characters].
MIN_WIDTH = 40


@dataclass
class CharGrid:
    """A rendered chart over alpha: ``lines`` to print, and the plot grid
    behind them (what :func:`to_rich` colours).

    ``cells[i][j]`` is the character at row i (top = largest alpha) and
    column j; row i's centre is ``alpha_deg[i]``; the grid's first row is
    ``lines[row0]`` starting at column ``col0``.  What a column is (a theta,
    a lane) is the subclass's.
    """

    lines: list
    cells: list
    alpha_deg: np.ndarray
    row0: int
    col0: int
    legend: dict = field(default_factory=dict)

    def __str__(self):
        return "\n".join(self.lines)


@dataclass
class CharMap(CharGrid):
    """The globe's map over (theta, alpha): column j's centre is ``theta_deg[j]``."""

    theta_deg: np.ndarray = field(kw_only=True)


def _fmt(x):
    return f"{x:g}"


def columns_for_width(width: int) -> int:
    """Theta columns of a map ``width`` characters wide (>= MIN_WIDTH):
    the cell grid to ask :func:`deathsphere.results.region_map.cell_map` for."""
    if width < MIN_WIDTH:
        raise ValueError(f"width must be >= {MIN_WIDTH} characters, got {width}")
    return width - _LEFT - 2


def char_map(cells) -> CharMap:
    """Character map of the allowed (theta, alpha) region in ``cells`` (a
    :class:`deathsphere.results.region_map.CellMap`, from :func:`deathsphere.region_cells`):
    one character per cell, the frame, axis labels and a legend, in
    ``len(cells.theta_deg) + 8`` columns (see :func:`columns_for_width`).
    With ``cells.stability`` the allowed cells whose orbit is linearly
    unstable are marked ``x`` (stable ones keep the shade ``.``).

    Returns
    -------
    CharMap (``str(result)`` or ``result.lines`` to print).
    """
    alpha_c, theta_c = cells.alpha_deg, cells.theta_deg
    nrow, ncol = alpha_c.size, theta_c.size
    width = ncol + _LEFT + 2
    lo_d, hi_d = cells.alpha_range_deg
    dal = (hi_d - lo_d) / (nrow - 1)
    dth = 180.0 / ncol
    a, r, k, mu, max_g = cells.a, cells.r, cells.k, cells.mu, cells.max_g
    outside, stability = cells.outside, cells.stability

    ok = cells.feasible
    grid = np.where(ok, SHADE, " ").astype("<U1")
    if stability:
        grid[cells.unstable] = UNSTABLE
        grid[cells.unknown] = UNKNOWN

    # boundaries: alpha roots on sub-column lines, theta roots on sub-row lines
    # (the k-th sample line lies in cell k // samples)
    sub = cells.samples
    legend = {}
    for name, (ch, text) in MARKS.items():
        if name not in cells.alpha_roots_deg:
            continue
        marked = np.zeros(grid.shape, dtype=bool)
        al_roots = cells.alpha_roots_deg[name]
        j = np.broadcast_to((np.arange(cells.sample_theta_deg.size) // sub)[:, None], al_roots.shape)
        i = np.floor((hi_d + dal / 2 - al_roots) / dal)
        f = np.isfinite(i) & (i >= 0) & (i < nrow)
        marked[i[f].astype(int), j[f]] = True
        th_roots = cells.theta_roots_deg[name]
        i = np.broadcast_to((np.arange(cells.sample_alpha_deg.size) // sub)[:, None], th_roots.shape)
        j = np.floor(th_roots / dth)
        f = np.isfinite(j) & (j >= 0) & (j < ncol)
        marked[i[f], j[f].astype(int)] = True
        if marked.any():
            grid[marked] = ch
            legend[ch] = OUTSIDE_MARKS.get(name, text) if outside else text

    # frame, labels, legend
    side = "outside" if outside else "inside"
    title = (("Stability of allowed" if stability else "Allowed")
             + f" horizontal orbits: wheel {side}, a/r = {_fmt(a / r)}, k = {_fmt(k)}")
    limits = [f"mu = {_fmt(mu)}" if np.isfinite(mu) else "", f"max g = {_fmt(max_g)}" if np.isfinite(max_g) else ""]
    limits = ", ".join(x for x in limits if x)
    if limits:
        title += f", {limits}"
    lines = [title[:width], "alpha [deg]"]
    tick_every = 30.0 if (hi_d - lo_d) <= 120 else 45.0
    row0 = len(lines)
    for i in range(nrow):
        label = ""
        if abs((alpha_c[i] - lo_d) / tick_every - round((alpha_c[i] - lo_d) / tick_every)) < 1e-9 \
                or i in (0, nrow - 1):
            label = _fmt(round(alpha_c[i], 1))
        lines.append(f"{label:>{_LEFT - 2}} |" + "".join(grid[i]))
    lines.append(" " * (_LEFT - 1) + "+" + "-" * ncol)
    ticks = [" "] * (ncol + 4)
    for t in range(0, 181, 30):
        pos = int(round(t / dth))
        s = str(t)
        start = min(max(pos - len(s) // 2, 0), ncol + 4 - len(s))
        ticks[start:start + len(s)] = list(s)
    lines.append(" " * (_LEFT - 1) + "".join(ticks).rstrip())
    lines.append(" " * (_LEFT - 1) + "theta [deg]".center(ncol).rstrip())
    if stability:
        shades = [f"{SHADE} allowed, stable", f"{UNSTABLE} allowed, unstable"]
        if UNKNOWN in set(grid[ok]):
            shades.append(f"{UNKNOWN} allowed, stability unknown")
    else:
        shades = [f"{SHADE} allowed"]
    items = [f"{ch} {text}" for ch, text in legend.items()] + shades
    line = " "
    for item in items:
        if len(line) + len(item) + 3 > width:
            lines.append(line.rstrip())
            line = " "
        line += item + "   "
    lines.append(line.rstrip())
    return CharMap(lines=lines, cells=["".join(row) for row in grid], theta_deg=theta_c,
                   alpha_deg=alpha_c, row0=row0, col0=_LEFT, legend=legend)


def to_rich(cmap):
    """The map as a :class:`rich.text.Text`, boundary characters in colour."""
    from rich.text import Text

    text = Text()
    for n, line in enumerate(cmap.lines):
        if cmap.row0 <= n < cmap.row0 + len(cmap.cells):
            text.append(line[:cmap.col0])
            for ch in line[cmap.col0:]:
                text.append(ch, style=STYLES.get(ch, ""))
        else:
            text.append(line)
        text.append("\n")
    return text
