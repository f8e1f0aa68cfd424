"""`speed` is the contact's speed along the ground in orbit, sweep and
orbit --input; `com_speed` the wheel centre's.  Checked against an
independent computation: on a steady orbit the contact runs round the
parallel of radius r sin(theta), so the rate of every row answering a
contact speed v is v / (r sin theta), and the tilt of each row satisfies
eq. (29) at that rate, written out here from the paper."""

import math

import numpy as np
import pytest

import deathsphere

A, R, K, G = 0.3, 3.0, 0.5, 9.80665


def eq29_residual(theta_deg, alpha_deg, omega, a=A, r=R, k=K, g=G):
    """McDonald (1993) eq. (29) as a residual, cross-multiplied:
    Omega^2 ((2k+1) r sin(theta) - (k+1) a cos(alpha)) sin(alpha) - g cos(alpha),
    scaled by g (zero on a steady orbit)."""
    th, al = np.radians(theta_deg), np.radians(alpha_deg)
    return (omega ** 2 * ((2 * k + 1) * r * np.sin(th) - (k + 1) * a * np.cos(al)) * np.sin(al)
            - g * np.cos(al)) / g


def test_contact_speed_gives_the_rate_v_over_r_sin_theta_and_eq29_holds():
    theta = np.array([20.0, 45.0, 60.0, 90.0, 120.0, 150.0])
    speed = np.array([2.0, 5.0, 7.0, 11.0, 20.0])
    t = deathsphere.orbit(theta[:, None], speed=speed[None, :], stability=False)
    rated = np.isfinite(t["omega_rad_s"])
    assert rated.sum() >= 20                                 # most requests have a tilt
    assert set(t["status"][~rated]) <= {"no_orbit"}
    th = t["theta_deg"][rated]
    asked = speed[np.searchsorted(speed, t["v_contact_m_s"][rated])]   # the echoed request
    assert set(t["v_contact_m_s"][rated]) <= set(speed)
    omega = t["omega_rad_s"][rated]
    # the contact's speed Omega r sin(theta) is the speed asked
    np.testing.assert_allclose(omega * R * np.sin(np.radians(th)), asked, rtol=1e-9)
    # and every row's tilt is a root of eq. (29) at that rate
    np.testing.assert_allclose(eq29_residual(th, t["alpha_deg"][rated], asked / (R * np.sin(np.radians(th)))),
                               0.0, atol=1e-8)
    # several tilts per request where eq. 29 has several roots: each distinct, each a row
    one = t[(t["theta_deg"] == 60.0) & (t["v_contact_m_s"] == 7.0)]
    assert len(set(one["alpha_deg"].tolist())) == len(one) >= 1


def test_com_speed_is_the_centre_speed_and_differs_from_the_contacts():
    centre = deathsphere.orbit(60, com_speed=7, stability=False)
    contact = deathsphere.orbit(60, speed=7, stability=False)
    assert set(centre["v_cm_m_s"].tolist()) == {7.0} and set(contact["v_contact_m_s"].tolist()) == {7.0}
    # the centre runs round the parallel of radius |r'|, the contact round r sin(theta)
    np.testing.assert_allclose(centre["omega_rad_s"] * np.abs(centre["r_prime_m"]), 7.0, rtol=1e-9)
    np.testing.assert_allclose(centre["v_contact_m_s"], centre["omega_rad_s"] * R * math.sin(math.radians(60)))
    assert not np.allclose(sorted(centre["alpha_deg"]), sorted(contact["alpha_deg"]))


def test_a_tilt_given_gets_its_contact_speed():
    t = deathsphere.orbit([30, 60, 90], 10, stability=False)
    np.testing.assert_allclose(t["v_contact_m_s"], t["omega_rad_s"] * R * np.sin(np.radians([30, 60, 90])))


@pytest.mark.parametrize("theta", [0, 180])
def test_contact_on_the_axis_is_no_orbit(theta):
    t = deathsphere.orbit(theta, speed=5, stability=False)
    assert t["status"].tolist() == ["no_orbit"] and "on the vertical axis" in t["reason"][0]
    assert t["v_contact_m_s"].tolist() == [5.0]


def test_exactly_one_hold(run):
    res = run("orbit", "--theta", "60", "--speed", "7", "--com-speed", "7")
    assert res.exit_code == 2 and res.stderr.count("\n") == 1 and "error: --com-speed: give one of" in res.stderr
    res = run("sweep", "--theta", "60", "--alpha", "10", "--speed", "7")
    assert res.exit_code == 2 and res.stderr.count("\n") == 1 and "--speed: give one of" in res.stderr
    with pytest.raises(deathsphere.ParameterError, match="exactly one of alpha"):
        deathsphere.orbit(60, speed=7, com_speed=7)


def test_input_columns_speed_and_com_speed(tmp_path):
    path = tmp_path / "in.csv"
    path.write_text("theta,speed,com_speed\n60,7,\n60,,7\n0,7,\n")
    t = deathsphere.orbit_input(path, stability=False).table()
    first, second = t[t["input_row"] == 1], t[t["input_row"] == 2]
    np.testing.assert_allclose(first["omega_rad_s"] * R * math.sin(math.radians(60)), 7.0, rtol=1e-9)
    assert set(second["v_cm_m_s"].tolist()) == {7.0}
    assert t[t["input_row"] == 3]["status"].tolist() == ["no_orbit"]


def test_a_result_csv_fed_back_reads_as_before(tmp_path):
    out = deathsphere.orbit(60, com_speed=7, stability=False)
    path = tmp_path / "out.csv"
    out.to_csv(path)
    back = deathsphere.orbit_input(path, stability=False).table()
    np.testing.assert_allclose(back["alpha_deg"], out["alpha_deg"])
    np.testing.assert_allclose(back["v_cm_m_s"], out["v_cm_m_s"], rtol=1e-12)
    assert set(back["status"]) == {"ok"}
    # a file without alpha_deg: v_cm_m_s is the centre's speed
    (tmp_path / "v.csv").write_text("theta_deg,v_cm_m_s\n60,7\n")
    again = deathsphere.orbit_input(tmp_path / "v.csv", stability=False).table()
    np.testing.assert_allclose(sorted(again["alpha_deg"]), sorted(out["alpha_deg"]))


def test_simulate_a_wheel_by_its_contact_speed_or_its_centre_speed():
    _, contact = deathsphere.simulate(60, speed=7, periods=0.1, points_per_period=10)
    omega = float(contact["omega_rad_s"][0])
    assert omega * R * math.sin(math.radians(60)) == pytest.approx(7.0, rel=1e-9)
    assert eq29_residual(60.0, float(contact["alpha_deg"][0]), omega) == pytest.approx(0.0, abs=1e-9)
    _, centre = deathsphere.simulate(60, com_speed=7, periods=0.1, points_per_period=10)
    assert float(centre["speed_m_s"][0]) == 7.0
    assert float(centre["alpha_deg"][0]) != pytest.approx(float(contact["alpha_deg"][0]), abs=1e-3)
    with pytest.raises(deathsphere.ParameterError, match="vertical axis"):
        deathsphere.simulate(0, speed=7, periods=0.1)


def test_simulate_refuses_a_second_hold(run):
    res = run("simulate", "--theta", "60", "--speed", "7", "--com-speed", "7")
    assert res.exit_code == 2 and res.stderr.count("\n") == 1 and "error: --com-speed: give one of" in res.stderr
