"""Every quantitative claim of McDonald (1993), checked.

Each :class:`Claim` states what the paper says and where; its ``check``
recomputes it from the physics of this package (closed forms, dense grids,
the exact equations of motion) and returns a :class:`Finding`: ``confirmed``
(the paper is right), ``corrected`` (right in substance, wrong in a detail
that docs/errata.md records: a sign, a factor, a label, a digit) or
``refuted`` (the statement does not hold), with the evidence in numbers.

:func:`run` evaluates a selection and returns a :class:`~deathsphere.model.Table`;
``deathsphere verify`` prints it as a checklist.  The verdicts are asserted in
tests/paper/test_verify.py.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Callable

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY as G
from deathsphere.model import Setup, Table
from deathsphere.physics import particle, sphere, wheel
from deathsphere.physics import vertical_orbit as vertical
from deathsphere.physics.geometry import SINGULAR, fits_inside, fits_outside, r_prime
from deathsphere.physics.status import Status
from deathsphere.results.table1 import PRINTED
from deathsphere.results.table1 import table1_comparison as table1

VERDICTS = ("confirmed", "corrected", "refuted")
A, R, K = 0.3, 3.0, 0.5
deg = np.deg2rad


@dataclass(frozen=True)
class Finding:
    verdict: str
    evidence: str


@dataclass(frozen=True)
class Claim:
    id: str
    section: str
    equation: str
    statement: str
    check: Callable[[], Finding]


CLAIMS: list[Claim] = []


def claim(id, section, equation, statement):
    def register(check):
        CLAIMS.append(Claim(id, section, equation, statement, check))
        return check
    return register


def _grid(n_theta=361, n_alpha=721, lo=-179.95, hi=179.95):
    return deg(np.linspace(0.25, 179.75, n_theta))[:, None], deg(np.linspace(lo, hi, n_alpha))[None, :]


# -- Table 1 -----------------------------------------------------------------

@claim("T1-v", "2.2.2", "Table 1", "v_cm of the ten orbits of Table 1")
def _table1_speed():
    t = table1()
    n = int(t["v_cm_agrees"].sum())
    worst = np.max(np.abs(t["v_cm_computed_m_s"] - t["v_cm_printed_m_s"]))
    return Finding("confirmed" if n == 10 else "refuted",
                   f"{n}/10 reproduced at the printed precision; largest difference {worst:.3f} m/s")


@claim("T1-mu", "2.2.2", "Table 1, eq. 35", "least friction coefficient mu of the ten orbits")
def _table1_mu():
    t = table1()
    bad = [f"{r[0]}/{r[1]}: {r[2]} vs {m:.4f}" for r, m, ok in zip(PRINTED, t["mu_computed"], t["mu_agrees"]) if not ok]
    rel = np.max(np.abs(t["mu_computed"] / t["mu_printed"] - 1))
    verdict = "confirmed" if not bad else ("corrected" if rel < 0.005 else "refuted")
    return Finding(verdict, f"{10 - len(bad)}/10 reproduced; off in the last digit: {'; '.join(bad)} "
                            f"(largest difference {100 * rel:.2f} %)")


@claim("T1-g", "2.2.2", "Table 1, eq. 36", "'No. of g's' of the ten orbits")
def _table1_g():
    t = table1()
    as_g, as_si = int(t["gs_column_is_g"].sum()), int(t["gs_column_is_m_s2"].sum())
    verdict = "confirmed" if as_g == 10 else ("corrected" if as_si == 10 else "refuted")
    return Finding(verdict, f"the column matches the acceleration in g in {as_g}/10 rows and in m/s^2 in "
                            f"{as_si}/10 (e.g. 48 printed: {t['accel_g_computed'][0]:.2f} g = "
                            f"{t['accel_m_s2_computed'][0]:.1f} m/s^2)")


# -- sec. 2: horizontal orbits of a wheel inside --------------------------------

@claim("E29", "2.2.2", "eq. 29", "Omega^2 = g cot(alpha) / ((2k+1) r' + k a cos(alpha)) is a steady orbit")
def _eq29_is_steady():
    from deathsphere.physics import dynamics

    theta = deg(np.array([float(r[0]) for r in PRINTED]))
    alpha = deg(np.array([float(r[1]) for r in PRINTED]))
    state, omega = dynamics.wheel_orbit_state(theta, alpha, A, R, K, G)
    params = dynamics.body_params(A, R, K, G)
    drift = np.abs(dynamics.rhs(state, params, frame_rate=omega))
    scale = np.max(np.abs(omega)) * (R + A)
    worst = float(np.max(drift) / scale)
    return Finding("confirmed" if worst < 1e-10 else "refuted",
                   f"the 10 Table 1 orbits are fixed points of the exact equations of motion in the frame "
                   f"turning at Omega: largest residual {worst:.1e} (relative)")


@claim("E0", "2.1", "eq. 0", "the wheel fits inside iff theta - pi + asin(a/r) < alpha < theta - asin(a/r)")
def _eq0():
    theta, alpha = _grid()
    disagree = 0
    for a_over_r in (0.01, 0.1, 0.3, 0.6):
        s = np.arcsin(a_over_r)
        printed = (theta - np.pi + s < alpha) & (alpha < theta - s)
        disagree += int(np.count_nonzero(printed != fits_inside(theta, alpha, a_over_r, 1.0)))
    return Finding("confirmed" if disagree == 0 else "refuted",
                   f"equals the geometric condition sin(theta - alpha) > a/r (docs/derivations.md) at all "
                   f"{4 * theta.size * alpha.size} grid points for a/r = 0.01..0.6 ({disagree} disagree)")


@lru_cache(maxsize=2)
def _survey(outside=False):
    """Feasible (theta, alpha, r') of the grids of :func:`_grid` for a/r =
    0.01..0.6 and k = 1/4, 1/2, in grid order.  Only the points where the
    wheel fits (eq. 0; eq. 81 outside) are evaluated: elsewhere the status
    is ``no_fit`` whatever the rest, so the feasible set is the same as over
    the whole grid, at half the work.  Cached (read-only): claims Q and UP
    share the survey inside."""
    theta, alpha = _grid()
    every_theta, every_alpha = np.broadcast_arrays(theta, alpha)
    out = []
    for a_over_r in (0.01, 0.1, 0.3, 0.6):
        fits = fits_outside(theta, alpha) if outside else fits_inside(theta, alpha, a_over_r, 1.0)
        th, al = every_theta[fits], every_alpha[fits]
        for k in (0.25, 0.5):
            res = wheel.horizontal_orbit(th, al, a_over_r, 1.0, k, G, outside=outside)
            ok = res["status"] == Status.OK
            out.append((th[ok], al[ok], res["r_prime"][ok]))
    found = [np.concatenate(x) for x in zip(*out)]
    for x in found:
        x.setflags(write=False)
    return found


@claim("Q", "2.2.2", "eqs. 29, 33, 34b", "steady horizontal orbits (inside) are possible only for 0 < alpha < pi/2")
def _quadrant():
    theta, alpha, _ = _survey()
    lo, hi = np.rad2deg(alpha.min()), np.rad2deg(alpha.max())
    inside = (alpha > 0) & (alpha < np.pi / 2)
    return Finding("confirmed" if inside.all() else "refuted",
                   f"{alpha.size} feasible orbits on grids over every quadrant (a/r 0.01..0.6, k 1/4, 1/2): "
                   f"alpha from {lo:.2f} to {hi:.2f} deg")


@claim("A0", "2.2.2", "eq. 29", "there are no steady horizontal orbits with alpha = 0")
def _alpha_zero():
    res = Setup().orbit(np.linspace(0, 180, 181), 0.0)
    n = int(np.count_nonzero(res["status"] == "ok"))
    return Finding("confirmed" if n == 0 else "refuted",
                   f"{n} of 181 orbits with alpha = 0 feasible (eq. 29 diverges: status no_orbit)")


@claim("UP", "abstract, 2.2.2", "eqs. 29, 33", "a wheel inside can orbit wholly above the equator")
def _above_equator():
    theta, alpha, _ = _survey()
    above = np.rad2deg(theta[theta < np.pi / 2])
    return Finding("confirmed" if above.size else "refuted",
                   f"{above.size} feasible orbits with theta < 90 deg, down to theta = {above.min():.2f} deg; "
                   f"Table 1 has six")


@claim("P", "1", "-", "a particle sliding freely inside has no horizontal orbit above the equator")
def _particle():
    theta = deg(np.linspace(0, 180, 721))
    res = particle.particle_orbit(theta, R, G)
    ok = res["status"] == Status.OK
    top = np.rad2deg(theta[ok]).min()
    return Finding("confirmed" if top > 90 else "refuted",
                   f"feasible only for theta > 90 deg (lowest {top:.2f} deg); Omega^2 = -g/(r cos theta)")


# -- sec. 2.2.1: vertical orbits ------------------------------------------------

@claim("E28a", "2.2.1", "eq. 28a", "a vertical orbit keeps contact iff phidot_0^2 > g/r'")
def _eq28a():
    theta = deg(np.array([50.0, 70.0, 90.0, 120.0]))
    rp = R * np.sin(theta) - A
    w_min = np.sqrt(G / rp)
    lo = vertical.vertical_orbit(theta, w_min * (1 - 1e-6), A, R, K, G)["status"]
    hi = vertical.vertical_orbit(theta, w_min * (1 + 1e-6), A, R, K, G)["status"]
    good = np.all(lo == Status.NO_CONTACT) and np.all(hi == Status.OK)
    return Finding("confirmed" if good else "refuted",
                   "contact is lost at 1e-6 below the bound and kept at 1e-6 above, at theta = 50, 70, 90, 120 deg")


@claim("E28b", "2.2.1", "eq. 28b", "on a vertical orbit the friction needed is mu > cot(theta)")
def _eq28b():
    theta = deg(np.array([30.0, 60.0, 120.0]))
    w0 = 1.2 * np.sqrt(G / (R * np.sin(theta) - A))
    phi = np.linspace(0, 2 * np.pi, 721)[:, None]
    mu = vertical.vertical_profile(phi, theta, w0, A, R, K, G)["mu_required"]
    least = np.nanmin(mu, axis=0)
    cot = 1 / np.tan(theta)
    at_bound = np.allclose(least, np.abs(cot), rtol=1e-9)
    return Finding("corrected" if at_bound else "refuted",
                   f"mu >= |cot theta| with equality at the top and bottom (least mu {np.round(least, 4).tolist()} "
                   f"vs cot theta {np.round(cot, 4).tolist()}): the bound is |cot theta| and is reached")


@claim("E28", "2.2.1", "eq. 28", "F = 2k/(2k+1) m g sin(phi) 2 + m (g cos(phi) - r' phidot^2) 3")
def _eq28():
    theta, w0, phi = deg(90.0), 2.5, deg(40.0)
    f = vertical.contact_force(phi, theta, w0, A, R, K, G)
    printed = 2 * K / (2 * K + 1) * G * np.sin(phi)
    along = float(f["along"])
    verdict = "corrected" if np.isclose(along, -printed, rtol=1e-12) else (
        "confirmed" if np.isclose(along, printed, rtol=1e-12) else "refuted")
    return Finding(verdict, f"F_2/m at phi = 40 deg: {along:.4f} m/s^2 from m r' phiddot = F_2 + m g sin(phi); "
                            f"printed +{printed:.4f}: the sign is wrong (mu unaffected)")


@claim("E82", "3", "eq. 82", "a wheel outside released from rest at the top leaves at cos(phi) = 2/(3+2k)")
def _eq82():
    k = np.array([0.0, 0.25, 0.5])

    def normal(phi):
        return vertical.contact_force(phi, deg(90.0), 0.0, A, R, k, G, outside=True)["normal"]

    # the three roots bisected side by side to 1e-14 rad: positive at
    # the top, negative at the side (scipy.optimize is not needed here,
    # which keeps its import out of a worker that checks only this claim)
    lo, hi = np.full(3, 1e-6), np.full(3, np.pi / 2)
    at_lo = normal(lo) > 0
    while np.any(hi - lo > 1e-14):
        mid = 0.5 * (lo + hi)
        same = (normal(mid) > 0) == at_lo
        lo, hi = np.where(same, mid, lo), np.where(same, hi, mid)
    rows = list(zip(k, np.cos(0.5 * (lo + hi)), 2 / (3 + 2 * k)))
    err = max(abs(c - e) for _, c, e in rows)
    return Finding("confirmed" if err < 1e-9 else "refuted",
                   "normal force of eqs. 27-28 root-found: " +
                   "; ".join(f"k = {k:g}: cos phi = {c:.6f} vs {e:.6f}" for k, c, e in rows))


# -- secs. 4-5: a sphere rolling on a sphere --------------------------------------

@claim("E56", "4", "eq. 56", "eq. 55 has real Omega iff (k a omega3)^2 >= 4 (k+1) g r' cos(theta)")
def _eq56():
    theta = deg(np.linspace(1, 179, 179))[:, None]
    omega3 = np.linspace(-80, 80, 321)[None, :]
    slow, _ = sphere.orbit_rates(theta, omega3, A, R, 0.4, G)
    real = np.isfinite(slow)
    predicted = (0.4 * A * omega3) ** 2 >= 4 * 1.4 * G * (R - A) * np.cos(theta)
    equator = np.abs(np.cos(theta)) <= SINGULAR
    mismatch = int(np.count_nonzero((real != predicted) & ~np.broadcast_to(equator, real.shape)))
    return Finding("confirmed" if mismatch == 0 else "refuted",
                   f"real roots exactly where eq. 56 holds on a {real.size}-point grid ({mismatch} mismatches)")


@claim("E58", "4", "eq. 58", "at the least spin of eq. 56, contact (eq. 58) needs tan^2(theta) > k + 1")
def _eq58():
    k = 0.4
    theta = deg(np.linspace(1, 89, 881))
    w3 = sphere.omega3_min_real(theta, A, R, k, G)
    slow, fast = sphere.orbit_rates(theta, w3 * (1 + 1e-12), A, R, k, G)
    omega = 0.5 * (slow + fast)
    contact = (R - A) * omega ** 2 * np.sin(theta) ** 2 > G * np.cos(theta)
    predicted = np.tan(theta) ** 2 > k + 1
    near = np.abs(np.tan(theta) ** 2 - (k + 1)) < 1e-3
    mismatch = int(np.count_nonzero((contact != predicted) & ~near))
    return Finding("confirmed" if mismatch == 0 else "refuted",
                   f"contact at the double root iff tan^2 theta > k + 1 on 881 angles ({mismatch} mismatches); "
                   f"k = 2/5: threshold {np.degrees(np.arctan(np.sqrt(1.4))):.2f} deg")


@claim("E58-text", "4", "text after eq. 58",
       "for k = 2/5 and theta < 50 deg larger |omega3| is needed for eq. (56) than for eq. (56)")
def _eq58_text():
    k = 0.4
    theta = deg(np.array([30.0, 45.0, 49.0, 51.0, 60.0]))
    real = sphere.omega3_min_real(theta, A, R, k, G)
    contact = sphere.omega3_min_contact(theta, A, R, k, G)
    more = contact > real * (1 + 1e-9)
    expected = np.degrees(theta) < np.degrees(np.arctan(np.sqrt(1 + k)))
    good = np.array_equal(more, expected)
    return Finding("corrected" if good else "refuted",
                   "contact (eq. 58) needs more spin than eq. 56 exactly below 49.80 deg: the text should read "
                   f"'(58) than (56)'; least |omega3| real/contact at 30 deg: {real[0]:.2f}/{contact[0]:.2f} rad/s")


@claim("E57", "4", "eq. 57", "F/m = (g + r' Omega^2 cos theta) sin theta 1 - (r' Omega^2 sin^2 theta - g cos theta) 3")
def _eq57():
    theta, omega = deg(120.0), 3.0
    rho = R - A
    normal, friction = sphere.contact_force(theta, omega, A, R, G)
    printed_1 = (G + rho * omega ** 2 * np.cos(theta)) * np.sin(theta)
    # independently, F/m = a_cm + g z with a_cm = -rho sin(theta) Omega^2 r_hat' (horizontal, towards
    # the axis); axis 1 = theta_hat (eq. 47), r_hat'.theta_hat = cos(theta), z.theta_hat = -sin(theta)
    direct_1 = -(rho * omega ** 2 * np.sin(theta)) * np.cos(theta) - G * np.sin(theta)
    verdict = "corrected" if np.isclose(direct_1, -printed_1) and np.isclose(float(friction), direct_1) else "refuted"
    return Finding(verdict, f"1-component at theta = 120 deg, Omega = 3: {direct_1:.4f} m/s^2 from m(a_cm + g z); "
                            f"printed {printed_1:+.4f}: the sign is wrong (contact, eq. 58, unaffected)")


@claim("E59", "5", "eq. 59", "outside, contact (eq. 59) can only hold for theta < pi/2")
def _eq59():
    theta = deg(np.linspace(1, 179, 179))[:, None]
    res = sphere.sphere_orbit(theta, np.linspace(-200, 200, 201)[None, :], A, R, 0.4, G, outside=True)
    ok = res["status"] == Status.OK
    lowest = np.rad2deg(np.broadcast_to(theta[..., None], ok.shape)[ok]).max()
    return Finding("confirmed" if lowest < 90 else "refuted",
                   f"feasible outside orbits up to theta = {lowest:.1f} deg only")


@claim("S5-spin", "5", "eqs. 55, 59", "outside, too large |omega3| violates eq. 59")
def _too_much_spin():
    theta = deg(30.0)
    res = sphere.sphere_orbit(theta, np.array([300.0, 1000.0, 10000.0]), A, R, 0.4, G, outside=True)
    slow_ok = bool(np.all(res["status"][:, 0] == Status.OK))
    fast_lost = bool(np.all(res["status"][:, 1] == Status.NO_CONTACT))
    return Finding("corrected" if slow_ok and fast_lost else "refuted",
                   "true of the fast root of eq. 55 only: at theta = 30 deg and |omega3| = 300, 1e3, 1e4 rad/s "
                   "the slow root keeps contact, the fast one loses it")


# -- sec. 3 and the figure ---------------------------------------------------------

@claim("S3-class", "3", "eqs. 29, 84", "outside there is a class of orbits with theta < pi/2 and alpha very near pi + theta")
def _outside_class():
    theta, alpha, rp = _survey(outside=True)
    upper = (theta < np.pi / 2) & (np.mod(alpha - theta, 2 * np.pi) > np.pi / 2)
    gap = np.rad2deg(np.pi - np.mod(alpha - theta, 2 * np.pi)[upper])   # how far below pi + theta
    at45 = upper & (np.abs(np.rad2deg(theta) - 45) < 0.3)
    below = theta > np.pi / 2
    return Finding("corrected" if upper.any() else "refuted",
                   f"the class exists ({int(upper.sum())} grid orbits) but is not 'very near': alpha lies up to "
                   f"{gap.max():.1f} deg below pi + theta ({gap[np.flatnonzero(at45[upper])].max():.1f} deg at "
                   f"theta = 45); beyond the paper, {int(below.sum())} feasible outside orbits also lie below the "
                   f"equator, near the bottom pole with the centre across the axis (r' < 0: "
                   f"{bool(np.all(rp[below] < 0))})")


@claim("FIG", "2.2.2", "figure alpha_wh, eqs. 0, 29, 33",
       "for a/r = 0.1 the allowed region is bounded by the curves of eqs. (0), (29) and (33)")
def _figure():
    theta = deg(np.linspace(0.05, 179.95, 1200))[:, None]
    alpha = deg(np.linspace(-179.95, 179.95, 2400))[None, :]
    # blocks of rows, each with the first row of the next, so that every
    # pair of neighbours (along theta too) is compared exactly once: the
    # count of the whole grid, with memory for one block only
    unexplained = 0
    for start in range(0, theta.shape[0], _FIGURE_ROWS):
        stop = min(start + _FIGURE_ROWS + 1, theta.shape[0])
        unexplained += _figure_unexplained(theta[start:stop], alpha, last=stop == theta.shape[0])
    return Finding("confirmed" if unexplained == 0 else "refuted",
                   f"every change of feasibility between neighbouring points of a 1200 x 2400 grid crosses one of "
                   f"the three curves ({unexplained} unexplained)")


#: rows of theta per block of the FIG check (240k points, about half evaluated).
_FIGURE_ROWS = 100


def _figure_unexplained(theta, alpha, last):
    """Changes of feasibility between neighbours of the block theta x alpha
    that cross none of the curves of eqs. 0, 29, 33; the changes within
    the block's last row are left to the next block unless ``last``."""
    a_over_r, k = 0.1, 0.5
    theta, alpha = np.broadcast_arrays(theta, alpha)
    # Only where the wheel fits (eq. 0) is the orbit evaluated: elsewhere it
    # is infeasible, and a neighbour pair with one point on each side of
    # eq. (0) always crosses that curve (the eq. 0 margin is > 0 exactly
    # where it fits), so the other margins there cannot change the count.
    fit_margin = np.sin(theta - alpha) - a_over_r                               # eq. 0
    fits = fit_margin > 0
    th, al = theta[fits], alpha[fits]
    res = wheel.horizontal_orbit(th, al, a_over_r, 1.0, k, G)
    ok = np.zeros(fits.shape, dtype=bool)
    ok[fits] = res["status"] == Status.OK
    sign29 = np.ones(fits.shape)
    sign33 = np.ones(fits.shape)
    with np.errstate(invalid="ignore"):
        sign29[fits] = np.sign(np.cos(al) / wheel.omega_squared_denominator(th, al, a_over_r, 1.0, k))  # eq. 29
        sign33[fits] = np.sign(np.where(np.isfinite(res["normal"]), res["normal"], -1.0))            # eq. 33
        signs = [np.sign(fit_margin), sign29, sign33]
    del res
    rows = slice(None) if last else slice(None, -1)      # along alpha: rows of this block only
    unexplained = 0
    for axis, part in ((0, slice(None)), (1, rows)):
        change = np.diff(ok[part], axis=axis)
        crossed = np.zeros_like(change)
        for sg in signs:
            crossed |= np.diff(sg[part], axis=axis) != 0
        unexplained += int(np.count_nonzero(change & ~crossed))
    return unexplained


# -- sec. 2.3: stability, against the exact linearisation and the simulator ----------

def _exact():
    from deathsphere.physics import stability

    return stability


@claim("STAB-V", "2.3.1", "eqs. 100-106", "all vertical orbits for which the wheel keeps contact are stable")
def _stab_vertical():
    st = _exact()
    # a/r = 0.1 grid: stable; a/r = 0.3, k = 1/2: a resonance tongue near the contact threshold
    th = deg(np.array([30.0, 60.0, 90.0]))
    rp = R * np.sin(th) - A
    small = st.vertical_floquet(th, 1.5 * np.sqrt(G / rp), A, R, K, G)
    big_a, theta_big = 0.9, deg(27.3)
    rate = 1.2 * np.sqrt(G / (R * np.sin(theta_big) - big_a))
    big = st.vertical_floquet(theta_big, rate, big_a, R, K, G)
    small_ok = bool(np.all(small["verdict"] == st.Verdict.STABLE))
    big_unstable = int(np.asarray(big["verdict"])) == st.Verdict.UNSTABLE
    return Finding("refuted" if big_unstable or not small_ok else "confirmed",
                   f"Floquet: a/r = 0.1 orbits stable ({small_ok}); a/r = 0.3, k = 1/2, theta = 27.3 deg, "
                   f"top rate 1.2 sqrt(g/r'): max|multiplier| = {float(np.asarray(big['max_abs'])):.3f} "
                   f"(a resonance tongue: unstable although in contact)")


@claim("E103", "2.3.1", "eqs. 103, 103a", "A w^4 - B w^2 - C = 0 with real positive roots for C > -B^2/4A")
def _eq103():
    st = _exact()
    v = st.vertical_paper(deg(70.0), 4.0, A, R, K, G)
    printed_negative = bool(np.asarray(v["omega2_printed"])[1].real < 0)
    corrected_positive = bool(np.all(np.asarray(v["omega2"]).real > 0))
    return Finding("corrected" if printed_negative and corrected_positive else "refuted",
                   f"the determinant of eq. 102 is -(A w^4 - B w^2 + C): with the printed sign a root w^2 is "
                   f"negative ({printed_negative}) on an orbit in contact (theta = 70 deg, top rate 4 rad/s); "
                   f"corrected, both are positive ({corrected_positive}) and stability needs C > 0 and B^2 >= 4AC")


@claim("STAB-EQ", "2.3.3", "eqs. 133-138", "all steady orbits on the equator are stable")
def _stab_equator():
    from deathsphere import simulation

    st = _exact()
    alpha = deg(np.arange(1.0, 84.0, 0.25))
    res = st.wheel_stability(np.pi / 2, alpha, A, R, K, G)
    unstable = np.rad2deg(alpha[res["verdict"] == st.Verdict.UNSTABLE])
    _, run = simulation.run_simulation(simulation.horizontal_starts(Setup(), 90.0, 80.0, perturb_deg=np.rad2deg(1e-6)), periods=2)
    verdict = "refuted" if unstable.size else "confirmed"
    return Finding(verdict, f"a/r = 0.1: exact linearisation unstable for alpha >= {unstable.min():.2f} deg "
                            f"(orbits fit up to 84.3); the simulator, kicked by 1e-6 rad at alpha = 80 deg: "
                            f"{run['status'][0]} after {float(run['periods_simulated'][0]):.2f} periods")


@claim("E133", "2.3.3", "eqs. 133-138", "the slow and fast nutation frequencies of orbits on the equator")
def _eq133():
    st = _exact()
    alpha = deg(np.arange(5.0, 70.0, 5.0))
    exact = st.wheel_stability(np.pi / 2, alpha, A, R, K, G)
    paper = st.equator_paper(alpha, A, R, K, G)
    off = np.abs(np.asarray(paper["freq_slow"]) / exact["freq_slow"] - 1)
    return Finding("refuted" if np.median(off) > 0.05 else "confirmed",
                   f"printed slow frequencies off the exact ones by {100 * np.median(off):.0f} % (median) to "
                   f"{100 * off.max():.0f} % for a/r = 0.1, alpha 5..65 deg: eq. 116 drops a first-order yaw "
                   f"of axis 3 (E4)")


@claim("STAB-SMALL", "2.3.4", "eqs. 201-207", "all orbits of small wheels (a << r') are stable")
def _stab_small():
    st = _exact()
    th, al = np.meshgrid(deg(np.arange(10.0, 176.0, 5.0)), deg(np.arange(1.0, 90.0, 1.0)), indexing="ij")
    h = wheel.horizontal_orbit(th, al, 0.01, 1.0, 0.5, G)
    ok = (h["status"] == Status.OK) & (0.01 / np.abs(np.sin(th) - 0.01 * np.cos(al)) <= 0.05)
    res = st.wheel_stability(th[ok], al[ok], 0.01, 1.0, 0.5, G)
    bad = np.rad2deg(al[ok][res["verdict"] == st.Verdict.UNSTABLE])
    below_85 = int(np.count_nonzero(bad < 85))
    return Finding("confirmed" if below_85 == 0 else "refuted",
                   f"a/r = 0.01, a/r' <= 0.05: {int(ok.sum()) - bad.size}/{int(ok.sum())} stable; the unstable ones "
                   f"all have alpha >= {bad.min() if bad.size else float('nan'):.0f} deg, where Omega -> 0 "
                   f"(eq. 201 also needs a << r' cot alpha)")


@claim("E207", "2.3.4", "eq. 207", "small wheels nutate at w^2 = Omega^2 tan(alpha) (1 + sin 2 alpha)")
def _eq207():
    st = _exact()
    th, al = np.meshgrid(deg([40.0, 60.0, 90.0, 120.0, 150.0]), deg([5.0, 20.0, 35.0]), indexing="ij")
    exact = st.wheel_stability(th, al, 1e-4, 1.0, 0.25, G)
    paper = st.small_wheel_paper(th, al, 1e-4, 1.0, 0.25, G)
    corrected = st.small_wheel_corrected(th, al, 1e-4, 1.0, 0.25, G)
    off = np.abs(paper["freq"] / exact["freq_slow"] - 1)
    fixed = np.abs(corrected["freq_slow"] / exact["freq_slow"] - 1)
    return Finding("refuted" if np.median(off) > 0.05 else "confirmed",
                   f"a/r = 1e-4: eq. 207 off the exact slow frequency by {100 * np.median(off):.0f} % (median), up to "
                   f"{100 * off.max():.0f} %; w^2 = Omega^2 [1 + 3 sin a tan a sin th / sin(th - a)] is within "
                   f"{100 * fixed.max():.2f} % (E5)")


@claim("STAB-LARGE", "2.3.4", "conjecture", "orbits of large wheels above the equator are stable")
def _stab_large():
    st = _exact()
    th, al = np.meshgrid(deg(np.arange(20.0, 90.0, 2.0)), deg(np.arange(1.0, 89.0, 1.0)), indexing="ij")
    h = wheel.horizontal_orbit(th, al, 0.3, 1.0, 0.5, G)
    ok = h["status"] == Status.OK
    res = st.wheel_stability(th[ok], al[ok], 0.3, 1.0, 0.5, G)
    share = float(np.mean(res["verdict"] == st.Verdict.STABLE))
    return Finding("refuted" if share < 0.99 else "confirmed",
                   f"a/r = 0.3, k = 1/2, theta < 90 deg: {100 * share:.0f} % of {int(ok.sum())} feasible orbits "
                   f"stable; the steeper tilts at each theta are unstable")


@claim("E208", "2.3.4", "eq. 208", "a wheel rolling on a plane is stable for Omega^2 > g/((2k+1) a)")
def _eq208():
    st = _exact()
    out = []
    for k in (0.25, 0.5):
        a, r, th = 1.0, 1e5, np.pi - 1e-3
        al = deg(np.linspace(89.5, 89.95, 2001))
        res = st.wheel_stability(th, al, a, r, k, G)
        w1sq = (r_prime(th, al, a, r) * res["omega"]) ** 2 * a / G
        i = np.flatnonzero((res["verdict"][:-1] == st.Verdict.STABLE) & (res["verdict"][1:] == st.Verdict.UNSTABLE))
        out.append((k, float(w1sq[i[0]]) if i.size else float("nan")))
    half = all(abs(x * 2 * (2 * k + 1) - 1) < 0.03 for k, x in out)
    return Finding("corrected" if half else "refuted",
                   "exact threshold of a disc rolling on a (locally) flat floor, w1^2 a/g: " +
                   "; ".join(f"k = {k:g}: {x:.4f} (printed {1 / (2 * k + 1):.4f})" for k, x in out) +
                   ": half the printed value, g/(2(2k+1)a) (E6)")


@claim("STAB-OUT", "3", "after eq. 84", "outside, orbits with alpha near pi + theta appear to be unstable")
def _stab_outside():
    st = _exact()
    th = deg(np.arange(10.0, 80.0, 5.0))[:, None]
    al = th + np.pi - deg(np.arange(0.5, 10.0, 0.5))[None, :]
    th, al = np.broadcast_arrays(th, al)
    h = wheel.horizontal_orbit(th, al, A, R, K, G, outside=True)
    ok = h["status"] == Status.OK
    res = st.wheel_stability(th[ok], al[ok], A, R, K, G, outside=True)
    share = float(np.mean(res["verdict"] == st.Verdict.STABLE))
    near90 = deg(np.arange(80.0, 89.9, 0.5))
    th2 = np.full_like(near90, deg(40.0))
    h2 = wheel.horizontal_orbit(th2, near90, A, R, K, G, outside=True)
    res2 = st.wheel_stability(th2[h2["status"] == Status.OK], near90[h2["status"] == Status.OK], A, R, K, G,
                              outside=True)
    share90 = float(np.mean(res2["verdict"] == st.Verdict.UNSTABLE)) if res2["verdict"].size else float("nan")
    return Finding("refuted" if share > 0.5 else "confirmed",
                   f"within 10 deg of pi + theta {100 * share:.0f} % of {int(ok.sum())} feasible orbits are stable "
                   f"(a spinning wheel standing nearly upright on the ball); next to alpha = 90 deg "
                   f"{100 * share90:.0f} % are unstable, as the paper says")


@claim("STAB-SPH", "4, 5", "eqs. 46, 55", "horizontal orbits of a rolling sphere are stable (Milne)")
def _stab_sphere():
    st = _exact()
    out = []
    for outside in (False, True):
        th = deg(np.linspace(5, 175, 35))[:, None]
        res = sphere.sphere_orbit(th, np.linspace(-150, 150, 31)[None, :], A, R, 0.4, G, outside=outside)
        ok = res["status"] == Status.OK
        theta = np.broadcast_to(th[..., None], ok.shape)[ok]
        stab = st.sphere_stability(theta, res["omega"][ok], A, R, 0.4, G, outside=outside)
        out.append((int(ok.sum()), int(np.count_nonzero(stab["verdict"] == st.Verdict.STABLE))))
    good = all(n == s for n, s in out)
    return Finding("confirmed" if good else "refuted",
                   f"exact linearisation: inside {out[0][1]}/{out[0][0]}, outside {out[1][1]}/{out[1][0]} orbits "
                   f"in contact stable")


@claim("T1-stable", "abstract, 2.2.2", "Table 1", "stable orbits lie wholly above the equator (e.g. Table 1)")
def _table1_stable():
    st = _exact()
    theta = deg(np.array([float(r[0]) for r in PRINTED]))
    alpha = deg(np.array([float(r[1]) for r in PRINTED]))
    res = st.wheel_stability(theta, alpha, A, R, K, G)
    n = int(np.count_nonzero(res["verdict"] == st.Verdict.STABLE))
    return Finding("confirmed" if n == 10 else "refuted",
                   f"{n}/10 Table 1 orbits stable (six of them above the equator); slow/fast nutation at "
                   f"(60, 10): {res['freq_slow'][3]:.2f}/{res['freq_fast'][3]:.2f} rad/s")


def run(ids: list[str] | None = None, progress: Callable[[Claim], None] | None = None,
        jobs: int = 1) -> Table:
    """Check the selected claims (all by default), in the order of the paper.

    ``progress`` is called with each claim before it is checked (with
    ``jobs`` > 1: as its finding arrives).  ``jobs`` > 1 checks the claims
    on that many processes (:func:`deathsphere.parallel.ordered_map`), the
    slow ones first so that no process is left with one at the end, and
    the claims that share cached work in one process; each claim is
    computed exactly as in one process, so the table is the same."""
    chosen = [c for c in CLAIMS if ids is None or c.id in ids]
    unknown = sorted(set(ids or []) - {c.id for c in CLAIMS})
    if unknown:
        raise ValueError(f"unknown claim {unknown[0]!r}; known: {', '.join(c.id for c in CLAIMS)}")
    if jobs > 1 and len(chosen) > 1:
        from deathsphere.parallel import ordered_map

        by_id = {c.id: c for c in chosen}
        done = {}
        units = _work_units([c.id for c in chosen])
        for unit, findings in zip(units, ordered_map(check_claims, units, jobs)):
            for claim_id, finding in zip(unit, findings):
                if progress:
                    progress(by_id[claim_id])
                done[claim_id] = finding
        found = [done[c.id] for c in chosen]
    else:
        found = []
        for c in chosen:
            if progress:
                progress(c)
            found.append(c.check())
    return Table({
        "id": np.array([c.id for c in chosen], dtype=object),
        "section": np.array([c.section for c in chosen], dtype=object),
        "equation": np.array([c.equation for c in chosen], dtype=object),
        "claim": np.array([c.statement for c in chosen], dtype=object),
        "verdict": np.array([f.verdict for f in found], dtype=object),
        "evidence": np.array([f.evidence for f in found], dtype=object),
    })


#: claims that share cached work (the survey inside), checked by one process
_SHARED = (("Q", "UP"),)
#: the slowest claims (CPU time, slowest first), started first with jobs > 1
_SLOW_FIRST = ("STAB-EQ", "FIG", "STAB-V", "Q", "S3-class")


def _work_units(ids: list[str]) -> list[tuple[str, ...]]:
    """``ids`` as units of work for several processes: groups of
    :data:`_SHARED` together, the slow ones first, else in given order."""
    grouped = [tuple(i for i in ids if i in group) for group in _SHARED]
    units = [u for u in grouped if u] + [(i,) for i in ids if not any(i in g for g in _SHARED)]

    def rank(unit):
        return min((_SLOW_FIRST.index(i) for i in unit if i in _SLOW_FIRST), default=len(_SLOW_FIRST))

    return sorted(units, key=rank)


def check_claims(ids: tuple[str, ...]) -> list[Finding]:
    """The findings of the claims ``ids``, in that order (a picklable unit
    of work for :func:`run` with several processes)."""
    by_id = {c.id: c for c in CLAIMS}
    unknown = [i for i in ids if i not in by_id]
    if unknown:
        raise ValueError(f"unknown claim {unknown[0]!r}")
    return [by_id[i].check() for i in ids]


def counts(table: Table) -> dict[str, int]:
    return {v: int(np.count_nonzero(table["verdict"] == v)) for v in VERDICTS}
