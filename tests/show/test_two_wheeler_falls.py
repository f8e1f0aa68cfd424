"""A show's two-wheeler rider who loses speed on the wall of death's drum
(docs/show.md sec. 13, "A two-wheeler's fall"): whether a steady turn still
holds it against ride --steer's own turns, its centre of mass's flight
against a parabola solved here to the drum's wall or floor, and the Monte
Carlo drawing its falls."""

import math
import tomllib

import numpy as np
import pytest

import deathsphere
from deathsphere.act.falls import simulate_falls
from deathsphere.physics.fall import OUTCOMES

G = 9.80665
FT = 0.3048
R = 16 * FT                     # a 32-foot drum: the wall rho = R, the floor z = 0
HEIGHT = "6ft"
T_FAIL = 0.3


#: A two-wheeler at 6 ft, 45 km/h and a machine above it on the other side, on the drum.
PLAN = f"""[arena]
surface = "cylinder"
diameter = "32ft"
wall_height = "12ft"
mu = 0.8
max_g = 6

[[rider]]
name = "Ana"
machine = "stunt125-steer"
width = "0.6m"
lane = "horizontal"
height = "{HEIGHT}"
speed = "45km/h"

[[rider]]
name = "Cal"
machine = "stunt125"
width = "0.7m"
lane = "horizontal"
height = "9ft"
speed = "40mph"
phase = 180
"""


def _plan():
    return tomllib.loads(PLAN)


@pytest.fixture(scope="module")
def act():
    """A two-wheeler at 6 ft, 45 km/h and a machine above it, on the drum."""
    return deathsphere.show(_plan())


def _ana(act):
    return act.lanes[0]


def test_at_its_full_speed_a_two_wheeler_rides_on(act):
    row = act.fall("Ana", T_FAIL, 1.0)[0]
    assert row["outcome"] == "rides_on"
    assert row["fall_time_s"] is None and row["victim"] == "Cal"
    # at every time of the lap
    t = np.linspace(0.0, _ana(act).period_s, 7)
    res = simulate_falls(act.lanes, act.plan.globe, np.zeros(t.size, int), t, np.ones(t.size))
    assert (res["outcome"] == OUTCOMES.index("rides_on")).all()


def _parabola_to_the_drum(x0, v0):
    """The first positive time the point x0 + v0 s - g s^2/2 z-hat meets the
    floor z = 0 (a quadratic in s) or the wall rho = R (the horizontal
    motion is a line: |p + u s|^2 = R^2, another quadratic), and where."""
    floor = np.roots([-0.5 * G, v0[2], x0[2]])
    wall = np.roots([v0[0] ** 2 + v0[1] ** 2, 2 * (x0[0] * v0[0] + x0[1] * v0[1]),
                     x0[0] ** 2 + x0[1] ** 2 - R * R])
    s = min(float(r.real) for r in np.concatenate((floor, wall)) if abs(r.imag) < 1e-12 and r.real > 0)
    return s, x0 + v0 * s - 0.5 * G * s * s * np.array([0.0, 0.0, 1.0])


@pytest.mark.parametrize("fraction, lands_on", [(0.01, "floor"), (0.5, "wall")])
def test_a_two_wheeler_that_falls_flies_its_centre_of_mass_to_the_drum(act, fraction, lands_on):
    row = act.fall("Ana", T_FAIL, fraction)[0]
    assert row["outcome"] == "falls" and row["t_contact_lost_s"] == T_FAIL
    kin = _ana(act).kinematics(np.array([T_FAIL]))
    x0, v = kin["com"][:, 0], kin["v_com"][:, 0]
    # the centre of mass turns with the whole machine at the lane's rate: its speed is ride's v_cm
    assert np.linalg.norm(v) == pytest.approx(act.riders[0]["v_cm_m_s"], rel=1e-9)
    assert abs(v[2]) < 1e-12 and abs(v[:2] @ x0[:2]) < 1e-9 * np.linalg.norm(v)
    s, x1 = _parabola_to_the_drum(x0, fraction * v)
    assert row["fall_time_s"] == pytest.approx(s, rel=1e-9)
    assert row["t_land_s"] == pytest.approx(T_FAIL + s, rel=1e-9)
    assert row["phi_land_deg"] == pytest.approx(math.degrees(math.atan2(x1[1], x1[0])) % 360.0, abs=1e-7)
    assert row["height_land_m"] == pytest.approx(x1[2], abs=1e-9)
    assert (row["height_land_m"] == pytest.approx(0.0, abs=1e-9)) == (lands_on == "floor")
    impact = np.linalg.norm(fraction * v - G * s * np.array([0.0, 0.0, 1.0]))
    assert row["impact_speed_m_s"] == pytest.approx(impact, rel=1e-9)
    # contact is lost at the rear contact: on the lane's height as typed, at its azimuth
    contact = kin["contact"][:, 0]
    assert row["height_lost_m"] == pytest.approx(6 * FT, abs=1e-12)
    assert row["phi_lost_deg"] == pytest.approx(math.degrees(math.atan2(contact[1], contact[0])) % 360.0, abs=1e-9)
    # the 3-D view's flight is the same parabola
    path = act.fall_path("Ana", T_FAIL, fraction, 5)
    assert np.allclose(path["com"][:, 0], x0, atol=1e-12) and np.allclose(path["com"][:, -1], x1, atol=1e-9)


def _show_holds(act, fractions):
    """Whether Ana rides on after dropping to each fraction, one vectorised call."""
    f = np.asarray(fractions, dtype=float)
    res = simulate_falls(act.lanes, act.plan.globe, np.zeros(f.size, int), np.full(f.size, T_FAIL), f)
    return res["outcome"] != OUTCOMES.index("falls")


def _ride_holds(speeds):
    """Whether ride --steer (its API) finds an ok steady turn at Ana's height at each rear speed, friction
    only (max_g unlimited, as a fall's test)."""
    table = deathsphere.ride(machine="stunt125-steer", steer="free", stability=False, mu=0.8, max_g=math.inf,
                             surface="cylinder", diameter="32ft", wall_height="12ft", height=HEIGHT,
                             speed=[float(v) for v in speeds])
    ok = np.zeros(len(speeds), bool)
    for row in table:                   # every turn found at a speed is a row of its input row (from 1)
        ok[row["input_row"] - 1] |= row["status"] == "ok"
    return ok


def _least(holds, lo, hi, rounds=2, n=1000):
    """The least value in [lo, hi] where holds(values) is true, to (hi - lo) / (n - 1)^rounds: sections
    of n values (holds is false below it and true above)."""
    for _ in range(rounds):
        x = np.linspace(lo, hi, n)
        ok = holds(x)
        k = int(np.argmax(ok))
        assert ok[k] and not ok[0] and ok[k:].all()
        lo, hi = x[k - 1], x[k]
    return hi


def test_the_ride_on_threshold_is_rides_least_speed_of_an_ok_turn_at_that_height(act):
    v_rear = act.riders[0]["v_contact_m_s"]
    threshold = _least(lambda f: _show_holds(act, f), 0.0, 1.0)
    least_speed = _least(_ride_holds, 0.05 * v_rear, v_rear)
    assert 0.1 < threshold < 0.95
    assert threshold == pytest.approx(least_speed / v_rear, abs=1e-6)


def test_a_monte_carlo_draws_the_two_wheelers_falls_the_same_for_one_seed(act):
    one, summary = act.falls(150, seed=7)
    two, _ = act.falls(150, seed=7)
    for col in one.names:
        a, b = np.asarray(one[col]), np.asarray(two[col])
        if a.dtype.kind == "f":
            assert np.array_equal(a, b, equal_nan=True), col
        else:
            assert list(a) == list(b), col
    ana = np.asarray(one["rider"]) == "Ana"
    outcome = np.asarray(one["outcome"])
    assert set(outcome[ana]) == {"falls", "rides_on"}
    # a two-wheeler's draw is one of its single falls
    i = int(np.flatnonzero(ana & (outcome == "falls"))[0])
    single = act.fall("Ana", float(one["t_fail_s"][i]), float(one["speed_fraction"][i]))[0]
    assert single["height_land_m"] == pytest.approx(float(one["height_land_m"][i]), abs=1e-12)
    assert single["fall_time_s"] == pytest.approx(float(one["fall_time_s"][i]), rel=1e-12)
    assert "Ana" in set(summary["rider"])


def test_the_3d_view_draws_a_two_wheelers_flight(act):
    from deathsphere.viewer.show_scene import act_scene

    scene = act_scene(act, act.fall("Ana", T_FAIL, 0.5))
    ana, = [track for track in scene.tracks if track.name == "Ana"]
    _, path = ana.paths["fall"]
    kin = _ana(act).kinematics(np.array([T_FAIL]))
    s, x1 = _parabola_to_the_drum(kin["com"][:, 0], 0.5 * kin["v_com"][:, 0])
    assert path[:, 0] == pytest.approx(kin["com"][:, 0], abs=1e-12) and path[:, -1] == pytest.approx(x1, abs=1e-9)
    # the envelope's five segments give way to the centre of mass at contact lost
    capsules = [item for item in ana.draw if item["kind"] == "capsule"]
    assert len(capsules) == 5 and all(item["until"] == T_FAIL for item in capsules)
