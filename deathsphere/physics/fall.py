"""A rider who loses speed: where he leaves the wall and where he lands.

Beyond the paper.  The globe is centred at the origin, z up, radius r,
gravity -g z.  Every function is vectorised over a trailing batch axis n:
positions and velocities are (3, n), scalars (n,) or broadcastable; angles
in radians, lengths in metres, times in seconds.  Nothing loops over falls.

The model, in three stages:

1. **The drop.**  At the instant of the failure the centre of mass keeps its
   position and its velocity becomes ``speed_fraction`` times what it was,
   along the direction of travel.
2. **Contact.**  A looper (a vertical lane, a great circle of radius rho,
   the centre of mass G on the circle of radius r_G = rho - h, psi from the
   top) keeps his energy (docs/machine.md sec. 10, eq. M21) and his contact
   while the in-plane normal force m (r_G psidot^2 - g cos psi) is positive
   (the force behind eq. M22); where it reaches zero he leaves the wall.  If
   it never does he rides on over the top; if his speed reaches zero first
   he swings back and forth below the equator.  A rider on a horizontal
   lane whose lane is no longer feasible at the new speed leaves at once.
3. **Flight.**  From contact loss the centre of mass flies on a parabola
   until it meets the globe's surface (:func:`ballistic_landing`).

A fall, put together (n falls at once): a looper's state (psi, psidot)
just before the drop gives ``loop_departure(psi, f * psidot, r, r - h, M, m,
g)``; where it FALLS, ``loop_state(psi_lost, psi_dot_lost, r - h, azimuth)``
is the start of the flight and :func:`ballistic_landing` its end.  A
horizontal rider whose lane does not hold at the new speed
(:func:`horizontal_holds`, or the lane's lowest feasible speed where its
feasible speeds form one band) flies from his centre of mass with
``drop_velocity(v_com, f)``.

A check with pencil and paper (the tests run it): a point mass on a great
circle of radius rho = r leaves it at psi before the top where the normal
force vanishes, g cos psi = v^2/rho.  There the parabola osculates the
circle: with x0 = rho (-sin psi, cos psi) and v0 = v (cos psi, sin psi) in
the loop's plane the landing quartic's three lowest coefficients vanish
(|x0| = rho; x0 . v0 = 0; v^2 - g z0 = v^2 - g rho cos psi = 0), so
f(t) = t^3 (g^2 t/4 - g v sin psi) and the flight lasts t = 4 v sin(psi)/g.
Then, with v^2 = g rho cos psi, x = rho sin(psi) (4 cos^2 psi - 1) =
rho sin(3 psi) and z = rho cos(psi) (1 - 4 sin^2 psi) = rho cos(3 psi): he
lands 3 psi past the top, whatever psi.

Limits of the model (say them wherever its numbers are shown): the body is
a point at its centre of mass in flight -- it tumbles, and its extremities
(head, handlebar) reach the steel or another rider before or after the
centre of mass does; bike and rider may separate, and each then flies its
own parabola; after contact loss friction and the wall's touch are ignored
until the centre of mass reaches the surface; a machine that leaves the
wall while its wheels still spin carries their angular momentum, which
changes nothing on the parabola of the centre of mass.  On the loop the
friction is not checked after the drop: a machine (c > 0 in eq. M24) needs
friction c g |sin psi| / (A - B cos psi), which grows without bound as the
normal force goes to zero, so a real tyre slips shortly before the
departure point; the model keeps it rolling, energy conserved, until the
normal force is zero.  The other riders do not react.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.machine_lanes import closest_tilt, orbits_for_speed, orbits_for_speed_on
from deathsphere.physics.status import Status

__all__ = [
    "RIDES_ON", "SWINGS", "FALLS", "NO_LOOP", "OUTCOMES",
    "LANDS", "STARTS_OUTSIDE", "NOT_FLOWN",
    "ballistic_landing", "loop_departure", "loop_time", "loop_state",
    "loop_speed_profile", "drop_velocity", "horizontal_holds", "horizontal_holds_on",
]

#: Outcome codes of :func:`loop_departure` (int8), and their names;
#: NO_LOOP marks a row outside the model (not 0 < r_g <= rho, M_eff <= 0 or
#: g <= 0), whose other fields are NaN.
RIDES_ON, SWINGS, FALLS, NO_LOOP = 0, 1, 2, -1
OUTCOMES = ("rides_on", "swings", "falls")

#: Status codes of :func:`ballistic_landing` (int8): NOT_FLOWN marks a row
#: with a non-finite input, r <= 0 or g <= 0.
LANDS, STARTS_OUTSIDE, NOT_FLOWN = 0, 1, 2

#: A start within this fraction of r of the surface starts on it; a
#: coefficient of the landing quartic below this (relative to its terms) is a
#: zero root at t = 0, divided out.
ON_SURFACE = 1e-9
#: A parabola that comes this close (relative to the terms of the quartic)
#: to touching the globe from inside touches it.
GRAZE = 1e-10
_BISECTIONS = 64
_RF_STEPS = 12


# ---------------------------------------------------------------------------
# the flight
# ---------------------------------------------------------------------------

def _horner(c, t):
    """sum_i c[i] t^i for coefficient rows c (d+1, n), lowest first; also
    sum_i |c[i]| |t|^i, the size of its terms (the scale of its rounding)."""
    val = np.zeros_like(t)
    size = np.zeros_like(t)
    at = np.abs(t)
    for ci in c[::-1]:                       # a loop over the degree, not over falls
        val = val * t + ci
        size = size * at + np.abs(ci)
    return val, size


def _value(c, t):
    """sum_i c[i] t^i for coefficient rows c (d+1, n), lowest first."""
    val = np.zeros_like(t)
    for ci in c[::-1]:                       # a loop over the degree, not over falls
        val = val * t + ci
    return val


def _cubic_roots(a, b, c, d):
    """The real zeros of a t^3 + b t^2 + c t + d (a != 0) as (n, 3), NaN-padded:
    Viete's trigonometric form for three real zeros, Cardano's for one, then
    two Newton steps on the cubic itself."""
    a_s = np.where(a != 0, a, 1.0)
    b, c, d = b / a_s, c / a_s, d / a_s
    shift = b / 3.0
    p = c - b * b / 3.0
    q = 2.0 * b ** 3 / 27.0 - b * c / 3.0 + d
    disc = (q / 2.0) ** 2 + (p / 3.0) ** 3               # < 0: three real zeros
    three = disc < 0
    p_neg = np.where(three, p, -1.0)
    rad = 2.0 * np.sqrt(-p_neg / 3.0)
    arg = np.clip(3.0 * q / (p_neg * rad), -1.0, 1.0)
    ang = np.arccos(arg) / 3.0
    trig = np.stack([rad * np.cos(ang - 2 * np.pi * k / 3) for k in range(3)], axis=-1)
    sq = np.sqrt(np.maximum(disc, 0.0))
    one = np.cbrt(-q / 2.0 + sq) + np.cbrt(-q / 2.0 - sq)
    lone = np.stack([one, np.full_like(one, np.nan), np.full_like(one, np.nan)], -1)
    roots = np.where(three[:, None], trig, lone)
    roots = roots - shift[:, None]
    for _ in range(2):                                   # Newton polish, skipped at a double zero
        f = ((roots + b[:, None]) * roots + c[:, None]) * roots + d[:, None]
        df = (3.0 * roots + 2.0 * b[:, None]) * roots + c[:, None]
        good = np.abs(df) > 0
        roots = roots - np.where(good, f / np.where(good, df, 1.0), 0.0)
    return roots


def _critical_points(c, degree):
    """The real zeros of the derivative of the polynomial with coefficient
    rows c (5, n) (lowest first) and degree (n,) in 1..4, as (n, 3),
    NaN-padded (closed forms: a cubic, a quadratic, a line)."""
    n = c.shape[1]
    nan = np.full(n, np.nan)
    # degree 4: p' = 4 c4 t^3 + 3 c3 t^2 + 2 c2 t + c1
    quartic = _cubic_roots(4 * c[4], 3 * c[3], 2 * c[2], c[1])
    # degree 3: p' = 3 c3 t^2 + 2 c2 t + c1
    qa, qb, qc = 3 * c[3], 2 * c[2], c[1]
    qd = qb * qb - 4 * qa * qc
    qa_s = np.where(qa != 0, qa, 1.0)
    sq = np.sqrt(np.maximum(qd, 0.0))
    real = qd >= 0
    quad = np.stack([np.where(real, (-qb - sq) / (2 * qa_s), nan),
                     np.where(real, (-qb + sq) / (2 * qa_s), nan), nan], -1)
    # degree 2: p' = 2 c2 t + c1
    lin_a = np.where(c[2] != 0, c[2], 1.0)
    line = np.stack([-c[1] / (2 * lin_a), nan, nan], -1)
    deg = degree[:, None]
    return np.where(deg == 4, quartic, np.where(deg == 3, quad, np.where(deg == 2, line, np.nan)))


def ballistic_landing(x0, v0, ground, g):
    """Where and when a centre of mass flying freely from ``x0`` with
    velocity ``v0`` meets the globe's surface (beyond the paper).

    The first time t > 0 with |x0 + v0 t - g t^2/2 z| = r, a zero of the quartic::

        f(t) = g^2/4 t^4 - g v_z t^3 + (|v0|^2 - g z0) t^2 + 2 (x0 . v0) t + |x0|^2 - r^2.

    x0, v0 : (3, n) [m], [m/s]; ``ground`` the globe (a
    :class:`~deathsphere.physics.ground.Sphere`, its radius r [m]), g [m/s^2]
    (> 0); r and g broadcast to (n,).

    A start on the surface (within ``ON_SURFACE`` r) has the root t = 0
    divided out as often as it is one (a tangent start: twice; a point mass
    leaving a loop, where the parabola osculates the circle: three times), so
    a start on the surface moving inward is never reported as landing at
    t = 0; moving outward (into the steel) it lands at t = 0.  The zeros of
    the derivative of what is left (closed forms, Newton-polished) cut
    [0, T] into pieces on which it is monotone, T a time by which the centre
    of mass is below the globe's floor; the first piece whose right end is
    outside the globe (or within ``GRAZE`` of it) holds the landing, found by
    bisection to the last bit.  So every real root is seen, tangent ones too.

    Returns dict: ``t_land`` (n,) [s], ``x_land`` (3, n) [m], ``v_land``
    (3, n) [m/s], ``impact_speed`` (n,) [m/s] (|v_land|), ``impact_normal``
    (n,) [m/s] (the outward radial component of v_land), int8 ``status``
    (LANDS; STARTS_OUTSIDE where |x0| > r (1 + ON_SURFACE), NOT_FLOWN
    where an input is not finite or r or g not positive: then NaN).
    """
    x0 = np.asarray(x0, dtype=float)
    v0 = np.asarray(v0, dtype=float)
    x0, v0 = np.broadcast_arrays(x0.reshape(3, -1), v0.reshape(3, -1))
    n = x0.shape[1]
    if n == 0:
        empty = np.zeros(0)
        return {"t_land": empty, "x_land": x0.copy(), "v_land": v0.copy(), "impact_speed": empty,
                "impact_normal": empty, "status": np.zeros(0, dtype=np.int8)}
    r = np.broadcast_to(np.asarray(ground.radius, dtype=float), (n,))
    g = np.broadcast_to(np.asarray(g, dtype=float), (n,))
    bad = ~(np.isfinite(x0).all(axis=0) & np.isfinite(v0).all(axis=0) & (r > 0) & (g > 0) & np.isfinite(r * g))
    x0 = np.where(bad, 0.0, x0)
    v0 = np.where(bad, 0.0, v0)
    r = np.where(bad, 1.0, r)
    g = np.where(bad, 1.0, g)
    z0, vz = x0[2], v0[2]
    xx = np.einsum("in,in->n", x0, x0)
    xv = np.einsum("in,in->n", x0, v0)
    vv = np.einsum("in,in->n", v0, v0)
    a = np.stack([xx - r * r, 2 * xv, vv - g * z0, -g * vz, 0.25 * g * g])      # lowest first
    scale = np.stack([r * r, 2 * r * np.sqrt(vv), vv + g * np.abs(z0), g * np.sqrt(vv), 0.25 * g * g])
    outside = a[0] > 2 * ON_SURFACE * r * r
    # zero roots at t = 0: consecutive vanishing low coefficients
    zero = np.abs(a[:4]) <= ON_SURFACE * scale[:4]
    zero[0] &= ~outside
    k = np.where(zero[0], 1, 0)
    for j in (1, 2, 3):                      # a loop over the degree, not over falls
        k = np.where((k == j) & zero[j], j + 1, k)
    c = np.zeros_like(a)
    for j in range(5):
        idx = j + k
        c[j] = np.where(idx <= 4, a[np.minimum(idx, 4), np.arange(n)], 0.0)
    degree = 4 - k
    at_once = outside | (c[0] > 0) | (degree == 0)
    # a time by which the centre of mass is below the floor (z < -r): f(T) >= 0
    depth = np.maximum(z0 + r, 0.0)
    gs = np.where(g > 0, g, 1.0)
    t_max = (vz + np.sqrt(vz * vz + 2 * gs * depth)) / gs
    t_max = np.where(at_once | ~(t_max > 0), 1.0, t_max * (1 + 1e-12) + 1e-300)
    crit = _critical_points(c, np.where(at_once, 4, degree))
    crit = np.where((crit > 0) & (crit < t_max[:, None]), crit, t_max[:, None])
    knots = np.sort(np.concatenate([crit, t_max[:, None]], axis=1), axis=1)      # (n, 4)
    val, size = _horner(c[:, :, None], knots)
    reached = val >= -GRAZE * size
    first = np.argmax(reached, axis=1)                 # t_max always reached
    hi = knots[np.arange(n), first]
    lo = np.where(first > 0, knots[np.arange(n), np.maximum(first - 1, 0)], 0.0)
    touch = val[np.arange(n), first] < 0               # grazing: the knot itself
    for _ in range(_BISECTIONS):                       # bisection steps, each over every fall
        mid = 0.5 * (lo + hi)
        inside = _value(c, mid) < 0
        lo = np.where(inside, mid, lo)
        hi = np.where(inside, hi, mid)
    t = np.where(touch, hi, 0.5 * (lo + hi))
    t = np.where(at_once, 0.0, t)
    t = np.where(outside | bad, np.nan, t)
    zhat = np.array([0.0, 0.0, 1.0])[:, None]
    x_land = x0 + v0 * t - 0.5 * g * t * t * zhat
    v_land = v0 - g * t * zhat
    speed = np.sqrt(np.einsum("in,in->n", v_land, v_land))
    rad = np.sqrt(np.einsum("in,in->n", x_land, x_land))
    rad_safe = np.where(rad > 0, rad, 1.0)
    normal = np.einsum("in,in->n", x_land, v_land) / rad_safe
    status = np.where(bad, NOT_FLOWN, np.where(outside, STARTS_OUTSIDE, LANDS)).astype(np.int8)
    return {"t_land": t, "x_land": x_land, "v_land": v_land, "impact_speed": speed,
            "impact_normal": normal, "status": status}


# ---------------------------------------------------------------------------
# the loop
# ---------------------------------------------------------------------------

def _rf(x, y, z):
    """Carlson's symmetric elliptic integral R_F(x, y, z), x, y, z >= 0, at
    most one zero, by duplication (Carlson 1995, Numer. Algorithms 10, eqs.
    2.2-2.3; DLMF 19.36.1): a fixed number of steps, each quartering the
    spread, then the fifth-order series."""
    for _ in range(_RF_STEPS):
        sx, sy, sz = np.sqrt(x), np.sqrt(y), np.sqrt(z)
        lam = sx * sy + sy * sz + sz * sx
        x, y, z = 0.25 * (x + lam), 0.25 * (y + lam), 0.25 * (z + lam)
    mu = (x + y + z) / 3.0
    dx, dy = 1.0 - x / mu, 1.0 - y / mu
    dz = -(dx + dy)
    e2 = dx * dy - dz * dz
    e3 = dx * dy * dz
    return (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0) / np.sqrt(mu)


def _ellip_f(phi, m, m1):
    """Incomplete elliptic integral of the first kind F(phi | m) for |phi| <=
    pi/2, 0 <= m <= 1 (not phi = +-pi/2 with m = 1), m1 = 1 - m given
    apart so that 1 - m sin^2 phi = cos^2 phi + m1 sin^2 phi keeps its
    digits near m = 1: sin(phi) R_F(cos^2 phi, 1 - m sin^2 phi, 1) (DLMF 19.25.5)."""
    s = np.sin(phi)
    cc = np.cos(phi) ** 2
    return s * _rf(cc, cc + np.maximum(m1, 0.0) * s * s, np.ones_like(s))


def _energy(psi0, psi_dot0, r_g, M_eff, m, g):
    """Mirror the loop so that the travel is towards increasing u = s psi,
    u0 in [0, 2 pi); M21: psidot^2 = C - kappa cos u."""
    psi0, psi_dot0, r_g, M_eff, m, g = np.broadcast_arrays(
        *(np.asarray(x, dtype=float) for x in (psi0, psi_dot0, r_g, M_eff, m, g)))
    sin0 = np.sin(psi0)
    s = np.where(psi_dot0 != 0, np.sign(psi_dot0), np.where(sin0 < 0, -1.0, 1.0))
    u0 = np.mod(s * psi0, 2 * np.pi)
    u0 = np.where(u0 >= 2 * np.pi, 0.0, u0)
    w0 = np.abs(psi_dot0)
    ok = (r_g > 0) & (M_eff > 0) & (g > 0) & np.isfinite(psi0) & np.isfinite(psi_dot0)
    kappa = np.where(ok, 2 * m * g * r_g / np.where(ok, M_eff, 1.0), 1.0)
    kappa = np.where(kappa > 0, kappa, 1.0)
    c = w0 * w0 + kappa * np.cos(u0)
    return s, u0, w0, kappa, c, ok


def _travel_time(u0, u1, c, kappa, turns=False):
    """t = int_{u0}^{u1} du / sqrt(c - kappa cos u), 0 <= u0 <= u1 < 2 pi,
    where the integrand is real (eq. M21 solved for the time; beyond the
    paper).  With x = (pi - u)/2, c - kappa cos u = (c + kappa)(1 - m sin^2 x),
    m = 2 kappa / (c + kappa):  t = 2 [F(x0|m) - F(x1|m)] / sqrt(c + kappa);
    for m > 1 (no lap over the top) the reciprocal-modulus form with
    sin(beta) = sqrt(m) sin(x):  t = sqrt(2/kappa) [F(beta0|1/m) - F(beta1|1/m)].
    ``turns``: u1 is a turning point (beta1 = -pi/2 exactly, not through an
    arcsine that loses half the digits there)."""
    x0 = 0.5 * (np.pi - u0)
    x1 = 0.5 * (np.pi - u1)
    total = c + kappa                                   # >= 0: the speed squared at the bottom
    laps = c >= kappa
    tot_s = np.where(total > 0, total, 1.0)
    m = np.where(laps, 2 * kappa / tot_s, 0.5)
    m1 = np.where(laps, (c - kappa) / tot_s, 0.5)
    t_lap = 2.0 * (_ellip_f(x0, m, m1) - _ellip_f(x1, m, m1)) / np.sqrt(tot_s)
    mr = np.where(laps, 0.5, total / (2 * kappa))       # 1/m in [0, 1)
    mr1 = np.where(laps, 0.5, (kappa - c) / (2 * kappa))
    mr_s = np.where(mr > 0, mr, 1.0)
    b0 = np.arcsin(np.clip(np.sin(x0) / np.sqrt(mr_s), -1.0, 1.0))
    b1 = np.where(turns, -0.5 * np.pi, np.arcsin(np.clip(np.sin(x1) / np.sqrt(mr_s), -1.0, 1.0)))
    t_swing = np.sqrt(2.0 / kappa) * (_ellip_f(b0, mr, mr1) - _ellip_f(b1, mr, mr1))
    t_swing = np.where(mr > 0, t_swing, 0.0)            # at rest at the bottom
    return np.where(laps, t_lap, t_swing)


def loop_departure(psi0, psi_dot0, rho, r_g, M_eff, m, g):
    """The rest of a vertical loop from the state just after a speed drop
    (docs/machine.md sec. 10, eqs. M21-M23; the departure itself beyond the
    paper).

    psi0 [rad] (from the top, any branch), psi_dot0 [rad/s] (sign = the
    direction of travel) of the centre of mass G on its circle of radius
    ``r_g`` [m] in the loop of radius ``rho`` [m] (0 < r_g <= rho);
    ``M_eff`` [kg m^2] the loop's effective inertia M = m r_G^2 + I_pitch +
    J (rho^2 - 2 rho a)/a^2 (M21; a point mass: m r_G^2), ``m`` [kg],
    ``g`` [m/s^2]; all broadcast.  Where only the loop's rates at the top
    and the bottom are at hand, M23 gives M = 4 m g r_G / (psidot_b^2 -
    psidot_t^2).

    Energy (M21) gives psidot^2 = C - kappa cos psi with kappa = 2 m g r_G / M
    and C = psi_dot0^2 + kappa cos psi0; the in-plane normal force per unit
    mass is r_G psidot^2 - g cos psi = A - B cos psi with A = r_G C and
    B = g + r_G kappa (= g (1 + 2q) of M24).  Going up towards the top,
    cos psi grows: the speed vanishes at cos psi = C/kappa, the normal force
    at A/B = C r_G / (g + r_G kappa), which comes first exactly when C > 0.
    So: RIDES_ON where A >= B (M22, to the tolerance of
    :func:`deathsphere.physics.machine.vertical_loop`); else SWINGS where
    C <= 0 (turning at cos psi = C/kappa <= 0, on or below the equator);
    else FALLS at cos psi = A/B (> 0, above the equator), or at once where
    the normal force is not positive just after the drop.  The time is
    :func:`loop_time`'s closed form.

    Returns dict of (n,) arrays: int8 ``outcome`` (RIDES_ON, SWINGS, FALLS;
    NO_LOOP outside the model), ``t_lost`` [s] after the drop and
    ``psi_lost`` [rad] (on the branch of psi0, along the travel; FALLS only,
    else NaN), ``psi_dot_lost`` [rad/s] (FALLS only, else NaN), ``psi_max``
    [rad] (the highest point reached with contact, as an angle from the top
    in [0, pi]: the turning point for SWINGS, the departure for FALLS, 0 for
    RIDES_ON), ``t_turn`` [s] (SWINGS: time to the first turning point) and
    ``swing_period`` [s] (SWINGS: a full swing, back and forth; the swing
    covers the arc through the bottom between psi = +-psi_max, the lanes it
    crosses are those that meet that arc).
    """
    psi0, psi_dot0, rho, r_g, M_eff, m, g = np.broadcast_arrays(
        *(np.asarray(x, dtype=float) for x in (psi0, psi_dot0, rho, r_g, M_eff, m, g)))
    s, u0, w0, kappa, c, ok = _energy(psi0, psi_dot0, r_g, M_eff, m, g)
    ok &= r_g <= rho * (1 + 1e-12)
    rg = np.where(ok, r_g, 1.0)
    gg = np.where(ok, g, 1.0)
    big_a = rg * c
    big_b = gg + rg * kappa
    n0 = rg * w0 * w0 - gg * np.cos(u0)
    at_once = n0 <= 0
    rides = ~at_once & (big_a - big_b >= -2e-12 * gg)
    swings = ~at_once & ~rides & (c <= 0)
    falls = ok & ~rides & ~swings
    outcome = np.where(rides, RIDES_ON, np.where(swings, SWINGS, FALLS))
    outcome = np.where(ok, outcome, NO_LOOP).astype(np.int8)
    # the event on the way up to the top: u_e = 2 pi - acos(c*) >= u0
    c_star = np.where(swings, c / kappa, big_a / big_b)
    u_e = 2 * np.pi - np.arccos(np.clip(c_star, -1.0, 1.0))
    u_e = np.where(at_once | rides | ~ok, u0, np.maximum(u_e, u0))
    t_event = _travel_time(u0, u_e, c, kappa, turns=swings)
    psi_event = psi0 + s * (u_e - u0)
    w_e = np.sqrt(np.maximum(c - kappa * np.cos(u_e), 0.0))
    highest = np.abs(np.mod(psi_event + np.pi, 2 * np.pi) - np.pi)   # angle from the top in [0, pi]
    nan = np.full(outcome.shape, np.nan)
    # a full swing, turning point to turning point and back: 4 K(1/m) sqrt(2/kappa)
    mr = np.where(swings, (c + kappa) / (2 * kappa), 0.0)
    mr1 = np.where(swings, (kappa - c) / (2 * kappa), 1.0)
    half = 2.0 * np.sqrt(2.0 / kappa) * _ellip_f(np.full(mr.shape, 0.5 * np.pi), mr, mr1)
    return {
        "outcome": outcome,
        "t_lost": np.where(falls, t_event, nan),
        "psi_lost": np.where(falls, psi_event, nan),
        "psi_dot_lost": np.where(falls, np.where(at_once, psi_dot0, s * w_e), nan),
        "psi_max": np.where(rides & ok, 0.0, np.where(ok, highest, nan)),
        "t_turn": np.where(swings, t_event, nan),
        "swing_period": np.where(swings, 2 * half, nan),
    }


def loop_time(psi0, psi_dot0, psi1, r_g, M_eff, m, g):
    """Time [s] for G to go from psi0 to psi1 on a loop with energy conserved
    (M21; beyond the paper: t = int dpsi / psidot(psi) in closed form with
    incomplete elliptic integrals of the first kind, Carlson's R_F).  psi1 is
    ahead of psi0 in the direction of psi_dot0 (of its sign, or of gravity's
    pull when psi_dot0 = 0), less than a lap on, and before the top is passed
    when the energy does not carry G over it.  NaN where psi1 is not reached
    (the speed vanishes before it) or outside the model."""
    psi1 = np.asarray(psi1, dtype=float)
    s, u0, w0, kappa, c, ok = _energy(psi0, psi_dot0, r_g, M_eff, m, g)
    s, u0, kappa, c, ok, psi1 = np.broadcast_arrays(s, u0, kappa, c, ok, psi1)
    ahead = s * (psi1 - np.asarray(psi0, dtype=float))
    u1 = u0 + ahead
    laps = c >= kappa
    x1 = 0.5 * (np.pi - u1)
    mr = np.where(laps, 0.5, (c + kappa) / (2 * kappa))
    reach = (ahead >= 0) & (u1 < 2 * np.pi) & (laps | (np.sin(x1) ** 2 <= mr * (1 + 1e-12)))
    reach &= ok
    u1s = np.where(reach, u1, u0)
    return np.where(reach, _travel_time(u0, u1s, c, kappa), np.nan)


def loop_speed_profile(t, psi0, psi_dot0, r_g, M_eff, m, g):
    """psi(t) and psidot(t) [rad, rad/s] of a loop ridden over the top with
    energy conserved (M21; beyond the paper), psi(0) = psi0 and psidot(0) =
    psi_dot0 > 0, for times t [s] (broadcast); psi is unwrapped (increases
    without bound).  Inverting :func:`loop_time`: with x = (pi - psi)/2,
    F(x|m) = F(x0|m) - t sqrt(C + kappa)/2, so x = am(.|m), the Jacobi
    amplitude (scipy.special.ellipj).  Returns dict ``psi``, ``psi_dot``,
    ``period`` [s] (one lap: 4 K(m) / psidot_bottom); NaN where the energy
    does not carry G over the top (C < kappa) or outside the model."""
    from scipy.special import ellipj, ellipk

    t = np.asarray(t, dtype=float)
    s, u0, w0, kappa, c, ok = _energy(psi0, psi_dot0, r_g, M_eff, m, g)
    psi0 = np.asarray(psi0, dtype=float)
    t, s, u0, kappa, c, ok, psi0 = np.broadcast_arrays(t, s, u0, kappa, c, ok, psi0)
    laps = ok & (c > kappa)
    total = np.where(laps, c + kappa, 2.0)
    mm = np.where(laps, 2 * kappa / total, 0.5)
    root = np.sqrt(total)
    x0 = 0.5 * (np.pi - u0)
    big_k = ellipk(mm)
    phase = _ellip_f(x0, mm, np.where(laps, (c - kappa) / total, 0.5)) - 0.5 * t * root
    turns = np.floor(phase / (2 * big_k) + 0.5)
    _sn, _cn, _dn, am = ellipj(phase - 2 * turns * big_k, mm)
    x = am + np.pi * turns
    u = np.pi - 2 * x
    psi = psi0 + s * (u - u0)
    psi_dot = s * np.sqrt(np.maximum(c - kappa * np.cos(u), 0.0))
    nan = np.full(psi.shape, np.nan)
    return {"psi": np.where(laps, psi, nan), "psi_dot": np.where(laps, psi_dot, nan),
            "period": np.where(laps, 4 * big_k / root, nan)}


def loop_state(psi, psi_dot, r_g, azimuth):
    """The centre of mass's position and velocity, (3, n) each [m, m/s], on
    a vertical great-circle loop whose plane holds z and e = (cos azimuth,
    sin azimuth, 0) (the show's vertical lane; docs/machine.md sec. 10):
    G = r_G (sin psi e + cos psi z), dG/dt = r_G psidot (cos psi e - sin psi z)."""
    psi, psi_dot, r_g, azimuth = np.broadcast_arrays(
        *(np.asarray(x, dtype=float) for x in (psi, psi_dot, r_g, azimuth)))
    sp, cp = np.sin(psi), np.cos(psi)
    ex, ey = np.cos(azimuth), np.sin(azimuth)
    x = r_g * np.stack([sp * ex, sp * ey, cp])
    v = r_g * psi_dot * np.stack([cp * ex, cp * ey, -sp])
    return x, v


def drop_velocity(v, speed_fraction):
    """The velocity (3, n) just after the drop: ``speed_fraction`` (n,) times
    the velocity ``v`` (3, n) before, along the direction of travel (the
    position is unchanged; stage 1 of the model above).

    Beyond the paper: the fall model of docs/show.md sec. 6.
    """
    return np.asarray(v, dtype=float) * np.asarray(speed_fraction, dtype=float)


def horizontal_holds(theta, speed, alpha_before, ground, g, machine, mu):
    """Whether a horizontal lane still holds a machine after the drop: some
    tilt alpha at the same contact height (``theta`` [rad]) gives a steady
    orbit whose centre of mass moves at ``speed`` [m/s] with contact, the
    friction within ``mu`` and the head clear (docs/machine.md eqs. M8-M12:
    every tilt for the speed and its orbit,
    :func:`deathsphere.physics.machine_lanes.orbits_for_speed`).  ``ground``
    the sphere, ``machine`` the machine's arrays
    (:class:`~deathsphere.physics.machine_arrays.MachineArrays`); all
    broadcast to (n,).

    Returns dict: ``holds`` (n,) bool (False where speed <= 0: a stall holds
    on no lane), ``alpha`` (n,) [rad] the tilt that holds closest to
    ``alpha_before`` (NaN where none does).  Where it does not hold the rider
    leaves the wall at once (stage 2 of the model above).
    """
    return _holds(orbits_for_speed, theta, speed, alpha_before, ground, g, machine, mu)


def horizontal_holds_on(height, speed, alpha_before, ground, g, machine, mu):
    """:func:`horizontal_holds` on any ground (beyond the paper;
    docs/show.md sec. 11, "A fall on a wall"): some tilt on the lane at
    ``height`` [m] above the floor gives a steady orbit whose centre of
    mass moves at ``speed`` [m/s] with the friction within ``mu`` (eqs.
    MS1-MS7, :func:`deathsphere.physics.machine_lanes.orbits_for_speed_on`).
    On the drum that is the wall of death's rule: the friction must carry
    the weight, mu N >= m g, which fails below a least speed; there the
    rider's wheels slide off the wall and he leaves it at once.  The same
    dict as :func:`horizontal_holds`."""
    return _holds(orbits_for_speed_on, height, speed, alpha_before, ground, g, machine, mu)


def _holds(orbits, where, speed, alpha_before, ground, g, machine, mu):
    """:func:`horizontal_holds` with the lanes' physics ``orbits`` (the
    globe's by theta, any ground's by height)."""
    where, speed, alpha_before, mu = np.broadcast_arrays(
        *(np.asarray(x, dtype=float).reshape(-1) for x in (where, speed, alpha_before, mu)))
    moving = speed > 0
    roots, orb = orbits(where, np.where(moving, speed, 1.0), ground, g, machine, mu)
    ok = np.isfinite(roots) & moving[:, None] & (orb["status"] == Status.OK)
    best, holds = closest_tilt(roots, ok, alpha_before)
    alpha = np.where(holds, roots[np.arange(where.size), best] if roots.shape[1] else np.nan, np.nan)
    return {"holds": holds, "alpha": alpha}
