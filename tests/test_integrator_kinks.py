"""The integrator's restarts at kinks of the right-hand side: no step
straddles one, so the error stays the smooth problem's.  The problem is
solved by hand: y' = 1 below y = 1, y' = 1 + c (y - 1)^2 above (its second
derivative jumps at y = 1), so y = t up to t = 1 and then
y = 1 + tan(sqrt(c) (t - 1)) / sqrt(c)."""

import numpy as np
import pytest

from deathsphere.simulation.integrator import integrate

C = 50.0
T = 1.15


def _rate(t, y):
    return np.array([1.0 + C * max(0.0, y[0] - 1.0) ** 2])


def _exact(t):
    return np.where(t < 1.0, t, 1.0 + np.tan(np.sqrt(C) * (t - 1.0)) / np.sqrt(C))


def test_a_step_ends_at_the_kink_and_the_error_is_the_smooth_problems():
    done = integrate(_rate, (0.0, T), [0.0], [], method="DOP853", rtol=1e-12, atol=1e-12, dense_output=True,
                     kinks=lambda y: np.atleast_1d(y)[:1])
    sol = done.sol
    assert sol.status == 0 and done.event is None and sol.t[-1] == T
    # the pieces joined: steps in order, one of them ending on the kink at t = 1
    assert np.all(np.diff(sol.t) > 0) and np.min(np.abs(sol.t - 1.0)) < 1e-10
    assert abs(sol.y[0, -1] - _exact(T)) < 1e-12
    ts = np.linspace(0.0, T, 101)
    assert np.max(np.abs(sol.sol(ts)[0] - _exact(ts))) < 1e-11      # one dense output over the pieces


@pytest.mark.parametrize("level", [0.5, 1.2])
def test_an_event_before_or_after_the_kink_stops_the_run_where_it_falls(level):
    from deathsphere.simulation.event import Event
    from deathsphere.simulation.status import RunStatus

    stop = Event(lambda t, y: level - y[0], RunStatus.CONTACT_LOST)
    done = integrate(_rate, (0.0, T), [0.0], [stop], method="DOP853", rtol=1e-12, atol=1e-12, dense_output=True,
                     kinks=lambda y: np.atleast_1d(y)[:1])
    # y = level at t = level below the kink, at 1 + atan(sqrt(c) (level - 1)) / sqrt(c) above
    expected = level if level < 1 else 1.0 + np.arctan(np.sqrt(C) * (level - 1.0)) / np.sqrt(C)
    assert done.event is stop and done.k_event == 0 and abs(done.t_event - expected) < 1e-11
    assert done.sol.status == 1 and len(done.sol.t_events) == 1
