import numpy as np
import pytest

from deathsphere.grid import (
    Axis,
    RangeError,
    grid_chunks,
    parse_many,
    parse_segment,
    parse_values,
    range_size,
)


def test_stop_included_as_a_physicist_reads_it():
    v = parse_values("5:175:1")
    assert len(v) == 171 and v[0] == 5 and v[-1] == 175


def test_fractional_steps_without_drift():
    v = parse_values("0:1:0.1")
    assert len(v) == 11 and v[-1] == pytest.approx(1.0, abs=1e-15)
    assert range_size(0, 0.95, 0.1) == 10  # stop off the grid is not included


@pytest.mark.parametrize("text", ["10:5:1", "1:2:0", "1:2:-1", "1:2", "a:b:c", "1:2:3:4", "nan", "inf", ""])
def test_bad_ranges(text):
    with pytest.raises(RangeError):
        parse_values(text)


def test_many_values_keep_order():
    assert parse_many(["90", "10:30:10"], "theta").tolist() == [90.0, 10.0, 20.0, 30.0]


def test_limit():
    with pytest.raises(RangeError, match="more than 1000"):
        parse_values("0:100:0.001", max_values=1000)


@pytest.mark.parametrize("text", ["0:1e308:1e-300", "0:180:1e-9"])
def test_huge_ranges_are_refused_without_being_built(text):
    with pytest.raises(RangeError, match="at most 1e\\+09"):
        parse_segment(text, "theta")


def test_range_values_are_the_decimals_written():
    """0.3:180:0.1 ends at exactly 180 (not 180.00000000000003), and its
    values are the decimals a person reads."""
    values = Axis([parse_segment("0.3:180:0.1")]).values()
    assert values[-1] == 180.0 and values[1] == 0.4 and len(values) == 1798


def test_axes_are_lazy():
    """A 5e8-value axis is never built: a chunk computes only its own values."""
    axis = Axis([parse_segment("0:1:2e-9")])
    assert len(axis) == 5 * 10**8 + 1
    first, grid = next(grid_chunks({"theta": axis}, 4))
    np.testing.assert_allclose(grid["theta"], [0, 2e-9, 4e-9, 6e-9])
    assert axis.take([5 * 10**8])[0] == 1.0


def test_chunks_cover_the_grid_in_order():
    axes = {"theta": np.array([1.0, 2.0, 3.0]), "alpha": np.array([10.0, 20.0])}
    chunks = list(grid_chunks(axes, 4))
    assert [first for first, _ in chunks] == [0, 4]
    theta = np.concatenate([c["theta"] for _, c in chunks])
    alpha = np.concatenate([c["alpha"] for _, c in chunks])
    assert theta.tolist() == [1, 1, 2, 2, 3, 3] and alpha.tolist() == [10, 20] * 3
