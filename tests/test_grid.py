import numpy as np
import pytest

from deathsphere.chunker import grid_chunks
from deathsphere.grid import (
    Axis,
    RangeError,
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
    chunk = next(grid_chunks({"theta": axis}, 4))
    np.testing.assert_allclose(chunk.values()["theta"], [0, 2e-9, 4e-9, 6e-9])
    assert axis.take([5 * 10**8])[0] == 1.0


def test_chunks_cover_the_grid_in_order():
    axes = {"theta": np.array([1.0, 2.0, 3.0]), "alpha": np.array([10.0, 20.0])}
    chunks = list(grid_chunks(axes, 4))
    assert [c.first for c in chunks] == [0, 4] and [len(c) for c in chunks] == [4, 2]
    theta = np.concatenate([c.values()["theta"] for c in chunks])
    alpha = np.concatenate([c.values()["alpha"] for c in chunks])
    assert theta.tolist() == [1, 1, 2, 2, 3, 3] and alpha.tolist() == [10, 20] * 3
    assert np.concatenate([c.input_row for c in chunks]).tolist() == [1, 2, 3, 4, 5, 6]


def test_a_chunk_gives_each_axis_its_index_in_row_order():
    """The rows of an outer product, last axis fastest: row i of a 3 x 2
    grid is (i // 2, i % 2), whatever the chunk size, and a chunk of a
    whole number of lines of the last axis starts a line."""
    axes = {"lane": np.array([7.0, 8.0, 9.0]), "speed": Axis([parse_segment("1:2:1")])}
    for rows in (1, 2, 4, 6, 100):
        chunks = list(grid_chunks(axes, rows))
        lane = np.concatenate([c.index["lane"] for c in chunks])
        speed = np.concatenate([c.index["speed"] for c in chunks])
        assert lane.tolist() == [0, 0, 1, 1, 2, 2] and speed.tolist() == [0, 1] * 3
        assert [c.first for c in chunks] == list(range(0, 6, rows))
    assert [c.index["speed"][0] for c in grid_chunks(axes, 4)] == [0, 0]


def test_an_empty_axis_gives_no_chunk():
    assert list(grid_chunks({"lane": np.empty(0), "speed": np.array([1.0])}, 4)) == []
