"""Simulating a machine (docs/machine.md sec. 5, eqs. M16-M19;
docs/simulation.md "Bodies"): the paper's wheel as a machine runs the
wheel's simulation, and ``stunt125``'s orbits behave as ``ride``'s
stability says."""

import math
import numpy as np
import pytest

import deathsphere
from deathsphere import ParameterError
from deathsphere.simulation import SERIES_COLUMNS, SUMMARY_COLUMNS

#: the wheel's own series columns that a machine's share (input_row and
#: t_s compared apart, the rest to round-off of two different codings of
#: the same equations)
SHARED = SERIES_COLUMNS[2:]


@pytest.mark.parametrize("theta, alpha, perturb", [(60, 10, 3.0), (60, 10, 0.0), (120, 30, 0.5)])
def test_the_papers_wheel_as_a_machine_is_the_wheels_simulation(theta, alpha, perturb):
    """Same equations (docs/machine.md sec. 5 derives the paper's wheel as a
    special case), same start, same kick: over a lap the series agree to
    ~1e-12 (measured; asserted 5e-10 of each column's scale, half the 1e-9
    two laps would be held to, so that a difference growing with time is
    caught as over two), not merely to the integrator's tolerance."""
    run = dict(r=3.0, perturb=perturb, periods=1, points_per_period=10)
    wheel, wsum = deathsphere.simulate(theta, alpha, a=0.3, k=0.5, **run)
    machine, msum = deathsphere.simulate(theta, alpha, machine="paper-wheel", **run)
    assert list(machine.names) == list(SERIES_COLUMNS) + ["v_cm_m_s", "head_clearance_m"]
    assert len(machine) == len(wheel) and str(msum["status"][0]) == str(wsum["status"][0]) == "completed"
    # eq. M8 and eq. 29 are different formulas for the same Omega: the
    # period, hence the time grid, may differ in the last bit
    np.testing.assert_allclose(machine["t_s"], wheel["t_s"], rtol=1e-14)
    for name in SHARED:
        x, y = np.asarray(machine[name], float), np.asarray(wheel[name], float)
        scale = max(np.max(np.abs(y)), 1e-3)
        assert np.max(np.abs(x - y)) < 5e-10 * scale, name
    # the paper's wheel's centre of mass is its hub, and its "head" too
    np.testing.assert_allclose(machine["v_cm_m_s"], wheel["speed_m_s"], rtol=1e-12)
    for name in ("omega_rad_s", "speed_m_s", "period_s", "theta_deg", "alpha_deg", "perturb_deg"):
        assert float(msum[name][0]) == pytest.approx(float(wsum[name][0]), rel=1e-12), name


def test_the_papers_wheel_as_a_machine_loses_contact_when_the_wheel_does():
    """The steep equator orbit (90, 80), kicked: contact lost at the same
    time and place (the events read the machine's contact force, eq. M18)."""
    run = dict(r=3.0, perturb=1e-3, periods=2, points_per_period=10)
    _, wsum = deathsphere.simulate(90, 80, a=0.3, k=0.5, **run)
    _, msum = deathsphere.simulate(90, 80, machine="paper-wheel", **run)
    assert str(msum["status"][0]) == str(wsum["status"][0]) == "contact_lost"
    assert float(msum["event_time_s"][0]) == pytest.approx(float(wsum["event_time_s"][0]), abs=1e-9)
    assert float(msum["event_alpha_deg"][0]) == pytest.approx(float(wsum["event_alpha_deg"][0]), abs=1e-7)


def _deviation(series, theta, alpha):
    t = np.asarray(series["t_s"])
    d_theta = np.radians(np.asarray(series["theta_deg"]) - theta)
    d_alpha = np.radians(np.asarray(series["alpha_deg"]) - alpha)
    return t, np.hypot(d_theta, d_alpha)


def test_an_unstable_stunt125_orbit_grows_at_rides_growth_rate():
    """The equator of a 16-ft globe at alpha = 10 deg (docs/machine.md sec.
    5): ride says unstable at 3.62 /s (a capsize: a real pair); the
    simulated tilt kick grows by orders of magnitude, at that rate."""
    ride = deathsphere.ride(90, 10, machine="stunt125", diameter="16ft", stability=True)
    assert str(ride["stability"]) == "unstable"
    series, summary = deathsphere.simulate(90, 10, machine="stunt125", diameter="16ft", perturb=1e-6, periods=2,
                                           points_per_period=40)
    t, dev = _deviation(series, 90, 10)
    assert dev[-1] > 1e4 * dev[0]
    late = t > t[-1] / 2
    rate = np.polyfit(t[late], np.log(dev[late]), 1)[0]
    assert rate == pytest.approx(float(ride["growth_rate_1_s"]), rel=0.02)
    assert list(summary.names) == list(SUMMARY_COLUMNS) + ["machine", "min_head_clearance_m"]
    assert str(summary["machine"][0]) == "stunt125" and str(summary["body"][0]) == "machine"


def test_a_stable_stunt125_orbit_stays_bounded():
    """High on the wall (theta 20, alpha -10.34 deg): ride says stable, its
    slow nutation 12.1 rad/s (a 0.52-s period, 3 orbit periods); over
    three nutations the tilt kick's deviation does not grow."""
    ride = deathsphere.ride(20, -10.34, machine="stunt125", diameter="16ft", stability=True)
    assert str(ride["stability"]) == "stable"
    series, summary = deathsphere.simulate(20, -10.34, machine="stunt125", diameter="16ft", perturb=1e-4,
                                           periods=12, points_per_period=20)
    assert str(summary["status"][0]) == "completed"
    t, dev = _deviation(series, 20, -10.34)
    first = t <= t[-1] / 2
    assert dev[~first].max() < 1.1 * dev[first].max()
    assert dev.max() < 1e-3
    # the head, 1.6 m up the machine, swings with the nutation's tilt
    lever = 1.65
    assert abs(float(summary["min_head_clearance_m"][0]) - float(ride["head_clearance_m"])) < lever * dev.max()


def test_a_machine_given_its_centre_speed_rides_that_speed():
    """simulate's com_speed is the centre of mass's (ride's com_speed): the
    tilt is ride's for it (eq. M12), and the simulated v_cm holds it on the
    steady orbit."""
    v = 30 / 3.6
    ride = deathsphere.ride(60, com_speed=v, machine="stunt125", diameter="16ft", stability=False)
    series, summary = deathsphere.simulate(60, machine="stunt125", com_speed=v, diameter="16ft", periods=0.5,
                                           points_per_period=10)
    assert float(summary["alpha_deg"][0]) == pytest.approx(float(np.min(ride["alpha_deg"])), abs=1e-12)
    np.testing.assert_allclose(series["v_cm_m_s"], v, rtol=1e-9)
    np.testing.assert_allclose(series["head_clearance_m"], float(ride["head_clearance_m"][0]), rtol=1e-9)
    assert float(summary["speed_m_s"][0]) == pytest.approx(v, rel=1e-12)


def test_a_machine_given_its_contact_speed_rides_that_speed():
    """simulate's speed is the contact's along the ground, as ride's: the
    tilt is ride's for it, and the contact, on the parallel of radius
    r sin(theta), runs at it: Omega r sin(theta) = v."""
    v, r = 30 / 3.6, 16 * 0.3048 / 2
    ride = deathsphere.ride(60, speed=v, machine="stunt125", diameter="16ft", stability=False)
    series, summary = deathsphere.simulate(60, machine="stunt125", speed=v, diameter="16ft", periods=0.5,
                                           points_per_period=10)
    assert float(summary["alpha_deg"][0]) == pytest.approx(float(np.min(ride["alpha_deg"])), abs=1e-12)
    assert float(summary["omega_rad_s"][0]) * r * math.sin(math.radians(60)) == pytest.approx(v, rel=1e-9)


@pytest.mark.parametrize("extra, words", [
    ({"k": 0.4}, "k not allowed"),
    ({"body": "sphere"}, "body not allowed"),
    ({"a": 0.2}, "a not allowed"),
    ({"side": "outside"}, "side='outside' not allowed"),
    ({"vertical": True, "v_top": 9.0}, "vertical loops of a machine are not simulated"),
])
def test_a_machine_refuses_the_papers_body_options(extra, words):
    with pytest.raises(ParameterError) as exc:
        deathsphere.simulate(60, 10, machine="stunt125", **extra)
    message = str(exc.value)
    assert words in message and "\n" not in message


def test_a_machine_that_does_not_fit_is_not_integrated():
    """The head hits the globe (status no_fit with ride's reason)."""
    series, summary = deathsphere.simulate(40, 60, machine="stunt125", diameter="16ft", periods=1)
    ride = deathsphere.ride(40, 60, machine="stunt125", diameter="16ft", stability=False)
    assert str(ride["status"]) == "no_fit"
    assert str(summary["status"][0]) == "no_fit" and str(summary["reason"][0]) == str(ride["reason"])
    assert len(series) == 0


def test_a_fall_from_an_unstable_orbit_says_why():
    """A kicked machine on an orbit its linearisation calls unstable
    (equator of a 16-ft globe, alpha = 10 deg: a capsize at 3.62 /s) slips
    within a second; the summary's reason says the orbit is unstable, with
    ride's growth rate, and that a rider steers.  A stable orbit's reason
    says no such thing."""
    ride = deathsphere.ride(90, 10, machine="stunt125", diameter="16ft", stability=True)
    _, summary = deathsphere.simulate(90, 10, machine="stunt125", diameter="16ft", perturb=0.05, mu=0.4,
                                      periods=3, points_per_period=20)
    reason = str(summary["reason"][0])
    assert str(summary["status"][0]) == "slips"
    assert "unstable" in reason and "steer" in reason
    assert f"growth rate {float(ride['growth_rate_1_s']):.3g} /s" in reason
    assert "," not in reason and "\n" not in reason
    _, calm = deathsphere.simulate(20, -10.34, machine="stunt125", diameter="16ft", perturb=0.01, mu=0.05,
                                   periods=1, points_per_period=20)
    assert str(calm["status"][0]) == "slips" and "unstable" not in str(calm["reason"][0])


def test_a_point_mass_machine_rides_but_has_no_equations_of_motion():
    """The point-mass limit (no yaw inertia, no spinning wheels): its steady
    orbits are eq. M8's, its yaw is undetermined, so ride leaves the
    stability empty and says why, and simulate refuses it before any work."""
    m = deathsphere.Machine(mass=100, h=0.8, a=0.3)
    row = deathsphere.ride(90, 20, machine=m, r=3.0)
    assert str(row["status"]) == "ok" and row[0]["stability"] is None
    assert row["stability_method"] == "not-analysed-point-mass"
    with pytest.raises(deathsphere.ParameterError, match="yaw inertia"):
        deathsphere.simulate(90, 20, machine=m, r=3.0)
