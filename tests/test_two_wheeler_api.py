"""The two-wheeler through the Python API: deathsphere.ride(..., flat=True)
reproduces the benchmark of Meijaard, Papadopoulos, Ruina & Schwab (2007)
(its Table 2 eigenvalues, weave and capsize speeds: the published numbers
held by tests/physics/test_two_wheeler.py), deathsphere.TwoWheeler takes a
user's parameters and refuses bad ones in one line, and the globe's turns
come one row per turn, every request answered in order."""

import importlib.util
import math
from dataclasses import asdict
from pathlib import Path

import numpy as np
import pytest

import deathsphere
from deathsphere import ParameterError
from deathsphere.api.two_wheelers import TWO_WHEELERS, TwoWheeler


def _published():
    path = Path(__file__).resolve().parent / "physics" / "test_two_wheeler.py"
    spec = importlib.util.spec_from_file_location("published_benchmark", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


PUBLISHED = _published()
#: The benchmark is defined at g = 9.81 (Table 1): its comparisons pass it, the run's gravity.
BENCHMARK_G = 9.81
#: A 16-foot globe's radius, m.
GLOBE = 16 * 0.3048 / 2


def _eigenvalues(row, k):
    return np.array([row[f"eig_{i}_re"] + 1j * row[f"eig_{i}_im"] for i in range(1, k + 1)])


def test_flat_rows_are_the_benchmarks_table_2():
    speeds = sorted(PUBLISHED.TABLE2)
    t = deathsphere.ride(machine="benchmark-bicycle", flat=True, speed=speeds, g=BENCHMARK_G)
    assert list(t["speed_m_s"]) == speeds and list(t["input_row"]) == [1, 2, 3, 4]
    for i, v in enumerate(speeds):
        published = np.array(PUBLISHED.TABLE2[v])
        expected = published[np.lexsort((-published.imag, -published.real))]   # largest real part first
        got = _eigenvalues(t[i], 4)
        assert np.max(np.abs(got - expected)) < 1e-12
        assert t["growth_rate_1_s"][i] == pytest.approx(expected.real.max(), abs=1e-12)
    # 0 and 4 m/s capsize or weave; 5 m/s is in the self-stable window; 10 m/s capsizes slowly
    assert list(t["stability"]) == ["unstable", "unstable", "stable", "unstable"]


def test_the_summary_gives_the_published_weave_and_capsize_speeds():
    s = deathsphere.ride(machine="benchmark-bicycle", flat=True, speed="0:10:0.5", summary=True, g=BENCHMARK_G)
    assert abs(s["weave_speed_m_s"][0] - PUBLISHED.WEAVE) < 1e-10
    assert abs(s["capsize_speed_m_s"][0] - PUBLISHED.CAPSIZE) < 1e-10
    # 4.5, 5.0, 5.5 and 6.0 m/s lie in the window
    assert s["speeds_tried"][0] == 21 and s["speeds_stable"][0] == 4


def test_the_locked_steer_on_flat_ground_leaves_the_lean_alone():
    # the lean row alone: M_ll s^2 + g K0_ll = 0 (C1_ll = K2_ll = 0, published)
    t = deathsphere.ride(machine="benchmark-bicycle", flat=True, steer="locked", speed=[0.0, 7.0], g=BENCHMARK_G)
    rate = math.sqrt(-BENCHMARK_G * PUBLISHED.PUBLISHED["K0"][0][0] / PUBLISHED.PUBLISHED["M"][0][0])
    for i in range(2):
        assert np.max(np.abs(_eigenvalues(t[i], 2) - [rate, -rate])) < 1e-10
    assert "eig_3_re" not in t


def test_a_users_two_wheeler_with_the_benchmarks_numbers_is_the_benchmark():
    mine = TwoWheeler(**TWO_WHEELERS["benchmark-bicycle"].benchmark_values(), name="mine")
    a = deathsphere.ride(machine=mine, flat=True, speed=[3.0, 5.0])
    b = deathsphere.ride(machine="benchmark-bicycle", flat=True, speed=[3.0, 5.0])
    assert list(a["machine"]) == ["mine", "mine"]
    assert np.array_equal(a["eig_1_re"], b["eig_1_re"])
    # a heavier front frame moves the weave speed
    heavier = TwoWheeler(**{**mine.benchmark_values(), "mH": 8.0})
    s = deathsphere.ride(machine=heavier, flat=True, speed=5.0, summary=True)
    assert abs(s["weave_speed_m_s"][0] - PUBLISHED.WEAVE) > 1e-3


@pytest.mark.parametrize("change, words", [
    ({"w": 0.0}, "w (wheel base) must be 0.05..10 m (got 0)"),
    ({"rF": math.nan}, "rF (front wheel radius) must be a finite number"),
    ({"lam": 2.0}, "lam (steer axis tilt) must be -1.5708..1.5708 rad (got 2)"),
    ({"mB": -1.0}, "mB (rear frame mass) must be 0..10000 kg (got -1)"),
    ({"IBxz": 10.0}, "IBxz (10 kg m^2) is too large"),
    ({"head": (1.0,)}, "head must be two finite numbers"),
    ({"name": "a,b"}, "holds a comma"),
])
def test_a_bad_two_wheeler_is_refused_in_one_line(change, words):
    values = {**asdict(TWO_WHEELERS["benchmark-bicycle"]), **change}
    with pytest.raises(ParameterError) as err:
        TwoWheeler(**values)
    assert words in str(err.value) and "\n" not in str(err.value)


@pytest.mark.parametrize("kwargs, words", [
    ({"machine": "stunt125", "flat": True, "speed": 5}, "'stunt125' is a single-contact machine"),
    ({"machine": "benchmark-bicycle", "flat": True, "speed": 5, "theta": 90}, "flat ground has no lane"),
    ({"machine": "benchmark-bicycle", "flat": True, "speed": -1}, "speed (rear contact speed) must be"),
    ({"machine": "benchmark-bicycle", "steer": "sideways", "theta": 90, "speed": 5}, "steer must be one of"),
    ({"machine": "benchmark-bicycle", "steer": "free", "theta": 90}, "give speed"),
    ({"machine": "benchmark-bicycle", "steer": "free", "theta": 90, "speed": 5, "mass": 80}, "does not take mass"),
    ({"machine": "benchmark-bicycle", "steer_torque": 0, "theta": 90, "speed": 5}, "not both"),
    ({"machine": "benchmark-bicycle", "steer": "torque=0", "steer_torque": 1, "theta": 90}, "torque once"),
    ({"machine": "benchmark-bicycle", "steer": "torque=", "theta": 90}, "steer must be one of"),
    ({"machine": "benchmark-bicycle", "steer": "torque=abc", "theta": 90}, "steer_torque"),
    ({"machine": "benchmark-bicycle", "steer": "torque=0", "flat": True, "speed": 5}, "is for the globe"),
    ({"machine": "benchmark-bicycle", "flat": "yes", "speed": 5}, "flat must be True or False"),
    ({"machine": "benchmark-bicycle", "steer": "free", "theta": "10:170:0.01", "speed": [[1.0], [2.0]]},
     "at most 30000 lanes and speeds (or torques) at once (got 2 x 16001)"),
    ({"machine": "benchmark-bicycle", "steer": "free", "theta": [90, 100], "speed": [5, 6, 7]},
     "cannot be broadcast together (shapes: theta (2,), speed (3,))"),
    ({"machine": "benchmark-bicycle", "flat": True, "speed": "0:100:1e-5"}, "at most 500000 values of speed"),
])
def test_bad_combinations_are_refused_in_one_line(kwargs, words):
    with pytest.raises(ParameterError) as err:
        deathsphere.ride(**kwargs)
    assert words in str(err.value) and "\n" not in str(err.value)


def test_one_name_one_machine():
    """benchmark-bicycle is the benchmark's two-wheeler whether or not a
    steer is asked for; its single-contact model has a name of its own."""
    rigid = deathsphere.ride(90, speed="30km/h", machine="benchmark-bicycle-rigid", diameter="16ft")
    assert "alpha_deg" in rigid and "steer_deg" not in rigid
    steered = deathsphere.ride(90, speed="30km/h", machine="benchmark-bicycle", diameter="16ft")
    assert "steer_deg" in steered and set(steered["machine"]) == {"benchmark-bicycle"}
    names = list(deathsphere.api.two_wheelers.machines_table()["name"])
    assert len(names) == len(set(names))


def test_hands_free_turns_one_row_each_are_held_without_torque_at_their_speed():
    free = deathsphere.ride(machine="benchmark-bicycle", steer_torque=0.0, height=1.0, diameter="16ft")
    assert len(free) >= 2 and set(free["input_row"]) == {1} and set(free["status"]) == {"ok"}
    # the same lanes asked by speed: the torque found by the other equation vanishes there
    by_speed = deathsphere.ride(machine="benchmark-bicycle", steer="free", height=1.0, diameter="16ft",
                                speed=free["v_rear_m_s"])
    for i in range(len(free)):
        rows = by_speed[by_speed["input_row"] == i + 1]
        match = np.argmin(np.abs(rows["lean_surface_deg"] - free["lean_surface_deg"][i]))
        assert abs(rows["steer_torque_n_m"][match]) < 1e-8
        assert rows["steer_deg"][match] == pytest.approx(free["steer_deg"][i], abs=1e-8)
    assert all(len(_eigenvalues(free[i], 6)) == 6 for i in range(len(free)))


def test_steer_torque_mode_is_the_held_torque():
    """steer="torque=T" asks what steer_torque=T asks: the same rows, the
    steer free under the held torque."""
    by_mode = deathsphere.ride(machine="benchmark-bicycle", steer="Torque = 0:1:0.5", height=1.0, diameter="16ft",
                               stability=False)
    by_value = deathsphere.ride(machine="benchmark-bicycle", steer_torque="0:1:0.5", height=1.0, diameter="16ft",
                                stability=False)
    assert set(by_mode["steer"]) == {"free"} and len(by_mode) == len(by_value) >= 3
    for name in by_value.columns:
        a, b = np.asarray(by_mode[name]), np.asarray(by_value[name])
        if a.dtype.kind == "f":
            np.testing.assert_array_equal(a, b)
        else:
            assert list(a) == list(b), name


def test_every_request_on_the_globe_gets_its_rows_in_order():
    t = deathsphere.ride(machine="benchmark-bicycle", steer="locked", theta=[[100.0], [0.0]], r=GLOBE,
                         speed=[0.0, 8.0])
    rows = list(t["input_row"])
    assert rows == sorted(rows) and set(rows) == {1, 2, 3, 4}
    first, pole = t[t["input_row"] == 1], t[t["input_row"] == 3]
    assert list(first["status"]) == ["no_orbit"] and "speed must be finite and positive" in first["reason"][0]
    assert list(pole["status"]) == ["no_orbit"] and "poles" in pole["reason"][0]
    assert "eig_4_re" in t and "eig_5_re" not in t       # steer locked on the sphere: four eigenvalues
    turns = t[t["input_row"] == 2]
    assert set(turns["v_rear_m_s"]) == {8.0} and set(turns["v_contact_m_s"]) == {8.0}   # as asked
    assert np.all(np.isfinite(turns["growth_rate_1_s"]))
    # the lap: the period is the time round at the rear contact's speed on its parallel
    radius = GLOBE * math.sin(math.radians(100.0))
    assert turns["period_s"][0] == pytest.approx(2 * math.pi * radius / 8.0, rel=1e-9)


def test_machines_lists_the_two_wheeler_with_its_geometry():
    t = deathsphere.machines_table()
    two = t[t["kind"] == "two-wheeler"]
    assert list(two["name"]) == ["benchmark-bicycle", "sport-tourer", "stunt125-steer"]
    assert two["wheel_base_m"][0] == 1.02 and two["trail_m"][0] == 0.08
    assert two["steer_axis_tilt_deg"][0] == pytest.approx(18.0, abs=1e-12)
    assert two["mass_kg"][0] == 94.0 and "Meijaard" in two["source"][0]


#: The same keywords asked of the single-contact machine and of its two-wheeler.
BROADCAST = dict(diameter="16ft")
KINDS = {"single-contact": dict(machine="stunt125"), "two-wheeler": dict(machine="stunt125-steer", steer="free")}


@pytest.mark.parametrize("height, speed, shape", [
    ([1.0, 2.0], [8.0, 10.0], (2,)),                 # elementwise: two requests
    ([[1.0], [2.0]], [8.0, 10.0], (2, 2)),           # a column and a row: their grid
    ([1.0, 2.0], 10.0, (2,)),                        # a scalar goes with every element
])
def test_both_kinds_of_machine_broadcast_the_same_keywords_to_the_same_rows_and_axes(height, speed, shape):
    """numpy's broadcasting, whatever the body: the same shape, rows and
    axes, each axis named after the column that echoes the keyword that
    varies along it (the height as given; the speed asked, which for a
    two-wheeler is its rear contact's)."""
    from deathsphere.table.frames import axis_names

    tables = {kind: deathsphere.ride(height=height, speed=speed, **kw, **BROADCAST) for kind, kw in KINDS.items()}
    single, two = tables["single-contact"], tables["two-wheeler"]
    assert len(single) == len(two) == math.prod(shape) and single.shape == two.shape == shape
    assert [row for row in two["input_row"]] == list(range(1, len(two) + 1))
    asked = {"height": np.broadcast_to(np.asarray(height), shape), "speed": np.broadcast_to(np.asarray(speed), shape)}
    for table in tables.values():
        assert len(table.axes) == len(shape) and table.axes[0] in ("height_m", None)
        # along an axis where only one keyword varies, the axis is its echo; where both do, neither
        for d, name in enumerate(table.axes):
            varies = [k for k, v in asked.items() if v.shape[d] > 1 and not np.all(v == np.take(v, [0], axis=d))]
            if len(varies) == 1:
                np.testing.assert_array_equal(table.grid(name), asked[varies[0]])
            else:
                assert name is None
        np.testing.assert_array_equal(table.grid("height_m"), asked["height"])
    assert axis_names(single)[0][0] == axis_names(two)[0][0]
    assert len(axis_names(single)[0]) == len(axis_names(two)[0])


def test_a_two_wheelers_requests_broadcast_elementwise_as_one_request_each():
    """Row i of the broadcast call is the turn of the call with the i-th
    height and speed alone (the same numbers, its input_row i + 1)."""
    heights, speeds = [1.0, 2.0, 1.5], [8.0, 10.0, 9.0]
    kw = dict(KINDS["two-wheeler"], **BROADCAST, stability=False)
    both = deathsphere.ride(height=heights, speed=speeds, **kw)
    assert len(both) == 3
    for i, (h, v) in enumerate(zip(heights, speeds)):
        alone = deathsphere.ride(height=h, speed=v, **kw)
        for name in ("height_m", "v_rear_m_s", "lean_deg", "steer_torque_n_m", "status"):
            assert both[i][name] == alone[0][name], name
        assert both[i]["input_row"] == i + 1


def test_a_two_wheelers_grid_is_the_streamed_outer_product():
    """The API's grid of a column of heights and a row of speeds is the
    command line's outer product of its options, row for row."""
    from deathsphere.api.two_wheeler_streams import two_wheeler_ride_sweep
    from deathsphere.table import Table

    kw = dict(KINDS["two-wheeler"], **BROADCAST, stability=False)
    grid = deathsphere.ride(height=[[1.0], [2.0], [1.5]], speed=[8.0, 10.0, 12.0], **kw)
    assert len(grid) == 9 and grid.shape == (3, 3)       # one turn per request
    for chunk_size, rows in ((1, [3, 3, 3]), (7, [6, 3])):      # a lane, then two lanes per chunk
        chunks = list(two_wheeler_ride_sweep(height=[1.0, 2.0, 1.5], speed=[8.0, 10.0, 12.0], chunk_size=chunk_size,
                                             **kw))
        assert [len(t) for t in chunks] == rows
        assert Table.concat(chunks).to_csv() == grid.to_csv()


def test_a_two_wheelers_rider_table_has_a_row_per_lane_asked():
    """summary groups the requests that differ only where the speeds vary:
    a column of heights against a row of speeds is a row per height, each
    over every speed; heights and speeds side by side are a row each."""
    kw = dict(KINDS["two-wheeler"], **BROADCAST, summary=True)
    grid = deathsphere.ride(height=[[1.0], [2.0]], speed=[8.0, 9.0, 10.0], **kw)
    assert grid["height_m"].tolist() == [1.0, 2.0] and grid["speeds_tried"].tolist() == [3, 3]
    pairs = deathsphere.ride(height=[1.0, 2.0], speed=[8.0, 10.0], **kw)
    assert pairs["height_m"].tolist() == [1.0, 2.0] and pairs["speeds_tried"].tolist() == [1, 1]


def test_both_kinds_of_machines_grid_exports_with_its_axes_as_coordinates():
    """xarray and pandas: the grid of a column of heights and a row of
    speeds has the heights and the speeds asked as its coordinates, for a
    two-wheeler as for a single-contact machine; a 2-D array of heights
    names no axis (no dimension twice)."""
    import xarray as xr      # the dataframes extra, which the test extra installs
    heights, speeds = [1.0, 2.0], [8.0, 10.0]
    for kw in KINDS.values():
        t = deathsphere.ride(height=[[h] for h in heights], speed=speeds, **kw, **BROADCAST, stability=False)
        ds = t.to_xarray()
        assert isinstance(ds, xr.Dataset) and ds["status"].dims == t.axes
        assert ds[t.axes[0]].values.tolist() == heights and ds[t.axes[1]].values.tolist() == speeds
        assert len(t.to_pandas()) == 4
        square = deathsphere.ride(height=[[1.0, 1.5], [2.0, 2.5]], speed=10.0, **kw, **BROADCAST, stability=False)
        assert square.to_xarray()["status"].dims == ("dim_0", "dim_1")
