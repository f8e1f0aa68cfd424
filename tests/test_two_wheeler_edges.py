"""The two-wheeler's edges through the Python API: what a row that finds no
turn says, an empty request, booleans, absurd parameters and impossible
geometry refused in one line (docs/two-wheeler.md sec. 10, docs/contract.md)."""

import math
from dataclasses import replace

import numpy as np
import pytest

import deathsphere
from deathsphere import ParameterError
from deathsphere.api.two_wheelers import STRAIGHT_COLUMNS, TURN_COLUMNS, TWO_WHEELERS, TwoWheeler

#: A lane and a rear speed the benchmark bicycle has no steady turn at (far too fast for its lean curve).
NO_TURN = dict(machine="stunt125-steer", steer="free", height=1.0, diameter="16ft")


def _no_orbit(table):
    return [row for row in table if row["status"] == "no_orbit"]


def test_a_row_without_a_turn_has_no_eigenvalue_at_all():
    rows = _no_orbit(deathsphere.ride(**NO_TURN, speed=[1.0, 100.0]))
    assert rows
    for row in rows:
        for i in range(1, 7):
            assert row[f"eig_{i}_re"] is None and row[f"eig_{i}_im"] is None


def test_a_row_without_a_turn_echoes_the_speed_asked_for():
    rows = _no_orbit(deathsphere.ride(**NO_TURN, speed=[100.0, 120.0]))
    assert [row["v_rear_m_s"] for row in rows] == [100.0, 120.0]
    assert [row["v_contact_m_s"] for row in rows] == [100.0, 120.0]


def test_a_row_without_a_turn_echoes_the_steer_torque_asked_for():
    rows = _no_orbit(deathsphere.ride(machine="benchmark-bicycle", steer_torque=[1e4, 2e4], height=1.0,
                                      diameter="16ft"))
    assert [row["steer_torque_n_m"] for row in rows] == [1e4, 2e4]


@pytest.mark.parametrize("kwargs, columns", [
    (dict(flat=True), STRAIGHT_COLUMNS),
    (dict(steer="free", height=1.0, diameter="16ft"), TURN_COLUMNS),
])
def test_no_speed_asked_for_is_an_empty_table(kwargs, columns):
    # as deathsphere.orbit answers an empty list: no row, the columns all there
    t = deathsphere.ride(machine="benchmark-bicycle", speed=[], **kwargs)
    assert len(t) == 0
    assert set(columns) <= set(t.columns)


def test_no_lane_asked_for_is_an_empty_table():
    t = deathsphere.ride(machine="benchmark-bicycle", steer="free", height=[], speed=5.0, diameter="16ft")
    assert len(t) == 0 and set(TURN_COLUMNS) <= set(t.columns)


@pytest.mark.parametrize("kwargs, name", [
    (dict(flat=True, speed=5.0, summary="no"), "summary"),
    (dict(flat=True, speed=5.0, stability="no"), "stability"),
    (dict(flat="yes", speed=5.0), "flat"),
    (dict(steer="free", height=1.0, speed=5.0, diameter="16ft", summary="no"), "summary"),
    (dict(steer="free", height=1.0, speed=5.0, diameter="16ft", stability=1), "stability"),
])
def test_booleans_are_booleans(kwargs, name):
    with pytest.raises(ParameterError) as err:
        deathsphere.ride(machine="benchmark-bicycle", **kwargs)
    assert err.value.param == name and "\n" not in str(err.value)


def test_two_wheeler_ride_itself_takes_no_text_for_flat():
    from deathsphere.api.two_wheelers import two_wheeler_ride

    with pytest.raises(ParameterError) as err:
        two_wheeler_ride("benchmark-bicycle", dict(flat="no", steer="free", height=1.0, speed=5.0, diameter="16ft"))
    assert err.value.param == "flat"


@pytest.mark.parametrize("kwargs, name", [
    (dict(flat="yes"), "flat"), (dict(hands_free="no"), "hands_free"), (dict(view=0), "view"),
])
def test_simulate_booleans_are_booleans(kwargs, name):
    from deathsphere.api.two_wheelers import simulate_two_wheeler

    with pytest.raises(ParameterError) as err:
        simulate_two_wheeler("benchmark-bicycle", speed=5.0, **({"flat": True} | kwargs))
    assert err.value.param == name


BENCHMARK = TWO_WHEELERS["benchmark-bicycle"].benchmark_values()


@pytest.mark.parametrize("key, value, words", [
    ("mB", 1e300, "mB (rear frame mass) must be 0..10000 kg (got 1e+300)"),
    # a million tonnes was accepted: no two-wheeler weighs that
    ("mB", 1e9, "mB (rear frame mass) must be 0..10000 kg (got 1000000000)"),
    ("IBxx", 1e7, "IBxx (rear frame inertia xx) must be 0..100000 kg m^2"),
    ("w", 1e6, "w (wheel base) must be 0.05..10 m"),
    ("rF", 1e-6, "rF (front wheel radius) must be 0.01..3 m"),
    ("xH", 1e6, "xH (front frame mass centre x) must be -10..10 m"),
])
def test_a_physically_absurd_parameter_is_refused_naming_it(key, value, words):
    with pytest.raises(ParameterError) as err:
        TwoWheeler(**(BENCHMARK | {key: value}))
    assert words in str(err.value) and "\n" not in str(err.value)


def test_an_absurd_file_key_is_refused_naming_it(tmp_path):
    from deathsphere.records.two_wheeler_files import two_wheeler_file

    path = tmp_path / "heavy.toml"
    path.write_text('base = "benchmark-bicycle"\nmB = 1e300\n')
    with pytest.raises(ParameterError) as err:
        two_wheeler_file(path)
    assert "heavy.toml" in str(err.value) and "mB (rear frame mass)" in str(err.value)


@pytest.mark.parametrize("corner", [
    dict(mB=1e4, IBxx=1e5, IByy=1e5, IBzz=1e5, IBxz=0.0),
    dict(mB=1e4, IBxx=0.0, IByy=0.0, IBzz=0.0, IBxz=0.0, mH=0.0, IHxx=0.0, IHyy=0.0, IHzz=0.0, IHxz=0.0),
    dict(w=10.0, rR=3.0, rF=3.0, xB=5.0, zB=-10.0, xH=9.0, zH=-5.0),
    dict(w=0.05, rR=0.01, rF=0.01, xB=0.01, zB=-0.02, xH=0.04, zH=-0.02, c=0.001),
])
def test_the_bounds_corners_give_numbers_not_warnings(corner):
    # the suite turns RuntimeWarning into an error: none may leak at any corner the bounds allow
    t = TwoWheeler(**(BENCHMARK | corner))
    table = deathsphere.ride(machine=t, flat=True, speed=[0.0, 1.0, 10.0, 100.0])
    assert np.isfinite(table["growth_rate_1_s"]).all()


@pytest.mark.parametrize("change, words", [
    # a 2 m front wheel on the benchmark's 1.02 m wheel base: the rims cross
    (dict(rF=1.0), "the wheels overlap"),
    (dict(rF=2.0), "the wheels overlap"),
    # z is down: +0.9 m is below the ground
    (dict(zB=0.9), "zB = 0.9 m puts the rear frame's mass centre at or below the ground"),
    (dict(zH=0.0), "zH = 0 m puts the front frame's mass centre at or below the ground"),
])
def test_impossible_geometry_is_refused_with_the_reason(change, words):
    with pytest.raises(ParameterError) as err:
        TwoWheeler(**(BENCHMARK | change))
    assert words in str(err.value) and "\n" not in str(err.value)


def test_a_massless_body_may_sit_anywhere():
    # no mass, no mass centre to misplace (the motorcycle presets lump their wheels' masses into the frames)
    TwoWheeler(**(BENCHMARK | dict(mH=0.0, IHxx=0.0, IHyy=0.0, IHzz=0.0, IHxz=0.0, zH=0.5)))


def test_wheels_that_do_not_fit_in_the_globe_are_refused():
    with pytest.raises(ParameterError) as err:
        deathsphere.ride(machine="benchmark-bicycle", steer="free", theta=120, speed=3.0, r=0.2)
    assert err.value.param == "r" and "do not fit in a sphere of radius 0.2 m" in str(err.value)


def test_straight_running_refuses_more_speeds_than_it_holds_in_one_line(run):
    # 2e6 speeds ran out of memory writing the table (1e6 peaked at 1.9 GB): refused from the count
    result = run("ride", "--machine", "benchmark-bicycle", "--flat", "--speed", "0:2000000:1")
    assert result.exit_code == 2
    assert result.stdout == "" and len(result.stderr.strip().splitlines()) == 1
    assert "at most 500000 values of speed" in result.stderr and "--speed" in result.stderr


def test_straight_running_is_the_same_whatever_the_chunk(monkeypatch):
    import deathsphere.api.two_wheelers as tw

    whole = {steer: deathsphere.ride(machine="benchmark-bicycle", flat=True, speed="0:10:0.25", steer=steer)
             for steer in ("free", "locked")}
    monkeypatch.setattr(tw, "STRAIGHT_CHUNK", 3)
    for steer, same in whole.items():
        chunked = deathsphere.ride(machine="benchmark-bicycle", flat=True, speed="0:10:0.25", steer=steer)
        for column in same.columns:
            np.testing.assert_array_equal(np.asarray(chunked[column]), np.asarray(same[column]))


# ---------------------------------------------------------------------------
# words: one definition per lean name, what a disturbance does

def test_stability_kind_from_the_verdicts_tolerances():
    from deathsphere.physics.stability.verdict import STABLE_TOL, UNSTABLE_TOL, stability_kind

    growth = np.array([-1.0, -0.5 * STABLE_TOL, 0.0, 0.5 * STABLE_TOL, 0.5 * UNSTABLE_TOL, UNSTABLE_TOL, 1.0, np.nan,
                       0.0])
    scale = np.array([1.0] * 8 + [0.0])
    assert stability_kind(growth, scale).tolist() == ["damped", "neutral", "neutral", "neutral", "unknown",
                                                      "growing", "growing", "", "neutral"]


def test_straight_running_says_whether_its_modes_decay():
    t = deathsphere.ride(machine="benchmark-bicycle", flat=True, speed=[0.0, 5.0, 10.0], g=9.81)
    # 0 m/s: capsize and inverted pendulum grow; 5 m/s self-stable, every mode decays; 10 m/s the capsize grows
    assert t["stability_kind"].tolist() == ["growing", "damped", "growing"]
    assert t.names[-1] == "stability_kind"


def test_a_turns_kind_agrees_with_its_eigenvalues_and_is_empty_without_a_turn():
    t = deathsphere.ride(machine="stunt125-steer", steer="free", height=1.0, speed=[8.0, 10.0, 100.0],
                         diameter="16ft")
    for row in t:
        if row["status"] == "no_orbit":
            assert row["stability_kind"] == "" or row["stability_kind"] is None
            continue
        growth = row["growth_rate_1_s"]
        assert row["stability_kind"] == ("damped" if growth < 0 else "growing")
    skipped = deathsphere.ride(machine="stunt125-steer", steer="free", height=1.0, speed=8.0, diameter="16ft",
                               stability=False)
    assert all(k in ("", None) for k in skipped["stability_kind"].tolist())


def test_each_lean_name_has_one_definition_in_every_two_wheeler_table():
    kw = dict(machine="stunt125-steer", steer="free", height=[1.0, 2.0], diameter="16ft")
    turns = deathsphere.ride(**kw, speed=[8.0, 10.0])
    ok = turns["status"] == "ok"
    np.testing.assert_array_equal(turns["lean_wall_deg"], turns["lean_surface_deg"])
    np.testing.assert_array_equal(turns["lean_vertical_deg"], turns["lean_deg"])
    # from the wall's normal at the rear contact and from the vertical: 180 deg - theta apart
    np.testing.assert_allclose(turns["lean_vertical_deg"][ok] - turns["lean_wall_deg"][ok],
                               180.0 - turns["theta_deg"][ok], atol=1e-9)
    summary = deathsphere.ride(**kw, speed=[8.0, 10.0], summary=True)
    for lane in range(2):
        mine = ok & (turns["height_m"] == summary["height_m"][lane])
        for name in ("lean_vertical", "lean_wall"):
            assert summary[f"{name}_min_deg"][lane] == turns[f"{name}_deg"][mine].min()
            assert summary[f"{name}_max_deg"][lane] == turns[f"{name}_deg"][mine].max()
        assert summary["lean_min_deg"][lane] == summary["lean_vertical_min_deg"][lane]


def test_simulate_names_its_lean_from_the_wall_and_its_start_from_the_vertical():
    from deathsphere.api.two_wheelers import simulate_two_wheeler

    series, summary = simulate_two_wheeler("stunt125-steer", height=2.0, speed=9.0, diameter="16ft", periods=0.1,
                                           points_per_period=20)
    np.testing.assert_array_equal(series["lean_wall_deg"], series["lean_surface_deg"])
    turn = deathsphere.ride(machine="stunt125-steer", steer="free", height=2.0, speed=9.0, diameter="16ft")[0]
    assert summary["lean_wall_deg"][0] == pytest.approx(turn["lean_wall_deg"], abs=1e-9)
    assert summary["lean_vertical_deg"][0] == pytest.approx(turn["lean_vertical_deg"], abs=1e-9)


# ---------------------------------------------------------------------------
# the rider's table: the stable speeds the rider can take

TOURER = dict(machine="sport-tourer", steer="locked", diameter="16ft", height=1.0, speed="40:65:3km/h", summary=True)


def test_the_stable_band_lies_within_the_limits_given_and_says_what_lies_beyond():
    free = deathsphere.ride(**TOURER)[0]
    assert free["speeds_stable"] == 4 and free["stable_beyond_limits"] == 0
    # the band's load, which no limit bounded: 6 g and more
    assert free["stable_load_min_g"] > 6.0 and free["stable_load_max_g"] > free["stable_load_min_g"]
    limited = deathsphere.ride(**TOURER, max_g=5.0, mu=1.0)[0]
    assert limited["speeds_stable"] == 0 and limited["stable_v_min_m_s"] is None
    assert limited["stable_load_min_g"] is None
    # the only stable speeds are past max_g: counted and spanned, not called the rider's
    assert limited["stable_beyond_limits"] == 4
    assert (limited["stable_beyond_v_min_m_s"], limited["stable_beyond_v_max_m_s"]) == (
        free["stable_v_min_m_s"], free["stable_v_max_m_s"])
