"""A show's two-wheeler riders: their lanes are ride's steady turns, their
envelopes hold the wheels, and a pair's certified least clearance against
brute force where the front wheel is what comes closest."""

import math

import numpy as np
import pytest
from brute_segments import brute_distance

import deathsphere
from deathsphere.act.lanes import build_lanes
from deathsphere.act.pairs import least_clearance
from deathsphere.act.plan import read_plan
from deathsphere.act.two_wheeler_lanes import SEGMENTS, _up, body_points, steady_turn
from deathsphere.errors import ParameterError
from deathsphere.physics.ground import Cylinder, Sphere
from deathsphere.physics.two_wheeler import geometry
from deathsphere.records.two_wheeler_presets import TWO_WHEELERS

R = 16 * 0.3048 / 2
G = 9.80665


def _two_wheeler(name="Ana", height="5ft", speed="40km/h", **extra):
    return {"name": name, "machine": "stunt125-steer", "width": "0.6m", "lane": "horizontal", "height": height,
            "speed": speed, **extra}


def _machine(name="Cal", height="2.6m", speed="30km/h", **extra):
    rider = {"name": name, "machine": "stunt125", "width": "0.6m", "lane": "horizontal", "height": height,
             "speed": speed, **extra}
    return {k: v for k, v in rider.items() if v is not None}


def _plan(*riders, **globe):
    return {"globe": {"radius": R, "mu": 0.9, "max_g": 8, **globe}, "rider": list(riders)}


RIDE_COLUMNS = ("alpha_deg", "lean_deg", "v_cm_m_s", "v_contact_m_s", "period_s", "load_g", "head_clearance_m")


def _ride_row(**keys):
    table = deathsphere.ride(machine="stunt125-steer", steer="free", stability=False, mu=0.9, max_g=8, **keys)
    assert len(table) == 1
    return table[0]


@pytest.fixture(scope="module")
def act():
    """A mixed act: a two-wheeler at 5 ft, 40 km/h and a machine on the lane above at 30 km/h."""
    return deathsphere.show(_plan(_two_wheeler(), _machine()))


def _lanes(plan):
    return build_lanes(read_plan(plan))


def test_a_two_wheelers_lane_is_rides_steady_turn_on_the_globe(act):
    mine = act.riders[0]
    want = _ride_row(diameter="16ft", height="5ft", speed="40km/h")
    for col in RIDE_COLUMNS:
        assert mine[col] == pytest.approx(want[col], rel=1e-12, abs=1e-12), col
    assert mine["lean_deg"] == pytest.approx(want["lean_vertical_deg"], rel=1e-12)
    assert mine["mu_required"] == pytest.approx(max(want["mu_required_rear"], want["mu_required_front"]), rel=1e-12)
    assert mine["status"] == want["status"] == "ok"
    assert mine["machine"] == "stunt125-steer"
    # a mixed act: the single-contact machine's row is ride's for it
    other = deathsphere.ride(machine="stunt125", diameter="16ft", height=2.6, speed="30km/h", mu=0.9, max_g=8,
                             stability=False)
    assert act.riders[1]["alpha_deg"] == pytest.approx(other[0]["alpha_deg"], rel=1e-12)


def test_a_two_wheelers_lane_is_rides_steady_turn_on_a_drum():
    lane, = _lanes({"arena": {"surface": "cylinder", "diameter": "8m", "wall_height": "5m"},
                    "rider": [_two_wheeler(height="1.5m", speed="14m/s")]})
    want = deathsphere.ride(machine="stunt125-steer", steer="free", stability=False, surface="cylinder",
                            diameter="8m", wall_height="5m", height=1.5, speed=14.0)[0]
    for key, col in (("alpha_deg", "alpha_deg"), ("v_cm", "v_cm_m_s"), ("v_contact", "v_contact_m_s"),
                     ("period", "period_s"), ("load_g", "load_g"), ("head_clearance", "head_clearance_m")):
        assert lane.orbit[key] == pytest.approx(want[col], rel=1e-12, abs=1e-12), col
    assert lane.status == want["status"] == "ok"


def test_a_lane_turns_at_its_rate_and_its_centre_of_mass_moves_at_v_cm():
    lane, = _lanes(_plan(_two_wheeler(direction="cw", phase=30)))
    row = {"v_cm_m_s": lane.orbit["v_cm"], "period_s": 2 * math.pi / abs(lane.rate)}
    kin = lane.kinematics(np.array([0.0, 0.1]))
    # the rear contact stays on its lane (height 5 ft) and starts at the plan's phase
    assert kin["contact"][2] + R == pytest.approx([5 * 0.3048] * 2, abs=1e-9)
    assert math.degrees(math.atan2(kin["contact"][1, 0], kin["contact"][0, 0])) == pytest.approx(30.0)
    assert np.linalg.norm(kin["v_com"], axis=0) == pytest.approx([row["v_cm_m_s"]] * 2, rel=1e-9)
    # clockwise seen from above: the azimuth falls; the rear contact moves at the speed planned
    step = kin["contact"][:, 1] - kin["contact"][:, 0]
    assert kin["contact"][0, 0] * step[1] - kin["contact"][1, 0] * step[0] < 0
    assert lane.period_s == pytest.approx(row["period_s"])


@pytest.mark.parametrize("name", sorted(TWO_WHEELERS))
def test_both_wheels_rims_lie_within_the_envelope(name):
    """Every rim point of the drawing (geometry.outline, the wheels' circles)
    is within 0.85 of its wheel's radius of one of the envelope's segments."""
    t = TWO_WHEELERS[name]
    for ground, at, v in ((Sphere(R), math.acos(1.524 / R - 1), 40 / 3.6), (Cylinder(4.0, 5.0), 1.5, 14.0)):
        turn = steady_turn(t, at, v, ground, G, math.inf, math.inf)
        body = body_points(turn["q"], t, ground)
        drawn = geometry.outline(turn["q"][:, None], t.parameters(), ground, t.head)
        for rim, radius in (("rear_rim", t.rR), ("front_rim", t.rF)):
            pts = np.stack([_up(x) for x in drawn[rim][:, :, 0].T], axis=1)
            # the distance to each segment the long way: 801 points along it
            s = np.linspace(0.0, 1.0, 801)
            d = np.min([np.linalg.norm(pts[:, :, None] - (body[a][:, None] + (body[b] - body[a])[:, None] * s)[:, None],
                                       axis=0).min(axis=1) for a, b in SEGMENTS], axis=0)
            assert d.max() < 0.85 * radius


#: A two-wheeler's envelope as docs/show.md states it: rear contact -> head, front contact -> head, rear
#: contact -> front contact, the wheels' line from the back of the rear rim to the front of the front rim, the
#: wheels' tops.
PROMISED = (("contact", "head"), ("front_contact", "head"), ("contact", "front_contact"), ("rear_back", "front_front"),
            ("rear_top", "front_top"))


def test_the_certified_clearance_holds_where_the_front_wheel_comes_closest(act):
    """A machine on the lane above a two-wheeler's, at another rate: every
    relative azimuth comes round, and at the closest the front of the
    two-wheeler's front wheel is next to the machine's contact.  An envelope
    from the rear contact to the head alone would miss it by some 18 cm."""
    row = act.pairs[0]
    a, b = act.lanes
    assert row["basis"] == "geometric"
    # densely sampled times over the pair's relative lap (the relative azimuth grows linearly in time)
    t = np.linspace(0.0, 2 * math.pi / abs(a.rate - b.rate), 40001)
    pa, pb = a.at_angle(a.phase + a.rate * t), b.kinematics(t)
    # the envelope the show promises (docs/show.md), spelt out here: the contacts, the head, both wheels
    ends_a = [(pa[p], pa[q]) for p, q in PROMISED]
    radii = 0.5 * (a.width_m + b.width_m)
    each = np.array([brute_distance(p0, p1, pb["contact"], pb["head"]) for p0, p1 in ends_a]) - radii
    brute = each.min(axis=0)
    assert brute.min() > 0                          # clear: no overlap's depth enters
    # certified to 1 mm above the true least; the samples miss it by at most half a step's change
    sampling = 0.5 * a.reach * abs(a.rate - b.rate) * (t[1] - t[0])
    assert brute.min() - sampling - 1e-12 <= row["min_clearance_m"] <= brute.min() + 1e-3
    # the closest is the two-wheeler's wheel line at its front end, the front of the front rim
    seg, k = np.unravel_index(int(np.argmin(each)), each.shape)
    assert PROMISED[seg] == ("rear_back", "front_front")
    front = a.at_angle(np.array([a.phase + a.rate * t[k]]))["front_front"][:, 0]
    assert np.linalg.norm(front - pb["contact"][:, k]) == pytest.approx(brute[k] + radii, abs=1e-6)
    # the head-only envelope is wrong here: its least clearance is far above the certified one
    head_only = (brute_distance(pa["contact"], pa["head"], pb["contact"], pb["head"]) - radii).min()
    assert head_only > row["min_clearance_m"] + 0.1


def test_a_looper_against_a_two_wheeler_over_the_acts_times():
    plan = _plan(_two_wheeler(), {"name": "V", "machine": "stunt125", "width": "0.6m", "lane": "vertical",
                                  "azimuth": 30, "v_top": "6.5m/s", "phase": 120})
    h, v = _lanes(plan)
    c, _, basis = least_clearance(h, v, 2.0)
    row = {"min_clearance_m": c}
    assert basis == "act"
    lipschitz = h.speed_bound() + v.speed_bound()
    t = np.linspace(0.0, 2.0, int(math.ceil(10 * 2.0 * lipschitz / 0.05)) + 1)
    pv = v.kinematics(t)
    radii = 0.5 * (h.width_m + v.width_m)
    brute = np.min([brute_distance(p0, p1, pv["contact"], pv["head"]) for p0, p1 in h.segment_ends(t)],
                   axis=0) - radii
    k = int(np.argmin(brute))
    if brute[k] > 0:
        assert row["min_clearance_m"] <= brute[k] + 1e-12
        assert row["min_clearance_m"] >= brute[k] - 1e-3 - 0.5 * lipschitz * (t[1] - t[0])
    else:
        assert row["min_clearance_m"] < 0


@pytest.mark.parametrize("extra, key", [
    ({"lane": "vertical", "azimuth": 0, "v_top": "6.5m/s", "height": None, "speed": None}, "lane"),
    ({"period": "1.3s", "speed": None}, "period"),
    ({"width": None}, "width"),
])
def test_a_plan_refuses_what_a_two_wheeler_does_not_ride_naming_the_key(extra, key):
    rider = {k: v for k, v in {**_two_wheeler(), **extra}.items() if v is not None}
    with pytest.raises(ParameterError) as err:
        deathsphere.show(_plan(rider))
    assert str(err.value).startswith(f"rider 'Ana': {key}: ")
    assert "\n" not in str(err.value)


def test_a_two_wheelers_fall_in_the_globe_flies_its_centre_of_mass_to_the_sphere(act):
    assert act.fall("Ana", 0.5, 1.0)[0]["outcome"] == "rides_on"
    row = act.fall("Ana", 0.5, 0.0)[0]
    assert row["outcome"] == "falls"
    # a dead stop: the centre of mass drops from rest, |x0 - g s^2/2 z-hat| = R at s^2 = 2 (z0 + sqrt(R^2 -
    # rho0^2)) / g (the lower crossing of the vertical line through it)
    x0 = act.lanes[0].kinematics(np.array([0.5]))["com"][:, 0]
    rho0 = math.hypot(x0[0], x0[1])
    s = math.sqrt(2.0 * (x0[2] + math.sqrt(R * R - rho0 * rho0)) / G)
    assert row["fall_time_s"] == pytest.approx(s, rel=1e-9)
    assert row["theta_land_deg"] == pytest.approx(math.degrees(math.pi - math.asin(rho0 / R)), rel=1e-9)
    assert row["phi_land_deg"] == pytest.approx(math.degrees(math.atan2(x0[1], x0[0])) % 360.0, abs=1e-9)
    assert row["impact_speed_m_s"] == pytest.approx(G * s, rel=1e-9)
    assert row["victim"] == "Cal" and math.isfinite(row["min_clearance_m"])
    # a mixed act's Monte Carlo draws both riders, each among the other's victims
    outcomes, _ = act.falls(400, seed=3)
    assert set(outcomes["rider"]) == {"Ana", "Cal"} and {"Ana", "Cal"} <= set(outcomes["victim"])
    # a machine's fall into a two-wheeler: the victim's envelope is its segments
    fall = act.fall("Cal", 0.5, 0.0)
    assert fall[0]["victim"] == "Ana"
    assert math.isfinite(fall[0]["min_clearance_m"])


def test_the_3d_view_draws_a_two_wheeler_as_its_segments(act):
    from deathsphere.viewer.show_scene import act_scene

    scene = act_scene(act)
    ana, cal = scene.tracks
    drawn = [item["points"] for item in ana.draw if item["kind"] == "capsule"]
    assert drawn == [list(ends) for ends in PROMISED]
    assert [item["points"] for item in cal.draw if item["kind"] == "capsule"] == [["contact", "head"]]
    # the front wheel's front is where the show puts it
    t = ana.t[:3]
    want = act.lanes[0].at_angle(act.lanes[0].phase + act.lanes[0].rate * t)["front_front"]
    assert np.allclose(ana.points["front_front"][:, :3], want, atol=1e-12)


def test_a_two_wheelers_parameter_file_rides_and_a_bad_one_is_refused_naming_machine(tmp_path):
    from deathsphere.records.two_wheeler_files import two_wheeler_text

    good = tmp_path / "mine.toml"
    good.write_text(two_wheeler_text("stunt125-steer"))
    plan = tmp_path / "act.toml"
    plan.write_text(f'[globe]\nradius = {R}\nmu = 0.9\nmax_g = 8\n\n[[rider]]\nname = "Ana"\nmachine = "mine.toml"\n'
                    'width = "0.6m"\nlane = "horizontal"\nheight = "5ft"\nspeed = "40km/h"\n')
    lane, = _lanes(plan)
    preset, = _lanes(_plan(_two_wheeler()))
    assert lane.orbit["alpha_deg"] == pytest.approx(preset.orbit["alpha_deg"], rel=1e-12)
    good.write_text(two_wheeler_text("stunt125-steer").replace("\nw = ", "\nw = -1\nold_w = "))
    with pytest.raises(ParameterError) as err:
        _lanes(plan)
    assert str(err.value).startswith("rider 'Ana': machine: machine file mine.toml")
    assert "\n" not in str(err.value)


def test_a_machine_may_ride_a_two_wheelers_lap():
    ana, dee = _lanes(_plan(_two_wheeler(), _machine(name="Dee", speed=None, same_lap_as="Ana", phase=180)))
    assert dee.period_s == pytest.approx(ana.period_s, rel=1e-9)


def test_a_two_wheelers_speed_band_edges_are_rides_to_1e_9():
    """The band's edges, found to 1e-10 of themselves, are where ride's own
    turns change status: ok at each edge, not 1e-9 beyond it (slips below,
    over_g above, under mu 0.9 and 8 g); with no limits the top edge is the
    solver's fastest turn (100 m/s), left empty."""
    act = deathsphere.show(_plan(_two_wheeler()))
    low, high = act.riders[0]["speed_low_m_s"], act.riders[0]["speed_high_m_s"]
    rows = deathsphere.ride(machine="stunt125-steer", steer="free", stability=False, mu=0.9, max_g=8,
                            diameter="16ft", height="5ft", speed=[low * (1 - 1e-9), low, high, high * (1 + 1e-9)])
    assert list(rows["status"]) == ["slips", "ok", "ok", "over_g"]
    free = deathsphere.show({"globe": {"radius": R}, "rider": [_two_wheeler()]})
    assert math.isfinite(free.riders[0]["speed_low_m_s"]) and free.riders[0]["speed_high_m_s"] is None
