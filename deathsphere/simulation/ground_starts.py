"""Initial conditions of the paper's wheel and ball on a ground other than
the globe (beyond the paper; docs/simulation.md, "On any ground").

A run starts on the steady orbit ``orbit`` finds on that lane
(:mod:`deathsphere.physics.revolution`, docs/surfaces.md S1-S7: the same
statuses, no_fit and no_orbit, decide whether a body can start), its state
that of :func:`deathsphere.physics.dynamics_on.wheel_orbit_state_on` or
:func:`~deathsphere.physics.dynamics_on.ball_orbit_state_on`, optionally
kicked off it by ``perturb_deg``:

* a wheel, as on the globe: tilted by the kick about its direction of travel
  (the tangent to the lane through the contact), keeping the contact point
  and the angular velocity -- the rim stays tangent to the surface there,
  so contact and rolling hold exactly;
* a ball: its angular velocity turned by the kick about the contact normal,
  which turns the centre's velocity by the same angle up the wall (positive
  up, whichever way it orbits), keeping its spin about the normal and its
  speed; contact and rolling hold exactly.  (On the globe a ball's kick
  moves its contact down the meridian; a wall's meridian has no angle to
  move it by.)

On the outside (``outside``: round a drum's outside, on a cone's or a
dome's roof, McDonald sec. 3 off the globe) the orbit is ``orbit``'s with
``side="outside"`` (S4 and S3 outside, S6 with the centre on the far side);
a wheel's steady state is the same formula (its tilt alone puts the centre
on either side of the contact, docs/dynamics.md sec. 7, "Outside"), a
ball's e3 is the wall's inward normal, and the kicks are the same, still
positive up the wall.
"""

from __future__ import annotations

import numpy as np

from deathsphere.physics import dynamics_on as don
from deathsphere.physics import revolution
from deathsphere.records.paper_bodies import Ball, PaperBodyKind
from deathsphere.simulation.bodies import GroundRun
from deathsphere.simulation.starts import Starts, start_status
from deathsphere.simulation.status import RunStatus

__all__ = ["ground_starts", "turned_about"]


def turned_about(v, axis, angle):
    """v (3, n) turned by ``angle`` [rad] (n,) about the unit ``axis`` (3, n)
    (Rodrigues' formula)."""
    c, s = np.cos(angle), np.sin(angle)
    along = np.sum(axis * v, axis=0)
    return c * v + s * np.cross(axis, v, axis=0) + (1 - c) * along * axis


def _on_wall(ground, height):
    """The heights clipped onto the wall (a lane off it has status no_fit and
    is not integrated)."""
    return np.clip(height, 0.0, getattr(ground, "highest_lane", np.inf))


def _wheel_state(ground, height, alpha, kick, a, k, g, phi):
    """States (9, n) of wheels on their steady orbits at tilt alpha [rad],
    tilted by ``kick`` [rad] about the direction of travel."""
    rho, z = ground.contact(height)
    steady, _ = don.wheel_state_at(rho, z, alpha, a, k, g, phi)
    # the kick moves c and e1 about the contact (they do not depend on Omega), w stays
    tilted, _ = don.wheel_state_at(rho, z, alpha + kick, a, k, g, phi)
    return np.concatenate((tilted[0:6], steady[6:9]))


def _ball_state(ground, height, rate, kick, a, k, g, phi, outside):
    """(states (9, n), omega3) of balls on their steady orbits of rate
    ``rate``, their velocity turned ``kick`` [rad] up the wall."""
    steady, spin = don.ball_orbit_state_on(ground, height, rate, a, k, g, phi, outside)
    # e3, from the centre to the contact: -n of the lane inside, +n outside
    side = np.where(outside, -1.0, 1.0)
    n_rho, n_z = ground.normal(height)
    rhat = np.stack((np.cos(phi), np.sin(phi), np.zeros_like(phi)))
    e3 = -side * (n_rho * rhat + n_z * np.array([0.0, 0.0, 1.0])[:, None])
    # v = a e3 x w (eq. 6): turning w about e3 turns v the same way, so the axis's
    # flip outside flips the angle to keep a positive kick up the wall
    w = turned_about(steady[6:9], e3, side * np.sign(rate) * kick)
    return np.concatenate((steady[0:6], w)), spin


def _orbit(ground, height, ball, held, branch, a, k, g, outside):
    """The steady orbits on the lanes (docs/surfaces.md S1-S7), inside or
    ``outside``: a wheel's at tilt ``held`` [rad], a ball's at spin
    ``held`` (root ``branch``) or, with branch None, at rate ``held``."""
    if not ball:
        return revolution.wheel_orbit(ground, height, held, a, k, g, outside=outside)
    if branch is None:
        return revolution.ball_orbit_from_rate(ground, height, held, a, k, g, outside=outside)
    return revolution.ball_orbit(ground, height, held, a, k, g, outside=outside, branch=branch)


def ground_starts(ground, body: PaperBodyKind, height, held: dict, *, a, k, g, mu=np.inf, perturb_deg=0.0,
                  phi_deg=0.0, input_row=None, outside=False) -> Starts:
    """Wheels or balls on steady horizontal orbits of ``ground`` at lane
    ``height`` [m] (on flat ground: the turn radius), arrays broadcast.

    ``held`` says how the orbit is held: a wheel by its tilt,
    ``{"alpha_deg": ...}`` [deg]; a ball by its spin, ``{"omega3": ...,
    "branch": 0 | 1}`` (the root of docs/surfaces.md S6: 0 slow, 1 fast),
    or its signed rate, ``{"omega": ...}`` [rad/s].  ``perturb_deg`` [deg] kicks it
    (module docstring); ``outside`` puts the bodies on the ground's far
    side (one side for the run).  Bodies with no steady orbit there get
    status no_fit / no_orbit and the orbit's reason, and are not
    integrated.  Summary fields: theta NaN (no polar angle off the globe),
    alpha the wheel's tilt or a ball's equivalent tilt 90 deg - beta inside,
    270 deg - beta outside (sec. 4 of the paper: the ball's axis 3 along
    the normal, theta -/+ 90 deg on the tangent sphere, as ``orbit``
    reports it).
    """
    outside = bool(outside)
    ball = isinstance(body, Ball)
    by_rate = ball and held.get("omega") is not None
    branch = None if by_rate else held.get("branch", 0)
    value = held["alpha_deg"] if not ball else held["omega" if by_rate else "omega3"]
    h, value, kick_deg, phi_deg = (np.array(x, dtype=float).reshape(-1)
                                   for x in np.broadcast_arrays(height, value, perturb_deg, phi_deg))
    n = h.size
    kick, phi = np.deg2rad(kick_deg), np.deg2rad(phi_deg)
    orb = _orbit(ground, h, ball, value if ball else np.deg2rad(value), branch, a, k, g, outside)
    status, reason = start_status(orb)
    ok = status == RunStatus.PENDING
    rate = np.where(ok, orb["omega"], np.nan)
    state, omega3_out = np.full((9, n), np.nan), np.full(n, np.nan)
    on_wall = _on_wall(ground, h)
    if ball:
        # a ball's equivalent tilt (axis 3 along the normal): 90 deg - beta (outside 270 deg - beta), as orbit
        # gives it
        alpha = np.deg2rad(270.0 if outside else 90.0) - np.asarray(ground.wall_angle(on_wall), dtype=float)
        alpha_deg_out = np.rad2deg(alpha)
        if ok.any():
            state[:, ok], omega3_out[ok] = _ball_state(ground, on_wall[ok], rate[ok], kick[ok], a, k, g, phi[ok],
                                                       outside)
    else:
        alpha, alpha_deg_out = np.deg2rad(value), value
        if ok.any():
            state[:, ok] = _wheel_state(ground, on_wall[ok], alpha[ok], kick[ok], a, k, g, phi[ok])
    rho, z = ground.contact(_on_wall(ground, h))
    rho, z = np.broadcast_to(rho, (n,)).astype(float), np.broadcast_to(z, (n,)).astype(float)
    params = GroundRun(a=np.full(n, float(a)), k=np.full(n, float(k)), g=np.full(n, float(g)),
                       sphere=np.full(n, ball), r=rho, height=z - ground.lowest, ground=ground,
                       outside=np.full(n, outside))
    period = np.where(ok, 2 * np.pi / np.abs(np.where(ok, rate, 1.0)), np.nan)
    return Starts(
        state=state, params=params, frame=np.broadcast_to(np.eye(3), (n, 3, 3)).copy(),
        input_row=np.arange(1, n + 1, dtype=np.int64) if input_row is None
        else np.broadcast_to(np.asarray(input_row, dtype=np.int64), (n,)).copy(),
        body=np.full(n, body.word, dtype=object), side=np.full(n, "outside" if outside else "inside", dtype=object),
        orbit=np.full(n, "horizontal", dtype=object), theta=np.full(n, np.nan),
        alpha=np.broadcast_to(alpha, (n,)).astype(float), theta_deg=np.full(n, np.nan),
        alpha_deg=np.broadcast_to(alpha_deg_out, (n,)).astype(float),
        rate=rate, turning=np.where(ok, rate, 0.0), period=period, phi0=phi,
        speed=np.where(ok, orb["v_cm"], np.nan), omega3=omega3_out, perturb_deg=kick_deg,
        perturb_theta_deg=np.zeros(n), mu=np.full(n, float(mu)), status=status, reason=reason)
