"""The Whipple two-wheeler's run: its body model over the physics of
:mod:`deathsphere.physics.two_wheeler.simulate`, integrated by the one
driver of every body (:func:`deathsphere.simulation.integrator.integrate`),
its events :class:`~deathsphere.simulation.event.Event` records and its
statuses :class:`~deathsphere.simulation.status.RunStatus` (beyond the
paper; docs/two-wheeler.md sec. 10.1).
"""

from __future__ import annotations

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics.two_wheeler import grounds, motion, on_wall
from deathsphere.physics.two_wheeler import simulate as tw
from deathsphere.physics.two_wheeler.parameters import BicycleParameters
from deathsphere.simulation.event import Event
from deathsphere.simulation.integrator import integrate, past_at_start
from deathsphere.simulation.status import RunStatus

__all__ = ["TWO_WHEELER", "run_two_wheeler"]

#: Right-hand sides evaluated between two reports to ``progress`` (some 5 ms of work).
_PROGRESS_EVERY = 100


class _TwoWheeler:
    """The Whipple two-wheeler as a body model (:class:`deathsphere.simulation.body.Body`):
    its parameters ``p`` a :class:`deathsphere.physics.two_wheeler.simulate.Run`,
    one body per run."""

    name = "two_wheeler"
    state_names = tuple(f"q{i}" for i in range(8)) + ("lean_rate", "rear_wheel_rate", "steer_rate")
    state_units = ("m", "m", "rad", "rad", "rad", "rad", "rad", "rad", "rad/s", "rad/s", "rad/s")
    #: what the series records (:func:`deathsphere.physics.two_wheeler.simulate.records`)
    series_extras = ("t", "lean", "steer", "heading", "theta_rear", "lean_rate", "steer_rate", "v_rear",
                     "steer_torque", "normal_rear", "normal_front", "friction_rear", "friction_front",
                     "energy_drift", "constraint_residual", "q")

    def ode(self, p: tw.Run, frame_rate=0.0):
        """The rates; the two-wheeler is integrated in the ground's frame only."""
        return lambda t, y: tw.rates(y, p)

    def contact_force(self, y, p: tw.Run) -> dict:
        """Rear and front (2,): normal and friction magnitude per mass."""
        n_rear, f_rear, n_front, f_front = tw.state_forces(y, p)
        return {"normal": np.array([n_rear, n_front]), "friction_magnitude": np.array([f_rear, f_front])}

    def energy(self, y, p: tw.Run):
        q, u_ind = y[:8], y[8:]
        return motion.energy(q, motion.dependent_speeds(q, u_ind, p.values, p.ground), p.values, p.ground)

    def project(self, y, p: tw.Run):
        """The pitch re-solved onto the front contact's holonomic constraint
        (the speeds satisfy the rolling constraints by construction)."""
        return np.concatenate([motion.pitch(np.array(y[:8], float), p.values, p.ground), y[8:]])

    def wall_events(self, p: tw.Run) -> list[Event]:
        """On a drum, a cone or a profile (a ground with lanes up to a
        highest one), the wall's ends as the paper's bodies meet them there:
        where the wall rises from a floor off the axis, a wheel's lowest rim
        point reaching it (``hits_floor``); where the wall has a top, the
        rear contact passing it (``over_the_top``).  The globe and flat
        ground have neither (docs/two-wheeler.md sec. 12.7)."""
        wall = grounds.of(p.ground).ground
        top = float(getattr(wall, "highest_lane", np.inf))
        out = []
        if hasattr(wall, "highest_lane") and float(wall.contact(0.0)[0]) > 0:
            out.append(Event(lambda t, y: float(on_wall.lowest_rim_height(y[:8], p.parameters, wall)),
                             RunStatus.HITS_FLOOR))
        if np.isfinite(top):
            out.append(Event(lambda t, y: top - float(on_wall.rear_lane(y[:8], wall)[0]), RunStatus.OVER_THE_TOP))
        return out

    def terminal_events(self, p: tw.Run, mu) -> list[Event]:
        """A normal force reaching zero at either wheel (``contact_lost``)
        and, for a finite ``mu``, the friction reaching mu times the normal
        (``slips``); on a wall its ends (:meth:`wall_events`)."""
        last = {}

        def forces(y):
            # both events ask at the same state: computed once
            key = y.tobytes()
            if key not in last:
                last.clear()
                last[key] = tw.state_forces(y, p)
            return last[key]

        def lost(t, y):
            n_rear, _, n_front, _ = forces(y)
            return min(n_rear, n_front)

        def slip(t, y):
            n_rear, f_rear, n_front, f_front = forces(y)
            return min(mu * n_rear - f_rear, mu * n_front - f_front)

        return ([Event(lost, RunStatus.CONTACT_LOST)] + ([Event(slip, RunStatus.SLIPS)] if np.isfinite(mu) else [])
                + self.wall_events(p))


TWO_WHEELER = _TwoWheeler()


def run_two_wheeler(parameters: BicycleParameters, q0, u_ind0, t_end, *, ground=motion.FLAT, g=STANDARD_GRAVITY,
             steering=tw.Steering(), kick=tw.Kick(), solver=tw.Solver(), mu=np.inf, progress=None):
    """Integrate from (q0, u_ind0) (a steady turn's q and its independent
    speeds (lean rate, rear wheel rate, steer rate)) on ``ground`` under
    gravity ``g`` with the start kicked by ``kick``
    (:class:`~deathsphere.physics.two_wheeler.simulate.Kick`), the steer
    held as ``steering`` says (:class:`~deathsphere.physics.two_wheeler.simulate.Steering`:
    the torque :func:`~deathsphere.physics.two_wheeler.simulate.rider_torque`,
    T_0 about lean_0, default q0's lean; or zero, hands-free; or, locked,
    the steer held at q0's steer, its rate zero, any given dropped, the
    torque :func:`~deathsphere.physics.two_wheeler.simulate.lock_torque`),
    for ``t_end`` s, integrated as ``solver`` says
    (:class:`~deathsphere.physics.two_wheeler.simulate.Solver`); events stop
    the run: a normal force reaching zero (``contact_lost``) or the friction
    exceeding ``mu`` times the normal at either wheel (``slips``), and on a
    drum, a cone or a profile a wheel reaching the floor (``hits_floor``)
    or the rear contact passing the wall's top (``over_the_top``) (beyond
    the paper; docs/two-wheeler.md sec. 10.1 and 12.7).  ``progress``, if given, is
    told (t, t_end) now and then as the integrator advances (a run of a few
    periods takes seconds).  Returns (series dict of (n,) arrays and the
    coordinates ``q`` (8, n), summary dict)."""
    run, y0 = tw.start(parameters, q0, u_ind0, ground=ground, g=g, steering=steering, kick=kick)
    body = TWO_WHEELER
    rates = body.ode(run)
    calls = [0]

    def fun(t, y):
        calls[0] += 1
        if progress is not None and calls[0] % _PROGRESS_EVERY == 0:
            progress(min(t, t_end), t_end)
        return rates(t, y)

    events = body.terminal_events(run, mu)
    t_eval = np.linspace(0.0, t_end, max(int(solver.n_points), 2))
    k_start = past_at_start(events, 0.0, y0)
    if k_start >= 0:
        status, t_event, ts, Y, nfev = events[k_start].status, 0.0, np.zeros(1), y0[:, None], 0
    else:
        done = integrate(fun, (0.0, t_end), y0, events, method=solver.method, t_eval=t_eval, rtol=solver.rtol,
                         atol=solver.rtol if solver.atol is None else solver.atol)
        sol = done.sol
        status, t_event, ts, Y, nfev = RunStatus.COMPLETED, np.nan, sol.t, sol.y, sol.nfev
        if done.event is not None:
            # the event's state closes the series
            status, t_event = done.event.status, done.t_event
            ts, Y = np.append(ts, t_event), np.concatenate([Y, done.y_event[:, None]], axis=1)
        elif not sol.success:
            status = RunStatus.FAILED
    series, extremes = tw.records(ts, Y, run)
    summary = {"status": status.label, "t_event": t_event, **extremes, "n_evaluations": int(nfev)}
    return series, summary
