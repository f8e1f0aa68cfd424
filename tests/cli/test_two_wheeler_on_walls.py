"""``deathsphere ride`` of a two-wheeler on the wall of death's drum and the
well of death's cone (docs/two-wheeler.md sec. 12): the globe's columns and
the arena's, the drum's symmetry in its rows, and one-line refusals."""

import csv
import io

import numpy as np
import pytest

import deathsphere
from deathsphere.api.two_wheelers import TURN_APPENDED, TURN_ARENA_COLUMNS, TURN_COLUMNS, TURN_LIMIT_COLUMNS

STUNT = ("ride", "--machine", "stunt125-steer")
DRUM = (*STUNT, "--surface", "cylinder", "--diameter", "32ft", "--wall-height", "12ft")
WELL = (*STUNT, "--surface", "cone", "--wall-angle", "80", "--diameter", "32ft")


def _rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_a_drums_turns_have_the_globes_columns_and_the_arenas(run):
    """One turn per height at 60 km/h; the drum is the same wall at every
    height, so every height's turn is the same turn (lean, steer, rate,
    steer torque, forces; only the height differs)."""
    res = run(*DRUM, "--height", "0.5:3.5:1m", "--speed", "60km/h", "--format", "csv")
    assert res.exit_code == 0, res.output
    rows = _rows(res.stdout)
    eigs = [f"eig_{i}_{part}" for i in range(1, 7) for part in ("re", "im")]
    assert list(rows[0]) == [*TURN_COLUMNS, *eigs, *TURN_LIMIT_COLUMNS, *TURN_APPENDED, *TURN_ARENA_COLUMNS]
    assert [r["height_m"] for r in rows] == ["0.5", "1.5", "2.5", "3.5"]
    assert all(r["status"] == "ok" and r["theta_deg"] == "" and r["theta_front_deg"] == "" for r in rows)
    assert all(r["surface"] == "cylinder" and float(r["rho_contact_m"]) == 4.8768 and float(r["wall_angle_deg"]) == 90
               for r in rows)
    for col in ("lean_wall_deg", "steer_deg", "omega_rad_s", "steer_torque_n_m", "normal_rear_per_mass_m_s2",
                "normal_front_per_mass_m_s2", "load_g", "eig_1_re"):
        values = np.array([float(r[col]) for r in rows])
        assert np.ptp(values) <= 1e-9 * max(1.0, np.abs(values).max()), col
    # the lean from the vertical and from the wall's normal, 90 degrees apart on a vertical wall
    for r in rows:
        assert float(r["lean_vertical_deg"]) - float(r["lean_wall_deg"]) == pytest.approx(90.0, abs=1e-9)
        assert float(r["alpha_deg"]) + float(r["lean_vertical_deg"]) == pytest.approx(90.0, abs=1e-9)


def test_a_cones_turns_and_the_api_agree(run):
    """The command line and deathsphere.ride give the same turns on a well
    of death; the wall angle and the contact's radius are the cone's."""
    res = run(*WELL, "--height", "1", "--speed", "50km/h", "--format", "csv")
    assert res.exit_code == 0, res.output
    rows = _rows(res.stdout)
    table = deathsphere.ride(machine="stunt125-steer", steer="free", surface="cone", wall_angle=80,
                             diameter="32ft", height=1, speed="50km/h")
    assert len(rows) == len(table) >= 1
    for row, lean in zip(rows, table["lean_wall_deg"]):
        assert float(row["lean_wall_deg"]) == lean
        assert float(row["wall_angle_deg"]) == pytest.approx(80.0, abs=1e-12)
        assert float(row["rho_contact_m"]) == pytest.approx(4.8768 + np.cos(np.radians(80)) / np.sin(np.radians(80)),
                                                            abs=1e-12)


def test_a_walls_hands_free_turns_and_rider_table(run):
    res = run(*DRUM, "--height", "2", "--steer-torque", "0", "--format", "csv")
    assert res.exit_code == 0, res.output
    assert all(float(r["steer_torque_n_m"]) == 0.0 for r in _rows(res.stdout))
    res = run(*WELL, "--height", "1:2:1", "--speed", "40:60:20km/h", "--summary", "--format", "csv")
    assert res.exit_code == 0, res.output
    rows = _rows(res.stdout)
    assert [r["height_m"] for r in rows] == ["1.0", "2.0"] and all(r["theta_deg"] == "" for r in rows)
    assert all(int(r["speeds_tried"]) == 2 for r in rows)


def test_a_profile_from_a_file_rides_as_the_drum_it_samples(run, tmp_path):
    """A meridian file of a 32-foot drum's wall: its turn is the drum's (the
    spline reproduces the straight meridian), r_m empty as a profile's."""
    path = tmp_path / "drum.csv"
    path.write_text("rho_ft,z_ft\n16,0\n16,5\n16,10\n16,20\n")
    tail = ("--height", "2", "--speed", "60km/h", "--no-stability", "--format", "csv")
    res = run(*STUNT, "--surface", "profile", "--profile", str(path), *tail)
    assert res.exit_code == 0, res.output
    (row,) = _rows(res.stdout)
    (drum,) = _rows(run(*STUNT, "--surface", "cylinder", "--diameter", "32ft", *tail).stdout)
    assert row["surface"] == "profile" and row["r_m"] == "" and drum["r_m"] == "4.8768"
    for col in ("lean_wall_deg", "steer_deg", "steer_torque_n_m", "normal_rear_per_mass_m_s2", "load_g",
                "rho_contact_m", "wall_angle_deg"):
        assert float(row[col]) == pytest.approx(float(drum[col]), rel=1e-12, abs=1e-12), col


@pytest.mark.parametrize("args, option, words", [
    ((*DRUM, "--height", "4", "--speed", "60km/h"), "--height", "at most 3.6576 m on this cylinder"),
    ((*DRUM, "--theta", "90", "--speed", "60km/h"), "--theta", "on a cylinder give height"),
    # flat ground's lane is its turn radius (its turns: tests/test_two_wheeler_flat_turns.py)
    ((*STUNT, "--surface", "plane", "--height", "1", "--speed", "5"), "--height", "flat ground has no height"),
    ((*STUNT, "--surface", "plane", "--speed", "5"), "--turn-radius", "Missing option"),
    ((*STUNT, "--surface", "cylinder", "--diameter", "0.5", "--height", "0.1", "--speed", "5"), "--diameter",
     "do not fit in a cylinder"),
    (("ride", "--machine", "benchmark-bicycle", "--flat", "--speed", "5", "--surface", "cylinder"), "--surface",
     "not for it"),
])
def test_what_a_two_wheeler_cannot_ride_exits_2_with_one_line(run, args, option, words):
    res = run(*args)
    assert res.exit_code == 2 and res.stdout == ""
    assert option in res.stderr and words in res.stderr and len(res.stderr.strip().splitlines()) == 1


def test_flat_grounds_turn_from_the_command_line_is_the_apis(run):
    """``ride --surface plane --turn-radius`` (docs/two-wheeler.md sec. 12.8): the API's turn, its lane
    echoed as the contact's distance from the turn's centre."""
    import csv
    import io

    import deathsphere

    res = run(*STUNT, "--surface", "plane", "--turn-radius", "10", "--speed", "20km/h", "--steer", "free",
              "--format", "csv")
    assert res.exit_code == 0, res.stderr
    (row,) = list(csv.DictReader(io.StringIO(res.stdout)))
    api = deathsphere.ride(machine="stunt125-steer", steer="free", surface="plane", turn_radius=10, speed="20km/h")
    assert row["surface"] == "plane" and float(row["rho_contact_m"]) == 10.0 and row["status"] == "ok"
    for col in ("lean_deg", "steer_deg", "steer_torque_n_m", "omega_rad_s", "eig_1_re", "head_clearance_m"):
        assert float(row[col]) == pytest.approx(float(api[col][0]), rel=1e-12), col
