"""A rider who loses speed on the wall of death's drum or in the well of
death's cone (docs/show.md sec. 11, "A fall on a wall"): the flight against
free fall and the drum's chord in closed form, against a brute-force root
of the cone's implicit function, the Monte Carlo against single falls, the
command line and the 3-D view."""

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

import deathsphere

G = 9.80665
FT, MPH = 0.3048, 0.44704
R = 16 * FT            # a 32-foot drum
ROOT = Path(__file__).resolve().parents[2]
#: the worked act (docs/show.md sec. 11), as shipped for users
WALL = str(ROOT / "examples" / "wall_of_death.toml")


def test_the_shipped_example_is_the_worked_act_the_goldens_pin():
    shipped = tomllib.loads(Path(WALL).read_text(encoding="utf-8"))
    assert shipped == tomllib.loads((ROOT / "tests" / "golden" / "wall.toml").read_text(encoding="utf-8"))


def _rider(name, height, phase=0, **hold):
    return {"name": name, "machine": "stunt125", "width": "0.7m", "lane": "horizontal", "height": height,
            "phase": phase, **hold}


def _plan(*riders, **arena):
    return {"arena": {"surface": "cylinder", "diameter": "32ft", "wall_height": "12ft", "mu": 0.8, "max_g": 6,
                      "min_clearance": "0.15m", **arena},
            "rider": list(riders)}


def _start(act, name, t, fraction):
    """The centre of mass and its velocity after the drop, from the lane's own kinematics."""
    lane = next(lane for lane in act.lanes if lane.name == name)
    kin = lane.kinematics(np.array([t]))
    return kin["com"][:, 0], fraction * kin["v_com"][:, 0]


def _drum_landing(x0, v0):
    """Free fall to the floor in sqrt(2 z0 / g), or the drum's chord to the
    wall first: the horizontal line p + u s meets |.| = R at
    s = -p.u + sqrt((p.u)^2 - |p|^2 + R^2)."""
    t_floor = math.sqrt(2 * x0[2] / G)
    speed = math.hypot(v0[0], v0[1])
    if speed == 0:
        return t_floor, x0 - 0.5 * G * t_floor ** 2 * np.array([0, 0, 1.0])
    u = v0[:2] / speed
    pu = float(x0[:2] @ u)
    t_wall = (-pu + math.sqrt(pu * pu - float(x0[:2] @ x0[:2]) + R * R)) / speed
    t = min(t_floor, t_wall)
    return t, x0 + v0 * t - 0.5 * G * t * t * np.array([0, 0, 1.0])


def test_a_dead_stop_on_the_drum_drops_straight_to_the_floor_in_root_2h_over_g():
    act = deathsphere.show(WALL)
    row = act.fall("Cal", 0.4, 0.0)[0]
    x0, _ = _start(act, "Cal", 0.4, 0.0)
    assert row["outcome"] == "falls" and row["t_contact_lost_s"] == 0.4
    assert row["fall_time_s"] == pytest.approx(math.sqrt(2 * x0[2] / G), rel=1e-12)
    assert row["height_land_m"] == 0.0
    assert row["height_lost_m"] == pytest.approx(9 * FT, abs=1e-12)          # on his lane, as typed
    # straight down: he lands at the azimuth where he stopped
    assert row["phi_land_deg"] == pytest.approx(math.degrees(math.atan2(x0[1], x0[0])) % 360, abs=1e-9)
    assert row["impact_speed_m_s"] == pytest.approx(math.sqrt(2 * G * x0[2]), rel=1e-12)
    assert row["theta_land_deg"] is None and row["theta_lost_deg"] is None      # theta is the globe's


@pytest.mark.parametrize("name,t,fraction", [("Ana", 0.3, 0.5), ("Ben", 1.1, 0.3), ("Cal", 1.0, 0.5),
                                             ("Cal", 2.0, 0.2)])
def test_a_fall_with_speed_lands_at_the_end_of_the_free_fall_or_of_the_chord(name, t, fraction):
    act = deathsphere.show(WALL)
    row = act.fall(name, t, fraction)[0]
    x0, v0 = _start(act, name, t, fraction)
    want_t, want_x = _drum_landing(x0, v0)
    assert row["outcome"] == "falls"
    assert row["fall_time_s"] == pytest.approx(want_t, rel=1e-12)
    assert row["t_land_s"] == pytest.approx(t + want_t, rel=1e-12)
    assert row["height_land_m"] == pytest.approx(want_x[2], abs=1e-9)
    assert row["phi_land_deg"] == pytest.approx(math.degrees(math.atan2(want_x[1], want_x[0])) % 360, abs=1e-9)
    path = act.fall_path(name, t, fraction)
    assert path["com"][:, -1] == pytest.approx(want_x, abs=1e-9) and path["t"][-1] == pytest.approx(t + want_t)


def test_a_small_drop_rides_on_and_a_large_one_falls_with_one_threshold():
    act = deathsphere.show(WALL)
    fractions = np.linspace(0.0, 1.0, 21)
    outcomes = [act.fall("Ana", 0.5, float(f))[0]["outcome"] for f in fractions]
    assert outcomes[0] == "falls" and outcomes[-1] == "rides_on"
    first_held = outcomes.index("rides_on")
    assert set(outcomes[first_held:]) == {"rides_on"} and set(outcomes[:first_held]) == {"falls"}


def test_the_least_clearance_during_a_fall_against_sampling_the_flight_densely():
    act = deathsphere.show(WALL)
    table = act.fall("Cal", 1.0, 0.5)
    x0, v0 = _start(act, "Cal", 1.0, 0.5)
    flight = float(table[0]["fall_time_s"])
    s = np.linspace(0.0, flight, 20001)
    point = x0[:, None] + v0[:, None] * s - 0.5 * G * s ** 2 * np.array([[0.0], [0.0], [1.0]])
    for row in table:
        victim = next(lane for lane in act.lanes if lane.name == row["victim"])
        p0, p1 = victim.ends(1.0 + s)
        # the distance from the flying point to the victim's segment, less both half-widths
        d = p1 - p0
        w = np.clip(np.sum((point - p0) * d, axis=0) / np.sum(d * d, axis=0), 0.0, 1.0)
        gap = np.linalg.norm(point - (p0 + w * d), axis=0) - 0.35 - 0.35
        assert row["min_clearance_m"] == pytest.approx(gap.min(), abs=2e-3)
        assert row["min_clearance_m"] <= gap.min() + 1e-9


def _cone_brute_force(x0, v0, beta, radius):
    """The first time max((rho - radius) sin(beta) - z cos(beta), -z) >= 0
    along the parabola: 20001 samples, then bisection in the test."""
    t_end = (v0[2] + math.sqrt(v0[2] ** 2 + 2 * G * x0[2])) / G * (1 + 1e-9)

    def outside(t):
        x = x0[:, None] + v0[:, None] * t - 0.5 * G * t ** 2 * np.array([[0.0], [0.0], [1.0]])
        return np.maximum((np.hypot(x[0], x[1]) - radius) * math.sin(beta) - x[2] * math.cos(beta), -x[2])

    ts = np.linspace(0.0, t_end, 20001)
    k = int(np.argmax(outside(ts)[1:] >= 0)) + 1
    lo, hi = ts[k - 1], ts[k]
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if outside(np.array([mid]))[0] < 0 else (lo, mid)
    return hi


@pytest.mark.parametrize("fraction", [0.0, 0.25, 0.45])
def test_in_the_well_of_death_he_lands_where_the_cones_implicit_function_says(fraction):
    riders = (_rider("Ana", "3ft", speed="30mph"), _rider("Cal", "9ft", phase=180, speed="60km/h"))
    act = deathsphere.show(_plan(*riders, surface="cone", wall_angle=80))
    row = act.fall("Cal", 0.7, fraction)[0]
    assert row["outcome"] == "falls"
    x0, v0 = _start(act, "Cal", 0.7, fraction)
    want = _cone_brute_force(x0, v0, math.radians(80), R)
    assert row["fall_time_s"] == pytest.approx(want, rel=1e-9)
    x1 = x0 + v0 * want - 0.5 * G * want ** 2 * np.array([0, 0, 1.0])
    assert row["height_land_m"] == pytest.approx(x1[2], abs=1e-8)


def test_the_monte_carlo_on_a_drum_is_reproducible_and_agrees_with_single_falls():
    act = deathsphere.show(WALL)
    outcomes, summary = act.falls(60, seed=3)
    again, _ = act.falls(60, seed=3)
    assert list(outcomes["t_land_s"].astype(float)) == pytest.approx(list(again["t_land_s"].astype(float)),
                                                                     nan_ok=True)
    assert set(outcomes["outcome"]) == {"rides_on", "falls"}
    for i in range(0, 60, 7):
        row = outcomes[i]
        single = act.fall(row["rider"], row["t_fail_s"], row["speed_fraction"])
        assert single[0]["outcome"] == row["outcome"]
        if row["outcome"] == "falls":
            assert single[0]["t_land_s"] == pytest.approx(row["t_land_s"], rel=1e-12)
            assert single[0]["height_land_m"] == pytest.approx(row["height_land_m"], abs=1e-12)
    total = summary[len(summary) - 1]
    assert total["falls"] == 60 and total["hits"] == int(np.sum(outcomes["hit"]))


def test_the_command_line_follows_a_fall_on_the_drum_and_the_view_draws_it(run, tmp_path):
    res = run("show", WALL, "--fail", "Cal@1.0:0.5", "--table", "falls", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    assert res.stdout.splitlines()[1].startswith("Cal,1.0,0.5,falls,")
    res = run("show", WALL, "--monte-carlo", "20", "--seed", "1", "--table", "summary", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    res = run("show", WALL, "--fail", "Cal@1.0:0.5", "--format", "table")
    assert res.exit_code == 0 and "2.74 m (9.00 ft) up" in res.stdout    # his lane's height, in the ft the plan typed it in

    from deathsphere.viewer.show_scene import act_scene

    act = deathsphere.show(WALL)
    scene = act_scene(act, act.fall("Cal", 1.0, 0.5))
    (cal,) = [track for track in scene.tracks if track.name == "Cal"]
    t, path = cal.paths["fall"]
    x0, v0 = _start(act, "Cal", 1.0, 0.5)
    assert path[:, 0] == pytest.approx(x0, abs=1e-12)
    assert path[:, -1] == pytest.approx(_drum_landing(x0, v0)[1], abs=1e-9)


def test_a_fall_closer_than_the_plans_min_clearance_is_a_conflict_and_not_a_hit(run, tmp_path):
    # Ben 90 deg ahead of Ana, nearly stopped: he drops past her with a few centimetres to spare
    plan = Path(WALL).read_text(encoding="utf-8").replace("phase = 120", "phase = 90")
    path = tmp_path / "close.toml"
    path.write_text(plan, encoding="utf-8")
    row = deathsphere.show(str(path)).fall("Ben", 0.5, 0.05)[0]
    assert row["victim"] == "Ana" and 0 < row["min_clearance_m"] < 0.15 and row["hit"] is False
    res = run("show", str(path), "--fail", "Ben@0.5:0.05", "--format", "table")
    assert res.exit_code == 0, res.stderr
    # the falls view's row: the falling rider, then the other (the pairs' rows name Ana first)
    (line,) = [text for text in res.stdout.splitlines() if text.split()[:2] == ["Ben", "Ana"]]
    assert "conflict" in line and "HIT" not in line


def test_the_fall_path_ends_where_the_table_lands_and_is_none_without_a_flight():
    act = deathsphere.show(WALL)
    assert act.fall_path("Ana", 0.5, 1.0) is None                         # rides on
    with pytest.raises(deathsphere.errors.ParameterError, match="rider must be one of Ana, Ben, Cal"):
        act.fall_path("Dan", 0.5)
    globe = deathsphere.show(str(ROOT / "tests" / "golden" / "act.toml"))
    row = globe.fall("Ana", 0.4, 0.0)[0]
    path = globe.fall_path("Ana", 0.4, 0.0)
    th, ph = math.radians(row["theta_land_deg"]), math.radians(row["phi_land_deg"])
    r = globe.plan.globe.r
    land = r * np.array([math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), math.cos(th)])
    assert path["com"][:, -1] == pytest.approx(land, abs=1e-9) and path["t"][-1] == pytest.approx(row["t_land_s"])
