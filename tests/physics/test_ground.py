"""The ground protocol (deathsphere.physics.ground): each ground's answers
agree with each other and with an independent reading of its surface."""

import numpy as np
import pytest

from deathsphere.physics.ground import Ground, Plane, Sphere

GROUNDS = [Sphere(2.4384), Plane()]
LANES = {"sphere": np.linspace(0.05, 4.8, 23), "plane": np.linspace(0.5, 30.0, 23)}


@pytest.mark.parametrize("ground", GROUNDS, ids=lambda g: g.name)
def test_every_ground_speaks_the_protocol(ground):
    assert isinstance(ground, Ground)


@pytest.mark.parametrize("ground", GROUNDS, ids=lambda g: g.name)
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


@pytest.mark.parametrize("ground", GROUNDS, ids=lambda g: g.name)
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
