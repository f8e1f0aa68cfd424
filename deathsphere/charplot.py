"""Terminal character plot of the allowed (theta, alpha) region of horizontal
wheel orbits -- McDonald (1993) figure "alpha_wh" in 80 columns.

theta runs along x from 0 to 180 deg, alpha up y.  The boundary curves
(root-found by :mod:`deathsphere.physics.region`, along columns *and* rows so
that steep stretches have no gaps) are drawn with one character each and the
allowed region is shaded:

    #  eq. (0)   the wheel fits (eq. (81) outside)
    =  eq. (29)  Omega^2 = 0 (alpha = 90 deg) or a pole (alpha = 0, r' = -k a cos(alpha)/(2k+1))
    *  eq. (33)  the normal force vanishes (eq. (83) outside)
    m  mu_required = mu        (only with a friction limit)
    g  g-load = max_g          (only with a g-load limit)
    .  allowed: a feasible orbit at the cell's centre
    x  allowed but linearly unstable (only with ``stability=True``)
    ?  allowed, stability unknown (only with ``stability=True``; rare)

A cell is shaded when its centre is feasible (status ``ok`` of
:func:`deathsphere.physics.wheel.horizontal_orbit`, and g-load <= max_g); a
boundary character replaces the shading where a curve crosses the cell.
With ``stability=True`` the feasible cells are split by the verdict of
:func:`deathsphere.physics.stability.wheel_stability` at the cell's centre
(exact linearisation, beyond the paper: docs/stability.md).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics import region
from deathsphere.physics.stability import Verdict, wheel_stability

#: Character and legend text of each boundary, in drawing order (later wins).
MARKS = {name: (ch, region.BOUNDARY_LABELS[name][0])
         for name, ch in (("eq29", "="), ("eq0", "#"), ("eq33", "*"), ("mu", "m"), ("max_g", "g"))}
SHADE = "."
UNSTABLE = "x"
UNKNOWN = "?"
OUTSIDE_MARKS = {name: region.BOUNDARY_LABELS[name][1] for name in ("eq0", "eq33")}

#: rich styles for :func:`to_rich`.
STYLES = {"=": "bold blue", "#": "bold red", "*": "bold magenta", "m": "bold green",
          "g": "bold yellow", SHADE: "cyan", UNSTABLE: "red", UNKNOWN: "yellow"}

_LEFT = 6            # "  90 |"
_SUB = 6             # root samples per cell along each axis


@dataclass
class CharMap:
    """A rendered map: ``lines`` to print, and the plot grid behind them.

    ``cells[i][j]`` is the character at row i (top = largest alpha) and
    column j; their centres are ``alpha_deg[i]`` and ``theta_deg[j]``; the
    grid's first row is ``lines[row0]`` starting at column ``col0``.
    """

    lines: list
    cells: list
    theta_deg: np.ndarray
    alpha_deg: np.ndarray
    row0: int
    col0: int
    legend: dict = field(default_factory=dict)

    def __str__(self):
        return "\n".join(self.lines)


def _fmt(x):
    return f"{x:g}"


def char_map(a, r, k, *, outside=False, mu=np.inf, max_g=np.inf, g=STANDARD_GRAVITY,
             width=80, rows=None, alpha_range_deg=None, stability=False):
    """Character map of the allowed (theta, alpha) region.

    Parameters
    ----------
    a, r : float, [m]   wheel and sphere radii (only a/r matters)
    k : float, [-]      inertia factor
    outside : bool      wheel outside the sphere (sec. 3)
    mu, max_g : float   friction coefficient and g-load limits (inf: none)
    width : int         total width in characters (>= 40)
    rows : int          rows of the plot grid (default: 19 inside, 28 outside)
    alpha_range_deg : (lo, hi) alpha axis [deg] (default 0..90 inside,
        0..270 outside, where the paper's allowed regions lie)
    stability : bool    mark allowed cells whose orbit is linearly unstable
        with ``x`` (stable ones keep the shade ``.``); one batched call of
        :func:`deathsphere.physics.stability.wheel_stability` for all
        allowed cell centres (beyond the paper, docs/stability.md)

    Returns
    -------
    CharMap (``str(result)`` or ``result.lines`` to print).
    """
    if width < 40:
        raise ValueError(f"width must be >= 40 characters, got {width}")
    lo_d, hi_d = alpha_range_deg or ((0.0, 270.0) if outside else (0.0, 90.0))
    nrow = rows or (28 if outside else 19)
    ncol = width - _LEFT - 2
    # rows are centred on lo_d .. hi_d inclusive, so alpha = lo_d and hi_d
    # (eq. 29's alpha = 0 and 90 deg inside) fall on rows
    alpha_c = np.linspace(hi_d, lo_d, nrow)
    dal = (hi_d - lo_d) / (nrow - 1)
    dth = 180.0 / ncol
    theta_c = (np.arange(ncol) + 0.5) * dth

    th_c, al_c = np.meshgrid(np.deg2rad(theta_c), np.deg2rad(alpha_c))
    ok = region.feasible(th_c, al_c, a, r, k, g, outside=outside, mu=mu, max_g=max_g)
    grid = np.where(ok, SHADE, " ").astype("<U1")
    if stability:
        verdict = wheel_stability(th_c[ok], al_c[ok], a, r, k, g, outside)["verdict"]
        grid[ok] = np.select([verdict == Verdict.UNSTABLE, verdict == Verdict.UNKNOWN],
                             [UNSTABLE, UNKNOWN], SHADE)

    # boundaries: alpha roots on sub-column lines, theta roots on sub-row lines
    a_top, a_bot = np.deg2rad(hi_d + dal / 2), np.deg2rad(lo_d - dal / 2)
    th_s = np.deg2rad((np.arange(ncol * _SUB) + 0.5) * dth / _SUB)
    al_s = np.linspace(a_top, a_bot, nrow * _SUB + 1)[:-1] - np.deg2rad(dal) / (2 * _SUB)
    win = (np.full(th_s.shape, a_bot), np.full(th_s.shape, a_top))
    by_col = region.boundary_alphas(th_s, a, r, k, outside=outside, mu=mu, max_g=max_g, window=win)
    by_row = region.boundary_thetas(al_s, a, r, k, outside=outside, mu=mu, max_g=max_g)
    legend = {}
    for name, (ch, text) in MARKS.items():
        if name not in by_col:
            continue
        marked = np.zeros(grid.shape, dtype=bool)
        al_roots = np.rad2deg(by_col[name])
        j = np.broadcast_to((np.arange(th_s.size) // _SUB)[:, None], al_roots.shape)
        i = np.floor((hi_d + dal / 2 - al_roots) / dal)
        f = np.isfinite(i) & (i >= 0) & (i < nrow)
        marked[i[f].astype(int), j[f]] = True
        th_roots = np.rad2deg(by_row[name])
        i = np.broadcast_to((np.arange(al_s.size) // _SUB)[:, None], th_roots.shape)
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
        cells = set(grid[ok])
        shades = [f"{SHADE} allowed, stable", f"{UNSTABLE} allowed, unstable"]
        if UNKNOWN in cells:
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
