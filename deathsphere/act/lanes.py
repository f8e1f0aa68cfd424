"""Each rider's lane (beyond the paper; docs/show.md, "Lanes"): where his
contact, head and centre of mass are at any time.

A horizontal lane is ``ride``'s steady orbit (docs/machine.md eqs. M1-M12)
at the plan's height and centre-of-mass speed: the contact at r (sin theta
cos phi, sin theta sin phi, cos theta), phi = phase +- Omega t, the machine's
up-axis u = -cos(alpha) rho-hat + sin(alpha) z-hat in the contact's meridian
plane, the centre of mass G = Q + (h - t) u and the head H = Q + (head - t) u
with Q = (r - t) n-hat (eq. M2).  Of the tilts giving the speed (eq. M12)
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
from scipy.special import ellipj, ellipk, ellipkinc

from deathsphere.api.machines import Machine
from deathsphere.api.rides import ride
from deathsphere.errors import ParameterError
from deathsphere.act.plan import Globe, Plan, Rider

#: Statuses with which a vertical lane is not ridden at all (the plan is refused).
LOOP_REFUSED = ("no_fit", "no_orbit", "no_contact")
_Z = np.array([0.0, 0.0, 1.0])[:, None]


@dataclass
class Lane:
    """One rider's lane.  ``kind`` 'horizontal' or 'vertical'; ``row`` the
    row of ``ride`` (or ``ride --vertical``) it rides; ``period_s`` its lap
    [s]; ``rate`` Omega [rad/s] signed (+ ccw) or psidot at the top;
    ``phase`` [rad] phi or psi at t = 0."""

    name: str
    kind: str
    machine: Machine
    width_m: float
    period_s: float
    r: float
    g: float
    phase: float
    row: dict = field(repr=False)
    theta: float = math.nan           # horizontal: contact's polar angle [rad]
    alpha: float = math.nan           # horizontal: tilt [rad]
    rate: float = math.nan            # horizontal: signed Omega; vertical: psidot at the top [rad/s]
    rate_bottom: float = math.nan     # vertical: psidot at the bottom [rad/s]
    azimuth: float = math.nan         # vertical: the loop plane's direction [rad]

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
        """(contact, head) (3, n) [m]: the envelope's segment at the times t."""
        t = np.asarray(t, dtype=float).reshape(-1) * clock
        if self.kind == "horizontal":
            angle = self.phase + self.rate * t
            c, s = np.cos(angle), np.sin(angle)
            mer = self._meridian()
            out = []
            for key in ("contact", "head"):
                rho, z = mer[key]
                pts = np.empty((3, t.size))
                pts[0], pts[1], pts[2] = rho * c, rho * s, z
                out.append(pts)
            return out[0], out[1]
        angle = _loop_angle(self._u(t), self.rate_bottom, self._m())[0]
        n = np.sin(angle) * self._e() + np.cos(angle) * _Z
        return self.r * n, (self.r - self.machine.head) * n

    def at_angle(self, angle) -> dict:
        """'contact', 'head', 'com' (3, n) [m] with the lane's angle (phi or
        psi [rad], (n,)) at ``angle``."""
        angle = np.asarray(angle, dtype=float).reshape(-1)
        m = self.machine
        if self.kind == "vertical":
            n = np.sin(angle) * self._e() + np.cos(angle) * _Z
            return {"contact": self.r * n, "com": (self.r - m.h) * n, "head": (self.r - m.head) * n}
        c, s = np.cos(angle), np.sin(angle)
        return {k: np.stack((rho * c, rho * s, np.full_like(angle, z))) for k, (rho, z) in self._meridian().items()}

    def _meridian(self) -> dict:
        """(rho, z) [m] of contact, centre of mass and head in the contact's
        meridian plane (eq. M2)."""
        m, r = self.machine, self.r
        st, ct, sa, ca = math.sin(self.theta), math.cos(self.theta), math.sin(self.alpha), math.cos(self.alpha)
        return {"contact": (r * st, r * ct),
                "com": ((r - m.t) * st - (m.h - m.t) * ca, (r - m.t) * ct + (m.h - m.t) * sa),
                "head": ((r - m.t) * st - (m.head - m.t) * ca, (r - m.t) * ct + (m.head - m.t) * sa)}

    def _e(self):
        return np.array([math.cos(self.azimuth), math.sin(self.azimuth), 0.0])[:, None]

    def _along(self, angle):
        """d(com)/d(angle) (3, n): the centre of mass's velocity per unit rate."""
        if self.kind == "vertical":
            return (self.r - self.machine.h) * (np.cos(angle) * self._e() - np.sin(angle) * _Z)
        rg = self._meridian()["com"][0]
        return np.stack((-rg * np.sin(angle), rg * np.cos(angle), np.zeros_like(angle)))

    def _m(self) -> float:
        return 1.0 - (self.rate / self.rate_bottom) ** 2

    def _u(self, t):
        """Jacobi's argument u at the times t (u = K at the top)."""
        m = self._m()
        beta0 = 0.5 * (math.pi - self.phase)
        t0 = 2.0 / self.rate_bottom * (ellipk(m) - ellipkinc(beta0, m))   # time from the top to the phase
        return ellipk(m) - 0.5 * self.rate_bottom * (t + t0)

    def speed_bound(self) -> float:
        """The greatest speed [m/s] of any point of the envelope's segment
        over the lap (a bound for how fast a clearance can change)."""
        m = self.machine
        reach = max(self.r, abs(self.r - m.head), abs(self.r - m.h))
        return reach * (abs(self.rate) if self.kind == "horizontal" else self.rate_bottom)


def _loop_angle(u, rate_bottom, m):
    """psi and psidot of the loop at Jacobi's argument u (module docstring)."""
    _, _, dn, beta = ellipj(u, m)
    return math.pi - 2.0 * beta, rate_bottom * dn


def _choose(rows: list[dict], theta: float) -> dict | None:
    """The tilt closest to upright on the wall among the ok rows, else
    among those with an orbit (module docstring)."""
    upright = math.degrees(theta) - 90.0
    for keep in (lambda r: r["status"] == "ok", lambda r: math.isfinite(r["omega_rad_s"])):
        rows_kept = [r for r in rows if keep(r)]
        if rows_kept:
            return min(rows_kept, key=lambda r: abs(r["alpha_deg"] - upright))
    return None


def horizontal_lane(rider: Rider, globe: Globe) -> Lane:
    """The horizontal lane of ``rider`` (ride's steady orbit)."""
    table = ride(rider.theta_deg, speed=rider.speed, machine=rider.machine, r=globe.r, g=globe.g, mu=globe.mu,
                 max_g=globe.max_g, stability=False)
    row = _choose(list(table), math.radians(rider.theta_deg))
    if row is None:
        reason = str(table["reason"].reshape(-1)[0])
        raise ParameterError(f"rider {rider.name!r}: speed: no steady orbit at this height and speed ({reason})",
                             "speed")
    return Lane(name=rider.name, kind="horizontal", machine=rider.machine, width_m=rider.width,
                period_s=float(row["period_s"]), r=globe.r, g=globe.g, phase=math.radians(rider.phase_deg), row=row,
                theta=math.radians(rider.theta_deg), alpha=math.radians(row["alpha_deg"]),
                rate=rider.direction * float(row["omega_rad_s"]))


def vertical_lane(rider: Rider, globe: Globe) -> Lane:
    """The vertical lane of ``rider`` (ride --vertical's loop on a great
    circle); refused when the loop is not ridden at all (no fit, off its
    plane, too slow at the top)."""
    row = ride(90.0, vertical=True, v_top=rider.v_top, machine=rider.machine, r=globe.r, g=globe.g, mu=globe.mu,
               max_g=globe.max_g)[0]
    if row["status"] in LOOP_REFUSED:
        raise ParameterError(f"rider {rider.name!r}: v_top: this vertical lane is not feasible ({row['status']}: "
                             f"{row['reason']}; least top speed {row['v_top_min_m_s']:.3g} m/s)", "v_top")
    top, bottom = float(row["omega_top_rad_s"]), float(row["omega_bottom_rad_s"])
    m = 1.0 - (top / bottom) ** 2
    return Lane(name=rider.name, kind="vertical", machine=rider.machine, width_m=rider.width,
                period_s=float(4.0 * ellipk(m) / bottom), r=globe.r, g=globe.g, phase=math.radians(rider.phase_deg),
                row=row,
                rate=top, rate_bottom=bottom, azimuth=math.radians(rider.azimuth_deg))


def build_lanes(plan: Plan) -> list[Lane]:
    """Every rider's lane, in the plan's order (ParameterError naming the
    rider and the key for a lane that cannot be ridden at all)."""
    return [horizontal_lane(r, plan.globe) if r.lane == "horizontal" else vertical_lane(r, plan.globe)
            for r in plan.riders]
