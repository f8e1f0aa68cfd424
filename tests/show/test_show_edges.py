"""The show's edges: lanes at the floor, the top and the poles, a duration
against a commensurate act, long acts, non-finite times and names."""

import math
import tomllib

import numpy as np
import pytest

import deathsphere
from deathsphere.api.shows import EXAMPLE_PLAN

GLOBE = {"diameter": "16ft", "mu": 0.9, "max_g": 8, "duration": 60}
LOOPER = {"name": "Ben", "lane": "vertical", "azimuth": 0, "v_top": "6.5m/s"}


def example():
    return tomllib.loads(EXAMPLE_PLAN)


@pytest.mark.parametrize("at", [{"height": "0m"}, {"height": "16ft"}, {"theta": 0}, {"theta": 180},
                                {"theta": 179.999}, {"theta": 0.001}])
@pytest.mark.parametrize("speed", ["1m/s", "30km/h"])
def test_a_lane_at_the_floor_the_top_or_a_pole_has_a_status_or_a_one_line_refusal(at, speed):
    rider = {"name": "Ana", "lane": "horizontal", "speed": speed, **at}
    try:
        act = deathsphere.show({"globe": GLOBE, "rider": [rider, LOOPER]})
    except deathsphere.ParameterError as exc:
        assert "\n" not in str(exc) and str(exc).startswith("rider 'Ana': ")
        return
    assert act.riders["status"][0] != "" and len(act.pairs) == 1


def test_the_common_period_wins_over_a_duration():
    plain = deathsphere.show(example())
    assert plain.commensurate
    cut = deathsphere.show(example(), duration=1)
    assert cut.duration_s == plain.duration_s
    assert cut.pairs["min_clearance_m"].tolist() == plain.pairs["min_clearance_m"].tolist()
    plan = example()
    plan["globe"]["duration"] = 1
    assert deathsphere.show(plan).duration_s == plain.duration_s


def test_a_long_act_is_searched_chunk_by_chunk(monkeypatch):
    from deathsphere.act import pairs

    whole = deathsphere.show(example(), duration=1)
    seen = []
    part = pairs._grid_part

    def counted(*args):
        seen.append(part(*args).size)
        return part(*args)

    monkeypatch.setattr(pairs, "CHUNK_SAMPLES", 64)
    monkeypatch.setattr(pairs, "_grid_part", counted)
    chunked = deathsphere.show(example(), duration=1)
    assert len(seen) > 1 and max(seen) <= 65
    assert np.allclose(chunked.pairs["min_clearance_m"], whole.pairs["min_clearance_m"], rtol=0, atol=1e-3)


@pytest.mark.parametrize("t", [math.inf, -math.inf, math.nan, 1e300, -1.0])
def test_a_fall_outside_the_act_is_refused(t):
    act = deathsphere.show(example())
    with pytest.raises(deathsphere.ParameterError, match=r"^t must be a number in \[0, 1.27371\] s"):
        act.fall("Cal", t, 0.0)


@pytest.mark.parametrize("t", [math.nan, math.inf, [0.0, -math.inf]])
def test_positions_at_times_that_are_not_finite_are_refused(t):
    with pytest.raises(deathsphere.ParameterError, match="^t must be finite"):
        deathsphere.show(example()).positions(t)


@pytest.mark.parametrize("name", ["A@b", " Ana", "Ana "])
def test_a_name_that_fail_cannot_take_is_refused(name):
    plan = example()
    plan["rider"][0]["name"] = name
    with pytest.raises(deathsphere.ParameterError, match=r"^rider 1: name: .*'@'"):
        deathsphere.show(plan)


def test_every_name_a_plan_takes_is_one_fail_can_name():
    from deathsphere.cli.show import parse_fail

    plan = example()
    plan["rider"][0]["name"] = "Mary-Ann: the 2nd"
    act = deathsphere.show(plan)
    name, t, fraction = parse_fail(f"{act.riders['name'][0]}@0.5:0")
    assert act.fall(name, t, fraction)["rider"][0] == "Mary-Ann: the 2nd"


@pytest.mark.parametrize("k", [0, 3])          # a horizontal lane and a loop
def test_a_rider_too_wide_for_the_globe_is_refused(k):
    plan = example()
    plan["rider"][k]["width"] = "100m"
    name = plan["rider"][k]["name"]
    with pytest.raises(deathsphere.ParameterError, match=rf"^rider '{name}': width: 100 m does not fit"):
        deathsphere.show(plan)
    plan["rider"][k]["width"] = "0.6m"
    assert deathsphere.show(plan).riders["status"][k] == "ok"


@pytest.mark.parametrize("duration", ["60", np.int64(60), np.float64(60.0), 60])
def test_the_api_takes_a_duration_as_it_takes_any_number(duration):
    plan = example()
    plan["rider"][0]["height"] = "1.45m"          # no common period: the duration is used
    act = deathsphere.show(plan, duration=duration)
    assert act.duration_s == 60.0 and not act.commensurate


@pytest.mark.parametrize("bad", ["soon", "-1", np.float64(math.nan), True])
def test_a_bad_api_duration_is_refused_naming_it(bad):
    with pytest.raises(deathsphere.ParameterError, match="^duration must be"):
        deathsphere.show(example(), duration=bad)


def test_a_plan_dict_takes_numpy_numbers():
    plan = example()
    plan["rider"][0]["height"] = np.int64(2)
    plan["rider"][0]["phase"] = np.float64(10.0)
    plan["globe"]["mu"] = np.float32(0.9)
    act = deathsphere.show(plan, duration=60)
    assert act.riders["phi0_deg"][0] == pytest.approx(10.0)
    assert act.plan.riders[0].theta_deg == deathsphere.show(
        {**example(), "rider": [{**example()["rider"][0], "height": 2}]}).plan.riders[0].theta_deg
