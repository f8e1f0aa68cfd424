"""deathsphere.api.two_wheelers.simulate_two_wheeler: a two-wheeler's run
on the globe from its steady turn, as ride --steer lists it; the controls
and refusals in one line."""

import math

import numpy as np
import pytest

import deathsphere
from deathsphere import ParameterError
from deathsphere.api.two_wheelers import SIMULATE_COLUMNS, SIMULATE_SUMMARY_COLUMNS, simulate_two_wheeler

RUN = dict(height=1.0, speed=5.0, diameter="16ft", periods=0.2, points_per_period=20, rtol=1e-6)


def test_the_run_starts_at_the_turn_ride_lists_and_holds_it_without_a_kick():
    turn = deathsphere.ride(machine="benchmark-bicycle", steer="free", height=1.0, speed=5.0, diameter="16ft",
                            stability=False)
    series, summary = simulate_two_wheeler("benchmark-bicycle", **RUN)
    assert list(series.columns) == list(SIMULATE_COLUMNS)
    assert list(summary.columns) == list(SIMULATE_SUMMARY_COLUMNS)
    assert len(series) == 5 and str(summary["status"][0]) == "completed"
    assert summary["height_m"][0] == 1.0 and summary["control"][0] == "steady-torque"
    np.testing.assert_allclose(series["lean_surface_deg"], turn["lean_surface_deg"][0], atol=1e-4)
    np.testing.assert_allclose(series["steer_torque_n_m"], turn["steer_torque_n_m"][0], rtol=1e-12)
    np.testing.assert_allclose(summary["period_s"][0], turn["period_s"][0], rtol=1e-12)
    # the rear contact runs round its lane
    np.testing.assert_allclose(series["theta_rear_deg"], turn["theta_deg"][0], atol=1e-3)


def test_hands_free_has_no_torque_and_conserves_energy():
    series, summary = simulate_two_wheeler("benchmark-bicycle", hands_free=True, **RUN | {"rtol": 1e-10})
    assert np.all(series["steer_torque_n_m"] == 0) and summary["control"][0] == "hands-free"
    assert summary["max_energy_drift"][0] < 1e-8


def test_the_riders_gains_enter_the_torque():
    series, summary = simulate_two_wheeler("benchmark-bicycle", steer_gains="10,10", perturb=0.2, **RUN)
    lean0 = summary["lean_surface_deg"][0]
    torque = summary["steer_torque_n_m"][0] + 10 * np.radians(series["lean_surface_deg"] - lean0) \
        + 10 * np.radians(series["lean_rate_deg_s"])
    np.testing.assert_allclose(series["steer_torque_n_m"], torque, rtol=1e-9, atol=1e-12)
    assert summary["control"][0] == "rider" and summary["k_lean_n_m_rad"][0] == 10


def test_too_little_friction_slips_at_once():
    _, summary = simulate_two_wheeler("benchmark-bicycle", mu=0.1, **RUN)
    assert summary["status"][0] == "slips" and summary["t_event_s"][0] == 0


@pytest.mark.parametrize("kwargs, words", [
    ({"steer": "locked"}, "steer must be free"),
    ({"view": "yes"}, "view must be True or False"),
    ({"hands_free": True, "steer_gains": (1, 2)}, "not both"),
    ({"steer_gains": (1, math.inf)}, "two finite numbers"),
    ({"speed": None}, "give speed"),
    ({"theta": 120}, "exactly one of theta and height"),
    ({"branch": 5}, "branch must be one of"),
    ({"speed": 500.0}, "no steady turn"),
    ({"height": 6.0}, "at most the globe's diameter"),
])
def test_bad_requests_are_refused_in_one_line(kwargs, words):
    with pytest.raises(ParameterError, match=words) as info:
        simulate_two_wheeler("benchmark-bicycle", **RUN | kwargs)
    assert "\n" not in str(info.value)


def test_a_single_contact_machine_is_refused():
    with pytest.raises(ParameterError, match="single-contact"):
        simulate_two_wheeler("stunt125", **RUN)
