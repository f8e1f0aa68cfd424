"""The machine (docs/machine.md): a single-contact gyrostat's steady
horizontal orbits against independent derivations -- the paper's wheel row
by row, Newton-Euler rebuilt from 3-D vectors, the point-mass rider, the
flat-ground limits (gyroscopic and tyre-width corrections) and the hand
calculation of docs/machine.md sec. 8."""

import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from machine_calls import loop as vertical_loop
from machine_calls import orbit as ride_orbit
from machine_calls import tilts as solve_alpha_for_speed
from deathsphere.physics.region import solve_alpha
from deathsphere.physics.status import Reason, Status
from deathsphere.physics.wheel import horizontal_orbit

G = 9.80665


def paper_wheel(a, k, m=2.0):
    """The paper's wheel as a machine: h = a, t = 0, inertia (k, 2k, k) m a^2,
    spin inertia 2 k m a^2 (the task's statement of the limit)."""
    return dict(mass=m, h=a, a=a, t=0.0, inertia_pitch=2 * k * m * a * a, inertia_yaw=k * m * a * a,
                spin_inertia=2 * k * m * a * a, head=a)


@pytest.mark.parametrize("a, r, k", [(0.3, 3.0, 0.5), (0.3, 2.0, 0.25), (1.0, 1.5, 0.7), (0.05, 10.0, 0.1)])
def test_the_papers_wheel_is_a_machine_row_by_row(a, r, k):
    theta = np.radians(np.linspace(2, 178, 45))[:, None]
    alpha = np.radians(np.linspace(-179.5, 179.5, 160))[None, :]
    wheel = horizontal_orbit(theta, alpha, a, r, k, G, mu=0.8)
    ride = ride_orbit(theta, alpha, r, G, **paper_wheel(a, k), mu=0.8)
    np.testing.assert_array_equal(ride["status"], wheel["status"])
    ok = wheel["status"] == Status.OK
    assert ok.sum() > 300
    for key in ("omega", "period", "v_cm", "normal", "friction", "mu_required"):
        np.testing.assert_allclose(ride[key][ok], wheel[key][ok], rtol=1e-12, atol=1e-12 * G, err_msg=key)
    # the wheel's spin is omega_1 = omega . e1 (eq. 13); the machine's is relative to the frame,
    # which turns at Omega z . e1 = -Omega cos(alpha) about the axle
    cos_a = np.broadcast_to(np.cos(alpha), ok.shape)
    np.testing.assert_allclose(ride["spin"][ok] - ride["omega"][ok] * cos_a[ok], wheel["spin"][ok],
                               rtol=1e-11, atol=1e-11 * np.max(np.abs(wheel["spin"][ok])))
    # load_g = |F|/(m g), the wheel's accel_g combined with gravity
    np.testing.assert_allclose(ride["load_g"][ok], np.hypot(wheel["accel_g"][ok], 1.0), rtol=1e-12)
    # where the wheel fits, the rows agree on the reason of failure too, up to
    # the machine's own reason codes (the same tests, worded for eq. M8)
    same = {Reason.NO_FIT_INSIDE: Reason.MACHINE_NO_FIT, Reason.OMEGA_IMAGINARY: Reason.MACHINE_OMEGA_IMAGINARY,
            Reason.NO_CONTACT_INSIDE: Reason.MACHINE_NO_CONTACT, Reason.SLIPS: Reason.SLIPS,
            Reason.NONE: Reason.NONE, Reason.OMEGA_ZERO: Reason.MACHINE_OMEGA_ZERO}
    mapped = np.vectorize(lambda x: same.get(Reason(x), -1))(wheel["reason"])
    known = mapped >= 0
    np.testing.assert_array_equal(ride["reason"][known], mapped[known])


def test_the_papers_wheel_gives_the_same_tilts_for_a_speed():
    a, r, k = 0.3, 2.0, 0.5
    th, v = np.meshgrid(np.radians(np.linspace(5, 175, 35)), [0.5, 1.0, 3.0, 6.0, 12.0], indexing="ij")
    th, v = th.ravel(), v.ravel()
    ref = solve_alpha(th, a, r, k, G, speed=v)
    p = paper_wheel(a, k)
    got = solve_alpha_for_speed(th, v, r, G, p["mass"], p["h"], p["a"], p["t"], p["inertia_pitch"],
                                p["inertia_yaw"], p["spin_inertia"])
    np.testing.assert_array_equal(np.isfinite(got).sum(axis=1), ref["count"])
    assert ref["count"].sum() > 100
    w = ref["alpha"].shape[1]
    np.testing.assert_allclose(got[:, :w], ref["alpha"], atol=1e-12)


# ---------------------------------------------------------------------------
# Newton-Euler rebuilt from 3-D vectors (no use of the scalar formula M8)

def _newton_euler_residual(theta, alpha, r, m, h, a, t, inertia, js, omega, g=G):
    """|dL_G/dt - torque about G| / (m g h), for a steady orbit at rate
    omega, built from 3-D vectors: the machine's axes, its centre of mass,
    the wheels' spin from the rolling condition solved as a 3x3 linear
    problem, angular momentum from the inertia tensor."""
    z = np.array([0.0, 0.0, 1.0])
    rhat = np.array([1.0, 0.0, 0.0])
    p_hat = np.sin(theta) * rhat + np.cos(theta) * z          # contact direction from the centre
    P = r * p_hat
    up = -np.cos(alpha) * rhat + np.sin(alpha) * z            # up-axis
    axle = np.cross(up, np.cross(z, rhat))                    # e1 with e1 x up = travel = y
    axle /= np.linalg.norm(axle)
    travel = np.cross(axle, up)
    Q = P - t * p_hat                                         # crown circle centre (inside the sphere by t)
    G_ = Q + (h - t) * up
    C = Q + (a - t) * up                                      # wheel centre
    # rolling: v_C + (omega z + s axle) x (P - C) = 0, with v_C = omega z x C
    v_c = omega * np.cross(z, C)
    lhs = v_c + np.cross(omega * z, P - C)
    s = -np.dot(lhs, travel) / np.dot(np.cross(axle, P - C), travel)
    assert np.linalg.norm(lhs + s * np.cross(axle, P - C)) < 1e-9 * (abs(omega) * r + 1)
    Rm = np.column_stack((travel, axle, up))                  # body (roll, pitch, yaw) -> lab
    I_lab = Rm @ np.diag(inertia) @ Rm.T
    L = I_lab @ (omega * z) + js * s * axle
    dL = np.cross(omega * z, L)
    a_g = omega * np.cross(z, omega * np.cross(z, G_))
    F = m * (a_g + g * z)
    torque = np.cross(P - G_, F)
    return np.linalg.norm(dL - torque) / (m * g * max(h, a)), s


@settings(max_examples=60, deadline=None)
@given(theta=st.floats(20, 175), alpha=st.floats(-20, 89), r=st.floats(1.5, 20), h=st.floats(0.1, 1.2),
       a=st.floats(0.1, 0.45), tf=st.floats(0, 0.9), roll=st.floats(1, 50), pitch=st.floats(1, 50),
       yaw=st.floats(1, 50), jf=st.floats(0, 1))
def test_newton_euler_holds_in_3d_vectors(theta, alpha, r, h, a, tf, roll, pitch, yaw, jf):
    t = tf * a
    m = 120.0
    js = jf * pitch
    th, al = np.radians(theta), np.radians(alpha)
    res = ride_orbit(th, al, r, G, m, h, a, t, pitch, yaw, js, h + 1)
    if not np.isfinite(res["omega"]):
        return
    residual, s = _newton_euler_residual(th, al, r, m, h, a, t, (roll, pitch, yaw), js, float(res["omega"]))
    assert residual < 1e-9
    assert float(res["spin"]) == pytest.approx(s, rel=1e-10)


def test_point_mass_rider_leans_along_acceleration_minus_gravity():
    """Massless wheels, no inertia: the contact-to-CoM line is parallel to
    a_G - g (independent vectors: positions and the CoM's acceleration)."""
    rng = np.random.default_rng(1)
    n = 400
    theta = rng.uniform(0.3, 3.0, n)
    alpha = rng.uniform(-0.3, 1.5, n)
    r, h, a, t = 2.45, 0.9, 0.3, rng.uniform(0, 0.25, n)
    res = ride_orbit(theta, alpha, r, G, 100.0, h, a, t, 0.0, 0.0, 0.0, 1.7)
    ok = np.isfinite(res["omega"])
    assert ok.sum() > 100
    th, al, tt, om = theta[ok], alpha[ok], t[ok], res["omega"][ok]
    P = r * np.stack((np.sin(th), np.cos(th)))                # (r-hat, z) components
    Q = (r - tt) * np.stack((np.sin(th), np.cos(th)))
    Gc = Q + (h - tt) * np.stack((-np.cos(al), np.sin(al)))
    acc = np.stack((-om ** 2 * Gc[0], np.zeros_like(om)))     # uniform circular motion of G
    f = acc - np.stack((np.zeros_like(om), -G * np.ones_like(om)))
    line = Gc - P
    cross = line[0] * f[1] - line[1] * f[0]
    assert np.max(np.abs(cross) / (np.hypot(*line) * np.hypot(*f))) < 1e-12


# ---------------------------------------------------------------------------
# flat ground: sphere radius -> infinity at a fixed turn radius

def _flat(R, v, h, a, t, m, pitch, yaw, js, r=1e8):
    """The tilt for CoM speed v on a circle of contact radius R at the
    bottom of a huge sphere; returns (lean from vertical, CoM radius)."""
    theta = np.pi - np.arcsin(R / r)
    roots = solve_alpha_for_speed([theta], [v], r, G, m, h, a, t, pitch, yaw, js)[0]
    roots = roots[np.isfinite(roots)]
    # the upright-ish root (lean below 90 deg)
    alpha = roots[(roots > 0) & (roots < np.pi / 2)]
    assert alpha.size == 1
    res = ride_orbit(theta, alpha[0], r, G, m, h, a, t, pitch, yaw, js, h + 1)
    assert res["status"] == Status.OK
    return np.pi / 2 - alpha[0], float(res["r_g"])


@pytest.mark.parametrize("js", [0.0, 0.5, 2.0])
def test_flat_ground_gyroscopic_correction(js):
    """tan(lean) g R / v^2 -> 1 + J / (m h a) (the textbook gyroscopic
    correction) as R / h -> infinity; corrections are O(h / R)."""
    m, h, a = 150.0, 0.7, 0.3
    R, v = 3000.0, 20.0
    lean, r_g = _flat(R, v, h, a, 0.0, m, 30.0, 20.0, js)
    assert np.tan(lean) * G * R / v ** 2 == pytest.approx(1 + js / (m * h * a), rel=1e-3)


def test_flat_ground_finite_radius_textbook_formula():
    """The sphere's eq. M8 tends, as r -> infinity at a fixed turn radius, to
    the flat-ground steady turn of a rigid gyrostat (docs/machine.md eq. M14:
    moments about the CoM in the lean plane, the wheels' angular momentum
    J v_P / a and the frame's (I_yaw - I_pitch) term):
    m g h sin(phi) = cos(phi) [m h v_G^2 / R_G + J Omega v_P / a
    + (I_yaw - I_pitch) Omega^2 sin(phi)],  v_P = Omega R, v_G = Omega R_G."""
    m, h, a, pitch, yaw, js = 150.0, 0.7, 0.3, 30.0, 20.0, 0.9
    R, v = 6.0, 7.0
    phi, r_g = _flat(R, v, h, a, 0.0, m, pitch, yaw, js)
    om = v / r_g
    lhs = m * G * h * np.sin(phi)
    rhs = np.cos(phi) * (m * h * v ** 2 / r_g + js * om * (om * R) / a + (yaw - pitch) * om ** 2 * np.sin(phi))
    assert lhs == pytest.approx(rhs, rel=1e-6)
    assert r_g == pytest.approx(R - h * np.sin(phi), rel=1e-7)   # r sin(theta) = R to ~1e-8 at r = 1e8


def test_flat_ground_tyre_width_correction():
    """Point mass on a round tyre: phi = phi' + asin(t sin(phi') / (h - t)),
    tan(phi') = v^2 / (g R_G) (the lean of the contact-to-CoM line)."""
    m, h, a, t = 150.0, 0.7, 0.3, 0.06
    R, v = 8.0, 7.0
    phi, r_g = _flat(R, v, h, a, t, m, 0.0, 0.0, 0.0)
    phi1 = np.arctan(v ** 2 / (G * r_g))
    assert phi == pytest.approx(phi1 + np.arcsin(t * np.sin(phi1) / (h - t)), abs=1e-7)   # O(R/r) = 8e-8
    assert phi > phi1 + 0.01                                   # the round tyre leans the machine further


def test_round_tyre_allows_tilts_below_zero_and_two_tilts_near_the_floor():
    m, h, a, t, pitch, yaw, js = 160.0, 0.75, 0.3, 0.05, 40.0, 25.0, 0.8
    r = 2.4384
    th = np.radians([150.0, 170.0])
    roots = solve_alpha_for_speed(th, [12.0, 10.0], r, G, m, h, a, t, pitch, yaw, js)
    assert np.nanmin(roots[0]) < 0
    assert np.sum(np.isfinite(roots[1])) == 2


# ---------------------------------------------------------------------------
# the hand calculation of docs/machine.md sec. 8

def test_the_hand_calculation_of_the_docs():
    """16-ft globe (r = 2.4384 m), the equator, alpha = 15 deg, the
    'stunt125' numbers; the intermediate values printed in docs/machine.md."""
    r, th, al = 2.4384, np.radians(90.0), np.radians(15.0)
    m, h, a, t, pitch, yaw, js, head = 165.0, 0.80, 0.30, 0.045, 40.0, 20.0, 0.8, 1.65
    res = ride_orbit(th, al, r, G, m, h, a, t, pitch, yaw, js, head)
    assert float(res["r_g"]) == pytest.approx(1.664126, abs=5e-7)
    assert float(res["omega2"]) == pytest.approx(24.88433, abs=5e-5)
    assert float(res["omega"]) == pytest.approx(4.98842, abs=5e-6)
    assert float(res["period"]) == pytest.approx(1.25955, abs=5e-6)
    assert float(res["v_cm"]) == pytest.approx(8.30136, abs=5e-6)
    assert float(res["v_contact"]) == pytest.approx(12.16376, abs=5e-6)
    assert float(res["spin"]) == pytest.approx(40.7542, abs=5e-5)
    assert float(res["normal"]) == pytest.approx(41.41065, abs=5e-6)
    assert float(res["friction"]) == pytest.approx(-9.80665, abs=5e-6)
    assert float(res["mu_required"]) == pytest.approx(0.23681, abs=5e-6)
    assert float(res["load_g"]) == pytest.approx(4.33950, abs=5e-6)
    assert float(res["head_clearance"]) == pytest.approx(1.49853, abs=5e-6)


# ---------------------------------------------------------------------------
# singular inputs: a status, never a warning or a NaN in an ok row

def test_singular_inputs_give_statuses_not_warnings():
    theta = np.radians([0.0, 180.0, 90.0, 90.0, 90.0, 45.0, 179.9])[:, None]
    alpha = np.radians([-90.0, 0.0, 90.0, 89.999999999, 45.0, -180.0])[None, :]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        res = ride_orbit(theta, alpha, 2.0, G, 100.0, 0.8, 0.3, 0.0, 10.0, 5.0, 0.5, 1.5)
        res2 = ride_orbit(theta, alpha, 2.0, G, 100.0, 0.8, 0.3, 0.2999, 10.0, 5.0, 0.5, 1.5)
        solve_alpha_for_speed(np.radians([0.0, 180.0, 90.0]), [1.0, 1.0, 1.0], 2.0, G, 100.0, 0.8, 0.3, 0.1,
                              10.0, 5.0, 0.5)
    for out in (res, res2):
        ok = out["status"] == Status.OK
        for key, val in out.items():
            assert np.all(np.isfinite(val[ok])), key
        assert np.all((out["reason"] != 0) == ~ok)
    # standing upright on the floor: no orbit, said so (and upright on the equator wall does not fit)
    assert (res["status"][6, 2], res["reason"][6, 2]) == (Status.NO_ORBIT, Reason.MACHINE_OMEGA_ZERO)
    # ... and on the axis at the very bottom both sides of eq. M8 vanish
    assert (res["status"][1, 2], res["reason"][1, 2]) == (Status.NO_ORBIT, Reason.MACHINE_ZERO_DENOMINATOR)
    assert res["status"][2, 2] == Status.NO_FIT


# ---------------------------------------------------------------------------
# vertical loops (docs/machine.md sec. 10)

def test_the_papers_wheel_loops_like_vertical():
    from deathsphere.api import vertical

    a, r, k, m = 0.3, 3.0, 0.5, 2.0
    i = k * m * a * a
    theta = [90.0, 60.0, 45.0, 120.0]
    res = vertical_loop(np.radians(theta), 6.0, r, G, m, a, a, 0.0, 2 * i, 2 * i, a)
    ref = vertical(theta, v_top=6.0, r=r, stability=False)
    np.testing.assert_allclose(res["v_top_min"], ref["v_top_min_m_s"], rtol=1e-13)
    np.testing.assert_allclose(res["v_bottom"], ref["v_bottom_m_s"], rtol=1e-13)
    # the contact force is in the loop's plane; its part along the sphere's normal is the wheel's
    np.testing.assert_allclose(res["load_bottom"] * np.sin(np.radians(theta)) * G,
                               ref["normal_bottom_per_mass_m_s2"], rtol=1e-12)


def test_a_point_mass_loops_with_v_top_squared_g_r_minus_h():
    """The task's limit: a point mass on massless wheels needs v^2 >= g (r - h)
    at the top of a great circle; energy alone gives v_b^2 = v_t^2 + 4 g (r - h)."""

    r, h = 2.4384, 0.8
    res = vertical_loop(np.pi / 2, [4.0, 6.0], r, G, 100.0, h, 0.3, 0.0, 0.0, 0.0, 1.6)
    assert res["v_top_min"][0] == pytest.approx(np.sqrt(G * (r - h)), rel=1e-14)
    np.testing.assert_allclose(res["v_bottom"], np.sqrt(np.array([16.0, 36.0]) + 4 * G * (r - h)), rtol=1e-14)
    assert res["status"].tolist() == [Status.NO_CONTACT, Status.OK]


def test_a_round_tyre_only_loops_on_a_great_circle():

    res = vertical_loop(np.radians([90.0, 70.0]), 8.0, 2.45, G, 165.0, 0.8, 0.3, 0.045, 40.0, 0.8, 1.65)
    assert res["status"].tolist() == [Status.OK, Status.NO_ORBIT]
    assert res["reason"][1] == Reason.LOOP_ROUND_TYRE_OFF_PLANE


def test_the_papers_wheel_needs_the_friction_of_vertical():
    """The friction needed round the loop (eq. M24) for the paper's wheel is
    `vertical`'s mu_required and worst point (eqs. 27-28b), and its slip verdict."""
    from deathsphere.api import vertical

    a, r, k, m = 0.3, 3.0, 0.5, 2.0
    i = k * m * a * a
    theta = np.array([90.0, 60.0, 45.0, 120.0])
    res = vertical_loop(np.radians(theta), 6.0, r, G, m, a, a, 0.0, 2 * i, 2 * i, a, mu=0.9)
    ref = vertical(theta, v_top=6.0, r=r, mu=0.9, stability=False)
    np.testing.assert_allclose(res["mu_required"], ref["mu_required"], rtol=1e-12)
    np.testing.assert_allclose(np.degrees(res["phi_worst"]), ref["phi_worst_deg"], rtol=1e-12)
    assert [s == Status.SLIPS for s in res["status"]] == [s == "slips" for s in ref["status"]]


def _loop_by_newton(theta, v_top, r, m, h, a, ip, js, n=20001):
    """mu needed round a loop from Newton's law sampled point by point: the
    rate from the energy (M21), the angular acceleration by differencing it,
    the force m a_G - m g in 3-D split along the sphere's normal."""
    phi = np.linspace(0.0, 2 * np.pi, n)
    rho = r * np.sin(theta)
    rg = rho - h
    big_m = m * rg * rg + ip + js * (rho * rho - 2 * rho * a) / (a * a)
    w2 = (v_top / rg) ** 2 + 2 * m * G * rg * (1 - np.cos(phi)) / big_m
    wdd = np.gradient(0.5 * w2, phi)                  # phi'' = d(phi'^2 / 2) / d phi
    out = np.stack((np.sin(phi), np.zeros_like(phi), np.cos(phi)))      # loop plane: x, z; y across
    along = np.stack((np.cos(phi), np.zeros_like(phi), -np.sin(phi)))
    acc = -rg * w2 * out + rg * wdd * along
    force = acc - np.array([0.0, 0.0, -G])[:, None]
    contact = np.array([0.0, r * np.cos(theta), 0.0])[:, None] + rho * out
    n_in = -contact / r
    normal = (force * n_in).sum(axis=0)
    friction = np.linalg.norm(force - normal * n_in, axis=0)
    load = np.linalg.norm(force, axis=0) / G
    return (friction / normal).max(), load.max()


@pytest.mark.parametrize("theta, v_top, h, a, ip, js", [
    (90.0, 8.0, 0.8, 0.3, 40.0, 0.8),          # stunt125's numbers on a great circle
    (65.0, 7.0, 0.86, 0.325, 16.1, 0.39),      # the benchmark bicycle off a great circle (knife edge)
    (90.0, 6.0, 0.3, 0.3, 0.2, 0.19),          # a small rider-less wheel: large friction along the path
])
def test_the_loops_friction_and_load_against_newton(theta, v_top, h, a, ip, js):

    r, m = 2.4384, 100.0
    mu, load = _loop_by_newton(np.radians(theta), v_top, r, m, h, a, ip, js)
    res = vertical_loop(np.radians(theta), v_top, r, G, m, h, a, 0.0, ip, js, h + 0.5)
    assert res["mu_required"] == pytest.approx(mu, rel=1e-6)
    assert res["load_bottom"] == pytest.approx(load, rel=1e-9)
    # the limits act on these numbers: just below either, the loop fails with its reason
    tight = vertical_loop(np.radians(theta), v_top, r, G, m, h, a, 0.0, ip, js, h + 0.5,
                          mu=[mu * 0.999, mu * 1.001, np.inf], max_g=[np.inf, load * 0.999, load * 1.001])
    assert tight["status"].tolist() == [Status.SLIPS, Status.OVER_G, Status.OK]
    assert tight["reason"][:2].tolist() == [Reason.LOOP_SLIPS, Reason.LOOP_OVER_G]
