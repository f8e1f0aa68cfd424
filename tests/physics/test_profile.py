"""Profile: a surface of revolution from samples of its meridian reproduces
the sphere and the drum it was sampled from, and refuses bad samples
naming the row."""

import numpy as np
import pytest

from deathsphere.physics import revolution
from deathsphere.physics.ground import Cylinder, Ground, Profile, Sphere
from deathsphere.physics.ground.profile import ProfileError

R = 3.0
GLOBE = Sphere(R)


def _sampled_globe(n):
    theta = np.linspace(np.pi, 0.05, n)          # from the bottom up, short of the top
    return Profile(R * np.sin(theta), R * np.cos(theta))


FINE = _sampled_globe(1000)
LANES = np.linspace(0.05, 5.9, 61)


def test_profile_speaks_the_protocol():
    assert isinstance(FINE, Ground)
    assert np.isclose(FINE.lowest, -R) and np.isclose(FINE.highest_lane, R * (1 + np.cos(0.05)))


def test_a_sampled_globe_is_the_globe():
    for got, want in zip(FINE.contact(LANES), GLOBE.contact(LANES)):
        assert np.allclose(got, want, rtol=0, atol=1e-6 * R)
    assert np.allclose(FINE.wall_angle(LANES), GLOBE.wall_angle(LANES), rtol=0, atol=1e-6)
    for got, want in zip(FINE.normal(LANES), GLOBE.normal(LANES)):
        assert np.allclose(got, want, rtol=0, atol=1e-6)
    for got, want in zip(FINE.curvatures(LANES), GLOBE.curvatures(LANES)):
        assert np.allclose(got, want, rtol=1e-6, atol=0)
    # the heights are the lanes asked for
    assert np.allclose(FINE.contact(LANES)[1] - FINE.lowest, LANES, rtol=0, atol=1e-12)


def test_the_wheel_on_a_sampled_globe_rolls_as_on_the_globe():
    profile = _sampled_globe(200)
    alpha = np.radians(np.linspace(3.0, 60.0, 12))[None, :]
    got = revolution.wheel_orbit(profile, LANES[:, None], alpha, 0.3, 0.5, 9.81)
    want = revolution.wheel_orbit(GLOBE, LANES[:, None], alpha, 0.3, 0.5, 9.81)
    assert np.array_equal(got["status"], want["status"]) and (want["status"] == 0).sum() > 100
    ok = want["status"] == 0
    for key in ("omega", "v_cm", "r_prime"):
        assert np.allclose(got[key][ok], want[key][ok], rtol=1e-6, atol=0), key
    # the forces to 1e-6 g (near a lost contact the push is a small difference)
    for key in ("normal", "friction"):
        assert np.allclose(got[key][ok], want[key][ok], rtol=0, atol=1e-6 * 9.81), key
    pressed = ok & (want["normal"] > 0.1 * 9.81)
    assert np.allclose(got["mu_required"][pressed], want["mu_required"][pressed], rtol=1e-6, atol=1e-6)


def test_a_sampled_drum_is_the_drum():
    drum = Cylinder(4.8768, 6.0)
    z = np.linspace(0.0, 6.0, 7)
    profile = Profile(np.full(z.size, drum.radius), z)
    lanes = np.linspace(0.0, 6.0, 25)
    for got, want in zip(profile.contact(lanes), drum.contact(lanes)):
        assert np.allclose(got, want, rtol=0, atol=1e-12)
    assert np.allclose(profile.wall_angle(lanes), np.pi / 2, atol=1e-12)
    for got, want in zip(profile.curvatures(lanes), drum.curvatures(lanes)):
        assert np.allclose(got, want, rtol=0, atol=1e-12)
    assert np.allclose(profile.clearance([1.0, 4.0], [2.0, 5.0]), drum.clearance([1.0, 4.0], [2.0, 5.0]), atol=1e-12)
    got = revolution.wheel_orbit(profile, lanes, np.radians(12.0), 0.3, 0.5, 9.81)
    want = revolution.wheel_orbit(drum, lanes, np.radians(12.0), 0.3, 0.5, 9.81)
    assert np.array_equal(got["status"], want["status"])
    assert np.allclose(got["mu_required"], want["mu_required"], rtol=1e-10)


def test_clearance_and_the_implicit_function_are_the_signed_distance():
    rng = np.random.default_rng(5)
    rho, z = rng.uniform(0.2, 2.5, 40), rng.uniform(-2.0, 2.0, 40)
    assert np.allclose(FINE.clearance(rho, z), GLOBE.clearance(rho, z), rtol=0, atol=1e-6)
    x, y = rho * np.cos(1.1), rho * np.sin(1.1)
    # the sphere's signed distance |p| - r, its gradient p/|p| and Hessian (I - p p^T/|p|^2)/|p|
    p = np.stack((x, y, z))
    dist = np.linalg.norm(p, axis=0)
    assert np.allclose(FINE.implicit(x, y, z), dist - R, atol=1e-6)
    assert np.allclose(FINE.gradient(x, y, z), p / dist, atol=1e-6)
    hess = (np.eye(3)[:, :, None] - p[:, None] * p[None, :] / dist ** 2) / dist
    assert np.allclose(FINE.hessian(x, y, z), hess, atol=1e-5)


@pytest.mark.parametrize("rho, z, words", [
    ([1.0, 1.0, 1.0], [0.0, 1.0, 2.0], "at least 4 points"),
    ([1.0, 1.0, np.nan, 1.0], [0.0, 1.0, 2.0, 3.0], "row 3: rho and z must be finite"),
    ([1.0, 1.0, 1.0, 1.0], [0.0, 1.0, np.inf, 3.0], "row 3: rho and z must be finite"),
    ([1.0, -1.0, 1.0, 1.0], [0.0, 1.0, 2.0, 3.0], "row 2: rho is the distance from the axis"),
    ([1.0, 1.0, 1.0, 1.0], [0.0, 1.0, 1.0, 3.0], "row 3: z must rise strictly"),
    ([1.0, 1.0, 1.0, 1.0], [0.0, 2.0, 1.0, 3.0], "row 3: z must rise strictly"),
    ([1.0, 1.0, 2.0, 3.0, 4.0], [0.0, 1.0, 2.0, 2.2, 2.4], "row 2: the meridian turns by 45"),
])
def test_bad_profiles_are_refused_naming_the_row(rho, z, words):
    with pytest.raises(ProfileError, match=words) as err:
        Profile(rho, z)
    assert "\n" not in str(err.value)


def test_a_gentle_bend_is_not_a_kink():
    # a bend of 20 degrees between chords is a corner the spline can carry
    angles = np.radians([90.0, 90.0, 70.0, 70.0])
    steps = np.stack((np.cos(angles), np.sin(angles)))
    pts = np.concatenate((np.array([[2.0], [0.0]]), np.array([[2.0], [0.0]]) + np.cumsum(steps, axis=1)), axis=1)
    Profile(pts[0], pts[1])


def test_the_lanes_kept_are_never_stale():
    """The profile keeps its last lanes' spline values (an orbit asks each
    answer of the same heights in turn): a height array changed in place,
    or another one, is answered afresh, as a new profile answers it."""
    from deathsphere.physics.ground import Cylinder, Profile

    drum = Cylinder(3.0)
    rho, z = np.full(9, 3.0), np.linspace(0.0, 8.0, 9)
    prof = Profile(rho, z)
    h = np.array([1.0, 2.0, 3.0])
    first = prof.contact(h)[1].copy()
    h += 0.5                                   # the same array, new values
    np.testing.assert_allclose(prof.contact(h)[1], h, rtol=0, atol=1e-12)
    assert not np.allclose(first, prof.contact(h)[1])
    np.testing.assert_allclose(prof.normal(np.array([4.0]))[0], drum.normal(np.array([4.0]))[0], atol=1e-12)
