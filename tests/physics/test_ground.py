"""The ground protocol (deathsphere.physics.ground): each ground's answers
agree with each other and with an independent reading of its surface."""

import numpy as np
import pytest

from deathsphere.physics.ground import Cone, Cylinder, Ground, Plane, Profile, Sphere

GROUNDS = [Sphere(2.4384), Plane(), Cylinder(4.8768, 3.6576), Cone(3.0, np.radians(80.0), 9.0),
           Cone(3.0, np.radians(100.0)), Cone(12.0, np.radians(45.0), 4.0)]
LANES = {"sphere": np.linspace(0.05, 4.8, 23), "plane": np.linspace(0.5, 30.0, 23),
         "cylinder": np.linspace(0.0, 3.6, 23), "cone": np.linspace(0.0, 4.0, 23)}


def _id(ground):
    return ground.name + (f"{np.degrees(ground.wall_angle_rad):.0f}" if isinstance(ground, Cone) else "")


@pytest.mark.parametrize("ground", GROUNDS, ids=_id)
def test_every_ground_speaks_the_protocol(ground):
    assert isinstance(ground, Ground)


@pytest.mark.parametrize("ground", GROUNDS, ids=_id)
def test_contact_lies_on_the_surface_and_the_normal_faces_inside(ground):
    lane = LANES[ground.name]
    rho, z = ground.contact(lane)
    x, y = rho * np.cos(0.7), rho * np.sin(0.7)
    assert np.max(np.abs(ground.implicit(x, y, z))) < 1e-12
    n_rho, n_z = ground.normal(lane)
    assert np.allclose(n_rho ** 2 + n_z ** 2, 1.0, rtol=0, atol=1e-15)
    # F < 0 on the inside: the normal points down the gradient
    grad = ground.gradient(x, y, z)
    g_rho = grad[0] * np.cos(0.7) + grad[1] * np.sin(0.7)
    g_norm = np.sqrt(g_rho ** 2 + grad[2] ** 2)
    assert np.allclose(-g_rho / g_norm, n_rho, atol=1e-14) and np.allclose(-grad[2] / g_norm, n_z, atol=1e-14)
    # and a step along the normal goes inside
    assert np.all(ground.implicit(x + 1e-3 * n_rho * np.cos(0.7), y + 1e-3 * n_rho * np.sin(0.7), z + 1e-3 * n_z) < 0)


@pytest.mark.parametrize("ground", GROUNDS, ids=_id)
def test_wall_angle_is_the_meridians_slope(ground):
    """beta from the contact curve's tangent by finite differences, and the
    normal (-sin beta, cos beta)."""
    lane = LANES[ground.name]
    h = 1e-6
    rho1, z1 = ground.contact(lane - h)
    rho2, z2 = ground.contact(lane + h)
    beta = np.arctan2(z2 - z1, rho2 - rho1)
    assert np.allclose(np.mod(beta, np.pi), ground.wall_angle(lane), atol=1e-7)
    n_rho, n_z = ground.normal(lane)
    b = ground.wall_angle(lane)
    assert np.allclose(n_rho, -np.sin(b), atol=1e-15) and np.allclose(n_z, np.cos(b), atol=1e-15)


def test_sphere_curvatures_from_the_meridian():
    """kappa_meridian = d(beta)/ds along the meridian; kappa_parallel = sin(beta) / rho (Meusnier)."""
    s = Sphere(3.0)
    lane = np.linspace(0.3, 5.7, 19)
    h = 1e-5
    rho1, z1 = s.contact(lane - h)
    rho2, z2 = s.contact(lane + h)
    ds = np.hypot(rho2 - rho1, z2 - z1)
    k_m = (s.wall_angle(lane + h) - s.wall_angle(lane - h)) / ds
    rho, _ = s.contact(lane)
    k_m_given, k_p_given = s.curvatures(lane)
    assert np.allclose(k_m, k_m_given, rtol=1e-6)
    assert np.allclose(np.sin(s.wall_angle(lane)) / rho, k_p_given, rtol=1e-12)


def test_sphere_height_and_theta_are_inverse_and_the_papers():
    s = Sphere(3.0)
    theta = np.linspace(0.0, np.pi, 37)
    assert np.allclose(s.theta(s.height(theta)), theta, atol=1e-7)
    assert s.height(np.pi) == 0.0 and s.height(0.0) == 6.0 and s.height(np.pi / 2) == pytest.approx(3.0)
    assert s.theta(7.0) == 0.0 and s.theta(-1.0) == pytest.approx(np.pi)


def test_hessians():
    x, y, z = np.array([0.3, 1.0]), np.array([0.1, -2.0]), np.array([0.5, 0.2])
    hs = Sphere(3.0).hessian(x, y, z)
    assert hs.shape == (3, 3, 2) and np.array_equal(hs[..., 1], np.eye(3))
    assert np.array_equal(Plane().hessian(x, y, z), np.zeros((3, 3, 2)))


@pytest.mark.parametrize("ground", [g for g in GROUNDS if not isinstance(g, Plane)], ids=_id)
def test_curvatures_from_the_meridian(ground):
    """kappa_meridian = d(beta)/ds along the meridian and kappa_parallel =
    sin(beta) / rho (Meusnier), by finite differences of the contact curve."""
    lane = LANES[ground.name][1:-1]
    h = 1e-5
    rho1, z1 = ground.contact(lane - h)
    rho2, z2 = ground.contact(lane + h)
    ds = np.hypot(rho2 - rho1, z2 - z1)
    k_m = (ground.wall_angle(lane + h) - ground.wall_angle(lane - h)) / ds
    rho, _ = ground.contact(lane)
    k_m_given, k_p_given = ground.curvatures(lane)
    assert np.allclose(k_m, k_m_given, rtol=1e-6, atol=1e-9)
    assert np.allclose(np.sin(ground.wall_angle(lane)) / rho, k_p_given, rtol=1e-12)


@pytest.mark.parametrize("ground", [g for g in GROUNDS if not isinstance(g, Plane)], ids=_id)
def test_clearance_is_the_distance_to_the_surface(ground):
    """A point stepped d along the inward normal from a contact is d inside."""
    lane = LANES[ground.name][1:-1]
    rho, z = ground.contact(lane)
    n_rho, n_z = ground.normal(lane)
    d = np.linspace(0.01, 0.5, lane.size)
    assert np.allclose(ground.clearance(rho + d * n_rho, z + d * n_z), d, rtol=0, atol=1e-12)
    assert np.allclose(ground.clearance(rho, z), 0.0, atol=1e-12)


@pytest.mark.parametrize("ground", GROUNDS, ids=_id)
def test_gradient_and_hessian_are_the_implicit_functions_derivatives(ground):
    rng = np.random.default_rng(3)
    x, y, z = rng.uniform(0.5, 2.0, (3, 8))
    h = 1e-6
    grad, hess = ground.gradient(x, y, z), ground.hessian(x, y, z)
    for i in range(3):
        step = np.zeros((3, 1))
        step[i] = h
        up, down = (x, y, z) + step, (x, y, z) - step
        assert np.allclose((ground.implicit(*up) - ground.implicit(*down)) / (2 * h), grad[i], atol=1e-7)
        assert np.allclose((ground.gradient(*up) - ground.gradient(*down)) / (2 * h), hess[:, i], atol=1e-6)


def test_the_upright_cone_is_the_drum():
    drum, cone = Cylinder(4.0), Cone(4.0, np.pi / 2)
    lane = np.linspace(0.0, 5.0, 7)
    for answer in ("contact", "wall_angle", "normal", "curvatures"):
        assert np.array_equal(np.asarray(getattr(drum, answer)(lane)), np.asarray(getattr(cone, answer)(lane)))


def test_a_cone_leaning_in_ends_at_its_apex():
    cone = Cone(3.0, np.radians(120.0), wall_height=10.0)
    assert cone.highest_lane == pytest.approx(3.0 * np.tan(np.radians(60.0)))
    assert cone.contact(cone.highest_lane)[0] == pytest.approx(0.0, abs=1e-12)
    assert Cone(3.0, np.radians(60.0), 2.0).highest_lane == 2.0 and Cylinder(3.0).highest_lane == np.inf


def _bowl():
    """A profile: a bowl of radius 3 m sampled at 60 points, its lanes up to 4 m."""
    theta = np.linspace(np.pi - 0.02, 0.6, 60)
    return Profile(3.0 * np.sin(theta), 3.0 * np.cos(theta))


MERIDIANS = GROUNDS + [_bowl()]
LANES["profile"] = np.linspace(0.05, 4.0, 23)


@pytest.mark.parametrize("ground", MERIDIANS, ids=_id)
def test_the_meridian_by_arc_length_is_the_lanes(ground):
    """meridian(arc_length(lane)) gives the lane's contact, wall angle and
    meridian curvature (the two-wheeler's rear contact reads the ground by
    arc length), and the arc length is the chord sum of a fine polyline of
    contacts (an independent measure of the meridian's length)."""
    lane = LANES[ground.name]
    s = ground.arc_length(lane)
    rho, z, beta, kappa, dkappa = ground.meridian(s)
    rho_c, z_c = ground.contact(lane)
    assert np.allclose(rho, rho_c, rtol=0, atol=1e-12) and np.allclose(z, z_c, rtol=0, atol=1e-12)
    assert np.allclose(np.mod(beta, 2 * np.pi), ground.wall_angle(lane), rtol=0, atol=1e-12)
    assert np.allclose(kappa, ground.curvatures(lane)[0], rtol=0, atol=1e-12)
    fine = np.linspace(lane[0], lane[-1], 20001)
    chord = np.sum(np.hypot(*(np.diff(c) for c in ground.contact(fine))))
    assert s[-1] - s[0] == pytest.approx(chord, rel=1e-8)


@pytest.mark.parametrize("ground", MERIDIANS, ids=_id)
def test_the_meridians_derivatives_by_a_complex_step(ground):
    """rho' = cos(beta), z' = sin(beta), beta' = kappa, kappa' = dkappa in
    the arc length, by a complex step through meridian(s): the chain rule
    the two-wheeler's derivation assumes, and that a complex step passes."""
    s = ground.arc_length(LANES[ground.name]) + 1j * 1e-30
    rho, z, beta, kappa, dkappa = ground.meridian(s)
    for value, slope in ((rho, np.cos(beta.real)), (z, np.sin(beta.real)), (beta, kappa.real), (kappa, dkappa.real)):
        assert np.allclose(value.imag / 1e-30, slope, rtol=0, atol=1e-12)


@pytest.mark.parametrize("ground", MERIDIANS, ids=_id)
def test_the_implicit_function_passes_a_complex_step(ground):
    """F and grad F at a complex point: their imaginary parts are the
    gradient's and the Hessian's along the step (the two-wheeler's front
    contact takes its derivatives so), the real parts unchanged."""
    rng = np.random.default_rng(5)
    x, y, z = rng.uniform(0.5, 2.0, (3, 8))
    d = rng.uniform(-1.0, 1.0, (3, 1))
    xc, yc, zc = (v + 1j * 1e-30 * dv for v, dv in zip((x, y, z), d))
    grad, hess = ground.gradient(x, y, z), ground.hessian(x, y, z)
    assert np.allclose(ground.implicit(xc, yc, zc).real, ground.implicit(x, y, z), rtol=0, atol=1e-15)
    assert np.allclose(ground.implicit(xc, yc, zc).imag / 1e-30, np.sum(grad * d, axis=0), rtol=0, atol=1e-12)
    assert np.allclose(ground.gradient(xc, yc, zc).imag / 1e-30, np.einsum("ij...,j...->i...", hess, d[:, 0]),
                       rtol=0, atol=1e-12)
