"""What the two-wheeler's 3-D view draws (geometry.outline), beyond the
paper: the rims are the wheels' circles in their planes and touch the
sphere at the contacts, the steer turns the front wheel's plane by the
steer angle about the steer axis, the head is at the head point."""

import numpy as np
import pytest

from deathsphere.physics.two_wheeler import motion
from deathsphere.physics.two_wheeler.geometry import RIM_POINTS, frames, outline
from deathsphere.physics.ground import Plane, Sphere
from deathsphere.physics.two_wheeler.parameters import BENCHMARK_GRAVITY, benchmark_bicycle

GLOBE = 2.4384      # a 16-foot globe's radius, m
SPHERE, FLAT = Sphere(GLOBE), Plane()
#: The benchmark's gravity (Table 1), at which these cases were set: the run passes it.
G = BENCHMARK_GRAVITY
B = benchmark_bicycle()
HEAD = (0.3, -1.7)


def _states(n=7, seed=3):
    """Random states inside the globe, their pitch solved (the front contact on the sphere)."""
    rng = np.random.default_rng(seed)
    q = np.zeros((8, n))
    q[0] = rng.uniform(np.radians(60), np.radians(170), n)
    q[1] = rng.uniform(-np.pi, np.pi, n)
    q[2] = rng.uniform(-np.pi, np.pi, n)
    q[3] = rng.uniform(-0.6, 0.6, n)
    q[5], q[7] = rng.uniform(-9, 9, (2, n))
    q[6] = rng.uniform(-0.6, 0.6, n)
    return motion.pitch(q, motion.parameter_values(B, G, SPHERE), SPHERE)


@pytest.fixture(scope="module")
def drawn():
    q = _states()
    return q, outline(q, B, SPHERE, HEAD)


@pytest.mark.parametrize("rim, centre, radius, plane", [("rear_rim", "rear_wheel", B.rR, "L"),
                                                        ("front_rim", "front_wheel", B.rF, "E")])
def test_the_rims_are_the_wheels_circles_in_their_planes(drawn, rim, centre, radius, plane):
    q, out = drawn
    pts = out[rim]
    assert pts.shape == (3, RIM_POINTS, q.shape[1])
    offset = pts - out[centre][:, None]
    np.testing.assert_allclose(np.linalg.norm(offset, axis=0), radius, rtol=1e-13)
    axle = frames(q, B.lam, SPHERE)[plane][1]        # the wheel turns about its frame's y axis
    np.testing.assert_allclose(np.sum(offset * axle[:, None], axis=0), 0.0, atol=1e-13)
    # the points go once round, evenly
    chord = np.linalg.norm(np.diff(pts, axis=1), axis=0)
    np.testing.assert_allclose(chord, 2 * radius * np.sin(np.pi / RIM_POINTS), rtol=1e-12)


def test_the_rims_touch_the_sphere_at_the_contacts_and_nowhere_cross_it(drawn):
    q, out = drawn
    for rim, contact in (("rear_rim", "P"), ("front_rim", "Q")):
        np.testing.assert_allclose(out[rim][:, 0], out[contact], rtol=0, atol=1e-14)
        reach = np.linalg.norm(out[rim], axis=0)
        assert np.all(reach <= GLOBE + 1e-9)
    assert np.max(np.abs(np.linalg.norm(out["P"], axis=0) - GLOBE)) < 1e-12
    assert np.max(np.abs(np.linalg.norm(out["Q"], axis=0) - GLOBE)) < 1e-9


def test_upright_on_flat_ground_the_drawing_is_the_benchmarks_reference_configuration():
    """Lean, pitch and steer zero: the benchmark's positions (x forward, z
    down from the rear contact), the rims in the plane y = 0, and the head
    tube on the steer axis through (w + c, 0) tilted lam back."""
    out = outline(np.zeros((8, 1)), B, FLAT, head=HEAD)
    np.testing.assert_allclose(out["head"][:, 0], [HEAD[0], 0.0, HEAD[1]], atol=1e-15)
    np.testing.assert_allclose(out["rear_wheel"][:, 0], [0.0, 0.0, -B.rR], atol=1e-15)
    np.testing.assert_allclose(out["front_wheel"][:, 0], [B.w, 0.0, -B.rF], atol=1e-15)
    np.testing.assert_allclose(out["rear_rim"][1], 0.0, atol=1e-15)
    np.testing.assert_allclose(out["front_rim"][1], 0.0, atol=1e-15)
    for end in ("steer_bottom", "steer_top"):
        x, _, z = out[end][:, 0]
        assert x == pytest.approx(B.w + B.c + z * np.tan(B.lam), abs=1e-15)
    assert out["steer_bottom"][2, 0] == pytest.approx(-2 * B.rF)
    assert out["steer_top"][2, 0] < out["steer_bottom"][2, 0]
    np.testing.assert_allclose(out["bar_right"][:, 0] - out["bar_left"][:, 0], [0.0, B.w / 2, 0.0], atol=1e-15)


@pytest.mark.parametrize("steer", [0.3, -0.5])
def test_the_steer_turns_the_front_wheels_plane_about_the_steer_axis(steer):
    """Upright on flat ground the rear wheel's plane is y = 0; the front
    wheel's normal is y turned by the steer about the steer axis
    (sin lam, 0, cos lam), which is normal to y: the two planes meet at the
    steer angle, and the front rim's normal has no part along that axis."""
    q = np.zeros((8, 1))
    q[6] = steer
    q = motion.pitch(q, motion.parameter_values(B, G, FLAT), FLAT)
    out = outline(q, B, FLAT, head=HEAD)
    rim = out["front_rim"][:, :, 0] - out["front_wheel"][:, :1]
    normal = np.cross(rim[:, 0], rim[:, RIM_POINTS // 4])
    normal /= np.linalg.norm(normal)
    cos_pitch, sin_pitch = np.cos(q[4, 0]), np.sin(q[4, 0])
    axis = np.array([np.sin(B.lam) * cos_pitch + np.cos(B.lam) * sin_pitch, 0.0,
                     np.cos(B.lam) * cos_pitch - np.sin(B.lam) * sin_pitch])
    assert abs(normal @ axis) < 1e-12
    assert np.degrees(np.arccos(abs(normal[1]))) == pytest.approx(np.degrees(abs(steer)), abs=1e-9)
    # a positive steer turns the wheel to the rider's right (+y), as the benchmark's
    assert np.sign(rim[1, 1] - rim[1, 0]) == np.sign(steer)
    # the front contact is on the ground, the lowest rim point
    assert out["Q"][2, 0] == pytest.approx(0.0, abs=1e-12)
    assert np.all(out["front_rim"][2] <= 1e-12)
