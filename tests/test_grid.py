import numpy as np
import pytest

from deathsphere.grid import RangeError, grid_chunks, parse_many, parse_values, range_size


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
    with pytest.raises(RangeError, match="sweep"):
        parse_values("0:100:0.001", max_values=1000)


def test_chunks_cover_the_grid_in_order():
    axes = {"theta": np.array([1.0, 2.0, 3.0]), "alpha": np.array([10.0, 20.0])}
    chunks = list(grid_chunks(axes, 4))
    assert [first for first, _ in chunks] == [0, 4]
    theta = np.concatenate([c["theta"] for _, c in chunks])
    alpha = np.concatenate([c["alpha"] for _, c in chunks])
    assert theta.tolist() == [1, 1, 2, 2, 3, 3] and alpha.tolist() == [10, 20] * 3
