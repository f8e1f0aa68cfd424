"""McDonald (1993) sec. 2.3, 3, 4-5: the paper's stability results, as printed
and as corrected, against the exact linearisation (docs/stability.md).

Each test states the paper's claim and what the exact analysis finds; the
errata E1-E7 referred to are listed in docs/stability.md.
"""

import numpy as np
import pytest

from deathsphere.physics import stability as st
from deathsphere.physics.stability.frequencies import quadratic_roots, real_frequencies
from deathsphere.physics.wheel import horizontal_orbit

G = 9.80665
S, U = st.Verdict.STABLE, st.Verdict.UNSTABLE


# ---------------------------------------------------------------- vertical

def test_eq102_determinant_is_A_w4_minus_B_w2_plus_C_erratum_E1():
    """Eq. (103) prints A w^4 - B w^2 - C = 0; the determinant of the printed
    2x2 system (102) is -(A w^4 - B w^2 + C)."""
    a, r, k = 0.3, 3.0, 0.5
    th, pd0 = np.radians(70.0), 4.0
    v = st.vertical_paper(th, pd0, a, r, k, G)
    rp = v["r_prime"]
    for w in (0.7, 3.0, 11.0):
        M = np.array([[2 * k * (rp + a) * pd0 * w, k * a * w ** 2 + k * (2 * rp + a) * pd0 ** 2],
                      [(k + 1) * a * w ** 2 + ((2 * k + 1) * rp + k * a) * pd0 ** 2 - G,
                       (2 * k + 1) * (rp + a) * pd0 * w]])
        det = np.linalg.det(M)
        corrected = v["A"] * w ** 4 - v["B"] * w ** 2 + v["C"]
        printed = v["A"] * w ** 4 - v["B"] * w ** 2 - v["C"]
        assert np.isclose(det, -corrected, rtol=1e-12)
        assert not np.isclose(det, -printed, rtol=1e-3)
    # printed roots (103a): one w^2 negative whenever C > 0 (eq. 106) -- the
    # printed formula would call every orbit satisfying eq. (106) unstable
    assert v["C"] > 0 and v["omega2_printed"][1].real < 0
    assert np.all(v["omega2"].real > 0) and v["stable"]


def test_vertical_claim_holds_for_small_wheels_but_not_in_resonance_tongues():
    """'All vertical orbits in contact are stable' (after eq. 106): the exact
    Floquet analysis agrees for a/r = 0.1 but finds parametric-resonance
    tongues for large wheels near the contact threshold (eq. 28a)."""
    thmin = np.arcsin(0.1)
    th = thmin + (np.pi / 2 - thmin) * np.array([0.2, 0.6, 1.0])
    f = np.array([1.05, 2.0])
    TH, F = np.meshgrid(th, f, indexing="ij")
    rp = np.sin(TH) - 0.1
    fl = st.vertical_floquet(TH, F * np.sqrt(G / rp), 0.1, 1.0, 0.5, G)
    assert np.all(fl["verdict"] == S)
    # counterexample: a/r = 0.6, k = 1/4, in contact (f = 1.2 > 1)
    th1 = np.radians(75.57897221815767)
    pd = 1.2 * np.sqrt(G / (np.sin(th1) - 0.6))
    fl = st.vertical_floquet(th1, pd, 0.6, 1.0, 0.25, G)
    vp = st.vertical_paper(th1, pd, 0.6, 1.0, 0.25, G)
    assert vp["contact_28a"] and vp["stable"] and vp["stable_printed"]
    assert fl["verdict"] == U and fl["max_abs"] > 1.1
    assert np.isclose(np.real(fl["multipliers"]).min(), -1.1074, atol=1e-3)  # period doubling


# ---------------------------------------------------------------- equator

def test_eqs_136_138_are_the_expansion_of_the_printed_det_133():
    al = np.radians(np.arange(2.0, 89.0, 3.0))
    e = st.equator_paper(al, 0.3, 3.0, 0.5, G)
    np.testing.assert_allclose(e["omega2_det"], e["omega2_closed"], rtol=1e-9)
    # the paper says A, B, C are all positive; with the printed formulas C < 0
    assert np.all(e["A"] > 0) and np.all(e["B"] > 0) and np.all(e["C"] < 0)
    assert np.all(e["stable_printed"])


def test_equator_printed_frequencies_vs_exact_erratum_E4():
    """Table 1's equatorial orbits: the printed system (133) misses the slow
    frequency by 24% and 54%; the closed form derived here is exact."""
    al = np.radians([25.0, 45.0])
    ex = st.wheel_stability(np.pi / 2, al, 0.3, 3.0, 0.5, G)
    pp = st.equator_paper(al, 0.3, 3.0, 0.5, G)
    cf = st.equator_exact_closed_form(al, 0.3, 3.0, 0.5, G)
    dev = pp["freq_slow"] / ex["freq_slow"] - 1
    assert np.all(dev < -0.2)
    np.testing.assert_allclose(cf["freq_slow"], ex["freq_slow"], rtol=1e-10)
    np.testing.assert_allclose(cf["freq_fast"], ex["freq_fast"], rtol=1e-10)
    # small-wheel limit of the closed form: (1 + 3 tan^2 alpha) Omega^2
    c = st.equator_exact_closed_form(al, 1e-5, 1.0, 0.5, G)
    np.testing.assert_allclose(c["freq_slow"] ** 2 / c["Omega"] ** 2, 1 + 3 * np.tan(al) ** 2, rtol=1e-4)


def test_small_wheel_limit_of_eq_133_vs_eq_207_errata_E7_E8():
    """The paper's equator system (133) and small-wheel result (207) should
    agree for a << r on the equator; they do not.  As a -> 0 the printed (133)
    gives w_slow = Omega; with the g sin(alpha) term of A13 signed as in
    eq. (127) (E7) it gives Omega^2 (1 + 2 sin^2 alpha), which is also what
    eqs. (202)-(206) give once eq. (128)'s sin(alpha_0) is corrected to the
    cos(alpha_0) of eqs. (122)/(133) (E8); eq. (207) itself used the typo.
    The exact limit is Omega^2 (1 + 3 tan^2 alpha) (E4/E5)."""
    al = np.radians(np.array([20.0, 30.0, 70.0]))      # (at 45 deg the two coincide)
    a, r, k = 1e-5, 1.0, 0.5
    c = st.equator_coefficients(al, a, r, k, G)

    def slow(c):
        A, B, C = st.equator_printed_abc(c)
        return real_frequencies(*quadratic_roots(A, -B, -C))[0] / c["Omega"]

    np.testing.assert_allclose(slow(c), 1.0, rtol=1e-3)
    fixed = dict(c, A13=c["A13"] - 2 * G * np.sin(al))
    np.testing.assert_allclose(slow(fixed), np.sqrt(1 + 2 * np.sin(al) ** 2), rtol=1e-3)
    eq207 = st.small_wheel_paper(np.pi / 2, al, a, r, k, G)["freq"] / c["Omega"]
    np.testing.assert_allclose(eq207, np.sqrt(np.tan(al) * (1 + np.sin(2 * al))), rtol=1e-3)
    assert np.all(np.abs(eq207 - slow(fixed)) > 0.1)
    ex = st.wheel_stability(np.pi / 2, al, a, r, k, G)
    np.testing.assert_allclose(ex["freq_slow"] / c["Omega"], np.sqrt(1 + 3 * np.tan(al) ** 2), rtol=1e-3)


def test_not_all_equatorial_orbits_are_stable():
    """'All steady orbits at the equator of the sphere are stable' (eq. 138
    ff.): true for small tilts, false for steep ones (slow orbits)."""
    al = np.radians(np.arange(1.0, 90.0, 1.0))
    for a_r, first_unstable in ((0.1, 72.0), (0.3, 43.0)):
        h = horizontal_orbit(np.pi / 2, al, a_r, 1.0, 0.5, G)
        ok = h["status"] == 0
        ex = st.wheel_stability(np.pi / 2, al[ok], a_r, 1.0, 0.5, G)
        uns = ex["verdict"] == U
        assert np.all(ex["verdict"][al[ok] < np.radians(first_unstable - 1)] == S)
        assert uns.any() and abs(np.degrees(al[ok][uns].min()) - first_unstable) <= 1.5


# ---------------------------------------------------------------- small wheels

def test_small_wheel_eq_207_vs_exact_erratum_E5():
    th, al = np.meshgrid(np.radians([40.0, 60.0, 90.0, 120.0, 150.0]), np.radians([5.0, 20.0, 35.0]),
                         indexing="ij")
    a, r, k = 1e-4, 1.0, 0.25
    ex = st.wheel_stability(th, al, a, r, k, G)
    assert np.all(ex["verdict"] == S)              # the claim itself holds here
    p = st.small_wheel_paper(th, al, a, r, k, G)
    c = st.small_wheel_corrected(th, al, a, r, k, G)
    np.testing.assert_allclose(p["omega2_first"], p["omega2_second"], rtol=1e-3)  # 207's 2 forms
    assert np.max(np.abs(p["freq"] / ex["freq_slow"] - 1)) > 0.3
    np.testing.assert_allclose(c["freq_slow"], ex["freq_slow"], rtol=2e-3)
    np.testing.assert_allclose(c["freq_fast"], ex["freq_fast"], rtol=2e-3)


def test_small_wheels_are_stable_except_where_omega_vanishes():
    """Claim after eq. (207): all small-wheel orbits stable.  Exact (a/r =
    0.01): true except a sliver alpha -> 90 deg where Omega -> 0."""
    th, al = np.meshgrid(np.radians(np.arange(10.0, 176.0, 5.0)), np.radians(np.arange(1.0, 90.0, 1.0)),
                         indexing="ij")
    h = horizontal_orbit(th, al, 0.01, 1.0, 0.5, G)
    ok = (h["status"] == 0) & (0.01 / np.abs(np.sin(th) - 0.01 * np.cos(al)) <= 0.05)
    ex = st.wheel_stability(th[ok], al[ok], 0.01, 1.0, 0.5, G)
    uns = ex["verdict"] == U
    assert np.all(ex["verdict"][al[ok] < np.radians(85)] == S)
    assert uns.any() and np.all(al[ok][uns] > np.radians(87))


def test_large_wheels_above_the_equator_are_not_all_stable():
    """Conjecture (abstract; after eq. 207): death-defying orbits of large
    wheels are stable.  Exact, a/r = 0.3: many above-equator orbits in
    contact are unstable (e.g. theta = 45 deg, alpha = 20 deg)."""
    th, al = np.radians([45.0, 45.0, 60.0, 60.0]), np.radians([10.0, 20.0, 20.0, 35.0])
    h = horizontal_orbit(th, al, 0.3, 1.0, 0.5, G)
    assert np.all(h["status"] == 0)
    ex = st.wheel_stability(th, al, 0.3, 1.0, 0.5, G)
    assert list(ex["verdict"]) == [S, U, S, U]


# ---------------------------------------------------------------- eq. 208

@pytest.mark.parametrize("k", [0.25, 0.5])
def test_rolling_disk_threshold_is_half_of_eq_208_erratum_E6(k):
    """Eq. (208) quotes Omega^2 > g/((2k+1) a) for a wheel rolling on a
    plane; a wide circle on a locally flat floor (bottom of a huge sphere)
    goes unstable at w1^2 = g/(2 (2k+1) a) (up to the circle's curvature)."""
    a, r, th = 1.0, 1e5, np.pi - 1e-3
    al = np.radians(np.linspace(89.5, 89.95, 4001))
    ex = st.wheel_stability(th, al, a, r, k, G)
    rp = r * np.sin(th) - a * np.cos(al)
    w1sq = (rp * ex["omega"]) ** 2 * a / G
    i = np.nonzero((ex["verdict"][:-1] == S) & (ex["verdict"][1:] == U))[0]
    assert i.size == 1
    assert abs(w1sq[i[0]] * 2 * (2 * k + 1) - 1) < 0.02


def test_near_pole_orbits_need_a_minimum_rate():
    """r' <~ a (after eq. 207): at theta = 175 deg, a/r = 0.1 the orbits are
    stable exactly above a critical Omega, of the order of eq. (208)."""
    a, k = 0.1, 0.5
    al = np.radians(np.arange(0.5, 90.0, 0.05))
    th = np.radians(175.0)
    h = horizontal_orbit(th, al, a, 1.0, k, G)
    rp = np.sin(th) - a * np.cos(al)
    m = (h["status"] == 0) & (np.abs(rp) <= a)
    ex = st.wheel_stability(th, al[m], a, 1.0, k, G)
    om2 = ex["omega"] ** 2 * a / G
    stable = ex["verdict"] == S
    assert stable.any() and (~stable).any()
    assert om2[~stable].max() < om2[stable].min()           # a minimum rate
    crit = 0.5 * (om2[~stable].max() + om2[stable].min())
    assert 0.5 < crit / (1 / (2 * k + 1)) < 2.0


# ---------------------------------------------------------------- outside, sphere

def test_outside_alpha_near_90_unstable_but_alpha_near_pi_plus_theta_stable():
    """Sec. 3: 'alpha = pi/2 ... clearly unstable' -- the neighbouring orbits
    are; 'alpha very near pi + theta ... also appear to be unstable' -- the
    exact analysis finds them stable (a/r = 0.1, k = 1/2)."""
    th = np.radians(np.array([20.0, 40.0, 60.0]))
    al_90 = np.radians(np.array([85.0, 87.0, 89.0]))
    al_pi = th + np.radians(175.0)
    for al, want in ((al_90, U), (al_pi, S)):
        h = horizontal_orbit(th, al, 0.1, 1.0, 0.5, G, outside=True)
        assert np.all(h["status"] == 0)
        ex = st.wheel_stability(th, al, 0.1, 1.0, 0.5, G, outside=True)
        assert np.all(ex["verdict"] == want)


def test_sphere_orbits_in_contact_are_stable_inside_and_outside():
    """Secs. 4-5 (and Milne): every horizontal orbit of a rolling sphere is
    stable; closed form of the nutation frequency."""
    th, Om = np.meshgrid(np.radians(np.arange(5.0, 176.0, 10.0)), np.geomspace(0.05, 50, 9), indexing="ij")
    for outside in (False, True):
        ex = st.sphere_stability(th, Om, 0.3, 3.0, 0.4, G, outside)
        assert np.all(ex["verdict"] == S)


def test_table1_orbits_exactly_stable():
    T1 = np.radians(np.array([(15, 5), (30, 5), (45, 10), (60, 10), (60, 25), (75, 15),
                              (75, 30), (90, 25), (90, 45), (135, 60)], dtype=float)).T
    ex, res = st.compare_with_paper(T1[0], T1[1], 0.3, 3.0, 0.5, G)
    assert np.all(ex["verdict"] == S)
    eq = res["equator_verdict"]
    assert eq["applies"].sum() == 2 and np.all(eq["deviation"][eq["applies"]] == 0)
    assert np.all(np.abs(res["equator_slow"]["corrected_deviation"][eq["applies"]]) < 1e-10)
