"""The terminal chart of the allowed (lane, alpha) region off the globe
(deathsphere.render.lane_charplot, drawn from region_curves): the shading
is where the wheel's forward model, orbit by orbit, finds a feasible
orbit; the boundary characters sit on the rows of their curves; the
layout fits the terminal; the lanes' table keeps its units."""

import math
import re

import numpy as np
import pytest
from rich.console import Console

import deathsphere
from deathsphere.physics import lane_region
from deathsphere.physics.ground import Cone, Cylinder
from deathsphere.physics.stability.lane_margin import stability_margin_on
from deathsphere.render.charplot import SHADE, UNSTABLE
from deathsphere.render.lane_charplot import MARKS, drawable, lane_char_map
from deathsphere.render.lane_map_text import lane_map_text

A, K, G = 0.3, 0.5, 9.80665
FT = 0.3048
BOUNDARY_CHARS = "".join(ch for ch, _ in MARKS.values())

CASES = {
    # the wall of death with the crew's friction and load limits
    "drum": (dict(surface="cylinder", diameter=32 * FT, wall_height=12 * FT, mu=0.8, max_g=3.0),
             Cylinder(16 * FT, 12 * FT), 0.8, 3.0),
    "well": (dict(surface="cone", diameter=6, wall_angle=80, wall_height=3, mu=1.0),
             Cone(3.0, math.radians(80), 3.0), 1.0, math.inf),
}


def _chart(case, width=80, **extra):
    typed, ground, mu, max_g = CASES[case]
    curves = deathsphere.region_curves(a=A, k=K, g=G, height="0:3:0.05", **typed, **extra)
    return curves, lane_char_map(curves, width), ground, mu, max_g


@pytest.mark.parametrize("case", sorted(CASES))
def test_the_shading_is_where_the_forward_model_finds_an_orbit(case):
    curves, chart, ground, mu, max_g = _chart(case)
    grid = np.array([list(row) for row in chart.cells])
    lanes, alpha = np.meshgrid(chart.x_m, np.radians(chart.alpha_deg))
    feasible = lane_region.feasible_on(ground, lanes, alpha, A, K, G, False, mu, max_g)
    plain = ~np.isin(grid, list(BOUNDARY_CHARS))
    assert plain.sum() > 0.5 * grid.size                     # most cells are shading, not curves
    np.testing.assert_array_equal(grid[plain] == SHADE, feasible[plain])
    assert (grid == SHADE).any() and (grid == " ").any()


def test_each_curve_is_drawn_on_the_rows_of_its_points():
    curves, chart, *_ = _chart("drum")
    rows = chart.alpha_deg
    step = rows[0] - rows[1]
    for name in ("mu", "max_g", "S2"):
        ch = MARKS[name][0]
        x, alpha = curves.points[name]
        for j, lane in enumerate(chart.x_m):
            want = {int(np.argmin(np.abs(rows - a))) for a in alpha[x == lane] if abs(rows - a).min() <= step / 2}
            got = {i for i, row in enumerate(chart.cells) if row[j] == ch}
            assert want <= got | {i for i, row in enumerate(chart.cells) if row[j] in BOUNDARY_CHARS}, (name, j)
            assert want, (name, j)
        assert ch in chart.legend


@pytest.mark.parametrize("width", [80, 100])
def test_the_chart_fits_the_terminal_and_labels_its_axes(width):
    curves, chart, *_ = _chart("drum", width)
    assert all(len(line) <= width for line in chart.lines)
    assert all(len(row) == width - 8 for row in chart.cells)
    text = str(chart)
    assert "alpha [deg]" in text and "height of the lane [m]" in text
    # the title is wrapped, never cut: its last words are there
    assert "max g = 3" in " ".join(chart.lines[:chart.row0])
    # the 30 deg ticks fall on rows, and the top and bottom rows are labelled
    assert chart.alpha_deg[0] % 30 == 0 and chart.alpha_deg[-1] % 30 == 0
    assert chart.lines[chart.row0].split("|")[0].strip() == f"{chart.alpha_deg[0]:g}"


def test_stability_marks_the_unstable_tilts():
    curves = deathsphere.region_curves(a=A, k=K, g=G, height="0:3:0.1", stability=True,
                                       **dict(CASES["well"][0], mu=math.inf))
    chart = lane_char_map(curves, 80)
    grid = np.array([list(row) for row in chart.cells])
    assert (grid == UNSTABLE).any() and (grid == SHADE).any()
    # each cell's own orbit, linearised at the cell's centre
    lanes, alpha = np.meshgrid(chart.x_m, np.radians(chart.alpha_deg))
    shaded = np.isin(grid, [SHADE, UNSTABLE])
    margin = stability_margin_on(CASES["well"][1], lanes[shaded], alpha[shaded], A, K, G, False)
    np.testing.assert_array_equal(grid[shaded] == SHADE, margin > 0)


def test_a_few_lanes_are_a_table_whose_headers_keep_their_units():
    curves = deathsphere.region_curves(a=A, height="0:3:1", **CASES["drum"][0])
    assert not drawable(curves)
    console = Console(width=100, record=True, color_system=None)
    console.print(lane_map_text(curves))
    text = console.export_text()
    assert "height of the lane [m]" in text and "allowed alpha [deg]" in text


@pytest.mark.parametrize("unit_name, metres_per_unit", [(None, 1.0), ("ft", FT)])
def test_each_tick_names_the_lane_drawn_above_it(unit_name, metres_per_unit):
    from deathsphere.render.display_units import DisplayUnit

    unit = None if unit_name is None else DisplayUnit(unit_name, 1 / metres_per_unit)
    curves, _, *_ = _chart("drum")
    chart = lane_char_map(curves, 80, unit)
    assert f"height of the lane [{unit_name or 'm'}]" in str(chart)
    # each tick's label, read in its unit, is the lane of the column under its centre, to a column
    ticks = chart.lines[chart.row0 + len(chart.cells) + 1]
    column_width = (curves.x_m[-1] - curves.x_m[0]) / len(chart.cells[0])
    labels = [(m.start() + len(m.group()) / 2 - 0.5, float(m.group())) for m in re.finditer(r"\S+", ticks)]
    assert len(labels) >= 3
    for centre, value in labels:
        j = min(max(int(round(centre - chart.col0)), 0), len(chart.x_m) - 1)
        assert abs(chart.x_m[j] - value * metres_per_unit) <= column_width, (centre, value)


def test_the_lanes_table_adds_the_lanes_in_the_unit_typed():
    from deathsphere.render.display_units import DisplayUnit

    curves, _, *_ = _chart("drum")
    console = Console(width=100, record=True, color_system=None)
    console.print(lane_map_text(curves, unit=DisplayUnit("ft", 1 / FT)))
    text = console.export_text()
    assert "height of the lane [m]" in text and "height of the lane [ft]" in text
    body = [line.split("│") for line in text.splitlines() if line.startswith("│")]
    assert len(body) == 13
    for row in body:
        assert float(row[2]) == pytest.approx(float(row[1]) / FT, rel=1e-3)   # both at 4 figures
