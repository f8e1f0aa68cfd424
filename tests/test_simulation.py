"""The simulator (the deathsphere.simulation package, docs/simulation.md).

Reference values are the paper's steady orbits (McDonald 1993 eqs. 29-36,
Table 1; eqs. 55-58 for a sphere), its vertical orbits (eqs. 26-28b, 82, as
generalised in deathsphere.physics.vertical_orbit), and the exact linear stability
of deathsphere.physics.stability.  The whole file runs in ~30 s on 2 cores.
"""

from __future__ import annotations

import sys

import numpy as np
import pytest

from deathsphere import simulation as sim
from deathsphere.model import Setup
from deathsphere.physics import dynamics as dyn
from deathsphere.physics import sphere as sph
from deathsphere.physics import vertical_orbit as vert
from deathsphere.physics import wheel
from deathsphere.physics.stability import wheel_stability
from deathsphere.render import figures as plot_module

TABLE1 = Setup()                 # wheel inside, a = 0.3 m, r = 3 m, k = 1/2, g = 9.80665
DEG = np.pi / 180


def run(starts, **options):
    return sim.run_simulation(starts, **options)


# --------------------------------------------------------------------------
# steady orbits


@pytest.fixture(scope="module")
def steady():
    """Table 1's orbit theta = 60, alpha = 10 deg for 20 periods (turning frame)."""
    return run(sim.horizontal_starts(TABLE1, 60.0, 10.0), periods=20, points_per_period=25)


def test_steady_table1_orbit_holds_for_20_periods(steady):
    series, summary = steady
    assert summary["status"][0] == "completed"
    assert summary["periods_simulated"][0] == pytest.approx(20.0, abs=1e-9)
    assert summary["max_theta_drift_deg"][0] * DEG < 1e-6
    assert summary["max_alpha_drift_deg"][0] * DEG < 1e-6
    # the series says the same, row by row
    assert np.max(np.abs(series["theta_deg"] - 60.0)) * DEG < 1e-6
    assert np.max(np.abs(series["alpha_deg"] - 10.0)) * DEG < 1e-6
    assert len(series) == 20 * 25 + 1
    # the contact point goes round 20 times at the rate of eq. (29)
    assert series["phi_deg"][-1] == pytest.approx(20 * 360.0, abs=1e-4)


def test_steady_run_conserves_energy_and_constraints(steady):
    series, summary = steady
    assert summary["max_abs_energy_drift"][0] < 1e-8
    assert summary["max_constraint_residual"][0] < 1e-8
    assert np.max(np.abs(series["energy_drift"])) < 1e-8
    assert np.max(series["constraint_residual"]) < 1e-8


def test_steady_forces_are_those_of_the_paper(steady):
    """Normal force, friction and mu along the run = eqs. (30)-(35) of the steady orbit."""
    series, _ = steady
    ref = wheel.horizontal_orbit(60 * DEG, 10 * DEG, TABLE1.a, TABLE1.r, TABLE1.k, TABLE1.g)
    for col, key in (("normal_per_mass_m_s2", "normal"), ("friction_magnitude_per_mass_m_s2", "friction"),
                     ("mu_required", "mu_required")):
        np.testing.assert_allclose(series[col], abs(float(ref[key])), rtol=1e-9)
    np.testing.assert_allclose(series["speed_m_s"], float(ref["v_cm"]), rtol=1e-9)
    assert float(ref["mu_required"]) == pytest.approx(1.19, abs=0.005)      # Table 1 prints 1.19


def test_steady_orbit_in_the_lab_frame():
    """The same orbit integrated in the lab frame (where it is a periodic orbit,
    not a fixed point) holds just as well."""
    series, summary = run(sim.horizontal_starts(TABLE1, 60.0, 10.0), periods=20, points_per_period=4,
                          frame="lab")
    assert summary["status"][0] == "completed"
    assert summary["max_theta_drift_deg"][0] * DEG < 1e-6
    assert summary["max_alpha_drift_deg"][0] * DEG < 1e-6
    assert summary["max_abs_energy_drift"][0] < 1e-8
    assert summary["max_constraint_residual"][0] < 1e-8
    assert series["phi_deg"][-1] == pytest.approx(20 * 360.0, abs=1e-4)


def test_steady_sphere_orbit_holds():
    """A ball inside, theta = 120 deg, omega3 = 10 rad/s, both roots of eq. (55)."""
    s = Setup(body="sphere")
    starts = sim.horizontal_starts(s, 120.0, omega3=10.0, branch=np.array([0, 1]))
    series, summary = run(starts, periods=5, points_per_period=10)
    ref = sph.sphere_orbit(120 * DEG, 10.0, s.a, s.r, s.k, s.g)
    assert list(summary["status"]) == ["completed", "completed"]
    np.testing.assert_allclose(summary["omega_rad_s"], ref["omega"], rtol=1e-12)
    assert np.all(summary["max_theta_drift_deg"] * DEG < 1e-6)
    np.testing.assert_allclose(summary["min_normal_per_mass_m_s2"], ref["normal"], rtol=1e-7)
    np.testing.assert_allclose(summary["max_mu_required"], ref["mu_required"], rtol=1e-6)
    # a sphere's alpha is the equivalent bank angle theta - 90 deg (sec. 4)
    np.testing.assert_allclose(series["alpha_deg"], 30.0, atol=1e-6)


# --------------------------------------------------------------------------
# perturbations and stability


def test_perturbation_is_a_tilt_kick_on_the_constraint_surface():
    eps = 1e-3
    starts = sim.horizontal_starts(TABLE1, 60.0, 10.0, perturb_deg=np.rad2deg(eps))
    steady = sim.horizontal_starts(TABLE1, 60.0, 10.0)
    res = dyn.constraint_residuals(starts.state, starts.params)
    assert abs(res["axis"][0]) < 1e-15 and abs(res["contact"][0]) < 1e-14
    np.testing.assert_array_equal(starts.state[dyn.W], steady.state[dyn.W])        # w kept
    p_kick = dyn.contact_point(starts.state, starts.params)
    p_steady = dyn.contact_point(steady.state, steady.params)
    np.testing.assert_allclose(p_kick, p_steady, atol=1e-14)                       # contact point kept
    series, _ = run(starts, periods=0.05, points_per_period=20)
    assert series["alpha_deg"][0] == pytest.approx(10.0 + np.rad2deg(eps), abs=1e-12)
    assert series["theta_deg"][0] == pytest.approx(60.0, abs=1e-12)


def test_start_state_is_the_dynamics_steady_state():
    starts = sim.horizontal_starts(TABLE1, 60.0, 10.0)
    ref, omega = dyn.wheel_orbit_state(60 * DEG, 10 * DEG, TABLE1.a, TABLE1.r, TABLE1.k, TABLE1.g)
    np.testing.assert_allclose(starts.state[:, 0], ref, atol=1e-13)
    assert starts.period[0] == pytest.approx(2 * np.pi / omega, rel=1e-14)


@pytest.mark.parametrize("side, theta, alpha, periods",
                         [("outside", 30.0, 60.0, 3), ("inside", 170.0, 85.0, 1)])
def test_unstable_orbit_grows_at_the_linear_rate(side, theta, alpha, periods):
    """A kick of 1e-10 rad grows as exp(lambda t), lambda the real eigenvalue
    of the exact linearisation (stability.wheel_stability), within 5 %."""
    s = Setup(side=side)
    stab = wheel_stability(theta * DEG, alpha * DEG, s.a, s.r, s.k, s.g, side == "outside")
    lam = float(stab["growth_rate"])
    ev = stab["eigenvalues"].reshape(-1)
    assert lam > 1.0 and np.min(np.abs(ev[ev.real > 0].imag)) < 1e-9 * lam       # a real eigenvalue
    series, summary = run(sim.horizontal_starts(s, theta, alpha, perturb_deg=np.rad2deg(1e-10)), periods=periods,
                          points_per_period=100)
    d = np.hypot(series["theta_deg"] - theta, series["alpha_deg"] - alpha) * DEG
    linear = (d > 1e-6) & (d < 1e-3)
    first = np.cumsum(~linear & (d >= 1e-3)) == 0                 # before it first leaves the window
    t = series["t_s"][linear & first]
    assert t.size > 20
    slope = np.polyfit(t, np.log(d[linear & first]), 1)[0]
    assert slope == pytest.approx(lam, rel=0.05)
    assert summary["max_theta_drift_deg"][0] > 0.1                 # it did run away


def test_steep_equator_orbit_is_unstable_against_the_papers_claim():
    """Sec. 2.3.2 (after eq. 138) says all steady orbits on the equator are
    stable.  For Table 1's wheel the orbit (90, 80 deg) (fits, has contact;
    needs mu = 11.4) is not: the slow and fast nutations have merged into a
    complex quadruplet (exact linearisation), and the simulated kick grows at
    its real part -- oscillating -- until the wheel loses contact."""
    stab = wheel_stability(90 * DEG, 80 * DEG, TABLE1.a, TABLE1.r, TABLE1.k, TABLE1.g)
    lam = float(stab["growth_rate"])
    assert lam > 4.0 and np.all(np.abs(stab["eigenvalues"].imag) > 6.0)
    ref = wheel.horizontal_orbit(90 * DEG, 80 * DEG, TABLE1.a, TABLE1.r, TABLE1.k, TABLE1.g)
    assert int(ref["status"]) == 0                                    # a legitimate steady orbit
    series, summary = run(sim.horizontal_starts(TABLE1, 90.0, 80.0, perturb_deg=np.rad2deg(1e-9)), periods=1,
                          points_per_period=400)
    d = np.hypot(series["theta_deg"] - 90.0, series["alpha_deg"] - 80.0) * DEG
    window = (d > 1e-6) & (d < 1e-3) & (np.cumsum(d >= 1e-3) == 0)
    slope = np.polyfit(series["t_s"][window], np.log(d[window]), 1)[0]
    assert slope == pytest.approx(lam, rel=0.05)
    assert summary["status"][0] == "contact_lost"
    assert summary["event_time_s"][0] < summary["period_s"][0]


def test_stable_orbit_nutates_at_the_linear_frequency():
    """Kicked Table 1 orbit: theta(t) oscillates at the slow nutation
    frequency of the linearisation (frame turning with the orbit)."""
    stab = wheel_stability(60 * DEG, 10 * DEG, TABLE1.a, TABLE1.r, TABLE1.k, TABLE1.g)
    slow = float(stab["freq_slow"])
    series, summary = run(sim.horizontal_starts(TABLE1, 60.0, 10.0, perturb_deg=np.rad2deg(1e-6)), periods=4,
                          points_per_period=100)
    assert summary["status"][0] == "completed"
    x = series["theta_deg"] - np.mean(series["theta_deg"])
    t = series["t_s"]
    spectrum = np.abs(np.fft.rfft(x * np.hanning(x.size), 16 * x.size))
    freqs = 2 * np.pi * np.fft.rfftfreq(16 * x.size, t[1] - t[0])
    assert freqs[np.argmax(spectrum)] == pytest.approx(slow, rel=0.03)
    assert summary["max_theta_drift_deg"][0] * DEG < 10e-6          # stays small: stable


# --------------------------------------------------------------------------
# events


def test_outside_vertical_orbit_leaves_at_the_release_angle():
    """Rolling over the top of the sphere with a small speed, the wheel leaves
    where cos(phi) = (2 + (2k+1) v^2/(g r'))/(3 + 2k) (eq. 82 generalised)."""
    s = Setup(side="outside")
    theta = np.array([90.0, 90.0, 60.0])
    v_top = np.array([0.5, 2.0, 1.0])
    series, summary = run(sim.vertical_starts(s, theta, v_top), periods=2, points_per_period=50)
    rp = vert.vertical_r_prime(theta * DEG, s.a, s.r, True)
    expected = np.rad2deg(vert.release_angle(theta * DEG, v_top / rp, s.a, s.r, s.k, s.g))
    assert np.all(expected > 40)                                  # a nontrivial angle
    assert list(summary["status"]) == ["contact_lost"] * 3
    np.testing.assert_allclose(summary["event_phi_deg"], expected, atol=0.1)
    np.testing.assert_allclose(summary["event_theta_deg"], theta, atol=1e-6)
    # each body's rows stop at its event, where the normal force is zero
    for i, row in enumerate(summary["input_row"]):
        mine = series["input_row"] == row
        assert series["t_s"][mine][-1] == summary["event_time_s"][i]
        assert abs(series["normal_per_mass_m_s2"][mine][-1]) < 1e-8


def test_inside_vertical_orbit_too_slow_from_the_bottom_loses_contact():
    """Started at the bottom with too little speed to loop, the wheel leaves
    the wall where r' phidot^2 = g cos(phi) (eqs. 27, 28): with V = v_bottom^2,
    cos(phi) = ((2k+1) V/(g r') - 2)/(2k+3) (phi from the top)."""
    s = TABLE1
    theta = 90.0
    rp = s.r - s.a
    v_bottom = np.array([6.0, 8.0])
    series, summary = run(sim.vertical_starts(s, theta, v_bottom, phi_start_deg=180.0), periods=2,
                          points_per_period=50)
    cos_phi = ((2 * s.k + 1) * v_bottom ** 2 / (s.g * rp) - 2) / (2 * s.k + 3)
    expected = 360.0 - np.rad2deg(np.arccos(cos_phi))
    assert list(summary["status"]) == ["contact_lost", "contact_lost"]
    np.testing.assert_allclose(summary["event_phi_deg"], expected, atol=0.1)


def test_inside_vertical_orbit_below_the_contact_limit_stops_at_once():
    """Eq. (28a): a top speed below sqrt(g r') cannot hold the wheel at the top."""
    rp = TABLE1.r - TABLE1.a
    v = np.sqrt(TABLE1.g * rp) * np.array([0.99, 1.01])
    series, summary = run(sim.vertical_starts(TABLE1, 90.0, v), periods=1, points_per_period=20)
    assert list(summary["status"]) == ["contact_lost", "completed"]
    assert summary["event_time_s"][0] == 0.0 and summary["event_phi_deg"][0] == 0.0
    assert np.sum(series["input_row"] == 1) == 1                   # the single row at t = 0
    # the closing orbit's period is the lap time; it goes round once
    lap = vert.lap_time(90 * DEG, v[1] / rp, TABLE1.a, TABLE1.r, TABLE1.k, TABLE1.g)
    assert summary["period_s"][1] == pytest.approx(float(lap), rel=1e-12)
    assert series["phi_deg"][series["input_row"] == 2][-1] == pytest.approx(360.0, abs=1e-6)


def test_slips_event_fires_where_the_friction_runs_out():
    """Inside vertical orbit with cot(theta) < mu < mu_max: slips at the
    analytic slip angle (physics.vertical_orbit.slip_angle, from eqs. 27-28b)."""
    theta = 60 * DEG
    rp = TABLE1.r * np.sin(theta) - TABLE1.a
    v = 1.2 * np.sqrt(TABLE1.g * rp)
    _, mu_max = vert.worst_point(theta, v / rp, TABLE1.a, TABLE1.r, TABLE1.k, TABLE1.g)
    mu = 0.5 * (1 / np.tan(theta) + float(mu_max))
    s = Setup(mu=mu)
    series, summary = run(sim.vertical_starts(s, 60.0, v), periods=1, points_per_period=50)
    expected = np.rad2deg(vert.slip_angle(theta, v / rp, s.a, s.r, s.k, s.g, mu))
    assert summary["status"][0] == "slips"
    assert summary["event_phi_deg"][0] == pytest.approx(float(expected), abs=0.1)
    assert series["mu_required"][-1] == pytest.approx(mu, rel=1e-8)
    assert summary["max_mu_required"][0] == pytest.approx(mu, rel=1e-8)


def test_horizontal_orbit_that_needs_more_friction_slips_at_once():
    s = Setup(mu=1.0)                             # Table 1: theta 60, alpha 10 needs 1.19
    series, summary = run(sim.horizontal_starts(s, 60.0, 10.0), periods=1)
    assert summary["status"][0] == "slips" and summary["event_time_s"][0] == 0.0
    assert len(series) == 1


def test_unstable_orbit_ends_in_an_event():
    """The outside orbit (30, 60) runs away and loses contact; with mu = 0.8
    (it needs 0.71 when steady) it slips first."""
    s = Setup(side="outside")
    starts = sim.Starts.concat([sim.horizontal_starts(s, 30.0, 60.0, perturb_deg=np.rad2deg(1e-8)),
                                sim.horizontal_starts(s, 30.0, 60.0, perturb_deg=np.rad2deg(1e-8), input_row=2)])
    series, summary = run(starts, periods=3, points_per_period=50, mu=np.array([np.inf, 0.8]))
    assert list(summary["status"]) == ["contact_lost", "slips"]
    assert summary["event_time_s"][1] < summary["event_time_s"][0]
    assert summary["min_normal_per_mass_m_s2"][0] == pytest.approx(0.0, abs=1e-8)


# --------------------------------------------------------------------------
# many bodies, streaming, statuses, options


def test_many_bodies_in_one_call_match_single_runs():
    """Bodies integrated together (one vectorised solve_ivp) behave as alone;
    one body's event does not stop the others."""
    a = sim.horizontal_starts(TABLE1, 60.0, 10.0, perturb_deg=np.rad2deg(1e-4))
    b = sim.vertical_starts(Setup(side="outside"), 90.0, 1.0, input_row=2)
    _, together = run(sim.Starts.concat([a, b]), periods=2, points_per_period=20, frame="lab")
    _, alone_a = run(a, periods=2, points_per_period=20, frame="lab")
    _, alone_b = run(b, periods=2, points_per_period=20)
    assert list(together["status"]) == ["completed", "contact_lost"]
    assert together["event_phi_deg"][1] == pytest.approx(alone_b["event_phi_deg"][0], abs=1e-6)
    assert together["max_alpha_drift_deg"][0] == pytest.approx(alone_a["max_alpha_drift_deg"][0], rel=1e-5)


def test_chunks_stream_period_by_period():
    sim_ = sim.Simulation(sim.horizontal_starts(TABLE1, 60.0, 10.0), periods=3, points_per_period=7)
    with pytest.raises(RuntimeError):
        sim_.summary()
    calls = []
    chunks = list(sim_.chunks(progress=lambda done, total: calls.append((done, total))))
    assert len(chunks) == sim_.n_chunks == 3
    assert calls == [(1, 3), (2, 3), (3, 3)]
    assert [len(c) for c in chunks] == [8, 7, 7]
    assert all(c.names == list(sim.SERIES_COLUMNS) for c in chunks)
    t = np.concatenate([c["t_s"] for c in chunks])
    np.testing.assert_allclose(t, np.arange(22) * sim_.starts.period[0] / 7, rtol=1e-13, atol=1e-15)
    summary = sim_.summary()
    assert summary.names == list(sim.SUMMARY_COLUMNS)
    assert summary["n_steps"][0] > 0 and summary["wall_time_s"][0] > 0


def test_orbits_that_do_not_exist_get_a_status_and_no_rows():
    starts = sim.Starts.concat([
        sim.horizontal_starts(TABLE1, np.array([120.0, 30.0, 60.0]), np.array([90.0, 60.0, 10.0])),
        sim.horizontal_starts(Setup(body="sphere"), 60.0, omega3=1.0, input_row=4),
    ])
    series, summary = run(starts, periods=0.1, points_per_period=10)
    # alpha = 90 deg below the equator: Omega^2 < 0 (eq. 29); (30, 60): does
    # not fit (eq. 0); sphere with too little spin: no real root (eq. 56)
    assert list(summary["status"]) == ["no_orbit", "no_fit", "completed", "no_orbit"]
    assert set(series["input_row"]) == {3}



def test_statuses_are_the_run_status_labels_with_their_reasons():
    """The summary's status texts are the RunStatus labels; every status a
    run can end in is one of STATUSES, with the status's own reason words."""
    assert sim.STATUSES == ("completed", "contact_lost", "slips", "no_fit", "no_orbit", "failed", "hits_floor",
                            "over_the_top")
    assert [sim.RunStatus[name.upper()].label for name in sim.STATUSES] == list(sim.STATUSES)
    starts = sim.Starts.concat([
        sim.horizontal_starts(TABLE1, np.array([60.0, 30.0]), np.array([10.0, 60.0])),
        sim.horizontal_starts(Setup(mu=0.5), 60.0, 10.0, input_row=3),
        sim.vertical_starts(TABLE1, 90.0, 1.0, input_row=4),
    ])
    _, summary = run(starts, periods=0.1, points_per_period=10)
    assert list(summary["status"]) == ["completed", "no_fit", "slips", "contact_lost"]
    for status, reason in zip(summary["status"], summary["reason"]):
        assert isinstance(status, str) and status in sim.STATUSES
        if status in ("completed", "slips", "contact_lost"):
            assert reason == sim.RunStatus[status.upper()].reason != ""


def test_kicks_are_degrees_like_every_angle_and_echoed_as_given():
    kicked = sim.horizontal_starts(TABLE1, 60.0, 10.0, perturb_deg=0.05)
    assert kicked.perturb_deg[0] == 0.05
    _, summary = run(kicked, periods=0.05, points_per_period=20)
    assert summary["perturb_deg"][0] == 0.05 and summary["theta_deg"][0] == 60.0
    # the tilt kick of 0.05 deg is one of 0.05 deg in alpha at the start
    series, _ = run(kicked, periods=0.05, points_per_period=20)
    assert series["alpha_deg"][0] == pytest.approx(10.05, abs=1e-12)
    with pytest.raises(ValueError, match="perturb_deg"):
        sim.horizontal_starts(TABLE1, 60.0, 10.0, perturb_deg=np.nan)


def test_invalid_parameters_raise():
    with pytest.raises(ValueError, match="wheel or sphere"):
        sim.horizontal_starts(Setup(body="particle"), 120.0, 10.0)
    with pytest.raises(ValueError, match="k > 0"):
        sim.horizontal_starts(Setup(k=0.0), 60.0, 10.0)
    with pytest.raises(ValueError, match="theta"):
        sim.horizontal_starts(TABLE1, 200.0, 10.0)
    with pytest.raises(ValueError, match="alpha"):
        sim.horizontal_starts(TABLE1, 60.0)
    with pytest.raises(ValueError, match="omega3"):
        sim.horizontal_starts(Setup(body="sphere"), 60.0)
    with pytest.raises(ValueError, match="speed"):
        sim.vertical_starts(TABLE1, 90.0, -1.0)
    starts = sim.horizontal_starts(TABLE1, 60.0, 10.0)
    for bad in ({"periods": 0}, {"points_per_period": 0}, {"method": "Euler"}, {"rtol": 0.0},
                {"atol": -1.0}, {"frame": "rotating"}, {"mu": -1.0}):
        with pytest.raises(ValueError):
            sim.Simulation(starts, **bad)


def test_implicit_method_with_block_sparsity_agrees():
    """Radau (block-diagonal Jacobian pattern over 2 bodies) agrees with DOP853."""
    starts = sim.horizontal_starts(TABLE1, 60.0, np.array([10.0, 25.0]), perturb_deg=np.rad2deg(1e-4))
    _, radau = run(starts, periods=0.25, points_per_period=8, method="Radau", rtol=1e-9)
    _, dop = run(starts, periods=0.25, points_per_period=8)
    assert list(radau["method"]) == ["Radau", "Radau"]
    np.testing.assert_allclose(radau["max_alpha_drift_deg"], dop["max_alpha_drift_deg"], rtol=1e-3)


# --------------------------------------------------------------------------
# the figure


@pytest.fixture(scope="module")
def short_run():
    starts = sim.Starts.concat([sim.horizontal_starts(TABLE1, 60.0, 10.0, perturb_deg=np.rad2deg(1e-3)),
                                sim.vertical_starts(Setup(side="outside"), 90.0, 1.0, input_row=2)])
    return run(starts, periods=1, points_per_period=40)


@pytest.mark.parametrize("suffix", ["png", "svg", "pdf"])
def test_plot_writes_files(short_run, tmp_path, suffix):
    from deathsphere.render.simulation_figure import plot_simulation

    series, summary = short_run
    out = tmp_path / f"sim.{suffix}"
    fig = plot_simulation(series, summary, output=out)
    assert out.stat().st_size > 1000
    assert len(fig.axes) == 4
    # theta(t) panel: one line per body plus the event marker of body 2
    assert len(fig.axes[0].lines) == 3


def test_plot_needs_matplotlib(short_run, monkeypatch, tmp_path):
    from deathsphere.render.simulation_figure import plot_simulation

    series, summary = short_run
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(plot_module.PlotExtraMissing, match=r"deathsphere\[plot\]"):
        plot_simulation(series, summary, output=tmp_path / "x.png")
    with pytest.raises(ValueError, match="png"):
        plot_simulation(series, summary, output=tmp_path / "x.jpg")
