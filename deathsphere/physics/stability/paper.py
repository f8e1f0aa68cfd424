"""The paper's stability results, as printed and as corrected.

McDonald (1993) sec. 2.3: vertical orbits eqs. (100)-(106), the orbit on
the equator eqs. (127)-(138), small wheels eqs. (201)-(207), near the poles
eq. (208); each implemented as printed and, where the printed form has a
slip, as corrected (docs/stability.md, "Errata").  The exact answers they
are compared with are in :mod:`~deathsphere.physics.stability.horizontal`,
:mod:`~deathsphere.physics.stability.floquet` and
:mod:`~deathsphere.physics.stability.closed_forms`.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.geometry import r_prime
from deathsphere.physics.stability.frequencies import (
    both_real_positive,
    quadratic_roots,
    real_frequencies,
)
from deathsphere.physics.wheel import omega_squared

__all__ = ["vertical_paper", "equator_coefficients", "equator_matrix", "equator_printed_abc",
           "equator_paper", "small_wheel_paper", "small_wheel_corrected", "near_pole_paper"]


def vertical_paper(theta, phidot_top, a, r, k, g):
    """The paper's stability analysis of vertical orbits, eqs. (100)-(106).

    McDonald (1993) sec. 2.3.1: the perturbation equations (76)-(77) frozen
    at the top of the orbit (phi = 0) with eps_r ~ cos(w t),
    eps_s ~ sin(w t) give the 2x2 system (102), whose determinant the paper
    writes A w^4 - B w^2 - C = 0 (103) with A, B, C of eqs. (104)-(105).

    Parameters broadcast: theta [rad] cone angle of the orbit (r sin(theta)
    is the radius of the rim's circle of contact), phidot_top [rad/s] orbital
    rate at the top, a, r [m], k [-], g [m/s^2].

    Returns dict: ``r_prime`` = r sin(theta) - a [m]; ``A`` [m^2],
    ``B`` [m^2/s^2], ``C`` [m^2/s^4] (eqs. 104-105); as printed:
    ``omega2_printed`` (2, ...) complex, roots (B +/- sqrt(B^2 + 4AC))/2A of
    eq. (103a) [rad^2/s^2]; ``stable_printed`` the paper's criterion
    B^2 + 4AC > 0 (its text: "real, positive roots whenever C > -B^2/4A");
    ``eq106`` phidot_top^2 > g/((2k+1) r' + k a); ``contact_28a``
    phidot_top^2 > g/r' (eq. 28a).  Corrected (errata E1, E2 of
    docs/stability.md): the determinant of (102) is
    -(A w^4 - B w^2 + C), so ``omega2`` (2, ...) = (B +/- sqrt(B^2 - 4AC))/2A
    and ``stable`` = (C > 0) & (B^2 >= 4AC) (both roots real positive);
    ``freq_slow``, ``freq_fast`` [rad/s] their square roots.

    The frozen-coefficient analysis is an approximation in any case (it
    drops the theta perturbation and, off the great circle theta = pi/2,
    mis-states the contact geometry, erratum E3); the exact answer is
    :func:`vertical_floquet`.
    """
    theta, phidot_top, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (theta, phidot_top, a, r, k, g)))
    rp = r_prime(theta, 0.0, a, r)
    p2 = phidot_top ** 2
    A = k * (k + 1) * a ** 2
    B = k * a * g + k * ((2 * k + 1) * (2 * rp ** 2 + a ** 2) + (4 * k + 1) * a * rp) * p2
    C = k * (2 * rp + a) * (((2 * k + 1) * rp + k * a) * p2 - g) * p2
    pr1, pr2 = quadratic_roots(A, -B, -C)
    x1, x2 = quadratic_roots(A, -B, C)
    slow, fast = real_frequencies(x1, x2)
    with np.errstate(divide="ignore", invalid="ignore"):
        eq106 = p2 > g / ((2 * k + 1) * rp + k * a)
        contact = (rp > 0) & (p2 * rp > g)
    return {
        "r_prime": rp, "A": A, "B": B, "C": C,
        "omega2_printed": np.stack((pr1, pr2)),
        "stable_printed": B * B + 4 * A * C > 0,
        "eq106": eq106, "contact_28a": contact,
        "omega2": np.stack((x1, x2)),
        "stable": (C > 0) & (B * B >= 4 * A * C),
        "freq_slow": slow, "freq_fast": fast,
    }


def equator_matrix(alpha, nu, a, r, k, g):
    """The 3x3 coefficient matrix of eq. (133)/(134) as printed, at trial
    frequency nu [rad/s] (the w of eq. 133), for the orbit on the equator (theta = pi/2) with
    tilt alpha [rad]; Omega from eq. (29), r'_0 = r - a cos(alpha).
    Rows: the s, t, u equations; columns: delta, eps_s, eps_t.
    Returns an array of shape (..., 3, 3)."""
    c = equator_coefficients(alpha, a, r, k, g)
    w = np.asarray(nu, dtype=float)
    w2 = w * w
    row1 = (c["A11"] * w, c["A12"] * w, c["A13"] + c["B13"] * w2)
    row2 = (c["A21"] * w2, c["A22"] + c["B22"] * w2, c["A23"] * w)
    row3 = (c["A31"] * w2, c["A32"] + 0 * w, c["A33"] * w)
    rows = [np.stack(np.broadcast_arrays(*row), axis=-1) for row in (row1, row2, row3)]
    return np.stack(rows, axis=-2)


def equator_printed_abc(c):
    """A, B, C of eqs. (136)-(138) as printed, from the coefficients of the
    3x3 system (134) (``c`` as returned by :func:`equator_coefficients`)."""
    A = c["B13"] * c["B22"] * c["A31"]
    B = (c["A11"] * c["B22"] * c["A33"] + c["A12"] * c["A23"] * c["A31"]
         + c["B13"] * c["A21"] * c["A32"] - c["A13"] * c["B22"] * c["A31"]
         - c["B13"] * c["A22"] * c["A31"] - c["A12"] * c["A21"] * c["A33"])
    C = (c["A11"] * c["A22"] * c["A33"] + c["A13"] * c["A21"] * c["A32"]
         - c["A13"] * c["A22"] * c["A31"] - c["A11"] * c["A23"] * c["A32"])
    return A, B, C


def equator_coefficients(alpha, a, r, k, g):
    """A_ij, B_ij of eq. (134), read off eq. (133) as printed, for the orbit
    on the equator with tilt alpha [rad]: dict with keys ``A11`` ... ``A33``,
    ``B13``, ``B22``, ``Omega`` [rad/s] (eq. 29) and ``r_prime`` [m]
    (eq. 8b at theta = pi/2)."""
    alpha, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (alpha, a, r, k, g)))
    sa, ca = np.sin(alpha), np.cos(alpha)
    rp = r_prime(np.pi / 2, alpha, a, r)               # r'_0 on the equator
    om2 = omega_squared(np.pi / 2, alpha, a, r, k, g)
    om2 = np.where(om2 > 0, om2, np.nan)
    Om = np.sqrt(om2)
    return {
        "Omega": Om, "r_prime": rp,
        "A11": 2 * Om * sa * ((2 * k + 1) * rp + k * a * ca),
        "A12": -Om * (2 * k + 1) * (rp + a * ca),
        "A13": -(om2 * ((2 * k + 1) * rp * ca + (k + sa ** 2) * a) - g * sa),
        "B13": -(k + 1) * a,
        "A21": -k * a * sa,
        "A22": k * om2 * ca * (2 * rp + a * ca),
        "B22": k * a,
        "A23": 2 * k * Om * (rp + a * ca),
        "A31": -(2 * k + 1) * rp,
        "A32": om2 * sa * ((2 * k + 1) * rp + (k + 1) * a * ca),
        "A33": 2 * (k + 1) * Om * sa * a,
    }


def equator_paper(alpha, a, r, k, g):
    """The paper's stability analysis of the orbit on the equator,
    eqs. (127)-(138), as printed.

    McDonald (1993) sec. 2.3.3: eq. (133) is a 3x3 homogeneous system in
    (delta, eps_s, eps_t); det = 0 gives A w^4 - B w^2 - C = 0 (135) with the
    closed forms (136)-(138).  Both routes are evaluated:

    ``omega2_det`` (2, ...) complex [rad^2/s^2]: roots in w^2 of
    det(eq. 133)/w^2 (a quadratic in w^2), found numerically by evaluating
    the printed matrix (:func:`equator_matrix`) at three trial frequencies;
    ``A``, ``B``, ``C`` from eqs. (136)-(138) and ``omega2_closed`` the roots
    of eq. (135) with them (the two agree: eqs. 135-138 are the correct
    expansion of the printed determinant); ``stable_printed`` both w^2 roots
    real and positive (what "stable" means); ``all_positive`` A, B, C > 0
    (the paper's stated numerical finding); ``freq_slow``, ``freq_fast``
    [rad/s]; ``Omega`` [rad/s] (eq. 29).

    Beyond-the-paper finding (docs/stability.md, erratum E4): eq. (133)
    rests on eq. (116), which keeps axis 3 in the vertical t-u plane; the
    rolling contact actually tilts it out of that plane by
    eps_s r sin(alpha)/(r cos(alpha) - a) on the equator, a first-order term
    the paper drops, so these frequencies differ from the exact ones
    (:func:`equator_exact_closed_form`, :func:`wheel_stability`).
    """
    c = equator_coefficients(alpha, a, r, k, g)
    A, B, C = equator_printed_abc(c)
    x1, x2 = quadratic_roots(A, -B, -C)
    # numerical route: q(x) = det(M(sqrt x))/x is quadratic in x = w^2
    Om2 = c["Omega"] ** 2
    xs = np.stack([Om2 * f for f in (1.0, 2.0, 3.0)])
    alpha_b = np.broadcast_to(np.asarray(alpha, dtype=float), Om2.shape)
    with np.errstate(invalid="ignore"):
        M = equator_matrix(alpha_b, np.sqrt(xs), a, r, k, g)
    finite = np.all(np.isfinite(M), axis=(-2, -1))
    dets = np.where(finite, np.linalg.det(np.where(finite[..., None, None], M, 0.0)), np.nan)
    q = dets / xs
    # q(x) = q2 x^2 + q1 x + q0 through the three points (x = Om2 (1, 2, 3))
    d1 = (q[1] - q[0]) / Om2
    d2 = (q[2] - q[1]) / Om2
    q2 = (d2 - d1) / (2 * Om2)
    q1 = d1 - q2 * (xs[0] + xs[1])
    q0 = q[0] - q1 * xs[0] - q2 * xs[0] ** 2
    y1, y2 = quadratic_roots(q2, q1, q0)
    slow, fast = real_frequencies(x1, x2)
    return {
        "Omega": c["Omega"], "r_prime": c["r_prime"],
        "A": A, "B": B, "C": C,
        "omega2_closed": np.stack((x1, x2)),
        "omega2_det": np.stack((y1, y2)),
        "stable_printed": both_real_positive(x1, x2),
        "all_positive": (A > 0) & (B > 0) & (C > 0),
        "freq_slow": slow, "freq_fast": fast,
    }


def small_wheel_paper(theta, alpha, a, r, k, g):
    """The paper's small-wheel result, eqs. (201)-(207), as printed.

    w^2 = Omega^2 sin(alpha)(cos(alpha) + 2 sin(alpha))
          + g sin^2(alpha)/((2k+1) r'_0)                      (207, first form)
        = Omega^2 tan(alpha)(1 + sin(2 alpha))              (207, second form)

    with Omega from eq. (29).  The two forms agree when a << r'_0 (eq. 201):
    checked, no slip in this step.  Returns dict ``omega2_first``,
    ``omega2_second`` [rad^2/s^2], ``freq`` [rad/s] (sqrt of the first
    form, NaN if negative), ``stable_printed`` (w^2 > 0: "all orbits for
    small wheels are stable"), ``validity`` a/r'_0 (eq. 201 asks << 1),
    ``Omega``.

    Eq. (203) inherits the sin/cos slip of eq. (128) (erratum E8: with cos
    the same steps give Omega^2 (1 + 2 sin^2 alpha)), and the physics behind
    eqs. (202)-(204) drops the first-order tilt of axis 3 (eq. 116, erratum
    E4); the correct small-wheel limit is :func:`small_wheel_corrected`.
    """
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (theta, alpha, a, r, k, g)))
    om2 = omega_squared(theta, alpha, a, r, k, g)
    om2 = np.where(om2 > 0, om2, np.nan)
    rp = r_prime(theta, alpha, a, r)
    sa, ca = np.sin(alpha), np.cos(alpha)
    with np.errstate(divide="ignore", invalid="ignore"):
        first = om2 * sa * (ca + 2 * sa) + g * sa ** 2 / ((2 * k + 1) * rp)
        second = om2 * np.tan(alpha) * (1 + np.sin(2 * alpha))
        validity = a / np.abs(rp)
        freq = np.sqrt(np.where(first > 0, first, np.nan))
    return {"omega2_first": first, "omega2_second": second, "freq": freq,
            "stable_printed": first > 0, "validity": validity,
            "Omega": np.sqrt(om2)}


def small_wheel_corrected(theta, alpha, a, r, k, g):
    """Correct small-wheel limit (a << r'_0) of the two nutation frequencies
    of a steady horizontal orbit (beyond the paper: erratum E5,
    docs/stability.md; confirmed against :func:`wheel_stability`).

    slow:  w_s^2 = Omega^2 [1 + 3 sin(alpha) tan(alpha) sin(theta)/sin(theta - alpha)]
    fast:  w_f^2 = 2 (2k+1)/(k+1) w_1^2,   w_1 = r'_0 Omega / a (eq. 13)

    Omega from eq. (29).  Leading order in a/r'_0; the slow form is
    independent of k.  Returns dict ``omega2_slow``, ``omega2_fast``
    [rad^2/s^2], ``freq_slow``, ``freq_fast`` [rad/s].
    """
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (theta, alpha, a, r, k, g)))
    om2 = omega_squared(theta, alpha, a, r, k, g)
    om2 = np.where(om2 > 0, om2, np.nan)
    rp = r_prime(theta, alpha, a, r)
    sa = np.sin(alpha)
    with np.errstate(divide="ignore", invalid="ignore"):
        slow2 = om2 * (1 + 3 * sa * np.tan(alpha) * np.sin(theta) / np.sin(theta - alpha))
        fast2 = 2 * (2 * k + 1) / (k + 1) * (rp / a) ** 2 * om2
        fs = np.sqrt(np.where(slow2 > 0, slow2, np.nan))
    return {"omega2_slow": slow2, "omega2_fast": fast2,
            "freq_slow": fs, "freq_fast": np.sqrt(fast2)}


def near_pole_paper(theta, alpha, a, r, k, g):
    """The paper's near-pole criterion, eq. (208), and its correction.

    McDonald (1993) eq. (208), quoted for a wheel rolling on a horizontal
    plane and offered for orbits with r'_0 <~ a:  Omega^2 > g/((2k+1) a).
    The straight-rolling criterion is in fact
    w^2 > g/(2 (2k+1) a) (erratum E6: the gyroscopic coupling is
    2 (2k+1) w^2 in the lean equation; classical hoop v^2 > g a/4, coin
    v^2 > g a/3; reproduced by :func:`wheel_stability` for a wide circle on a
    nearly flat floor).

    Returns dict ``Omega`` [rad/s] (eq. 29), ``threshold_printed`` =
    g/((2k+1) a) and ``threshold_disk`` = g/(2 (2k+1) a) [rad^2/s^2],
    ``stable_printed`` Omega^2 > threshold_printed, ``stable_disk``
    Omega^2 > threshold_disk, ``applies`` r'_0 <= a (the paper's "r'_0 <~ a").
    """
    theta, alpha, a, r, k, g = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (theta, alpha, a, r, k, g)))
    om2 = omega_squared(theta, alpha, a, r, k, g)
    om2 = np.where(om2 > 0, om2, np.nan)
    rp = r_prime(theta, alpha, a, r)
    t_p = g / ((2 * k + 1) * a)
    t_d = t_p / 2
    return {"Omega": np.sqrt(om2), "threshold_printed": t_p, "threshold_disk": t_d,
            "stable_printed": om2 > t_p, "stable_disk": om2 > t_d,
            "applies": np.abs(rp) <= a}
