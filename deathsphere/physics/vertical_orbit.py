"""Vertical orbits of a wheel rolling on a fixed sphere.

McDonald (1993) sec. 2.2.1, eqs. (26)-(28b) (inside) and sec. 3, eq. (82)
(outside).  On a vertical orbit the normal z' of the orbit plane is
horizontal (beta = pi/2) and the wheel lies in the orbit plane: alpha = 0
inside, alpha = pi outside.  The contact point runs round a circle of cone
angle ``theta`` about z' (radius r sin(theta)); the wheel's centre runs round
a circle of radius

    r' = r sin(theta) - a   inside,    r' = r sin(theta) + a   outside

(eq. 8b with alpha = 0 or pi).  phi is the azimuth of the centre from the top
(phi = 0 at the top, phi = pi at the bottom), phidot_top the rate at the top.
theta = 90 deg is a vertical great circle; theta and 180 deg - theta are
mirror images.

Force components (per unit mass) use the basis of the orbit: ``along`` is
along the velocity (axis 2 of the paper), ``radial`` along r-hat' (from the
z' axis towards the contact point).  ``normal`` is the component pressing
wheel and sphere together, ``meridional`` the friction component along
theta-hat (positive towards increasing theta, i.e. away from the z'-pole of
the cone).  The friction magnitude is hypot(along, meridional) (eq. 28c).

Units: angles in rad, lengths in m, rates in rad/s, g in m/s^2.  Everything
broadcasts; nothing raises for a physically impossible orbit (that is a
status, :mod:`deathsphere.physics.status`).  Derivations that go beyond the
printed equations (lap time, release angle with a top speed, worst point,
slip angle) are in docs/derivations-configurations.md.
"""

import numpy as np

from deathsphere.physics.geometry import SINGULAR, r_prime
from deathsphere.physics.status import Reason, Status, first_failure, mu_required

__all__ = [
    "vertical_r_prime", "vertical_fits", "top_rate_from_speed", "top_speed_from_rate",
    "min_top_rate", "min_top_speed", "rate_squared", "contact_force",
    "release_angle", "slip_angle", "worst_point", "lap_time", "phi_grid",
    "vertical_orbit", "vertical_profile",
]


def _ellipk(m):
    """Complete elliptic integral of the first kind K(m), parameter m in
    [0, 1), by the arithmetic-geometric mean: K(m) = pi / (2 AGM(1,
    sqrt(1 - m))) (Abramowitz & Stegun 17.6.1).  Agrees with
    scipy.special.ellipk to a few ulp (5.6e-16 relative, measured over
    [0, 1 - 1e-16]); written here so that the vertical-orbit path does not
    import scipy.special (~0.3 s).  Beyond the paper (lap time,
    docs/derivations-configurations.md)."""
    m = np.asarray(m, dtype=float)
    a = np.ones_like(m)
    b = np.sqrt(1.0 - m)
    for _ in range(64):                  # quadratic convergence: <= ~10 rounds
        if np.all(np.abs(a - b) <= 2.3e-16 * a):
            break
        a, b = 0.5 * (a + b), np.sqrt(a * b)
    return np.pi / (a + b)


def _arrays(*xs):
    return [np.asarray(x, dtype=float) for x in xs]


def _cos(theta):
    """cos(theta), snapped to 0 within SINGULAR: theta = 90 deg given in
    degrees is a great circle only up to round-off (cos = 6e-17)."""
    c = np.cos(theta)
    return np.where(np.abs(c) <= SINGULAR, 0.0, c)


def vertical_r_prime(theta, a, r, outside=False):
    """Radius r' of the circle of the wheel's centre, eq. (8b) with alpha = 0 / pi.

    .. math:: r' = r\\sin\\theta - a \\ \\text{(inside)}, \\qquad r' = r\\sin\\theta + a \\ \\text{(outside, sec. 3)}

    [m].  Inside, r' <= 0 means the wheel does not fit on the circle.
    """
    theta, a, r = _arrays(theta, a, r)
    return r_prime(theta, np.where(outside, np.pi, 0.0), a, r)


def vertical_fits(theta, a, r, outside=False):
    """True where the wheel fits on the vertical circle.

    Inside (sec. 2.2.1, last paragraph): r sin(theta) > a, i.e. r' > 0.
    Outside: eq. (81) with alpha = pi, i.e. 0 < theta < pi (sin(theta) > 0;
    at theta = 0 or pi the wheel would lie flat in the tangent plane).
    Values within SINGULAR of the boundary count as not fitting.
    """
    theta, a, r = _arrays(theta, a, r)
    s = np.sin(theta)
    return np.where(outside, s > SINGULAR, r_prime(theta, 0.0, a, r) > SINGULAR * r)


def top_rate_from_speed(v_top, theta, a, r, outside=False):
    """Top rate phidot_top = v_top / r' [rad/s] from the top speed of the centre
    v_top [m/s] (eq. 8: v_cm = r' phidot).  NaN where the wheel does not fit."""
    v_top, theta, a, r = _arrays(v_top, theta, a, r)
    rp = vertical_r_prime(theta, a, r, outside)
    ok = vertical_fits(theta, a, r, outside)
    return np.where(ok, v_top / np.where(ok, rp, 1.0), np.nan)


def top_speed_from_rate(phidot_top, theta, a, r, outside=False):
    """Top speed of the centre v_top = r' phidot_top [m/s] (eq. 8).  NaN where
    the wheel does not fit."""
    phidot_top, theta, a, r = _arrays(phidot_top, theta, a, r)
    rp = vertical_r_prime(theta, a, r, outside)
    return np.where(vertical_fits(theta, a, r, outside), rp * phidot_top, np.nan)


def min_top_rate(theta, a, r, g, outside=False):
    """Least top rate that keeps the wheel on the wall, eq. (28a): phidot_top^2 > g/r'.

    Returns sqrt(g / r') [rad/s] inside (the bound itself is excluded).  NaN
    outside the sphere, where no top rate keeps contact all the way round
    (sec. 3), and where the wheel does not fit.
    """
    theta, a, r, g = _arrays(theta, a, r, g)
    rp = vertical_r_prime(theta, a, r, False)
    ok = vertical_fits(theta, a, r, False) & ~np.asarray(outside, dtype=bool)
    return np.where(ok, np.sqrt(g / np.where(ok, rp, 1.0)), np.nan)


def min_top_speed(theta, a, r, g, outside=False):
    """Least top speed of the centre, v_top = sqrt(g r') [m/s] (eq. 28a times r').
    NaN outside and where the wheel does not fit."""
    theta, a, r, g = _arrays(theta, a, r, g)
    rp = vertical_r_prime(theta, a, r, False)
    ok = vertical_fits(theta, a, r, False) & ~np.asarray(outside, dtype=bool)
    return np.where(ok, np.sqrt(g * np.where(ok, rp, 1.0)), np.nan)


def _coefficients(theta, phidot_top, a, r, k, g, outside):
    """r', V = r' phidot_top^2, D = V + 2g/(2k+1), B = (2k+3) g/(2k+1), c = 2k/(2k+1).

    With these, eqs. (27)-(28) read  r' phidot^2 - g cos(phi) = D - B cos(phi)
    (the inward push inside, minus the outward push outside)."""
    rp = vertical_r_prime(theta, a, r, outside)
    fits = vertical_fits(theta, a, r, outside)
    rp_safe = np.where(fits, rp, 1.0)
    v = rp_safe * phidot_top ** 2
    d = v + 2 * g / (2 * k + 1)
    b = (2 * k + 3) * g / (2 * k + 1)
    c = 2 * k / (2 * k + 1)
    return rp, rp_safe, fits, v, d, b, c


def rate_squared(phi, theta, phidot_top, a, r, k, g, outside=False):
    """phidot^2 at azimuth phi from energy conservation, eq. (27).

    .. math:: \\dot\\phi^2 = \\dot\\phi_0^2 + \\frac{2 g (1 - \\cos\\phi)}{(2k+1) r'}

    Same inside and outside (sec. 3: eq. 26 holds with r' = r sin(theta) + a).
    Written with 1 - cos(phi) = 2 sin^2(phi/2).  NaN where the wheel does
    not fit.  Note that this is the rolling solution: outside it is physical
    only up to the release angle.
    """
    phi, theta, phidot_top, a, r, k, g = _arrays(phi, theta, phidot_top, a, r, k, g)
    rp, rp_safe, fits, *_ = _coefficients(theta, phidot_top, a, r, k, g, outside)
    out = phidot_top ** 2 + 4 * g * np.sin(phi / 2) ** 2 / ((2 * k + 1) * rp_safe)
    return np.where(fits, out, np.nan)


def contact_force(phi, theta, phidot_top, a, r, k, g, outside=False):
    """Contact force per unit mass on a vertical orbit, eq. (28) corrected.

    .. math:: \\mathbf F/m = -\\frac{2k}{2k+1} g\\sin\\phi\\,\\hat{\\mathbf 2}
                           + (g\\cos\\phi - r'\\dot\\phi^2)\\,\\hat{\\mathbf r}'

    with phidot^2 from eq. (27).  The paper prints ``+2k/(2k+1) m g sin(phi)``
    for the 2-component: the sign is wrong (torque balance a F_2 = -I11
    d(omega_1)/dt, and friction must oppose the speed-up on the way down;
    see docs/errata.md and tests/physics/test_vertical.py).  Inside,
    r-hat' = axis 3 (alpha = 0); outside r-hat' = -axis 3 (alpha = pi).

    Returns a dict of arrays (per unit mass, m/s^2):

    ``along``       F . 2-hat, along the velocity (friction; eq. 28)
    ``radial``      F . r-hat' (eq. 28: F_3 inside)
    ``normal``      F_perp, pressing wheel and sphere together (eq. 28d:
                    -F_3 sin(theta) inside, +F . r-hat' sin(theta) outside);
                    positive means contact
    ``meridional``  friction along theta-hat, F . r-hat' cos(theta)
    ``friction``    |F_parallel| = hypot(along, meridional), eq. (28c) with
                    cos^2(theta) (the paper's ``cos theta^2``)
    ``mu_required`` eq. (28b): friction / normal, NaN where normal <= 0
    """
    phi, theta, phidot_top, a, r, k, g = _arrays(phi, theta, phidot_top, a, r, k, g)
    rp, rp_safe, fits, v, d, b, c = _coefficients(theta, phidot_top, a, r, k, g, outside)
    along = -c * g * np.sin(phi)
    # g cos(phi) - r' phidot^2 = -(D - B cos(phi)), by eq. (27)
    radial = -(d - b * np.cos(phi))
    normal = np.where(outside, radial, -radial) * np.sin(theta)
    meridional = radial * _cos(theta)
    friction = np.hypot(along, meridional)
    mu = mu_required(np.where(fits, normal, np.nan), friction)
    nan = ~fits
    return {
        "along": np.where(nan, np.nan, along),
        "radial": np.where(nan, np.nan, radial),
        "normal": np.where(nan, np.nan, normal),
        "meridional": np.where(nan, np.nan, meridional),
        "friction": np.where(nan, np.nan, friction),
        "mu_required": mu,
    }


def release_angle(theta, phidot_top, a, r, k, g):
    """Where a wheel rolling down the OUTSIDE of the sphere from the top leaves it.

    Generalises eq. (82) to a top rate phidot_top (beyond the paper; derivation
    in docs/derivations-configurations.md):

    .. math:: \\cos\\phi_{\\rm leave} = \\frac{2 + (2k+1)\\, r'\\dot\\phi_0^2/g}{3 + 2k},
              \\qquad r' = r\\sin\\theta + a,

    which is eq. (82), cos(phi) = 2/(3+2k), for phidot_top = 0.  Returns
    phi_leave [rad] in [0, pi/2); 0 when r' phidot_top^2 >= g (the wheel leaves
    at once).  Assumes enough friction to roll until then (see
    :func:`slip_angle`).  NaN where the wheel does not fit.
    """
    theta, phidot_top, a, r, k, g = _arrays(theta, phidot_top, a, r, k, g)
    rp, rp_safe, fits, v, d, b, c = _coefficients(theta, phidot_top, a, r, k, g, True)
    cos_leave = np.minimum(d / b, 1.0)
    return np.where(fits, np.arccos(cos_leave), np.nan)


def slip_angle(theta, phidot_top, a, r, k, g, mu, outside=False):
    """First phi >= 0 (going round from the top) where rolling needs more
    friction than ``mu`` (beyond the paper; derivation in
    docs/derivations-configurations.md).

    With q = sqrt(mu^2 sin^2(theta) - cos^2(theta)) the wheel slips where
    |F_along| > q F_perp / sin(theta), i.e. (in the notation of
    :func:`worst_point`)

    inside:   c g sin(phi) + q B cos(phi) > q D,  first at  phi = delta - acos(qD/R)
    outside:  q B cos(phi) - c g sin(phi) < q D,  first at  phi = acos(qD/R) - delta

    with R = hypot(c g, q B), delta = atan2(c g, q B).  Returns phi [rad];
    0 if mu < |cot(theta)| (eq. 28b: it slips at the top already); NaN if it
    never slips (inside) or does not slip before it leaves (outside), and
    where the wheel has no contact at the top or does not fit.
    """
    theta, phidot_top, a, r, k, g, mu = _arrays(theta, phidot_top, a, r, k, g, mu)
    outside = np.asarray(outside, dtype=bool)
    rp, rp_safe, fits, v, d, b, c = _coefficients(theta, phidot_top, a, r, k, g, outside)
    contact_top = np.where(outside, b > d, d > b) & fits
    finite = np.isfinite(mu)
    mu_s = np.where(finite, mu, 0.0)
    q2 = (mu_s * np.sin(theta)) ** 2 - _cos(theta) ** 2
    q = np.sqrt(np.maximum(q2, 0.0))
    cg = c * g
    big_r = np.hypot(cg, q * b)
    has_r = big_r > 0
    big_r_s = np.where(has_r, big_r, 1.0)
    delta = np.arctan2(cg, q * b)
    ratio = q * d / big_r_s
    # inside: R cos(phi - delta) > qD first happens at delta - acos(qD/R) when qD < R
    inside_phi = np.where(ratio < 1, delta - np.arccos(np.minimum(ratio, 1.0)), np.nan)
    # outside: R cos(phi + delta) < qD first at acos(qD/R) - delta (qD/R < qB/R <= 1 there)
    outside_phi = np.arccos(np.clip(ratio, -1.0, 1.0)) - delta
    leave = np.arccos(np.minimum(d / b, 1.0))
    outside_phi = np.where(outside_phi < leave, outside_phi, np.nan)
    phi = np.where(outside, outside_phi, inside_phi)
    phi = np.where(cg > 0, phi, np.nan)         # k = 0: mu_required = |cot(theta)| throughout
    phi = np.where(q2 < 0, 0.0, phi)            # mu below |cot(theta)|: slips at the top
    phi = np.where(phi < 0, 0.0, phi)           # round-off at the top
    return np.where(finite & contact_top, phi, np.nan)


def worst_point(theta, phidot_top, a, r, k, g):
    """Where the friction needed on an INSIDE vertical orbit peaks, and its value.

    Beyond the paper (derivation in docs/derivations-configurations.md): by
    eqs. (27), (28), (28b), mu(phi)^2 sin^2(theta) = cos^2(theta) +
    (c g sin(phi) / (D - B cos(phi)))^2 with c = 2k/(2k+1),
    D = r' phidot_top^2 + 2g/(2k+1), B = (2k+3) g/(2k+1), whose maximum is at

    .. math:: \\cos\\phi^* = B/D, \\qquad
              \\mu_{\\max} = \\frac{\\sqrt{\\cos^2\\theta + c^2 g^2/(D^2 - B^2)}}{\\sin\\theta}

    (and at -phi*).  phi* lies in the upper half of the orbit and tends to the
    top as phidot_top falls to the contact limit (28a), where mu_max diverges.
    For k = 0 mu is constant (= |cot(theta)|) and phi* is just one of the
    maxima.  The least mu round the orbit is |cot(theta)| (eq. 28b), at top
    and bottom.  Returns ``(phi_worst, mu_max)`` [rad, -]; NaN where the wheel
    does not fit or loses contact (r' phidot_top^2 <= g).
    """
    theta, phidot_top, a, r, k, g = _arrays(theta, phidot_top, a, r, k, g)
    rp, rp_safe, fits, v, d, b, c = _coefficients(theta, phidot_top, a, r, k, g, False)
    ok = fits & (d > b)
    d_s = np.where(ok, d, 2.0 * b)
    phi_w = np.arccos(b / d_s)
    sin_s = np.where(ok, np.sin(theta), 1.0)
    mu_max = np.sqrt(_cos(theta) ** 2 + (c * g) ** 2 / ((d_s - b) * (d_s + b))) / sin_s
    return np.where(ok, phi_w, np.nan), np.where(ok, mu_max, np.nan)


def lap_time(theta, phidot_top, a, r, k, g):
    """Time for one lap of a vertical orbit, with a complete elliptic integral.

    Beyond the paper (derivation in docs/derivations-configurations.md): from
    eq. (27), phidot^2 = phidot_top^2 + kappa sin^2(phi/2), kappa = 4g/((2k+1) r'),

    .. math:: T = \\int_0^{2\\pi}\\frac{d\\phi}{\\dot\\phi}
                = \\frac{4 K(m)}{\\dot\\phi_{\\rm bottom}}, \\qquad
              \\dot\\phi_{\\rm bottom}^2 = \\dot\\phi_{\\rm top}^2 + \\kappa, \\quad
              m = \\kappa / \\dot\\phi_{\\rm bottom}^2,

    K the complete elliptic integral of the first kind with parameter m
    (by the arithmetic-geometric mean, :func:`_ellipk`).  The period of the
    rolling solution of eq. (27) for the wheel inside, whether or not the
    wall holds it there (eq. 28a): :func:`vertical_orbit` reports it only
    where it does, the Floquet analysis
    (:func:`deathsphere.physics.stability.floquet.vertical_floquet`) of
    every rolling orbit.  Returns T [s]; NaN where the wheel does not fit or
    phidot_top = 0.
    """
    theta, phidot_top, a, r, k, g = _arrays(theta, phidot_top, a, r, k, g)
    rp, rp_safe, fits, v, d, b, c = _coefficients(theta, phidot_top, a, r, k, g, False)
    ok = fits & (phidot_top != 0)
    kappa = 4 * g / ((2 * k + 1) * rp_safe)
    bottom2 = np.where(ok, phidot_top ** 2 + kappa, 2.0 * kappa)
    m = np.where(ok, kappa / bottom2, 0.5)
    return np.where(ok, 4 * _ellipk(m) / np.sqrt(bottom2), np.nan)


def phi_grid(n, endpoint=True):
    """n azimuths [rad] from the top (0) round to 2 pi (included when
    endpoint): the points of :func:`vertical_profile`, the point-by-point
    view of eqs. (27)-(28b)."""
    return np.linspace(0.0, 2 * np.pi, int(n), endpoint=endpoint)


def vertical_orbit(theta, phidot_top, a, r, k, g, outside=False, mu=np.inf):
    """Everything about one vertical orbit of a wheel per request, vectorised.

    McDonald (1993) sec. 2.2.1 eqs. (26)-(28b) inside, sec. 3 eq. (82) outside.

    Parameters
    ----------
    theta : array_like, [rad]   cone angle of the contact circle about the
                                horizontal z' axis (90 deg: great circle)
    phidot_top : array_like, [rad/s]  rate at the top; only its size matters
                                (the orbit's sense is a mirror image).  Use
                                :func:`top_rate_from_speed` for a top speed.
    a, r : [m];  k : [-] (I11 = 2 k m a^2);  g : [m/s^2]
    outside : bool array        wheel on the outside of the sphere
    mu : [-]                    friction coefficient available (inf: unlimited)

    Returns
    -------
    dict of arrays broadcast to one shape:

    ``r_prime``      radius of the centre's circle, r sin(theta) -+ a [m]
    ``omega``        top rate |phidot_top| [rad/s]
    ``omega_bottom`` rate at the bottom (inside; eq. 27) [rad/s]
    ``omega_min``    least top rate for contact, sqrt(g/r') (eq. 28a; NaN outside)
    ``period``       lap time (elliptic integral) [s]
    ``v_cm``         top speed r' |phidot_top| [m/s];  ``v_bottom`` [m/s]
    ``v_min``        least top speed for contact, sqrt(g r') [m/s]
    ``spin``         wheel spin at the top, omega_1 = r' phidot_top / a (eq. 13) [rad/s]
    ``accel``        largest centre acceleration of the lap, r' phidot_bottom^2
                     (at the bottom) [m/s^2];  ``accel_g`` the same in g
    ``normal``, ``friction``, ``mu_required``
                     normal force, friction magnitude (per unit mass, m/s^2)
                     and mu at the worst point, where mu peaks
    ``phi_worst``    that point [rad] (also at -phi_worst)
    ``mu_top``       mu at the top and bottom, |cot(theta)|: the least mu of
                     the lap (eq. 28b)
    ``normal_top``, ``normal_bottom``  normal force per unit mass at top and
                     bottom (negative at the top: the wheel falls off)
    ``phi_leave``    outside: where the wheel leaves the surface (eq. 82
                     generalised); NaN inside
    ``phi_slip``     where rolling first needs more than ``mu`` (NaN if never /
                     not before it leaves)
    ``contact``      bool: the wheel keeps contact all the way round (eq. 28a;
                     always False outside)
    ``status``, ``reason``  int8 codes: no_fit (NO_FIT_VERTICAL inside, r
                     sin(theta) <= a; NO_FIT_OUTSIDE at theta = 0, 180 deg),
                     no_contact (VERTICAL_TOP_TOO_SLOW inside, eq. 28a;
                     VERTICAL_OUTSIDE_LEAVES always outside: no vertical orbit
                     closes outside, sec. 3), slips (mu_required > mu).

    Lap quantities (period, accel, omega_bottom, v_bottom, worst point) are NaN
    unless the wheel keeps contact all the way round (status ok or slips).
    """
    theta, phidot_top, a, r, k, g, mu = _arrays(theta, phidot_top, a, r, k, g, mu)
    outside = np.asarray(outside, dtype=bool)
    theta, phidot_top, a, r, k, g, mu, outside = np.broadcast_arrays(theta, phidot_top, a, r, k, g, mu, outside)
    phidot_top = np.abs(phidot_top)
    rp, rp_safe, fits, v, d, b, c = _coefficients(theta, phidot_top, a, r, k, g, outside)
    contact = fits & ~outside & (d > b)

    top = contact_force(0.0, theta, phidot_top, a, r, k, g, outside)
    bottom = contact_force(np.pi, theta, phidot_top, a, r, k, g, outside)
    phi_w, mu_max = worst_point(theta, phidot_top, a, r, k, g)
    phi_w = np.where(contact, phi_w, np.nan)
    mu_max = np.where(contact, mu_max, np.nan)
    worst = contact_force(phi_w, theta, phidot_top, a, r, k, g, outside)
    period = np.where(contact, lap_time(theta, phidot_top, a, r, k, g), np.nan)
    bottom2 = np.where(contact, rate_squared(np.pi, theta, phidot_top, a, r, k, g, outside), np.nan)
    omega_bottom = np.sqrt(np.where(contact, bottom2, 0.0))
    omega_bottom = np.where(contact, omega_bottom, np.nan)
    accel = rp_safe * bottom2

    status, reason = first_failure([
        (~fits, Status.NO_FIT, np.where(outside, Reason.NO_FIT_OUTSIDE, Reason.NO_FIT_VERTICAL)),
        (outside, Status.NO_CONTACT, Reason.VERTICAL_OUTSIDE_LEAVES),
        (~contact, Status.NO_CONTACT, Reason.VERTICAL_TOP_TOO_SLOW),
        (mu_max > mu, Status.SLIPS, Reason.SLIPS),
    ])
    sin_s = np.where(fits, np.sin(theta), 1.0)
    mu_top = np.where(fits, np.abs(_cos(theta)) / sin_s, np.nan)
    leave = np.where(outside, release_angle(theta, phidot_top, a, r, k, g), np.nan)
    return {
        "r_prime": rp,
        "omega": phidot_top,
        "omega_bottom": omega_bottom,
        "omega_min": min_top_rate(theta, a, r, g, outside),
        "period": period,
        "v_cm": np.where(fits, rp_safe * phidot_top, np.nan),
        "v_bottom": rp_safe * omega_bottom,
        "v_min": min_top_speed(theta, a, r, g, outside),
        "spin": np.where(fits, rp_safe * phidot_top / a, np.nan),
        "accel": accel,
        "accel_g": accel / g,
        "normal": worst["normal"],
        "friction": worst["friction"],
        "mu_required": mu_max,
        "phi_worst": phi_w,
        "mu_top": mu_top,
        "normal_top": top["normal"],
        "normal_bottom": np.where(outside, np.nan, bottom["normal"]),
        "phi_leave": leave,
        "phi_slip": slip_angle(theta, phidot_top, a, r, k, g, mu, outside),
        "contact": contact,
        "status": status,
        "reason": reason,
    }


def vertical_profile(phi, theta, phidot_top, a, r, k, g, outside=False, mu=np.inf):
    """Point-by-point view of a vertical orbit: every input broadcasts, so
    ``phi[:, None]`` against requests of shape (n,) gives an (N, n) table.

    McDonald (1993) eqs. (27) (speed), (28)/(28c)/(28d) (forces, with the
    sign of F_2 corrected) and (28b) (mu).  Returns a dict of arrays:

    ``phi`` [rad], ``omega`` rate phidot [rad/s], ``v_cm`` speed r' phidot
    [m/s], ``accel`` |centre acceleration| = hypot(r' phidot^2, r' phiddot)
    [m/s^2] (phiddot from eq. 26), ``along``, ``radial``, ``meridional``, ``friction``,
    ``normal`` (per unit mass, see :func:`contact_force`), ``mu_required``
    (NaN where normal <= 0), ``status``/``reason`` per point: no_fit,
    no_contact where the normal force is not positive (outside: from
    phi_leave on; the rolling values there are not physical), slips where
    mu_required > mu.
    """
    phi, theta, phidot_top, a, r, k, g, mu = _arrays(phi, theta, phidot_top, a, r, k, g, mu)
    outside = np.asarray(outside, dtype=bool)
    phi, theta, phidot_top, a, r, k, g, mu, outside = np.broadcast_arrays(
        phi, theta, phidot_top, a, r, k, g, mu, outside)
    rp, rp_safe, fits, *_ = _coefficients(theta, phidot_top, a, r, k, g, outside)
    w2 = rate_squared(phi, theta, phidot_top, a, r, k, g, outside)
    w = np.sqrt(np.where(fits, w2, 0.0))
    f = contact_force(phi, theta, phidot_top, a, r, k, g, outside)
    tangential = g * np.sin(phi) / (2 * k + 1)            # r' phiddot, eq. (26)
    accel = np.hypot(rp_safe * np.where(fits, w2, 0.0), tangential)
    status, reason = first_failure([
        (~fits, Status.NO_FIT, np.where(outside, Reason.NO_FIT_OUTSIDE, Reason.NO_FIT_VERTICAL)),
        (~(f["normal"] > 0), Status.NO_CONTACT,
         np.where(outside, Reason.VERTICAL_OUTSIDE_LEAVES, Reason.VERTICAL_TOP_TOO_SLOW)),
        (f["mu_required"] > mu, Status.SLIPS, Reason.SLIPS),
    ])
    nan = ~fits
    return {
        "phi": phi,
        "omega": np.where(nan, np.nan, w),
        "v_cm": np.where(nan, np.nan, rp_safe * w),
        "accel": np.where(nan, np.nan, accel),
        "along": f["along"],
        "radial": f["radial"],
        "meridional": f["meridional"],
        "friction": f["friction"],
        "normal": f["normal"],
        "mu_required": f["mu_required"],
        "status": status,
        "reason": reason,
    }
