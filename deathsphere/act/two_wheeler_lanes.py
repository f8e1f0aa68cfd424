"""A two-wheeler's lane in a show (beyond the paper; docs/show.md, "Two-wheeler
riders"): ``ride``'s steady turn of the Whipple two-wheeler
(docs/two-wheeler.md sec. 8; on a drum or a cone sec. 12) at the lane's
height and rear contact speed, as a rigid configuration turning about the
vertical axis.

Of the turns at that height and speed the lane takes the one closest to
upright on the wall (the least |lean| from the wall's normal at the rear
contact) among those with status ok, or, when none is ok, among all (the
riders table then reports the status), as a single-contact machine's lane
takes its tilt.  The steady turn is the same with the steer free or
locked (the steer's mode changes its stability only, which the show does
not report), so a plan's two-wheeler has no steer key.

Its envelope is several segments, each swept with the rider's width (a
capsule of radius width/2 about each): rear contact -> head, front
contact -> head, rear contact -> front contact, the line through both
wheels' centres from the back of the rear rim to the front of the front
rim, and the wheels' tops (each wheel's rim point opposite its contact).
Every rim point lies within 0.71 of its wheel's radius of one of the last
three with the steer straight, within 0.83 at the presets' steady turns
(the front rim steered out of the line's plane; tests/show/test_two_wheeler_riders.py):
a width of 1.7 wheel radii or more holds both wheels.  Each point of the configuration turns about the vertical at the
lane's rate, so it moves at its distance from the axis times the rate: the
greatest such distance over the segments' ends (a segment's points are
their convex combinations) is the lane's ``reach``, which bounds how fast
a clearance can change (docs/show.md, "Clearance")."""

from __future__ import annotations

import math

import numpy as np

from deathsphere.errors import ParameterError
from deathsphere.physics.status import REASON_TEXT, Status
from deathsphere.physics.two_wheeler import geometry, steady
from deathsphere.requests.arena import is_globe

#: The envelope's segments of a two-wheeler, by the names of their ends.
SEGMENTS = (("contact", "head"), ("front_contact", "head"), ("contact", "front_contact"),
            ("rear_back", "front_front"), ("rear_top", "front_top"))
#: The bodies whose mass-weighted mean is the centre of mass (geometry.points's names).
_BODIES = (("mB", "rear_frame"), ("mR", "rear_wheel"), ("mH", "front_frame"), ("mF", "front_wheel"))


def _up(v):
    """A vector of the two-wheeler's frame N (z down) in the show's frame (z up)."""
    return np.array([v[0], v[1], -v[2]], dtype=float)


def body_points(q, machine, ground) -> dict:
    """The envelope's ends and the centre of mass (3,) [m] in the show's
    frame (z up, the ground's origin) at the steady turn's coordinates q (8,)."""
    p = machine.parameters()
    pts = geometry.points(np.asarray(q, float)[:, None], p, ground, machine.head)
    at = {k: _up(v[:, 0]) for k, v in pts.items() if k != "frames"}
    rear, front = at["rear_wheel"], at["front_wheel"]
    along = (front - rear) / np.linalg.norm(front - rear)
    mass = sum(getattr(p, m) for m, _ in _BODIES)
    return {"contact": at["P"], "front_contact": at["Q"], "head": at["head"],
            "com": sum(getattr(p, m) * at[k] for m, k in _BODIES) / mass,
            "rear_back": rear - p.rR * along, "front_front": front + p.rF * along,
            "rear_top": 2.0 * rear - at["P"], "front_top": 2.0 * front - at["Q"]}


def _placed(points: dict, sense: int, direction: int) -> dict:
    """The points turned about the vertical so that the rear contact is at
    azimuth 0, mirrored (y -> -y) when the rider rides the other way round
    from the turn found (the two-wheeler is symmetric: its mirror image
    turns the other way)."""
    phi = math.atan2(points["contact"][1], points["contact"][0])
    c, s = math.cos(-phi), math.sin(-phi)
    mirror = 1.0 if sense == direction else -1.0
    return {k: np.array([c * v[0] - s * v[1], mirror * (s * v[0] + c * v[1]), v[2]]) for k, v in points.items()}


def steady_turn(machine, at: float, speed: float, ground, g: float, mu: float, max_g: float) -> dict:
    """The two-wheeler's chosen steady turn (module docstring) at the lane
    ``at`` (theta [rad] on the globe, the rear contact's height [m] on a
    drum or a cone) and rear contact speed ``speed`` [m/s]: its quantities
    as scalars (``turn_state``'s, with int ``status`` and ``reason``
    codes), ``found`` False when there is none; ``q`` its coordinates."""
    out = steady.turns_for_speed(np.array([at]), np.array([speed]), machine.parameters(), ground, g, machine.head)
    found = np.isfinite(out["lean"][0])
    mu_rear, mu_front = out["mu_required_rear"][0], out["mu_required_front"][0]
    codes, why = steady.turn_status(found, out["head_clearance"][0], out["contact"][0] == 1, mu_rear, mu_front,
                                    out["load_g"][0], mu, max_g, why_none=out["reason"][0])
    if not found.any():
        return {"found": False, "status": int(np.asarray(codes).reshape(-1)[0]),
                "reason": int(np.asarray(why).reshape(-1)[0])}
    ok = found & (codes == Status.OK)
    pool = ok if ok.any() else found
    k = int(np.argmin(np.where(pool, np.abs(out["lean"][0]), np.inf)))
    turn = {key: float(np.asarray(v)[0, k]) for key, v in out.items() if np.ndim(v) == 2}
    turn.update(found=True, status=int(codes[k]), reason=int(why[k]), q=np.asarray(out["q"])[:, 0, k])
    return turn


def two_wheeler_lane(rider, ground, globe):
    """The fields of the :class:`~deathsphere.act.lanes.Lane` of a
    two-wheeler rider on a horizontal lane held by its rear contact's
    speed, or a ParameterError (not raised) naming ``speed`` when there is
    no steady turn."""
    machine = rider.machine
    on_globe = is_globe(ground)
    height = rider.contact_height
    at = math.radians(rider.theta_deg) if on_globe else height
    turn = steady_turn(machine, at, rider.speed, ground, globe.g, globe.mu, globe.max_g)
    if not turn["found"]:
        return ParameterError(f"rider {rider.name!r}: speed: no steady turn of the two-wheeler at this height and "
                              f"speed ({REASON_TEXT[turn['reason']]})", "speed")
    # the tilt from the inward horizontal as ride's table reads it: 90 deg - beta - the lean from the wall's normal
    beta = 180.0 - math.degrees(at) if on_globe else math.degrees(float(ground.wall_angle(height)))
    alpha_deg = 90.0 - beta - math.degrees(turn["lean"])
    omega = turn["omega"]
    body = _placed(body_points(turn["q"], machine, ground), 1 if omega > 0 else -1, rider.direction)
    orbit = {"status": turn["status"], "reason": turn["reason"], "alpha_deg": alpha_deg,
             "v_contact": turn["v_rear"], "v_cm": turn["v_cm"], "load_g": turn["load_g"],
             "mu_required": float(np.fmax(turn["mu_required_rear"], turn["mu_required_front"])),
             "head_clearance": turn["head_clearance"], "period": 2.0 * math.pi / abs(omega), "omega": abs(omega),
             "height": height, "lean_surface_deg": math.degrees(turn["lean"]),
             "steer_deg": math.degrees(turn["steer"])}
    points = {k: (math.hypot(v[0], v[1]), float(v[2])) for k, v in body.items()}
    reach = max(math.hypot(*body[k][:2]) for pair in SEGMENTS for k in pair)
    where = {"theta": at} if on_globe else {"height": height}
    return dict(name=rider.name, kind="horizontal", machine=machine, width_m=rider.width,
                period_s=orbit["period"], phase=math.radians(rider.phase_deg), orbit=orbit, points=points,
                reach=reach, alpha=math.radians(alpha_deg), rate=rider.direction * abs(omega), body=body,
                segments=SEGMENTS, **where)
