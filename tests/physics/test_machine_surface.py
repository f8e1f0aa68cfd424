"""The machine on any surface of revolution (docs/machine.md, "On any surface
of revolution", eqs. MS1-MS7): on the globe it is the sphere's machine
(M1-M12) to rounding; on the drum and the cone its orbits satisfy
Newton-Euler rebuilt from 3-D vectors, its wheel fits where its crown
circle stays a tyre's radius inside the wall, the wall of death's rule
(friction g per unit mass, the normal push the centripetal force) holds,
and the tilts for a speed or a rate give that speed or rate back."""

import math
import warnings

import numpy as np
import pytest

from deathsphere.physics.ground import Cone, Cylinder, Plane, Profile, Sphere
from deathsphere.physics.machine import fit_window, meridian_points, ride_orbit, solve_alpha_for_speed
from deathsphere.physics.machine_arrays import MachineArrays, machine_arrays
from deathsphere.physics.machine_surface import (
    fit_window_on,
    meridian_points_on,
    ride_orbit_on,
    solve_alpha_for_rate_on,
    solve_alpha_for_speed_on,
)
from deathsphere.physics.status import Reason, Status
from deathsphere.records.machine_presets import PRESETS

G = 9.80665
FT = 0.3048
KEYS = ("r_g", "omega2", "omega", "period", "v_cm", "v_contact", "spin", "normal", "friction", "mu_required",
        "load_g", "head_clearance", "height")


@pytest.mark.parametrize("name", sorted(PRESETS))
@pytest.mark.parametrize("r", [8 * FT, 3.0])
def test_on_the_sphere_every_output_is_the_spheres_machine(name, r):
    m = machine_arrays(PRESETS[name])
    ground = Sphere(r)
    # the lanes by height, and the sphere's machine at the same lanes' theta
    height = ground.height(np.radians(np.linspace(3, 177, 59)))[:, None]
    theta = ground.theta(height)
    alpha = np.radians(np.linspace(-89, 179, 135))[None, :]
    ref = ride_orbit(theta, alpha, ground, G, m, mu=1.0, max_g=6.0)
    got = ride_orbit_on(height, alpha, ground, G, m, mu=1.0, max_g=6.0)
    np.testing.assert_array_equal(got["status"], ref["status"])
    # the same reasons, those of a wheel, head and contact worded for any wall
    wall = {Reason.MACHINE_NO_FIT_WALL: Reason.MACHINE_NO_FIT, Reason.HEAD_HITS_WALL: Reason.HEAD_HITS,
            Reason.MACHINE_NO_CONTACT_WALL: Reason.MACHINE_NO_CONTACT}
    np.testing.assert_array_equal(np.vectorize(lambda x: wall.get(Reason(x), x))(got["reason"]), ref["reason"])
    assert (ref["status"] == Status.OK).sum() > 200
    for key in KEYS:
        scale = np.nanmax(np.abs(ref[key][np.isfinite(ref[key])]))
        np.testing.assert_allclose(got[key], ref[key], rtol=1e-12, atol=1e-12 * scale, err_msg=key)
    np.testing.assert_allclose(got["rho_contact"], r * np.sin(theta) + 0 * alpha, rtol=1e-12, atol=1e-12 * r)
    np.testing.assert_allclose(got["wall_angle"], np.pi - theta + 0 * alpha, atol=1e-12)
    for key, (rho, z) in meridian_points(theta, alpha, ground, m).items():
        grho, gz = meridian_points_on(height, alpha, ground, m)[key]
        np.testing.assert_allclose(grho, rho, atol=1e-12 * r)
        np.testing.assert_allclose(gz, z, atol=1e-12 * r)
    lo, hi = fit_window(theta, ground, m)
    glo, ghi = fit_window_on(height, ground, m)
    np.testing.assert_allclose(glo, lo, atol=1e-12)
    np.testing.assert_allclose(ghi, hi, atol=1e-12)


@pytest.mark.parametrize("name", ["stunt125", "benchmark-bicycle-rigid"])
def test_on_the_sphere_the_tilts_for_a_speed_are_the_spheres(name):
    m = machine_arrays(PRESETS[name])
    r = 8 * FT
    th, v = np.meshgrid(np.radians(np.linspace(10, 170, 17)), [3.0, 6.0, 9.0, 14.0], indexing="ij")
    height = Sphere(r).height(th.ravel())
    th, v = Sphere(r).theta(height), v.ravel()
    ref = solve_alpha_for_speed(th, v, Sphere(r), G, m)
    got = solve_alpha_for_speed_on(height, v, Sphere(r), G, m)
    np.testing.assert_array_equal(np.isfinite(got), np.isfinite(ref))
    assert np.isfinite(ref).sum() > 40
    np.testing.assert_allclose(got, ref, atol=1e-10)


# ---------------------------------------------------------------------------
# Newton-Euler from 3-D vectors, on the drum and the cone

def _vectors(ground, height, alpha, m: MachineArrays):
    """The contact P, the crown point Q, the axle's centre C, the centre of
    mass G and the axes (e1, u) in 3-D, the meridian plane being x-z (x
    away from the axis, y the direction of travel), from the ground's
    contact and normal and the construction of the tyre (Q on the
    surface's normal a tyre's radius inside P)."""
    rho, z = (float(x) for x in ground.contact(height))
    n_rho, n_z = (float(x) for x in ground.normal(height))
    p, n = np.array([rho, 0.0, z]), np.array([n_rho, 0.0, n_z])
    e1 = np.array([-math.sin(alpha), 0.0, -math.cos(alpha)])
    u = np.array([-math.cos(alpha), 0.0, math.sin(alpha)])
    t = float(m.tyre_radius)
    q = p + t * n
    return p, n, q, q + (float(m.wheel_radius) - t) * u, q + (float(m.com_height) - t) * u, e1, u


def _residual(ground, height, alpha, omega, m: MachineArrays, g=G):
    """|dL_G/dt - (P - G) x F| / (m g h) for the orbit at rate ``omega``,
    the spin solved from the rolling condition as a vector equation (its own
    residual returned too) and L_G from the inertia tensor; and F/m."""
    p, n, q, c, gc, e1, u = _vectors(ground, height, alpha, m)
    zh = np.array([0.0, 0.0, 1.0])
    e2 = np.cross(e1, u)
    # rolling: omega z x C + (omega z + s e1) x (P - C) = 0, one unknown s
    lhs = np.cross(e1, p - c)[:, None]
    rhs = -(np.cross(omega * zh, c) + np.cross(omega * zh, p - c))
    s, *_ = np.linalg.lstsq(lhs, rhs, rcond=None)
    roll = np.linalg.norm(lhs[:, 0] * s[0] - rhs)
    inertia = (float(m.pitch_inertia) * np.outer(e1, e1) + float(m.roll_inertia) * np.outer(e2, e2)
               + float(m.yaw_inertia) * np.outer(u, u))
    lg = inertia @ (omega * zh) + float(m.spin_inertia) * s[0] * e1
    dl = np.cross(omega * zh, lg)
    mass = float(m.mass)
    force = mass * (np.cross(omega * zh, np.cross(omega * zh, gc)) + g * zh)
    torque = np.cross(p - gc, force)
    scale = mass * g * float(m.com_height)
    return np.linalg.norm(dl - torque) / scale, roll, force / mass, n, s[0]


GROUNDS = [Cylinder(16 * FT, 12 * FT), Cylinder(10 * FT, 12 * FT), Cone(4.0, math.radians(80), 5.0),
           Cone(6.0, math.radians(45), 4.0), Cone(3.0, math.radians(100), 2.0)]


@pytest.mark.parametrize("ground", GROUNDS, ids=lambda g: f"{g.name}-{g.radius:.2f}")
@pytest.mark.parametrize("name", ["stunt125", "benchmark-bicycle-rigid", "paper-wheel"])
def test_newton_euler_from_vectors_vanishes_at_the_returned_rate(ground, name):
    m = machine_arrays(PRESETS[name])
    heights = np.linspace(0.3, 0.9 * ground.highest_lane, 7)
    alphas = np.radians(np.linspace(-60, 80, 29))
    orb = ride_orbit_on(heights[:, None], alphas[None, :], ground, G, m)
    has = np.isfinite(orb["omega"])
    assert has.sum() > 20
    for i, k in zip(*np.nonzero(has)):
        res, roll, f, n, s = _residual(ground, heights[i], alphas[k], orb["omega"][i, k], m)
        assert res < 1e-12 and roll < 1e-12 * orb["omega"][i, k] * ground.radius
        np.testing.assert_allclose(s, orb["spin"][i, k], rtol=1e-12)
        # the normal push and the friction (down the wall) from the force vector
        down = np.array([-n[2], 0.0, n[0]])               # -(cos beta, sin beta): n = (-sin beta, cos beta)
        assert abs(f @ n - orb["normal"][i, k]) < 1e-12 * G * orb["load_g"][i, k]
        assert abs(f @ down - orb["friction"][i, k]) < 1e-12 * G * orb["load_g"][i, k]


def test_the_residual_does_detect_a_wrong_rate():
    m, ground = machine_arrays(PRESETS["stunt125"]), Cylinder(16 * FT, 12 * FT)
    orb = ride_orbit_on(1.5, math.radians(20), ground, G, m)
    assert orb["status"] == Status.OK
    assert _residual(ground, 1.5, math.radians(20), float(orb["omega"]) * 1.01, m)[0] > 1e-3


# ---------------------------------------------------------------------------
# the wall of death's rule

@pytest.mark.parametrize("name", ["stunt125", "benchmark-bicycle-rigid"])
def test_on_the_drum_friction_carries_the_weight_and_the_wall_the_centripetal_force(name):
    m, radius = machine_arrays(PRESETS[name]), 16 * FT
    ground = Cylinder(radius, 12 * FT)
    alpha = np.radians(np.linspace(2, 60, 30))
    orb = ride_orbit_on(5 * FT, alpha, ground, G, m)
    ok = orb["status"] == Status.OK
    assert ok.sum() > 10
    # F/m = -Omega^2 r_G rho-hat + g z-hat, and on a vertical wall the normal is -rho-hat
    np.testing.assert_allclose(orb["friction"][ok], -G, rtol=1e-14)
    # the centre of mass turns on r_G = R - t - (h - t) cos(alpha), off the contact's circle
    t, h = float(m.tyre_radius), float(m.com_height)
    r_g = radius - t - (h - t) * np.cos(alpha[ok])
    np.testing.assert_allclose(orb["r_g"][ok], r_g, rtol=1e-14)
    np.testing.assert_allclose(orb["normal"][ok], orb["v_cm"][ok] ** 2 / r_g, rtol=1e-12)
    np.testing.assert_allclose(orb["mu_required"][ok], G * r_g / orb["v_cm"][ok] ** 2, rtol=1e-12)
    np.testing.assert_allclose(orb["v_contact"][ok], orb["v_cm"][ok] * radius / r_g, rtol=1e-12)


def test_a_point_mass_rider_on_the_drum_leans_along_the_force_and_needs_mu_tan_alpha():
    # textbook wall of death: a point mass h above a knife edge, no inertia,
    # the body along the contact force: tan(alpha) = g r_G / v^2 = mu needed
    m = MachineArrays(*(np.asarray(x, dtype=float) for x in (100.0, 1.0, 0.3, 0.0, 0, 0, 0, 0, 1.2)))
    radius = 5.0
    alpha = np.radians(np.linspace(5, 60, 12))
    orb = ride_orbit_on(2.0, alpha, Cylinder(radius, 6.0), G, m)
    r_g = radius - np.cos(alpha)
    np.testing.assert_allclose(orb["v_cm"] ** 2, G * r_g / np.tan(alpha), rtol=1e-12)
    np.testing.assert_allclose(orb["mu_required"], np.tan(alpha), rtol=1e-12)


def test_a_point_mass_rider_on_the_cone_balances_as_on_any_wall():
    # the body along F whatever the wall: tan(alpha) = g / (Omega^2 r_G);
    # the normal push F . n with n = (-sin beta, cos beta)
    m = MachineArrays(*(np.asarray(x, dtype=float) for x in (80.0, 1.1, 0.3, 0.0, 0, 0, 0, 0, 1.5)))
    beta = math.radians(70)
    cone = Cone(4.0, beta, 6.0)
    alpha = np.radians(np.linspace(10, 60, 11))
    orb = ride_orbit_on(1.0, alpha, cone, G, m)
    rho = 4.0 + 1.0 / math.tan(beta)
    r_g = rho - 1.1 * np.cos(alpha)
    om2 = G / (np.tan(alpha) * r_g)
    np.testing.assert_allclose(orb["omega2"], om2, rtol=1e-12)
    np.testing.assert_allclose(orb["normal"], om2 * r_g * math.sin(beta) + G * math.cos(beta), rtol=1e-12)


# ---------------------------------------------------------------------------
# the fit (MS6) against the crown circle itself, and the head's clearance

@pytest.mark.parametrize("ground", [Cylinder(2.0, 3.0), Cone(1.5, math.radians(75), 2.0),
                                    Cone(2.0, math.radians(110), 1.0)], ids=lambda g: g.name)
def test_where_the_wheel_fits_its_crown_circle_stays_a_tyres_radius_inside(ground):
    # a big wheel in a small arena, so that the fit window is narrow
    a, t = 0.6, 0.1
    m = MachineArrays(*(np.asarray(x, dtype=float) for x in (100.0, 0.8, a, t, 1, 1, 1, 0.5, 1.5)))
    height = 0.5
    alphas = np.radians(np.linspace(-120, 200, 1601))
    lo, hi = fit_window_on(height, ground, m)
    psi = np.linspace(0, 2 * np.pi, 721)
    fits_seen = 0
    for alpha in alphas:
        p, n, q, c, _, e1, u = _vectors(ground, height, alpha, m)
        e2 = np.cross(e1, u)
        ring = c[:, None] + (a - t) * (-np.cos(psi)[None, :] * u[:, None] + np.sin(psi)[None, :] * e2[:, None])
        gap = ground.clearance(np.hypot(ring[0], ring[1]), ring[2]) - t
        inside = lo < alpha < hi
        fits_seen += inside
        if inside:
            assert gap.min() > -1e-12
        elif min(abs(alpha - lo), abs(alpha - hi)) > 1e-2:
            assert gap.min() < 0
    assert fits_seen > 100


def test_the_head_clearance_is_the_grounds_distance_of_the_head():
    m = machine_arrays(PRESETS["stunt125"])
    ground = Cylinder(10 * FT, 12 * FT)
    alpha = np.radians([5.0, 30.0, 80.0])
    orb = ride_orbit_on(1.5, alpha, ground, G, m)
    head_rho = 10 * FT - float(m.tyre_radius) - (float(m.head_height) - float(m.tyre_radius)) * np.cos(alpha)
    np.testing.assert_allclose(orb["head_clearance"], 10 * FT - head_rho, rtol=1e-14)


# ---------------------------------------------------------------------------
# the lane for a speed and for a rate

@pytest.mark.parametrize("ground", GROUNDS[:4], ids=lambda g: f"{g.name}-{g.radius:.2f}")
def test_the_tilts_for_a_speed_and_a_rate_give_them_back(ground):
    m = machine_arrays(PRESETS["stunt125"])
    h, v = np.meshgrid([0.5, 1.5, 3.0], [6.0, 11.0, 16.0, 25.0], indexing="ij")
    h, v = h.ravel(), v.ravel()
    tilts = solve_alpha_for_speed_on(h, v, ground, G, m)
    rows, cols = np.nonzero(np.isfinite(tilts))
    assert rows.size >= h.size
    orb = ride_orbit_on(h[rows], tilts[rows, cols], ground, G, m)
    np.testing.assert_allclose(orb["v_cm"], v[rows], rtol=1e-9)
    # every tilt on a fine scan whose speed crosses v is found (no root is lost)
    scan = np.radians(np.linspace(-89.9, 179.9, 20001))
    for i in range(h.size):
        sv = ride_orbit_on(h[i], scan, ground, G, m)
        d = np.where(sv["status"] != Status.NO_FIT, sv["v_cm"] - v[i], np.nan)
        crossings = np.sum((d[:-1] * d[1:] < 0) & (np.abs(np.diff(sv["v_cm"])) < 1.0))
        assert np.isfinite(tilts[i]).sum() == crossings
    rates = np.array([1.0, 2.0, 3.5, 5.0])[:, None] + 0 * h[None, :]
    hh = np.broadcast_to(h, rates.shape).ravel()
    tilts = solve_alpha_for_rate_on(hh, rates.ravel(), ground, G, m)
    rows, cols = np.nonzero(np.isfinite(tilts))
    assert rows.size > 10
    orb = ride_orbit_on(hh[rows], tilts[rows, cols], ground, G, m)
    np.testing.assert_allclose(orb["omega"], rates.ravel()[rows], rtol=1e-9)


def test_singular_lanes_give_statuses_not_warnings():
    m = machine_arrays(PRESETS["stunt125"])
    cone = Cone(2.0, math.radians(120), 5.0)          # leans in: apex at 3.46 m
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        orb = ride_orbit_on(np.array([0.0, 1.0, cone.apex_height]), np.radians([0.0, 90.0, 30.0]), cone, G, m)
        lo, hi = fit_window_on(np.array([cone.apex_height]), cone, m)
        tilts = solve_alpha_for_speed_on(np.array([cone.apex_height, 1.0]), np.array([5.0, 5.0]), cone, G, m)
    assert np.all(orb["status"] != Status.OK)
    assert np.isnan(lo).all() and np.isnan(hi).all()
    assert np.isnan(tilts[0]).all()


def test_the_floor_clearance_is_the_lowest_of_the_tyre_sampled_and_the_head():
    m = machine_arrays(PRESETS["stunt125"])
    a, t = float(m.wheel_radius), float(m.tyre_radius)
    ground = Cylinder(16 * FT, 12 * FT)
    psi = np.linspace(0, 2 * np.pi, 3601)
    heights = np.array([0.02, 0.05, 0.3, 1.0])
    alphas = np.radians(np.linspace(-60, 60, 25))
    orb = ride_orbit_on(heights[:, None], alphas[None, :], ground, G, m)
    head_z = meridian_points_on(heights[:, None], alphas[None, :], ground, m)["head"][1]
    for i, h in enumerate(heights):
        for k, alpha in enumerate(alphas):
            _, _, _, c, _, e1, u = _vectors(ground, h, alpha, m)
            ring = c[:, None] + (a - t) * (-np.cos(psi) * u[:, None] + np.sin(psi) * np.cross(e1, u)[:, None])
            want = min(ring[2].min() - t, head_z[i, k]) - ground.lowest
            assert abs(orb["floor_clearance"][i, k] - want) < 1e-6
    hits = orb["floor_clearance"] <= 0
    assert hits.any() and (~hits).any()
    assert np.all(orb["reason"][hits & (orb["reason"] != Reason.MACHINE_NO_FIT_WALL)
                                & (orb["reason"] != Reason.HEAD_HITS_WALL)] == Reason.MACHINE_HITS_FLOOR)
    assert np.all(orb["reason"][~hits] != Reason.MACHINE_HITS_FLOOR)


class _ProtocolOnly:
    """A ground that answers the protocol and nothing else (no radius, no
    class the physics could know), as any meridian from samples would."""

    name = "profile"

    def __init__(self, inner):
        self._inner = inner
        self.lowest, self.highest_lane = inner.lowest, inner.highest_lane

    def __getattr__(self, key):
        if key in ("contact", "wall_angle", "normal", "curvatures", "clearance"):
            return getattr(self._inner, key)
        raise AttributeError(key)


def test_the_machine_needs_of_a_ground_its_protocol_only():
    m = machine_arrays(PRESETS["stunt125"])
    cone = Cone(4.0, math.radians(80), 5.0)
    h, alpha = np.linspace(0.2, 4.0, 9)[:, None], np.radians(np.linspace(-40, 80, 13))[None, :]
    ref, got = ride_orbit_on(h, alpha, cone, G, m), ride_orbit_on(h, alpha, _ProtocolOnly(cone), G, m)
    for key in ref:
        np.testing.assert_array_equal(got[key], ref[key], err_msg=key)
    np.testing.assert_array_equal(solve_alpha_for_speed_on(h[:, 0], np.full(9, 12.0), _ProtocolOnly(cone), G, m),
                                  solve_alpha_for_speed_on(h[:, 0], np.full(9, 12.0), cone, G, m))


# ---------------------------------------------------------------------------
# flat ground and a profile: the machine through the same protocol

def test_a_point_mass_rider_on_flat_ground_leans_as_the_textbook_says():
    """A point mass h above a knife edge on flat ground, the contact R from
    the turn's centre: the body lies along the contact force, so its lean
    phi from the vertical is tan(phi) = v_G^2 / (g r_G) with r_G = R - h
    sin(phi) (the textbook's tan(phi) = v^2 / (g R) for the centre of mass's
    own circle)."""
    m = MachineArrays(*(np.asarray(x, dtype=float) for x in (100.0, 1.0, 0.3, 0.0, 0, 0, 0, 0, 1.2)))
    turn = 20.0
    alpha = np.radians(np.linspace(20, 85, 14))
    orb = ride_orbit_on(turn, alpha, Plane(), G, m)
    assert np.all(orb["status"] == Status.OK)
    phi = np.pi / 2 - alpha
    r_g = turn - 1.0 * np.sin(phi)
    np.testing.assert_allclose(orb["r_g"], r_g, rtol=1e-14)
    np.testing.assert_allclose(np.tan(phi), orb["v_cm"] ** 2 / (G * r_g), rtol=1e-12)
    # flat ground carries the weight, friction the centripetal force
    np.testing.assert_allclose(orb["normal"], G, rtol=1e-15)
    np.testing.assert_allclose(orb["mu_required"], np.tan(phi), rtol=1e-12)


def test_a_wide_tyre_leans_further_by_the_motorcycle_formula():
    """A tyre of cross-section radius t: the contact force runs from the
    contact to the centre of mass, at phi_eff from the vertical, tan(phi_eff)
    = v_G^2 / (g r_G); the machine's own lean phi is larger, phi = phi_eff +
    asin(t sin(phi_eff) / (h - t)) (the triangle contact - crown centre -
    centre of mass: PQ = t upright, QG = h - t along the machine)."""
    h, t, turn = 0.6, 0.09, 15.0
    m = MachineArrays(*(np.asarray(x, dtype=float) for x in (200.0, h, 0.3, t, 0, 0, 0, 0, 1.4)))
    alpha = np.radians(np.linspace(25, 85, 13))
    orb = ride_orbit_on(turn, alpha, Plane(), G, m)
    assert np.all(orb["status"] == Status.OK)
    phi = np.pi / 2 - alpha
    r_g = turn - (h - t) * np.sin(phi)                       # G above the crown's centre, t over the contact
    phi_eff = np.arctan(orb["omega"] ** 2 * r_g / G)
    np.testing.assert_allclose(phi, phi_eff + np.arcsin(t * np.sin(phi_eff) / (h - t)), rtol=1e-12)
    # the point rider's lean would be phi_eff: the tyre adds lean
    assert np.all(phi > phi_eff)


FLAT_AND_PROFILES = [Plane(), Profile(np.linspace(0.0, 12.0, 61), 0.08 * np.linspace(0.0, 12.0, 61) ** 2),
                     Profile(np.full(7, 16 * FT), np.linspace(0.0, 12 * FT, 7))]


@pytest.mark.parametrize("ground", FLAT_AND_PROFILES, ids=["plane", "bowl", "drum-sampled"])
@pytest.mark.parametrize("name", ["stunt125", "benchmark-bicycle-rigid"])
def test_newton_euler_from_vectors_on_flat_ground_and_profiles(ground, name):
    m = machine_arrays(PRESETS[name])
    lanes = np.array([6.0, 15.0, 40.0]) if isinstance(ground, Plane) else np.linspace(0.6, 3.3, 4)
    alphas = np.radians(np.linspace(-30, 85, 24))
    orb = ride_orbit_on(lanes[:, None], alphas[None, :], ground, G, m)
    ok = orb["status"] == Status.OK
    assert ok.sum() > 10
    for i, k in zip(*np.nonzero(np.isfinite(orb["omega"]))):
        res, roll, f, n, s = _residual(ground, lanes[i], alphas[k], orb["omega"][i, k], m)
        assert res < 1e-12 and roll < 1e-12 * orb["omega"][i, k] * 20.0
        np.testing.assert_allclose(s, orb["spin"][i, k], rtol=1e-12)
        assert abs(f @ n - orb["normal"][i, k]) < 1e-12 * G * orb["load_g"][i, k]


def test_a_drum_sampled_as_a_profile_is_the_drum():
    m = machine_arrays(PRESETS["stunt125"])
    drum, sampled = Cylinder(16 * FT, 12 * FT), FLAT_AND_PROFILES[2]
    h, alpha = np.linspace(0.2, 3.0, 8)[:, None], np.radians(np.linspace(-40, 85, 26))[None, :]
    ref, got = ride_orbit_on(h, alpha, drum, G, m), ride_orbit_on(h, alpha, sampled, G, m)
    np.testing.assert_array_equal(got["status"], ref["status"])
    assert (ref["status"] == Status.OK).sum() > 50
    for key in KEYS + ("floor_clearance",):
        np.testing.assert_allclose(got[key], ref[key], rtol=1e-9, atol=1e-9, err_msg=key)


def test_on_flat_ground_the_tyre_stands_on_the_floor_it_rides():
    """The floor of MS7 is flat ground itself: the tyre's lowest point is the
    contact (0 above it, to rounding), not a hit; a wheel tilted below the
    ground does not fit."""
    m = machine_arrays(PRESETS["stunt125"])
    orb = ride_orbit_on(20.0, np.radians([-10.0, 10.0, 30.0, 60.0, 89.0]), Plane(), G, m)
    assert orb["status"][0] == Status.NO_FIT and orb["reason"][0] == Reason.MACHINE_NO_FIT_WALL
    assert np.all(orb["status"][1:] == Status.OK)
    assert np.all(np.abs(orb["floor_clearance"][1:]) < 1e-12)


@pytest.mark.parametrize("ground", FLAT_AND_PROFILES[:2], ids=["plane", "bowl"])
def test_the_tilts_for_a_speed_and_a_rate_give_them_back_on_flat_ground_and_a_bowl(ground):
    m = machine_arrays(PRESETS["stunt125"])
    lanes = np.array([8.0, 30.0]) if isinstance(ground, Plane) else np.array([1.0, 4.0])
    h, v = (x.ravel() for x in np.meshgrid(lanes, [6.0, 11.0, 16.0], indexing="ij"))
    tilts = solve_alpha_for_speed_on(h, v, ground, G, m)
    rows, cols = np.nonzero(np.isfinite(tilts))
    assert np.unique(rows).size == h.size
    np.testing.assert_allclose(ride_orbit_on(h[rows], tilts[rows, cols], ground, G, m)["v_cm"], v[rows], rtol=1e-9)
    rate = v / (h if isinstance(ground, Plane) else np.asarray(ground.contact(h)[0]))
    tilts = solve_alpha_for_rate_on(h, rate, ground, G, m)
    rows, cols = np.nonzero(np.isfinite(tilts))
    assert np.unique(rows).size == h.size
    np.testing.assert_allclose(ride_orbit_on(h[rows], tilts[rows, cols], ground, G, m)["omega"], rate[rows],
                               rtol=1e-9)
