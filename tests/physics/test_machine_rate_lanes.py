"""Lanes held at an orbital rate (docs/machine.md eq. M12r): a contact
speed or a lap time fixes Omega, and the tilts found must be every tilt at
which the forward model (eq. M8, ride_orbit) turns at that rate: checked
against a dense scan of the forward model, not the polynomial itself."""

import warnings

import numpy as np

from deathsphere.physics.ground import Sphere
from deathsphere.physics.machine import fit_window, ride_orbit, solve_alpha_for_rate
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.physics.machine_lanes import contact_rate, horizontal_lanes_at_rate, orbits_for_rate
from deathsphere.physics.status import Reason, Status
from deathsphere.records.machine_presets import stunt125

G = 9.80665
GLOBE = Sphere(2.4384)                       # a 16 ft globe
M = machine_arrays(stunt125())


def _scanned_crossings(theta, omega, n=40001):
    """The tilts where ride_orbit's Omega crosses ``omega``, located on a
    dense grid of the fit window (sign changes of Omega - omega between two
    grid points where both have an orbit)."""
    lo, hi = fit_window(theta, GLOBE, M)
    alpha = np.linspace(lo + 1e-9, hi - 1e-9, n)
    orb = ride_orbit(np.full(n, theta), alpha, GLOBE, G, M)
    f = orb["omega"] - omega
    ok = np.isfinite(f[:-1]) & np.isfinite(f[1:]) & (np.sign(f[:-1]) != np.sign(f[1:]))
    return 0.5 * (alpha[:-1][ok] + alpha[1:][ok])


def test_the_tilts_for_a_rate_are_the_forward_models_crossings():
    rng = np.random.default_rng(7)
    theta = np.radians(rng.uniform(95.0, 170.0, 8))
    omega = rng.uniform(1.5, 6.0, 8)
    tilts = solve_alpha_for_rate(theta, omega, GLOBE, G, M)
    for i in range(theta.size):
        found = np.sort(tilts[i][np.isfinite(tilts[i])])
        scanned = _scanned_crossings(theta[i], omega[i])
        assert found.size == scanned.size, (np.degrees(found), np.degrees(scanned))
        np.testing.assert_allclose(found, scanned, atol=2e-4)
        # and at each the forward model turns at the rate asked for
        back = ride_orbit(np.full(found.size, theta[i]), found, GLOBE, G, M)["omega"]
        np.testing.assert_allclose(back, omega[i], rtol=1e-9)


def test_a_contact_speed_is_omega_times_the_contacts_distance_from_the_axis():
    rng = np.random.default_rng(3)
    theta = np.radians(rng.uniform(100.0, 160.0, 20))
    v = rng.uniform(5.0, 12.0, 20)
    omega = contact_rate(theta, v, GLOBE)
    lanes = horizontal_lanes_at_rate(theta, omega, GLOBE, G, M)
    has = lanes["chosen"]
    assert has.sum() >= 10
    # the contact: r sin(theta) from the vertical axis (the sphere's geometry)
    rho = GLOBE.radius * np.sin(theta[has])
    np.testing.assert_allclose(lanes["omega"][has] * rho, v[has], rtol=1e-9)
    np.testing.assert_allclose(lanes["v_contact"][has], v[has], rtol=1e-9)
    # the centre of mass: Omega |r_G| with r_G from the forward model at the tilt returned
    forward = ride_orbit(theta[has], lanes["alpha"][has], GLOBE, G, M)
    np.testing.assert_allclose(lanes["v_cm"][has], lanes["omega"][has] * np.abs(forward["r_g"]), rtol=1e-12)
    np.testing.assert_allclose(forward["v_contact"], v[has], rtol=1e-9)


def test_a_contact_on_the_axis_has_no_orbit_and_says_why_without_a_warning():
    theta = np.radians([180.0, 0.0, 120.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        omega = contact_rate(theta, np.array([8.0, 8.0, 8.0]), GLOBE)
        tilts, orbit = orbits_for_rate(theta, omega, GLOBE, G, M)
        lanes = horizontal_lanes_at_rate(theta, omega, GLOBE, G, M)
    assert np.isnan(omega[:2]).all() and np.isfinite(omega[2])
    assert np.isnan(tilts[:2]).all()
    assert (orbit["status"][:2] == Status.NO_ORBIT).all()
    assert (orbit["reason"][:2] == Reason.CONTACT_ON_AXIS).all()
    assert list(lanes["reason"][:2]) == [Reason.CONTACT_ON_AXIS] * 2 and not lanes["chosen"][:2].any()
