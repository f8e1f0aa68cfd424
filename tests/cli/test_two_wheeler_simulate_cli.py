"""``deathsphere simulate --machine benchmark-bicycle --steer free``: the
time series piped, the summary on a terminal, a table file, the 3-D view
and the figure, and one-line refusals with exit status 2."""

import csv
import io

import pytest

from deathsphere.api.two_wheelers import SIMULATE_COLUMNS

#: The benchmark bicycle at the benchmark's gravity (Table 1), at which the expected turn was set.
RUN = ("simulate", "--machine", "benchmark-bicycle", "--steer", "free", "--height", "1", "--speed", "5",
       "--diameter", "16ft", "--periods", "0.2", "--points-per-period", "20", "--rtol", "1e-6", "-g", "9.81")


def test_piped_the_series_goes_to_stdout_the_verdict_to_stderr(run):
    res = run(*RUN, "--perturb", "0.2", "--steer-gains", "10,10", "--format", "csv")
    assert res.exit_code == 0, res.output
    rows = list(csv.DictReader(io.StringIO(res.stdout)))
    assert len(rows) == 5 and list(rows[0]) == list(SIMULATE_COLUMNS)
    assert float(rows[0]["lean_surface_deg"]) == pytest.approx(-13.362 + 0.2, abs=1e-3)
    assert "completed" in res.stderr and res.stderr.count("\n") == 1


def test_summary_only_is_one_row_naming_the_control(run):
    res = run(*RUN, "--hands-free", "--summary-only", "--format", "csv")
    assert res.exit_code == 0, res.output
    rows = list(csv.DictReader(io.StringIO(res.stdout)))
    assert len(rows) == 1 and rows[0]["control"] == "hands-free" and rows[0]["k_lean_n_m_rad"] == "0.0"


def test_a_table_file_is_written(run, tmp_path):
    out = tmp_path / "run.csv"
    res = run(*RUN, "--output", str(out))
    assert res.exit_code == 0, res.output
    assert res.stdout == "" and len(out.read_text().splitlines()) == 6


def test_the_3d_view_is_written_and_nothing_printed(run, tmp_path):
    out = tmp_path / "run.html"
    res = run(*RUN, "--output", str(out))
    assert res.exit_code == 0, res.output
    assert res.stdout == "" and f"wrote {out}" in res.stderr
    page = out.read_text(encoding="utf-8")
    assert '"format":"deathsphere-scene/1"' in page and '"n":5,' in page


def test_the_figure_is_written(run, tmp_path):
    pytest.importorskip("matplotlib")
    out = tmp_path / "run.svg"
    res = run(*RUN, "--output", str(out))
    assert res.exit_code == 0, res.output
    assert res.stdout == "" and "<svg" in out.read_text(encoding="utf-8")


@pytest.mark.parametrize("extra, words", [
    (("--alpha", "10"), "--alpha not for a two-wheeler's run"),
    (("--output", "v.html", "--loop-seconds", "2"), "--loop-seconds not for a two-wheeler's run"),
    (("--hands-free", "--steer-gains", "1,2"), "not both"),
    (("--steer-gains", "1"), "two finite numbers"),
])
def test_bad_combinations_are_refused_in_one_line(run, extra, words):
    res = run(*RUN, *extra)
    assert res.exit_code == 2 and words in res.stderr and res.stderr.count("\n") == 1, res.stderr


def test_height_without_a_two_wheeler_is_refused(run):
    res = run("simulate", "--height", "1", "--alpha", "10")
    assert res.exit_code == 2 and "--height is a two-wheeler's lane" in res.stderr


def test_a_locked_steer_is_simulated_and_says_so(run):
    res = run(*[("locked" if a == "free" else a) for a in RUN], "--perturb-lean-rate", "2", "--summary-only",
              "--format", "csv")
    assert res.exit_code == 0, res.output
    (row,) = csv.DictReader(io.StringIO(res.stdout))
    assert row["control"] == "locked" and row["steer"] == "locked" and row["perturb_lean_rate_deg_s"] == "2.0"


FLAT = ("simulate", "--machine", "benchmark-bicycle", "--flat", "--speed", "5", "--perturb", "0.5")


def test_the_benchmarks_case_runs_from_straight_running(run):
    res = run(*FLAT, "--duration", "0.5", "--points-per-period", "10", "--rtol", "1e-6", "--format", "csv")
    assert res.exit_code == 0, res.output
    rows = list(csv.DictReader(io.StringIO(res.stdout)))
    assert len(rows) == 6 and float(rows[-1]["t_s"]) == 0.5
    assert float(rows[0]["lean_surface_deg"]) == 0.5 and float(rows[0]["v_rear_m_s"]) == pytest.approx(5.0)
    assert "from upright straight running" in res.stderr and "completed" in res.stderr


@pytest.mark.parametrize("extra, words", [
    (("--height", "1"), "flat ground has no lane on a sphere"),
    (("--periods", "2"), "straight running on flat ground has no period"),
    (("--steer", "locked", "--perturb-steer-rate", "3"), "no steer rate to kick"),
    (("--frame", "lab"), "--frame not for a two-wheeler's run"),
    (("--output", "run.gif"), "drawn as a page (.html), not a loop (.gif)"),
])
def test_bad_flat_combinations_are_refused_in_one_line(run, extra, words):
    res = run(*FLAT, *extra)
    assert res.exit_code == 2 and words in res.stderr and res.stderr.count("\n") == 1, res.stderr
