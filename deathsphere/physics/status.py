"""Status and reason codes shared by every configuration.

A status names the *first* condition an orbit fails, in the order of the
contract (docs/contract.md): fit, real rotation rate, contact, friction,
load (``over_g``, applied by the model to an orbit that is otherwise ok).  Each status
carries a reason code whose words live in :data:`REASONS`; physics functions
return small integer arrays, and only the model turns them into text.
"""

from enum import IntEnum

import numpy as np


class Status(IntEnum):
    OK = 0
    NO_FIT = 1
    NO_ORBIT = 2
    NO_CONTACT = 3
    SLIPS = 4
    INVALID = 5
    OVER_G = 6

    @property
    def label(self) -> str:
        return self.name.lower()


STATUS_LABELS = np.array([s.label for s in Status], dtype=object)


class Reason(IntEnum):
    NONE = 0
    NO_FIT_INSIDE = 1
    NO_FIT_OUTSIDE = 2
    ALPHA_IN_ORBIT_PLANE = 3
    ZERO_DENOMINATOR = 4
    OMEGA_ZERO = 5
    OMEGA_IMAGINARY = 6
    NO_CONTACT_INSIDE = 7
    NO_CONTACT_OUTSIDE = 8
    SLIPS = 9
    POLE = 10
    SPIN_TOO_SMALL = 11
    PARTICLE_ABOVE_EQUATOR = 12
    NO_FIT_VERTICAL = 13
    SPHERE_NO_FIT = 14
    ZERO_RATE_EQUATOR = 15
    VERTICAL_TOP_TOO_SLOW = 16
    VERTICAL_OUTSIDE_LEAVES = 17
    SPHERE_NO_CONTACT_INSIDE = 18
    SPHERE_NO_CONTACT_OUTSIDE = 19
    EQUATOR_SINGLE_ROOT = 20
    SPHERE_OMEGA_ZERO = 21
    SPHERE_K_ZERO = 22
    PARTICLE_OUTSIDE_BELOW_EQUATOR = 23
    NO_ALPHA_FOR_RATE = 24
    OVER_G = 25
    MACHINE_NO_FIT = 26
    HEAD_HITS = 27
    MACHINE_ZERO_DENOMINATOR = 28
    MACHINE_OMEGA_ZERO = 29
    MACHINE_OMEGA_IMAGINARY = 30
    MACHINE_NO_CONTACT = 31
    MACHINE_OVER_G = 32
    MACHINE_NO_ALPHA = 33
    LOOP_TOO_SMALL = 34
    LOOP_ROUND_TYRE_OFF_PLANE = 35
    LOOP_TOP_TOO_SLOW = 36
    LOOP_SLIPS = 37
    LOOP_OVER_G = 38
    TURN_BAD_LANE = 39
    TURN_BAD_SPEED = 40
    TURN_BAD_TORQUE = 41
    TURN_NONE = 42
    TURN_HEAD_HITS = 43
    TURN_WHEEL_LIFTS = 44
    TURN_SLIPS_REAR = 45
    TURN_SLIPS_FRONT = 46
    TURN_SLIPS_BOTH = 47
    TURN_OVER_G = 48
    MACHINE_NO_FIT_WALL = 49
    MACHINE_NO_CONTACT_WALL = 50
    HEAD_HITS_WALL = 51
    MACHINE_HITS_FLOOR = 52
    CONTACT_ON_AXIS = 53
    LANE_OFF_WALL = 54
    SURFACE_NO_FIT = 55
    SURFACE_NO_CONTACT = 56
    BELOW_FLOOR = 57
    BALL_FLAT_GROUND = 58
    BALL_NO_FIT_MERIDIAN = 59
    PARTICLE_STEEP_WALL = 60
    PARTICLE_FLAT_GROUND = 61
    SURFACE_NO_CONTACT_OUTSIDE = 62
    SURFACE_NO_FIT_OUTSIDE = 63
    LANE_ON_AXIS = 64
    NO_TILT_FITS_LANE = 65
    SURFACE_NO_ALPHA = 66
    VERTICAL_LOOP_NO_FIT = 67
    VERTICAL_LOOP_TOO_SLOW = 68
    VERTICAL_LOOP_OVERHANG = 69
    VERTICAL_LOOP_TOO_FAST = 70
    MACHINE_LOOP_NO_FIT = 71
    MACHINE_LOOP_HEAD_HITS = 72
    MACHINE_LOOP_TOO_SLOW = 73
    MACHINE_LOOP_OVERHANG = 74
    MACHINE_LOOP_TOO_FAST = 75
    MACHINE_LOOP_SLIPS = 76
    MACHINE_LOOP_OVER_G = 77
    RIM_CROSSES_WALL = 78
    BALL_CROSSES_WALL = 79


REASONS = {
    Reason.NONE: "",
    Reason.NO_FIT_INSIDE: "does not fit inside the sphere at this tilt (eq. 0 needs sin(theta - alpha) > a/r)",
    Reason.NO_FIT_OUTSIDE: "would cut into the sphere at this tilt (eq. 81 needs theta < alpha < theta + 180 deg)",
    Reason.ALPHA_IN_ORBIT_PLANE: "alpha = 0 or 180 deg: wheel in the orbit plane; eq. 29 diverges so there is no steady horizontal orbit",
    Reason.ZERO_DENOMINATOR: "the denominator of eq. 29 ((2k+1) r' + k a cos(alpha)) vanishes",
    Reason.OMEGA_ZERO: "Omega^2 = 0 (eq. 29 at alpha = 90 deg): the wheel stands at rest; not an orbit",
    Reason.OMEGA_IMAGINARY: "Omega^2 < 0 (eq. 29): no real rotation rate",
    Reason.NO_CONTACT_INSIDE: "contact force pulls away from the wall (eq. 33 needs r' Omega^2 sin(theta) > g cos(theta))",
    Reason.NO_CONTACT_OUTSIDE: "contact force pulls into the sphere (eq. 83 needs r' Omega^2 sin(theta) < g cos(theta))",
    Reason.SLIPS: "mu_required exceeds the friction coefficient given (mu_available)",
    Reason.POLE: "contact point at a pole: the orbit has zero radius",
    Reason.SPIN_TOO_SMALL: "|omega_3| below the minimum for a real orbit (eq. 56)",
    Reason.PARTICLE_ABOVE_EQUATOR: "a frictionless particle has no horizontal orbit at or above the equator",
    Reason.NO_FIT_VERTICAL: "wheel does not fit on this circle (needs r sin(theta) > a)",
    Reason.SPHERE_NO_FIT: "rolling sphere does not fit inside (needs a < r)",
    Reason.ZERO_RATE_EQUATOR: "on the equator eq. 55 needs k omega_3 != 0 (a spin and rotational inertia)",
    Reason.VERTICAL_TOP_TOO_SLOW: "top rate too low: the wheel leaves the wall at the top of the vertical orbit (eq. 28a needs r' phidot0^2 > g)",
    Reason.VERTICAL_OUTSIDE_LEAVES: "outside the sphere a vertical orbit cannot close: the wheel leaves the surface at phi_leave (eq. 82)",
    Reason.SPHERE_NO_CONTACT_INSIDE: "contact force pulls away from the wall (eq. 58 needs (r-a) Omega^2 sin^2(theta) > g cos(theta))",
    Reason.SPHERE_NO_CONTACT_OUTSIDE: "contact force pulls into the sphere (eq. 59 needs (r+a) Omega^2 sin^2(theta) < g cos(theta))",
    Reason.EQUATOR_SINGLE_ROOT: "on the equator eq. 55 is linear in Omega: only one orbit (branch 0)",
    Reason.SPHERE_OMEGA_ZERO: "Omega = 0 cannot satisfy eq. 55 (it would need g = 0)",
    Reason.SPHERE_K_ZERO: "k = 0: omega_3 drops out of eq. 55 and cannot be found from Omega",
    Reason.PARTICLE_OUTSIDE_BELOW_EQUATOR: "outside the sphere below the equator the normal force would have to pull (N/m = g/cos(theta) < 0)",
    Reason.NO_ALPHA_FOR_RATE: "no tilt alpha in the fit range gives this speed or rate (eq. 29 has no root)",
    Reason.OVER_G: "the load load_g (|contact force| / (m g): what the rider feels) exceeds the largest given (max_g)",
    Reason.MACHINE_NO_FIT: "the wheel does not fit inside the sphere at this tilt (machine.md eq. M10 needs sin(theta - alpha) > (a - t)/(r - t))",
    Reason.HEAD_HITS: "the rider's head reaches the globe at this tilt (head_clearance_m <= 0)",
    Reason.MACHINE_ZERO_DENOMINATOR: "the denominator of machine.md eq. M8 vanishes: no steady orbit at this tilt",
    Reason.MACHINE_OMEGA_ZERO: "Omega^2 = 0 (machine.md eq. M8): the centre of mass is straight above the contact; the machine balances at rest",
    Reason.MACHINE_OMEGA_IMAGINARY: "Omega^2 < 0 (machine.md eq. M8): no real rotation rate at this tilt",
    Reason.MACHINE_NO_CONTACT: "contact force pulls away from the wall (machine.md eq. M9 needs r_G Omega^2 sin(theta) > g cos(theta))",
    Reason.MACHINE_OVER_G: "the load load_g (machine.md eq. M11) exceeds the largest given (max_g)",
    Reason.MACHINE_NO_ALPHA: "no tilt alpha at which the wheel fits gives this speed (machine.md eq. M12 has no root)",
    Reason.LOOP_TOO_SMALL: "the loop is too small for the machine (machine.md sec. 10 needs r sin(theta) > a and > h)",
    Reason.LOOP_ROUND_TYRE_OFF_PLANE: "a round tyre off a great circle touches the sphere t cos(theta) out of the loop's plane: the machine cannot stay in the plane (it must lean and steer; machine.md sec. 10)",
    Reason.LOOP_TOP_TOO_SLOW: "the machine leaves the wall at the top of the loop (machine.md eq. M22 needs v_top^2 >= g r_G)",
    Reason.LOOP_SLIPS: "somewhere round the loop rolling needs more friction than given: mu_required (the most round the loop; machine.md eq. M24) exceeds mu_available",
    Reason.LOOP_OVER_G: "the load at the bottom of the loop load_bottom_g (the most round it; machine.md eq. M23) exceeds the largest given (max_g)",
    # the two-wheeler's steady turns (docs/two-wheeler.md sec. 8)
    Reason.TURN_BAD_LANE: "theta must be finite and strictly between 0 and 180 degrees (the poles have no lap); "
                          "on flat ground the curvature must be finite",
    Reason.TURN_BAD_SPEED: "the speed must be finite and positive",
    Reason.TURN_BAD_TORQUE: "the steer torque must be finite",
    Reason.TURN_NONE: "no steady turn at this lane and speed or torque",
    Reason.TURN_HEAD_HITS: "the rider's head reaches the globe on this turn (head_clearance_m <= 0)",
    Reason.TURN_WHEEL_LIFTS: "a wheel would lift: its normal force does not push",
    Reason.TURN_SLIPS_REAR: "the rear wheel needs more friction than mu_available (mu_required_rear exceeds it)",
    Reason.TURN_SLIPS_FRONT: "the front wheel needs more friction than mu_available (mu_required_front exceeds it)",
    Reason.TURN_SLIPS_BOTH: "both wheels need more friction than mu_available (mu_required_rear and mu_required_front "
                            "exceed it)",
    Reason.TURN_OVER_G: "the load load_g (|total contact force| / weight) exceeds the largest given (max_g)",
    Reason.MACHINE_NO_FIT_WALL: "the wheel does not fit against the wall at this tilt (machine.md eq. MS6 needs sin(alpha + beta) (1 - t kappa) > (a - t) kappa)",
    Reason.MACHINE_NO_CONTACT_WALL: "contact force pulls away from the wall (machine.md eq. MS5 needs r_G Omega^2 sin(beta) + g cos(beta) > 0)",
    Reason.HEAD_HITS_WALL: "the rider's head reaches the wall at this tilt (head_clearance_m <= 0)",
    Reason.MACHINE_HITS_FLOOR: "the tyre or the rider's head reaches the floor at this tilt (machine.md eq. MS7)",
    Reason.CONTACT_ON_AXIS: "the contact is on the vertical axis (theta 0 or 180 deg): it does not move on any "
                            "orbit so no contact speed holds one (give com_speed or alpha)",
    # any surface of revolution (docs/surfaces.md)
    Reason.LANE_OFF_WALL: "the lane's height is outside the wall: below the floor (height < 0) or above the "
                          "wall's top (height > its highest lane)",
    Reason.SURFACE_NO_FIT: "the wheel's rim does not bend more than the wall along the lane at this tilt "
                           "(surfaces.md eq. S4 needs a kappa_parallel < sin(alpha + beta))",
    Reason.SURFACE_NO_CONTACT: "contact force pulls away from the wall (surfaces.md eq. S3 needs "
                               "r' Omega^2 sin(beta) + g cos(beta) > 0)",
    Reason.BELOW_FLOOR: "the body reaches below the floor at this lane and tilt (surfaces.md eq. S5)",
    Reason.BALL_FLAT_GROUND: "a rolling ball has no steady turn on flat ground (surfaces.md eq. S6 at beta = 0 "
                             "needs Omega^2 r_C = 0)",
    Reason.BALL_NO_FIT_MERIDIAN: "the ball does not fit the wall's bend: needs a < 1/kappa for both principal "
                                 "curvatures (surfaces.md eq. S7)",
    Reason.PARTICLE_STEEP_WALL: "a frictionless particle needs a wall angle under 90 deg (surfaces.md eq. S8: "
                                "Omega^2 = g tan(beta) / rho)",
    Reason.PARTICLE_FLAT_GROUND: "on flat ground a frictionless particle cannot turn (surfaces.md eq. S8 gives "
                                 "Omega = 0)",
    Reason.SURFACE_NO_CONTACT_OUTSIDE: "contact force pulls into the wall (surfaces.md eq. S3 outside needs "
                                       "r' Omega^2 sin(beta) + g cos(beta) < 0)",
    Reason.SURFACE_NO_FIT_OUTSIDE: "would cut into the wall at this tilt (surfaces.md eq. S4 outside needs "
                                   "sin(alpha + beta) < 0)",
    Reason.LANE_ON_AXIS: "the lane's contact is on the vertical axis (rho_contact = 0): it does not move on any "
                         "orbit so no contact speed holds one (give com_speed or omega or alpha)",
    Reason.NO_TILT_FITS_LANE: "the wheel fits along this lane at no tilt (surfaces.md eq. S4 needs "
                              "a kappa_parallel < 1: the wall bends more than the rim)",
    Reason.SURFACE_NO_ALPHA: "no tilt alpha at which the wheel fits the wall gives this speed or rate "
                             "(surfaces.md eq. S2 has no root in the window of eq. S4)",
    Reason.RIM_CROSSES_WALL: "the wheel's rim crosses the wall away from its contact (surfaces.md eq. S4g: "
                             "it fits by eq. S4 only near the contact)",
    Reason.BALL_CROSSES_WALL: "the ball reaches the wall away from its contact (surfaces.md eq. S7g: it fits "
                              "the wall's bend at the contact only)",
    # a vertical loop inside a closed profile (docs/surfaces.md eqs. S9-S12)
    Reason.VERTICAL_LOOP_NO_FIT: "the wheel does not fit the loop's tightest bend (needs a below the meridian's "
                                 "least radius of curvature: a kappa_max < 1)",
    Reason.VERTICAL_LOOP_TOO_SLOW: "top speed too low: the wheel leaves the wall somewhere round the loop "
                                   "(surfaces.md eq. S10 needs N = v^2 kappa_C + g cos(beta) > 0 all round)",
    Reason.VERTICAL_LOOP_OVERHANG: "no top speed holds the wheel round the loop: the wall overhangs (cos(beta) < 0) "
                                   "where it does not bend towards the centre (kappa <= 0; surfaces.md eq. S10)",
    Reason.VERTICAL_LOOP_TOO_FAST: "too fast where the wall bends away from the centre: the wheel leaves it there "
                                   "(surfaces.md eq. S10 needs N = v^2 kappa_C + g cos(beta) > 0 with kappa_C < 0)",
    # a machine's vertical loop inside a closed profile (docs/machine.md eqs. M25-M30)
    Reason.MACHINE_LOOP_NO_FIT: "the machine does not fit the loop's tightest bend (machine.md eq. M25 needs a "
                                "kappa_max < 1 and h kappa_max < 1 and eq. M26 a positive effective inertia)",
    Reason.MACHINE_LOOP_HEAD_HITS: "the rider's head reaches the wall somewhere round the loop (head_clearance_m "
                                   "<= 0: the least round it; machine.md eq. M30)",
    Reason.MACHINE_LOOP_TOO_SLOW: "top speed too low: the machine leaves the wall somewhere round the loop "
                                  "(machine.md eq. M29 needs the normal force of eq. M28 > 0 all round)",
    Reason.MACHINE_LOOP_OVERHANG: "no top speed holds the machine round the loop: the wall overhangs where it "
                                  "does not bend towards the centre (machine.md eq. M29)",
    Reason.MACHINE_LOOP_TOO_FAST: "too fast where the wall bends away from the centre: the machine leaves it there "
                                  "(machine.md eq. M29)",
    Reason.MACHINE_LOOP_SLIPS: "somewhere round the loop rolling needs more friction than given: mu_required "
                               "(the most round the loop; machine.md eq. M30) exceeds mu_available",
    Reason.MACHINE_LOOP_OVER_G: "the largest load round the loop load_max_g (machine.md eq. M30) exceeds the "
                                "largest given (max_g)",
}

# Reasons never contain a comma, so CSV output stays splittable with awk -F,.
REASON_TEXT = np.array([REASONS[Reason(i)] for i in range(len(Reason))], dtype=object)


def mu_required(normal, friction):
    """Least static friction coefficient that holds the contact, eq. (35):
    |friction| / normal, NaN where the normal force is not positive.

    Every body takes its mu_required from here, and decides ``no_contact``
    on the same test (normal > 0 fails), so that a no_contact row never
    carries a friction coefficient: friction cannot hold a contact that
    would have to pull (docs/contract.md, "Statuses")."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.abs(friction) / np.where(normal > 0, normal, np.nan)


def first_failure(conditions):
    """Status and reason of the first failing condition, vectorised.

    ``conditions`` is an ordered list of ``(failed_mask, status, reason_array)``;
    later entries only apply where no earlier one failed.  Returns integer
    arrays ``(status, reason)`` broadcast to the common shape.
    """
    # Each row is decided by at most one condition, so its codes are those of
    # that condition added to OK = NONE = 0: sums of 0/1 bytes times the code,
    # no masked writes (status[hit] = ...), which on an irregular mask cost
    # ~5 ns per element in mispredicted branches.
    shape = np.broadcast_shapes(*(np.shape(c[0]) for c in conditions))
    status = np.zeros(shape, dtype=np.int8)
    reason = np.zeros(shape, dtype=np.int8)
    undecided = np.ones(shape, dtype=bool)
    hit = np.empty(shape, dtype=bool)
    for failed, st, why in conditions:
        np.logical_and(undecided, failed, out=hit)
        np.not_equal(undecided, hit, out=undecided)      # hit is a subset of undecided
        once = hit.view(np.int8)                         # 1 where this condition decides
        status += once * np.int8(st)
        reason += once * np.asarray(why, dtype=np.int8)
    return status, reason
