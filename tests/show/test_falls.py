"""Falls in the act against independent derivations, and the Monte Carlo's
rows: vectorised, reproducible, the same on a cluster."""

import math

import numpy as np
import pytest

import deathsphere

R = 16 * 0.3048 / 2
G = 9.80665


def _act(*riders, **kw):
    return deathsphere.show({"globe": {"radius": R, "mu": 0.9, "max_g": 8}, "rider": list(riders)}, **kw)


ANA = {"name": "Ana", "lane": "horizontal", "height": "3.2m", "com_speed": "30km/h", "phase": 20}
CAL = {"name": "Cal", "lane": "horizontal", "height": "1.4m", "com_speed": "26km/h", "phase": 200}


def test_a_stall_above_the_equator_falls_straight_down():
    act = _act(ANA, CAL, duration=3)
    t = 0.37
    com = act.positions([t])["Ana"]["com"][:, 0]
    row = act.fall("Ana", t, 0.0)[0]
    assert row["outcome"] == "falls" and row["t_contact_lost_s"] == t
    # straight down: the vertical through the centre of mass meets the globe at z = -sqrt(r^2 - rho^2)
    rho = math.hypot(com[0], com[1])
    z_land = -math.sqrt(R * R - rho * rho)
    assert row["fall_time_s"] == pytest.approx(math.sqrt(2 * (com[2] - z_land) / G), rel=1e-9)
    assert row["phi_land_deg"] == pytest.approx(math.degrees(math.atan2(com[1], com[0])) % 360, abs=1e-9)
    assert row["theta_land_deg"] == pytest.approx(math.degrees(math.acos(z_land / R)), abs=1e-9)
    assert row["impact_speed_m_s"] == pytest.approx(math.sqrt(2 * G * (com[2] - z_land)), rel=1e-9)
    assert row["t_land_s"] == pytest.approx(t + row["fall_time_s"])
    # where: he leaves the wall at his lane's height as planned, lands where the vertical meets the floor's side
    assert row["height_lost_m"] == 3.2
    assert row["height_land_m"] == pytest.approx(R + z_land, abs=1e-9)
    outcomes, _ = act.falls(40, seed=3)
    fell = [outcomes[i] for i in range(len(outcomes)) if outcomes["outcome"][i] == "falls"]
    assert fell and all(r["height_lost_m"] == {"Ana": 3.2, "Cal": 1.4}[r["rider"]] for r in fell)
    assert all(r["height_land_m"] == pytest.approx(R * (1 + math.cos(math.radians(r["theta_land_deg"]))))
               for r in fell)


def test_a_small_drop_rides_on_and_the_alone_rider_has_one_row():
    act = _act(ANA)
    table = act.fall("Ana", 0.2, 0.97)
    assert len(table) == 1 and table[0]["victim"] in ("", None) and table[0]["outcome"] == "rides_on"
    assert np.isnan(np.asarray(table["t_land_s"], dtype=float)[0])


def test_the_victim_clearance_against_sampling_the_flight():
    act = _act(ANA, CAL, {"name": "Ben", "lane": "vertical", "azimuth": 20, "v_top": "6.5m/s", "phase": 300},
               duration=3)
    rows = act.fall("Ben", 0.1, 0.2)
    assert rows[0]["outcome"] == "falls"
    lane = {x.name: x for x in act.lanes}
    start, flight = rows[0]["t_contact_lost_s"], rows[0]["fall_time_s"]
    from deathsphere.act.falls import simulate_falls

    res = simulate_falls(act.lanes, act.plan.globe, [2], [0.1], [0.2])
    x0, v0 = res["x0"][:, 0], res["v0"][:, 0]
    s = np.linspace(0, flight, 40001)
    point = x0[:, None] + v0[:, None] * s - 0.5 * G * s * s * np.array([0, 0, 1.0])[:, None]
    for row in rows:
        p0, p1 = lane[row["victim"]].ends(start + s)
        d = p1 - p0
        u = np.clip(np.sum((point - p0) * d, axis=0) / np.sum(d * d, axis=0), 0, 1)
        brute = np.linalg.norm(point - p0 - u * d, axis=0) - 0.5 * (0.8 + lane[row["victim"]].width_m)
        assert brute.min() - 1.5e-3 <= row["min_clearance_m"] <= brute.min() + 1e-8
        assert row["hit"] == (row["min_clearance_m"] < 0)


def test_the_monte_carlo_is_reproducible_and_agrees_with_single_falls():
    act = _act(ANA, CAL, {"name": "Ben", "lane": "vertical", "azimuth": 20, "v_top": "6.5m/s"}, duration=3)
    outcomes, summary = act.falls(300, seed=7)
    again, _ = act.falls(300, seed=7)
    assert list(outcomes["t_fail_s"]) == list(again["t_fail_s"])
    assert set(outcomes["outcome"]) <= {"rides_on", "swings", "falls"}
    for i in (0, 1, 2, 17):
        row = outcomes[i]
        single = act.fall(row["rider"], row["t_fail_s"], row["speed_fraction"])
        assert single[0]["outcome"] == row["outcome"]
        if row["outcome"] == "falls":
            assert single[0]["t_land_s"] == pytest.approx(row["t_land_s"], rel=1e-12)
    total = summary[len(summary) - 1]
    assert total["falls"] == 300 and total["hits"] == int(np.sum(outcomes["hit"]))


def test_the_monte_carlo_on_a_cluster_gives_the_same_rows():
    distributed = pytest.importorskip("distributed", reason="the distributed extra is not installed")
    act = _act(ANA, CAL, duration=3)
    local, _ = act.falls(50, seed=3)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        remote, _ = act.falls(50, seed=3, scheduler=client)
    for col in ("rider", "outcome", "t_land_s", "victim", "min_clearance_m"):
        assert list(map(str, local[col])) == list(map(str, remote[col]))


def test_a_looper_who_swings_reports_how_high_and_whose_lanes_he_crosses():
    act = _act(ANA, CAL, {"name": "Ben", "lane": "vertical", "azimuth": 20, "v_top": "6.5m/s", "phase": 180},
               duration=3)
    rows = act.fall("Ben", 0.0, 0.3)          # at the bottom, 30 % of his speed: below the equator he swings
    by_victim = {r["victim"]: r for r in rows}
    row = rows[0]
    assert row["outcome"] == "swings"
    # energy (M21) from the bottom: (1/2) M psidot^2 = m g dz, with M from ride's rates at top and bottom
    # (M23: M = 4 m g r_G / (psidot_b^2 - psidot_t^2)); the contact rises r / r_G times the centre of mass
    loop = deathsphere.ride(90, vertical=True, v_top=6.5, machine="stunt125", r=R)[0]
    r_g = R - 0.8
    m_eff = 4 * 165 * G * r_g / (loop["omega_bottom_rad_s"] ** 2 - loop["omega_top_rad_s"] ** 2)
    psidot = 0.3 * loop["omega_bottom_rad_s"]
    rise = 0.5 * m_eff * psidot ** 2 / (165 * G)
    assert row["swing_height_m"] == pytest.approx(rise * R / r_g, rel=1e-9)
    assert by_victim["Cal"]["crosses_lane"] == (1.4 <= row["swing_height_m"])
    assert not by_victim["Ana"]["crosses_lane"]                # 3.2 m: above any swing below the equator


def test_a_point_mass_looper_leaves_where_the_normal_force_vanishes_and_lands_three_times_as_far():
    point_mass = {"base": "paper-wheel", "com_height": 0, "roll_inertia": 0, "pitch_inertia": 0, "yaw_inertia": 0,
                  "spin_inertia": 0}
    act = _act({"name": "P", "lane": "vertical", "machine": point_mass, "azimuth": 30, "v_top": "6m/s",
                "phase": 180})
    row = act.fall("P", 0.0, 0.7)[0]          # at the bottom, 70 % of his speed
    assert row["outcome"] == "falls"
    # energy: v^2 = v_b^2 - 2 g r (1 + cos beta) at beta from the top; the normal force vanishes where
    # v^2 = g r cos beta, so cos beta = (v_b^2 / (g r) - 2) / 3; he leaves beta before the top ...
    v_b = 0.7 * math.sqrt(6.0 ** 2 + 4 * G * R)
    beta = math.acos((v_b ** 2 / (G * R) - 2) / 3)
    assert row["theta_lost_deg"] == pytest.approx(math.degrees(beta), abs=1e-6)
    assert row["phi_lost_deg"] == pytest.approx(210.0, abs=1e-6)
    # ... and lands 3 beta past the top, in the loop's plane
    land = R * np.array([math.sin(3 * beta) * math.cos(math.radians(30)), math.sin(3 * beta) * math.sin(
        math.radians(30)), math.cos(3 * beta)])
    assert row["theta_land_deg"] == pytest.approx(math.degrees(math.acos(land[2] / R)), abs=1e-6)
    assert row["phi_land_deg"] == pytest.approx(math.degrees(math.atan2(land[1], land[0])) % 360, abs=1e-6)
