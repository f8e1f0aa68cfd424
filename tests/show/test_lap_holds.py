"""A show's horizontal lane held by the contact's speed, the centre of
mass's, a lap time or another rider's lap (docs/show.md, "Lanes"): each
checked against ride's own rows and the lap's definition, and every
refusal one line naming the rider and the key."""

import math

import pytest

import deathsphere

GLOBE = {"diameter": "16ft", "mu": 0.9, "max_g": 8}
LOOPER = {"name": "Ben", "lane": "vertical", "azimuth": 90, "v_top": "6.5m/s"}


def _show(*riders, **kwargs):
    return deathsphere.show({"globe": GLOBE, "rider": list(riders)}, **kwargs)


def test_a_plans_speed_is_the_contacts_and_its_lane_is_rides():
    act = _show({"name": "Ana", "lane": "horizontal", "height": "2m", "speed": "40km/h"}, LOOPER, duration=2)
    row = act.riders[0]
    assert row["v_contact_m_s"] == 40 / 3.6
    # the contact's parallel: r sin(theta) from the axis, the rate the lap's
    r = 16 * 0.3048 / 2
    assert 2 * math.pi / row["period_s"] * r * math.sin(math.radians(row["theta_deg"])) == pytest.approx(40 / 3.6)
    (mine,) = [t for t in deathsphere.ride(height=2.0, speed="40km/h", diameter="16ft", mu=0.9, max_g=8,
                                           stability=False) if t["alpha_deg"] == row["alpha_deg"]]
    assert row["v_cm_m_s"] == mine["v_cm_m_s"] and row["load_g"] == mine["load_g"]


def test_a_lap_time_and_the_same_lap_as_a_looper():
    act = _show({"name": "Ana", "lane": "horizontal", "height": "1.4m", "period": "0.0212325min"},
                {"name": "Cal", "lane": "horizontal", "height": "2m", "same_lap_as": "Ben"}, LOOPER)
    ana, cal, ben = act.riders[0], act.riders[1], act.riders[2]
    assert ana["period_s"] == pytest.approx(1.27395)
    # Cal rides the looper's lap: his rate 2 pi over it (the loop's lap from its elliptic integral)
    assert act.lanes[1].rate == pytest.approx(2 * math.pi / ben["period_s"], rel=1e-9)
    assert cal["period_s"] == pytest.approx(ben["period_s"], rel=1e-9)
    assert act.commensurate


def test_a_chain_of_same_laps_resolves_and_a_circle_is_refused():
    act = _show({"name": "A", "lane": "horizontal", "height": "1.2m", "same_lap_as": "B"},
                {"name": "B", "lane": "horizontal", "height": "2.2m", "same_lap_as": "C"},
                {"name": "C", "lane": "horizontal", "height": "1.7m", "period": "1.3s"}, duration=1.3)
    assert [round(p, 9) for p in act.riders["period_s"]] == [1.3, 1.3, 1.3]
    with pytest.raises(deathsphere.ParameterError) as err:
        _show({"name": "A", "lane": "horizontal", "height": "1.2m", "same_lap_as": "B"},
              {"name": "B", "lane": "horizontal", "height": "2.2m", "same_lap_as": "A"})
    assert "rider 'A': same_lap_as" in str(err.value) and "circle" in str(err.value)


@pytest.mark.parametrize("rider, words", [
    ({"speed": "30km/h", "com_speed": "30km/h"}, ("rider 'Ana'", "com_speed", "exactly one")),
    ({"period": "1.3s", "same_lap_as": "Ben"}, ("rider 'Ana'", "same_lap_as", "exactly one")),
    ({"same_lap_as": "Zed"}, ("rider 'Ana'", "same_lap_as", "names no rider")),
    ({"same_lap_as": 3}, ("rider 'Ana'", "same_lap_as", "name of another rider")),
    ({"period": "3m"}, ("rider 'Ana'", "period", "a time")),
    ({}, ("rider 'Ana'", "speed", "com_speed", "period", "same_lap_as")),
])
def test_a_bad_hold_is_one_line_naming_the_rider_and_the_key(rider, words):
    with pytest.raises(deathsphere.ParameterError) as err:
        _show({"name": "Ana", "lane": "horizontal", "height": "2m", **rider}, LOOPER)
    message = str(err.value)
    assert "\n" not in message and all(w in message for w in words), message


def test_a_looper_cannot_take_a_lap_of_another():
    with pytest.raises(deathsphere.ParameterError, match="same_lap_as is not a key of a vertical lane|same_lap_as"):
        _show({"name": "Ana", "lane": "horizontal", "height": "2m", "speed": "30km/h"},
              {**LOOPER, "same_lap_as": "Ana"})
