"""simulate off the globe on the command line (docs/simulation.md, "On any
ground"): the arena's options shared with orbit, the columns appended, and
every bad combination refused in one line naming the option (exit 2)."""

import csv
import io

import pytest

import deathsphere


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


DRUM = ("--surface", "cylinder", "--diameter", "32ft", "--height", "2")


def test_the_drum_run_starts_on_orbits_steady_orbit_and_appends_its_columns(run):
    res = run("simulate", *DRUM, "--alpha", "10", "--periods", "0.05", "--points-per-period", "40", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    table = rows(res.stdout)
    assert list(table[0])[-2:] == ["height_m", "rho_contact_m"]
    assert list(table[0])[:11] == list(deathsphere.simulation.SERIES_COLUMNS)
    assert all(row["theta_deg"] == "" for row in table)
    assert float(table[0]["height_m"]) == 2.0 and float(table[0]["rho_contact_m"]) == pytest.approx(4.8768)
    # the start is orbit's steady orbit on that lane: its speed and its push on the wall
    steady = deathsphere.orbit(surface="cylinder", diameter="32ft", height=2, alpha=10, stability=False)
    assert float(table[0]["speed_m_s"]) == pytest.approx(float(steady["v_cm_m_s"]), rel=1e-12)
    assert float(table[0]["normal_per_mass_m_s2"]) == pytest.approx(float(steady["normal_per_mass_m_s2"]),
                                                                     rel=1e-9)
    res = run("simulate", *DRUM, "--alpha", "10", "--periods", "0.05", "--summary-only", "--format", "csv")
    (summary,) = rows(res.stdout)
    assert list(summary)[-4:] == ["surface", "height_m", "max_height_drift_m", "max_rho_drift_m"]
    assert summary["surface"] == "cylinder" and summary["status"] == "completed"


def test_a_machine_on_the_drum_appends_the_machines_columns_and_the_walls(run):
    res = run("simulate", *DRUM, "--machine", "stunt125", "--alpha", "10", "--periods", "0.02",
              "--summary-only", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    (summary,) = rows(res.stdout)
    assert list(summary)[-6:] == ["machine", "min_head_clearance_m", "surface", "height_m", "max_height_drift_m",
                                  "max_rho_drift_m"]
    assert summary["surface"] == "cylinder" and summary["body"] == "machine" and summary["theta_deg"] == ""


@pytest.mark.parametrize("held", [("--speed", "30mph"), ("--com-speed", "12"), ("--omega", "2.5")])
def test_a_wheel_on_the_drum_given_its_speed_or_rate_starts_on_the_tilt_orbit_finds(run, held):
    res = run("simulate", *DRUM, *held, "--periods", "0.05", "--summary-only", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    (summary,) = rows(res.stdout)
    keyword = {"--speed": "speed", "--com-speed": "com_speed", "--omega": "omega"}[held[0]]
    steady = deathsphere.orbit(surface="cylinder", diameter="32ft", height=2, stability=False, **{keyword: held[1]})
    assert len(steady) == 1
    assert float(summary["alpha_deg"]) == pytest.approx(float(steady["alpha_deg"][0]), rel=1e-12)
    # the drum's contact runs round r = 16 ft: the rate the speed asks for, written out
    rate = {"--speed": 30 * 0.44704 / 4.8768, "--omega": 2.5}.get(held[0], float(steady["omega_rad_s"][0]))
    assert float(summary["omega_rad_s"]) == pytest.approx(rate, rel=1e-9)
    assert summary["status"] == "completed"


def test_a_wheel_on_a_cone_roof_starts_on_orbits_outside_orbit(run):
    roof = ("--surface", "cone", "--diameter", "10", "--wall-angle", "120", "--height", "2", "--side", "outside",
            "-a", "2", "--alpha", "235")
    res = run("simulate", *roof, "--periods", "0.05", "--points-per-period", "40", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    table = rows(res.stdout)
    steady = deathsphere.orbit(surface="cone", diameter=10, wall_angle=120, height=2, side="outside", a=2,
                               alpha=235, stability=False)
    assert str(steady["status"]) == "ok"
    assert float(table[0]["speed_m_s"]) == pytest.approx(float(steady["v_cm_m_s"]), rel=1e-12)
    assert float(table[0]["normal_per_mass_m_s2"]) == pytest.approx(float(steady["normal_per_mass_m_s2"]),
                                                                     rel=1e-9)
    res = run("simulate", *roof, "--periods", "0.05", "--summary-only", "--format", "csv")
    (summary,) = rows(res.stdout)
    assert summary["side"] == "outside" and summary["status"] == "completed"


@pytest.mark.parametrize("args, option", [
    (DRUM + ("--theta", "60", "--alpha", "10"), "--theta"),
    (DRUM + ("--speed", "1"), "--speed"),                   # too slow for any tilt to hold the wall
    (DRUM + ("--speed", "30mph", "--branch", "3"), "--branch"),
    # flat ground has one side (a drum, a cone and a profile are ridden outside too)
    (("--surface", "plane", "--turn-radius", "5", "--alpha", "10", "--side", "outside"), "--side"),
    (DRUM + ("--alpha", "10", "--vertical"), "--vertical"),
    (DRUM + ("--alpha", "10", "--com-speed", "20", "--machine", "stunt125"), "--com-speed"),
    (DRUM + ("--alpha", "10", "--machine", "stunt125", "--body", "sphere"), "--machine"),
    (("--surface", "plane", "--height", "2", "--alpha", "10"), "--height"),
    (("--surface", "plane", "--alpha", "10"), "--turn-radius"),
    (("--surface", "cone", "--diameter", "6", "--height", "2", "--alpha", "10"), "--wall-angle"),
    (("--surface", "cylinder", "--height", "2", "--alpha", "10"), "--diameter"),
    # a two-wheeler rides the drum, the cone and a profile (docs/two-wheeler.md sec. 12.7), not the plane's lanes
    (("--surface", "plane", "--turn-radius", "5", "--steer", "free", "--speed", "5", "--machine",
      "benchmark-bicycle"), "--surface"),
])
def test_bad_combinations_are_one_line_naming_the_option(run, args, option):
    res = run("simulate", *args)
    assert res.exit_code == 2
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0] and "Traceback" not in res.stderr
