"""The show on the wall of death's drum and the well of death's cone: a
plan's ``[arena]``, the lanes on the machine's physics on that ground, the
pairs' least clearance against a brute force over sampled times, and the
refusals (theta and vertical loops are the globe's; falls there:
test_arena_falls.py)."""

import math

import numpy as np
import pytest
from brute_segments import wall_lanes_least_clearance

import deathsphere
from deathsphere.constants import STANDARD_GRAVITY as G
from deathsphere.errors import ParameterError
from deathsphere.physics.ground import Cone, Cylinder
from deathsphere.records.machine_presets import PRESETS

FT, MPH = 0.3048, 0.44704
R = 16 * FT            # a 32-foot drum


def _rider(name, height, **hold):
    return {"name": name, "machine": "stunt125", "width": "0.7m", "lane": "horizontal", "height": height,
            **hold}


def _plan(*riders, **arena):
    return {"arena": {"surface": "cylinder", "diameter": "32ft", "wall_height": "12ft", "mu": 0.8, "max_g": 6,
                      **arena},
            "rider": list(riders)}


def _refusal(plan) -> str:
    with pytest.raises(ParameterError) as exc:
        deathsphere.show(plan)
    return str(exc.value)


def test_an_arena_plan_rides_the_drum():
    act = deathsphere.show(_plan(_rider("Ana", "5ft", speed="35mph")))
    assert isinstance(act.plan.globe.ground, Cylinder) and act.plan.globe.ground.radius == pytest.approx(R)
    row = {k: act.riders[k][0] for k in act.riders.columns}
    assert row["status"] == "ok" and math.isnan(row["theta_deg"])
    # the contact runs round the drum's wall at the planned speed: the lap is 2 pi R / v
    assert row["period_s"] == pytest.approx(2 * math.pi * R / (35 * MPH), rel=1e-9)


def test_the_drum_lane_is_the_drums_physics_not_the_spheres():
    """On the drum the wall's push is the centre of mass's centripetal force
    on its own circle and the friction carries the weight (docs/machine.md,
    "The wall of death"): load = sqrt((v_G^2/r_G)^2 + g^2)/g and mu needed
    = g r_G / v_G^2, r_G from the contact's radius, the tilt and the machine."""
    act = deathsphere.show(_plan(_rider("Ana", "5ft", speed="35mph"), _rider("Ben", "8ft", com_speed="40km/h")))
    m = PRESETS["stunt125"]
    for k, lane in enumerate(act.lanes):
        alpha = math.radians(act.riders["alpha_deg"][k])
        r_g = R - m.tyre_radius - (m.com_height - m.tyre_radius) * math.cos(alpha)
        v_g = act.riders["v_cm_m_s"][k]
        assert lane.points["contact"] == pytest.approx((R, lane.height), abs=1e-12)
        assert act.riders["load_g"][k] == pytest.approx(math.hypot(v_g ** 2 / r_g, G) / G, rel=1e-9)
        assert act.riders["mu_required"][k] == pytest.approx(G * r_g / v_g ** 2, rel=1e-9)
        assert act.riders["v_contact_m_s"][k] == pytest.approx(R * abs(lane.rate), rel=1e-9)
    assert act.riders["v_cm_m_s"][1] == pytest.approx(40 / 3.6)


def test_a_cone_rides_its_own_wall():
    act = deathsphere.show(_plan(_rider("Ana", "5ft", speed="35mph"), surface="cone", wall_angle=80))
    ground = act.plan.globe.ground
    assert isinstance(ground, Cone)
    rho, z = act.lanes[0].points["contact"]
    # the well of death leans out: the contact at 5 ft is R + 5 ft cot(80 deg) from the axis
    assert (rho, z) == pytest.approx((R + 5 * FT / math.tan(math.radians(80)), 5 * FT), abs=1e-9)
    assert act.riders["status"][0] == "ok"


def _brute_least(a, b, t, wall_angle=90.0):
    """The least clearance of two lanes over the times t, from their height
    and tilt alone: each envelope's axis rebuilt on the wall leaning out at
    ``wall_angle`` [deg] from the horizontal (90: the drum) with the
    floor's radius R (P = (R + height cot beta) rho-hat + height z-hat, the
    inward normal n = -sin beta rho-hat + cos beta z-hat, Q = P + t n, H =
    Q + (head - t)(-cos alpha rho-hat + sin alpha z-hat)), sampled at 401
    points along a's axis, each point's distance to b's axis by projection."""
    beta = math.radians(wall_angle)

    def meridian(height):
        return R + height * math.cos(beta) / math.sin(beta), height, beta

    return wall_lanes_least_clearance(a, b, t, meridian)


def test_two_riders_on_a_32ft_drum_against_a_brute_force_over_sampled_times():
    act = deathsphere.show(_plan(_rider("Ben", "6ft", speed="35mph", phase=60),
                                 _rider("Cal", "9ft", speed="60km/h", phase=180)))
    a, b = act.lanes
    row = {k: act.pairs[k][0] for k in act.pairs.columns}
    assert row["basis"] == "geometric"
    # over one period of their angle apart every relative azimuth is swept
    rel = 2 * math.pi / abs(a.rate - b.rate)
    brute = _brute_least(a, b, np.linspace(0.0, rel, 40001))
    assert 0 < row["min_clearance_m"] < 0.5
    assert row["min_clearance_m"] == pytest.approx(brute, abs=2e-3)
    # and at the time it reports the two are that close
    assert _brute_least(a, b, np.array([row["t_s"]])) == pytest.approx(row["min_clearance_m"], abs=2e-3)
    assert row["height_a_m"] == pytest.approx(6 * FT) and row["height_b_m"] == pytest.approx(9 * FT)


def test_two_riders_in_a_well_of_death_against_a_brute_force():
    act = deathsphere.show(_plan(_rider("Ben", "6ft", speed="35mph", phase=60),
                                 _rider("Cal", "9ft", speed="60km/h", phase=180), surface="cone", wall_angle=80))
    a, b = act.lanes
    rel = 2 * math.pi / abs(a.rate - b.rate)
    brute = _brute_least(a, b, np.linspace(0.0, rel, 40001), wall_angle=80.0)
    assert act.pairs["basis"][0] == "geometric"
    assert act.pairs["min_clearance_m"][0] == pytest.approx(brute, abs=2e-3)
    # the drum's points would put them elsewhere: the cone's lean is in the answer
    assert abs(_brute_least(a, b, np.linspace(0.0, rel, 4001)) - brute) > 0.01


def test_a_rider_too_wide_for_the_drum_is_refused():
    line = _refusal(_plan({**_rider("Ana", "5ft", speed="35mph"), "width": "7.5m"}))
    assert line.startswith("rider 'Ana': width: 7.5 m does not fit on this cylinder")


def test_a_pair_sharing_a_lap_keeps_its_clearance():
    act = deathsphere.show(_plan(_rider("Ana", "3ft", speed="35mph"),
                                 _rider("Ben", "6ft", same_lap_as="Ana", phase=20)))
    a, b = act.lanes
    brute = _brute_least(a, b, np.linspace(0.0, a.period_s, 2001))
    assert act.pairs["min_clearance_m"][0] == pytest.approx(brute, abs=2e-3)


def test_the_speed_band_is_the_drums():
    act = deathsphere.show(_plan(_rider("Ana", "5ft", speed="35mph")))
    low, high = act.riders["speed_low_m_s"][0], act.riders["speed_high_m_s"][0]
    on = deathsphere.show(_plan(_rider("Ana", "5ft", speed=f"{low * 1.001}m/s")))
    off = deathsphere.show(_plan(_rider("Ana", "5ft", speed=f"{low * 0.999}m/s")))
    assert on.riders["status"][0] == "ok" and off.riders["status"][0] != "ok"
    assert low < 35 * MPH < high


def test_a_lane_too_low_is_the_riders_status_and_above_the_wall_refused():
    act = deathsphere.show(_plan(_rider("Ana", "0.01m", speed="35mph")))
    assert (act.riders["status"][0], act.infeasible) == ("no_fit", {"Ana": "no_fit"})
    assert "floor" in act.riders["reason"][0]
    assert _refusal(_plan(_rider("Ana", "13ft", speed="35mph"))).startswith("rider 'Ana': height: ")


@pytest.mark.parametrize("change, start", [
    ({"wall_angle": 80}, "arena: wall_angle: "),
    ({"surface": "cone"}, "arena: wall_angle: "),
    ({"surface": "cone", "wall_angle": 190}, "arena: wall_angle: "),
    ({"surface": "plane"}, "arena: surface: "),
    ({"diameter": "-3ft"}, "arena: diameter: "),
    ({"walls": 2}, "arena: walls: "),
])
def test_the_arenas_refusals_name_its_key(change, start):
    assert _refusal(_plan(_rider("Ana", "5ft", speed="35mph"), **change)).startswith(start)


def test_theta_a_loop_and_both_tables_are_refused():
    theta = _rider("Ana", "5ft", speed="35mph")
    del theta["height"]
    theta["theta"] = 80
    assert _refusal(_plan(theta)).startswith("rider 'Ana': theta: ")
    loop = {"name": "Ben", "lane": "vertical", "azimuth": 0, "v_top": "6.5m/s", "width": "0.6m"}
    line = _refusal(_plan(_rider("Ana", "5ft", speed="35mph"), loop))
    assert line.startswith("rider 'Ben': lane: a vertical loop is the globe's: not on a cylinder")
    assert "needs a roof" in line                       # why: a loop over the top rides on a surface above him
    both = {**_plan(_rider("Ana", "5ft", speed="35mph")), "globe": {"diameter": "16ft"}}
    assert _refusal(both).startswith("plan: arena: ")


def test_the_scene_draws_the_drum_and_the_cone():
    from deathsphere.viewer.show_scene import act_scene

    riders = (_rider("Ana", "5ft", speed="35mph"), _rider("Ben", "8ft", speed="35mph"))
    scene = act_scene(deathsphere.show(_plan(*riders)))
    assert scene.ground["kind"] == "revolution"
    assert max(scene.ground["rho"]) == pytest.approx(R) and max(scene.ground["z"]) == pytest.approx(12 * FT)
    assert "cylinder" in scene.title
    cone = act_scene(deathsphere.show(_plan(*riders, surface="cone", wall_angle=80)))
    # the well's rim: 12 ft up, 12 ft cot(80 deg) further out than the floor's edge
    assert max(cone.ground["rho"]) == pytest.approx(R + 12 * FT / math.tan(math.radians(80)))


def test_the_speed_bound_holds_every_point_of_the_envelope_on_a_cone():
    """The pairs' certificate rests on each lane's speed bound: no point of
    the segment from contact to head moves faster (finite differences of the
    lane's own points over a lap, 11 points along the segment)."""
    act = deathsphere.show(_plan(_rider("Ana", "2ft", speed="30mph"), _rider("Cal", "10ft", speed="60km/h"),
                                 surface="cone", wall_angle=70))
    for lane in act.lanes:
        t = np.linspace(0.0, lane.period_s, 20001)
        contact, head = lane.ends(t)
        s = np.linspace(0.0, 1.0, 11)[:, None, None]
        x = contact + s * (head - contact)                            # (11, 3, n)
        speed = np.sqrt(np.sum(np.diff(x, axis=2) ** 2, axis=1)) / np.diff(t)
        assert speed.max() <= lane.speed_bound() * (1 + 1e-9)
        assert speed.max() >= 0.99 * lane.speed_bound()             # and it is not loose


@pytest.mark.parametrize("shape", [{}, {"surface": "cone", "wall_angle": 80}])
def test_a_riders_lane_is_rides_on_that_ground(shape):
    """The show's rider and ``ride --surface`` at the same height and speed
    on the same ground: one orbit, the same numbers."""
    act = deathsphere.show(_plan(_rider("Ana", "3ft", speed="30mph"), **shape))
    ride = deathsphere.ride(machine="stunt125", surface=shape.get("surface", "cylinder"), diameter="32ft",
                            wall_height="12ft", height="3ft", speed="30mph", stability=False, mu=0.8, max_g=6,
                            **({"wall_angle": 80} if shape else {}))
    ok = np.flatnonzero(ride["status"] == "ok")
    k = ok[np.argmin(np.abs(ride["alpha_deg"][ok] - (90.0 - ride["wall_angle_deg"][ok])))]
    for col in ("alpha_deg", "v_cm_m_s", "period_s", "load_g", "mu_required", "head_clearance_m"):
        assert act.riders[col][0] == pytest.approx(ride[col][k], rel=1e-12), col
