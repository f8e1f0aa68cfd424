"""A machine's records as arrays (physics.machine_arrays), eq. M2's points
(physics.machine.meridian_points) and the lane a rider takes at a speed
(physics.machine_lanes), against ride's own rows."""

import math

import numpy as np
import pytest

import deathsphere
from deathsphere.physics.ground import Sphere
from deathsphere.physics.machine import meridian_points, ride_orbit
from deathsphere.physics.machine_arrays import FIELDS, MachineArrays, machine_arrays
from deathsphere.physics.machine_lanes import horizontal_lanes, speed_is_feasible
from deathsphere.physics.status import Reason, Status
from deathsphere.records.machine_presets import benchmark_bicycle_rigid, stunt125

G = 9.80665
GLOBE = Sphere(2.4384)


def test_records_become_arrays_in_one_place():
    one = machine_arrays(stunt125())
    assert isinstance(one, MachineArrays) and all(np.ndim(x) == 0 for x in one)
    assert one.com_height == 0.80 and one.pitch_inertia == 40.0 and one.head_height == 1.65
    two = machine_arrays([stunt125(), benchmark_bicycle_rigid()])
    assert all(np.shape(x) == (2,) and np.asarray(x).dtype == np.float64 for x in two)
    assert machine_arrays(two) is two
    assert two.take(1) == machine_arrays(benchmark_bicycle_rigid())
    assert FIELDS == MachineArrays._fields


def test_one_call_over_two_machines_is_each_machine_alone():
    theta, alpha = np.radians([100.0, 110.0]), np.radians([20.0, 15.0])
    both = ride_orbit(theta, alpha, GLOBE, G, machine_arrays([stunt125(), benchmark_bicycle_rigid()]), mu=0.9)
    for i, m in enumerate((stunt125(), benchmark_bicycle_rigid())):
        alone = ride_orbit(theta[i], alpha[i], GLOBE, G, machine_arrays(m), mu=0.9)
        for key, val in alone.items():
            np.testing.assert_array_equal(both[key][i], val, err_msg=key)


def test_the_head_of_eq_m2_is_rides_head_clearance():
    theta, alpha = np.radians(np.linspace(60, 170, 12)), np.radians(np.linspace(-10, 50, 12))
    m = machine_arrays(stunt125())
    hx, hz = meridian_points(theta, alpha, GLOBE, m)["head"]
    np.testing.assert_array_equal(GLOBE.radius - np.sqrt(hx * hx + hz * hz),
                                  ride_orbit(theta, alpha, GLOBE, G, m)["head_clearance"])
    cx, cz = meridian_points(theta, alpha, GLOBE, m)["contact"]
    np.testing.assert_allclose(np.hypot(cx, cz), GLOBE.radius, rtol=1e-15)


@pytest.mark.parametrize("height, kmh", [(1.4, 25.58), (2.0, 30.0), (2.7, 29.35), (0.6, 12.0), (4.5, 80.0)])
def test_the_lane_is_the_tilt_rides_table_would_choose(height, kmh):
    """Of ride's rows for the height and speed: the tilt closest to upright
    on the wall among the ok rows, else among those with an orbit."""
    rows = list(deathsphere.ride(height=height, com_speed=kmh / 3.6, machine="stunt125", r=GLOBE.radius, mu=0.9,
                                 max_g=8, stability=False))
    theta = GLOBE.theta(height)
    lane = horizontal_lanes([theta], [kmh / 3.6], GLOBE, G, machine_arrays(stunt125()), 0.9, 8.0)
    upright = math.degrees(theta) - 90
    ok = [r for r in rows if r["status"] == "ok"] or [r for r in rows if math.isfinite(r["omega_rad_s"])]
    if not ok:
        assert not lane["chosen"][0] and np.isnan(lane["alpha"][0])
        assert str(rows[0]["reason"]) == str(deathsphere.physics.status.REASON_TEXT[lane["reason"][0]])
        return
    best = min(ok, key=lambda r: abs(r["alpha_deg"] - upright))
    assert lane["chosen"][0]
    assert np.degrees(lane["alpha"][0]) == best["alpha_deg"]
    assert lane["period"][0] == best["period_s"] and lane["load_g"][0] == best["load_g"]
    assert str(deathsphere.physics.status.STATUS_LABELS[lane["status"][0]]) == best["status"]
    assert speed_is_feasible([theta], [kmh / 3.6], GLOBE, G, machine_arrays(stunt125()), 0.9, 8.0)[0] == (
        any(r["status"] == "ok" for r in rows))


def test_no_tilt_for_the_speed_is_no_orbit_and_a_tilt_without_contact_is_kept_with_its_status():
    # 0.3 m/s: at the equator no tilt gives it; above it a tilt does, hanging off the wall (no contact)
    lane = horizontal_lanes(np.radians([90.0, 60.0]), [0.3, 0.3], GLOBE, G, machine_arrays(stunt125()))
    assert lane["chosen"].tolist() == [False, True]
    assert lane["status"].tolist() == [Status.NO_ORBIT, Status.NO_CONTACT]
    assert lane["reason"][0] == Reason.MACHINE_NO_ALPHA
    assert np.isnan(lane["alpha"][0]) and np.isfinite(lane["alpha"][1]) and np.isfinite(lane["height"]).all()
