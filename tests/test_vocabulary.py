"""One vocabulary: every command that takes an option takes the same one
(from the parameter registry), with the same units and suffixes; a
single-valued option given twice is refused; an option given with --input
applies to every row; help fits 80 columns."""

import csv
import io
import math

import pytest

from deathsphere.cli import cli
from deathsphere.params import PARAMS

PHYSICS = ("orbit", "sweep", "vertical", "map", "limits", "stability", "simulate")


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def options_of(command):
    return {flag for p in cli.commands[command].params for flag in p.opts + p.secondary_opts}


def test_every_physics_command_takes_the_setup_options():
    for command in PHYSICS:
        assert {"-a", "-r", "--diameter", "-k", "-g", "--mu", "--side"} <= options_of(command), command


@pytest.mark.parametrize("option, commands", [
    ("--speed", ("orbit", "sweep", "stability", "simulate")),
    ("--omega", ("orbit", "sweep", "stability", "simulate")),
    ("--omega3", ("orbit", "sweep", "stability", "simulate")),
    ("--max-g", ("orbit", "sweep", "limits", "map")),
    ("--body", ("orbit", "sweep", "limits", "stability", "simulate")),
    ("--only", ("orbit", "sweep", "vertical")),
    ("--input", ("orbit", "sweep", "vertical", "stability", "limits")),
    ("--machine", ("ride", "simulate")),
    ("--machine-file", ("ride", "simulate")),
    ("--mass", ("ride", "simulate")),
    ("--head-height", ("ride", "simulate")),
])
def test_each_option_is_on_every_command_where_it_makes_sense(option, commands):
    for command in commands:
        assert option in options_of(command), (command, option)


def test_an_option_reads_the_same_on_every_command():
    """Same flags, metavar and help wherever a registry parameter appears
    (theta may say what it means for a vertical orbit or the limits)."""
    seen = {}
    for command in PHYSICS:
        for p in cli.commands[command].params:
            if p.name in PARAMS and p.name != "theta":
                text = p.help.replace(" Repeat it or give start:stop:step.", "")
                seen.setdefault(p.name, set()).add((tuple(p.opts), p.metavar, text))
    assert {name: len(forms) for name, forms in seen.items() if len(forms) > 1} == {}


@pytest.mark.parametrize("args", [
    ["orbit", "--theta", "60", "--alpha", "10", "--body", "wheel", "--body", "sphere"],
    ["orbit", "--theta", "60", "--alpha", "10", "--format", "csv", "--format", "json"],
    ["orbit", "--theta", "60", "--alpha", "10", "--mu", "1", "--mu", "2"],
    ["vertical", "--theta", "90", "--v-top", "6", "-g", "9.8", "-g", "1.6"],
    ["simulate", "--theta", "60", "--alpha", "10", "--perturb", "1", "--perturb", "2"],
    ["limits", "--mu", "1", "--max-g", "5", "--max-g", "4"],
])
def test_a_single_valued_option_given_twice_is_a_usage_error(run, args):
    res = run(*args)
    assert res.exit_code == 2 and res.stderr.count("\n") == 1 and "given 2 times" in res.stderr
    assert res.stdout == ""


def test_unit_suffixes_are_the_same_numbers_as_si(run):
    """A rider's units: km/h, ft, a diameter, rpm and radians give the rows
    of the same request in SI (CSV stays SI)."""
    si = rows(run("orbit", "--theta", "90", "--speed", "11.11111111111111", "-r", "2.4384",
                  "--format", "csv").stdout)
    rider = rows(run("orbit", "--theta", "90", "--speed", "40km/h", "--diameter", "16ft", "--format", "csv").stdout)
    assert [r["alpha_deg"] for r in si] == [r["alpha_deg"] for r in rider] and len(rider) >= 1
    assert {r["r_m"] for r in rider} == {"2.4384"} and float(rider[0]["v_contact_m_s"]) == pytest.approx(40 / 3.6, 1e-15)
    rad = rows(run("orbit", "--theta", "60", "--alpha", f"{math.radians(10)!r}rad", "--format", "csv").stdout)
    assert float(rad[0]["alpha_deg"]) == pytest.approx(10.0, abs=1e-12)
    spin = rows(run("orbit", "--body", "sphere", "--theta", "60", "--omega3", "600rpm", "--format", "csv").stdout)
    assert float(spin[0]["omega3_rad_s"]) == pytest.approx(20 * math.pi, 1e-15)
    ranged = rows(run("orbit", "--theta", "90", "--speed", "30:50:10km/h", "--format", "csv").stdout)
    assert sorted({float(r["v_contact_m_s"]) for r in ranged}) == pytest.approx([30 / 3.6, 40 / 3.6, 50 / 3.6])


@pytest.mark.parametrize("args, words", [
    (["orbit", "--theta", "90", "--speed", "40km"], "km is a length"),
    (["orbit", "--theta", "60", "--alpha", "10", "-r", "3", "--diameter", "6"], "not both"),
    (["orbit", "--theta", "60", "--alpha", "10", "-a", "3lb"], "--wheel-radius"),
])
def test_a_wrong_unit_is_one_line_naming_the_option(run, args, words):
    res = run(*args)
    assert res.exit_code == 2 and res.stderr.count("\n") == 1 and words in res.stderr


def test_max_g_marks_the_orbits_past_it(run):
    """--max-g limits the load the rider feels, |a - g| / g (load_g), not
    the centre's acceleration accel_g (eq. 36): at theta 60, alpha 10 the
    centre accelerates at 2.75 g and the rider feels 2.92 g, so --max-g 2.8
    marks it over_g."""
    out = rows(run("orbit", "--theta", "60", "--alpha", "5", "--alpha", "20", "--max-g", "2", "--format", "csv").stdout)
    assert [r["status"] for r in out] == ["over_g", "ok"]
    assert float(out[0]["load_g"]) > 2 >= float(out[1]["load_g"]) and {r["max_g"] for r in out} == {"2.0"}
    assert {r["max_accel_g"] for r in out} == {"2.0"}                    # the limit's first column, kept
    assert "max_g" in out[0]["reason"] and out[0]["stability"]           # the orbit exists: it is analysed
    (row,) = rows(run("orbit", "--theta", "60", "--alpha", "10", "--max-g", "2.8", "--format", "csv").stdout)
    accel, load = float(row["accel_g"]), float(row["load_g"])
    assert accel < 2.8 < load and load == pytest.approx(math.hypot(1.0, accel), rel=1e-14)
    assert row["status"] == "over_g"


def test_only_keeps_the_statuses_asked_for_on_orbit_and_vertical(run):
    out = rows(run("orbit", "--theta", "60", "--alpha", "-10:30:10", "--only", "ok", "--format", "csv").stdout)
    assert out and {r["status"] for r in out} == {"ok"}
    out = rows(run("vertical", "--theta", "90", "--v-top", "1:7:1", "--only", "ok", "--format", "csv").stdout)
    assert out and {r["status"] for r in out} == {"ok"}


def test_an_option_given_with_input_applies_to_every_row(run):
    """A result CSV fed back with a new --mu takes that mu (it is not
    silently ignored), and the other columns are read as before."""
    first = run("orbit", "--theta", "60", "--alpha", "10", "--alpha", "20", "--format", "csv").stdout
    again = rows(run("orbit", "--input", "-", "--mu", "0.5", "--format", "csv", input=first).stdout)
    assert [r["mu_available"] for r in again] == ["0.5", "0.5"]
    assert [r["status"] for r in again] == ["slips", "slips"] and [r["alpha_deg"] for r in again] == ["10.0", "20.0"]


def test_sweep_and_limits_and_stability_read_input_files(run):
    requests = "theta;alpha\n60;10\n90;45,5\n"      # a spreadsheet export: ';' and a decimal comma
    swept = rows(run("sweep", "--input", "-", "--no-stability", input=requests).stdout)
    assert [r["alpha_deg"] for r in swept] == ["10.0", "45.5"]
    limits = rows(run("limits", "--input", "-", "--mu", "1.2", "--format", "csv", input="theta\n60\n90\n").stdout)
    assert [r["input_row"] for r in limits][:1] == ["1"] and {r["status"] for r in limits} == {"ok"}
    report = rows(run("stability", "--input", "-", "--format", "csv", input="theta,alpha\n90,45\n90,80\n").stdout)
    verdicts = [r["exact"] for r in report if r["source"] == "exact" and r["quantity"] == "verdict"]
    assert verdicts == ["stable", "unstable"]


@pytest.mark.parametrize("command", sorted(cli.commands))
def test_every_help_fits_80_columns(run, command):
    text = run(command, "--help", env={"COLUMNS": "200"}).stdout
    assert text and max(len(line) for line in text.splitlines()) <= 80, command


def test_stability_kind_says_what_a_disturbance_does(run):
    """The paper's wheel conserves energy: a stable orbit is neutral (its
    spectrum imaginary), never damped; an unstable one grows; an orbit not
    analysed has no kind."""
    out = rows(run("orbit", "--theta", "90", "--alpha", "10", "--alpha", "45", "--alpha", "80", "--alpha", "120",
                   "--format", "csv").stdout)
    kinds = {(r["stability"], r["stability_kind"]) for r in out}
    assert kinds <= {("stable", "neutral"), ("unstable", "growing"), ("", "")}
    assert ("stable", "neutral") in kinds and ("unstable", "growing") in kinds and ("", "") in kinds
    for r in out:
        if r["stability_kind"] == "neutral":
            assert abs(float(r["growth_rate_1_s"])) < 1e-6
