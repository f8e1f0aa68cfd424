import csv
import io

import pytest


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_steady_orbit_holds(run):
    res = run("simulate", "--theta", "60", "--alpha", "10", "--periods", "3", "--summary-only", "--format", "csv")
    (row,) = rows(res.stdout)
    assert row["status"] == "completed" and float(row["periods_simulated"]) == pytest.approx(3.0)
    assert float(row["max_theta_drift_deg"]) < 1e-8 and float(row["max_alpha_drift_deg"]) < 1e-8
    assert row["method"] == "DOP853" and float(row["rtol"]) == 1e-10


def test_time_series_streams_with_summary_on_stderr(run):
    res = run("simulate", "--theta", "60", "--alpha", "10", "--perturb", "3", "--periods", "2",
              "--points-per-period", "8", "--format", "csv")
    out = rows(res.stdout)
    assert list(out[0])[:3] == ["input_row", "t_s", "phi_deg"] and len(out) >= 16
    alphas = [float(r["alpha_deg"]) for r in out]
    assert max(alphas) - min(alphas) > 1.0  # the kick makes alpha nutate
    assert "completed" in res.stderr


def test_unstable_orbit_loses_contact(run):
    res = run("simulate", "--theta", "90", "--alpha", "80", "--perturb", "1e-6", "--summary-only", "--format", "json")
    assert '"status": "contact_lost"' in res.stdout


def test_vertical_run_and_slip(run):
    res = run("simulate", "--vertical", "--theta", "60", "--v-top", "6", "--mu", "0.6", "--summary-only",
              "--format", "csv")
    (row,) = rows(res.stdout)
    assert row["status"] == "slips" and row["orbit"] == "vertical"


def test_simulate_table_on_a_terminal(run):
    text = run("simulate", "--body", "sphere", "--theta", "60", "--omega3", "40", "--periods", "1",
               "--format", "table", env={"COLUMNS": "100"}).stdout
    assert "solve_ivp DOP853" in text and "status" in text


@pytest.mark.parametrize("args, words", [
    (["--theta", "60"], "needs alpha"),
    (["--theta", "60", "--alpha", "10", "--v-top", "3"], "v_top is for vertical orbits"),
    (["--vertical", "--theta", "90"], "v_top"),
    (["--body", "sphere", "--theta", "60"], "exactly one of omega3"),
    (["--body", "particle", "--theta", "120"], "is not one of 'wheel', 'sphere'"),
    (["--theta", "260", "--alpha", "10"], "theta (polar angle) must be 0..180 deg"),
    (["--theta", "60", "--alpha", "10", "--rtol", "0"], "--rtol"),
    (["--theta", "60", "--alpha", "10", "--perturb", "nan"], "--perturb"),
])
def test_simulate_usage_errors(run, args, words):
    res = run("simulate", *args)
    assert res.exit_code == 2 and words in res.stderr and len(res.stderr.strip().splitlines()) == 1


def test_a_machine_simulated_on_the_command_line(run):
    """--machine with ride's machine options: the series (CSV) gains the
    machine's columns, the summary has its status and name."""
    res = run("simulate", "--machine", "stunt125", "--theta", "20", "--alpha", "-10.34", "--diameter", "16ft",
              "--perturb", "1e-4", "--periods", "1", "--points-per-period", "4", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    out = rows(res.stdout)
    assert len(out) == 5 and list(out[0])[-2:] == ["v_cm_m_s", "head_clearance_m"]
    assert "completed" in res.stderr
    summary = rows(run("simulate", "--machine", "stunt125", "--theta", "90", "--alpha", "15", "--diameter", "16ft",
                       "--mass", "200", "-a", "0.32", "--perturb", "1e-3", "--periods", "1", "--summary-only",
                       "--format", "csv").stdout)
    (row,) = summary
    assert row["status"] == "completed" and row["machine"] == "stunt125 (modified)"
    assert row["body"] == "machine" and float(row["a_m"]) == 0.32 and float(row["min_head_clearance_m"]) > 0


@pytest.mark.parametrize("args, words", [
    (["--machine", "stunt125", "--theta", "60", "--alpha", "10", "-k", "0.3"], "k not allowed"),
    (["--machine", "stunt125", "--theta", "60", "--alpha", "10", "--body", "sphere"], "body not allowed"),
    (["--machine", "stunt125", "--vertical", "--theta", "90", "--v-top", "9"], "not simulated"),
    (["--machine", "stunt125", "--theta", "60"], "Missing option '--alpha'"),
    (["--theta", "60", "--alpha", "10", "--mass", "100"], "--mass is a machine option"),
    (["--machine", "bicycle", "--theta", "60", "--alpha", "10"], "'bicycle' is not one of"),
])
def test_a_machine_with_a_bad_combination_is_one_line(run, args, words):
    res = run("simulate", *args)
    assert res.exit_code == 2 and words in res.stderr and len(res.stderr.strip().splitlines()) == 1
    assert "Traceback" not in res.stderr and res.stdout == ""


def test_a_machine_without_yaw_inertia_is_refused_in_one_line(run):
    result = run("simulate", "--machine", "stunt125", "--roll-inertia", "10", "--pitch-inertia", "10",
                 "--yaw-inertia", "0", "--spin-inertia", "0", "--theta", "90", "--alpha", "20")
    assert result.exit_code == 2
    assert len(result.stderr.strip().splitlines()) == 1 and "yaw inertia" in result.stderr
    assert "Traceback" not in result.stderr and result.stdout == ""
