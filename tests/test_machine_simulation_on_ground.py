"""``simulate --machine`` on the drum, the cone and a profile (docs/machine.md,
"On any ground" and "On a profile"), through the API's own path (simulation_request ->
prepare_simulation).  From the recorded states:

* the tyre's gap to the wall by the ground's own distance function: the
  least clearance over the crown circle (a search round the circle, not
  the equations' Newton step for the crown point) less the tyre radius;
* the energy (the machine's energy function, the globe's) against the
  kinetic energy: a run that conserves it to 1e-9 of the kinetic energy
  over three laps, after a kick that moved it.
"""

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from deathsphere.api.simulation import prepare_simulation, simulation_request
from deathsphere.errors import ParameterError
from deathsphere.physics import machine_motion as mm
from deathsphere.physics.ground import Profile

#: lanes that `ride` calls stable with the steering locked, kicked a little: nothing holds a lane's height
#: on a wall (every height has a lane at the same tilt and rate), so a kick drifts it and a large one falls
#: to the floor.  Three laps on the drum and in the bowl (the slow tests here: the step is capped by the
#: wheels' spin), half a lap in the well.
CASES = {
    "drum": dict(surface="cylinder", diameter="32ft", height=1.5, alpha=8.5, periods=3),
    "well": dict(surface="cone", wall_angle=80, diameter="32ft", height=1.5, alpha=11.0, periods=0.5),
    # a profile: a bowl of radius 3 m sampled every 0.98 deg, three laps of a lane ride calls stable (the
    # crown point on the meridian moved a tyre radius along its normal, docs/machine.md "On a profile"):
    # measured, the energy holds to 2e-15 of the kinetic energy and the tyre's gap (by the profile's own
    # distance function round the crown circle) stays below 3e-15 m
    "profile": dict(surface="profile", height=2.96, alpha=14.0, periods=3,
                    profile=Profile(3.0 * np.sin(np.linspace(np.pi, 0.35 * np.pi, 121)),
                                    3.0 + 3.0 * np.cos(np.linspace(np.pi, 0.35 * np.pi, 121)))),
}


def _run(**typed):
    sim = prepare_simulation(*simulation_request({"record_states": True, "points_per_period": 4,
                                                  "machine": "stunt125", **typed}))
    series, summary = sim.run()
    return series, summary, sim.sample_states()["state"], sim.starts.params


def _tyre_gap(ground, C, E, a, t):
    """The least clearance of the crown circle (centre C, radius a - t, normal E) less t."""
    e1 = E / np.linalg.norm(E)
    u = np.cross(e1, [0.0, 0.0, 1.0])
    u /= np.linalg.norm(u)
    v = np.cross(e1, u)

    def clearance(phi):
        x = C + (a - t) * (np.cos(phi) * u + np.sin(phi) * v)
        return float(ground.clearance(np.hypot(x[0], x[1]), x[2]))

    grid = np.linspace(0.0, 2 * np.pi, 721)
    ring = C[:, None] + (a - t) * (np.cos(grid) * u[:, None] + np.sin(grid) * v[:, None])
    best = grid[np.argmin(ground.clearance(np.hypot(ring[0], ring[1]), ring[2]))]
    found = minimize_scalar(clearance, bracket=(best - 0.01, best, best + 0.01), tol=1e-12)
    return found.fun - t


@pytest.mark.parametrize("name", list(CASES))
def test_energy_and_contact_hold_over_the_laps(name):
    series, summary, states, params = _run(rtol=1e-12, perturb=1e-4, **CASES[name])
    assert summary["status"][0] == "completed" and summary["periods_simulated"][0] == CASES[name]["periods"]
    m = params.machine
    a, t = float(m.wheel_radius[0]), float(m.tyre_radius[0])
    gaps = [_tyre_gap(params.ground, states[0:3, j], states[3:6, j], a, t) for j in range(states.shape[1])]
    assert np.max(np.abs(gaps)) < 1e-9
    mp = m.map(lambda x: np.broadcast_to(x[:1], (states.shape[1],)))
    energy, kinetic = mm.machine_energy(states, params.g[0], mp, params.geometry((states.shape[1],)))
    assert np.max(np.abs(energy - energy[0])) < 1e-9 * np.min(kinetic)
    # the kick moved it: the run is not a fixed point's
    assert np.ptp(np.asarray(series["height_m"], dtype=float)) > 1e-4
    assert summary["surface"][0] == CASES[name]["surface"] and np.isnan(summary["theta_deg"][0])


def test_an_unkicked_stable_lane_is_held():
    series, summary, _, _ = _run(rtol=1e-12, **{**CASES["drum"], "periods": 0.25})
    assert summary["status"][0] == "completed"
    assert float(summary["max_height_drift_m"][0]) < 1e-9


@pytest.mark.parametrize(("extra", "param"), [
    (dict(surface="cylinder", diameter="32ft", height=1.5, alpha=10, com_speed=20.0), "com_speed"),
    (dict(surface="cylinder", diameter="32ft", height=1.5, com_speed=1.0), "com_speed"),
    (dict(surface="cylinder", diameter="32ft", height=1.5, com_speed=20.0, branch=5), "branch"),
    (dict(surface="cylinder", diameter="32ft", height=1.5), "alpha"),
    (dict(surface="cylinder", diameter="32ft", height=1.5, alpha=10, body="sphere"), "machine"),
])
def test_what_a_machine_off_the_globe_does_not_take_is_refused_naming_it(extra, param):
    with pytest.raises(ParameterError) as err:
        simulation_request({"machine": "stunt125", **extra})
    assert err.value.param == param and "\n" not in str(err.value)


def test_the_3d_views_frames_put_the_tyre_on_the_wall():
    from deathsphere.simulation.frames import body_frames

    sim = prepare_simulation(*simulation_request({"record_states": True, "points_per_period": 8, "machine": "stunt125",
                                                  "periods": 0.1, **{k: v for k, v in CASES["drum"].items()
                                                                     if k != "periods"}}))
    _, summary = sim.run()
    (frames,) = body_frames(summary, sim.sample_states(), refine=False, params=sim.starts.params).values()
    P, C = frames["contact"], frames["centre"]
    radius = 16 * 0.3048
    np.testing.assert_allclose(np.hypot(P[0], P[1]), radius, rtol=0, atol=1e-9)      # the contact on the drum
    assert np.all(np.hypot(C[0], C[1]) < radius - 0.1)                                # the wheel centre inside


@pytest.mark.parametrize("held", ["com_speed", "speed"])
def test_a_speed_starts_on_the_tilt_ride_gives(held):
    """By the centre of mass's speed or the contact's, as ride lists the tilts (branch 0: the least)."""
    import deathsphere

    lane = dict(surface="cylinder", diameter="32ft", height=1.5)
    table = deathsphere.ride(machine="stunt125", **lane, **{held: "40km/h"}, stability=False)
    series, summary, _, _ = _run(periods=0.02, **lane, **{held: "40km/h"})
    assert summary["alpha_deg"][0] == pytest.approx(float(np.min(table["alpha_deg"])), rel=1e-12)
    assert summary["speed_m_s"][0] == pytest.approx(float(table["v_cm_m_s"][np.argmin(table["alpha_deg"])]),
                                                    rel=1e-9)


def test_the_3d_views_frames_put_the_tyre_on_a_profile():
    from deathsphere.simulation.frames import body_frames

    lane = {k: v for k, v in CASES["profile"].items() if k != "periods"}
    sim = prepare_simulation(*simulation_request({"record_states": True, "points_per_period": 8, "machine": "stunt125",
                                                  "periods": 0.1, **lane}))
    _, summary = sim.run()
    (frames,) = body_frames(summary, sim.sample_states(), refine=False, params=sim.starts.params).values()
    P, C = frames["contact"], frames["centre"]
    profile = lane["profile"]
    # the contact on the profile by its own distance function, the wheel centre inside it
    np.testing.assert_allclose(profile.clearance(np.hypot(P[0], P[1]), P[2]), 0.0, rtol=0, atol=1e-9)
    assert np.all(profile.clearance(np.hypot(C[0], C[1]), C[2]) > 0.1)
