"""Short simulated runs for the 3-D view's tests (few frames, fast)."""

import numpy as np

from deathsphere import simulation as sim
from deathsphere.model import Setup
from deathsphere.physics import dynamics as dyn

#: name -> (setup, kind, arguments): one run of every body, side and orbit
CASES = {
    "wheel_inside": (Setup(), "h", dict(theta_deg=60, alpha_deg=10)),
    "wheel_kicked": (Setup(), "h", dict(theta_deg=60, alpha_deg=10, perturb_deg=3.0)),
    "wheel_outside": (Setup(side="outside"), "h", dict(theta_deg=30, alpha_deg=80)),
    "sphere_inside": (Setup(body="sphere"), "h", dict(theta_deg=120, omega3=40.0)),
    "sphere_outside": (Setup(body="sphere", side="outside"), "h", dict(theta_deg=30, omega3=200.0, branch=0)),
    "vertical": (Setup(), "v", dict(theta_deg=90, speed=6.0)),
    "unstable": (Setup(), "h", dict(theta_deg=90, alpha_deg=80, perturb_deg=0.06)),
}


def run_case(name, periods=1.0, points_per_period=100, frame="turning", seconds=None, dt=None):
    """(series, summary, states, params) of one case; ``seconds`` and
    ``dt`` [s], when given, set the run's length and output step instead
    (the cases' periods range from 1.8 to 14 s)."""
    setup, kind, args = CASES[name]
    starts = sim.horizontal_starts(setup, **args) if kind == "h" else sim.vertical_starts(setup, **args)
    period = float(starts.period[0])
    if seconds is not None:
        periods = seconds / period
    if dt is not None:
        points_per_period = int(np.ceil(period / dt))
    s = sim.Simulation(starts, periods=periods, points_per_period=points_per_period, frame=frame,
                       record_states=True)
    series, summary = s.run()
    params = dyn.BodyParams(*(x[0] for x in starts.params))
    return series, summary, s.sample_states(), params


def central_difference(x, t):
    """d/dt of x (..., N) at the inner samples 1..N-2."""
    return (x[..., 2:] - x[..., :-2]) / (t[2:] - t[:-2])


def evenly_spaced(t):
    """Mask of the inner samples 1..N-2 with equal steps on both sides (an
    event's last row is off the grid; a central difference there is only
    first order)."""
    left, right = t[1:-1] - t[:-2], t[2:] - t[1:-1]
    return np.abs(left - right) <= 1e-9 * right


def norm(v):
    return np.sqrt(np.sum(v * v, axis=0))
