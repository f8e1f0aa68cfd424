"""Lanes against independent derivations: the loop's psi(t) against a
numerical integration of the energy equation, the horizontal lane against
ride's own row."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import deathsphere
from deathsphere.act.lanes import build_lanes
from deathsphere.act.plan import read_plan

R = 16 * 0.3048 / 2
PLAN = {"globe": {"radius": R, "mu": 0.9, "max_g": 8},
        "rider": [{"name": "Ana", "lane": "horizontal", "height": "2m", "com_speed": "30km/h", "phase": 30,
                   "direction": "cw"},
                  {"name": "Ben", "lane": "vertical", "azimuth": 60, "v_top": "6.5m/s", "phase": 100}]}


def test_the_loop_follows_the_energy_equation():
    ana, ben = build_lanes(read_plan(PLAN))
    row = deathsphere.ride(90, vertical=True, v_top=6.5, machine="stunt125", r=R)[0]
    top, bottom = row["omega_top_rad_s"], row["omega_bottom_rad_s"]
    # M21: psidot^2 = top^2 + (bottom^2 - top^2) (1 - cos psi) / 2, i.e. psiddot = (bottom^2 - top^2) sin(psi) / 4
    k2 = bottom ** 2 - top ** 2
    psidot0 = math.sqrt(top ** 2 + k2 * (1 - math.cos(math.radians(100))) / 2)
    t = np.linspace(0, 2.5, 60)
    sol = solve_ivp(lambda _, y: [y[1], 0.25 * k2 * math.sin(y[0])], (0, 2.5), [math.radians(100), psidot0],
                    t_eval=t, rtol=1e-11, atol=1e-12)
    kin = ben.kinematics(t)
    assert np.allclose(kin["psi"], sol.y[0], atol=1e-7)
    # the contact on the great circle in the plane of azimuth 60 deg, psi from the top
    e = np.array([math.cos(math.radians(60)), math.sin(math.radians(60)), 0])
    expect = R * (np.sin(sol.y[0])[None] * e[:, None] + np.cos(sol.y[0])[None] * np.array([0, 0, 1.0])[:, None])
    assert np.allclose(kin["contact"], expect, atol=1e-6)
    # the lap: psi grows by 2 pi over one period
    lap = ben.kinematics(np.array([0.0, ben.period_s]))["psi"]
    assert lap[1] - lap[0] == pytest.approx(2 * math.pi, abs=1e-9)


def test_the_horizontal_lane_is_rides_orbit():
    ana, _ = build_lanes(read_plan(PLAN))
    rows = deathsphere.ride(height=2.0, com_speed=30 / 3.6, machine="stunt125", r=R, mu=0.9, max_g=8, stability=False)
    mine = [r for r in rows if r["alpha_deg"] == pytest.approx(math.degrees(ana.alpha), abs=1e-12)]
    assert len(mine) == 1 and mine[0]["status"] == "ok"
    upright = math.degrees(ana.theta) - 90
    ok = [r["alpha_deg"] for r in rows if r["status"] == "ok"]
    assert abs(mine[0]["alpha_deg"] - upright) == min(abs(a - upright) for a in ok)
    t = np.array([0.0, 0.4])
    kin = ana.kinematics(t)
    # cw: phi = phase - Omega t; the centre of mass on a circle of ride's radius at ride's speed
    assert np.allclose(np.degrees(kin["phi"]), 30 - np.degrees(mine[0]["omega_rad_s"]) * t)
    assert np.allclose(np.hypot(kin["com"][0], kin["com"][1]), mine[0]["com_orbit_radius_m"])
    assert np.allclose(np.linalg.norm(kin["v_com"], axis=0), mine[0]["v_cm_m_s"])
    assert np.allclose(np.linalg.norm(kin["head"], axis=0), R - mine[0]["head_clearance_m"])
    assert np.allclose(kin["contact"][2], 2.0 - R)


def test_lanes_hold_no_globe_and_no_gravity_and_take_every_machine_at_once():
    plan = read_plan({"globe": {"radius": R, "mu": 0.9, "max_g": 8}, "rider": [
        {"name": "A", "lane": "horizontal", "height": "2.0m", "com_speed": "30km/h", "machine": "stunt125"},
        {"name": "B", "lane": "horizontal", "height": "1.2m", "com_speed": "20km/h", "machine": "benchmark-bicycle-rigid"},
        {"name": "C", "lane": "vertical", "v_top": "6.5m/s", "machine": "stunt125"}]})
    lanes = build_lanes(plan)
    for lane in lanes:
        assert not hasattr(lane, "r") and not hasattr(lane, "g")
    # each horizontal lane is the one ride gives that machine
    for lane, height, kmh in zip(lanes[:2], (2.0, 1.2), (30, 20)):
        rows = deathsphere.ride(height=height, com_speed=kmh / 3.6, machine=lane.machine, r=R, mu=0.9, max_g=8,
                                stability=False)
        assert any(r["alpha_deg"] == lane.orbit["alpha_deg"] and r["period_s"] == lane.period_s for r in rows)
