"""vertical off the globe: a loop needs a surface that closes over the top,
so a drum, a cone and flat ground are refused in one line naming the
option and saying why, and so is a profile open at the top or closed over
the top only (a dome on a floor); a profile closed at both ends (an
ellipsoid) has its loop computed, theta 90 and inside only."""

from pathlib import Path

import numpy as np
import pytest

import deathsphere
from deathsphere.api.vertical_arena import closes_over_top
from deathsphere.physics.ground import Cone, Cylinder, Plane, Profile, Sphere

ELLIPSOID = Path(__file__).resolve().parents[1] / "data" / "ellipsoid_dome.csv"


@pytest.mark.parametrize("shape, why", [
    (("--surface", "cylinder", "--diameter", "32ft"), "does not close"),
    (("--surface", "cone", "--diameter", "6", "--wall-angle", "80"), "does not close"),
    (("--surface", "plane"), "does not close"),
    (("--surface", "cone", "--diameter", "6", "--wall-angle", "100"), "closed below"),   # its apex: not below
])
def test_off_the_globe_a_loop_is_refused_in_one_line(run, shape, why):
    res = run("vertical", *shape, "--theta", "90", "--v-top", "6")
    assert res.exit_code == 2 and "--surface" in res.stderr and why in res.stderr
    assert len(res.stderr.strip().splitlines()) == 1 and "Traceback" not in res.stderr


def test_a_dome_on_a_floor_closes_over_the_top_only_and_is_refused(run, tmp_path):
    theta = np.linspace(np.pi / 2, 0.0, 40)
    path = tmp_path / "dome.csv"
    path.write_text("rho_m,z_m\n" + "".join(f"{3 * np.sin(t):.12f},{3 * np.cos(t):.12f}\n" for t in theta))
    res = run("vertical", "--surface", "profile", "--profile", str(path), "--theta", "90", "--v-top", "6")
    assert res.exit_code == 2 and "--surface" in res.stderr and "closed below" in res.stderr
    assert len(res.stderr.strip().splitlines()) == 1 and "Traceback" not in res.stderr
    with pytest.raises(deathsphere.ParameterError, match="closed below"):
        deathsphere.vertical_sweep(90, 6, surface="profile", profile=str(path))


def test_an_ellipsoid_rides_its_loop_with_the_arenas_columns(run):
    res = run("vertical", "--surface", "profile", "--profile", str(ELLIPSOID), "--theta", "90", "--v-top", "8",
              "--v-top", "6", "-a", "1", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    header, *rows = res.stdout.strip().splitlines()
    assert header.endswith(",stability,stability_method,growth_rate_1_s,surface,height_m")
    assert [row.split(",")[9] for row in rows] == ["ok", "no_contact"]
    assert all(row.endswith(",profile,6.0") for row in rows)
    # the loop that keeps contact has its Floquet verdict (docs/stability.md sec. 2.1), the other none
    assert [row.split(",")[31:33] for row in rows] == [["stable", "floquet"], ["", ""]]
    view = run("vertical", "--surface", "profile", "--profile", str(ELLIPSOID), "--theta", "90", "--v-top", "8",
               "--no-stability", "--format", "table")
    assert view.exit_code == 0, view.stderr
    # the loop's own equations are cited, not the globe's
    assert "eqs. S9-S12" in view.stdout and "eq. S10" in view.stdout and "eq. 28a" not in view.stdout


@pytest.mark.parametrize("option, typed, named", [
    (("--theta", "80"), "theta must be 90", "--theta"),
    (("--theta", "90", "--side", "outside"), "inside only", "--side"),
])
def test_on_a_profile_a_loop_off_the_meridian_plane_or_outside_is_refused(run, option, typed, named):
    res = run("vertical", "--surface", "profile", "--profile", str(ELLIPSOID), *option, "--v-top", "8")
    assert res.exit_code == 2 and typed in res.stderr and named in res.stderr
    assert len(res.stderr.strip().splitlines()) == 1 and "Traceback" not in res.stderr


def test_an_input_files_rows_on_a_profile_each_give_a_row(run, tmp_path):
    path = tmp_path / "loops.csv"
    path.write_text("theta,v_top\n90,8\n80,8\n90,-1\n")
    res = run("vertical", "--surface", "profile", "--profile", str(ELLIPSOID), "--input", str(path),
              "--no-stability", "--format", "csv")
    assert res.exit_code == 1 and "2 input row(s) invalid" in res.stderr       # every row answered, two refused
    rows = res.stdout.strip().splitlines()[1:]
    assert [row.split(",")[9] for row in rows] == ["ok", "invalid", "invalid"]
    assert "theta must be 90" in rows[1] and "v_top" in rows[2]


def test_a_profiles_points_read_back_are_requests_for_their_loop(run, tmp_path):
    """Each point's speed at its phi goes back to the top by S9: the loop at 8 m/s, seven times."""
    points = run("vertical", "--surface", "profile", "--profile", str(ELLIPSOID), "--theta", "90", "--v-top", "8",
                 "--points", "7", "--format", "csv")
    path = tmp_path / "points.csv"
    path.write_text(points.stdout)
    back = run("vertical", "--surface", "profile", "--profile", str(ELLIPSOID), "--input", str(path),
               "--no-stability", "--format", "csv")
    assert back.exit_code == 0, back.stderr
    header, *rows = back.stdout.strip().splitlines()
    speeds = [float(row.split(",")[header.split(",").index("v_cm_m_s")]) for row in rows]
    np.testing.assert_allclose(speeds, 8.0, rtol=1e-12)
    rate = tmp_path / "rate.csv"
    rate.write_text("theta,phidot_top,phi\n90,2,30\n90,2,0\n")
    res = run("vertical", "--surface", "profile", "--profile", str(ELLIPSOID), "--input", str(rate),
              "--no-stability", "--format", "csv")
    assert [row.split(",")[9] for row in res.stdout.strip().splitlines()[1:]] == ["invalid", "ok"]


def test_the_machines_loop_on_a_profile_needs_theta_90(run):
    # the machine's loop inside a closed profile (docs/machine.md eqs. M25-M30) runs through the axis
    res = run("ride", "--vertical", "--surface", "profile", "--profile", str(ELLIPSOID), "--v-top", "30km/h")
    assert res.exit_code == 2 and "Traceback" not in res.stderr
    assert len(res.stderr.strip().splitlines()) == 1 and "--theta 90" in res.stderr
    ok = run("ride", "--vertical", "--surface", "profile", "--profile", str(ELLIPSOID), "--theta", "90",
             "--v-top", "30km/h", "--format", "csv")
    assert ok.exit_code == 0 and ",ok," in ok.stdout


def test_which_grounds_close_over_the_top():
    assert closes_over_top(Sphere(3.0))
    assert closes_over_top(Cone(3.0, np.radians(100.0)))          # its apex
    assert not closes_over_top(Cone(3.0, np.radians(80.0), 8.0))
    assert not closes_over_top(Cylinder(4.8768, 6.0)) and not closes_over_top(Plane())
    bowl = np.linspace(np.pi, np.radians(30.0), 30)               # open at the top
    assert not closes_over_top(Profile(3 * np.sin(bowl), 3 * np.cos(bowl)))


def test_the_globe_by_name_still_rides(run):
    res = run("vertical", "--surface", "sphere", "--theta", "90", "--v-top", "6", "--format", "csv")
    assert res.exit_code == 0, res.stderr
