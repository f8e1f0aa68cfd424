"""``deathsphere ride --surface cylinder|cone`` on the command line: the wall
of death's lap as the API gives it, and one line with exit status 2 for
what a wall does not take."""

import csv
import io

import pytest


def _rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_a_lap_on_the_drum_with_its_arena_columns(run):
    res = run("ride", "--machine", "stunt125", "--surface", "cylinder", "--diameter", "32ft", "--wall-height",
              "12ft", "--height", "5ft", "--com-speed", "40km/h", "--format", "csv")
    assert res.exit_code == 0
    (row,) = _rows(res.stdout)
    assert row["status"] == "ok" and row["surface"] == "cylinder" and row["theta_deg"] == ""
    assert float(row["v_cm_km_h"]) == pytest.approx(40.0) and float(row["wall_angle_deg"]) == 90.0
    assert float(row["friction_per_mass_m_s2"]) == pytest.approx(-9.80665, rel=1e-12)


def test_the_riders_table_on_the_cone_a_row_per_height(run):
    res = run("ride", "--surface", "cone", "--wall-angle", "80", "--diameter", "32ft", "--height", "3:5:1ft",
              "--speed", "30:80:10km/h", "--mu", "1", "--summary", "--format", "csv")
    assert res.exit_code == 0
    assert [r["speeds_tried"] for r in _rows(res.stdout)] == ["6", "6", "6"]


@pytest.mark.parametrize("args, named", [
    (("--surface", "cylinder", "--theta", "90", "--speed", "40km/h"), "--theta"),
    (("--surface", "cylinder", "--wall-height", "12ft", "--height", "13ft", "--speed", "40km/h"), "--height"),
    (("--surface", "drum", "--height", "5ft", "--speed", "40km/h"), "--surface"),
    (("--surface", "cone", "--wall-angle", "180", "--height", "5ft", "--speed", "40km/h"), "--wall-angle"),
    (("--wall-height", "3", "--height", "1", "--speed", "4"), "--wall-height"),
])
def test_what_a_wall_does_not_take_is_one_line_and_exit_2(run, args, named):
    res = run("ride", "--diameter", "32ft", *args)
    assert res.exit_code == 2
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and named in lines[0] and "Traceback" not in res.stderr


def test_a_wall_refuses_jobs_rather_than_ignoring_them(run):
    res = run("ride", "--surface", "cylinder", "--diameter", "32ft", "--height", "1", "--speed", "10", "--jobs", "2")
    assert res.exit_code == 2 and len(res.stderr.strip().splitlines()) == 1 and "--jobs" in res.stderr
