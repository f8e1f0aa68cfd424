"""ride --vertical inside a profile closed over the top (docs/machine.md
eqs. M25-M30): the globe's loop columns in their order, then the arena's
and the loop's own; theta 90 only; a ground that does not close over the
rider, another lane's option or another theta refused in one line naming
the option, exit status 2."""

from pathlib import Path

import numpy as np
import pytest

import deathsphere
from deathsphere.api.ride_loops import ARENA_COLUMNS
from deathsphere.api.rides import LOOP_COLUMNS

ELLIPSOID = Path(__file__).resolve().parents[1] / "data" / "ellipsoid_dome.csv"
LOOP = ("ride", "--vertical", "--surface", "profile", "--profile", str(ELLIPSOID))


def test_a_loop_inside_an_ellipsoid_has_the_globes_columns_then_the_arenas(run):
    res = run(*LOOP, "--theta", "90", "--v-top", "10:40:10km/h", "--max-g", "8", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    header, *rows = res.stdout.strip().splitlines()
    assert header.split(",") == [*LOOP_COLUMNS, *ARENA_COLUMNS]
    assert header.startswith(",".join(LOOP_COLUMNS) + ",surface,height_m,")     # appended, never reordered
    cells = [dict(zip(header.split(","), row.split(","))) for row in rows]
    assert [c["status"] for c in cells] == ["no_contact", "no_contact", "ok", "over_g"]
    assert all(c["r_m"] == "" and c["surface"] == "profile" and c["height_m"] == "6.0" for c in cells)
    assert [c["stability"] for c in cells] == ["", "", "unknown", "unknown"]
    assert cells[2]["stability_method"] == "not-analysed-loop" and cells[2]["period_s"] != ""
    assert cells[0]["period_s"] == "" and cells[0]["mu_required"] == ""       # no lap without contact


def test_the_terminal_view_cites_the_loops_own_equations(run):
    res = run(*LOOP, "--theta", "90", "--v-top", "30km/h", "--format", "table")
    assert res.exit_code == 0, res.stderr
    assert "eq. M29" in res.stdout and "lap time" in res.stdout and "eq. M22" not in res.stdout


def test_the_api_gives_the_same_table():
    table = deathsphere.ride(90, vertical=True, v_top=[7.0, 9.0], surface="profile", profile=str(ELLIPSOID))
    assert list(table.columns) == [*LOOP_COLUMNS, *ARENA_COLUMNS]
    assert table["status"].tolist() == ["ok", "ok"]
    assert np.all(np.diff(np.asarray(table["period_s"], dtype=float)) < 0)      # faster, a shorter lap


@pytest.mark.parametrize("args, named, says", [
    (("--theta", "80", "--v-top", "8"), "--theta", "theta must be 90"),
    (("--theta", "90", "--v-top", "8", "--height", "1"), "", "--vertical takes --theta 90"),
    (("--theta", "90"), "", "--vertical takes --theta 90"),
])
def test_a_loop_off_the_meridian_plane_or_with_another_lane_is_refused(run, args, named, says):
    res = run(*LOOP, *args)
    assert res.exit_code == 2 and named in res.stderr and says in res.stderr
    assert len(res.stderr.strip().splitlines()) == 1 and "Traceback" not in res.stderr


@pytest.mark.parametrize("shape, why", [
    (("--surface", "cylinder", "--diameter", "32ft", "--wall-height", "12ft"), "does not close"),
    (("--surface", "cone", "--diameter", "6", "--wall-angle", "100"), "closed below"),
])
def test_a_ground_that_does_not_close_over_the_rider_is_refused(run, shape, why):
    res = run("ride", "--vertical", *shape, "--theta", "90", "--v-top", "8")
    assert res.exit_code == 2 and "--vertical" in res.stderr and why in res.stderr
    assert len(res.stderr.strip().splitlines()) == 1 and "Traceback" not in res.stderr


def test_a_top_speed_without_vertical_is_refused_naming_it(run):
    res = run("ride", "--surface", "profile", "--profile", str(ELLIPSOID), "--height", "1", "--v-top", "8")
    assert res.exit_code == 2 and "--vertical" in res.stderr and "Traceback" not in res.stderr
    with pytest.raises(deathsphere.ParameterError, match="v_top"):
        deathsphere.ride(height=1.0, v_top=8.0, surface="profile", profile=str(ELLIPSOID))


def test_loops_computed_a_few_hundred_at_a_time_are_those_computed_at_once(monkeypatch):
    from deathsphere.api import ride_loops

    v_top = np.linspace(5.0, 15.0, 7)
    whole = deathsphere.ride(90, vertical=True, v_top=v_top, surface="profile", profile=str(ELLIPSOID), mu=0.5)
    monkeypatch.setattr(ride_loops, "LOOPS_PER_CALL", 3)
    pieces = deathsphere.ride(90, vertical=True, v_top=v_top, surface="profile", profile=str(ELLIPSOID), mu=0.5)
    assert len(set(whole["status"].tolist())) > 1                        # rows of more than one kind
    for name in whole.columns:
        a, b = np.asarray(whole[name]), np.asarray(pieces[name])
        same = np.array_equal(a, b, equal_nan=True) if a.dtype.kind == "f" else a.tolist() == b.tolist()
        assert same, name


def test_too_many_loops_are_refused_in_one_line(run):
    res = run(*LOOP, "--theta", "90", "--v-top", "0:200:0.001")
    assert res.exit_code == 2 and "fewer top speeds" in res.stderr and "Traceback" not in res.stderr
