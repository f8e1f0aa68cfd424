"""The riders table against ride's own rows, the speed band's edges against
ride's statuses, the drift against the chord's closed form, and phase auto
against trying the phases one by one."""

import math

import numpy as np
import pytest

import deathsphere

R = 16 * 0.3048 / 2
GLOBE = {"radius": R, "mu": 0.9, "max_g": 8, "min_clearance": "0.15m"}


def _act(*riders, **kw):
    return deathsphere.show({"globe": GLOBE, "rider": list(riders)}, **kw)


def _h(name, phase, height="2.2m", speed="29km/h"):
    return {"name": name, "lane": "horizontal", "height": height, "com_speed": speed, "phase": phase}


def test_the_riders_table_is_rides_rows():
    act = _act(_h("A", 0), {"name": "V", "lane": "vertical", "azimuth": 90, "v_top": "6.5m/s"}, duration=2)
    a, v = act.riders[0], act.riders[1]
    rows = deathsphere.ride(height=2.2, com_speed=29 / 3.6, machine="stunt125", r=R, mu=0.9, max_g=8, stability=False)
    (mine,) = [r for r in rows if r["alpha_deg"] == a["alpha_deg"]]
    for col in ("theta_deg", "lean_deg", "v_cm_m_s", "v_cm_km_h", "v_contact_m_s", "period_s", "load_g",
                "mu_required", "head_clearance_m", "status"):
        assert a[col] == mine[col]
    loop = deathsphere.ride(90, vertical=True, v_top=6.5, machine="stunt125", r=R, mu=0.9, max_g=8)[0]
    for col, theirs in (("v_top_min_m_s", "v_top_min_m_s"), ("v_bottom_m_s", "v_bottom_m_s"),
                        ("load_bottom_g", "load_bottom_g"), ("mu_required", "mu_required"), ("status", "status")):
        assert v[col] == loop[theirs]
    assert v["lane"] == "vertical" and a["lane"] == "horizontal"


@pytest.mark.parametrize("rider", [0, 1])
def test_the_speed_band_edges_are_where_ride_changes_its_verdict(rider):
    act = _act(_h("A", 0), {"name": "V", "lane": "vertical", "azimuth": 90, "v_top": "6.5m/s"}, duration=2)
    row = act.riders[rider]
    # found to 1e-10 of the planned speed: ride's verdict changes within 2e-10 of each edge
    for edge, inside in (("speed_low_m_s", 1 + 2e-10), ("speed_high_m_s", 1 - 2e-10)):
        v = row[edge]
        if rider == 0:
            def ok(speed):
                t = deathsphere.ride(height=2.2, speed=speed, machine="stunt125", r=R, mu=0.9, max_g=8,
                                     stability=False)
                return bool(np.any(np.asarray(t["status"]) == "ok"))
        else:
            def ok(speed):
                return deathsphere.ride(90, vertical=True, v_top=speed, machine="stunt125", r=R, mu=0.9,
                                        max_g=8)[0]["status"] == "ok"
        assert ok(v * inside) and not ok(v * (2 - inside))
    planned = row["v_contact_m_s"] if rider == 0 else 6.5
    assert row["margin_low_pct"] == pytest.approx(100 * (planned - row["speed_low_m_s"]) / planned)


def test_a_loopers_speed_band_is_where_his_friction_and_load_reach_the_limits():
    from scipy.optimize import brentq

    act = _act({"name": "V", "lane": "vertical", "azimuth": 90, "v_top": "6.5m/s"})
    row = act.riders[0]

    def loop(v_top, key):
        return deathsphere.ride(90, vertical=True, v_top=v_top, machine="stunt125", r=R, mu=0.9, max_g=8)[0][key]

    # the continuous quantities ride reports, each root bracketed and found to the last bits: slow, the
    # friction needed reaches mu = 0.9; fast, the bottom's load reaches max_g = 8
    low = brentq(lambda v: loop(v, "mu_required") - 0.9, 1.0001 * row["v_top_min_m_s"], 6.5, xtol=1e-14, rtol=1e-15)
    high = brentq(lambda v: loop(v, "load_bottom_g") - 8, 6.5, 12.0, xtol=1e-14, rtol=1e-15)
    assert row["speed_low_m_s"] == pytest.approx(low, rel=1e-10)
    assert row["speed_high_m_s"] == pytest.approx(high, rel=1e-10)


def test_drift_of_two_riders_in_one_lane_closed_form():
    act = _act(_h("A", 0), _h("B", 100))
    lane = act.lanes[0]
    m = lane.machine
    rho = min(R * math.sin(lane.theta),
              (R - m.tyre_radius) * math.sin(lane.theta) - (m.head_height - m.tyre_radius) * math.cos(lane.alpha))
    # the chord 2 rho sin(delta/2) - width reaches 0.15 m at delta*; A 1 % off closes the 100 deg gap at 0.01 Omega
    delta = 2 * math.asin((0.15 + m.width) / (2 * rho))
    expect = (math.radians(100) - delta) / (0.01 * abs(lane.rate))
    row = act.pairs[0]
    assert row["verdict"] == "clear"
    assert row["drift_time_s"] == pytest.approx(expect, abs=0.05)


def test_phase_auto_is_at_least_as_good_as_every_phase_tried():
    from deathsphere.act.lanes import build_lanes
    from deathsphere.act.pairs import least_clearance
    from deathsphere.act.plan import read_plan

    looper = {"name": "V", "lane": "vertical", "azimuth": 90, "v_top": "6.5m/s", "phase": 0}
    # the horizontal lap equal to the loop's (1.274 s): commensurate, one lap is the act
    rider = _h("A", 0, height="2.0m", speed="28.86km/h")
    auto = _act(rider, looper, phase="auto")
    assert auto.commensurate
    best = auto.pairs[0]["min_clearance_m"]
    tried = []
    for phase in range(0, 360, 30):
        lanes = build_lanes(read_plan({"globe": GLOBE, "rider": [rider, {**looper, "phase": phase}]}))
        tried.append(least_clearance(*lanes, auto.duration_s)[0])
    assert best >= max(tried) - 0.02
    chosen = auto.plan.riders[1].phase_deg
    assert any(a <= chosen <= b if a <= b else (chosen >= a or chosen <= b) for a, b in auto.phase_windows["V"])
    assert best >= 0.15


@pytest.mark.parametrize("phase, azimuth, theta, phi", [(178, 90, 178.0, 90.0), (282, 0, 78.0, 180.0),
                                                        (282.3, 30, 77.7, 210.0), (0, 45, 0.0, 45.0),
                                                        (180, 300.5, 180.0, 300.5), (-90, 200, 90.0, 20.0)])
def test_a_vertical_riders_theta_and_phi_echo_his_phase_as_typed(phase, azimuth, theta, phi):
    # the contact at t = 0 is r (sin psi e + cos psi z): theta = psi on the near side of the loop
    # (phi its azimuth), 360 - psi on the far side (phi + 180); the text typed, not its float's residue
    act = deathsphere.show({"globe": {"diameter": "16ft", "mu": 0.9, "max_g": 8}, "rider": [
        {"name": "V", "lane": "vertical", "azimuth": azimuth, "v_top": "6.5m/s", "phase": phase}]})
    row = act.riders[0]
    assert (row["theta_deg"], row["phi0_deg"]) == (theta, phi)
    contact = act.positions([0.0])["V"]["contact"][:, 0]
    assert np.degrees(np.arccos(contact[2] / np.linalg.norm(contact))) == pytest.approx(theta, abs=1e-9)


def test_phase_auto_writes_its_phase_and_window_in_the_riders_table():
    looper = {"name": "V", "lane": "vertical", "azimuth": 90, "v_top": "6.5m/s", "phase": 0}
    rider = _h("A", 0, height="2.0m", speed="28.86km/h")
    auto = _act(rider, looper, phase="auto")
    a, v = auto.riders[0], auto.riders[1]
    # a row reads an empty text and an undefined number as None
    assert (a["phase_from"], a["phase_deg"], a["safe_phases_deg"], a["window_lo_deg"]) == ("plan", 0.0, None, None)
    assert v["phase_from"] == "auto"
    assert v["phase_deg"] == auto.plan.riders[1].phase_deg
    # the phase ridden is the lane's: the looper's contact at t = 0 is psi = phase from the top
    contact = auto.positions([0.0])["V"]["contact"][:, 0]
    assert math.degrees(math.acos(contact[2] / np.linalg.norm(contact))) == pytest.approx(
        min(v["phase_deg"], 360 - v["phase_deg"]), abs=1e-6)
    lo, hi = v["window_lo_deg"], v["window_hi_deg"]
    assert (lo, hi) in auto.phase_windows["V"]
    assert (lo <= v["phase_deg"] <= hi) if lo <= hi else (v["phase_deg"] >= lo or v["phase_deg"] <= hi)
    assert f"{lo:.6g}-{hi:.6g}" in v["safe_phases_deg"].split()
    assert v["in_the_way"] is None
    plain = _act(rider, looper)
    assert plain.riders[1]["phase_from"] == "plan" and plain.riders[1]["phase_deg"] == 0.0


def test_an_empty_window_names_the_riders_in_the_way(tmp_path):
    from deathsphere.api.shows import EXAMPLE_PLAN

    path = tmp_path / "act.toml"
    path.write_text(EXAMPLE_PLAN, encoding="utf-8")
    auto = deathsphere.show(str(path), phase="auto")
    rule = auto.plan.globe.min_clearance
    rows = {r["name"]: r for r in (auto.riders[i] for i in range(len(auto.riders)))}
    pairs = {(p["rider_a"], p["rider_b"]): p["min_clearance_m"] for p in (auto.pairs[i] for i in range(len(auto.pairs)))}
    for looper, earlier in (("Ben", ["Ana", "Cal", "Dee"]), ("Eve", ["Ana", "Cal", "Dee", "Ben"])):
        row = rows[looper]
        assert row["safe_phases_deg"] == "none" and row["window_lo_deg"] is None
        # the pairs, found to 1 mm at the phase taken, say who is closer than the rule
        closer = [o for o in earlier if pairs.get((o, looper), pairs.get((looper, o))) < rule]
        assert closer and row["in_the_way"] == ";".join(closer)
