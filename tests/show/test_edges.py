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
