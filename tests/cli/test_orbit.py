import csv
import io
import json
import subprocess
import sys

import pytest

from deathsphere import __version__
from deathsphere.model import COLUMNS

CONTRACT = ("input_row,body,side,theta_deg,alpha_deg,a_m,r_m,k,g_m_s2,status,reason,r_prime_m,omega_rad_s,"
            "period_s,v_cm_m_s,spin_rad_s,accel_m_s2,accel_g,normal_per_mass_m_s2,friction_per_mass_m_s2,mu_required")


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_csv_header_starts_with_the_contract(run):
    res = run("orbit", "--theta", "60", "--alpha", "10", "--format", "csv")
    assert res.exit_code == 0
    header = res.stdout.splitlines()[0]
    assert header.startswith(CONTRACT + ",") and header == ",".join(COLUMNS)


def test_piped_output_defaults_to_csv(run):
    res = run("orbit", "--theta", "60", "--alpha", "10")
    assert res.stdout.startswith("input_row,body,side")
    (row,) = rows(res.stdout)
    assert row["status"] == "ok" and float(row["v_cm_m_s"]) == pytest.approx(7.8767, rel=1e-4)
    assert row["mu_available"] == ""  # no --mu: unlimited, empty


def test_table_format_shows_every_quantity(run):
    res = run("orbit", "--theta", "60", "--alpha", "10", "--format", "table", env={"COLUMNS": "100"})
    for label in ("Ω orbital rate", "v_cm", "wheel spin", "normal force", "μ required", "status", "ok"):
        assert label in res.stdout, label
    assert "\x1b[" not in res.stdout  # not a terminal: no colour codes, even in table format


def test_no_color_is_respected(run):
    res = run("orbit", "--theta", "60", "--alpha", "10", "--format", "table", env={"NO_COLOR": "1"})
    assert "\x1b[3" not in res.stdout


def test_ranges_and_repeats_make_all_combinations(run):
    res = run("orbit", "--theta", "30:90:30", "--theta", "135", "--alpha", "5", "--alpha", "10", "--format", "csv")
    got = [(r["theta_deg"], r["alpha_deg"]) for r in rows(res.stdout)]
    assert got == [(t, a) for t in ("30.0", "60.0", "90.0", "135.0") for a in ("5.0", "10.0")]
    assert [r["input_row"] for r in rows(res.stdout)] == [str(i) for i in range(1, 9)]


def test_json_and_ndjson(run):
    res = run("orbit", "--theta", "90", "--alpha", "0:30:15", "--format", "json")
    data = json.loads(res.stdout)
    assert [d["status"] for d in data] == ["no_orbit", "ok", "ok"]
    assert data[0]["omega_rad_s"] is None and list(data[0]) == list(COLUMNS)
    res = run("orbit", "--theta", "90", "--alpha", "0:30:15", "--format", "ndjson")
    assert [json.loads(line)["alpha_deg"] for line in res.stdout.splitlines()] == [0.0, 15.0, 30.0]


def test_mu_gives_slips(run):
    res = run("orbit", "--theta", "60", "--alpha", "10", "--mu", "1", "--format", "csv")
    (row,) = rows(res.stdout)
    assert row["status"] == "slips" and row["mu_available"] == "1.0"


@pytest.mark.parametrize("args, words", [
    (["--theta", "200", "--alpha", "10"], "theta (polar angle) must be 0..180 deg"),
    (["--theta", "-1", "--alpha", "10"], "theta (polar angle) must be 0..180 deg"),
    (["--theta", "60", "--alpha", "10", "-a", "0"], "a (body radius) must be 1e-09..1e+09 m"),
    (["--theta", "60", "--alpha", "10", "-a", "-0.3"], "a (body radius) must be 1e-09..1e+09 m"),
    (["--theta", "60", "--alpha", "10", "-r", "0.3"], "must be > a = 0.3 m"),
    (["--theta", "60", "--alpha", "10", "-k", "-0.5"], "k (inertia factor) must be 0..1000"),
    (["--theta", "60", "--alpha", "10", "-g", "0"], "g (gravity) must be 1e-09"),
    (["--theta", "nan", "--alpha", "10"], "must be a finite number"),
    (["--theta", "60", "--alpha", "inf"], "must be a finite number"),
    (["--theta", "60", "--alpha", "10", "-a", "nan"], "a (body radius) must be a finite number"),
    (["--theta", "sixty", "--alpha", "10"], "must be a number"),
    (["--theta", "10:5:1", "--alpha", "10"], "stop must be >= start"),
    (["--theta", "1:2:0", "--alpha", "10"], "step > 0"),
    (["--theta", "1:2", "--alpha", "10"], "start:stop:step"),
    (["--theta", "60", "--alpha", "10", "--format", "xml"], "'xml' is not one of"),
    (["--input", "/no/such/file.csv"], "No such file"),
    (["--theta", "60"], "exactly one of alpha"),
    (["--alpha", "10"], "Missing option '--theta'"),
    (["--theta", "60", "--alpha", "10", "--body", "bicycle"], "'bicycle' is not one of"),
])
def test_bad_options_exit_2_with_one_line(run, args, words):
    res = run("orbit", *args)
    assert res.exit_code == 2
    assert res.stdout == ""
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("deathsphere: error: ")
    assert words in lines[0]
    assert "Traceback" not in res.stderr


def test_input_csv_bad_rows_are_kept_in_order(run):
    data = "theta,alpha,a\n60,10,\n90,abc,0.3\n200,10,\n45,10,-1\n75,15,0.3\n"
    res = run("orbit", "--input", "-", input=data)
    assert res.exit_code == 1
    out = rows(res.stdout)
    assert [r["input_row"] for r in out] == ["1", "2", "3", "4", "5"]
    assert [r["status"] for r in out] == ["ok", "invalid", "invalid", "invalid", "ok"]
    assert "alpha" in out[1]["reason"] and "theta" in out[2]["reason"] and "a (body radius)" in out[3]["reason"]
    assert "3 input row(s) invalid" in res.stderr


def test_input_defaults_come_from_options(run):
    res = run("orbit", "--input", "-", "--alpha", "10", "-a", "0.2", input="theta\n60\n90\n")
    out = rows(res.stdout)
    assert res.exit_code == 0 and [r["a_m"] for r in out] == ["0.2", "0.2"]
    assert [r["alpha_deg"] for r in out] == ["10.0", "10.0"]


def test_input_accepts_output_column_names(run):
    first = run("orbit", "--theta", "60", "--alpha", "10", "--format", "csv").stdout
    picked = "\n".join(",".join(r.split(",")[3:9]) for r in first.splitlines()) + "\n"
    again = run("orbit", "--input", "-", input=picked).stdout
    assert rows(again)[0]["v_cm_m_s"] == rows(first)[0]["v_cm_m_s"]


@pytest.mark.parametrize("data, words", [
    ("", "is empty"),
    ("\n\n", "is empty"),
    ("theta,alfa\n60,10\n", "unknown column 'alfa'"),
    ("theta,theta\n60,10\n", "more than once"),
])
def test_unreadable_input_exits_2(run, data, words):
    res = run("orbit", "--input", "-", input=data)
    assert res.exit_code == 2 and words in res.stderr and len(res.stderr.strip().splitlines()) == 1


def test_header_only_input_gives_header_only(run):
    res = run("orbit", "--input", "-", "--format", "csv", input="theta,alpha\n")
    assert res.exit_code == 0 and res.stdout.strip() == ",".join(COLUMNS)


def test_version_and_help(run):
    assert __version__ in run("--version").stdout
    text = run("orbit", "--help").stdout
    assert "deathsphere orbit --theta 60 --alpha 10" in text
    assert "deathsphere table1" in run("--help").stdout


def test_singular_inputs_produce_statuses_not_warnings(run):
    res = run("orbit", "--theta", "0", "--theta", "90", "--theta", "180", "--alpha", "-90:90:45", "--format", "csv")
    assert res.exit_code == 0 and "Warning" not in res.stderr
    for r in rows(res.stdout):
        if r["status"] == "ok":
            assert all(r[c] != "" for c in ("omega_rad_s", "v_cm_m_s", "mu_required"))
        else:
            assert r["reason"]


def test_python_m_and_a_real_pipe():
    proc = subprocess.run(
        f"{sys.executable} -m deathsphere orbit --theta 30:90:15 --alpha 10 | cut -d, -f4,10,15",
        shell=True, capture_output=True, text=True, check=True)
    lines = proc.stdout.splitlines()
    assert lines[0] == "theta_deg,status,v_cm_m_s" and len(lines) == 6
    assert proc.stderr == ""


def test_table1_command(run):
    res = run("table1", "--format", "csv")
    out = rows(res.stdout)
    assert len(out) == 10 and res.exit_code == 0
    assert sum(r["mu_agrees"] == "False" for r in out) == 3
    shown = run("table1", "--format", "table", env={"COLUMNS": "100"}).stdout
    assert "erratum T1-g" in shown and "erratum T1-mu" in shown and "135" in shown
