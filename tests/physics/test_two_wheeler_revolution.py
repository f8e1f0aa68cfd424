"""The two-wheeler on any surface of revolution, the ground as data
(docs/two-wheeler.md sec. 12): through the one generated module for every
such ground, the globe's and flat ground's turns are those of their own
closed forms, and the front contact found from the ground's implicit
function is where the rim touches it."""

import numpy as np
import pytest

from deathsphere.physics.ground import Cone, Cylinder, Plane, Profile, Sphere
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


def _point_wheelbase(w):
    """The benchmark bicycle shrunk to one contact (wheel base w, no trail,
    equal wheels, every mass centre on the line through the contacts, no
    products of inertia) and ride's single-contact machine with its mass,
    centre of mass and inertia (docs/machine.md sec. 1)."""
    import dataclasses

    from machine_calls import arrays

    b0 = benchmark_bicycle()
    b = dataclasses.replace(b0, w=w, c=0.0, rF=b0.rR, xB=0.0, xH=0.0, IBxz=0.0, IHxz=0.0)
    bodies = [(b.mR, -b.rR, b.IRyy, b.IRxx), (b.mB, b.zB, b.IByy, b.IBzz),
              (b.mH, b.zH, b.IHyy, b.IHzz), (b.mF, -b.rF, b.IFyy, b.IFxx)]
    mass = sum(m for m, *_ in bodies)
    z_cm = sum(m * z for m, z, *_ in bodies) / mass
    machine = arrays(mass, -z_cm, b.rR, 0.0, sum(iy + m * (z - z_cm) ** 2 for m, z, iy, _ in bodies),
                     sum(iz for *_, iz in bodies), b.IRyy + b.IFyy)
    return b, machine


@pytest.mark.parametrize("ground, tilt_deg", [(Cylinder(4.8768, 6.0), [15.0, 25.0, 35.0]),
                                              (Cone(4.0, np.radians(80.0), 6.0), [10.0, 20.0, 30.0]),
                                              (Cone(12.0, np.radians(45.0), 6.0), [30.0, 40.0, 50.0])],
                         ids=["drum", "well", "track"])
def test_as_the_wheel_base_vanishes_a_walls_turns_are_rides_single_contact_machine(ground, tilt_deg):
    """An independent derivation: ride's single-contact machine on the same
    wall (docs/machine.md eqs. MS1-MS7, the contact force from the mass
    centre's circle) at tilt alpha gives the contact's speed; the shrunk
    bicycle at that speed and height leans by 90 deg - beta - alpha from
    the wall's normal, with the machine's normal force, mass centre's speed
    and load, to the order of the wheel base."""
    from deathsphere.physics.machine_surface import ride_orbit_on

    w = 1e-3
    b, machine = _point_wheelbase(w)
    height, alpha = np.array([1.0, 2.0, 3.0]), np.radians(tilt_deg)
    orbit = ride_orbit_on(height, alpha, ground, G, machine)
    assert orbit["status"].tolist() == [0, 0, 0]
    out = steady.turns_for_speed(height, orbit["v_contact"], b, ground, G)
    lean = np.pi / 2 - ground.wall_angle(height) - alpha
    # the turn nearest the machine's (a speed may have others, far from it)
    pick = np.nanargmin(np.abs(out["lean"] - lean[:, None]), axis=1)

    def at(key):
        return out[key][np.arange(3), pick]

    # observed 0.0007-0.0022 w: the lean converges linearly with the wheel base
    assert np.abs(at("lean") - lean).max() < 0.005 * w
    np.testing.assert_allclose(at("normal_rear") + at("normal_front"), orbit["normal"], rtol=1e-3 * w)
    np.testing.assert_allclose(at("v_cm"), orbit["v_cm"], rtol=1e-3 * w)
    np.testing.assert_allclose(at("load_g"), orbit["load_g"], rtol=1e-3 * w)


def test_a_shallow_cone_far_out_is_flat_ground():
    """A cone of wall angle 0.01 deg, the lane 20 m from its axis, against
    flat ground's turn of radius 20 m (the separate flat-ground equations):
    the floor there is banked by beta, so the lean from its normal plus
    beta is flat ground's lean from the vertical; lean, steer and steer
    torque agree to 1e-4, and the spectrum is flat ground's four
    eigenvalues and the circle's drift +-i omega, now slightly damped."""
    b = benchmark_bicycle()
    radius, speed, beta = 20.0, 5.0, np.radians(0.01)
    flat = stability.turns_with_stability(1 / radius, b, Plane(), G, speed=speed)
    cone = Cone(10.0, beta)
    height = (radius - 10.0) * np.tan(beta)
    out = stability.turns_with_stability(height, b, cone, G, speed=speed)
    assert out["count"].tolist() == flat["count"].tolist() == [1]
    assert out["lean"][0, 0] + beta == pytest.approx(flat["lean"][0, 0], rel=1e-4)
    for key in ("steer", "steer_torque", "normal_rear", "normal_front", "omega"):
        assert out[key][0, 0] == pytest.approx(flat[key][0, 0], rel=1e-4), key
    omega = flat["omega"][0, 0]
    expected = np.concatenate([flat["eigenvalues_free"][0, 0], [1j * omega, -1j * omega]])
    got = out["eigenvalues_free"][0, 0]
    assert np.all(np.abs(expected[:, None] - got[None, :]).min(axis=1) < 1e-3 * np.abs(expected).max())
    drift = got[np.argmin(np.abs(got - 1j * omega))]
    assert -1e-2 * omega < drift.real < 0


def test_lanes_off_the_wall_get_a_reason_and_no_row():
    """Below the floor, above the wall's top, a non-finite height: no turn,
    the lane's reason; the lane on the wall has its turns."""
    from deathsphere.physics.status import Reason

    b = TWO_WHEELERS["stunt125-steer"].parameters()
    out = steady.turns_for_speed([-0.5, 6.5, np.nan, 2.0], 60 / 3.6, b, Cylinder(4.8768, 6.0), G)
    assert out["count"][:3].tolist() == [0, 0, 0] and out["count"][3] >= 1
    assert out["reason"].tolist() == [Reason.TURN_BAD_LANE] * 3 + [Reason.NONE]
    assert np.isnan(out["lean"][:3]).all()


def test_a_profile_rides_as_the_ground_it_was_sampled_from():
    """Through the same code a profile (its spline by arc length, the front
    contact from its signed distance): sampled from a drum (a straight
    meridian, which the spline reproduces) its turn is the drum's to
    1e-12; sampled from a sphere at 200 points, the globe's closed forms'
    to 1e-7 (the spline's own error).  One lane each: a profile's signed
    distance costs a nearest-point search per call, a second per lane."""
    b = TWO_WHEELERS["stunt125-steer"].parameters()
    drum = Cylinder(4.8768, 6.0)
    z = np.linspace(0.0, 6.0, 7)
    sampled = steady.turns_for_speed(1.0, 16.0, b, Profile(np.full(z.size, drum.radius), z), G)
    exact = steady.turns_for_speed(1.0, 16.0, b, drum, G)
    _agree(sampled, exact, ("lean", "steer", "pitch", "steer_torque", "normal_rear", "normal_front"))
    sphere = Sphere(4.0)
    theta = np.linspace(np.pi, 0.05, 200)
    globe = Profile(sphere.radius * np.sin(theta), sphere.radius * np.cos(theta))
    sampled = steady.turns_for_speed(2.5, 12.0, b, globe, G)
    exact = steady.turns_for_speed(sphere.theta(2.5), 12.0, b, sphere, G)
    assert sampled["count"].tolist() == exact["count"].tolist() == [1]
    for key in ("lean", "steer", "steer_torque", "normal_rear", "normal_front"):
        scale = max(1.0, float(np.abs(exact[key]).max()))
        np.testing.assert_allclose(sampled[key], exact[key], rtol=0, atol=1e-7 * scale, err_msg=key)
