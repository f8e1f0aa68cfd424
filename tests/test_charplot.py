"""The terminal map of the allowed (theta, alpha) region
(deathsphere.results.region_map.cell_map drawn by deathsphere.render.charplot):
layout, labels, and that the shading and the curves are where the physics
(deathsphere.physics.wheel, point by point) puts them."""

import numpy as np
import pytest
from scipy.optimize import brentq

from deathsphere.physics import wheel
from deathsphere.physics.geometry import r_prime
from deathsphere.physics.status import Status
from deathsphere.render import charplot
from deathsphere.render.charplot import MARKS, SHADE, to_rich
from deathsphere.results.region_map import cell_map

A, R, K, G = 0.3, 3.0, 0.5, 9.80665
BOUNDARY_CHARS = "".join(ch for ch, _ in MARKS.values())


def char_map(a, r, k, *, width=80, rows=None, **options):
    """The map as the map command draws it: the cells for a terminal
    ``width`` characters wide, then the characters."""
    return charplot.char_map(cell_map(a, r, k, resolution=(charplot.columns_for_width(width), rows), **options))


def _feasible(cmap, outside=False, mu=np.inf, max_g=np.inf):
    th, al = np.meshgrid(np.deg2rad(cmap.theta_deg), np.deg2rad(cmap.alpha_deg))
    orb = wheel.horizontal_orbit(th, al, A, R, K, G, outside, mu)
    return (orb["status"] == Status.OK) & (orb["accel_g"] <= max_g)


@pytest.mark.parametrize("kwargs", [{}, {"mu": 1.0, "max_g": 5.0}, {"outside": True}],
                         ids=["paper", "limits", "outside"])
def test_layout_fits_80_columns_and_grid_is_consistent(kwargs):
    cmap = char_map(A, R, K, **kwargs)
    assert all(len(line) <= 80 for line in cmap.lines)
    assert len(cmap.cells) == cmap.alpha_deg.size and len(cmap.lines) <= 40
    assert all(len(row) == cmap.theta_deg.size == 72 for row in cmap.cells)
    # the grid printed is the grid described
    for i, row in enumerate(cmap.cells):
        assert cmap.lines[cmap.row0 + i][cmap.col0:] == row
    assert cmap.theta_deg[0] > 0 and cmap.theta_deg[-1] < 180
    text = str(cmap)
    assert "theta [deg]" in text and "alpha [deg]" in text
    assert "0" in cmap.lines[cmap.row0 + len(cmap.cells) + 1] and "180" in text


def test_labels_name_the_equations():
    text = str(char_map(A, R, K))
    for label in ("eq. (0)", "eq. (29)", "eq. (33)", "allowed", "a/r = 0.1", "k = 0.5"):
        assert label in text
    limited = str(char_map(A, R, K, mu=1.0, max_g=5.0))
    assert "mu_required = mu" in limited and "load_g = max_g" in limited and "mu = 1" in limited
    outside = str(char_map(A, R, K, outside=True))
    assert "eq. (81)" in outside and "eq. (83)" in outside


@pytest.mark.parametrize("kwargs", [{}, {"mu": 1.0, "max_g": 5.0}, {"outside": True}],
                         ids=["paper", "limits", "outside"])
def test_shaded_cells_are_exactly_the_feasible_ones(kwargs):
    cmap = char_map(A, R, K, **kwargs)
    grid = np.array([list(row) for row in cmap.cells])
    ok = _feasible(cmap, **kwargs)
    assert ok.sum() > 100
    assert np.all(ok[grid == SHADE])                       # shaded -> feasible
    assert np.all(np.isin(grid[ok], list(SHADE + BOUNDARY_CHARS)))   # feasible -> shaded or on a curve
    margin = 0.6 if kwargs.get("outside") else 0.8         # the curves cover only a margin
    assert np.sum(grid == SHADE) > margin * ok.sum()


def test_curves_are_drawn_where_they_are():
    cmap = char_map(A, R, K)
    grid = np.array([list(row) for row in cmap.cells])
    dal = cmap.alpha_deg[0] - cmap.alpha_deg[1]
    row_of = lambda alpha_deg: int(np.argmin(np.abs(cmap.alpha_deg - alpha_deg)))  # noqa: E731
    # eq. (29): alpha = 0 and 90 deg are full rows of '='
    eq29 = MARKS["eq29"][0]
    assert np.mean(grid[row_of(0.0)] == eq29) > 0.8 and np.mean(grid[row_of(90.0)] == eq29) > 0.4
    for j in range(8, 34, 5):                              # theta = 20 .. 85 deg
        th = np.deg2rad(cmap.theta_deg[j])

        def normal(al):
            om2 = wheel.omega_squared(th, al, A, R, K, G)
            return r_prime(th, al, A, R) * om2 * np.sin(th) - G * np.cos(th)

        alpha_c = np.rad2deg(brentq(normal, 1e-3, np.pi / 2 - 1e-3, xtol=1e-12))
        i = row_of(alpha_c)
        assert MARKS["eq33"][0] in grid[max(i - 1, 0):i + 2, j], (cmap.theta_deg[j], alpha_c)
        assert abs(cmap.alpha_deg[i] - alpha_c) <= dal / 2 + 1e-9
    # eq. (0): alpha = theta - asin(a/r) crosses the row of 30 deg near theta = 35.7 deg
    j = int(np.argmin(np.abs(cmap.theta_deg - (30.0 + np.rad2deg(np.arcsin(A / R))))))
    assert MARKS["eq0"][0] in grid[row_of(30.0), j - 1:j + 2]


def test_narrow_width_and_rich_rendering():
    cmap = char_map(A, R, K, width=60, rows=12)
    assert all(len(line) <= 60 for line in cmap.lines) and len(cmap.cells) == 12
    rich_text = to_rich(cmap)
    assert rich_text.plain.rstrip("\n") == str(cmap)
    assert any(span.style for span in rich_text.spans)
    with pytest.raises(ValueError, match="width"):
        char_map(A, R, K, width=20)


def test_stability_marks_exactly_the_unstable_cells():
    from deathsphere.physics.stability import Verdict, wheel_stability
    from deathsphere.render.charplot import UNSTABLE

    a, r = 0.9, 3.0                                        # a/r = 0.3: stable and unstable orbits
    cmap = char_map(a, r, K, stability=True)
    grid = np.array([list(row) for row in cmap.cells])
    th, al = np.meshgrid(np.deg2rad(cmap.theta_deg), np.deg2rad(cmap.alpha_deg))
    orb = wheel.horizontal_orbit(th, al, a, r, K, G)
    ok = orb["status"] == Status.OK
    verdict = wheel_stability(th, al, a, r, K, G)["verdict"]
    unstable, stable = ok & (verdict == Verdict.UNSTABLE), ok & (verdict == Verdict.STABLE)
    assert unstable.sum() > 100 and stable.sum() > 100 and not np.any(ok & (verdict == Verdict.UNKNOWN))
    on_curve = np.isin(grid, list(BOUNDARY_CHARS))
    assert np.array_equal(grid == UNSTABLE, unstable & ~on_curve)
    assert np.array_equal(grid == SHADE, stable & ~on_curve)
    text = str(cmap)
    assert "x allowed, unstable" in text and ". allowed, stable" in text and text.startswith("Stability")
    assert all(len(line) <= 80 for line in cmap.lines)
    # without the option nothing changes: no 'x', the plain legend
    plain = char_map(a, r, K)
    assert UNSTABLE not in "".join(plain.cells) and "allowed, unstable" not in str(plain)
    assert any(span.style == "red" for span in to_rich(cmap).spans)


def test_the_map_draws_what_the_cells_hold_and_nothing_else():
    """charplot computes nothing: a hand-made CellMap is drawn cell for cell."""
    from deathsphere.results.region_map import CellMap

    ncol, nrow, sub = charplot.columns_for_width(40), 4, 2
    feasible = np.zeros((nrow, ncol), dtype=bool)
    feasible[1:3, 10:20] = True
    unstable = np.zeros_like(feasible)
    unstable[2, 12] = True
    nan = np.full((ncol * sub, 1), np.nan)
    alpha_roots = nan.copy()
    alpha_roots[1, 0] = 89.0                  # a crossing in the top row, first column
    theta_roots = np.full((nrow * sub, 1), np.nan)
    theta_roots[7, 0] = 100.0                 # a crossing in the bottom row at theta = 100 deg
    cells = CellMap(a=0.2, r=1.0, k=0.5, outside=False, mu=np.inf, max_g=np.inf, g=G, stability=True,
                    alpha_range_deg=(0.0, 90.0), theta_deg=(np.arange(ncol) + 0.5) * 180.0 / ncol,
                    alpha_deg=np.linspace(90.0, 0.0, nrow), feasible=feasible, unstable=unstable,
                    unknown=np.zeros_like(feasible), samples=sub,
                    sample_theta_deg=np.zeros(ncol * sub), sample_alpha_deg=np.zeros(nrow * sub),
                    alpha_roots_deg={"eq0": alpha_roots}, theta_roots_deg={"eq0": theta_roots})
    cmap = charplot.char_map(cells)
    grid = np.array([list(row) for row in cmap.cells])
    fit = MARKS["eq0"][0]
    assert set(map(tuple, np.argwhere(grid == fit))) == {(0, 0), (3, int(100.0 // (180.0 / ncol)))}
    assert np.array_equal(grid == SHADE, feasible & ~unstable) and grid[2, 12] == charplot.UNSTABLE
    assert np.sum(grid == " ") == grid.size - feasible.sum() - 2
    assert cmap.lines[0] == "Stability of allowed horizontal orbits: "   # the title, cut at the width
    assert MARKS["eq0"][1] in str(cmap) and "x allowed, unstable" in str(cmap) and "eq. (29)" not in str(cmap)
    assert all(len(line) <= 40 for line in cmap.lines)


def test_cell_map_grid_and_its_limits():
    cells = cell_map(A, R, K, resolution=(30, 7), alpha_range_deg=(10.0, 70.0))
    assert cells.feasible.shape == (7, 30) and cells.unstable is None and cells.unknown is None
    assert np.allclose(cells.alpha_deg, [70, 60, 50, 40, 30, 20, 10]) and np.isclose(cells.theta_deg[0], 3.0)
    assert cells.sample_theta_deg.size == 30 * cells.samples and cells.sample_alpha_deg.size == 7 * cells.samples
    assert set(cells.alpha_roots_deg) == set(cells.theta_roots_deg) == {"eq0", "eq29", "eq33"}
    for bad in ((0, 10), (10, 1)):
        with pytest.raises(ValueError, match="column"):
            cell_map(A, R, K, resolution=bad)
