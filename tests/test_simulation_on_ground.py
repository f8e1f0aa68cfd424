"""``simulate`` off the globe: the paper's wheel and ball on the drum, the
cones and a bowl, through the API's own path (simulation_request ->
prepare_simulation).  Each check is made from the recorded states with
geometry of its own, not the equations' contact search:

* the gap: the least clearance of the body from the wall, by the ground's
  distance function, over the rim (a wheel: a golden-section search round
  the rim circle) or the ball's surface (its centre's clearance less a);
* the energy: the kinetic energy from the angular velocity and the
  contact point found that way (v = w x (c - p), the contact at rest),
  plus g z;
* the golfer's dilemma: the bobbing frequency read off the height series
  by its zero crossings, against Omega sqrt(k / (k + 1)) (Gualtieri et al.,
  Am. J. Phys. 74, 497 (2006); docs/dynamics.md eq. G9).
"""

import numpy as np
import pytest
from wall_contacts import ball_contact, state_energy, wheel_contact

from deathsphere.api.simulation import prepare_simulation, simulation_request
from deathsphere.physics.ground import Profile

G = 9.80665
#: a paraboloid bowl z = rho^2 / (2 * 3 m), sampled at 41 points
_RHO = np.linspace(0.0, 4.0, 41)
BOWL = Profile(_RHO, _RHO ** 2 / 6.0)


def _run(**typed):
    sim = prepare_simulation(*simulation_request({"record_states": True, "points_per_period": 4, **typed}))
    series, summary = sim.run()
    return series, summary, sim.sample_states()["state"], sim.starts.params.ground


CASES = {
    # the wheel in the drum, a large wheel so that three laps take few steps
    "drum": dict(surface="cylinder", diameter=10, height=2, alpha=20, a=2.0, perturb=1),
    "cone80": dict(surface="cone", diameter=6, wall_angle=80, height=2, body="sphere", omega=3, a=1.0, perturb=1),
    "cone100": dict(surface="cone", diameter=10, wall_angle=100, height=2, body="sphere", omega=3, a=1.0,
                    perturb=1),
    "bowl": dict(surface=BOWL, height=1.5, alpha=20, a=2.0, perturb=1),
    # the ball's contact crosses a knot of the spline (rho = 3 m) as it bobs: the
    # integration restarts there (docs/simulation.md, "On any ground")
    "bowl_ball": dict(surface=BOWL, height=1.5, body="sphere", omega=3, a=1.0, perturb=1),
}


@pytest.mark.parametrize("name", list(CASES))
def test_energy_and_contact_hold_over_three_laps(name):
    typed = dict(CASES[name])
    ball = typed.get("body") == "sphere"
    series, summary, states, ground = _run(periods=3, rtol=1e-12, **typed)
    assert summary["status"][0] == "completed" and summary["periods_simulated"][0] == 3.0
    a, k = typed["a"], float(summary["k"][0])
    if ball:
        p, gap = ball_contact(ground, states[0:3], a)
    else:
        p, gap = wheel_contact(ground, states[0:3], states[3:6], a)
    assert np.max(np.abs(gap)) < 1e-12
    energy, kinetic = state_energy(states, p, a, k, ball)
    assert np.max(np.abs(energy - energy[0])) < 1e-9 * np.min(kinetic)
    # the kick moved it: the run is not a fixed point's
    assert np.ptp(np.asarray(series["height_m"], dtype=float)) > 1e-3


def test_a_stable_lane_is_held():
    """The wheel on a drum's lane that orbit calls stable, not kicked: three
    laps later its centre is where the steady orbit keeps it."""
    from deathsphere.api.orbits import orbit

    lane = dict(surface="cylinder", diameter=10, height=2, alpha=20, a=2.0)
    assert str(orbit(**lane)["stability"]) == "stable"
    series, summary, states, _ = _run(periods=3, **lane)
    assert summary["status"][0] == "completed"
    rho_c = np.hypot(states[0], states[1])
    assert np.ptp(states[2]) < 1e-9 and np.ptp(rho_c) < 1e-9
    assert float(summary["max_height_drift_m"][0]) < 1e-9


def test_the_golfers_dilemma_bobbing_frequency():
    """A ball on a drum's wall, its velocity turned 1 degree up the wall:
    it bobs between two heights at Omega sqrt(k / (k + 1)).

    Omega is the measured mean azimuthal rate (the kick lowers it by
    cos(1 deg)); the frequency is read from the height's zero crossings
    about its mean, linearly interpolated between rows 1/50 of a lap apart.
    Tolerance 1e-4: the crossings' interpolation errs by O((omega dt)^3)
    ~ 1e-6 of a period (omega dt = 0.07), the integrator by 1e-10; taking
    the midpoint of the extremes sampled on the rows as the centre shifts
    the crossings by O((omega dt)^2 / 8) ~ 6e-4 of the amplitude, which
    alternates in sign and cancels over whole half-bobs.  (Measured:
    3e-6.)"""
    k = 0.4
    series, summary, _, _ = _run(surface="cylinder", diameter="32ft", height=3, body="sphere", omega=6, perturb=1,
                                 periods=8, points_per_period=50)
    assert summary["status"][0] == "completed"
    t = np.asarray(series["t_s"], dtype=float)
    z = np.asarray(series["height_m"], dtype=float)
    phi = np.radians(np.asarray(series["phi_deg"], dtype=float))
    omega = np.polyfit(t, phi, 1)[0]
    # on a drum the azimuthal rate stays the kicked one: the horizontal part of the velocity, Omega cos(1 deg)
    assert abs(omega / (6.0 * np.cos(np.radians(1.0))) - 1) < 1e-9
    z = z - 0.5 * (z.max() + z.min())
    i = np.flatnonzero(np.sign(z[:-1]) != np.sign(z[1:]))
    crossings = t[i] - z[i] * (t[i + 1] - t[i]) / (z[i + 1] - z[i])
    assert crossings.size >= 6
    measured = np.pi * (crossings.size - 1) / (crossings[-1] - crossings[0])
    assert abs(measured / (omega * np.sqrt(k / (k + 1))) - 1) < 1e-4
    # two heights: the kick's amplitude v sin(1 deg) / omega_bob about the start
    assert 0.05 < 0.5 * np.ptp(z) < 0.5


@pytest.mark.parametrize("start, kick, wall, status", [(2.0, 5.0, 2.5, "over_the_top"), (0.5, -5.0, None, "hits_floor")])
def test_the_wall_ends_stop_a_bobbing_ball_when_its_bob_says(start, kick, wall, status):
    """The golfer's dilemma on a drum, solved by hand (Newton-Euler for a
    ball of I = k m a^2, its centre at rho = R - a, turning at the constant
    rate Omega' = Omega cos(kick)): (k + 1) z" = -g - k a Omega' w_n and
    d(w_n)/dt = Omega' z' / a, so z is harmonic at w = Omega' sqrt(k / (k + 1)):

        z(t) = z0 + (v0 / w) sin(w t) + (z"0 / w^2) (1 - cos(w t)),

    v0 = Omega rho sin(kick), z"0 = -g (1 - cos(kick)) / (k + 1) (the steady
    orbit's spin w_n = -g / (k a Omega) now meets the slower Omega').  The
    contact (on a drum at the centre's height) reaches the wall's top; the
    ball's lowest point, a below its centre, the floor."""
    from scipy.optimize import brentq

    k, omega, a, rho = 0.4, 6.0, 0.3, 4.8768 - 0.3
    shape = {} if wall is None else {"wall_height": wall}
    series, summary, _, _ = _run(surface="cylinder", diameter="32ft", height=start, body="sphere", omega=omega,
                                 perturb=kick, periods=3, points_per_period=20, **shape)
    assert summary["status"][0] == status
    d = np.radians(kick)
    bob = omega * np.cos(d) * np.sqrt(k / (k + 1))
    v0, acc0 = omega * rho * np.sin(d), -G * (1 - np.cos(d)) / (k + 1)
    target = wall if wall is not None else a

    def z(t):
        return start + v0 / bob * np.sin(bob * t) + acc0 / bob ** 2 * (1 - np.cos(bob * t)) - target

    expected = brentq(z, 0.0, 0.5 * np.pi / bob, xtol=1e-14)
    assert abs(float(summary["event_time_s"][0]) / expected - 1) < 1e-7
    # the event is the last row, at the wall's top or with the ball's lowest point on the floor
    assert abs(float(series["height_m"][len(series) - 1]) - target) < 1e-9


def test_the_figure_plots_the_height_off_the_globe():
    pytest.importorskip("matplotlib")
    from deathsphere.render.simulation_figure import plot_simulation

    series, summary, _, _ = _run(surface="cylinder", diameter="32ft", height=2, alpha=10, perturb=2, periods=0.1,
                                 points_per_period=40)
    fig = plot_simulation(series, summary)
    lane, track = fig.axes[0], fig.axes[3]
    assert lane.get_ylabel() == "contact height [m]" == track.get_ylabel()
    np.testing.assert_array_equal(lane.lines[0].get_ydata(), np.asarray(series["height_m"]))
    assert "on the cylinder, height 2 m" in fig.get_suptitle()
