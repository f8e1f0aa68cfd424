import csv
import io
import json

import pytest

from deathsphere.model import COLUMNS


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_orbit_csv_has_the_stability_columns_filled(run):
    (row,) = rows(run("orbit", "--theta", "60", "--alpha", "10", "--format", "csv").stdout)
    names = list(row)
    i = names.index("stability")
    assert names[i:i + 5] == ["stability", "stability_method", "growth_rate_1_s", "freq_slow_rad_s", "freq_fast_rad_s"]
    assert row["stability"] == "stable" and row["stability_method"] == "exact-linearisation"
    # docs/stability.md sec. 6.8: Table 1 (60, 10) nutates at 3.61 and 44.76 rad/s
    assert float(row["freq_slow_rad_s"]) == pytest.approx(3.61, abs=0.01)
    assert float(row["freq_fast_rad_s"]) == pytest.approx(44.76, abs=0.01)


def test_steep_equatorial_orbit_is_unstable_and_no_stability_leaves_blanks(run):
    out = rows(run("orbit", "--theta", "90", "--alpha", "45", "--alpha", "80", "--format", "csv").stdout)
    assert [r["stability"] for r in out] == ["stable", "unstable"]
    assert float(out[1]["growth_rate_1_s"]) > 1.0
    out = rows(run("orbit", "--theta", "90", "--alpha", "80", "--no-stability", "--format", "csv").stdout)
    assert out[0]["stability"] == "" and out[0]["growth_rate_1_s"] == ""


def test_no_orbit_rows_have_no_stability(run):
    (row,) = rows(run("orbit", "--theta", "60", "--alpha", "-10", "--format", "csv").stdout)
    assert row["status"] == "no_orbit" and row["stability"] == ""


def test_sweep_has_the_columns(run):
    out = json.loads(run("sweep", "--theta", "90", "--alpha", "40:80:20", "--format", "json").stdout)
    assert list(out[0]) == list(COLUMNS) and [r["stability"] for r in out] == ["stable", "stable", "unstable"]


def test_stability_command_equator(run):
    out = json.loads(run("stability", "--theta", "90", "--alpha", "45", "--format", "json").stdout)
    exact = {r["quantity"]: r["exact"] for r in out if r["source"] == "exact"}
    assert exact["verdict"] == "stable" and exact["slow nutation frequency"] == pytest.approx(2.8088, abs=1e-3)
    eq = [r for r in out if r["source"] == "paper: equator"]
    assert all(r["applies"] for r in eq)
    slow = next(r for r in eq if r["quantity"] == "slow nutation frequency")
    assert slow["deviation"] == pytest.approx((slow["paper"] - slow["exact"]) / slow["exact"])


def test_stability_command_table(run):
    text = run("stability", "--theta", "90", "--alpha", "80", "--format", "table", env={"COLUMNS": "110"}).stdout
    assert "unstable" in text and "equator" in text and "differs" in text


@pytest.mark.parametrize("args, words", [
    (["--theta", "90"], "exactly one of alpha"), (["--theta", "190", "--alpha", "10"], "theta (polar angle) must be 0..180 deg"),
    (["--theta", "90", "--alpha", "10", "--body", "sphere"], "a sphere needs exactly one of omega3"),
    (["--theta", "90", "--alpha", "10", "--alpha", "20", "--speed", "7"], "--speed: give one of --alpha"),
])
def test_stability_usage_errors(run, args, words):
    res = run("stability", *args)
    assert res.exit_code == 2 and words in res.stderr


def test_vertical_orbits_get_their_stability(run):
    (row,) = rows(run("vertical", "--theta", "90", "--v-top", "6", "--format", "csv").stdout)
    assert row["stability"] == "stable" and row["stability_method"] == "floquet"


def test_stability_takes_the_orbit_options_and_reports_each_orbit(run):
    """--speed (a rider's units too) gives every tilt with that speed, each
    reported; a sphere gets its exact rows only."""
    out = rows(run("stability", "--theta", "90", "--speed", "25.2km/h", "--format", "csv").stdout)
    orbits = {(r["input_row"], r["branch"]) for r in out}
    assert len(orbits) >= 1 and all(r["body"] == "wheel" for r in out)
    exact_v = [r for r in out if r["quantity"] == "orbit status"]
    assert len(exact_v) == len(orbits)
    sphere = rows(run("stability", "--body", "sphere", "--theta", "60", "--omega3", "80", "--format", "csv").stdout)
    assert {r["source"] for r in sphere} == {"exact"} and {r["branch"] for r in sphere} == {"0", "1"}
    # the slow root does not keep contact (nothing to linearise about); the fast one is stable
    verdicts = [r for r in sphere if r["quantity"] == "verdict"]
    assert [r["exact"] for r in verdicts] == ["", "stable"] and "no_contact" in verdicts[0]["note"]


def test_stability_of_a_grid_is_the_stability_of_each_orbit_alone(run):
    both = rows(run("stability", "--theta", "90", "--alpha", "45", "--alpha", "80", "--format", "csv").stdout)
    for i, alpha in enumerate(("45", "80"), 1):
        alone = rows(run("stability", "--theta", "90", "--alpha", alpha, "--format", "csv").stdout)
        mine = [r for r in both if r["input_row"] == str(i)]
        assert [{k: v for k, v in r.items() if k != "input_row"} for r in mine] == \
            [{k: v for k, v in r.items() if k != "input_row"} for r in alone]
