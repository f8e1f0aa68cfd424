"""A two-wheeler's ride on the globe with the single-contact ride's limits
and rider's table (docs/two-wheeler.md sec. 10): ``mu`` and ``max_g`` flag
turns ``slips`` and ``over_g`` exactly where the table's own friction and
load columns cross them, the rider's table counts what the full table
holds, its hands-free speeds are where the table's steer torque changes
sign, and the lanes stream in chunks to the same rows.

The limits are taken from a table computed without them (a row's own
friction and load, so that the test meets each limit exactly), and the
expected statuses are worked out here from the columns, in ride's order
(slips before over_g, docs/contract.md): an independent check of the
flags."""

import importlib
import math
import pickle
import re

import numpy as np
import pytest

import deathsphere
from deathsphere.api.two_wheeler_streams import two_wheeler_ride_sweep
from deathsphere.api.two_wheelers import TURN_APPENDED, TURN_COLUMNS, TURN_LIMIT_COLUMNS, turn_request

#: Two lanes of a 16-foot globe and four rear speeds, each lane with each
#: speed (a column of heights and a row of speeds broadcast to their grid,
#: as the streamed ride's outer product): slow turns there need the most
#: friction, fast ones load the rider most.
ASK = {"machine": "benchmark-bicycle", "steer": "free", "diameter": "16ft", "height": [[0.4], [1.0]],
       "speed": [3.0, 4.0, 11.0, 12.0]}


def _row(table, height, speed):
    (i,) = np.flatnonzero((table["height_m"] == height) & (table["v_rear_m_s"] == speed))
    return i


@pytest.fixture(scope="module")
def plain():
    return deathsphere.ride(**ASK, stability=False)


@pytest.fixture(scope="module")
def limits(plain):
    """mu: the friction the turn at 1 m and 4 m/s needs; max_g: the load of the turn at 1 m and 11 m/s."""
    i, j = _row(plain, 1.0, 4.0), _row(plain, 1.0, 11.0)
    return {"mu": float(max(plain["mu_required_rear"][i], plain["mu_required_front"][i])),
            "max_g": float(plain["load_g"][j])}


@pytest.fixture(scope="module")
def limited(limits):
    """The same rows with the limits, streamed a lane per chunk."""
    return two_wheeler_ride_sweep(**ASK, **limits, chunk_size=1).table()


@pytest.fixture(scope="module")
def summary(limits):
    return two_wheeler_ride_sweep(**ASK, **limits, summary=True, chunk_size=1).table()


def test_slips_and_over_g_flip_exactly_where_friction_and_load_cross_the_limits(plain, limits, limited):
    mu, max_g = limits["mu"], limits["max_g"]
    assert list(limited["input_row"]) == list(plain["input_row"])
    for col in ("lean_surface_deg", "steer_deg", "load_g", "mu_required_rear", "mu_required_front"):
        assert np.array_equal(limited[col], plain[col], equal_nan=True)
    rear, front = plain["mu_required_rear"] > mu, plain["mu_required_front"] > mu
    was_ok = plain["status"] == "ok"
    expected = np.where(~was_ok, plain["status"],
                        np.where(rear | front, "slips", np.where(plain["load_g"] > max_g, "over_g", "ok")))
    assert list(limited["status"]) == list(expected)
    for i in np.flatnonzero(expected == "slips"):
        wheel = "both wheels" if rear[i] and front[i] else "the rear wheel" if rear[i] else "the front wheel"
        assert limited["reason"][i].startswith(wheel)
    assert all("max_g" in why for why in limited["reason"][expected == "over_g"])
    # the rows that meet a limit exactly are ok; each status is met, and a
    # turn both slipping and over the load is slips (ride's order)
    assert limited["status"][_row(plain, 1.0, 4.0)] == limited["status"][_row(plain, 1.0, 11.0)] == "ok"
    assert {"ok", "slips", "over_g"} <= set(expected)
    assert np.any((expected == "slips") & (plain["load_g"] > max_g))
    assert np.all(limited["mu_available"] == mu) and np.all(limited["max_g"] == max_g)
    assert limited.names == list(TURN_COLUMNS) + [f"eig_{i}_{p}" for i in range(1, 7) for p in ("re", "im")] + \
        list(TURN_LIMIT_COLUMNS) + list(TURN_APPENDED)
    assert np.all(np.isnan(plain["mu_available"])) and np.all(np.isnan(plain["max_g"]))


def test_the_riders_table_counts_what_the_full_table_holds(limited, summary, limits):
    assert list(summary["height_m"]) == ASK["height"]
    lane_of = (limited["input_row"] - 1) // len(ASK["speed"])
    for k in range(len(ASK["height"])):
        rows = limited[lane_of == k]
        ok = rows["status"] == "ok"
        ok_speeds = set(rows["input_row"][ok])
        stable = ok & (rows["stability"] == "stable")
        got = {c: summary[c][k] for c in summary.names}
        assert got["speeds_tried"] == len(set(rows["input_row"])) == len(ASK["speed"])
        assert got["speeds_ok"] == len(ok_speeds)
        for status in ("slips", "over_g", "no_contact", "no_orbit"):
            failing = {r for r, s in zip(rows["input_row"], rows["status"]) if s == status and r not in ok_speeds}
            assert got[status] == len(failing)
        assert got["limits"] == " ".join(sorted(set(rows["status"][~ok])))
        for lo, hi, col in (("v_rear_min_m_s", "v_rear_max_m_s", "v_rear_m_s"), ("load_min_g", "load_max_g", "load_g"),
                            ("lean_min_deg", "lean_max_deg", "lean_deg"),
                            ("steer_torque_min_n_m", "steer_torque_max_n_m", "steer_torque_n_m")):
            assert (got[lo], got[hi]) == (rows[col][ok].min(), rows[col][ok].max())
        assert got["mu_max"] == max(rows["mu_required_rear"][ok].max(), rows["mu_required_front"][ok].max())
        assert got["mu_max"] <= limits["mu"] and got["load_max_g"] <= limits["max_g"]
        assert got["head_clearance_min_m"] == rows["head_clearance_m"][ok].min()
        assert got["speeds_stable"] == len(set(rows["input_row"][stable]))
        if stable.any():
            assert (got["stable_v_min_m_s"], got["stable_v_max_m_s"]) == (rows["v_rear_m_s"][stable].min(),
                                                                          rows["v_rear_m_s"][stable].max())
        else:
            assert math.isnan(got["stable_v_min_m_s"]) and math.isnan(got["stable_v_max_m_s"])
        assert (got["mu_available"], got["max_g"], got["steer"]) == (limits["mu"], limits["max_g"], "free")
    # something is counted: each lane has ok speeds and some that fail
    assert np.all(summary["speeds_ok"] > 0) and np.all(summary["speeds_ok"] < summary["speeds_tried"])


def test_the_hands_free_speeds_are_where_the_tables_steer_torque_changes_sign(summary):
    """At 1 m the lane's hands-free turns (steer torque 0) found by their
    own equation (sec. 8.2) lie where the torque of the turns at a grid of
    speeds changes sign: one change between the two grid speeds around
    each, none elsewhere (one turn per speed here, so consecutive rows are
    one branch).  Linear interpolation between those two rows lands within
    twice h^2 |T''| / (8 |T'|) of it (the interpolation error of a smooth T
    with the curvature and slope the table itself shows)."""
    h = 0.5
    table = deathsphere.ride(**{**ASK, "height": 1.0, "speed": "3.5:11:0.5"}, stability=False)
    v, torque = table["v_rear_m_s"], table["steer_torque_n_m"]
    assert np.array_equal(table["input_row"], np.arange(1, len(v) + 1))       # one turn per speed
    (lane,) = np.flatnonzero(summary["height_m"] == 1.0)
    hands_free = [float(s) for s in summary["hands_free_v_rear_m_s"][lane].split()]
    inside = [s for s in hands_free if v[0] < s < v[-1]]
    changes = np.flatnonzero(np.sign(torque[:-1]) != np.sign(torque[1:]))
    assert len(inside) == len(changes) == 2 == summary["hands_free_turns"][lane]
    for s, i in zip(sorted(inside), changes):
        assert v[i] < s < v[i + 1]
        slope = (torque[i + 1] - torque[i]) / h
        curvature = max(abs(torque[j - 1] - 2 * torque[j] + torque[j + 1]) / h**2 for j in (i, i + 1))
        crossing = v[i] - torque[i] / slope
        assert abs(crossing - s) <= 2 * h**2 * curvature / (8 * abs(slope))


def test_a_streamed_request_travels_to_other_processes():
    request = turn_request("benchmark-bicycle", {"theta": [100.0, 110.0], "speed": "8:9:1", "diameter": "16ft",
                                                "mu": 0.5}, streamed=True)
    again = pickle.loads(pickle.dumps(request))
    assert again.machine == request.machine and np.array_equal(again.lanes, request.lanes)
    assert (again.mu, again.max_g, again.total) == (0.5, math.inf, 4)


@pytest.mark.parametrize("kwargs, words", [
    ({"mu": [0.5, 0.6]}, "takes one mu per call (got 2 values)"),
    ({"mu": "0.5:0.7:0.1"}, "takes one mu per call (got 3 values)"),
    ({"mu": -0.1}, "mu"),
    ({"max_g": 0}, "max_g"),
    ({"summary": True, "speed": None, "steer_torque": 0}, "give speed, not steer_torque"),
    ({"summary": True, "stability": False}, "needs the stability"),
    ({"alpha": 10, "speed": None}, "does not take alpha"),
])
def test_bad_limits_and_summaries_are_refused_in_one_line(kwargs, words):
    with pytest.raises(deathsphere.ParameterError) as err:
        deathsphere.ride(**{**ASK, **kwargs})
    assert words in str(err.value) and "\n" not in str(err.value)


def test_a_grid_too_large_to_hold_says_how_to_stream_it():
    with pytest.raises(deathsphere.ParameterError) as err:
        deathsphere.ride(**{**ASK, "height": np.arange(201)[:, None] * 0.01, "speed": "1:20:0.1"})
    words = str(err.value)
    assert "201 x 191" in words and "\n" not in words
    # the function it names exists
    module, name = re.search(r"(deathsphere\.api\.\w+)\.(\w+)", words).groups()
    assert getattr(importlib.import_module(module), name) is two_wheeler_ride_sweep


def test_flat_ground_refuses_the_globes_limits():
    with pytest.raises(deathsphere.ParameterError, match="mu and max_g are for the globe"):
        deathsphere.ride(machine="benchmark-bicycle", flat=True, speed=5, max_g=3)


def test_a_head_that_reaches_the_globe_is_no_fit_and_counted():
    """A rider 2.6 m tall (head point) on a 16-foot globe: exactly the turns
    whose head clearance is not positive are ``no_fit`` (ride's status for
    a head that hits, before a wheel that lifts), the rest as without it,
    and the rider's table counts those speeds as ``head_hits``."""
    from dataclasses import replace

    from deathsphere.api.two_wheelers import TWO_WHEELERS
    from deathsphere.physics.status import REASONS, Reason

    tall = replace(TWO_WHEELERS["benchmark-bicycle"], head=(0.3, -2.6), name="tall")
    ask = dict(machine=tall, steer="free", diameter="16ft", height=[[2.0], [3.0]], speed=[4.0, 6.0, 8.0])
    table = deathsphere.ride(**ask, stability=False)
    turned = np.isfinite(table["lean_deg"])
    hits = turned & ~(table["head_clearance_m"] > 0)
    assert hits.sum() >= 1 and (turned & ~hits).sum() >= 3
    assert list(table["status"][hits]) == ["no_fit"] * int(hits.sum())
    assert set(table["reason"][hits]) == {REASONS[Reason.TURN_HEAD_HITS]} and "head" in REASONS[Reason.TURN_HEAD_HITS]
    assert "no_fit" not in set(table["status"][~hits])
    summary = deathsphere.ride(**ask, summary=True)
    for i, height in enumerate(ask["height"]):
        lane = table["height_m"] == height
        ok_speeds = set(table["v_rear_m_s"][lane & (table["status"] == "ok")])
        hit_speeds = set(table["v_rear_m_s"][lane & hits]) - ok_speeds
        assert summary["head_hits"][i] == len(hit_speeds)
        assert summary["speeds_ok"][i] == len(ok_speeds)


def test_only_keeps_the_full_tables_rows_of_those_statuses_in_order(plain):
    """only= filters as ride's does: the rows of the whole table whose
    status is one asked for, in their order, also when streamed."""
    mu = float(np.nanmedian(np.fmax(plain["mu_required_rear"], plain["mu_required_front"])))
    full = deathsphere.ride(**ASK, mu=mu, stability=False)
    kept = deathsphere.ride(**ASK, mu=mu, stability=False, only=["slips", "no_orbit"])
    want = np.isin(full["status"], ["slips", "no_orbit"])
    assert 0 < want.sum() < len(full)
    for name in ("input_row", "status", "lean_deg", "v_rear_m_s"):
        np.testing.assert_array_equal(np.asarray(kept[name]), np.asarray(full[name])[want])
    streamed = two_wheeler_ride_sweep(**ASK, mu=mu, stability=False, only="slips", chunk_size=1)
    rows = np.concatenate([t["input_row"] for t in streamed])
    np.testing.assert_array_equal(rows, np.asarray(full["input_row"])[np.asarray(full["status"]) == "slips"])


@pytest.mark.parametrize("extra, words", [
    ({"only": "ok", "summary": True}, "give only or summary, not both"),
    ({"only": "sideways"}, "only must be one of"),
])
def test_only_is_refused_where_it_means_nothing(extra, words):
    with pytest.raises(deathsphere.ParameterError, match=words):
        deathsphere.ride(**ASK | extra)


def test_only_on_flat_ground_is_refused():
    with pytest.raises(deathsphere.ParameterError, match="only is for the globe"):
        deathsphere.ride(machine="benchmark-bicycle", flat=True, speed=5, only="ok")
