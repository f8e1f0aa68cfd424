"""The pairs' least clearance against independent derivations."""

import math

import numpy as np
import pytest
from brute_segments import brute_distance

import deathsphere
from deathsphere.act.lanes import build_lanes
from deathsphere.act.pairs import FIRST_STEP_M, common_period, least_clearance
from deathsphere.act.plan import read_plan

R = 16 * 0.3048 / 2


def _plan(*riders, **globe):
    return {"globe": {"radius": R, "mu": 0.9, "max_g": 8, **globe}, "rider": list(riders)}


def _horizontal(name, phase, height="2m", speed="30km/h", direction="ccw"):
    return {"name": name, "lane": "horizontal", "height": height, "com_speed": speed, "phase": phase,
            "direction": direction}


@pytest.mark.parametrize("delta", [25.0, 60.0, 180.0])
def test_two_riders_one_lane_phases_apart_closed_form(delta):
    act = deathsphere.show(_plan(_horizontal("A", 10.0), _horizontal("B", 10.0 + delta)))
    row = deathsphere.ride(height=2.0, com_speed=30 / 3.6, machine="stunt125", r=R, mu=0.9, max_g=8,
                           stability=False)
    lane = act.lanes[0]
    alpha = lane.alpha
    m = lane.machine
    # both segments in meridian planes delta apart, congruent: with rho1, rho2 >= rho_min, the distance^2
    # (rho1 - rho2)^2 + (z1 - z2)^2 + 4 rho1 rho2 sin^2(delta/2) is least at the point nearest the axis on both
    rho_contact = R * math.sin(lane.theta)
    rho_head = (R - m.tyre_radius) * math.sin(lane.theta) - (m.head_height - m.tyre_radius) * math.cos(alpha)
    assert any(r["alpha_deg"] == pytest.approx(math.degrees(alpha)) for r in row)
    expect = 2 * min(rho_contact, rho_head) * math.sin(math.radians(delta) / 2) - m.width
    got = act.pairs[0]
    if expect < 0:                  # overlapping: less the overlap along the axes (their positions: rigid, any t)
        at = act.positions([0.0])
        expect = float(_with_overlap(np.array([expect]), at["A"], at["B"], m.width, n=2001)[0])
    # the overlap along the axes is integrated at 65 points (to well under a millimetre)
    assert got["min_clearance_m"] == pytest.approx(expect, abs=1e-9 if expect >= 0 else 1e-4)
    assert got["basis"] == "act"
    assert got["verdict"] == ("clear" if expect >= 0.15 else "conflict" if expect >= 0 else "collision")


def _with_overlap(clearance, pa, pb, radii, n=101):
    """Where the envelopes overlap, less the overlap across integrated along
    the axes per unit of the radii (docs/show.md), the long way: each axis as
    n points, each point's distance to the other axis's points."""
    inside = np.flatnonzero(clearance < 0)
    s = (np.arange(n) + 0.5) / n
    out = clearance.copy()
    for chunk in np.array_split(inside, max(1, inside.size // 200)):
        ends = [(p["contact"][:, chunk], p["head"][:, chunk]) for p in (pa, pb)]
        pts = [e0[:, :, None] + (e1 - e0)[:, :, None] * s for e0, e1 in ends]                 # (3, m, n)
        dist = np.linalg.norm(pts[0][:, :, :, None] - pts[1][:, :, None, :], axis=0)      # (m, n, n)
        lengths = [np.linalg.norm(e1 - e0, axis=0) for e0, e1 in ends]
        along = (lengths[0] * np.maximum(0, radii - dist.min(axis=2)).mean(axis=1)
                 + lengths[1] * np.maximum(0, radii - dist.min(axis=1)).mean(axis=1))
        out[chunk] -= 0.5 * along / radii
    return out


def test_a_looper_and_a_horizontal_rider_against_sampling_ten_times_finer():
    plan = _plan(_horizontal("H", 40.0, height="2.2m", speed="29km/h"),
                 {"name": "V", "lane": "vertical", "azimuth": 30, "v_top": "6.5m/s", "phase": 200})
    h, v = build_lanes(read_plan(plan))
    span = 3.0
    c, t, basis = least_clearance(h, v, span)
    lipschitz = h.speed_bound() + v.speed_bound()
    times = np.linspace(0, span, int(math.ceil(10 * span * lipschitz / FIRST_STEP_M)) + 1)
    a, b = h.kinematics(times), v.kinematics(times)
    radii = 0.5 * (h.width_m + v.width_m)
    brute = _with_overlap(brute_distance(a["contact"], a["head"], b["contact"], b["head"]) - radii, a, b, radii)
    k = int(np.argmin(brute))
    assert basis == "act"
    assert c <= brute[k] + 1e-12                  # never above a sample: no minimum missed
    assert c >= brute[k] - 1e-3 - 0.5 * lipschitz * (times[1] - times[0])
    assert abs(t - times[k]) < 0.05 or brute[np.abs(times - t).argmin()] < c + 2e-3


def test_horizontal_lanes_of_different_rates_take_the_geometric_least_clearance():
    act = deathsphere.show(_plan(_horizontal("A", 0.0, height="2m", speed="30km/h"),
                                 _horizontal("B", 137.0, height="2.6m", speed="30km/h")), duration=5)
    row = act.pairs[0]
    assert row["basis"] == "geometric"
    a, b = act.lanes
    # every relative azimuth is swept: brute force over it, both meridian planes
    delta = np.linspace(0, 2 * np.pi, 20001)
    pa, pb = a.at_angle(delta), b.at_angle(np.zeros_like(delta))
    radii = 0.5 * (a.width_m + b.width_m)
    brute = brute_distance(pa["contact"], pa["head"], pb["contact"], pb["head"]) - radii
    brute = _with_overlap(brute, pa, pb, radii)
    assert brute.min() - 1e-3 <= row["min_clearance_m"] <= brute.min() + 1e-12
    # whatever the phases
    other = deathsphere.show(_plan(_horizontal("A", 50.0, height="2m", speed="30km/h"),
                                   _horizontal("B", 0.0, height="2.6m", speed="30km/h")), duration=5)
    assert other.pairs[0]["min_clearance_m"] == pytest.approx(row["min_clearance_m"], abs=1e-3)


def test_the_common_period_and_its_tolerance():
    assert common_period([1.0, 1.5]) == pytest.approx(3.0)
    assert common_period([1.0, 1.0005]) == pytest.approx(1.0)       # within 1e-3
    assert common_period([1.0, math.sqrt(2)]) is None
    with pytest.raises(deathsphere.ParameterError, match="duration"):
        deathsphere.show(_plan(_horizontal("A", 0.0), {"name": "V", "lane": "vertical", "v_top": "6.1m/s"}))


def test_the_pairs_say_how_high_they_are_and_where_they_come_closest():
    from deathsphere.api.shows import EXAMPLE_PLAN

    act = deathsphere.show(read_plan_text(EXAMPLE_PLAN))
    s = (np.arange(1201) + 0.5) / 1201
    for i in range(len(act.pairs)):
        row = act.pairs[i]
        at = act.positions([row["t_s"]])
        a, b = at[row["rider_a"]], at[row["rider_b"]]
        # the contacts' heights above the floor (a horizontal lane's as planned)
        assert row["height_a_m"] == pytest.approx(a["contact"][2, 0] + R, abs=1e-9)
        assert row["height_b_m"] == pytest.approx(b["contact"][2, 0] + R, abs=1e-9)
        # the closest approach the long way: both axes as points, the closest two, midway
        pa = a["contact"] + (a["head"] - a["contact"]) * s
        pb = b["contact"] + (b["head"] - b["contact"]) * s
        dist = np.linalg.norm(pa[:, :, None] - pb[:, None, :], axis=0)
        j, k = np.unravel_index(int(np.argmin(dist)), dist.shape)
        mid = 0.5 * (pa[:, j] + pb[:, k])
        assert row["closest_height_m"] == pytest.approx(mid[2] + R, abs=2e-3)
        assert row["closest_phi_deg"] == pytest.approx(math.degrees(math.atan2(mid[1], mid[0])) % 360, abs=0.2)
    heights = {act.pairs[i]["rider_a"]: act.pairs[i]["height_a_m"] for i in range(len(act.pairs))}
    assert (heights["Ana"], heights["Cal"]) == (1.4, 2.0)


def read_plan_text(text):
    import tomllib

    return tomllib.loads(text)
