"""The single-contact machine's vertical loop inside a closed profile
(docs/machine.md eqs. M25-M30).  On a 16-ft globe sampled at 2001 points it
is the globe's loop (eqs. M21-M24, physics/machine.py's closed forms) in
every output, to the sampling's accuracy; on an ellipsoid
(tests/data/ellipsoid_dome.csv, semi-axes 4 m across and 3 m up) the least
top speed and the bottom's load follow from the ellipse's own curvature
and effective inertia written here, and the lap time, the bottom's speed,
the friction needed and the largest load from the one-degree-of-freedom
Lagrangian in the ellipse's own parameter, integrated by solve_ivp."""

from pathlib import Path

import numpy as np
import pytest
from sampled_grounds import sampled_sphere

from deathsphere.physics.ground import Profile, Sphere
from deathsphere.physics.machine import vertical_loop
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.physics.machine_loop_on import machine_loop_on
from deathsphere.physics.meridian_loop import Loop
from deathsphere.physics.status import REASON_TEXT, Status
from deathsphere.records.machine_presets import PRESETS

G = 9.80665
R = 16 * 0.3048 / 2                              # a 16-ft globe
ELLIPSOID = Path(__file__).resolve().parents[1] / "data" / "ellipsoid_dome.csv"
A_AXIS, B_AXIS = 4.0, 3.0                        # the ellipsoid's semi-axes: across, up


@pytest.fixture(scope="module")
def globe_loop():
    return Loop.of(sampled_sphere(R))


@pytest.fixture(scope="module")
def ellipse_loop():
    return Loop.of(Profile(*np.loadtxt(ELLIPSOID, delimiter=",", skiprows=1).T))


#: Agreement with the globe's closed forms, measured on the sphere sampled at
#: 2001 points (relative, or absolute below 1): the speeds, rates, loads and
#: radii 1e-7 to 4.7e-6 (the spline's curvature is the sphere's to 1.7e-6
#: at the axis, where the loop's top and bottom are); the friction needed
#: 4.6e-6 and its worst point, on a flat maximum, 1.4e-4 rad, with kappa'
#: the grid's central difference (with the spline's own kappa', which jumps
#: at every sample, they were 6e-3 and 0.034 rad).
AGREE = 1e-5
LOOSER = {"mu_required": 2e-5, "phi_worst": 5e-4}


@pytest.mark.parametrize("name", sorted(PRESETS))
def test_on_a_sampled_sphere_every_output_is_the_globes(globe_loop, name):
    m = machine_arrays(PRESETS[name])
    v_top = np.array([3.0, 4.5, 5.0, 6.0, 8.0, 11.0])          # too slow, near the least top speed, ..., fast
    got = machine_loop_on(globe_loop, v_top, G, m, mu=0.8, max_g=6.0)
    ref = vertical_loop(np.full(v_top.shape, np.pi / 2), v_top, Sphere(np.full(v_top.shape, R)), G, m, 0.8, 6.0)
    assert got["status"].tolist() == ref["status"].tolist()
    assert {Status.NO_CONTACT, Status.OVER_G} <= set(ref["status"].tolist())
    for key in ref:
        if key in ("status", "reason"):
            continue
        a, b = np.asarray(got[key], dtype=float), np.asarray(ref[key], dtype=float)
        assert np.array_equal(np.isnan(a), np.isnan(b)), key
        ok = ~np.isnan(b)
        assert np.all(np.abs(a[ok] - b[ok]) <= LOOSER.get(key, AGREE) * np.maximum(np.abs(b[ok]), 1.0)), (key, a, b)


def test_on_a_sampled_sphere_the_lap_and_the_largest_load_are_the_circles(globe_loop):
    """The lap time from M21 by quadrature in phi (written here), and the
    load largest at the bottom (sec. 10)."""
    from scipy.integrate import quad

    mach = PRESETS["stunt125"]
    m = machine_arrays(mach)
    v_top = 6.0
    got = machine_loop_on(globe_loop, v_top, G, m)
    mass, h, a, ip, js = mach.mass, mach.com_height, mach.wheel_radius, mach.pitch_inertia, mach.spin_inertia
    r_g = R - h
    inertia = mass * r_g ** 2 + ip + js * (R ** 2 - 2 * R * a) / a ** 2            # M21's M (per phidot^2)
    rate2 = lambda phi: (v_top / r_g) ** 2 + 2 * mass * G * r_g * (1 - np.cos(phi)) / inertia  # noqa: E731
    lap = 2 * quad(lambda phi: 1 / np.sqrt(rate2(phi)), 0.0, np.pi, epsabs=0, epsrel=1e-12)[0]
    np.testing.assert_allclose(got["period"], lap, rtol=1e-6)
    np.testing.assert_allclose(got["load_max"], got["load_bottom"], rtol=1e-6)
    np.testing.assert_allclose(got["phi_load_max"], np.pi, atol=1e-3)


# --- an ellipse's own geometry ---------------------------------------------------------

def _ellipse(u):
    """The meridian x = A sin u, z = B (1 - cos u) (u = 0 the bottom, pi the
    top): point, unit tangent (increasing u), inward normal, curvature, ds/du."""
    x, z = A_AXIS * np.sin(u), B_AXIS * (1 - np.cos(u))
    dx, dz = A_AXIS * np.cos(u), B_AXIS * np.sin(u)
    speed = np.hypot(dx, dz)
    kappa = A_AXIS * B_AXIS / speed ** 3
    tangent = np.array([dx, dz]) / speed
    normal = np.array([-tangent[1], tangent[0]])
    return np.array([x, z]), tangent, normal, kappa, speed


def _machine(name="stunt125"):
    mach = PRESETS[name]
    return mach.mass, mach.com_height, mach.wheel_radius, mach.pitch_inertia, mach.spin_inertia


def test_on_an_ellipsoid_the_top_and_the_bottom_are_the_ellipses(ellipse_loop):
    """At the top and the bottom the curvature is B / A^2; N = 0 at the top
    at the least top speed (contact's rate sdot, v_G = (1 - h kappa) sdot:
    N/m = (1 - h kappa) kappa sdot^2 - g), and the energy with the same M at
    both ends gives the bottom's rate and load."""
    mass, h, a, ip, js = _machine()
    kappa = B_AXIS / A_AXIS ** 2
    stretch = 1 - h * kappa
    v_min = np.sqrt(G * stretch / kappa)
    inertia = mass * stretch ** 2 + ip * kappa ** 2 + js * (1 - 2 * a * kappa) / a ** 2
    v_top = np.array([1.3 * v_min, 2.0 * v_min])
    got = machine_loop_on(ellipse_loop, v_top, G, machine_arrays(PRESETS["stunt125"]))
    # the spline's curvature at the axis, from 801 samples: measured 4.8e-6
    np.testing.assert_allclose(got["v_top_min"], v_min, rtol=1e-5)
    sdot_b2 = (v_top / stretch) ** 2 + 2 * mass * G * (2 * B_AXIS - 2 * h) / inertia
    np.testing.assert_allclose(got["v_bottom"], stretch * np.sqrt(sdot_b2), rtol=1e-7)
    np.testing.assert_allclose(got["load_bottom"], (stretch * kappa * sdot_b2 + G) / G, rtol=1e-5)
    np.testing.assert_allclose(got["r_g"], stretch / kappa, rtol=2e-5)                   # measured 9.6e-6
    assert got["status"].tolist() == [Status.OK, Status.OK]
    slow = machine_loop_on(ellipse_loop, 0.999 * v_min, G, machine_arrays(PRESETS["stunt125"]))
    assert int(slow["status"]) == Status.NO_CONTACT


def test_on_an_ellipsoid_the_lagrangian_integrated_gives_the_lap_the_friction_and_the_load(ellipse_loop):
    """The one degree of freedom in the ellipse's parameter u: L = (1/2) mu(u)
    udot^2 - m g z_G(u), mu = M(kappa(u)) (ds/du)^2, integrated from the top
    down to the bottom by solve_ivp; the contact force from Newton,
    F = m (a_G + g z-hat), a_G from G(u) = P + h n differentiated by central
    differences."""
    from scipy.integrate import solve_ivp

    mass, h, a, ip, js = _machine()
    v_top = 8.0

    def inertia(u):
        _, _, _, kappa, speed = _ellipse(u)
        return (mass * (1 - h * kappa) ** 2 + ip * kappa ** 2 + js * (1 - 2 * a * kappa) / a ** 2) * speed ** 2

    def height(u):
        p, _, n, _, _ = _ellipse(u)
        return p[1] + h * n[1]

    def com(u):
        p, _, n, _, _ = _ellipse(u)
        return p + h * n

    d = 1e-5

    def rhs(_, y):
        u, w = y
        d_inertia = (inertia(u + d) - inertia(u - d)) / (2 * d)
        d_height = (height(u + d) - height(u - d)) / (2 * d)
        return [w, -(0.5 * d_inertia * w * w + mass * G * d_height) / inertia(u)]

    top = np.pi
    _, _, _, kappa_top, speed_top = _ellipse(top)
    w0 = -v_top / ((1 - h * kappa_top) * speed_top)
    bottom = lambda _, y: y[0]  # noqa: E731
    bottom.terminal = True
    sol = solve_ivp(rhs, (0.0, 10.0), [top, w0], events=bottom, rtol=1e-11, atol=1e-12, dense_output=True)
    t_half = sol.t_events[0][0]
    got = machine_loop_on(ellipse_loop, v_top, G, machine_arrays(PRESETS["stunt125"]))
    np.testing.assert_allclose(got["period"], 2 * t_half, rtol=1e-6)
    u_b, w_b = sol.y_events[0][0]
    _, _, _, kappa_b, speed_b = _ellipse(0.0)
    np.testing.assert_allclose(got["v_bottom"], (1 - h * kappa_b) * speed_b * abs(w_b), rtol=1e-6)

    times = np.linspace(0.0, t_half, 4001)
    u, w = sol.sol(times)
    acc = np.array(rhs(0.0, [u, w]))[1]
    g_u = (com(u + d) - com(u - d)) / (2 * d)
    g_uu = (com(u + d) - 2 * com(u) + com(u - d)) / d ** 2
    a_g = g_uu * w ** 2 + g_u * acc
    force = a_g + np.array([0.0, G])[:, None]                                 # per mass
    _, tangent, normal, _, _ = _ellipse(u)
    push, along = np.sum(force * normal, axis=0), np.sum(force * tangent, axis=0)
    assert np.all(push > 0)
    need = np.abs(along) / push
    # measured 3.6e-5 and 1.9e-6 (801 samples; the reference's largest of 4001 points in time)
    np.testing.assert_allclose(got["mu_required"], need.max(), rtol=2e-4)
    np.testing.assert_allclose(got["load_max"], np.hypot(push, along).max() / G, rtol=2e-5)
    i = np.argmax(need)
    phi = np.arctan2(B_AXIS * np.sin(u[i]), -A_AXIS * np.cos(u[i]))            # the tangent's turn from the top
    np.testing.assert_allclose(got["phi_worst"], phi, atol=5e-3)     # measured 1.7e-3: the reference's spacing


def test_a_machine_taller_than_the_tightest_bend_does_not_fit_and_a_low_roof_hits_the_head(ellipse_loop):
    tightest = B_AXIS ** 2 / A_AXIS                                         # the ellipse's least radius, at its sides
    mach = PRESETS["stunt125"]
    m = machine_arrays(mach)
    fits = machine_loop_on(ellipse_loop, 20.0, G, m._replace(com_height=np.array(0.98 * tightest),
                                                             head_height=np.array(2.5)))
    tall = machine_loop_on(ellipse_loop, 20.0, G, m._replace(com_height=np.array(1.02 * tightest),
                                                             head_height=np.array(2.5)))
    assert int(fits["status"]) != Status.NO_FIT and int(tall["status"]) == Status.NO_FIT
    assert "tightest bend" in REASON_TEXT[int(tall["reason"])]
    # a head above the roof at the bottom: 2 B - head from it
    head = machine_loop_on(ellipse_loop, 20.0, G, m._replace(head_height=np.array(2 * B_AXIS + 0.1)))
    assert int(head["status"]) == Status.NO_FIT and "head" in REASON_TEXT[int(head["reason"])]
    np.testing.assert_allclose(head["head_clearance"], -0.1, atol=1e-6)
    # a head inside every centre of curvature (the least radius 2.25 m) is nearest its own wall: head away
    np.testing.assert_allclose(machine_loop_on(ellipse_loop, 20.0, G, m)["head_clearance"], mach.head_height,
                               rtol=1e-6)


def test_an_overhang_bending_away_from_the_centre_holds_the_machine_at_no_speed():
    """A waist (rho = 3 sin t (1 - 0.35 sin^2 t), z = 3.9 cos t): above it the
    wall leans out and bends away from the centre, so by M28-M29 the normal
    force there, (1 - h kappa) kappa sdot^2 + g cos(beta), is negative at
    every speed."""
    t = np.linspace(np.pi, 0.0, 801)
    waisted = Loop.of(Profile(np.abs(3 * np.sin(t) * (1 - 0.35 * np.sin(t) ** 2)), 3.9 * np.cos(t)))
    assert np.min(waisted.kappa) < 0
    m = machine_arrays(PRESETS["paper-wheel"])
    got = machine_loop_on(waisted, np.array([5.0, 50.0]), G, m)
    assert got["status"].tolist() == [Status.NO_CONTACT] * 2
    assert all("overhangs" in REASON_TEXT[int(r)] for r in got["reason"])
    assert np.all(np.isinf(got["v_top_min"]))
