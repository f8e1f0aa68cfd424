"""Quantitative claims of McDonald (1993), secs. 1, 2.2.1, 3, 4 and 5.

Source: K. T. McDonald, "Circular Orbits Inside the Sphere of Death" (1993),
the paper's LaTeX source.  Each test quotes the claim it checks; where
the printed claim is wrong or garbled the test asserts the correct statement
and says so (these are the errata of docs/errata.md).  The checks are made
with means independent of the formulas under test where possible: direct
integration of the equation of motion, root finding, vector mechanics, scans.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from deathsphere.physics import sphere as S
from deathsphere.physics import vertical_orbit as V
from deathsphere.physics.particle import particle_orbit
from deathsphere.physics.status import Status
from deathsphere.physics.wheel import horizontal_orbit

G = 9.80665
A, R = 0.3, 3.0          # Table 1's wheel and sphere
DEG = np.pi / 180


# ---------------------------------------------------------------- introduction

def test_intro_particle_has_no_orbit_above_equator_but_a_wheel_has():
    """Abstract / introduction: a rolling wheel can orbit wholly above the
    equator, a particle sliding freely cannot."""
    theta = np.arange(1.0, 180.0, 1.0) * DEG
    particle = particle_orbit(theta, R, G)
    ok = particle["status"] == Status.OK
    assert np.all(ok == (theta > 90 * DEG))
    wheel = horizontal_orbit(60 * DEG, 10 * DEG, A, R, 0.5, G)       # Table 1, row 4
    assert wheel["status"] == Status.OK


# ---------------------------------------------------------------- sec. 2.2.1

def test_eq28a_contact_iff_top_rate_exceeds_sqrt_g_over_rprime():
    """Eq. (28a): the vertical orbit is physical as long as phidot0^2 > g/r'.
    Independent check: the least normal force round the orbit on a dense
    grid changes sign exactly at the printed threshold."""
    theta = np.array([35.0, 60.0, 90.0, 130.0]) * DEG
    rp = R * np.sin(theta) - A
    phi = np.linspace(0, 2 * np.pi, 3601)[:, None, None]
    factor = np.array([0.999, 1.001])[:, None]
    w0 = np.sqrt(G / rp) * factor
    least = V.vertical_profile(phi, theta, w0, A, R, 0.5, G)["normal"].min(axis=0)
    assert np.all(least[0] < 0) and np.all(least[1] > 0)


def test_eq28_friction_along_the_orbit_has_the_opposite_sign():
    """Eq. (28) prints F_2 = +2k/(2k+1) m g sin(phi).  Torque balance about
    the centre, a F_2 = -I11 d(omega_1)/dt with I11 = 2 k m a^2 and
    omega_1 = r' phidot / a, and eq. (26) give F_2 = -2k/(2k+1) m g sin(phi)
    (friction holds the wheel back while gravity speeds it up)."""
    theta, k, w0, phi = 70 * DEG, 0.5, 3.0, np.linspace(0.2, 3.0, 8)
    rp = R * np.sin(theta) - A
    phiddot = G * np.sin(phi) / ((2 * k + 1) * rp)                  # eq. (26)
    f2_torque = -2 * k * A ** 2 * (rp * phiddot / A) / A              # a F_2 = -I11 d(omega_1)/dt
    f = V.contact_force(phi, theta, w0, A, R, k, G)
    assert f["along"] == pytest.approx(f2_torque, rel=1e-12)
    printed = 2 * k / (2 * k + 1) * G * np.sin(phi)
    assert np.all(np.sign(f["along"]) == -np.sign(printed))


def test_eq28c_means_cos_squared_theta():
    """Eq. (28c) prints sqrt(F_3^2 cos theta^2 + F_2^2); the tangential part
    of F (F minus its projection on the sphere's normal) has size
    sqrt(F_3^2 cos^2(theta) + F_2^2), not cos(theta^2)."""
    theta, k, w0, phi = 60 * DEG, 0.5, 3.0, 1.0
    f = V.contact_force(phi, theta, w0, A, R, k, G)
    f2, f3 = float(f["along"]), float(f["radial"])
    # vectors: axis 2 = (0,1,0), axis 3 = (1,0,0) (= r-hat' inside), z' = (0,0,-1)
    force = np.array([f3, f2, 0.0])
    n_out = np.sin(theta) * np.array([1.0, 0, 0]) + np.cos(theta) * np.array([0, 0, -1.0])
    tangential = np.linalg.norm(force - (force @ n_out) * n_out)
    assert tangential == pytest.approx(np.sqrt(f3 ** 2 * np.cos(theta) ** 2 + f2 ** 2), rel=1e-12)
    assert tangential != pytest.approx(np.sqrt(f3 ** 2 * np.cos(theta ** 2) + f2 ** 2), rel=1e-3)
    assert float(f["friction"]) == pytest.approx(tangential, rel=1e-12)
    assert -f3 * np.sin(theta) == pytest.approx(float(f["normal"]))          # eq. (28d)


def test_eq28b_mu_exceeds_cot_theta_and_is_large_only_near_losing_contact():
    """Eq. (28b): mu = cot(theta) sqrt(1 + (F_2 / F_3 cos(theta))^2) must be
    greater than cot(theta), but only much greater if the wheel nearly loses
    contact at the top; pi/4 <~ theta <= pi/2 is consistent with mu <~ 1."""
    theta = np.arange(30.0, 90.0, 5.0) * DEG
    rp = R * np.sin(theta) - A
    phi = np.linspace(0, 2 * np.pi, 721)[:, None, None]
    margin = np.array([1e-4, 0.5, 2.0, 10.0])[:, None]
    w0 = np.sqrt((1 + margin) * G / rp)
    prof = V.vertical_profile(phi, theta, w0, A, R, 0.5, G)
    cot = 1 / np.tan(theta)
    f2, f3 = prof["along"], prof["radial"]
    printed = cot * np.sqrt(1 + (f2 / (f3 * np.cos(theta))) ** 2)
    assert prof["mu_required"] == pytest.approx(printed, rel=1e-12)
    assert np.all(prof["mu_required"] >= cot - 1e-12)
    mu_max = V.vertical_orbit(theta, w0, A, R, 0.5, G)["mu_required"]
    assert np.all(mu_max[0] - cot > 20)                       # nearly losing contact
    assert np.all(mu_max[2:] - cot < 0.1)                     # comfortably fast
    # pi/4 <~ theta <= pi/2 and mu <~ 1: from 50 deg on, a top speed of
    # sqrt(1.5 g r') suffices; below 45 deg mu >= cot(theta) > 1 always
    w = np.sqrt(1.5 * G / rp)
    mu = V.vertical_orbit(theta, w, A, R, 0.5, G)["mu_required"]
    assert np.all(mu[theta >= 50 * DEG] < 1) and np.all(mu[theta < 45 * DEG] > 1)


def test_vertical_orbits_off_great_circles_need_friction_particle_does_not_have():
    """Sec. 2.2.1: a wheel's friction permits vertical orbits with theta <
    pi/2, while a particle sliding freely has vertical orbits only on great
    circles.  With k = 0 (no rolling inertia) and mu = 0 (no friction) only
    theta = 90 deg keeps going."""
    theta = np.array([40.0, 70.0, 89.0, 90.0, 110.0]) * DEG
    out = V.vertical_orbit(theta, 3.0, A, R, 0.0, G, mu=0.0)
    assert out["status"].tolist() == [Status.SLIPS] * 3 + [Status.OK, Status.SLIPS]
    wheel = V.vertical_orbit(theta, 3.0, A, R, 0.5, G)          # unlimited friction
    assert np.all(wheel["status"] == Status.OK)


def test_only_restrictions_are_fit_and_minimum_rate():
    """Sec. 2.2.1, end: the only restrictions are r sin(theta) > a and eq. (28a)."""
    theta = np.arange(1.0, 180.0, 1.0)[:, None] * DEG
    w0 = np.linspace(0.5, 6.0, 23)
    out = V.vertical_orbit(theta, w0, A, R, 0.5, G)
    fits = R * np.sin(theta) > A
    rate_ok = w0 ** 2 > G / np.where(fits, R * np.sin(theta) - A, 1.0)
    assert np.all((out["status"] == Status.OK) == (fits & rate_ok))


# ---------------------------------------------------------------- sec. 3

def leave_angle_by_integration(k, v_top, theta=90 * DEG, a=A, r=R):
    """Roll a wheel down the outside from the top (vertical plane, alpha = pi):
    integrate phi'' = g sin(phi) / ((2k+1) r') and stop where Newton's radial
    equation N/m = g cos(phi) - r' phidot^2 reaches zero."""
    rp = r * np.sin(theta) + a
    y0 = [1e-7, v_top / rp] if v_top == 0 else [0.0, v_top / rp]

    def normal(t, y):
        return G * np.cos(y[0]) - rp * y[1] ** 2
    normal.terminal = True
    sol = solve_ivp(lambda t, y: [y[1], G * np.sin(y[0]) / ((2 * k + 1) * rp)], (0, 100), y0,
                    events=normal, rtol=1e-12, atol=1e-14)
    return sol.y_events[0][0][0]


@pytest.mark.parametrize("k, cos_printed", [(0.0, 2 / 3), (0.5, 1 / 2), (0.25, 2 / 3.5)])
def test_eq82_release_angle_from_rest(k, cos_printed):
    """Eq. (82): from rest at the top the wheel leaves the sphere where
    cos(phi) = 2/(3+2k): 2/3 for a particle (k = 0), 1/2 for a rim wheel."""
    phi = leave_angle_by_integration(k, 0.0)
    assert np.cos(phi) == pytest.approx(cos_printed, abs=1e-6)
    assert float(V.release_angle(90 * DEG, 0.0, A, R, k, G)) == pytest.approx(phi, abs=1e-5)


@pytest.mark.parametrize("v_top", [0.5, 2.0, 4.0])
def test_release_angle_with_top_speed(v_top):
    """Beyond eq. (82): cos(phi) = (2 + (2k+1) v_top^2/(g r'))/(3+2k)."""
    k = 0.5
    phi = leave_angle_by_integration(k, v_top)
    rp = R + A
    assert np.cos(phi) == pytest.approx((2 + (2 * k + 1) * v_top ** 2 / (G * rp)) / (3 + 2 * k), abs=1e-9)
    w0 = v_top / rp
    assert float(V.release_angle(90 * DEG, w0, A, R, k, G)) == pytest.approx(phi, abs=1e-8)


def test_no_vertical_orbits_outside():
    """Sec. 3: 'We expect no vertical orbits as the wheel will lose contact
    with the sphere at some point' - for every k and top speed it leaves
    before phi = pi/2."""
    k = np.array([0.0, 0.25, 0.5, 1.0, 5.0])[:, None]
    w0 = np.array([0.0, 0.3, 1.0, 1.7, 10.0])
    out = V.vertical_orbit(70 * DEG, w0, A, R, k, G, outside=True)
    assert np.all(out["status"] == Status.NO_CONTACT)
    assert np.all(out["phi_leave"] < np.pi / 2)


# ---------------------------------------------------------------- sec. 4

def test_eq49_radial_component_sign():
    """Eq. (49) prints + phidot^2 sin^2(theta) for the 3-component of
    d^2(3-hat)/dt^2; for a unit vector, 3-hat . d^2(3-hat)/dt^2 = -|d(3-hat)/dt|^2
    = -phidot^2 sin^2(theta).  (Harmless for eq. 50, where 3 x 3 = 0.)"""
    theta, om, t = 50 * DEG, 1.7, np.linspace(-1e-3, 1e-3, 5)
    n = np.stack([np.sin(theta) * np.cos(om * t), np.sin(theta) * np.sin(om * t),
                  np.full_like(t, np.cos(theta))])
    h = t[1] - t[0]
    n_ddot = (n[:, 3] - 2 * n[:, 2] + n[:, 1]) / h ** 2
    assert n[:, 2] @ n_ddot == pytest.approx(-om ** 2 * np.sin(theta) ** 2, rel=1e-5)


def test_eq52_needs_the_factor_g():
    """Eq. (52) prints (k+1) r' phiddot sin(theta) = sin(beta) sin(phi): the
    right-hand side lacks g.  On a vertical great circle (beta = theta = pi/2,
    omega_3 = 0) the vector equation (46), (k+1) r' 3 x 3'' - k a omega_3 3'
    = g z x 3, holds with phiddot = g sin(phi)/((k+1) r') and fails without g."""
    k, rho, phi, phidot = 0.4, R - A, 0.8, 1.3
    n = np.array([0.0, np.sin(phi), np.cos(phi)])
    s = np.array([0.0, np.cos(phi), -np.sin(phi)])
    zhat = np.array([0.0, 0.0, 1.0])

    def residual(phiddot):
        n_ddot = phiddot * s - phidot ** 2 * n
        return (k + 1) * rho * np.cross(n, n_ddot) - G * np.cross(zhat, n)
    assert np.abs(residual(G * np.sin(phi) / ((k + 1) * rho))).max() < 1e-12
    assert np.abs(residual(np.sin(phi) / ((k + 1) * rho))).max() > 1


def test_eq55_roots_and_eq56_threshold():
    """Eq. (55) is a quadratic for Omega; eq. (56): real orbits iff
    (k a omega_3)^2 >= 4 (k+1) g r' cos(theta); satisfied below the equator
    for any omega_3 including zero; a lower limit on |omega_3| above it; on
    the equator Omega = -g/(k a omega_3), so omega_3 != 0 is needed."""
    k, rho = 0.4, R - A
    theta = np.array([30.0, 60.0, 89.0]) * DEG
    w_min = 2 * np.sqrt((k + 1) * G * rho * np.cos(theta)) / (k * A)
    assert S.omega3_min_real(theta, A, R, k, G) == pytest.approx(w_min)
    for th, w in zip(theta, w_min):
        lo = S.orbit_rates(th, w * (1 - 1e-9), A, R, k, G)
        hi = S.orbit_rates(th, w * (1 + 1e-9), A, R, k, G)
        assert np.all(np.isnan(lo)) and np.all(np.isfinite(hi))
        for om in hi:
            assert (k + 1) * rho * om ** 2 * np.cos(th) + k * A * w * om + G == pytest.approx(0, abs=1e-6)
    below = S.sphere_orbit(np.array([95.0, 135.0, 175.0]) * DEG, 0.0, A, R, k, G)
    assert np.all(below["status"] == Status.OK)
    eq = S.sphere_orbit(90 * DEG, np.array([-50.0, 0.0, 20.0]), A, R, k, G, branch=0)
    assert eq["omega"][[0, 2]] == pytest.approx(-G / (k * A * np.array([-50.0, 20.0])))
    assert eq["status"][1] == Status.NO_ORBIT


def test_eq57_contact_force_corrected():
    """Eq. (57) prints F/m = (g + r' Omega^2 cos(theta)) sin(theta) 1-hat
    - (r' Omega^2 sin^2(theta) - g cos(theta)) 3-hat 'using eqs. (2) and
    (54)'.  From eq. (2) with r_cm = r' 3-hat (eq. 42) and 3'' from eq. (49),
    F/m = r' 3'' + g z: the 3-component is as printed, the 1-component is
    -(g + r' Omega^2 cos(theta)) sin(theta) (1-hat = 2-hat x 3-hat points
    down the meridian, and friction must hold the ball up), as in eq. (32)
    for the wheel."""
    theta, om, rho = 60 * DEG, 2.5, R - A
    e3 = np.array([np.sin(theta), 0.0, np.cos(theta)])
    e2 = np.array([0.0, 1.0, 0.0])
    e1 = np.cross(e2, e3)
    zprime = -np.sin(theta) * e1 + np.cos(theta) * e3                # eq. (47)
    assert zprime == pytest.approx([0, 0, 1])
    force = rho * (-om ** 2 * np.sin(theta) * np.array([1.0, 0, 0])) + G * np.array([0, 0, 1.0])
    assert force @ e3 == pytest.approx(-(rho * om ** 2 * np.sin(theta) ** 2 - G * np.cos(theta)))
    assert force @ e1 == pytest.approx(-(G + rho * om ** 2 * np.cos(theta)) * np.sin(theta))
    normal, friction = S.contact_force(theta, om, A, R, G)
    assert float(friction) == pytest.approx(force @ e1) and float(normal) == pytest.approx(-(force @ e3))


def test_eq58_always_holds_below_the_equator():
    """Eq. (58) 'is always satisfied for orbits below the equator'."""
    theta = np.linspace(90.5, 179.5, 60)[:, None] * DEG
    w3 = np.linspace(-300, 300, 61)
    out = S.sphere_orbit(theta, w3, A, R)
    real = np.isfinite(out["omega"])
    assert real.all()
    assert np.all(out["normal"] > 0)


def test_eq58_at_the_least_spin_needs_tan2_theta_above_k_plus_1():
    """After eq. (58): with omega_3 at the minimum of eq. (56),
    Omega = -k a omega_3 / (2 (k+1) r' cos(theta)), and then eq. (58)
    requires tan^2(theta) > k + 1."""
    k, rho = 0.4, R - A
    for th_deg in (20.0, 40.0, 49.0, 51.0, 60.0, 80.0):
        th = th_deg * DEG
        w = float(S.omega3_min_real(th, A, R, k, G))
        om = -k * A * w / (2 * (k + 1) * rho * np.cos(th))
        assert (k + 1) * rho * om ** 2 * np.cos(th) + k * A * w * om + G == pytest.approx(0, abs=1e-9)
        contact = rho * om ** 2 * np.sin(th) ** 2 > G * np.cos(th)
        assert contact == (np.tan(th) ** 2 > k + 1)


def test_k_two_fifths_threshold_is_49_8_degrees_and_text_means_58_than_56():
    """After eq. (58): 'So for k = 2/5 and at angles theta < 50 deg larger
    values of |omega_3| are needed to satisfy eq. (56) than to satisfy eq.
    (56).'  It should read '... to satisfy eq. (58) than to satisfy eq.
    (56)'; and the angle is atan(sqrt(1.4)) = 49.80 deg, which the paper
    rounds to 50 deg."""
    k = 0.4
    threshold = np.degrees(np.arctan(np.sqrt(k + 1)))
    assert threshold == pytest.approx(49.80, abs=0.005)
    theta = np.array([10.0, 30.0, 49.7, 49.9, 60.0, 85.0]) * DEG
    need58 = S.omega3_min_contact(theta, A, R, k, G)
    need56 = S.omega3_min_real(theta, A, R, k, G)
    larger = need58 > need56 * (1 + 1e-12)
    assert larger.tolist() == [True, True, True, False, False, False]
    # independent check by a scan of |omega_3| on both branches at 30 deg
    w = np.linspace(need56[1], need56[1] * 1.5, 20001)
    out = S.sphere_orbit(theta[1], -w, A, R, k, G)
    first_ok = w[np.argmax((out["status"] == Status.OK).any(axis=-1))]
    assert first_ok == pytest.approx(need58[1], rel=1e-4)
    assert first_ok > need56[1] * 1.01


def test_orbits_at_any_theta_for_large_spin():
    """After eq. (58): 'there are horizontal orbits at any theta > 0 for
    |omega_3| large enough' (the fast branch)."""
    theta = np.array([0.5, 2.0, 10.0, 45.0]) * DEG
    need = S.omega3_min_contact(theta, A, R)
    assert np.all(np.isfinite(need))
    out = S.sphere_orbit(theta, -1.01 * need, A, R, branch=1)
    assert np.all(out["status"] == Status.OK)


# ---------------------------------------------------------------- sec. 5

def test_eq59_only_above_the_equator():
    """Sec. 5: eq. (59) 'can only be satisfied for theta < pi/2': no spin gives
    an orbit with contact on or below the equator outside."""
    theta = np.linspace(90.0, 179.0, 46)[:, None] * DEG
    w3 = np.concatenate([-np.logspace(-2, 4, 60), np.logspace(-2, 4, 60)])
    out = S.sphere_orbit(theta, w3, A, R, outside=True)
    assert not np.any(out["status"] == Status.OK)
    above = S.sphere_orbit(np.linspace(5, 85, 17)[:, None] * DEG, w3, A, R, outside=True)
    assert np.any(above["status"] == Status.OK, axis=(1, 2)).all()


def test_eq59_too_large_spin_only_fails_on_the_fast_branch():
    """Sec. 5: 'if [|omega_3|] is too large eq. (59) can no longer be
    satisfied in view of eq. (55)'.  True for the fast root of eq. (55),
    whose |Omega| grows with |omega_3|; the slow root, Omega ~ -g/(k a omega_3),
    keeps contact for every large spin (a fast top's slow precession)."""
    theta = np.array([10.0, 30.0, 45.0, 70.0]) * DEG
    big = -1e4
    out = S.sphere_orbit(theta, big, A, R, outside=True)
    assert np.all(out["status"][:, 1] == Status.NO_CONTACT)
    assert np.all(out["status"][:, 0] == Status.OK)
    # and the fast branch keeps contact just above the least real spin
    # when tan^2(theta) < k + 1, up to a finite largest spin
    win = S.contact_spin_window(theta, A, R, outside=True)
    steep = np.tan(theta) ** 2 > 1.4
    assert np.all(np.isfinite(win["hi1"][~steep])) and np.all(np.isnan(win["hi1"][steep]))


def test_sec5_eq55_holds_outside_with_r_plus_a():
    """Sec. 5: eqs. (55) and (56) hold with r' = r + a (omega_3 along the
    axis from the ball's centre to the contact point, now inwards).  Checked
    with Euler's equation about the centre in vector form."""
    k, theta, w3 = 0.4, 40 * DEG, -150.0
    rho = R + A
    for om in S.orbit_rates(theta, w3, A, R, k, G, outside=True):
        n = np.array([np.sin(theta), 0.0, np.cos(theta)])          # outward normal
        n_dot = om * np.sin(theta) * np.array([0.0, 1.0, 0.0])
        n_ddot = -om ** 2 * np.sin(theta) * np.array([1.0, 0.0, 0.0])
        arm = -A * n                                                # centre -> contact
        w_dot = -w3 * n_dot + (rho / A) * np.cross(n, n_ddot)       # from v = a n x w
        force = rho * n_ddot + G * np.array([0.0, 0.0, 1.0])
        assert np.abs(k * A ** 2 * w_dot - np.cross(arm, force)).max() < 1e-9
