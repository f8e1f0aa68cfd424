"""Each rider's lane (beyond the paper; docs/show.md, "Lanes"): where his
contact, head and centre of mass are at any time.

A horizontal lane is ``ride``'s steady orbit (docs/machine.md eqs. M1-M12r)
at the plan's height, held as the plan holds it: by the contact's speed
(the rate Omega = v / (r sin theta)), the lap time (Omega = 2 pi / T), the
lap of another rider (his lap time), or the centre of mass's speed (eq.
M12): the contact at r (sin theta
cos phi, sin theta sin phi, cos theta), phi = phase +- Omega t, the machine's
up-axis u = -cos(alpha) rho-hat + sin(alpha) z-hat in the contact's meridian
plane, the centre of mass G = Q + (h - t) u and the head H = Q + (head - t) u
with Q = (r - t) n-hat (eq. M2).  Of the tilts giving the speed or rate
the lane takes the one closest to upright on the wall (alpha = theta - 90
deg, the up-axis along the inward normal) among those with status ok, or,
when none is ok, among all (the table then reports the status).

A vertical lane is ``ride --vertical``'s loop on a great circle (sec. 10):
the contact at r (sin psi e + cos psi z-hat), e = (cos azimuth, sin azimuth,
0), G = (r - h) n-hat, H = (r - head) n-hat, with psi(t) from the energy
M21.  With psidot_t and psidot_b the rates at top and bottom (M23) M21 reads
psidot^2 = psidot_b^2 (1 - m cos^2(psi/2)), m = 1 - psidot_t^2/psidot_b^2,
so with beta = (pi - psi)/2 and u = K(m) - psidot_b t/2 (t from the top):
beta = am(u | m), psidot = psidot_b dn(u | m), the lap 4 K(m)/psidot_b
(Jacobi's elliptic functions: exact, no step)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from deathsphere.act.plan import Plan, Rider
from deathsphere.errors import ParameterError
from deathsphere.physics.machine import meridian_points, vertical_loop
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.physics.machine_lanes import (contact_rate, contact_rate_on, horizontal_lanes,
                                               horizontal_lanes_at_rate, horizontal_lanes_at_rate_on,
                                               horizontal_lanes_on)
from deathsphere.physics.machine_surface import meridian_points_on
from deathsphere.requests.arena import is_globe
from deathsphere.physics.status import REASON_TEXT, STATUS_LABELS, Status
from deathsphere.records.machine import Machine
from deathsphere.records.two_wheeler import TwoWheeler

#: Statuses with which a vertical lane is not ridden at all (the plan is refused).
LOOP_REFUSED = (Status.NO_FIT, Status.NO_ORBIT, Status.NO_CONTACT)
_Z = np.array([0.0, 0.0, 1.0])[:, None]
#: A vertical lane's plane holds the globe's centre: its cone angle is 90 deg.
GREAT_CIRCLE = math.radians(90.0)


@dataclass
class Lane:
    """One rider's lane.  ``kind`` 'horizontal' or 'vertical'; ``orbit``
    the physics' quantities of the orbit it rides (scalars: a horizontal
    lane's :func:`~deathsphere.physics.machine.ride_orbit` keys, a vertical
    one's :func:`~deathsphere.physics.machine.vertical_loop` keys, int
    ``status`` and ``reason`` codes); ``period_s`` its lap [s]; ``rate``
    Omega [rad/s] signed (+ ccw) or psidot at the top; ``phase`` [rad] phi
    or psi at t = 0; ``points`` where its contact, centre of mass and head
    are in the lane's own plane: (rho, z) [m] in the contact's meridian plane
    (horizontal, eq. M2) or their distances [m] from the globe's centre
    along the contact's radius (vertical); ``reach`` the greatest distance of
    those points from the centre [m] (how far a point moves per radian)."""

    name: str
    kind: str
    machine: Machine
    width_m: float
    period_s: float
    phase: float
    orbit: dict = field(repr=False)
    points: dict = field(repr=False)
    reach: float
    theta: float = math.nan           # horizontal: contact's polar angle [rad] (the globe's; NaN on a wall)
    height: float = math.nan          # horizontal on a drum or a cone: the contact's height above the floor [m]
    alpha: float = math.nan           # horizontal: tilt [rad]
    rate: float = math.nan            # horizontal: signed Omega; vertical: psidot at the top [rad/s]
    rate_bottom: float = math.nan     # vertical: psidot at the bottom [rad/s]
    azimuth: float = math.nan         # vertical: the loop plane's direction [rad]
    #: a two-wheeler's points (3,) [m] at lane angle 0 (act/two_wheeler_lanes.py; None: a single-contact
    #: machine's, in the contact's meridian plane, ``points``)
    body: dict | None = field(default=None, repr=False)
    #: the envelope's segments by the names of their ends (a single-contact machine's: contact -> head)
    segments: tuple = (("contact", "head"),)

    @property
    def status(self) -> str:
        return str(STATUS_LABELS[self.orbit["status"]])

    @property
    def reason(self) -> str:
        return str(REASON_TEXT[self.orbit["reason"]])

    def kinematics(self, t, clock: float = 1.0) -> dict:
        """Points (3, n) [m] 'contact', 'head', 'com', the centre of mass's
        velocity 'v_com' (3, n) [m/s] and the lane angle 'phi' (horizontal)
        or 'psi' (vertical) (n,) [rad] at the times t (n,) [s]; ``clock``
        scales the lane's time (1.01: the rider 1 % fast)."""
        t = np.asarray(t, dtype=float).reshape(-1) * clock
        if self.kind == "horizontal":
            angle, rate = self.phase + self.rate * t, np.full_like(t, self.rate)
        else:
            angle, rate = _loop_angle(self._u(t), self.rate_bottom, self._m())
        out = self.at_angle(angle)
        out["v_com"] = rate * self._along(angle)
        out["phi" if self.kind == "horizontal" else "psi"] = angle
        return out

    def ends(self, t, clock: float = 1.0):
        """(contact, head) (3, n) [m]: the envelope's segment at the times t
        (a two-wheeler's first segment: :meth:`segment_ends` gives them all)."""
        t = np.asarray(t, dtype=float).reshape(-1) * clock
        if self.body is not None:
            return self.segment_ends(t)[0]
        if self.kind == "horizontal":
            angle = self.phase + self.rate * t
            c, s = np.cos(angle), np.sin(angle)
            out = []
            for key in ("contact", "head"):
                rho, z = self.points[key]
                pts = np.empty((3, t.size))
                pts[0], pts[1], pts[2] = rho * c, rho * s, z
                out.append(pts)
            return out[0], out[1]
        angle = _loop_angle(self._u(t), self.rate_bottom, self._m())[0]
        n = np.sin(angle) * self._e() + np.cos(angle) * _Z
        return self.points["contact"] * n, self.points["head"] * n

    def segment_ends(self, t, clock: float = 1.0) -> list:
        """[(p0, p1)] (3, n) [m]: every segment of the envelope at the times t."""
        if self.body is None:
            return [self.ends(t, clock)]
        t = np.asarray(t, dtype=float).reshape(-1) * clock
        pts = self.at_angle(self.phase + self.rate * t)
        return [(pts[a], pts[b]) for a, b in self.segments]

    def at_angle(self, angle) -> dict:
        """'contact', 'head', 'com' (3, n) [m] with the lane's angle (phi or
        psi [rad], (n,)) at ``angle``."""
        angle = np.asarray(angle, dtype=float).reshape(-1)
        if self.kind == "vertical":
            n = np.sin(angle) * self._e() + np.cos(angle) * _Z
            return {k: self.points[k] * n for k in ("contact", "com", "head")}
        c, s = np.cos(angle), np.sin(angle)
        if self.body is not None:            # a two-wheeler: its points turned about the vertical
            return {k: np.stack((x * c - y * s, x * s + y * c, np.full_like(angle, z)))
                    for k, (x, y, z) in self.body.items()}
        return {k: np.stack((rho * c, rho * s, np.full_like(angle, z))) for k, (rho, z) in self.points.items()}

    def _e(self):
        return np.array([math.cos(self.azimuth), math.sin(self.azimuth), 0.0])[:, None]

    def _along(self, angle):
        """d(com)/d(angle) (3, n): the centre of mass's velocity per unit rate."""
        if self.kind == "vertical":
            return self.points["com"] * (np.cos(angle) * self._e() - np.sin(angle) * _Z)
        if self.body is not None:
            x, y, _ = self.body["com"]
            c, s = np.cos(angle), np.sin(angle)
            return np.stack((-x * s - y * c, x * c - y * s, np.zeros_like(angle)))
        rg = self.points["com"][0]
        return np.stack((-rg * np.sin(angle), rg * np.cos(angle), np.zeros_like(angle)))

    def _m(self) -> float:
        return 1.0 - (self.rate / self.rate_bottom) ** 2

    def _u(self, t):
        """Jacobi's argument u at the times t (u = K at the top)."""
        from scipy.special import ellipk, ellipkinc  # a loop's only: importing scipy.special costs ~0.15 s

        m = self._m()
        beta0 = 0.5 * (math.pi - self.phase)
        t0 = 2.0 / self.rate_bottom * (ellipk(m) - ellipkinc(beta0, m))   # time from the top to the phase
        return ellipk(m) - 0.5 * self.rate_bottom * (t + t0)

    def speed_bound(self) -> float:
        """The greatest speed [m/s] of any point of the envelope's segment
        over the lap (a bound for how fast a clearance can change)."""
        return self.reach * (abs(self.rate) if self.kind == "horizontal" else self.rate_bottom)


def _loop_angle(u, rate_bottom, m):
    """psi and psidot of the loop at Jacobi's argument u (module docstring)."""
    from scipy.special import ellipj

    _, _, dn, beta = ellipj(u, m)
    return math.pi - 2.0 * beta, rate_bottom * dn


def _reach(r: float, machine: Machine) -> float:
    return max(r, abs(r - machine.head_height), abs(r - machine.com_height))


def _scalars(arrays: dict, i: int) -> dict:
    return {k: np.asarray(v)[i].item() for k, v in arrays.items() if np.ndim(v) == 1}


#: The physics of a horizontal lane on the globe (by theta) and on any other
#: ground (by height): the contact's rate, the lanes by the centre of mass's
#: speed and at a rate.
ON_THE_GLOBE = (contact_rate, horizontal_lanes, horizontal_lanes_at_rate)
ON_A_WALL = (contact_rate_on, horizontal_lanes_on, horizontal_lanes_at_rate_on)


def _found_lanes(riders: list[Rider], theta, ground, globe, machines, laps: dict, physics=ON_THE_GLOBE) -> dict:
    """The physics' lanes of ``riders`` (one call for those held by the
    centre of mass's speed, one for those held at a rate: a contact speed,
    a lap time, or the lap in ``laps`` [s] of the rider named by
    same_lap_as), as (n,) arrays in the riders' order; ``theta`` their
    lanes' theta [rad] on the globe, or heights [m] with ``physics``
    :data:`ON_A_WALL`."""
    rate_of, horizontal_lanes, horizontal_lanes_at_rate = physics
    by_com = np.array([math.isfinite(r.com_speed) for r in riders])
    omega = np.empty(len(riders))
    for i, rider in enumerate(riders):
        if math.isfinite(rider.speed):
            omega[i] = rate_of(theta[i], rider.speed, ground)
        elif math.isfinite(rider.period):
            omega[i] = 2.0 * math.pi / rider.period
        elif rider.same_lap_as is not None:
            omega[i] = 2.0 * math.pi / laps[rider.same_lap_as]
        else:
            omega[i] = math.nan
    parts = []
    for sel, make, value in ((by_com, horizontal_lanes, np.array([r.com_speed for r in riders])),
                             (~by_com, horizontal_lanes_at_rate, omega)):
        idx = np.flatnonzero(sel)
        if idx.size:
            parts.append((idx, make(theta[idx], value[idx], ground, globe.g, machines.take(idx), globe.mu,
                                    globe.max_g)))
    keys = [k for k in parts[0][1] if k != "tilts"]
    out = {}
    for key in keys:
        first = np.asarray(parts[0][1][key])
        out[key] = np.empty(len(riders), dtype=first.dtype)
        for idx, found in parts:
            out[key][idx] = np.asarray(found[key])
    return out


def horizontal_lanes_of(riders: list[Rider], ground, globe, laps: dict | None = None) -> list:
    """The horizontal lanes of ``riders`` (ride's steady orbits), in two
    calls to the physics at most; ``laps`` the lap times [s] of the riders
    they name by same_lap_as; a rider whose lane has no orbit gets a
    ParameterError (not raised) in his place."""
    if not riders:
        return []
    two = [isinstance(r.machine, TwoWheeler) for r in riders]
    if any(two):
        # a two-wheeler's lane is its steady turn (act/two_wheeler_lanes.py); the machines' as before
        from deathsphere.act.two_wheeler_lanes import two_wheeler_lane

        machines = iter(horizontal_lanes_of([r for r, t in zip(riders, two) if not t], ground, globe, laps))
        found = [two_wheeler_lane(r, ground, globe) if t else next(machines) for r, t in zip(riders, two)]
        return [Lane(**x) if isinstance(x, dict) else x for x in found]
    if not is_globe(ground):
        return _wall_lanes_of(riders, ground, globe, laps)
    machines = machine_arrays([r.machine for r in riders])
    theta = np.radians([r.theta_deg for r in riders])
    found = _found_lanes(riders, theta, ground, globe, machines, laps or {})
    # the lane's tilt as the riders' table reads it, in degrees, so that both agree to the bit
    alpha_deg = np.degrees(found["alpha"])
    points = meridian_points(theta, np.radians(alpha_deg), ground, machines)
    return _lanes(riders, found, alpha_deg, points,
                  lambda i, rider, pts: {"reach": _reach(float(ground.radius), rider.machine),
                                         "theta": math.radians(rider.theta_deg)})


def _wall_lanes_of(riders: list[Rider], ground, globe, laps: dict | None) -> list:
    """:func:`horizontal_lanes_of` on a drum or a cone: the machine's physics
    on that ground (docs/machine.md, "On any surface of revolution") at the
    lanes' heights, the points of eq. MS1 in the contact's meridian plane."""
    machines = machine_arrays([r.machine for r in riders])
    height = np.array([r.height for r in riders])
    found = _found_lanes(riders, height, ground, globe, machines, laps or {}, ON_A_WALL)
    alpha_deg = np.degrees(found["alpha"])
    points = meridian_points_on(height, np.radians(alpha_deg), ground, machines)
    # every point of the segment turns about the axis: it moves at its distance from it times the rate
    return _lanes(riders, found, alpha_deg, points,
                  lambda i, rider, pts: {"reach": max(abs(rho) for rho, _ in pts.values()), "height": float(height[i])})


def _lanes(riders: list[Rider], found: dict, alpha_deg, points: dict, where) -> list:
    """Each rider's :class:`Lane` from the lanes found (or the refusal of a
    lane with no steady orbit, naming the key that holds it), with the
    ground's own fields from ``where(i, rider, points)``: the reach that
    bounds the clearance's rate and where on the ground the lane is."""
    out = []
    for i, rider in enumerate(riders):
        orbit = _scalars(found, i)
        if not found["chosen"][i]:
            key = _hold_key(rider)
            out.append(ParameterError(f"rider {rider.name!r}: {key}: no steady orbit at this height and "
                                      f"{'lap' if key in ('period', 'same_lap_as') else 'speed'} "
                                      f"({REASON_TEXT[orbit['reason']]})", key))
            continue
        orbit["alpha_deg"] = float(alpha_deg[i])
        pts = {k: (float(rho[i]), float(z[i])) for k, (rho, z) in points.items()}
        out.append(Lane(name=rider.name, kind="horizontal", machine=rider.machine, width_m=rider.width,
                        period_s=float(orbit["period"]), phase=math.radians(rider.phase_deg), orbit=orbit,
                        points=pts, alpha=math.radians(orbit["alpha_deg"]),
                        rate=rider.direction * float(orbit["omega"]), **where(i, rider, pts)))
    return out


def _hold_key(rider: Rider) -> str:
    """The plan's key that holds a horizontal lane (what a refusal names)."""
    if rider.same_lap_as is not None:
        return "same_lap_as"
    return next(k for k in ("speed", "com_speed", "period") if math.isfinite(getattr(rider, k)))


def vertical_lanes_of(riders: list[Rider], ground, globe) -> list:
    """The vertical lanes of ``riders`` (ride --vertical's loops on great
    circles), all in one call to the physics; a loop not ridden at all (no
    fit, off its plane, too slow at the top) gets a ParameterError (not
    raised) in its rider's place."""
    if not riders:
        return []
    machines = machine_arrays([r.machine for r in riders])
    loops = vertical_loop(GREAT_CIRCLE, np.array([r.v_top for r in riders]), ground, globe.g, machines, globe.mu,
                          globe.max_g)
    out = []
    r = float(ground.radius)
    for i, rider in enumerate(riders):
        orbit = _scalars(loops, i)
        if orbit["status"] in LOOP_REFUSED:
            out.append(ParameterError(
                f"rider {rider.name!r}: v_top: this vertical lane is not feasible ({STATUS_LABELS[orbit['status']]}: "
                f"{REASON_TEXT[orbit['reason']]}; least top speed {orbit['v_top_min']:.3g} m/s)", "v_top"))
            continue
        from scipy.special import ellipk

        top, bottom = float(orbit["omega_top"]), float(orbit["omega_bottom"])
        m = 1.0 - (top / bottom) ** 2
        out.append(Lane(name=rider.name, kind="vertical", machine=rider.machine, width_m=rider.width,
                        period_s=float(4.0 * ellipk(m) / bottom), phase=math.radians(rider.phase_deg), orbit=orbit,
                        points={"contact": r, "com": r - rider.machine.com_height,
                                "head": r - rider.machine.head_height},
                        reach=_reach(r, rider.machine), rate=top, rate_bottom=bottom,
                        azimuth=math.radians(rider.azimuth_deg)))
    return out


def build_lanes(plan: Plan) -> list[Lane]:
    """Every rider's lane, in the plan's order: the horizontal ones in one
    physics call (two where some ride by the centre of mass's speed and
    some at a rate), the vertical ones in another, then those that take
    another rider's lap (same_lap_as) once his is known (ParameterError
    naming the first rider, in the plan's order, and the key for a lane
    that cannot be ridden at all, or a rider too wide for the globe)."""
    ground = plan.globe.ground
    built: dict[str, Lane | ParameterError] = {}
    borrowed = set()               # riders refused only because the lap they take cannot be ridden
    pending = list(plan.riders)
    while pending:                  # read_plan refused circles: each round builds at least one rider
        ready = [r for r in pending if r.same_lap_as is None or r.same_lap_as in built]
        pending = [r for r in pending if r not in ready]
        laps = {}
        for rider in ready:
            ahead = built.get(rider.same_lap_as) if rider.same_lap_as is not None else None
            if isinstance(ahead, ParameterError):
                borrowed.add(rider.name)
                built[rider.name] = ParameterError(f"rider {rider.name!r}: same_lap_as: {rider.same_lap_as!r}'s "
                                                   "lane cannot be ridden, so neither can his lap", "same_lap_as")
            elif ahead is not None:
                laps[rider.same_lap_as] = ahead.period_s
        ready = [r for r in ready if r.name not in built]
        horizontal = [r for r in ready if r.lane == "horizontal"]
        vertical = [r for r in ready if r.lane == "vertical"]
        for riders, lanes in ((horizontal, horizontal_lanes_of(horizontal, ground, plan.globe, laps)),
                              (vertical, vertical_lanes_of(vertical, ground, plan.globe))):
            built.update((r.name, lane) for r, lane in zip(riders, lanes))
    lanes = [built[r.name] for r in plan.riders]
    # the first refusal of a lane of its own (not one only following another's) names the cause
    for rider in sorted(plan.riders, key=lambda r: r.name in borrowed):
        if isinstance(built[rider.name], ParameterError):
            raise built[rider.name]
    for lane in lanes:
        if is_globe(ground):
            _check_width(lane, float(ground.radius))
        else:
            _check_width_on(lane, ground)
    return lanes


def _check_width_on(lane: Lane, ground) -> None:
    """:func:`_check_width` on a drum or a cone: the ends of the width
    across the lane at the head, a horizontal half-width either side of it,
    are inside the wall (the ground's clearance of that point)."""
    rho, z = lane.points["head"]
    out = -float(ground.clearance(math.hypot(rho, 0.5 * lane.width_m), z))
    if out >= 0:
        raise ParameterError(f"rider {lane.name!r}: width: {lane.width_m:g} m does not fit on this {ground.name} (at "
                             f"his head its ends would be {out:.3g} m outside the wall)", "width")


def _check_width(lane: Lane, r: float) -> None:
    """ParameterError naming ``width`` when the rider does not fit: his
    envelope's ends across the lane at the head (the handlebar or the
    shoulders, width/2 either side) would lie outside the globe."""
    head = lane.points["head"]
    from_centre = math.hypot(*head) if lane.kind == "horizontal" else abs(head)
    reach = math.hypot(from_centre, 0.5 * lane.width_m)
    if reach > r:
        raise ParameterError(f"rider {lane.name!r}: width: {lane.width_m:g} m does not fit in this globe (at his "
                             f"head its ends would be {reach - r:.3g} m outside the wall)", "width")
