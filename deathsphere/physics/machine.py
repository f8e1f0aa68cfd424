"""Steady horizontal orbits of a machine -- a single-contact gyrostat: a rigid
frame (motorcycle and rider, wheels locked) carrying axisymmetric wheels that
spin about one axle direction -- rolling without slipping on a fixed sphere.

Beyond the paper (docs/machine.md, eqs. M1-M12): Newton-Euler about the
centre of mass G with the wheels' spin angular momentum.  In the meridian
plane of the contact point (unit vectors r-hat horizontal outwards, z-hat up)
the contact point is P = r (sin(theta), cos(theta)), the centre of the
tyre's crown circle Q = (r - t) (sin(theta), cos(theta)) (on the sphere's
normal through P, t inside it), the up-axis u = (-cos(alpha), sin(alpha)),
and G = Q + (h - t) u.  On a steady orbit at rate Omega about the vertical
the frame turns at Omega z-hat and the wheels spin at s = sigma Omega
relative to it (eq. M4), and the balance of angular momentum about G
(eq. M7) is one scalar equation, solved for Omega^2 (eq. M8)::

    Omega^2 = g d_r / (sin(alpha) (j sigma + delta cos(alpha)) - d_z r_G)

    r_G   = (r - t) sin(theta) - (h - t) cos(alpha)     (CoM's orbit radius, M2)
    d_r   = t sin(theta) + (h - t) cos(alpha)            (P - G, horizontal, M6)
    d_z   = t cos(theta) - (h - t) sin(alpha)            (P - G, vertical, M6)
    W     = (a - t) + t sin(theta - alpha)               (rolling radius, M4)
    sigma = r sin(theta) / W                             (M4)
    j     = spin_inertia / mass,  delta = (I_yaw - I_pitch) / mass

The paper's wheel (h = a, t = 0, inertia (k, 2k, k) m a^2, spin_inertia
2 k m a^2) gives eq. (29) exactly (docs/machine.md, sec. 4).

Every function takes broadcastable float arrays (theta, alpha in radians,
g in m/s^2), the ground (a :class:`~deathsphere.physics.ground.Sphere`, its
radius r a number or an array) and the machine's arrays
(:class:`~deathsphere.physics.machine_arrays.MachineArrays`, from
:func:`~deathsphere.physics.machine_arrays.machine_arrays`), and loops over
no orbit.  Statuses and reasons are :mod:`deathsphere.physics.status` codes.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.ground import Sphere
from deathsphere.physics.machine_arrays import MachineArrays
from deathsphere.physics.status import Reason, Status, first_failure, mu_required
from deathsphere.physics.trig_roots import evaluate_rows, roots_in

__all__ = ["vertical_loop", "ride_orbit", "meridian_points", "speed_polynomial", "solve_alpha_for_speed",
           "rate_polynomial", "solve_alpha_for_rate", "fit_window", "ROOT_MATCH_RTOL"]

#: A root of the speed polynomial (eq. M12) is kept only where the forward
#: model gives the target speed back to this relative tolerance (as
#: :data:`deathsphere.physics.region.ROOT_MATCH_RTOL`).
ROOT_MATCH_RTOL = 1e-3


def _parts(st, ct, sa, ca, r, h, a, t):
    """The lengths of eqs. M2-M6 from sines and cosines (docs/machine.md)."""
    hq = h - t
    r_g = _point(st, ca, r, h, t)                      # M2: CoM distance from the axis
    d_r = t * st + hq * ca                             # M6: (P - G) . r-hat
    d_z = t * ct - hq * sa                             # M6: (P - G) . z-hat
    w = (a - t) + t * (st * ca - ct * sa)              # M4: (a - t) + t sin(theta - alpha)
    return r_g, d_r, d_z, w


def _point(sn, cs, r, height, t):
    """One coordinate of eq. M2's point at ``height`` along the up-axis,
    Q + (height - t) u with Q = (r - t) n-hat, u = (-cos alpha, sin alpha):
    rho for (sn, cs) = (sin theta, cos alpha), z for (cos theta, -sin alpha).
    The one place eq. M2 is written."""
    return (r - t) * sn - (height - t) * cs


def _meridian(st, ct, sa, ca, r, m: MachineArrays) -> dict:
    t = m.tyre_radius
    return {"contact": (r * st, r * ct),
            "com": (_point(st, ca, r, m.com_height, t), _point(ct, -sa, r, m.com_height, t)),
            "head": (_point(st, ca, r, m.head_height, t), _point(ct, -sa, r, m.head_height, t))}


def meridian_points(theta, alpha, ground, machine: MachineArrays) -> dict:
    """Eq. M2: the contact point P, the centre of mass G = Q + (h - t) u and
    the head H = Q + (head - t) u as (rho, z) [m] in the contact's meridian
    plane (rho horizontal from the axis, z up from the sphere's centre), for
    the contact at polar angle theta and the tilt alpha [rad] (arrays,
    broadcast against the machine's); Q = (r - t) n-hat is the centre of the
    tyre's crown circle, u = (-cos alpha, sin alpha) the up-axis.  Keys
    'contact', 'com', 'head'."""
    theta, alpha = np.asarray(theta, dtype=float), np.asarray(alpha, dtype=float)
    return _meridian(np.sin(theta), np.cos(theta), np.sin(alpha), np.cos(alpha), ground.radius, machine)


def ride_orbit(theta, alpha, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf):
    """Every quantity of a machine's steady horizontal orbit inside the sphere,
    vectorised (docs/machine.md eqs. M1-M11).

    Parameters (broadcast)
    ----------------------
    theta, alpha : [rad]  polar angle of the contact point; tilt of the up-axis
        above the orbit plane (the paper's alpha for the paper's wheel).
    ground : the sphere (:class:`~deathsphere.physics.ground.Sphere`, radius
        r [m]); g [m/s^2]; machine the machine's arrays (mass [kg] > 0;
        com_height h, wheel_radius a, tyre_radius t, head_height [m], all
        along the up-axis above the contact on flat ground; pitch_inertia,
        yaw_inertia, spin_inertia [kg m^2]); mu friction available; max_g the
        largest load_g allowed.

    Returns
    -------
    dict of arrays of the broadcast shape: ``r_g`` [m] signed CoM orbit
    radius, ``omega2`` [1/s^2] (NaN where undefined), ``omega`` [rad/s],
    ``period`` [s], ``v_cm`` [m/s], ``v_contact`` [m/s], ``spin`` [rad/s]
    (wheels relative to the frame, eq. M4), ``normal``, ``friction`` [m/s^2]
    (per unit mass; friction positive down the wall), ``mu_required``,
    ``load_g`` (|F| / (m g)), ``head_clearance`` [m] (r - |head point|),
    ``height`` [m] contact above the floor, int8 ``status`` and ``reason``.
    An ok row is all finite.
    """
    m = machine
    theta, alpha, r, g, mu, max_g = (np.asarray(x, dtype=float) for x in (theta, alpha, ground.radius, g, mu, max_g))
    mass, h, a, t, ip, iy, js = (m.mass, m.com_height, m.wheel_radius, m.tyre_radius, m.pitch_inertia,
                                 m.yaw_inertia, m.spin_inertia)
    st, ct = np.sin(theta), np.cos(theta)
    sa, ca = np.sin(alpha), np.cos(alpha)
    r_g, d_r, d_z, w = _parts(st, ct, sa, ca, r, h, a, t)
    j = js / mass
    delta = (iy - ip) / mass
    fit = (st * ca - ct * sa) * (r - t) > (a - t)                   # M10: sin(theta - alpha) > (a-t)/(r-t)
    w_ok = w > 0                                                     # true wherever the wheel fits
    with np.errstate(divide="ignore", invalid="ignore"):
        sigma = np.where(w_ok, r * st / np.where(w_ok, w, 1.0), np.nan)   # M4
    den = sa * (j * sigma + delta * ca) - d_z * r_g                  # M8 denominator [m^2]
    den_scale = (r + h + a) * (h + t + a) + np.abs(j) * r / (a - t) + np.abs(delta)
    singular = ~(np.abs(den) > SINGULAR * den_scale)                 # also NaN (wheel cannot fit)
    with np.errstate(divide="ignore", invalid="ignore"):
        om2 = np.where(singular, np.nan, g * d_r / np.where(singular, 1.0, den))   # M8
    om2_zero = np.abs(om2) <= SINGULAR * g / r
    real = (om2 > 0) & ~om2_zero
    om2_real = np.where(real, om2, np.nan)
    omega = np.sqrt(om2_real)
    with np.errstate(divide="ignore"):
        period = 2 * np.pi / omega
    centripetal = r_g * om2_real                                     # |a_G| signed towards the axis
    normal = centripetal * st - g * ct                               # M9: F . n_in / m
    friction = -(centripetal * ct + g * st)                          # M9: F . theta-hat / m
    mu_req = mu_required(normal, friction)
    load = np.sqrt(centripetal * centripetal + g * g) / g            # M11
    # the head point H (eq. M2), and its distance from the centre
    hx, hz = _point(st, ca, r, m.head_height, t), _point(ct, -sa, r, m.head_height, t)
    clearance = r - np.sqrt(hx * hx + hz * hz)
    status, reason = first_failure([
        (~fit, Status.NO_FIT, Reason.MACHINE_NO_FIT),
        (~(clearance > 0), Status.NO_FIT, Reason.HEAD_HITS),
        (singular, Status.NO_ORBIT, Reason.MACHINE_ZERO_DENOMINATOR),
        (om2_zero, Status.NO_ORBIT, Reason.MACHINE_OMEGA_ZERO),
        (~real, Status.NO_ORBIT, Reason.MACHINE_OMEGA_IMAGINARY),
        (~(normal > 0), Status.NO_CONTACT, Reason.MACHINE_NO_CONTACT),
        (mu_req > mu, Status.SLIPS, Reason.SLIPS),
        (load > max_g, Status.OVER_G, Reason.MACHINE_OVER_G),
    ])
    out = {
        "r_g": r_g,
        "omega2": om2,
        "omega": omega,
        "period": period,
        "v_cm": np.abs(r_g) * omega,
        "v_contact": r * st * omega,
        "spin": sigma * omega,
        "normal": normal,
        "friction": friction,
        "mu_required": mu_req,
        "load_g": load,
        "head_clearance": clearance,
        "height": r * (1.0 + ct),                                   # Sphere.height, its cosine at hand
        "status": status,
        "reason": reason,
    }
    shape = status.shape
    return {key: (val if val.shape == shape else np.broadcast_to(val, shape)) for key, val in out.items()}


# ---------------------------------------------------------------------------
# every tilt for a speed (eq. M12)
# ---------------------------------------------------------------------------

def _lin(c0, cc, cs):
    """Coefficient rows (n, 3) of c0 + cc cos(alpha) + cs sin(alpha) in
    exp(i j alpha), j = -1, 0, 1 (the convention of
    :mod:`deathsphere.physics.trig_roots`)."""
    c0, cc, cs = np.broadcast_arrays(*(np.asarray(x, dtype=complex) for x in (c0, cc, cs)))
    return np.stack((0.5 * cc + 0.5j * cs, c0, 0.5 * cc - 0.5j * cs), axis=-1)


def _mul(p, q):
    """Product of coefficient rows (n, 2P+1) and (n, 2Q+1): a convolution
    along the harmonics (a loop over harmonics, not over orbits)."""
    n, lp = p.shape
    out = np.zeros((n, lp + q.shape[1] - 1), dtype=complex)
    for k in range(q.shape[1]):
        out[:, k:k + lp] += p * q[:, k:k + 1]
    return out


def _add(p, q):
    if p.shape[1] < q.shape[1]:
        p, q = q, p
    d = (p.shape[1] - q.shape[1]) // 2
    out = p.copy()
    out[:, d:d + q.shape[1]] += q
    return out


def _balance_terms(theta, ground, g, m: MachineArrays):
    """Coefficient rows of eq. M8's parts (docs/machine.md eq. M12): ``(d_r,
    W, r_G, den W)``, den the denominator of eq. M8, so that Omega^2 =
    g d_r W / (den W) wherever the wheel fits (W > 0)."""
    r, mass, h, a, t = ground.radius, m.mass, m.com_height, m.wheel_radius, m.tyre_radius
    st, ct = np.sin(theta), np.cos(theta)
    hq = h - t
    j = m.spin_inertia / mass
    delta = (m.yaw_inertia - m.pitch_inertia) / mass
    zero = np.zeros_like(st)
    r_g = _lin((r - t) * st, -hq + zero, zero)
    d_r = _lin(t * st, hq + zero, zero)
    d_z = _lin(t * ct, zero, -hq + zero)
    w = _lin((a - t) + zero, t * st, -t * ct)
    sin_a = _lin(zero, zero, 1.0 + zero)
    cos_a = _lin(zero, 1.0 + zero, zero)
    bracket = _add(_lin(j * r * st, zero, zero), _mul(cos_a, w) * delta[:, None])
    den_w = _add(_mul(sin_a, bracket), -_mul(_mul(d_z, r_g), w))
    return d_r, w, r_g, den_w


def speed_polynomial(theta, speed, ground, g, m: MachineArrays):
    """Coefficient rows (n, 9) of the trigonometric polynomial in alpha of
    degree 4 whose zeros are the tilts giving the CoM speed ``speed``
    (docs/machine.md eq. M12), all inputs 1-D of one length n (the sphere's
    radius and the machine's arrays included)::

        f(alpha) = g d_r r_G^2 W - v^2 [sin(alpha) (j r sin(theta) + delta cos(alpha) W) - d_z r_G W]

    i.e. (g d_r r_G^2 - v^2 den) W with den the denominator of eq. M8 (W > 0
    wherever the wheel fits, so no zero is added or lost there)."""
    d_r, w, r_g, den_w = _balance_terms(theta, ground, g, m)
    v2 = (speed * speed)[:, None]
    left = _mul(_mul(_mul(d_r, r_g), r_g), w) * g[:, None]
    return _add(left, -v2 * den_w)


def rate_polynomial(theta, omega, ground, g, m: MachineArrays):
    """Coefficient rows (n, 7) of the trigonometric polynomial in alpha of
    degree 3 whose zeros are the tilts of a steady orbit at the rate
    ``omega`` (docs/machine.md eq. M12r, beyond the paper: eq. M8 with
    Omega given instead of v_cm = Omega |r_G|)::

        f(alpha) = g d_r W - Omega^2 [sin(alpha) (j r sin(theta) + delta cos(alpha) W) - d_z r_G W]

    i.e. (g d_r - Omega^2 den) W, as :func:`speed_polynomial` without the
    factor r_G^2 (all inputs 1-D of one length n)."""
    d_r, w, _, den_w = _balance_terms(theta, ground, g, m)
    return _add(_mul(d_r, w) * g[:, None], -(omega * omega)[:, None] * den_w)


def fit_window(theta, ground, machine: MachineArrays):
    """The tilts at which the wheel fits (eq. M10), (lo, hi) [rad]: the open
    interval theta - pi + asin(q) < alpha < theta - asin(q), q = (a-t)/(r-t)."""
    r, a, t = ground.radius, machine.wheel_radius, machine.tyre_radius
    q = np.arcsin(np.clip((a - t) / (r - t), -1.0, 1.0))
    return theta - np.pi + q, theta - q


def solve_alpha_for_speed(theta, speed, ground, g, machine: MachineArrays):
    """Every tilt in the fit window (eq. M10) at which the CoM speed of a
    steady orbit is ``speed`` (1-D inputs of one length n, speed > 0; the
    sphere's radius and the machine's arrays broadcast against them).

    The zeros of :func:`speed_polynomial` (at most 8 per period) are all
    found as eigenvalues of the companion matrix and refined by bisection
    (:func:`deathsphere.physics.trig_roots.roots_in`); a zero is kept only
    where the forward model :func:`ride_orbit` gives the speed back to
    :data:`ROOT_MATCH_RTOL` (eq. M8 defined there).  Tangent (double) zeros,
    where the speed is exactly a local extremum of v_cm(alpha), are not
    reported.  Returns (n, m) roots, sorted, NaN-padded, m <= 8.
    """
    return _tilts_giving(theta, speed, ground, g, machine, speed_polynomial, "v_cm")


def solve_alpha_for_rate(theta, omega, ground, g, machine: MachineArrays):
    """Every tilt in the fit window (eq. M10) at which a steady orbit turns
    at the rate ``omega`` [rad/s] > 0 about the vertical (docs/machine.md
    eq. M12r, beyond the paper): the zeros of :func:`rate_polynomial` (at
    most 6 per period), kept where :func:`ride_orbit` gives Omega back to
    :data:`ROOT_MATCH_RTOL`, as :func:`solve_alpha_for_speed` (1-D inputs
    of one length n).  A contact speed v_contact fixes Omega = v_contact /
    (r sin(theta)) whatever the tilt (the contact runs round the parallel of
    radius r sin(theta)), and a lap time T fixes Omega = 2 pi / T: both are
    lanes by rate.  Returns (n, m) roots, sorted, NaN-padded, m <= 6.
    """
    return _tilts_giving(theta, omega, ground, g, machine, rate_polynomial, "omega")


def _tilts_giving(theta, target, ground, g, machine: MachineArrays, polynomial, key: str):
    """The zeros of ``polynomial`` in the fit window at which ride_orbit's
    ``key`` is ``target`` (the shared body of the two solves above)."""
    args = np.broadcast_arrays(*(np.asarray(x, dtype=float).reshape(-1) for x in
                                 (theta, target, ground.radius, g, *machine)))
    theta, target, r, g = args[:4]
    m = MachineArrays(*args[4:])
    n = theta.size
    if n == 0:
        return np.full((0, 0), np.nan)
    coef = polynomial(theta, target, Sphere(r), g, m)
    lo, hi = fit_window(theta, Sphere(r), m)
    eps = 1e-12
    roots = roots_in(coef, lo + eps, hi - eps) if hi.size else np.full((n, 0), np.nan)
    found = np.isfinite(roots)
    if roots.shape[1] == 0:
        return roots
    col = (slice(None), None)
    # the head set above the centre of mass: only the speed (or rate) is checked here
    mc = m._replace(head_height=m.com_height + 1.0).map(lambda x: x[col])
    orb = ride_orbit(theta[col], np.where(found, roots, 0.0), Sphere(r[col]), g[col], mc)
    with np.errstate(invalid="ignore"):
        found &= np.abs(orb[key] - target[col]) <= ROOT_MATCH_RTOL * target[col]
    roots = np.sort(np.where(found, roots, np.nan), axis=1)
    width = max(1, int(np.max(np.sum(np.isfinite(roots), axis=1), initial=0)))
    return roots[:, :width]


def polynomial_values(coef, alpha):
    """Values of coefficient rows (n, 2N+1) at alpha (n, m) (a check)."""
    return evaluate_rows(coef, alpha)


# ---------------------------------------------------------------------------
# vertical loops (docs/machine.md sec. 10, eqs. M21-M23)
# ---------------------------------------------------------------------------

def vertical_loop(theta, v_top, ground, g, machine: MachineArrays, mu=np.inf, max_g=np.inf):
    """A machine looping in the vertical plane at distance r cos(theta) from
    the sphere's centre, its up-axis towards the loop's centre (docs/machine.md
    sec. 10).  Loop radius rho = r sin(theta), centre-of-mass radius
    r_G = rho - h, the wheels' spin s = -phidot rho / a relative to the frame;
    energy (M21): (1/2) M phidot^2 + m g r_G cos(phi) = const with
    M = m r_G^2 + I_pitch + J (rho^2 - 2 rho a) / a^2; contact at the top
    (M22): v_top^2 >= g r_G; at the bottom (M23) phidot_b^2 = phidot_t^2 +
    4 m g r_G / M and the load is phidot_b^2 r_G / g + 1, the most round the
    loop.  The friction needed (M24, beyond the paper; the machine's eqs.
    (27)-(28b) of the wheel): with q = m r_G^2 / M the in-plane force is
    (D - B cos(phi)) inwards and -c g sin(phi) along the path, D = v_top^2 /
    r_G + 2 q g, B = (1 + 2 q) g, c = 1 - q, so that mu(phi) = hypot(c g
    sin(phi), (D - B cos(phi)) cos(theta)) / ((D - B cos(phi)) sin(theta)),
    largest at cos(phi*) = B / D:  mu_max = sqrt(cos^2(theta) + c^2 g^2 /
    (D^2 - B^2)) / sin(theta).  A knife edge (t = 0) stays in any loop's
    plane; a round tyre only on a great circle (theta = 90 deg).  ``v_top``
    is the centre of mass's speed at the top; ``mu`` the friction available
    and ``max_g`` the largest load allowed (status slips / over_g).

    Returns dict of arrays: ``r_g``, ``v_top_min``, ``v_bottom``,
    ``omega_top``, ``omega_bottom``, ``load_top``, ``load_bottom``,
    ``head_clearance`` (r - |head point| at the top), ``mu_required`` (the
    most round the loop), ``phi_worst`` [rad] (where, from the top; also at
    -phi_worst), ``status``, ``reason``.
    """
    m = machine
    theta, v_top, r, g, mu, max_g = (np.asarray(x, dtype=float) for x in (theta, v_top, ground.radius, g, mu, max_g))
    mass, h, a, t, ip, js, head = (m.mass, m.com_height, m.wheel_radius, m.tyre_radius, m.pitch_inertia,
                                   m.spin_inertia, m.head_height)
    st, ct = np.sin(theta), np.cos(theta)
    rho = r * st
    r_g = rho - h
    small = ~((rho > a) & (r_g > 0))
    off_plane = (t > 0) & (np.abs(ct) > SINGULAR)
    safe = np.where(small, 1.0, r_g)
    meff = mass * safe * safe + ip + js * (rho * rho - 2 * rho * a) / (a * a)
    om_t = v_top / safe
    om_b2 = om_t * om_t + 4 * mass * g * safe / meff
    with np.errstate(invalid="ignore"):
        v_min = np.sqrt(g * safe)
    hx = np.abs(rho - head)                       # the head point in the plane, distance from the loop's centre
    clearance = r - np.sqrt(hx * hx + (r * ct) ** 2)
    load_bottom = om_b2 * safe / g + 1.0
    # M24: N_in/m = D - B cos(phi) from M21, F_along/m = -c g sin(phi)
    q = mass * safe * safe / meff
    d = v_top * v_top / safe + 2 * q * g
    b = (1 + 2 * q) * g
    c = 1 - q
    touches = (d > b) & ~small
    d_s = np.where(touches, d, 2.0 * b)
    sin_s = np.where(touches & (st > 0), st, 1.0)
    mu_max = np.sqrt(ct * ct + (c * g) ** 2 / ((d_s - b) * (d_s + b))) / sin_s
    phi_worst = np.arccos(b / d_s)
    status, reason = first_failure([
        (small, Status.NO_FIT, Reason.LOOP_TOO_SMALL),
        (off_plane, Status.NO_ORBIT, Reason.LOOP_ROUND_TYRE_OFF_PLANE),
        (~(clearance > 0), Status.NO_FIT, Reason.HEAD_HITS),
        (v_top < v_min * (1 - 1e-12), Status.NO_CONTACT, Reason.LOOP_TOP_TOO_SLOW),
        (np.where(touches, mu_max, np.inf) > mu, Status.SLIPS, Reason.LOOP_SLIPS),   # diverges at M22's limit
        (load_bottom > max_g, Status.OVER_G, Reason.LOOP_OVER_G),
    ])
    bad = small | off_plane
    nan = np.nan
    no_mu = bad | ~touches
    out = {
        "r_g": np.where(small, nan, r_g),
        "v_top_min": np.where(bad, nan, v_min),
        "v_bottom": np.where(bad, nan, np.sqrt(om_b2) * safe),
        "omega_top": np.where(bad, nan, om_t),
        "omega_bottom": np.where(bad, nan, np.sqrt(om_b2)),
        "load_top": np.where(bad, nan, np.abs(om_t * om_t * safe - g) / g),
        "load_bottom": np.where(bad, nan, load_bottom),
        "head_clearance": clearance,
        "mu_required": np.where(no_mu, nan, mu_max),
        "phi_worst": np.where(no_mu, nan, phi_worst),
        "status": status,
        "reason": reason,
    }
    shape = status.shape
    return {k: (v if v.shape == shape else np.broadcast_to(v, shape)) for k, v in out.items()}
