"""vertical off the globe: a loop needs a surface that closes over the top,
so a drum, a cone and flat ground are refused in one line naming the
option and saying why, and so is a profile that closes (not solved there)."""

import numpy as np
import pytest

import deathsphere
from deathsphere.api.vertical_arena import closes_over_top
from deathsphere.physics.ground import Cone, Cylinder, Plane, Profile, Sphere


@pytest.mark.parametrize("shape, why", [
    (("--surface", "cylinder", "--diameter", "32ft"), "does not close"),
    (("--surface", "cone", "--diameter", "6", "--wall-angle", "80"), "does not close"),
    (("--surface", "plane"), "does not close"),
    (("--surface", "cone", "--diameter", "6", "--wall-angle", "100"), "sphere only"),
])
def test_off_the_globe_a_loop_is_refused_in_one_line(run, shape, why):
    res = run("vertical", *shape, "--theta", "90", "--v-top", "6")
    assert res.exit_code == 2 and "--surface" in res.stderr and why in res.stderr
    assert len(res.stderr.strip().splitlines()) == 1 and "Traceback" not in res.stderr


def test_a_dome_profile_closes_over_the_top_and_is_refused(run, tmp_path):
    theta = np.linspace(np.pi, 0.0, 40)
    path = tmp_path / "dome.csv"
    path.write_text("rho_m,z_m\n" + "".join(f"{abs(3 * np.sin(t)):.12f},{3 * np.cos(t):.12f}\n" for t in theta))
    res = run("vertical", "--surface", "profile", "--profile", str(path), "--theta", "90", "--v-top", "6")
    assert res.exit_code == 2 and "--surface" in res.stderr and "sphere only" in res.stderr
    with pytest.raises(deathsphere.ParameterError, match="sphere only"):
        deathsphere.vertical_sweep(90, 6, surface="profile", profile=str(path))


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
