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
        two_wheeler_ride("benchmark-bicycle", flat="no", steer="free", height=1.0, speed=5.0, diameter="16ft")
    assert err.value.param == "flat"


@pytest.mark.parametrize("kwargs, name", [
    (dict(flat="yes"), "flat"), (dict(hands_free="no"), "hands_free"), (dict(view=0), "view"),
])
def test_simulate_booleans_are_booleans(kwargs, name):
    from deathsphere.api.two_wheelers import simulate_two_wheeler

    with pytest.raises(ParameterError) as err:
        simulate_two_wheeler("benchmark-bicycle", speed=5.0, **({"flat": True} | kwargs))
    assert err.value.param == name
