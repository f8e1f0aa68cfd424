"""The show on a profile's surface of revolution (docs/show.md sec. 12): a
32-foot drum sampled as a profile rides as the drum act does; a bowl's
banked transition (examples/bowl_of_death.toml) against its analytic
meridian: the lanes against the tangent cone's, the pairs' least clearance
and a fall's landing against brute forces over sampled times; the plan's
refusals; the 3-D view."""

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from brute_segments import wall_lanes_least_clearance

import deathsphere
from deathsphere.constants import STANDARD_GRAVITY as G
from deathsphere.errors import ParameterError
from deathsphere.physics.ground import Profile

FT = 0.3048
ROOT = Path(__file__).resolve().parents[2]
WALL = ROOT / "examples" / "wall_of_death.toml"
BOWL = ROOT / "examples" / "bowl_of_death.toml"
DOME = ROOT / "tests" / "data" / "ellipsoid_dome.csv"
#: examples/bowl.csv: the floor's edge at RHO0 from the axis, a quarter circle of radius RF up to a vertical
#: wall at RHO0 + RF, the wall's top at TOP (the meridian in closed form, for the brute forces)
RHO0, RF, TOP = 3.0, 2.0, 3.5


def _bowl(height):
    """The bowl's contact (rho, z) and wall angle beta [rad] at ``height``, in closed form."""
    h = np.asarray(height, dtype=float)
    u = np.where(h < RF, np.arccos(np.clip(1.0 - h / RF, -1.0, 1.0)), 0.5 * math.pi)
    return RHO0 + RF * np.sin(u), h, u


def _drum_as_a_profile(tmp_path, points: int = 49) -> Path:
    """examples/wall_of_death.toml with its drum (32 ft across, 12 ft high)
    given as a profile file beside the plan, ``points`` samples up the wall."""
    z = np.linspace(0.0, 12 * FT, points)
    rows = "".join(f"{16 * FT!r},{float(x)!r}\n" for x in z)
    (tmp_path / "drum.csv").write_text("rho_m,z_m\n" + rows, encoding="utf-8")
    text = WALL.read_text(encoding="utf-8")
    text = text.replace('surface = "cylinder"', 'surface = "profile"\nprofile = "drum.csv"')
    text = text.replace('diameter = "32ft"\n', "").replace('wall_height = "12ft"\n', "")
    plan = tmp_path / "plan.toml"
    plan.write_text(text, encoding="utf-8")
    return plan


def _same_table(a, b, rtol):
    assert list(a.columns) == list(b.columns) and len(a) == len(b)
    for key in a.columns:
        x, y = np.asarray(a[key]), np.asarray(b[key])
        if x.dtype.kind == "f":
            assert np.allclose(x, y, rtol=rtol, atol=rtol, equal_nan=True), key
        else:
            assert list(x) == list(y), key


def test_a_drum_sampled_as_a_profile_rides_the_wall_of_death_act(tmp_path):
    """The profile's path is read from the plan's directory (the test runs
    elsewhere); a straight meridian is a cubic spline's exactly, so the
    riders' and pairs' tables agree with the drum's to round-off (measured:
    1e-14 relative), far inside the 1e-9 asked here."""
    drum, profile = deathsphere.show(str(WALL)), deathsphere.show(str(_drum_as_a_profile(tmp_path)))
    assert isinstance(profile.plan.globe.ground, Profile)
    _same_table(drum.riders, profile.riders, 1e-9)
    _same_table(drum.pairs, profile.pairs, 1e-9)
    # a fall and the Monte Carlo land on the profile's wall or floor as on the drum's
    _same_table(drum.fall("Cal", 1.0, 0.5), profile.fall("Cal", 1.0, 0.5), 1e-9)
    _same_table(drum.falls(30, seed=2)[0], profile.falls(30, seed=2)[0], 1e-9)


def test_the_bowls_lanes_ride_as_on_the_cone_tangent_at_each_contact():
    """A steady orbit sees the ground only at its contact (its point, wall
    angle and the parallel's curvature sin(beta)/rho, docs/machine.md eqs.
    MS1-MS6): each lane of the bowl is the lane of the cone touching the
    bowl along that parallel (the floor's radius rho - h cot beta), from the
    analytic meridian; the head's clearance is the bowl's own and differs."""
    act = deathsphere.show(str(BOWL))
    plan = tomllib.loads(BOWL.read_text(encoding="utf-8"))
    for k, rider in enumerate(plan["rider"]):
        rho, h, beta = (float(x) for x in _bowl(act.lanes[k].height))
        assert act.lanes[k].points["contact"] == pytest.approx((rho, h), abs=2e-4)
        same_lap = rider.pop("same_lap_as", None)
        if same_lap:
            rider["period"] = f"{act.lanes[0].period_s!r}s"
        cone = {"surface": "cylinder", "diameter": f"{2 * rho}m"} if beta == 0.5 * math.pi else {
            "surface": "cone", "diameter": f"{2 * (rho - h / math.tan(beta))}m", "wall_angle": math.degrees(beta)}
        tangent = deathsphere.show({"arena": {**cone, "mu": 0.8, "max_g": 6}, "rider": [rider]})
        for key in ("alpha_deg", "v_cm_m_s", "period_s", "load_g", "mu_required", "speed_low_m_s", "speed_high_m_s"):
            assert act.riders[key][k] == pytest.approx(tangent.riders[key][0], rel=2e-4, abs=2e-5), key
        assert act.riders["status"][k] == tangent.riders["status"][0] == "ok"


def _brute_least(act, a, b, t):
    """The least clearance of lanes a and b over the times t from their
    height and tilt alone, on the bowl's analytic meridian: P its contact,
    n = (-sin beta, cos beta), Q = P + t n, H = Q + (head - t)(-cos alpha,
    sin alpha) in the meridian plane at phi = phase + rate t; 401 points
    along a's axis, each one's distance to b's axis by projection."""
    return wall_lanes_least_clearance(a, b, t, _bowl)


def test_the_bowls_pairs_least_clearance_against_a_brute_force_over_sampled_times():
    act = deathsphere.show(str(BOWL))
    rows = {(act.pairs["rider_a"][i], act.pairs["rider_b"][i]): i for i in range(len(act.pairs))}
    lanes = {lane.name: lane for lane in act.lanes}
    for (a, b), basis in ((("Ana", "Ben"), "act"), (("Ana", "Cal"), "geometric"), (("Ben", "Cal"), "geometric")):
        i, la, lb = rows[(a, b)], lanes[a], lanes[b]
        assert act.pairs["basis"][i] == basis
        # over one period of their angle apart every relative azimuth is swept (one lap: the pair is rigid)
        span = la.period_s if basis == "act" else 2 * math.pi / abs(la.rate - lb.rate)
        brute = _brute_least(act, la, lb, np.linspace(0.0, span, 20001))
        assert act.pairs["min_clearance_m"][i] == pytest.approx(brute, abs=2e-3), (a, b)
        assert _brute_least(act, la, lb, np.array([act.pairs["t_s"][i]])) == pytest.approx(brute, abs=2e-3)
    # Ben on the transition and Cal on the wall above pass 24 cm apart: clear of the crew's 15 cm
    assert act.pairs["verdict"][rows[("Ben", "Cal")]] == "clear"
    assert 0.15 < act.pairs["min_clearance_m"][rows[("Ben", "Cal")]] < 0.3


def _outside_the_bowl(x):
    """Where the points x (3, n) are outside the bowl, from its closed form:
    below the floor, beyond the quarter circle's arc, or beyond the wall."""
    rho, z = np.hypot(x[0], x[1]), x[2]
    arc = (rho > RHO0) & (z < RF) & (np.hypot(rho - RHO0, z - RF) > RF)
    return (z < 0) | arc | ((z >= RF) & (rho > RHO0 + RF))


@pytest.mark.parametrize("name,t,fraction", [("Ana", 0.5, 0.2), ("Ben", 1.0, 0.3), ("Cal", 0.7, 0.4)])
def test_a_fall_in_the_bowl_lands_where_its_closed_form_says(name, t, fraction):
    act = deathsphere.show(str(BOWL))
    row = act.fall(name, t, fraction)[0]
    assert row["outcome"] == "falls"
    lane = next(lane for lane in act.lanes if lane.name == name)
    kin = lane.kinematics(np.array([t]))
    x0, v0 = kin["com"][:, 0], fraction * kin["v_com"][:, 0]
    s = np.linspace(0.0, 2.0, 200001)
    path = x0[:, None] + v0[:, None] * s - 0.5 * G * s ** 2 * np.array([[0.0], [0.0], [1.0]])
    first = s[int(np.argmax(_outside_the_bowl(path)))]
    assert row["fall_time_s"] == pytest.approx(first, abs=2e-4)
    landing = x0 + v0 * first - 0.5 * G * first ** 2 * np.array([0, 0, 1.0])
    assert row["height_land_m"] == pytest.approx(landing[2], abs=2e-3)


def _refusal(plan) -> str:
    with pytest.raises(ParameterError) as exc:
        deathsphere.show(plan)
    return str(exc.value)


def _plan(*riders, **arena):
    return {"arena": {"surface": "profile", "profile": str(ROOT / "examples" / "bowl.csv"), "mu": 0.8, "max_g": 6,
                      **arena}, "rider": list(riders) or [_rider("Ana", "1m")]}


def _rider(name, height, **more):
    return {"name": name, "machine": "stunt125", "width": "0.7m", "lane": "horizontal", "height": height,
            "speed": "30km/h", **more}


@pytest.mark.parametrize("plan, start", [
    (_plan(profile=None), "arena: profile: must be a profile CSV file's path"),
    ({"arena": {"surface": "profile"}, "rider": [_rider("Ana", "1m")]}, "arena: profile: a profile arena needs"),
    (_plan(profile="no-such-file.csv"), "arena: profile: cannot read the profile file"),
    (_plan(profile=3), "arena: profile: must be a profile CSV file's path"),
    (_plan(diameter="10m"), "arena: diameter: diameter is not a shape of the profile"),
    (_plan(surface="cylinder", diameter="32ft"), "arena: profile: profile is not a shape of the cylinder"),
    (_plan(_rider("Ana", "3.6m")), "rider 'Ana': height: height (contact height) is above the wall's top"),
    (_plan(_rider("Ana", "0m"), profile=str(DOME)), "rider 'Ana': height: the profile's meridian meets its axis"),
    (_plan(_rider("Ana", "6m"), profile=str(DOME)), "rider 'Ana': height: the profile's meridian meets its axis"),
    (_plan({"name": "Ben", "lane": "vertical", "azimuth": 0, "v_top": "6.5m/s", "width": "0.6m"}, profile=str(DOME)),
     "rider 'Ben': lane: a vertical loop is the globe's: not on a profile (a show's loops ride the globe's"),
    (_plan({**_rider("Ana", "1m"), "theta": 80}), "rider 'Ana': theta: a lane on a profile is given by its height"),
])
def test_a_profile_plans_refusals_name_the_key(plan, start):
    line = _refusal(plan)
    assert line.startswith(start) and "\n" not in line


def test_a_dict_plan_takes_a_profile_record_and_a_path_from_the_working_directory(monkeypatch):
    record = deathsphere.show(str(BOWL)).plan.globe.ground
    plan = tomllib.loads(BOWL.read_text(encoding="utf-8"))
    by_record = deathsphere.show({**plan, "arena": {**plan["arena"], "profile": record}})
    assert by_record.plan.globe.ground is record
    monkeypatch.chdir(ROOT / "examples")                # a dict has no directory: its path is the working one's
    by_path = deathsphere.show(plan)
    _same_table(by_record.pairs, by_path.pairs, 0.0)


def test_the_scene_draws_the_bowl_from_its_meridian():
    from deathsphere.viewer.show_scene import act_scene

    scene = act_scene(deathsphere.show(str(BOWL)))
    rho, z = np.array(scene.ground["rho"]), np.array(scene.ground["z"])
    assert scene.ground["kind"] == "revolution" and (rho[0], z[0]) == (0.0, 0.0)      # the floor from the axis
    assert rho.max() == pytest.approx(RHO0 + RF) and z.max() == pytest.approx(TOP)
    # every drawn point of the wall is on the closed-form meridian, spread along it (the flat start too)
    want_rho = _bowl(z[1:])[0]
    assert rho[1:] == pytest.approx(want_rho, abs=2e-4)
    steps = np.hypot(np.diff(rho[1:]), np.diff(z[1:]))
    assert steps.max() < 1.01 * steps.min()


def test_the_command_line_rides_the_bowl_and_refuses_a_missing_profile_in_one_line(run, tmp_path):
    res = run("show", str(BOWL), "--table", "pairs", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    rows = [line.split(",") for line in res.stdout.splitlines()]
    assert rows[3][:2] == ["Ben", "Cal"] and float(rows[3][2]) == pytest.approx(0.2397, abs=1e-3)
    plan = tmp_path / "plan.toml"
    plan.write_text(BOWL.read_text(encoding="utf-8"), encoding="utf-8")      # bowl.csv is not beside it
    res = run("show", str(plan))
    assert res.exit_code == 2
    (line,) = res.stderr.strip().splitlines()
    assert "arena: profile: cannot read the profile file" in line and "bowl.csv" in line
