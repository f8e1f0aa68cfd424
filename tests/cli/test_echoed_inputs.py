"""Inputs come back in the CSV as they were given: a grid the user's step
lays out is its decimal multiples (``map --step 0.3``: 0.9, not the
0.8999999999999999 of 3 x 0.3), while computed quantities keep every
digit (docs/units.md, "What each output does with units")."""

import csv
import io
from decimal import Decimal

import pytest


def _column(text: str, name: str) -> list[str]:
    return [row[name] for row in csv.DictReader(io.StringIO(text))]


@pytest.mark.parametrize("step", ["0.3", "0.7", "2.5"])
def test_map_thetas_are_the_steps_decimal_multiples(run, step):
    out = run("map", "--step", step, "--format", "csv")
    assert out.exit_code == 0, out.output
    thetas = sorted(set(_column(out.stdout, "theta_deg")), key=float)
    # the multiples of the step strictly inside (0, 180), each the float nearest k x step in decimal
    wanted = [repr(float(Decimal(step) * k)) for k in range(1, 2000) if Decimal(step) * k < 180 - Decimal(step) / 2]
    assert thetas == wanted


@pytest.mark.parametrize("points", [13, 8])
def test_vertical_points_azimuths_are_the_grids_fractions(run, points):
    from fractions import Fraction

    out = run("vertical", "--theta", "60", "--v-top", "6", "--points", str(points), "--format", "csv")
    assert out.exit_code == 0, out.output
    # every (points - 1)-th of a turn, the float nearest k x 360 / (points - 1): 120.0, not 119.99999999999999
    assert _column(out.stdout, "phi_deg") == [repr(float(Fraction(360 * k, points - 1))) for k in range(points)]
