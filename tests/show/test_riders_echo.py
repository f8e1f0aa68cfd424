"""The riders table echoes the plan: a horizontal lane's theta and phase
as typed (120 is 120.0 in the CSV, not 119.99999999999999 through the
contact's coordinates), whatever the direction and on a drum."""

import csv
import io

import pytest

from deathsphere import show


def _riders_csv(plan: dict) -> list[dict]:
    return list(csv.DictReader(io.StringIO(show(plan).riders.to_csv())))


@pytest.mark.parametrize("direction", ["ccw", "cw"])
def test_theta_and_phase_as_typed_on_the_globe(direction):
    rows = _riders_csv({"globe": {"diameter": 4.88, "duration": 10}, "rider": [
        {"name": "Ana", "lane": "horizontal", "theta": 120, "speed": 8.0, "phase": 120, "direction": direction},
        {"name": "Ben", "lane": "horizontal", "theta": 100, "period": 1.3, "phase": -77.7}]})
    assert [(r["theta_deg"], r["phi0_deg"]) for r in rows] == [("120.0", "120.0"), ("100.0", "282.3")]


def test_phase_as_typed_on_a_drum():
    rows = _riders_csv({"arena": {"surface": "cylinder", "diameter": "32ft", "wall_height": "12ft", "mu": 0.8},
                        "rider": [{"name": "Ana", "lane": "horizontal", "height": "3ft", "speed": "30mph"},
                                  {"name": "Ben", "lane": "horizontal", "height": "6ft", "same_lap_as": "Ana",
                                   "phase": 120},
                                  {"name": "Cal", "lane": "horizontal", "height": "9ft", "speed": "60km/h",
                                   "phase": 240}]})
    assert [(r["theta_deg"], r["phi0_deg"]) for r in rows] == [("", "0.0"), ("", "120.0"), ("", "240.0")]
