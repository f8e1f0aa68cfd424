"""Regression tests for inputs that once crashed the tool, lost rows or
printed wrong numbers (docs/contract.md says what each must do instead)."""

from __future__ import annotations

import csv
import io
import json
import subprocess
import sys

import numpy as np
import pytest

DS = [sys.executable, "-m", "deathsphere"]


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def one_error_line(res, words=""):
    lines = res.stderr.strip().splitlines()
    assert res.exit_code == 2 and len(lines) == 1 and lines[0].startswith("deathsphere: error: "), res.stderr
    assert words in lines[0], lines[0]


# ---- rows lost or numbers falsified


@pytest.mark.parametrize("command, header", [("orbit", "theta,alpha,k"), ("vertical", "theta,v_top,k")])
def test_k_zero_in_a_batch_is_a_row_not_a_crash(run, command, header):
    res = run(command, "--input", "-", "--format", "csv", input=f"{header}\n60,10,0\n60,10,0.5\n")
    out = rows(res.stdout)
    assert res.exit_code == 0 and [r["k"] for r in out] == ["0.0", "0.5"]
    assert out[0]["stability"] == "unknown" and out[0]["stability_method"] == "not-analysed-k0"
    assert out[1]["stability"] in ("stable", "unstable")


def test_k_zero_on_the_command_line(run):
    res = run("orbit", "--theta", "60", "--alpha", "10", "-k", "0", "--format", "csv")
    assert res.exit_code == 0 and rows(res.stdout)[0]["stability"] == "unknown"


def test_a_row_of_commas_is_kept_and_numbering_never_shifts(run):
    data = "theta,alpha\n60,10\n,\n\n90,25\n\"60,10\n45,10\n"
    res = run("orbit", "--input", "-", "--format", "csv", input=data)
    out = rows(res.stdout)
    assert [r["input_row"] for r in out] == ["1", "2", "4", "5", "6"]
    assert [r["status"] for r in out] == ["ok", "invalid", "ok", "invalid", "ok"]
    assert "theta is missing" in out[1]["reason"] and "quote" in out[3]["reason"]
    assert res.exit_code == 1


@pytest.mark.parametrize("args, words", [
    (["--body", "sphere", "--theta", "120", "--omega", "1e308"], "omega (orbital rate) must be"),
    (["--theta", "60", "--alpha", "10", "-a", "1e-320"], "a (body radius) must be 1e-09"),
    (["--theta", "60", "--speed", "0"], "speed (contact speed) must be"),
    (["--theta", "60", "--omega", "-1"], "rate about the vertical: > 0"),
    (["--theta", "0:1e308:1e-300", "--alpha", "1"], "too many values"),
])
def test_values_that_would_overflow_are_refused(run, args, words):
    one_error_line(run("orbit", *args), words)


@pytest.mark.parametrize("periods", ["0.001", "0.999", "2.5"])
def test_simulate_runs_exactly_the_periods_asked(run, periods):
    res = run("simulate", "--theta", "60", "--alpha", "10", "--periods", periods, "--summary-only",
              "--format", "csv")
    summary = rows(res.stdout)[0]
    assert summary["status"] == "completed"
    assert float(summary["periods_simulated"]) == pytest.approx(float(periods), rel=1e-12)


def test_sweep_of_a_sphere_takes_its_spin(run):
    res = run("sweep", "--body", "sphere", "--theta", "60", "--omega3", "60:100:20", "--format", "csv")
    out = rows(res.stdout)
    assert res.exit_code == 0 and len(out) == 6 and "invalid" not in {r["status"] for r in out}
    assert "ok" in {r["status"] for r in out}
    one_error_line(run("sweep", "--body", "sphere", "--theta", "60"), "exactly one of omega3")


def test_sweep_combinations_that_break_a_rule_are_invalid_rows(run):
    res = run("sweep", "--theta", "60", "--alpha", "10", "-a", "0.3", "-a", "5", "--format", "csv")
    out = rows(res.stdout)
    assert res.exit_code == 1 and [r["status"] for r in out] == ["ok", "invalid"]
    assert "r (sphere radius) must be > a" in out[1]["reason"]


# ---- tracebacks and hangs


@pytest.mark.parametrize("args", [["--theta", "3"], ["--theta", "30", "--mu", "0.01"],
                                  ["--theta", "30", "--mu", "1", "--max-g", "5"]])
def test_limits_with_nothing_feasible(run, args):
    res = run("limits", *args, "--format", "csv")
    out = rows(res.stdout)
    assert res.exit_code == 0 and len(out) == 1 and out[0]["intervals"] == "0"


def test_limits_says_when_the_bound_needs_unbounded_speed(run):
    out = rows(run("limits", "--mu", "1", "--format", "csv").stdout)[0]
    assert out["v_cm_m_s"] == "" and "without limit" in out["note"]
    assert float(out["theta_deg"]) == pytest.approx(45.0, abs=1e-6)


@pytest.mark.parametrize("command, path, words", [
    ("map", "nodir/map.png", "does not exist"),
    ("map", "{tmp}/dir.png", "is a directory"),
    ("map", "{tmp}/dir.png/", "is a directory"),
    ("map", "map.jpg", ".png, .svg or .pdf"),
    ("simulate", "s.xyz", "must end in"),
    ("simulate", "nodir/run.png", "does not exist"),
])
def test_output_paths_are_checked_before_any_work(run, tmp_path, monkeypatch, command, path, words):
    import deathsphere.simulation as simulation

    def never(*args, **kwargs):
        raise AssertionError("integrated before the --output check")

    monkeypatch.setattr(simulation.Simulation, "chunks", never)
    monkeypatch.chdir(tmp_path)
    (tmp_path / "dir.png").mkdir()
    extra = ["--theta", "60", "--alpha", "10"] if command == "simulate" else []
    one_error_line(run(command, *extra, "--output", path.format(tmp=tmp_path)), words)


def test_a_missing_plot_extra_is_refused_before_any_work(run, monkeypatch, tmp_path):
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: None if name == "matplotlib" else real(name, *a))
    one_error_line(run("map", "--output", str(tmp_path / "m.png")), "pip install 'deathsphere[plot]'")


@pytest.mark.parametrize("command, args, words", [
    ("vertical", ["--theta", "90", "--v-top", "1e308"], "v_top (top speed)"),
    ("vertical", ["--theta", "90", "--phidot-top", "-2"], "phidot_top (top rate)"),
    ("limits", ["-g", "1e-320"], "g (gravity)"),
    ("map", ["--step", "nan"], "step (theta step)"),
    ("sweep", ["--theta", "0:180:1e-9", "--alpha", "1"], "at most 1e+09"),
    ("vertical", ["--theta", "90", "--v-top", "0:1:1e-12"], "at most 1e+09"),
    ("vertical", ["--theta", "90", "--v-top", "6", "--points", "0"], "points"),
])
def test_extreme_values_are_usage_errors(run, command, args, words):
    one_error_line(run(command, *args), words)


def test_a_huge_sweep_starts_at_once():
    """Validation is per chunk: a 1e12-row grid prints its first rows at once."""
    head = subprocess.run(" ".join(DS + ["sweep", "-a", "0.1:0.2:1e-6", "-r", "3:4:1e-6", "--theta", "60",
                                         "--alpha", "10", "--no-stability", "|", "head", "-3"]),
                          shell=True, capture_output=True, text=True, timeout=60)
    assert len(head.stdout.splitlines()) == 3 and head.stderr == ""


# ---- exit statuses and streams


@pytest.mark.parametrize("args", [
    ["sweep", "--theta", "0:180:0.1", "--alpha", "0:90:0.1"],
    ["simulate", "--theta", "60", "--alpha", "10"],
    ["orbit", "--theta", "0:180:0.5", "--alpha", "0:90:0.5", "--format", "json"],
    ["map", "--format", "json"],
])
def test_a_reader_that_stops_early_is_not_an_error(args):
    proc = subprocess.run(" ".join(DS + args) + " | head -1 > /dev/null; echo ${PIPESTATUS[0]}", shell=True,
                          capture_output=True, text=True, timeout=120, executable="/bin/bash")
    assert proc.stdout.strip() == "0" and proc.stderr == ""


@pytest.mark.parametrize("redirect, code, words", [
    (">&-", 3, "standard output is closed"),
    ("> /dev/full", 3, "No space left on device"),
    ("--input - <&-", 2, "standard input"),
])
def test_closed_or_full_streams_give_one_line(redirect, code, words):
    args = "orbit --theta 0:180:1 --alpha 10" if "input" not in redirect else "orbit"
    proc = subprocess.run(" ".join(DS) + f" {args} {redirect}", shell=True, capture_output=True, text=True,
                          timeout=60, executable="/bin/bash")
    lines = proc.stderr.strip().splitlines()
    assert proc.returncode == code and len(lines) == 1 and words in lines[0], proc.stderr


def test_bare_command_prints_the_help(run):
    res = run()
    assert res.exit_code == 0 and "Commands:" in res.stdout and "orbit" in res.stdout and res.stderr == ""


@pytest.mark.parametrize("bom, encoding", [(b"\xef\xbb\xbf", "utf-8"), (b"", "utf-16")])
def test_spreadsheet_encodings(run, bom, encoding):
    data = bom + "theta,alpha\r\n60,10\r\n".encode(encoding)
    res = run("orbit", "--input", "-", "--format", "csv", input=data)
    assert res.exit_code == 0 and rows(res.stdout)[0]["status"] == "ok"


@pytest.mark.parametrize("args", [
    ["--theta", "30:90:30", "--alpha", "10"],
    ["--theta", "60", "--speed", "7"],
    ["--body", "particle", "--theta", "120"],
    ["--body", "sphere", "--theta", "60", "--omega3", "80"],
])
def test_output_fed_back_gives_the_same_orbits(run, args):
    first = run("orbit", *args, "--format", "csv")
    data = first.stdout
    if "sphere" in args:  # the spin was the input: the one column renamed, as docs/contract.md says
        data = data.replace("omega3_rad_s", "omega3", 1)
    again = run("orbit", "--input", "-", "--format", "csv", input=data)
    a, b = rows(first.stdout), rows(again.stdout)
    assert again.exit_code == 0
    # every row fed back recomputes its orbit (a sphere's two rows each give both branches again)
    for row in a:
        same = [r for r in b if r["status"] == row["status"] and r["theta_deg"] == row["theta_deg"]
                and all(r[k] == row[k] == "" or (r[k] and row[k] and float(r[k]) == pytest.approx(float(row[k]),
                                                                                                  rel=1e-12))
                        for k in ("v_cm_m_s", "mu_required", "omega_rad_s"))]
        assert same, row


def test_a_range_ends_on_its_stop(run):
    res = run("orbit", "--theta", "0.3:180:0.1", "--alpha", "10", "--no-stability", "--format", "csv")
    out = rows(res.stdout)
    assert res.exit_code == 0 and out[-1]["theta_deg"] == "180.0" and out[1]["theta_deg"] == "0.4"


def test_any_tilt_is_reduced(run):
    """205 deg and -155 deg are the same tilt; the row echoes what was given."""
    a = rows(run("orbit", "--side", "outside", "--theta", "30", "--alpha", "205", "--format", "csv").stdout)[0]
    b = rows(run("orbit", "--side", "outside", "--theta", "30", "--alpha", "-155", "--format", "csv").stdout)[0]
    assert a["alpha_deg"] == "205.0" and a["status"] == b["status"] == "ok"
    for key in ("omega_rad_s", "v_cm_m_s", "mu_required", "growth_rate_1_s"):
        assert float(a[key]) == pytest.approx(float(b[key]), rel=1e-12)


def test_stability_says_when_there_is_no_orbit(run):
    out = json.loads(run("stability", "--theta", "0", "--alpha", "10", "--format", "json").stdout)
    status = next(r for r in out if r["quantity"] == "orbit status")
    assert status["exact"] == "no_fit" and all(r["exact"] is None for r in out if r is not status)
    assert np.all([r["source"] == "exact" for r in out])
