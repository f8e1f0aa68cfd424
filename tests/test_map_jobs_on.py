"""``map --surface ... --stability --jobs N`` (docs/limits.md sec. 8): the
stability boundary's batches of lanes on a pool of processes give the
output of one process byte for byte (the data, the terminal plot) and the
same figure curves, on a drum and on the bowl's profile.  The lanes are
chosen so that there are several batches (16 lanes each) and the
stability boundary crosses some of them, so that a batch out of order or
padded differently would show."""

from pathlib import Path

import numpy as np
import pytest

import deathsphere
from deathsphere.params import ParameterError

ROOT = Path(__file__).resolve().parents[1]
BOWL = str(ROOT / "examples" / "bowl.csv")
#: typed as on the command line and as API keywords (a 32-ft drum 12 ft tall; the bowl)
CLI = {
    "drum": ["--surface", "cylinder", "--diameter", "32ft", "--wall-height", "12ft", "--height", "0:3.6:0.2"],
    "bowl": ["--surface", "profile", "--profile", BOWL, "--height", "0:1.7:0.1"],
}
API = {
    "drum": dict(surface="cylinder", diameter="32ft", wall_height="12ft", height="0:3.6:0.2"),
    "bowl": dict(surface="profile", profile=BOWL, height="0:1.7:0.1"),
}


@pytest.mark.parametrize("case", sorted(CLI))
def test_the_data_on_two_processes_is_one_process_byte_for_byte(case, run):
    one = run("map", *CLI[case], "--stability", "--format", "csv")
    two = run("map", *CLI[case], "--stability", "--format", "csv", "--jobs", "2")
    assert one.exit_code == 0 and two.exit_code == 0
    assert two.stdout == one.stdout
    stability = [line for line in one.stdout.splitlines() if line.startswith("stability,")]
    # more lanes than one batch, and crossings to get wrong
    assert len(one.stdout.splitlines()) > 1 and len(stability) > 5


def test_the_json_on_two_processes_is_one_process_byte_for_byte(run):
    one, two = (run("map", *CLI["drum"], "--stability", "--format", "json", *jobs) for jobs in ([], ["--jobs", "2"]))
    assert one.exit_code == 0 and two.stdout == one.stdout and '"stability"' in one.stdout


def test_the_terminal_plot_on_two_processes_is_one_process_byte_for_byte(run):
    env = {"COLUMNS": "80"}
    one = run("map", *CLI["bowl"], "--stability", "--format", "table", env=env)
    two = run("map", *CLI["bowl"], "--stability", "--format", "table", "--jobs", "2", env=env)
    assert one.exit_code == 0 and two.stdout == one.stdout and one.stdout


@pytest.mark.parametrize("case", sorted(API))
def test_the_figure_curves_on_two_processes_are_one_process(case):
    one = deathsphere.region_curves(stability=True, **API[case])
    two = deathsphere.region_curves(stability=True, jobs=2, **API[case])
    for name in ("x_m", "lo_deg", "hi_deg", "count"):
        np.testing.assert_array_equal(getattr(two, name), getattr(one, name))
    assert sorted(two.points) == sorted(one.points) and one.points["stability"][0].size > 0
    for name, (x, alpha) in one.points.items():
        np.testing.assert_array_equal(two.points[name][0], x)
        np.testing.assert_array_equal(two.points[name][1], alpha)
    for mine, theirs in zip(two.stable, one.stable):
        np.testing.assert_array_equal(mine, theirs)


def test_progress_counts_every_lane_once_in_order():
    told = []
    table = deathsphere.region(stability=True, jobs=2, progress=lambda done, total: told.append((done, total)),
                               **API["drum"])
    lanes = 19                                     # 0:3.6:0.2 m
    assert len(table) > 0 and told[-1] == (lanes, lanes)
    assert [done for done, _ in told] == [16, 19]  # one tick per batch of 16 lanes
    assert {total for _, total in told} == {lanes}


def test_the_globes_figure_takes_no_processes():
    # on the sphere the curves are drawn on grids of their own: jobs there would do nothing
    with pytest.raises(ParameterError) as caught:
        deathsphere.region_curves(jobs=2)
    assert caught.value.param == "jobs"


def test_jobs_and_a_scheduler_together_are_refused_off_the_globe():
    with pytest.raises(ParameterError, match="not both"):
        deathsphere.region(stability=True, jobs=2, scheduler="tcp://127.0.0.1:1", **API["drum"])


def test_a_terminal_sees_the_lanes_counted_on_stderr(monkeypatch, run):
    import io

    from rich.console import Console

    import deathsphere.cli.base as base

    screen = io.StringIO()
    monkeypatch.setattr(base, "_isatty", lambda stream: True)
    monkeypatch.setattr(base, "PROGRESS_DELAY_S", 0.0)
    monkeypatch.setattr(base, "stderr_console", lambda: Console(file=screen, force_terminal=True, width=80))
    res = run("map", *CLI["drum"], "--stability", "--format", "csv", "--jobs", "2")
    assert res.exit_code == 0 and "stability," in res.stdout
    assert "boundaries" in screen.getvalue() and "19/19" in screen.getvalue()   # 0:3.6:0.2 m: 19 lanes
