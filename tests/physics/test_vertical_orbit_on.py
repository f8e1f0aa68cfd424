"""A wheel's vertical loop inside a closed profile (docs/surfaces.md eqs.
S9-S12).  On a sphere sampled at 2001 points it is the globe's vertical loop
(McDonald 1993 eqs. 26-28b, the closed forms of physics/vertical_orbit.py)
in every column ``vertical`` prints, to the sampling's accuracy; on an
ellipsoid (tests/data/ellipsoid_dome.csv, semi-axes 4 m across and 3 m up)
the least top speed, the top's and the bottom's normal force, the worst
point and the lap time agree with the ellipse's own curvature and an
adaptive quadrature along its parametrisation, written here."""

from pathlib import Path

import numpy as np
import pytest
import sampled_grounds

import deathsphere
from deathsphere.physics.ground import Profile
from deathsphere.physics.meridian_loop import Loop, loop_closure
from deathsphere.results.vertical import COLUMNS, POINT_COLUMNS

R, G = 3.0, 9.80665
ELLIPSOID = Path(__file__).resolve().parents[1] / "data" / "ellipsoid_dome.csv"
A_AXIS, B_AXIS = 4.0, 3.0                     # the ellipsoid's semi-axes: across, up


@pytest.fixture(scope="module")
def sampled_sphere():
    """The globe of radius 3 m sampled at 2001 points from its bottom to its top."""
    return sampled_grounds.sampled_sphere(R)


#: Agreement with the globe, measured (relative, or absolute below 1): the
#: spline's curvature is the sphere's to 2e-7 inside and 1.7e-6 at the
#: axis, where the loop's top and bottom are, and a force per mass, a
#: difference of v^2 kappa_C and g, is off by that of the loop's largest;
#: the worst point sits on a flat maximum, which the curvature's ripple
#: moves by more (3.2e-5 of phi at 5 % above the least top speed), and its
#: mu divides by a small normal force there (2.2e-5; the first slip 5e-6);
#: the lap time's quadrature and sampling error is 1.5e-10.
WORST_POINT = {"normal_per_mass_m_s2": 3e-5, "friction_magnitude_per_mass_m_s2": 3e-5, "phi_worst_deg": 5e-5,
               "mu_required": 3e-5, "phi_slip_deg": 1e-5}
AGREE = 3e-6
#: Not the globe's to compare: the sphere's radius (empty on a profile), the
#: stability (compared on its own below), the reason (the loop's
#: no_contact names its own equation).
#: The largest force per mass of a loop (at its bottom), the scale of every force's error.
FORCE_SCALE = "normal_bottom_per_mass_m_s2"
NOT_COMPARED = {"r_m", "stability", "stability_method", "growth_rate_1_s", "reason"}


def _agree(got, ref, columns, tolerances=None):
    for name in columns:
        if name in NOT_COMPARED:
            continue
        a, b = got[name], ref[name]
        if a.dtype.kind in "OUS":
            assert a.tolist() == b.tolist(), name
            continue
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        assert np.array_equal(np.isnan(a), np.isnan(b)), name
        tol = (tolerances or {}).get(name, AGREE)
        ok = ~np.isnan(b)
        # a force per mass is a difference of v^2 kappa_C and g: its error is the curvature's of the largest push
        largest = (np.nan_to_num(ref[FORCE_SCALE]) if FORCE_SCALE in ref.columns
                   else np.nanmax(np.abs(ref["normal_per_mass_m_s2"])))       # point by point: the lap's largest
        scale = np.maximum(np.abs(b), largest if name.endswith("per_mass_m_s2") else 1.0)
        assert np.all(np.abs(a[ok] - b[ok]) <= tol * np.maximum(scale[ok], 1.0)), (name, a, b)


@pytest.mark.parametrize("k", [0.5, 0.2, 0.0])
def test_on_a_sampled_sphere_every_column_is_the_globes(sampled_sphere, k):
    v_top = [4.0, 5.3, 6.0, 7.0, 10.0, 20.0]       # too slow, near the least top speed, ..., fast
    got = deathsphere.vertical_sweep(90, v_top, surface="profile", profile=sampled_sphere, k=k, mu=0.5,
                                     stability=False).table()
    ref = deathsphere.vertical_sweep(90, v_top, k=k, mu=0.5, stability=False).table()
    assert list(got.columns)[: len(COLUMNS)] == list(COLUMNS)            # appended, never reordered
    assert list(got.columns)[len(COLUMNS):] == ["surface", "height_m"]
    assert set(ref["status"].tolist()) == ({"no_contact", "ok"} if k == 0.0 else {"no_contact", "ok", "slips"})
    _agree(got, ref, COLUMNS, WORST_POINT)
    assert got["surface"].tolist() == ["profile"] * 6
    np.testing.assert_allclose(got["height_m"], 2 * R, rtol=1e-12)
    assert np.isnan(got["r_m"]).all()
    for name in ("stability", "stability_method"):                     # not asked for: empty, as the globe's
        assert got[name].tolist() == ref[name].tolist() == [""] * 6


def test_the_stability_columns_are_the_globes(sampled_sphere):
    """A stable and an unstable loop (a light rim, k = 0.1, in a resonance
    tongue) and k = 0: the globe's verdicts, methods and growth rates (the
    Floquet analyses of the sphere's and of the profile's equations of
    motion: tests/physics/test_loop_floquet.py)."""
    v_top = np.array([1.2, 1.1, 1.2]) * np.sqrt(9.80665 * 1.5)
    got, ref = ({name: [] for name in ("stability", "stability_method", "growth_rate_1_s")} for _ in range(2))
    for v, k in zip(v_top, (0.5, 0.1, 0.0)):
        on = deathsphere.vertical_sweep(90, v, a=1.5, k=k, surface="profile", profile=sampled_sphere).table()
        globe = deathsphere.vertical_sweep(90, v, a=1.5, k=k).table()
        for name in got:
            got[name].append(on[name][0])
            ref[name].append(globe[name][0])
    got, ref = ({name: np.array(values) for name, values in d.items()} for d in (got, ref))
    assert got["stability"].tolist() == ref["stability"].tolist() == ["stable", "unstable", "unknown"]
    assert got["stability_method"].tolist() == ref["stability_method"].tolist() == [
        "floquet", "floquet", "not-analysed-k0"]
    np.testing.assert_allclose(got["growth_rate_1_s"][:2], ref["growth_rate_1_s"][:2], rtol=1e-6, atol=1e-9)
    assert ref["growth_rate_1_s"][1] > 0.1 and np.isnan(got["growth_rate_1_s"][2])


def test_a_top_rate_is_the_globes_too(sampled_sphere):
    got = deathsphere.vertical_sweep(90, phidot_top=[2.0, 3.0], surface="profile", profile=sampled_sphere,
                                     stability=False).table()
    ref = deathsphere.vertical_sweep(90, phidot_top=[2.0, 3.0], stability=False).table()
    _agree(got, ref, COLUMNS, WORST_POINT)


def test_point_by_point_it_is_the_globes(sampled_sphere):
    got = deathsphere.vertical_sweep(90, [6.0, 7.0], surface="profile", profile=sampled_sphere, points=13,
                                     mu=0.3).table()
    ref = deathsphere.vertical_sweep(90, [6.0, 7.0], points=13, mu=0.3).table()
    _agree(got, ref, POINT_COLUMNS)
    assert list(got.columns) == list(POINT_COLUMNS) + ["surface", "height_m"]


# --- an ellipsoid: the ellipse's own geometry ------------------------------------

def _ellipse(u, a, k, g, v_top):
    """The loop's descent on the ellipse (A sin u, B (1 + cos u)), u = 0 at
    the top: speed^2, normal force and friction per mass, the centre's path
    element, from the ellipse's parametrisation (not the spline)."""
    w = np.hypot(A_AXIS * np.cos(u), B_AXIS * np.sin(u))          # |dP/du|
    kappa = A_AXIS * B_AXIS / w ** 3
    n_z = -A_AXIS * np.cos(u) / w                                  # the inward normal's vertical part
    z_c = B_AXIS * (1 + np.cos(u)) + a * n_z
    z_c_top = 2 * B_AXIS - a
    v2 = v_top ** 2 + 2 * g * (z_c_top - z_c) / (2 * k + 1)
    normal = v2 * kappa / (1 - a * kappa) + g * n_z
    along = 2 * k / (2 * k + 1) * g * B_AXIS * np.sin(u) / w
    return v2, normal, along, (1 - a * kappa) * w


def test_on_an_ellipsoid_the_least_top_speed_is_where_the_top_presses_nothing():
    a, k = 0.3, 0.5
    top_radius = A_AXIS ** 2 / B_AXIS - a                          # 1 / kappa_C at the top
    t = deathsphere.vertical_sweep(90, [8.0, 12.0], a=a, k=k, surface="profile", profile=str(ELLIPSOID),
                                   stability=False).table()
    # measured: 4.3e-6 (the spline's curvature at the axis, 801 samples)
    np.testing.assert_allclose(t["v_top_min_m_s"], np.sqrt(G * top_radius), rtol=2e-5)
    np.testing.assert_allclose(t["r_prime_m"], top_radius, rtol=3e-5)
    v = np.array([8.0, 12.0])
    np.testing.assert_allclose(t["normal_top_per_mass_m_s2"], v ** 2 / top_radius - G, rtol=1e-4)
    v_b2 = v ** 2 + 2 * G * 2 * (B_AXIS - a) / (2 * k + 1)
    np.testing.assert_allclose(t["v_bottom_m_s"], np.sqrt(v_b2), rtol=1e-9)
    np.testing.assert_allclose(t["normal_bottom_per_mass_m_s2"], v_b2 / top_radius + G, rtol=1e-4)
    assert t["status"].tolist() == ["ok", "ok"]
    slow = deathsphere.vertical_sweep(90, 0.999 * np.sqrt(G * top_radius), a=a, surface="profile",
                                      profile=str(ELLIPSOID), stability=False).table()
    assert slow["status"].tolist() == ["no_contact"]


def test_on_an_ellipsoid_the_lap_time_and_worst_point_are_the_ellipses():
    from scipy.integrate import quad
    from scipy.optimize import minimize_scalar

    a, k, v_top = 0.3, 0.5, 8.0
    t = deathsphere.vertical_sweep(90, v_top, a=a, k=k, surface="profile", profile=str(ELLIPSOID),
                                   stability=False).table()

    def dt(u):
        v2, _, _, ds = _ellipse(u, a, k, G, v_top)
        return ds / np.sqrt(v2)

    lap = 2 * quad(dt, 0.0, np.pi, epsabs=0, epsrel=1e-12, limit=200)[0]
    np.testing.assert_allclose(t["period_s"], lap, rtol=1e-7)              # measured 1.5e-8

    def mu(u):
        _, normal, along, _ = _ellipse(u, a, k, G, v_top)
        return along / normal

    grid = np.linspace(0.0, np.pi, 4001)
    u0 = grid[np.argmax(mu(grid))]
    best = minimize_scalar(lambda u: -mu(u), bounds=(u0 - 1e-3, u0 + 1e-3), method="bounded",
                           options={"xatol": 1e-12})
    np.testing.assert_allclose(t["mu_required"], mu(best.x), rtol=1e-5)    # measured 1.5e-6
    # phi is the turn of the tangent from the top: tan(phi) = B tan(u) / A on the ellipse
    phi = np.degrees(np.arctan2(B_AXIS * np.sin(best.x), A_AXIS * np.cos(best.x)))
    np.testing.assert_allclose(t["phi_worst_deg"], phi, rtol=0, atol=1e-4)  # measured 5e-6 deg


def test_a_wheel_wider_than_the_tightest_bend_does_not_fit():
    tightest = B_AXIS ** 2 / A_AXIS                                 # the ellipse's least radius, at its sides
    status = [deathsphere.vertical_sweep(90, 20.0, a=a, surface="profile", profile=str(ELLIPSOID),
                                         stability=False).table() for a in (0.98 * tightest, 1.02 * tightest)]
    assert [t["status"][0] for t in status] == ["ok", "no_fit"]
    assert "tightest bend" in status[1]["reason"][0]


# --- which profiles close -----------------------------------------------------------

def test_a_profile_closes_only_on_the_axis_at_both_ends_without_a_corner():
    t = np.linspace(np.pi / 2, 0.0, 60)
    on_a_floor = Profile(3 * np.sin(t), 3 * np.cos(t))             # a hemisphere standing on the floor
    assert "closed below" in loop_closure(on_a_floor)
    u = np.linspace(-1.0, 1.0, 81)                                  # a lens: two arcs meeting on the axis
    lens = Profile(np.maximum(np.sqrt(4.0 - u ** 2) - np.sqrt(3.0), 0.0), u)
    assert "corner" in loop_closure(lens)
    ellipsoid = Profile(*np.loadtxt(ELLIPSOID, delimiter=",", skiprows=1).T)
    assert loop_closure(ellipsoid) == ""
    loop = Loop.of(ellipsoid)
    assert loop.turns_one_way and loop.s.size % 2 == 1             # Simpson's rule: an even number of intervals


def _waisted(waist):
    """A closed profile with a waist: rho = 3 sin t (1 - waist sin^2 t), z = 3.9 cos t."""
    t = np.linspace(np.pi, 0.0, 801)
    return Profile(np.abs(3 * np.sin(t) * (1 - waist * np.sin(t) ** 2)), 3.9 * np.cos(t))


def test_an_overhang_bending_away_from_the_centre_holds_the_wheel_at_no_speed():
    """At the waist the wall leans out above it (cos beta < 0 on the way up)
    and bends away from the centre (kappa < 0): by S10 N = v^2 kappa_C + g
    cos(beta) < 0 at every speed there."""
    deep, shallow = _waisted(0.35), _waisted(0.2)
    assert Loop.of(deep).kappa.min() < 0 and not Loop.of(deep).turns_one_way
    t = deathsphere.vertical_sweep(90, [6.0, 30.0, 300.0], surface="profile", profile=deep, stability=False).table()
    assert t["status"].tolist() == ["no_contact"] * 3
    assert all("no top speed holds the wheel" in reason for reason in t["reason"])
    assert np.isnan(t["v_top_min_m_s"]).all()
    fine = deathsphere.vertical_sweep(90, 30.0, surface="profile", profile=shallow, stability=False).table()
    assert fine["status"].tolist() == ["ok"]
    with pytest.raises(deathsphere.ParameterError, match="bends both ways"):
        deathsphere.vertical_sweep(90, 30.0, surface="profile", profile=deep, points=5)


def test_a_wheel_wider_than_the_globe_fits_a_large_profile(tmp_path):
    """The globe's r > a is not asked on a profile: its fit is the curve's (a kappa_max < 1)."""
    big = np.loadtxt(ELLIPSOID, delimiter=",", skiprows=1) * 10.0          # semi-axes 40 m and 30 m
    t = deathsphere.vertical_sweep(90, 30.0, a=3.5, surface="profile", profile=Profile(*big.T),
                                   stability=False).table()
    assert t["status"].tolist() == ["ok"]
    np.testing.assert_allclose(t["r_prime_m"], 10 * A_AXIS ** 2 / B_AXIS - 3.5, rtol=3e-5)
    path = tmp_path / "loops.csv"
    path.write_text("theta,v_top,a\n90,30,3.5\n")
    rows = deathsphere.vertical_input(str(path), surface="profile", profile=Profile(*big.T), stability=False).table()
    assert rows["status"].tolist() == ["ok"] and np.isnan(rows["r_m"]).all()


def test_a_bump_bending_away_from_the_centre_is_left_by_a_fast_wheel():
    """Below the equator a bump bends the wall away from the centre (kappa <
    0) where it still faces up (cos beta > 0): by S10 N = v^2 kappa_C + g
    cos(beta) falls with speed there, and a wheel fast enough for the top
    leaves the wall at the bump."""
    t = np.linspace(np.pi, 0.0, 801)
    bump = Profile(np.abs(R * np.sin(t) * (1 - 0.15 * np.exp(-((t - 2.3) / 0.25) ** 2))), R * np.cos(t))
    loop = Loop.of(bump)
    concave = loop.kappa < 0
    assert concave.any() and np.all(np.cos(loop.beta[concave]) > 0)
    rows = deathsphere.vertical_sweep(90, [5.0, 6.0, 30.0], surface="profile", profile=bump,
                                      stability=False).table()
    v_min = rows["v_top_min_m_s"][0]
    assert 5.0 < v_min < 6.0 and rows["status"].tolist() == ["no_contact"] * 3
    assert "top speed too low" in rows["reason"][0]
    assert all("too fast where the wall bends away" in reason for reason in rows["reason"][1:])
