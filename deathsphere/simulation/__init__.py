"""Simulate wheels and spheres rolling on a fixed sphere.

Beyond the paper: McDonald (1993) writes the Newton-Euler equations in
general form, eqs. (2)-(7b), and solves them only for steady orbits.  This
package integrates the exact equations of motion of
:mod:`deathsphere.physics.dynamics` with :func:`scipy.integrate.solve_ivp`,
starting on (or near) a steady orbit of the paper, and watches the contact
force as it goes.  Method, tolerances, perturbation, events and outputs are
described in ``docs/simulation.md``.

Modules
-------
* :mod:`~deathsphere.simulation.starts` -- initial conditions:
  :class:`Starts`, :func:`horizontal_starts`, :func:`vertical_starts` and
  the start-state geometry of eqs. (8b), (11)-(13);
* :mod:`~deathsphere.simulation.bodies` -- the body model (the paper's
  wheel and sphere, or a machine: docs/machine.md eqs. M16-M19) the others
  ask for the dynamics;
* :mod:`~deathsphere.simulation.machine_starts` -- a machine's initial
  conditions: :func:`machine_starts`;
* :mod:`~deathsphere.simulation.runner` -- the integrator driver:
  :class:`Simulation` (solve_ivp, chunking period by period, recorded
  states), :func:`run_simulation`, :data:`METHODS`, :data:`FRAMES`;
* :mod:`~deathsphere.simulation.body` -- the protocol every body model
  keeps (state, right-hand side, contact forces, energy, projection,
  events, series);
* :mod:`~deathsphere.simulation.integrator` -- the one solve_ivp call every
  run goes through;
* :mod:`~deathsphere.simulation.event` -- one terminal event as a record
  (its condition, the status it ends a body with);
* :mod:`~deathsphere.simulation.events` -- the terminal events
  (contact lost, slips) of the paper's bodies and machines;
* :mod:`~deathsphere.simulation.two_wheeler` -- the Whipple two-wheeler's
  body model and run (docs/two-wheeler.md sec. 10.1);
* :mod:`~deathsphere.simulation.series` -- the time series: quantities at
  each sample, row assembly, :data:`SERIES_COLUMNS`, :func:`concat_tables`;
* :mod:`~deathsphere.simulation.summary` -- the summary: per-body
  bookkeeping of drifts, extremes, events and counters,
  :data:`SUMMARY_COLUMNS`;
* :mod:`~deathsphere.simulation.status` -- :class:`RunStatus`, the final
  statuses (:data:`STATUSES`) and their reason words.

Use
---
1. Build the initial conditions (one or many bodies; arrays broadcast):
   :func:`horizontal_starts` (a steady horizontal orbit: a wheel given
   (theta, alpha); a sphere given (theta, omega3 and a branch) or (theta,
   Omega)) or :func:`vertical_starts` (a vertical orbit of a wheel given
   the cone angle theta and the speed of its centre), optionally kicked
   off the steady orbit by ``perturb_deg``.
   :meth:`Starts.concat` joins several sets.
2. ``for chunk in Simulation(starts, ...).chunks(progress): ...`` yields
   the time series period by period, then ``sim.summary()`` gives one row
   per body; :func:`run_simulation` does both and returns ``(series, summary)``.

Statuses (:data:`STATUSES`): ``completed`` (ran the requested time),
``contact_lost`` (the normal force fell to zero; terminal event),
``slips`` (the friction needed reached mu times the normal force; terminal
event), ``no_fit`` / ``no_orbit`` (no steady orbit to start from: nothing is
integrated), ``failed`` (the integrator gave up).

Angles are in degrees at this level, as on the command line (the kicks
``perturb_deg`` and ``perturb_theta_deg`` too); lengths in m, rates in
rad/s, forces per unit mass in m/s^2.
"""

from deathsphere.simulation.machine_starts import machine_run, machine_starts
from deathsphere.simulation.runner import FRAMES, METHODS, Simulation, run_simulation
from deathsphere.simulation.series import SERIES_COLUMNS, concat_tables
from deathsphere.simulation.starts import Starts, horizontal_starts, vertical_starts
from deathsphere.simulation.status import STATUSES, RunStatus
from deathsphere.simulation.summary import SUMMARY_COLUMNS

__all__ = [
    "STATUSES", "RunStatus", "SERIES_COLUMNS", "SUMMARY_COLUMNS", "METHODS", "FRAMES",
    "Starts", "horizontal_starts", "vertical_starts", "machine_starts", "machine_run", "Simulation",
    "run_simulation", "concat_tables",
]
