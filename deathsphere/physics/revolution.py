"""Steady horizontal orbits of the paper's bodies on any surface of revolution.

Beyond the paper, which has one ground, the sphere; the derivation is in
docs/surfaces.md (eqs. S1-S9), built on McDonald (1993) sec. 2.2.2 (eqs.
13, 29-36), sec. 4 (eq. 55) and the particle of the introduction.

A lane is a parallel of the ground (``ground.contact(height)``: the
contact's distance rho from the axis and its z; the wall angle beta; the
inward normal n = (-sin beta, cos beta); the principal curvatures).  Every
force on these bodies acts at the contact, so a steady orbit sees the
surface only through that circle, its normal and, for the fit, its
curvatures:

* the wheel: eq. (29) holds unchanged with r' = rho - a cos(alpha) (S1);
  the contact force per unit mass g z-hat - Omega^2 r' rho-hat (eq. 32) is
  split along the wall's frame (S3); the rim fits where it bends more than
  the wall along the lane (S4) and stays above the floor (S5), the whole
  fit on the sphere, a drum and a cone, and on a profile is checked
  against the whole wall (S4g, :mod:`deathsphere.physics.rim_fit`);
* the ball: eq. (55) becomes k a omega3 Omega sin(beta) = (k+1) Omega^2
  r_C cos(beta) - g sin(beta) (S6), which is eq. (55) itself on the sphere
  tangent to the ground along the lane (centre on the axis, radius
  R_t = rho / sin(beta), polar angle pi - beta): the ball is solved there
  by :mod:`deathsphere.physics.sphere`, and the fit takes both principal
  curvatures (S7) and, on a profile, the whole wall (S7g);
* the particle: Omega^2 = g tan(beta) / rho (S8), the sphere's particle on
  the same tangent sphere.

Each function takes ``(ground, height, ..., body arrays, g, outside, mu)``
and returns the dict of arrays of its sphere counterpart
(:func:`deathsphere.physics.wheel.horizontal_orbit`,
:func:`deathsphere.physics.sphere.sphere_orbit`,
:func:`deathsphere.physics.particle.particle_orbit`) plus ``height``,
``rho_contact``, ``z_contact`` and ``wall_angle``.  On the flat
:class:`~deathsphere.physics.ground.Plane` the lane is the contact's turn
radius, not a height.  Vectorised; singular inputs give statuses, never a
NaN warning.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics import particle as _particle
from deathsphere.physics import rim_fit as _rim_fit
from deathsphere.physics import sphere as _sphere
from deathsphere.physics.geometry import SINGULAR
from deathsphere.physics.status import Reason, Status, first_failure, mu_required

__all__ = ["lane", "wheel_orbit", "ball_orbit", "ball_orbit_from_rate", "particle_orbit"]


def _highest(ground) -> float:
    # the plane has no wall: its lane (a turn radius) has no top
    return float(getattr(ground, "highest_lane", np.inf))


def lane(ground, height):
    """Where a lane is: a dict of arrays ``height`` (as given), ``off_wall``
    (the height outside [0, highest_lane]: no lane there; its geometry is
    that of the nearest lane, masked by the callers), ``rho``, ``z`` (the
    contact [m]), ``wall_angle`` beta, ``sin_beta``, ``cos_beta`` (from the
    ground's normal, exact on an upright wall), ``kappa_meridian``,
    ``kappa_parallel`` [1/m] (docs/surfaces.md, S0); ``at`` the height
    the geometry is of (clipped to the wall)."""
    height = np.asarray(height, dtype=float)
    top = _highest(ground)
    off = ~((height >= 0) & (height <= top))          # NaN is off the wall too
    safe = np.clip(np.where(np.isnan(height), 0.0, height), 0.0, top)
    rho, z = ground.contact(safe)
    n_rho, n_z = ground.normal(safe)
    k_mer, k_par = ground.curvatures(safe)
    return {"height": height, "off_wall": off, "at": safe, "rho": np.asarray(rho, dtype=float), "z": np.asarray(z, dtype=float),
            "wall_angle": np.asarray(ground.wall_angle(safe), dtype=float),
            "sin_beta": -np.asarray(n_rho, dtype=float), "cos_beta": np.asarray(n_z, dtype=float),
            "kappa_meridian": np.asarray(k_mer, dtype=float), "kappa_parallel": np.asarray(k_par, dtype=float)}


def _length_scale(where, a):
    """The lane's natural length: the tangent sphere's radius 1/kappa_parallel
    (the globe's r on the sphere), else the contact's distance from the axis
    (flat ground), at least a; for the thresholds of :data:`SINGULAR`."""
    k_par = where["kappa_parallel"]
    with np.errstate(divide="ignore"):
        length = np.where(k_par > 0, 1.0 / np.where(k_par > 0, k_par, 1.0), where["rho"])
    return np.maximum(length, a)


def _lane_columns(where, res, floats_off):
    """Append the lane's columns and blank every float of an off-wall row."""
    out = {}
    off = floats_off
    for key, value in res.items():
        value = np.asarray(value)
        if value.dtype.kind == "f" and np.any(off):
            value = np.where(np.broadcast_to(off, value.shape), np.nan, value)
        out[key] = value
    shape = np.shape(res["status"])
    for key, name in (("height", "height"), ("rho", "rho_contact"), ("z", "z_contact"),
                      ("wall_angle", "wall_angle")):
        value = np.broadcast_to(np.expand_dims(where[key], -1) if len(shape) > np.ndim(where[key]) else where[key],
                                shape)
        out[name] = np.where(np.broadcast_to(off, shape) & (key != "height"), np.nan, value)
    return out


def _pick(condition, if_true, if_false):
    return np.where(condition, np.int8(if_true), np.int8(if_false)).astype(np.int8)


def _global_check(ground, candidates):
    """No crossing yet on the lanes' shape, and a function putting an input
    on that shape as one row (a single lane is 0-d); None for it where no
    lane needs the global check (S4 or S7 is the whole fit on this ground,
    or no lane is a candidate)."""
    shape = np.shape(candidates)
    crosses = np.zeros(shape, dtype=bool)
    if ground.local_fit_is_global or not np.any(candidates):
        return crosses, None
    return crosses, lambda x: np.reshape(np.broadcast_to(x, shape), -1)


def _rim_crosses(ground, where, alpha, a, tilt, outside, candidates):
    """Where the rim, fitting by S4 near its contact, leaves the wall away
    from it (docs/surfaces.md eq. S4g): never where S4 is the whole fit (the
    sphere, the drum, the cone, flat ground); on a profile, the lanes whose
    rim neither the tangent ball (a <= r_P |sin(alpha + beta)|, less a
    margin) nor, inside, the tangent cone (the wall bending outwards over
    the rim's heights) holds are sampled (:func:`deathsphere.physics.rim_fit.rim_crosses_wall`)."""
    crosses, flat = _global_check(ground, candidates)
    if flat is None:
        return crosses
    reach = flat(ground.tangent_ball_radius(where["at"], outside))
    check = np.flatnonzero(flat(candidates))
    a, alpha, tilt, outside = flat(a), flat(alpha), flat(tilt), flat(outside)
    # (on the candidates only: elsewhere an infinite reach may meet tilt 0)
    held = a[check] <= (1.0 - _rim_fit.BALL_MARGIN) * reach[check] * np.abs(tilt[check])
    check = check[~held]
    # inside, a wall that bends outwards over the rim's heights holds what
    # its tangent cone holds, and the cone holds the rim by S4 (the proof)
    z, rise = flat(where["z"])[check], 2.0 * a[check] * np.sin(alpha[check])
    cone_holds = ~outside[check] & ground.bends_out(z + np.minimum(rise, 0.0), z + np.maximum(rise, 0.0))
    check = check[~cone_holds]
    if check.size:
        out = crosses.reshape(-1)
        out[check] = _rim_fit.rim_crosses_wall(ground, flat(where["rho"])[check], flat(where["z"])[check],
                                               alpha[check], a[check], outside[check])
        crosses = out.reshape(crosses.shape)
    return crosses


def wheel_orbit(ground, height, alpha, a, k, g, outside=False, mu=np.inf):
    """Every quantity of a wheel's steady horizontal orbit on ``ground``,
    vectorised (docs/surfaces.md S1-S5 and S4g, the rim's fit away from its
    contact, beyond the paper; McDonald 1993 eqs. 13, 29-36 with the surface
    entering only through S3-S5).

    height : [m] the contact's height above the ground's lowest point (the
        turn radius on flat ground); alpha : [rad] the tilt of the wheel's
        diameter through the contact below the orbit plane (as on the
        sphere); a [m], k [-] (I11 = 2 k m a^2), g [m/s^2]; outside: the
        wheel on the convex side; mu: the friction coefficient available.

    Returns the keys of :func:`deathsphere.physics.wheel.horizontal_orbit`
    (``friction`` positive down the wall, ``normal`` pressing wheel and
    wall together) plus the lane's ``height``, ``rho_contact``,
    ``z_contact``, ``wall_angle``.
    """
    alpha, a, k, g, mu = (np.asarray(x, dtype=float) for x in (alpha, a, k, g, mu))
    outside = np.asarray(outside, dtype=bool)
    height = np.asarray(height, dtype=float)
    shape = np.broadcast_shapes(height.shape, alpha.shape, a.shape, k.shape, g.shape, mu.shape, outside.shape)
    height, alpha, a, k, g, mu, outside = (np.broadcast_to(x, shape) for x in (height, alpha, a, k, g, mu, outside))
    where = lane(ground, height)
    s_b, c_b = where["sin_beta"], where["cos_beta"]
    sin_a, cos_a = np.sin(alpha), np.cos(alpha)
    rp = where["rho"] - a * cos_a                                            # S1 (eq. 8b)
    tilt = sin_a * c_b + cos_a * s_b                                         # sin(alpha + beta)
    fits = np.where(outside, tilt < 0, a * where["kappa_parallel"] < tilt)   # S4 (eq. 0 / 81)
    # S5: the rim's lowest point, a |sin(alpha)| below the centre, above the floor
    lowest = where["z"] + a * sin_a - a * np.abs(sin_a)
    length = _length_scale(where, a)
    floor_hit = ~outside & (lowest < ground.lowest - SINGULAR * length)
    crosses = _rim_crosses(ground, where, alpha, a, tilt, outside, ~where["off_wall"] & fits & ~floor_hit)
    den = sin_a * ((2 * k + 1) * rp + k * a * cos_a)                         # eq. (29)
    undefined = np.abs(den) <= SINGULAR * ((2 * k + 1) * length + (k + 1) * a)
    om2 = np.where(undefined, np.nan, g * cos_a / np.where(undefined, 1.0, den))
    om2_zero = np.abs(om2) <= SINGULAR * g / length
    real = (om2 > 0) & ~om2_zero
    om2_real = np.where(real, om2, np.nan)
    omega = np.sqrt(np.where(real, om2, 1.0))
    omega = np.where(real, omega, np.nan)
    period = np.where(real, 2 * np.pi / np.where(real, omega, 1.0), np.nan)
    centripetal = rp * om2_real
    normal_in = centripetal * s_b + g * c_b                                  # S3: F . n
    normal = np.where(outside, -normal_in, normal_in)
    friction = centripetal * c_b - g * s_b                                   # S3: -F . t, down the wall
    mu_req = mu_required(normal, friction)                                   # eq. (35)
    status, reason = first_failure([
        (where["off_wall"], Status.NO_FIT, Reason.LANE_OFF_WALL),
        (~fits, Status.NO_FIT, _pick(outside, Reason.SURFACE_NO_FIT_OUTSIDE, Reason.SURFACE_NO_FIT)),
        (floor_hit, Status.NO_FIT, Reason.BELOW_FLOOR),
        (crosses, Status.NO_FIT, Reason.RIM_CROSSES_WALL),
        (undefined, Status.NO_ORBIT, _pick(np.abs(sin_a) <= SINGULAR, Reason.ALPHA_IN_ORBIT_PLANE,
                                           Reason.ZERO_DENOMINATOR)),
        (om2_zero, Status.NO_ORBIT, Reason.OMEGA_ZERO),
        (~real, Status.NO_ORBIT, Reason.OMEGA_IMAGINARY),
        (~(normal > 0), Status.NO_CONTACT, _pick(outside, Reason.SURFACE_NO_CONTACT_OUTSIDE,
                                                 Reason.SURFACE_NO_CONTACT)),
        (mu_req > mu, Status.SLIPS, Reason.SLIPS),
    ])
    accel = np.abs(rp) * om2_real                                            # eq. (36) times g
    res = {
        "r_prime": rp, "omega2": om2, "omega": omega, "period": period,
        "v_cm": np.abs(rp) * omega,
        "spin": rp * omega / a,                                              # eq. (13)
        "omega3": -omega * sin_a,
        "accel": accel, "accel_g": accel / g,
        "load_g": np.sqrt(accel * accel + g * g) / g,
        "normal": normal, "friction": friction, "mu_required": mu_req,
        "status": status, "reason": reason,
    }
    return _lane_columns(where, res, where["off_wall"])


def _tangent_sphere(where):
    """The sphere tangent to the ground along the lane: polar angle
    theta_t = pi - beta, radius R_t = rho / sin(beta) (docs/surfaces.md S6);
    and the mask of flat lanes (sin(beta) = 0), where it is a plane."""
    s_b, c_b = where["sin_beta"], where["cos_beta"]
    flat = np.abs(s_b) <= SINGULAR
    theta_t = np.arctan2(s_b, -c_b)
    radius_t = np.where(flat, 1.0, where["rho"] / np.where(flat, 1.0, s_b))
    return theta_t, radius_t, flat


_BALL_REASONS = {Reason.SPHERE_NO_FIT: Reason.BALL_NO_FIT_MERIDIAN,
                 Reason.SPHERE_NO_CONTACT_INSIDE: Reason.SURFACE_NO_CONTACT,
                 Reason.SPHERE_NO_CONTACT_OUTSIDE: Reason.SURFACE_NO_CONTACT_OUTSIDE}
_PARTICLE_REASONS = {Reason.PARTICLE_ABOVE_EQUATOR: Reason.PARTICLE_STEEP_WALL,
                     Reason.PARTICLE_OUTSIDE_BELOW_EQUATOR: Reason.SURFACE_NO_CONTACT_OUTSIDE}


def _renamed(reason, names):
    """The sphere's reason codes in the words of a general surface."""
    out = np.asarray(reason, dtype=np.int8).copy()
    for old, new in names.items():
        out[reason == old] = new
    return out


def _ball_failures(where, a, outside):
    """The ball's fit on the ground (S7, beyond the tangent sphere's a < R_t)
    and its floor (S5): masks of lanes it cannot ride."""
    k_mer, k_par = where["kappa_meridian"], where["kappa_parallel"]
    bend_in = ((k_mer > 0) & (a * k_mer >= 1)) | ((k_par > 0) & (a * k_par >= 1))
    bend_out = ((k_mer < 0) & (-a * k_mer >= 1)) | ((k_par < 0) & (-a * k_par >= 1))
    no_fit = np.where(outside, bend_out, bend_in)
    return no_fit


def _ball_crosses(ground, where, a, outside, candidates):
    """Where the ball, fitting by S7 at its contact, reaches the wall away
    from it (docs/surfaces.md eq. S7g): never where S7 is the whole fit; on
    a profile, the lanes the tangent ball r_P (less a margin) does not hold
    are decided by the centre's distance from the meridian and its mirror
    (:func:`deathsphere.physics.rim_fit.ball_crosses_wall`)."""
    crosses, flat = _global_check(ground, candidates)
    if flat is None:
        return crosses
    reach = flat(ground.tangent_ball_radius(where["at"], outside))
    a, outside = flat(a), flat(outside)
    check = np.flatnonzero(flat(candidates) & ~(a <= (1.0 - _rim_fit.BALL_MARGIN) * reach))
    if check.size:
        out = crosses.reshape(-1)
        out[check] = _rim_fit.ball_crosses_wall(ground, flat(where["rho"])[check], flat(where["z"])[check],
                                                flat(where["sin_beta"])[check], flat(where["cos_beta"])[check],
                                                a[check], outside[check])
        crosses = out.reshape(crosses.shape)
    return crosses


def _ball(ground, height, second, a, k, g, outside, mu, branch, solve):
    a, k, g, mu = (np.asarray(x, dtype=float) for x in (a, k, g, mu))
    outside = np.asarray(outside, dtype=bool)
    height, second = np.asarray(height, dtype=float), np.asarray(second, dtype=float)
    shape = np.broadcast_shapes(height.shape, second.shape, a.shape, k.shape, g.shape, mu.shape, outside.shape)
    height, second, a, k, g, mu, outside = (np.broadcast_to(x, shape)
                                            for x in (height, second, a, k, g, mu, outside))
    where = lane(ground, height)
    theta_t, radius_t, flat = _tangent_sphere(where)
    no_fit = _ball_failures(where, a, outside)
    # S5: inside, the centre sits a along the normal: its lowest point a below it
    length = _length_scale(where, a)
    floor_hit = ~outside & (where["z"] + a * where["cos_beta"] - a < ground.lowest - SINGULAR * length)
    crosses = _ball_crosses(ground, where, a, outside, ~where["off_wall"] & ~flat & ~no_fit & ~floor_hit)
    res = solve(theta_t, second, a, radius_t, k, g, outside, mu, branch)
    extra = [where["off_wall"], flat, no_fit, floor_hit, crosses]
    if np.ndim(res["status"]) > len(shape):          # both branches on a new last axis
        extra = [np.expand_dims(m, -1) for m in extra]
    off, flat, no_fit, floor_hit, crosses = (np.broadcast_to(m, np.shape(res["status"])) for m in extra)
    status, reason = first_failure([
        (off, Status.NO_FIT, Reason.LANE_OFF_WALL),
        (flat, Status.NO_ORBIT, Reason.BALL_FLAT_GROUND),
        (no_fit, Status.NO_FIT, Reason.BALL_NO_FIT_MERIDIAN),
        (floor_hit, Status.NO_FIT, Reason.BELOW_FLOOR),
        (crosses, Status.NO_FIT, Reason.BALL_CROSSES_WALL),
        (res["status"] != Status.OK, res["status"], _renamed(res["reason"], _BALL_REASONS)),
    ])
    res = dict(res, status=status, reason=reason)
    res["alpha"] = np.where(flat, np.nan, res["alpha"])
    return _lane_columns(where, res, off | flat)


def ball_orbit(ground, height, omega3, a, k=_sphere.K_SOLID_BALL, g=_sphere.STANDARD_GRAVITY, outside=False,
               mu=np.inf, branch=None):
    """A rolling ball's horizontal orbits on ``ground`` for a given spin
    omega3 about the axis from its centre to the contact (docs/surfaces.md
    S6, S7; on the sphere McDonald 1993 eqs. 55-59): the keys of
    :func:`deathsphere.physics.sphere.sphere_orbit` (``branch`` None: both
    roots on a new last axis) plus the lane's columns; ``r_prime`` is the
    centre's distance from the axis r_C, ``rho`` the tangent sphere's
    centre distance R_t -/+ a."""
    def solve(theta_t, omega3, a, radius_t, k, g, outside, mu, branch):
        return _sphere.sphere_orbit(theta_t, omega3, a, radius_t, k, g, outside, mu, branch)
    return _ball(ground, height, omega3, a, k, g, outside, mu, branch, solve)


def ball_orbit_from_rate(ground, height, omega, a, k=_sphere.K_SOLID_BALL, g=_sphere.STANDARD_GRAVITY,
                         outside=False, mu=np.inf):
    """:func:`ball_orbit` for a given signed orbital rate Omega (omega3
    from S6; on the sphere eq. 55 solved for omega3)."""
    def solve(theta_t, omega, a, radius_t, k, g, outside, mu, branch):
        return _sphere.sphere_orbit_from_rate(theta_t, omega, a, radius_t, k, g, outside, mu)
    return _ball(ground, height, omega, a, k, g, outside, mu, None, solve)


def particle_orbit(ground, height, g, outside=False, mu=np.inf):
    """A frictionless particle's horizontal orbit on ``ground``: Omega^2 =
    g tan(beta) / rho, N/m = g / cos(beta) (docs/surfaces.md S8; on the
    sphere the particle of :func:`deathsphere.physics.particle.particle_orbit`,
    whose keys it returns, plus the lane's columns)."""
    g, mu = np.asarray(g, dtype=float), np.asarray(mu, dtype=float)
    outside = np.asarray(outside, dtype=bool)
    height = np.asarray(height, dtype=float)
    shape = np.broadcast_shapes(height.shape, g.shape, mu.shape, outside.shape)
    height, g, mu, outside = (np.broadcast_to(x, shape) for x in (height, g, mu, outside))
    where = lane(ground, height)
    theta_t, radius_t, flat = _tangent_sphere(where)
    res = _particle.particle_orbit(theta_t, radius_t, g, outside, mu)
    status, reason = first_failure([
        (where["off_wall"], Status.NO_FIT, Reason.LANE_OFF_WALL),
        (flat, Status.NO_ORBIT, Reason.PARTICLE_FLAT_GROUND),
        (res["status"] != Status.OK, res["status"], _renamed(res["reason"], _PARTICLE_REASONS)),
    ])
    res = dict(res, status=status, reason=reason)
    res["r_prime"] = np.where(flat, where["rho"], res["r_prime"])
    return _lane_columns(where, res, where["off_wall"])
