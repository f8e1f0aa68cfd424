"""Frame geometry of the 3-D view (deathsphere.viewer.frames) against the
physics: every drawn quantity comes from the simulated state."""

import numpy as np
import pytest
from viewer_cases import CASES, central_difference, evenly_spaced, norm, run_case

from deathsphere import simulation as sim
from deathsphere.model import Setup
from deathsphere.physics import dynamics as dyn
from deathsphere.physics import wheel
from deathsphere.simulation.frames import frame_geometry


@pytest.mark.parametrize("name", sorted(CASES))
def test_contact_point_is_on_the_sphere_and_rolls(name):
    series, summary, states, p = run_case(name, seconds=0.5, dt=4e-4)
    t, y = states["t_s"], states["state"]
    geo = frame_geometry(t, y, p)
    assert np.allclose(geo["contact"], geo["centre"] + p.a * geo["e3"], rtol=0, atol=1e-12)
    assert np.allclose(norm(geo["contact"]), p.r, rtol=1e-9)
    assert np.allclose(norm(geo["e3"]), 1.0) and np.allclose(norm(geo["axis"]), 1.0)
    if t.size < 3:          # lost contact at once: nothing moves
        return
    # rolling: the body's material point at the contact has no velocity,
    # dc/dt + w x (p - c) = 0, with dc/dt from the frames themselves
    w = y[dyn.W][:, 1:-1]
    v_c = central_difference(geo["centre"], t)
    slip = v_c + np.cross(w, (geo["contact"] - geo["centre"])[:, 1:-1], axis=0)
    even = evenly_spaced(t)
    assert np.max(norm(slip)[even]) < 1e-4 * np.max(norm(v_c))


@pytest.mark.parametrize("name", ["wheel_inside", "wheel_kicked", "wheel_outside", "vertical", "sphere_inside"])
def test_the_marked_spoke_turns_with_the_body(name):
    """A body-fixed vector s obeys ds/dt = w x s: the spoke (wheel: the
    integrated spin angle; sphere: the state's marker) must."""
    _, _, states, p = run_case(name, seconds=0.5, dt=4e-4)
    t, y = states["t_s"], states["state"]
    spoke = frame_geometry(t, y, p)["spoke"]
    ds = central_difference(spoke, t)
    expected = np.cross(y[dyn.W][:, 1:-1], spoke[:, 1:-1], axis=0)
    # a sphere's marker is kept out of the integrator's error control
    # (docs/simulation.md), so it holds to ~1e-3 only; a wheel's spoke is
    # integrated here from controlled quantities
    bound = 5e-3 if p.sphere else 1e-4
    assert np.max(norm(ds - expected)[evenly_spaced(t)]) < bound * np.max(norm(expected))
    assert np.allclose(norm(spoke), 1.0)


def test_steady_orbit_keeps_the_papers_tilt_and_loads():
    """Table 1 (theta 60, alpha 10): axle and contact direction of eq. (11)
    at every frame, the g-load of eq. (36), mu required 1.19 (eq. 35)."""
    series, summary, states, p = run_case("wheel_inside", periods=2, points_per_period=50)
    geo = frame_geometry(states["t_s"], states["state"], p)
    th, al = np.deg2rad(60.0), np.deg2rad(10.0)
    rhat = geo["contact"] * np.array([1, 1, 0])[:, None]
    rhat /= norm(rhat)
    z = np.array([0.0, 0.0, 1.0])[:, None]
    assert np.allclose(geo["axis"], -np.sin(al) * rhat - np.cos(al) * z, atol=1e-9)
    assert np.allclose(geo["e3"], np.cos(al) * rhat - np.sin(al) * z, atol=1e-9)
    assert np.allclose(np.arccos(geo["contact"][2] / p.r), th, atol=1e-9)
    orbit = wheel.horizontal_orbit(th, al, p.a, p.r, p.k, p.g)
    assert np.allclose(geo["accel_g"], orbit["accel_g"], rtol=1e-9)
    # the readout is the load the rider feels, the orbit's load_g (|F| / (m g)), not eq. 36
    assert np.allclose(geo["load_g"], orbit["load_g"], rtol=1e-9)
    assert np.all(geo["load_g"] > geo["accel_g"])
    assert np.allclose(series["mu_required"], 1.19, atol=5e-3)
    # the spin rate is constant on a steady orbit: the angle grows linearly
    rate = np.diff(geo["spin"]) / np.diff(states["t_s"])
    assert np.allclose(rate, rate[0], rtol=1e-9) and abs(rate[0]) > 1.0


@pytest.mark.parametrize("name", ["wheel_kicked", "sphere_inside", "vertical", "wheel_outside"])
def test_force_arrows_add_up_to_the_simulated_contact_force(name):
    series, _, states, p = run_case(name, periods=0.5)
    geo = frame_geometry(states["t_s"], states["state"], p)
    total = geo["normal_force"] + geo["friction_force"]
    assert np.allclose(total, geo["force"], rtol=0, atol=1e-12 * np.max(norm(geo["force"])))
    n_hat = geo["contact"] / norm(geo["contact"])
    # the normal part lies along the contact normal, the friction across it
    assert np.allclose(np.sum(geo["friction_force"] * n_hat, axis=0), 0.0, atol=1e-9)
    side = -1.0 if not p.outside else 1.0
    assert np.allclose(side * np.sum(geo["normal_force"] * n_hat, axis=0), series["normal_per_mass_m_s2"],
                       rtol=1e-9, atol=1e-9)
    assert np.allclose(norm(geo["friction_force"]), series["friction_magnitude_per_mass_m_s2"], rtol=1e-9, atol=1e-9)
    # F/m = d2c/dt2 + g z (eq. 2)
    assert np.allclose(geo["acceleration"] + p.g * np.array([0, 0, 1.0])[:, None], geo["force"])


def test_recorded_states_are_lab_states_and_change_nothing_else():
    starts = sim.horizontal_starts(Setup(), 60, 10, perturb_deg=3.0)
    plain, plain_summary = sim.Simulation(starts, periods=0.5, points_per_period=20).run()
    runs = {}
    for frame in ("turning", "lab"):
        s = sim.Simulation(starts, periods=0.5, points_per_period=20, frame=frame, record_states=True)
        series, summary = s.run()
        runs[frame] = (series, s.sample_states())
    series, states = runs["turning"]
    for name in sim.SERIES_COLUMNS:                    # the public columns are untouched
        assert np.array_equal(series[name], plain[name]), name
    assert list(series.names) == list(sim.SERIES_COLUMNS)
    assert np.array_equal(states["t_s"], series["t_s"])
    # integrated in the turning frame, handed out in lab components
    assert np.allclose(states["state"], runs["lab"][1]["state"], atol=1e-7)
    unrecorded = sim.Simulation(starts, periods=0.1)
    unrecorded.run()
    with pytest.raises(RuntimeError, match="record_states"):
        unrecorded.sample_states()
