"""The two-wheeler on any surface of revolution, the ground as data
(docs/two-wheeler.md sec. 12): through the one generated module for every
such ground, the globe's and flat ground's turns are those of their own
closed forms, and the front contact found from the ground's implicit
function is where the rim touches it."""

import numpy as np
import pytest

from deathsphere.physics.ground import Cone, Cylinder, Plane, Sphere
from deathsphere.physics.two_wheeler import geometry, grounds, rim_contact, stability, steady
from deathsphere.physics.two_wheeler.parameters import BENCHMARK_GRAVITY, benchmark_bicycle
from deathsphere.records.two_wheeler_presets import TWO_WHEELERS

G = BENCHMARK_GRAVITY
GLOBE = 2.4384      # a 16-foot globe's radius, m
#: What a steady turn carries that both paths give (the eigenvalues apart).
QUANTITIES = ("lean", "steer", "pitch", "steer_torque", "normal_rear", "normal_front", "friction_rear",
              "friction_front", "load_g", "omega", "v_front", "v_cm")


def _agree(new, old, keys):
    """Every key of two tables of turns equal to 1e-12 of the quantity's largest magnitude."""
    for key in keys:
        scale = np.nanmax(np.abs(old[key]))
        np.testing.assert_allclose(new[key], old[key], rtol=1e-12, atol=1e-12 * scale, err_msg=key)


@pytest.mark.parametrize("machine, radius, speeds", [("benchmark-bicycle", GLOBE, (5.0, 7.0)),
                                                     ("stunt125-steer", 4.0, (12.0, 16.0))])
def test_the_globe_through_the_general_path_is_the_globes(machine, radius, speeds):
    """The sphere as a surface of revolution (its meridian by arc length,
    the front contact by Newton's method on its implicit function) against
    its own closed forms (theta, the farthest rim point): every turn's
    lean, steer, pitch, steer torque, forces and both spectra to 1e-12."""
    b = TWO_WHEELERS[machine].parameters()
    sphere = Sphere(radius)
    theta = np.deg2rad([105.0, 130.0, 155.0])
    theta, speed = (x.ravel() for x in np.meshgrid(theta, speeds))
    old = stability.turns_with_stability(theta, b, sphere, G, speed=speed)
    new = stability.turns_with_stability(sphere.height(theta), b, grounds.OnRevolution(sphere), G, speed=speed)
    assert new["count"].tolist() == old["count"].tolist() and old["count"].min() >= 1
    _agree(new, old, QUANTITIES + ("head_clearance", "theta_rear", "theta_front", "eigenvalues_free",
                                   "eigenvalues_locked"))
    assert new["stability_free"].tolist() == old["stability_free"].tolist()


def test_flat_ground_through_the_general_path_is_flat_grounds():
    """A turn of radius R on flat ground as a lane of a surface of
    revolution (the plane's meridian, the lowest rim point by Newton's
    method) against flat ground's own turn of curvature 1/R: every quantity
    to 1e-12; its spectrum is flat ground's four eigenvalues and the pair
    +-i omega of a circle whose centre is displaced from the axis (on flat
    ground any centre will do, so that mode is neutral, seen from the axis
    turning at omega)."""
    b = benchmark_bicycle()
    radius, speed = (x.ravel() for x in np.meshgrid([5.0, 20.0, 60.0], [3.0, 5.0]))
    old = stability.turns_with_stability(1 / radius, b, Plane(), G, speed=speed)
    new = stability.turns_with_stability(radius, b, grounds.OnRevolution(Plane()), G, speed=speed)
    assert new["count"].tolist() == old["count"].tolist() and old["count"].min() >= 1
    _agree(new, old, QUANTITIES)
    for mode in ("free", "locked"):
        found = np.isfinite(old["lean"])
        flat, general = old[f"eigenvalues_{mode}"][found], new[f"eigenvalues_{mode}"][found]
        omega = old["omega"][found]
        expected = np.concatenate([flat, 1j * omega[:, None], -1j * omega[:, None]], axis=1)
        scale = np.abs(expected).max()
        for want, got in zip(expected, general):
            # the same spectrum as sets: each eigenvalue matched to the nearest
            distance = np.abs(want[:, None] - got[None, :])
            assert np.all(distance.min(axis=1) < 1e-12 * scale), mode
            assert sorted(distance.argmin(axis=1).tolist()) == list(range(got.size)), mode


@pytest.mark.parametrize("ground", [Cylinder(4.8768, 6.0), Cone(4.0, np.radians(80.0), 6.0),
                                    Cone(12.0, np.radians(45.0)), Cone(3.0, np.radians(100.0), 2.5)],
                         ids=["drum", "well", "track", "overhang"])
def test_the_front_contact_is_on_the_surface_and_the_rim_tangent_there(ground):
    """At steady-turn configurations on each wall the front contact found by
    Newton's method lies on the surface to 1e-12 m, the rim's tangent there
    is tangent to the surface, and no point of the rim is outside the
    surface (a sampling of the rim against the ground's clearance: an
    independent reading of "the rim point that touches")."""
    b = TWO_WHEELERS["stunt125-steer"].parameters()
    height = np.array([0.5, 1.2, 2.0])
    lean, steer = np.meshgrid(np.radians([-30.0, -10.0, 0.0, 15.0]), np.radians([-5.0, 0.0, 4.0]))
    h, lean, steer = np.broadcast_arrays(height[:, None, None], lean[None], steer[None])
    q = steady.configuration(h.ravel(), lean.ravel(), steer.ravel(), b, ground)
    pts = geometry.points(q, b, ground)
    Q, centre, E = pts["Q"], pts["front_wheel"], pts["frames"]["E"]
    grad = rim_contact.gradient(ground, Q)
    normal = grad / np.linalg.norm(grad, axis=0)
    rho, z = np.hypot(Q[0], Q[1]), -Q[2]
    assert np.abs(ground.clearance(rho, z)).max() < 1e-12
    # the rim's tangent at Q: along the front axle crossed with Q's radius
    tangent = np.cross(E[1], Q - centre, axis=0) / b.rF
    assert np.abs(np.sum(tangent * normal, axis=0)).max() < 1e-12
    angle = np.linspace(0.0, 2 * np.pi, 721)[:, None]
    rim = centre[:, None] + b.rF * (np.sin(angle) * E[0][:, None] + np.cos(angle) * E[2][:, None])
    assert ground.clearance(np.hypot(rim[0], rim[1]), -rim[2]).min() > -1e-12
