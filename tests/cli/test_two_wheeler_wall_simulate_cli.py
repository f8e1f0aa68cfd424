"""``deathsphere simulate`` of a two-wheeler on the wall of death's drum and
the well of death's cone (docs/two-wheeler.md sec. 12.7): it starts from
the turn ``ride`` finds at that height and speed, keeps the globe's columns
with the arena's appended, and refuses in one line what it cannot ride."""

import csv
import io

import numpy as np
import pytest

import deathsphere
from deathsphere.api.two_wheelers import (SIMULATE_COLUMNS, SIMULATE_SUMMARY_COLUMNS, WALL_SERIES_COLUMNS,
                                          WALL_SUMMARY_COLUMNS)

STUNT = ("simulate", "--machine", "stunt125-steer")
DRUM = ("--surface", "cylinder", "--diameter", "32ft", "--height", "2m", "--speed", "60km/h")
WELL = ("--surface", "cone", "--wall-angle", "80", "--diameter", "32ft", "--height", "2m", "--speed", "60km/h")
#: a short run: a twentieth of a lap, loose tolerances (the physics' own tests hold the accuracy)
SHORT = ("--periods", "0.05", "--points-per-period", "40", "--rtol", "1e-7")


def _rows(text):
    return list(csv.DictReader(io.StringIO(text)))


@pytest.mark.parametrize("arena, ride_arena", [
    (DRUM, dict(surface="cylinder", diameter="32ft")),
    (WELL, dict(surface="cone", wall_angle=80, diameter="32ft")),
], ids=["drum", "cone"])
@pytest.mark.parametrize("steer", ["free", "locked"])
def test_a_run_on_a_wall_starts_from_rides_turn_with_the_arenas_columns(run, arena, ride_arena, steer):
    res = run(*STUNT, "--steer", steer, *arena, *SHORT, "--perturb", "1", "--summary-only", "--format", "csv")
    assert res.exit_code == 0, res.output
    (row,) = _rows(res.stdout)
    assert list(row) == [*SIMULATE_SUMMARY_COLUMNS, *WALL_SUMMARY_COLUMNS]
    (turn,) = deathsphere.ride(machine="stunt125-steer", steer=steer, height=2, speed="60km/h", stability=False,
                               **ride_arena)
    for col in ("lean_surface_deg", "steer_deg", "steer_torque_n_m", "period_s", "lean_vertical_deg",
                "rho_contact_m", "wall_angle_deg", "r_m"):
        assert float(row[col]) == pytest.approx(float(turn[col]), rel=1e-12, abs=1e-12), col
    assert row["surface"] == ride_arena["surface"] and row["theta_deg"] == "" and row["status"] == "completed"
    assert float(row["height_m"]) == 2.0 and row["steer"] == steer
    # kicked a degree in lean, the rear contact moves off its lane, but not far in a twentieth of a lap
    assert 0 < float(row["max_height_drift_m"]) < 0.05


def test_the_series_gains_the_rear_contacts_lane(run):
    res = run(*STUNT, "--steer", "free", *DRUM, *SHORT, "--format", "csv")
    assert res.exit_code == 0, res.output
    rows = _rows(res.stdout)
    assert list(rows[0]) == [*SIMULATE_COLUMNS, *WALL_SERIES_COLUMNS]
    # unkicked, the steady turn holds its lane: 2 m up a drum of radius 16 ft
    height = np.array([float(r["height_m"]) for r in rows])
    rho = np.array([float(r["rho_contact_m"]) for r in rows])
    assert np.max(np.abs(height - 2.0)) < 1e-6 and np.all(rho == 4.8768)


@pytest.mark.parametrize("args, option, words", [
    (("--surface", "cylinder", "--diameter", "32ft", "--wall-height", "4m", "--height", "5m", "--speed", "60km/h"),
     "--height", "at most 4 m"),
    (("--surface", "cylinder", "--diameter", "32ft", "--theta", "60", "--speed", "60km/h"), "--theta",
     "give height"),
    (DRUM + ("--turn-radius", "3"), "--turn-radius", "on the cylinder height"),
    (DRUM + ("--flat",), "--flat", "not for it"),
    (("--surface", "cylinder", "--diameter", "0.5", "--height", "0.1", "--speed", "5"), "--diameter",
     "do not fit"),
    (("--surface", "cylinder", "--diameter", "32ft", "--height", "2", "--speed", "1"), "--speed",
     "no steady turn at height 2 m on the cylinder"),
])
def test_what_a_two_wheeler_cannot_ride_on_a_wall_exits_2_with_one_line(run, args, option, words):
    res = run(*STUNT, "--steer", "free", *args)
    assert res.exit_code == 2 and res.stdout == ""
    assert option in res.stderr and words in res.stderr and len(res.stderr.strip().splitlines()) == 1
    assert "Traceback" not in res.stderr


def test_a_profile_sampling_the_drum_runs_as_the_drum(run, tmp_path):
    """A meridian file of the 32-foot drum's wall: the same run as the
    drum's (the spline reproduces the straight meridian), r_m empty as a
    profile's."""
    path = tmp_path / "drum.csv"
    path.write_text("rho_ft,z_ft\n16,0\n16,5\n16,10\n16,20\n")
    tail = (*SHORT, "--perturb", "1", "--summary-only", "--format", "csv")
    res = run(*STUNT, "--steer", "free", "--surface", "profile", "--profile", str(path), "--height", "2m",
              "--speed", "60km/h", *tail)
    assert res.exit_code == 0, res.output
    (row,) = _rows(res.stdout)
    (drum,) = _rows(run(*STUNT, "--steer", "free", *DRUM, *tail).stdout)
    assert row["surface"] == "profile" and row["r_m"] == "" and row["status"] == "completed"
    for col in ("lean_surface_deg", "steer_torque_n_m", "max_lean_deviation_deg", "final_lean_deviation_deg",
                "max_height_drift_m", "rho_contact_m", "min_normal_front_per_mass_m_s2"):
        assert float(row[col]) == pytest.approx(float(drum[col]), rel=1e-9, abs=1e-12), col


def test_flat_grounds_turn_radius_still_reaches_its_run(run):
    """--turn-radius is flat ground's lane: without an arena it is passed once, as before walls were ridden."""
    res = run("simulate", "--machine", "benchmark-bicycle", "--flat", "--speed", "5", "--turn-radius", "10",
              "--steer", "locked", "--periods", "0.02", "--rtol", "1e-7", "--summary-only", "--format", "csv")
    assert res.exit_code == 0, res.output
    (row,) = _rows(res.stdout)
    assert row["surface"] == "flat" and float(row["turn_radius_m"]) == 10.0 and list(row) == list(
        SIMULATE_SUMMARY_COLUMNS)
