"""The single-contact machine's equations of motion and stability on the
drum, the cone, flat ground and a profile (docs/machine.md, "On any
ground" and "On a profile"), each
held against something derived apart from them: the globe's own
equations, the steady lanes' closed forms (MS1-MS4), central finite
differences, the ground's distance function, and the limits where one
ground becomes another."""

import numpy as np
import pytest

from deathsphere.api.machines import PRESETS
from deathsphere.physics import machine_dynamics as md
from deathsphere.physics import machine_dynamics_on as mo
from deathsphere.physics import machine_motion as mm
from deathsphere.physics.ground import Cone, Cylinder, Plane, Profile, Sphere
from deathsphere.physics.machine_arrays import machine_arrays

G = 9.81
STUNT = machine_arrays(PRESETS["stunt125"])

#: Steady lanes with an orbit on each ground: (ground, heights or turn radii [m], tilts [deg]).
LANES = [
    (Cylinder(5.0), [1.0, 2.0], [10.0, 20.0]),
    (Cone(5.0, np.radians(80.0)), [1.0, 2.0], [15.0, 25.0]),
    (Cone(5.0, np.radians(45.0)), [1.0, 2.0], [45.0, 50.0]),
    (Cone(6.0, np.radians(100.0)), [1.0, 2.0], [5.0, 10.0]),
    (Plane(), [10.0, 20.0], [60.0, 70.0]),
    # a profile: a bowl z = 0.08 rho^2 sampled every 0.2 m (its parallel surface by the meridian, MP1-MP5)
    (Profile(np.linspace(0.0, 12.0, 61), 0.08 * np.linspace(0.0, 12.0, 61) ** 2), [1.0, 2.0], [30.0, 40.0]),
]
IDS = ["drum", "well", "board-track", "leaning-in", "flat", "bowl"]


@pytest.mark.parametrize("ground", [Sphere(3.0), Cylinder(4.0), Cone(5.0, np.radians(80.0)),
                                    Cone(6.0, np.radians(110.0)), Plane()], ids=str)
def test_the_parallel_surface_is_a_tyre_radius_inside_and_its_quadric_vanishes_on_it(ground):
    t = 0.07
    parallel = ground.offset(t)
    a_rho, a_z, b_z, c = parallel.quadric()
    lanes = np.array([0.5, 1.0, 2.0])
    rho, z = parallel.contact(lanes)
    # distance from the ground itself, by the ground's own clearance function
    np.testing.assert_allclose(ground.clearance(rho, z), t, rtol=0, atol=1e-12)
    F = 0.5 * a_rho * rho ** 2 + 0.5 * a_z * z ** 2 + b_z * z + c
    np.testing.assert_allclose(F, 0.0, atol=1e-12)
    # the quadric's gradient points out of the inside: against the ground's inward normal
    n_rho, n_z = ground.normal(np.array([1.0]))
    grad = np.array([a_rho * rho, a_z * z + b_z])
    cosine = (grad[0] * n_rho + grad[1] * n_z) / np.hypot(*grad)
    if not isinstance(ground, Sphere):      # the globe's normal differs lane by lane
        np.testing.assert_allclose(cosine, -1.0, atol=1e-12)


def test_a_profiles_parallel_surface_has_no_quadric():
    profile = Profile([5.0, 5.0, 5.0, 5.0], [0.0, 1.0, 2.0, 3.0])
    assert mo.crown_quadric(profile, 0.1) is None


@pytest.mark.parametrize("preset", sorted(PRESETS))
def test_on_the_globe_the_general_equations_are_the_globes(preset):
    p = machine_arrays(PRESETS[preset])
    globe = Sphere(2.4)
    theta, alpha = np.radians([90.0, 70.0, 110.0, 100.0]), np.radians([30.0, 40.0, 20.0, 50.0])
    X, om = md.machine_orbit_state(theta, alpha, globe, G, p)
    X_on, om_on = mo.machine_orbit_state_on(globe.height(theta), alpha, globe, G, p)
    np.testing.assert_allclose(X_on, X, rtol=0, atol=1e-12 * np.max(np.abs(X)))
    np.testing.assert_allclose(om_on, om, rtol=1e-12)
    # off the steady states too: a disturbed state, in the lab frame and the turning one
    Xd = X + 0.01 * np.random.default_rng(1).standard_normal(X.shape)
    for rate in (0.0, om):
        f, f_on = md.machine_rhs(Xd, globe, G, p, rate), mo.machine_rhs_on(Xd, globe, G, p, rate)
        np.testing.assert_allclose(f_on, f, rtol=0, atol=1e-12 * np.max(np.abs(f)))
    ev = md.machine_stability(theta, alpha, globe, G, p)["eigenvalues"]
    ev_on = mo.machine_stability_on(globe.height(theta), alpha, globe, G, p)["eigenvalues"]
    assert _spectrum_gap(ev_on, ev) < 1e-12 * np.max(np.abs(ev))


def _spectrum_gap(one, other):
    """The largest distance from an eigenvalue of either set (n, 4) to the
    nearest of the other's, row by row (an order-free comparison: a sort
    by real part swaps a conjugate pair whose real parts differ by rounding)."""
    d = np.abs(one[:, :, None] - other[:, None, :])
    return max(np.max(d.min(axis=2)), np.max(d.min(axis=1)))


@pytest.mark.parametrize(("ground", "lanes", "tilts"), LANES, ids=IDS)
def test_a_steady_lane_is_an_equilibrium_of_the_equations_in_the_turning_frame(ground, lanes, tilts):
    X, om = mo.machine_orbit_state_on(np.array(lanes), np.radians(tilts), ground, G, STUNT)
    assert np.isfinite(om).all()
    rates = mo.machine_rhs_on(X, ground, G, STUNT, om)
    # the scale of each rate: |C| Omega, Omega, |w| Omega
    scale = np.max(np.abs(X)) * np.max(om + np.abs(X[6:9]).max(axis=0))
    assert np.max(np.abs(rates)) < 1e-12 * scale


def test_the_crown_point_is_the_crown_circles_farthest_point_out_on_a_disturbed_drum():
    # MG1 against brute force: F of the parallel surface along the whole crown circle
    drum = Cylinder(5.0)
    X, _ = mo.machine_orbit_state_on(np.array([1.5]), np.radians([15.0]), drum, G, STUNT)
    X = X + 0.05 * np.random.default_rng(2).standard_normal(X.shape)
    a, t = float(STUNT.wheel_radius), float(STUNT.tyre_radius)
    quadric = mo.crown_quadric(drum, t)
    crown = mo.crown_geometry(quadric)(X[0:3, None], X[3:6, None], a, t)
    C, e1 = X[0:3, 0], X[3:6, 0] / np.linalg.norm(X[3:6, 0])
    u = np.cross(e1, [0.0, 0.0, 1.0])
    u /= np.linalg.norm(u)
    v = np.cross(e1, u)
    phi = np.linspace(0, 2 * np.pi, 200001)
    ring = C[:, None] + (a - t) * (np.cos(phi) * u[:, None] + np.sin(phi) * v[:, None])
    F = 0.5 * (ring[0] ** 2 + ring[1] ** 2) - 0.5 * (5.0 - t) ** 2
    best = ring[:, np.argmax(F)]
    np.testing.assert_allclose(crown.Q[:, 0, 0], best, atol=(a - t) * 2 * np.pi / 200000)
    # the contact a tyre radius out along the drum's normal: on the drum
    P = crown.P[:, 0, 0]
    assert abs(np.hypot(P[0], P[1]) - np.hypot(*crown.Q[:2, 0, 0]) - t) < 1e-12


def _central_difference_eigenvalues(ground, lane, tilt):
    """The spectrum of the 9x9 Jacobian of the equations in the turning
    frame by central differences, Richardson-extrapolated from steps h and
    h/2 (the error O(h^4): the zero modes' near-Jordan blocks amplify
    rounding, so a small plain step is not enough)."""
    X, om = mo.machine_orbit_state_on(np.array([lane]), np.array([tilt]), ground, G, STUNT)
    X = X[:, 0]

    def central(h):
        J = np.zeros((9, 9))
        for i in range(9):
            step = h * (10.0 if i >= 6 else 1.0)
            dX = np.zeros(9)
            dX[i] = step
            J[:, i] = (mo.machine_rhs_on(X + dX, ground, G, STUNT, om[0])
                       - mo.machine_rhs_on(X - dX, ground, G, STUNT, om[0])) / (2 * step)
        return J

    return np.linalg.eigvals((4 * central(5e-4) - central(1e-3)) / 3)


@pytest.mark.parametrize(("ground", "lanes", "tilts"), LANES, ids=IDS)
def test_the_eigenvalues_are_those_of_central_differences_of_the_equations(ground, lanes, tilts):
    ev = mo.machine_stability_on(np.array(lanes[:1]), np.radians(tilts[:1]), ground, G, STUNT)["eigenvalues"][0]
    assert np.isfinite(ev).all()
    # the full 9x9 Jacobian's spectrum holds the reduced one and five (near) zeros:
    # the two constraints, the phase and the family's two tangents
    fd = _central_difference_eigenvalues(ground, lanes[0], np.radians(tilts[0]))
    for value in ev:
        assert np.min(np.abs(fd - value)) < 1e-6 * np.abs(value)


def test_a_cone_at_ninety_degrees_is_the_drum():
    lanes, tilts = np.array([1.0, 2.0]), np.radians([10.0, 20.0])
    drum = mo.machine_stability_on(lanes, tilts, Cylinder(5.0), G, STUNT)
    cone = mo.machine_stability_on(lanes, tilts, Cone(5.0, np.pi / 2), G, STUNT)
    assert _spectrum_gap(cone["eigenvalues"], drum["eigenvalues"]) < 1e-12


def test_the_floor_of_a_vast_globe_and_a_shallow_cone_tend_to_flat_ground_at_the_same_turn_radius():
    # the drum's wall stays vertical however wide: flat ground's limits are a globe's floor and a cone laid flat
    turn, tilts = np.array([10.0, 20.0]), np.radians([60.0, 70.0])
    flat = mo.machine_stability_on(turn, tilts, Plane(), G, STUNT)["eigenvalues"]
    errors = []
    for radius in (1e4, 1e6):
        globe = Sphere(radius)
        lanes = globe.height(np.pi - np.arcsin(turn / radius))
        errors.append(_spectrum_gap(mo.machine_stability_on(lanes, tilts, globe, G, STUNT)["eigenvalues"], flat))
    assert errors[1] < 1e-4 * np.max(np.abs(flat)) and errors[1] < 0.02 * errors[0]   # O(1/r)
    cone = Cone(1.0, 1e-5)
    ev = mo.machine_stability_on((turn - 1.0) * np.tan(1e-5), tilts, cone, G, STUNT)["eigenvalues"]
    assert _spectrum_gap(ev, flat) < 1e-4 * np.max(np.abs(flat))


@pytest.mark.parametrize(("ground", "lanes", "tilts"), LANES, ids=IDS)
def test_the_energy_is_conserved_at_disturbed_states_far_from_any_lane(ground, lanes, tilts):
    """The pitch constraint's reaction (MG3) is ideal and the contact rolls,
    so the energy's rate along the equations is zero anywhere on the
    constraints: by central differences of the energy along the rates, at
    states kicked far from the lane (5 cm, 0.1 of the axle, 3 rad/s) and put
    back on the constraints.  (A couple off by 0.1 % gives 2.5e-5.)"""
    n = 20
    rng = np.random.default_rng(3)
    X, _ = mo.machine_orbit_state_on(np.full(n, lanes[0]), np.radians(np.full(n, tilts[0])), ground, G, STUNT)
    X = X + np.concatenate([0.05 * rng.standard_normal((3, n)), 0.1 * rng.standard_normal((3, n)),
                            3.0 * rng.standard_normal((3, n))])
    X = mo.machine_project_on(X, ground, STUNT)
    geometry = mo.geometry_on(ground, STUNT)
    rates = mo.machine_rhs_on(X, ground, G, STUNT)
    h = 1e-6
    energy_rate = (mm.machine_energy(X + h * rates, G, STUNT, geometry)[0]
                   - mm.machine_energy(X - h * rates, G, STUNT, geometry)[0]) / (2 * h)
    kinetic = mm.machine_energy(X, G, STUNT, geometry)[1]
    assert np.max(np.abs(energy_rate) / (kinetic * np.sqrt(np.sum(X[6:9] ** 2, axis=0)))) < 1e-9
