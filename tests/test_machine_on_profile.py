"""The single-contact machine on a profile (docs/machine.md, "On a
profile", MP1-MP5): its crown point on the profile's parallel surface, the
meridian moved a tyre radius along its normal, held against grounds whose
parallel surface is a quadric (a profile sampled from a drum, from a cone
of 80 degrees and from a sphere gives their eigenvalues, through the
quadric's own equations), the profile's own distance function, and a
brute-force search round the crown circle.  (Equilibrium, central
differences and energy on a bowl: tests/test_machine_dynamics_on.py.)"""

import numpy as np
import pytest

from deathsphere.api.machines import PRESETS
from deathsphere.physics import machine_dynamics_on as mo
from deathsphere.physics.ground import Cone, Cylinder, Profile, Sphere
from deathsphere.physics.machine_arrays import machine_arrays

G = 9.81
STUNT = machine_arrays(PRESETS["stunt125"])
A_T = float(STUNT.wheel_radius - STUNT.tyre_radius)
T = float(STUNT.tyre_radius)


def _spectrum_gap(one, other):
    """The largest distance from an eigenvalue of either set (n, 4) to the nearest of the other's."""
    d = np.abs(one[:, :, None] - other[:, None, :])
    return max(np.max(np.min(d, axis=2)), np.max(np.min(d, axis=1)))


def _globe_profile(radius, samples):
    """The globe's meridian from its bottom to 63 degrees above its equator, ``samples`` points."""
    theta = np.linspace(np.pi, 0.35 * np.pi, samples)
    return Profile(radius * np.sin(theta), radius + radius * np.cos(theta))


def _cases():
    z = np.linspace(0.0, 6.0, 25)
    beta = np.radians(80.0)
    globe = Sphere(10.0)
    return {
        # a straight meridian is its own spline: the same eigenvalues to round-off (measured 2e-12 of |lambda|)
        "drum": (Cylinder(5.0), Profile(np.full(z.size, 5.0), z), [1.0, 2.0], [10.0, 20.0], 1e-10),
        "cone-80": (Cone(5.0, beta), Profile(5.0 + z / np.tan(beta), z), [1.0, 2.0], [15.0, 25.0], 1e-10),
        # a circle sampled every 0.98 deg: the spline's curvature is the sampling's (measured 1.2e-7 of |lambda|;
        # 31 samples give 1.1e-6, 241 give 2.4e-8)
        "sphere": (globe, _globe_profile(10.0, 121), list(globe.height(np.radians([100.0, 110.0]))),
                   [30.0, 35.0], 1e-6),
    }


@pytest.mark.parametrize("name", ["drum", "cone-80", "sphere"])
def test_a_profile_sampled_from_a_quadric_ground_gives_its_eigenvalues(name):
    ground, profile, lanes, tilts, tol = _cases()[name]
    exact = mo.machine_stability_on(np.array(lanes), np.radians(tilts), ground, G, STUNT)
    sampled = mo.machine_stability_on(np.array(lanes), np.radians(tilts), profile, G, STUNT)
    assert np.isfinite(exact["eigenvalues"]).all()
    scale = np.max(np.abs(exact["eigenvalues"]))
    assert _spectrum_gap(sampled["eigenvalues"], exact["eigenvalues"]) < tol * scale
    np.testing.assert_allclose(sampled["growth_rate"], exact["growth_rate"], rtol=0, atol=tol * scale)
    assert (sampled["verdict"] == exact["verdict"]).all()


def test_the_parallel_meridian_is_a_tyre_radius_inside_along_the_shared_normal():
    rho = np.linspace(0.0, 12.0, 61)
    bowl = Profile(rho, 0.08 * rho ** 2)
    parallel = bowl.offset(T)
    lanes = np.array([0.5, 2.0, 6.0])
    q_rho, q_z = parallel.contact(lanes)
    # by the profile's own distance function (its fine table and Newton's steps, not the parallel's)
    np.testing.assert_allclose(bowl.clearance(q_rho, q_z), T, rtol=0, atol=1e-12)
    np.testing.assert_allclose(parallel.clearance(q_rho, q_z), 0.0, rtol=0, atol=1e-12)
    # the foot of Q on the meridian is the lane's own point: the two meridians share their normals
    np.testing.assert_allclose(parallel.foot(q_rho, q_z), bowl.spline_parameter(lanes), rtol=0, atol=1e-12)
    # and a point 3 cm further in is 3 cm inside the parallel surface
    n_rho, n_z = bowl.normal(lanes)
    np.testing.assert_allclose(parallel.clearance(q_rho + 0.03 * n_rho, q_z + 0.03 * n_z), 0.03, atol=1e-12)


def test_the_crown_point_is_the_crown_circles_point_nearest_the_bowl():
    """MP4-MP5 against brute force: the profile's clearance along the whole
    crown circle of a disturbed state; the crown point is its least, and
    the contact a tyre radius out from it is on the profile."""
    rho = np.linspace(0.0, 12.0, 61)
    bowl = Profile(rho, 0.08 * rho ** 2)
    X, _ = mo.machine_orbit_state_on(np.array([2.0]), np.radians([30.0]), bowl, G, STUNT)
    X = X + 0.05 * np.random.default_rng(2).standard_normal(X.shape)
    crown = mo.geometry_on(bowl, STUNT)(X[0:3, None], X[3:6, None], float(STUNT.wheel_radius), T)
    C, e1 = X[0:3, 0], X[3:6, 0] / np.linalg.norm(X[3:6, 0])
    u = np.cross(e1, [0.0, 0.0, 1.0])
    u /= np.linalg.norm(u)
    v = np.cross(e1, u)
    phi = np.linspace(0, 2 * np.pi, 20001)
    ring = C[:, None] + A_T * (np.cos(phi) * u[:, None] + np.sin(phi) * v[:, None])
    clearance = bowl.clearance(np.hypot(ring[0], ring[1]), ring[2])
    i = int(np.argmin(clearance))
    np.testing.assert_allclose(crown.Q[:, 0, 0], ring[:, i], atol=A_T * 2 * np.pi / 20000)
    Q = crown.Q[:, 0, 0]
    assert float(bowl.clearance(np.hypot(Q[0], Q[1]), Q[2])) <= clearance[i] + 1e-12
    P = crown.P[:, 0, 0]
    # the contact on the profile, and a tyre radius from the crown point
    assert abs(float(bowl.clearance(np.hypot(P[0], P[1]), P[2])) - (float(bowl.clearance(np.hypot(Q[0], Q[1]), Q[2]))
                                                                      - T)) < 1e-12
    assert abs(np.linalg.norm(P - Q) - T) < 1e-12


def test_the_crown_normals_jets_are_the_derivatives_of_the_normal_along_a_path():
    """MP4's first and second coefficients (the foot's s1, s2 by implicit
    differentiation) against central differences of the normal itself, each
    point's foot found afresh, along X(eps) = X0 + X1 eps + X2 eps^2 / 2
    off the bowl's wall."""
    from deathsphere.physics.crown_surfaces import crown_surface
    from deathsphere.physics.taylor import Taylor

    rho = np.linspace(0.0, 12.0, 61)
    bowl = Profile(rho, 0.08 * rho ** 2)
    surface = crown_surface(bowl, T)
    rng = np.random.default_rng(5)
    q_rho, q_z = bowl.offset(T).contact(np.array([1.0, 3.0, 7.0]))
    X0 = np.stack((q_rho * np.cos(1.0), q_rho * np.sin(1.0), q_z)) + 0.02 * rng.standard_normal((3, 3))
    X1, X2 = rng.standard_normal((3, 3)), rng.standard_normal((3, 3))
    jet = surface.normal(Taylor(X0, X1, X2), surface.foot(X0))

    def at(eps):
        X = X0 + X1 * eps + X2 * eps ** 2 / 2
        return surface.normal(X, surface.foot(X))

    h = 1e-4
    first = (at(h) - at(-h)) / (2 * h)
    second = (at(h) - 2 * at(0.0) + at(-h)) / h ** 2
    np.testing.assert_allclose(jet.x0, at(0.0), rtol=0, atol=1e-15)
    np.testing.assert_allclose(jet.x1, first, rtol=0, atol=1e-7 * np.max(np.abs(jet.x1)))
    np.testing.assert_allclose(jet.x2, second, rtol=0, atol=1e-5 * np.max(np.abs(jet.x2)))
    # the normal is a unit vector, and its value F is the signed distance: |grad F| = 1
    np.testing.assert_allclose(np.sum(jet.x0 ** 2, axis=0), 1.0, atol=1e-15)
