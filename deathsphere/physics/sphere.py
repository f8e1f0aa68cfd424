"""Horizontal orbits of a sphere rolling inside or outside a fixed sphere.

McDonald (1993) sec. 4 (inside, eqs. 41-58) and sec. 5 (outside, eq. 59).

Symbols.  theta is the polar angle of the contact point from the upward
vertical through the fixed sphere's centre (as for the wheel); ``rho`` is the
distance between the two centres, the paper's sec.-4 r' (eq. 42):

    rho = r - a   inside,      rho = r + a   outside (sec. 5).

The ball's centre runs round a horizontal circle of radius rho sin(theta):
this is the output ``r_prime`` (distance of the centre from the vertical
axis, as for the wheel), NOT the paper's sec.-4 r'.  k is the inertia
factor, I = k m a^2 (2/5 for a solid ball, 2/3 for a thin shell).

Sign conventions (eq. 55).  ``Omega`` is the signed orbital rate about the
upward vertical (positive: anticlockwise seen from above).  ``omega3`` is the
component of the ball's angular velocity along axis 3, the unit vector from
the ball's centre to the contact point (inside: the outward normal of the
fixed sphere; outside: the inward normal), right-handed.  With these signs
eq. (55),

    (k+1) rho Omega^2 cos(theta) + k a omega3 Omega + g = 0,

holds inside and outside (checked in tests/physics/test_sphere.py from
Newton's and Euler's equations in vector form).  Flipping both signs gives
the mirror-image orbit.

Branches.  For given omega3, eq. (55) has up to two roots.  Branch 0 is the
slow root (smaller |Omega|), branch 1 the fast root (larger |Omega|).  On the
equator (cos(theta) = 0) eq. (55) is linear and only branch 0 exists,
Omega = -g/(k a omega3); it continues the slow root smoothly across the
equator, while the fast root runs off to infinity there.  Ties (a double root
at the minimum |omega3| of eq. 56, or omega3 = 0 below the equator, where the
roots are +-Omega, mirror images) go to branch 0 for the root the slow root
has in the limit omega3 -> 0-: at omega3 = 0 branch 0 is Omega > 0.

Units: rad, m, s; all functions broadcast and never raise for an impossible
orbit (status codes of :mod:`deathsphere.physics.status`).
"""

import numpy as np

from deathsphere.constants import DEFAULT_INERTIA, STANDARD_GRAVITY
from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.status import Reason, Status, first_failure, mu_required

#: inertia factor of a uniform solid ball, I = k m a^2 (sec. 4), 2/5
K_SOLID_BALL = DEFAULT_INERTIA["sphere"]

__all__ = [
    "K_SOLID_BALL", "STANDARD_GRAVITY", "centre_distance", "equivalent_alpha",
    "orbit_rates", "omega3_from_rate", "omega3_min_real", "omega3_min_contact",
    "contact_spin_window", "contact_force", "sphere_orbit", "sphere_orbit_from_rate",
]


def _arrays(*xs):
    return [np.asarray(x, dtype=float) for x in xs]


def centre_distance(a, r, outside=False):
    """Distance rho between the centres, the paper's sec.-4 r' [m]:
    eq. (42) rho = r - a inside; sec. 5 rho = r + a outside."""
    a, r = _arrays(a, r)
    return np.where(outside, r + a, r - a)


def equivalent_alpha(theta, outside=False):
    """Bank angle of the ball's axis 3 below the orbit plane, in the wheel's
    convention (eq. 11): alpha = theta - pi/2 inside (sec. 4), and
    alpha = theta + pi/2 outside (axis 3 then points into the fixed sphere;
    this alpha satisfies eq. 81).  [rad]"""
    theta = np.asarray(theta, dtype=float)
    return np.where(outside, theta + np.pi / 2, theta - np.pi / 2)


def _quadratic(theta, a, r, k, g, outside):
    """Coefficients of eq. (55): A Omega^2 + B' omega3 Omega + g = 0,
    A = (k+1) rho cos(theta), B' = k a.  cos(theta) is snapped to 0 within
    SINGULAR (degrees land on 90 only up to round-off)."""
    rho = centre_distance(a, r, outside)
    cos_t = np.cos(theta)
    cos_t = np.where(np.abs(cos_t) <= SINGULAR, 0.0, cos_t)
    return rho, cos_t, (k + 1) * rho * cos_t, k * a


def _spin_term(b, rho, k, g):
    """k a omega3, snapped to 0 when below SINGULAR of the natural scale
    sqrt((k+1) g rho) (on the equator it would give an absurd |Omega| = g/|b|)."""
    scale = np.sqrt(np.abs((k + 1) * g * rho))
    return np.where(np.abs(b) <= SINGULAR * scale, 0.0, b)


def orbit_rates(theta, omega3, a, r, k=K_SOLID_BALL, g=STANDARD_GRAVITY, outside=False):
    """Both roots of eq. (55) for Omega given omega3.

    .. math:: (k+1) r' \\Omega^2 \\cos\\theta + k a \\omega_3 \\Omega + g = 0

    (r' = rho = r - a inside, eq. 42; r + a outside, sec. 5).  Returns
    ``(Omega_0, Omega_1)`` [rad/s], the slow and the fast root (module
    docstring), computed without cancellation: q = -(B + s sqrt(disc))/2 with
    B = k a omega3, s = +1 if B > 0 else -1; slow = g/q, fast = q/A.  NaN
    where the root is not real (eq. 56 fails), where it does not exist
    (branch 1 on the equator; both when B = 0 there) or where q = 0.
    |k a omega3| below 1e-12 sqrt((k+1) g r') counts as 0.
    """
    theta, omega3, a, r, k, g = _arrays(theta, omega3, a, r, k, g)
    rho, cos_t, big_a, ka = _quadratic(theta, a, r, k, g, outside)
    b = _spin_term(ka * omega3, rho, k, g)
    disc = b * b - 4 * big_a * g
    real = disc >= 0
    sgn = np.where(b > 0, 1.0, -1.0)
    q = -(b + sgn * np.sqrt(np.where(real, disc, 0.0))) / 2
    q_ok = real & (q != 0)
    q_s = np.where(q_ok, q, 1.0)
    slow = np.where(q_ok, g / q_s, np.nan)
    a_ok = q_ok & (big_a != 0)
    fast = np.where(a_ok, q_s / np.where(a_ok, big_a, 1.0), np.nan)
    return slow, fast


def omega3_from_rate(theta, omega, a, r, k=K_SOLID_BALL, g=STANDARD_GRAVITY, outside=False):
    """omega3 [rad/s] from the orbital rate Omega, eq. (55) solved for omega3:

    .. math:: \\omega_3 = -\\frac{(k+1) r' \\Omega^2\\cos\\theta + g}{k a \\Omega}

    (r' = r - a inside, eq. 42; r + a outside, sec. 5).  NaN where Omega = 0
    or k a = 0 (omega3 then drops out of eq. 55).  The one definition of this
    formula (the steady states of :mod:`deathsphere.physics.dynamics` use it
    too).  cos(theta) is snapped to 0 within SINGULAR, as in
    :func:`orbit_rates`: 90 deg reaches radians as pi/2 rounded, whose cosine
    is 6.1e-17, not the 0 the user meant (docs/derivations.md, "The sphere's
    spin on the equator").  Complex theta and omega are accepted (the complex
    step of the stability closed forms): only the real part of the cosine is
    snapped, so its imaginary part, the derivative, is kept.
    """
    theta, omega, a, r, k, g = (np.asarray(x) for x in (theta, omega, a, r, k, g))
    rho = centre_distance(a, r, outside)
    cos_t = np.cos(theta)
    cos_t = np.where(np.abs(np.real(cos_t)) <= SINGULAR, cos_t - np.real(cos_t), cos_t)
    den = k * a * omega
    ok = den != 0
    return np.where(ok, -((k + 1) * rho * omega ** 2 * cos_t + g) / np.where(ok, den, 1.0), np.nan)


def omega3_min_real(theta, a, r, k=K_SOLID_BALL, g=STANDARD_GRAVITY, outside=False):
    """Least |omega3| with a real orbit, eq. (56): (k a omega3)^2 >= 4 (k+1) g r' cos(theta).

    .. math:: |\\omega_3|_{\\min} = \\frac{2\\sqrt{(k+1) g r'\\cos\\theta}}{k a} \\quad (\\theta < \\pi/2)

    0 at and below the equator (on the equator omega3 = 0 itself is
    excluded: eq. 55 then reads g = 0).  inf where k a = 0 above the
    equator.  [rad/s]
    """
    theta, a, r, k, g = _arrays(theta, a, r, k, g)
    rho, cos_t, big_a, ka = _quadratic(theta, a, r, k, g, outside)
    above = big_a > 0
    ka_ok = ka > 0
    val = 2 * np.sqrt(np.where(above, big_a * g, 0.0)) / np.where(ka_ok, ka, 1.0)
    return np.where(above, np.where(ka_ok, val, np.inf), 0.0)


def _critical(theta, a, r, k, g, outside):
    """Omega_c^2 = g |cos(theta)| / (rho sin^2 theta), where the normal force
    of eq. (58)/(59) vanishes, Omega_d^2 = g / A (double root), and the
    |omega3| at which a root of eq. (55) equals Omega_c:
    w_c = (A Omega_c^2 + g) / (k a Omega_c)."""
    rho, cos_t, big_a, ka = _quadratic(theta, a, r, k, g, outside)
    sin_t = np.sin(theta)
    pole = np.abs(sin_t) <= SINGULAR
    sin_s = np.where(pole, 1.0, sin_t)
    rho_s = np.where(rho > 0, rho, 1.0)
    oc2 = g * np.abs(cos_t) / (rho_s * sin_s ** 2)
    oc = np.sqrt(oc2)
    ok = (oc > 0) & (ka > 0)
    w_c = np.where(ok, (big_a * oc2 + g) / np.where(ok, ka * oc, 1.0), np.inf)
    return pole, cos_t, big_a, ka, oc2, w_c


def contact_spin_window(theta, a, r, k=K_SOLID_BALL, g=STANDARD_GRAVITY, outside=False):
    """The |omega3| ranges in which each branch keeps contact (beyond the
    paper's text, from eqs. 55, 56, 58, 59; derivation in
    docs/derivations-configurations.md).

    Returns a dict of arrays [rad/s]: ``min_real`` (eq. 56), ``lo0``,
    ``hi0``, ``lo1``, ``hi1``: branch b keeps contact for lo_b < |omega3| <
    hi_b (lo_b = min_real means "from the least real spin on", the bound
    itself included; NaN, NaN: never).  With Omega_c the rate at which the
    normal force vanishes and w_c the spin at which a root equals Omega_c:

    - inside, above the equator: if tan^2(theta) > k+1 (Omega_c < double
      root) branch 1 always, branch 0 below w_c; else branch 1 above w_c,
      branch 0 never;
    - inside, on or below the equator: every real orbit (eq. 58);
    - outside, above the equator: if tan^2(theta) < k+1 branch 0 always,
      branch 1 below w_c; else branch 0 above w_c, branch 1 never (eq. 59);
    - outside, on or below the equator: never.
    """
    theta, a, r, k, g = _arrays(theta, a, r, k, g)
    outside = np.asarray(outside, dtype=bool)
    theta, a, r, k, g, outside = np.broadcast_arrays(theta, a, r, k, g, outside)
    w_min = omega3_min_real(theta, a, r, k, g, outside)
    pole, cos_t, big_a, ka, oc2, w_c = _critical(theta, a, r, k, g, outside)
    above = big_a > 0
    # Omega_c^2 vs the double root g/A  <=>  tan^2(theta) vs k+1
    steep = above & (oc2 * big_a < g)          # Omega_c < Omega_d: tan^2(theta) > k+1
    nan = np.full(theta.shape, np.nan)
    inf = np.full(theta.shape, np.inf)
    # inside
    lo0_in = np.where(above, np.where(steep, w_min, nan), 0.0)
    hi0_in = np.where(above, np.where(steep, w_c, nan), inf)
    lo1_in = np.where(above, np.where(steep, w_min, w_c), 0.0)
    hi1_in = np.where(above, inf, np.where(cos_t == 0, nan, inf))
    lo1_in = np.where(~above & (cos_t == 0), nan, lo1_in)
    # outside
    lo0_out = np.where(above, np.where(steep, w_c, w_min), nan)
    hi0_out = np.where(above, inf, nan)
    lo1_out = np.where(above & ~steep, w_min, nan)
    hi1_out = np.where(above & ~steep, w_c, nan)
    res = {
        "min_real": w_min,
        "lo0": np.where(outside, lo0_out, lo0_in),
        "hi0": np.where(outside, hi0_out, hi0_in),
        "lo1": np.where(outside, lo1_out, lo1_in),
        "hi1": np.where(outside, hi1_out, hi1_in),
    }
    bad = pole | (~outside & (a >= r))
    return {key: np.where(bad & (key != "min_real"), np.nan, val) for key, val in res.items()}


def omega3_min_contact(theta, a, r, k=K_SOLID_BALL, g=STANDARD_GRAVITY, outside=False):
    """Least |omega3| for an orbit that keeps contact, on either branch
    (eq. 56 with eq. 58 inside / eq. 59 outside).

    Inside above the equator it is the eq. (56) minimum when tan^2(theta) >=
    k+1 and otherwise the larger w_c = (A Omega_c^2 + g)/(k a Omega_c), with
    Omega_c^2 = g cos(theta)/(r' sin^2(theta)) where eq. (58) becomes an
    equality (the paper's remark after eq. 58).  Outside it is the eq. (56)
    minimum when tan^2(theta) <= k+1, else w_c (eq. 59).  0 on and below the
    equator inside; NaN outside on or below the equator (no orbit keeps
    contact, eq. 59), at the poles and where the ball does not fit; inf
    above the equator when k a = 0.  [rad/s]
    """
    win = contact_spin_window(theta, a, r, k, g, outside)
    return np.fmin(win["lo0"], win["lo1"])


def contact_force(theta, omega, a, r, g=STANDARD_GRAVITY, outside=False):
    """Contact force per unit mass on a horizontal orbit, eq. (57) corrected.

    .. math:: \\mathbf F/m = -(g + r'\\Omega^2\\cos\\theta)\\sin\\theta\\,\\hat{\\boldsymbol\\theta}
                            - (r'\\Omega^2\\sin^2\\theta - g\\cos\\theta)\\,\\hat{\\mathbf n}
              = -r'\\Omega^2\\sin\\theta\\,\\hat\\rho + g\\hat{\\mathbf z}

    (n-hat the outward normal of the fixed sphere, theta-hat down the
    meridian; inside n-hat = axis 3 and theta-hat = axis 1 of the paper).
    It follows from eqs. (2), (42) and (49), not "(2) and (54)" as printed;
    the paper's 1-component has the wrong sign (compare eq. 32 of the wheel).
    Returns ``(normal, friction)`` [m/s^2]: the component pressing ball and
    sphere together (inside r'Omega^2 sin^2(theta) - g cos(theta), eq. 58;
    outside its negative, eq. 59) and F . theta-hat (positive down the wall,
    as for the wheel).
    """
    theta, omega, a, r, g = _arrays(theta, omega, a, r, g)
    rho = centre_distance(a, r, outside)
    w2 = omega ** 2
    f_n = g * np.cos(theta) - rho * w2 * np.sin(theta) ** 2
    f_theta = -(g + rho * w2 * np.cos(theta)) * np.sin(theta)
    return np.where(outside, f_n, -f_n), f_theta


def _orbit(theta, omega, omega3, branch, a, r, k, g, outside, mu, extra_fail):
    """Common tail of :func:`sphere_orbit` and :func:`sphere_orbit_from_rate`."""
    rho = centre_distance(a, r, outside)
    fits = outside | (a < r)
    pole = np.abs(np.sin(theta)) <= SINGULAR
    defined = np.isfinite(omega) & fits & ~pole
    om = np.where(defined, omega, np.nan)
    normal, friction = contact_force(theta, om, a, r, g, outside)
    ok_n = normal > 0
    mu_req = mu_required(normal, friction)
    rp = rho * np.sin(theta)
    om_s = np.where(defined, om, 1.0)
    period = np.where(defined, 2 * np.pi / np.abs(om_s), np.nan)
    v = np.abs(rp) * np.abs(om)
    accel = np.abs(rp) * om ** 2
    status, reason = first_failure([
        (~fits, Status.NO_FIT, Reason.SPHERE_NO_FIT),
        (pole, Status.NO_ORBIT, Reason.POLE),
    ] + extra_fail + [
        (~ok_n, Status.NO_CONTACT,
         np.where(outside, Reason.SPHERE_NO_CONTACT_OUTSIDE, Reason.SPHERE_NO_CONTACT_INSIDE)),
        (mu_req > mu, Status.SLIPS, Reason.SLIPS),
    ])
    spin = v / a
    return {
        "r_prime": rp,
        "rho": rho,
        "alpha": equivalent_alpha(theta, outside),
        "omega": om,
        "omega2": om ** 2,
        "period": period,
        "v_cm": v,
        "spin": spin,
        "spin_total": np.hypot(spin, omega3),
        "omega3": omega3,
        "branch": branch,
        "accel": accel,
        "accel_g": accel / g,
        # what the rider feels, |a - g| / g (a horizontal, g vertical: eq. 32)
        "load_g": np.sqrt(accel * accel + g * g) / g,
        "normal": normal,
        "friction": friction,
        "mu_required": mu_req,
        "omega3_min_real": omega3_min_real(theta, a, r, k, g, outside),
        "omega3_min_contact": omega3_min_contact(theta, a, r, k, g, outside),
        "status": status,
        "reason": reason,
    }


def sphere_orbit(theta, omega3, a, r, k=K_SOLID_BALL, g=STANDARD_GRAVITY, outside=False,
                 mu=np.inf, branch=None):
    """Horizontal orbits of a rolling sphere for a given spin omega3, vectorised.

    McDonald (1993) eqs. (42) r', (55) Omega, (56) real roots, (57) contact
    force (corrected), (58)/(59) contact; mu = |F_theta| / F_perp.

    Parameters
    ----------
    theta : [rad]  polar angle of the contact point (< 90 deg: upper half)
    omega3 : [rad/s]  spin about axis 3 (ball centre -> contact point), signed
    a, r : [m]; k : [-] (I = k m a^2, default 2/5); g : [m/s^2]
    outside : bool   ball on the outside (sec. 5)
    mu : [-]  friction coefficient available (inf: unlimited)
    branch : None, or int array (0 slow, 1 fast) broadcast with the inputs.
        None: both branches, stacked on a new LAST axis (shape S + (2,)).

    Returns
    -------
    dict of arrays:
    ``r_prime`` distance of the ball's centre from the vertical axis,
    rho sin(theta) [m]; ``rho`` distance between the centres (the paper's
    sec.-4 r') [m]; ``alpha`` equivalent bank angle [rad]; ``omega`` signed
    Omega [rad/s]; ``omega2``; ``period`` 2 pi/|Omega| [s]; ``v_cm`` [m/s];
    ``spin`` rolling rate |omega x axis 3| = v_cm/a [rad/s]; ``spin_total``
    |omega| [rad/s]; ``omega3`` [rad/s]; ``branch`` (0 slow, 1 fast);
    ``accel``, ``accel_g`` centripetal acceleration of the centre;
    ``load_g`` |F| / (m g) = sqrt(1 + accel_g^2), what a rider feels;
    ``normal``, ``friction`` per unit mass (see :func:`contact_force`);
    ``mu_required``; ``omega3_min_real`` (eq. 56), ``omega3_min_contact``
    (eqs. 56, 58/59) [rad/s]; int8 ``status``, ``reason``: no_fit (a >= r
    inside), no_orbit (pole; omega3 = 0 on the equator; branch 1 on the
    equator; |omega3| below eq. 56), no_contact (eq. 58/59), slips.
    """
    theta, omega3, a, r, k, g, mu = _arrays(theta, omega3, a, r, k, g, mu)
    outside = np.asarray(outside, dtype=bool)
    if branch is None:
        args = [np.expand_dims(x, -1) for x in (theta, omega3, a, r, k, g, mu, outside)]
        theta, omega3, a, r, k, g, mu, outside = args
        branch = np.array([0, 1])
    branch = np.asarray(branch, dtype=np.int8)
    theta, omega3, a, r, k, g, mu, outside, branch = np.broadcast_arrays(
        theta, omega3, a, r, k, g, mu, outside, branch)
    slow, fast = orbit_rates(theta, omega3, a, r, k, g, outside)
    omega = np.where(branch == 0, slow, fast)
    rho, cos_t, big_a, ka = _quadratic(theta, a, r, k, g, outside)
    b = _spin_term(ka * omega3, rho, k, g)
    equator = cos_t == 0
    extra = [
        (equator & (b == 0), Status.NO_ORBIT, Reason.ZERO_RATE_EQUATOR),
        (equator & (branch == 1), Status.NO_ORBIT, Reason.EQUATOR_SINGLE_ROOT),
        (~np.isfinite(omega), Status.NO_ORBIT, Reason.SPIN_TOO_SMALL),
    ]
    return _orbit(theta, omega, omega3, branch, a, r, k, g, outside, mu, extra)


def sphere_orbit_from_rate(theta, omega, a, r, k=K_SOLID_BALL, g=STANDARD_GRAVITY, outside=False,
                           mu=np.inf):
    """Horizontal orbit of a rolling sphere for a given signed rate Omega.

    omega3 follows from eq. (55) (:func:`omega3_from_rate`); the rest as in
    :func:`sphere_orbit`, whose keys it returns.  ``branch`` tells which root
    of eq. (55) for that omega3 the orbit is: 0 (slow) where Omega^2 |A| < g
    with A = (k+1) r' cos(theta) (the other root is g/(A Omega)), 1 where
    Omega^2 |A| > g; ties (relative 1e-12) go to branch 0, except below the
    equator for Omega < 0 (omega3 = 0, mirror pair), which is branch 1.
    Status no_orbit where Omega = 0 (SPHERE_OMEGA_ZERO) or k a = 0
    (SPHERE_K_ZERO).
    """
    theta, omega, a, r, k, g, mu = _arrays(theta, omega, a, r, k, g, mu)
    outside = np.asarray(outside, dtype=bool)
    theta, omega, a, r, k, g, mu, outside = np.broadcast_arrays(theta, omega, a, r, k, g, mu, outside)
    rho, cos_t, big_a, ka = _quadratic(theta, a, r, k, g, outside)
    omega3 = omega3_from_rate(theta, omega, a, r, k, g, outside)
    x = omega ** 2 * np.abs(big_a)
    tie = np.abs(x - g) <= 1e-12 * g
    branch = np.where(tie, np.where((big_a < 0) & (omega < 0), 1, 0), np.where(x < g, 0, 1)).astype(np.int8)
    extra = [
        (omega == 0, Status.NO_ORBIT, Reason.SPHERE_OMEGA_ZERO),
        (ka == 0, Status.NO_ORBIT, Reason.SPHERE_K_ZERO),
    ]
    om = np.where((omega != 0) & (ka != 0), omega, np.nan)
    return _orbit(theta, om, omega3, branch, a, r, k, g, outside, mu, extra)
