"""Edges of ``simulate``: scales float64 cannot integrate, runs too long to
finish, and tolerances solve_ivp would not honour (docs/simulation.md,
"Cost" and "Integration")."""

import warnings
from types import SimpleNamespace

import numpy as np
import pytest

import deathsphere
from deathsphere import simulation as sim
from deathsphere.api import prepare_simulation, simulation_request
from deathsphere.model import Setup
from deathsphere.params import RTOL_MIN, ParameterError
from deathsphere.simulation import integrator, runner


#: The warnings a fresh interpreter does not show (Python's default filters).
_HIDDEN_BY_PYTHON = (DeprecationWarning, PendingDeprecationWarning, ImportWarning, ResourceWarning)


def _cli(run, *args):
    """``deathsphere simulate ...`` run in-process (the ``run`` fixture): its
    exit status, stdout and stderr, with any Python warning on stderr as a
    fresh ``python -m deathsphere`` would print it there."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.resetwarnings()
        for category in _HIDDEN_BY_PYTHON:
            warnings.filterwarnings("ignore", category=category)
        res = run("simulate", "--theta", "60", "--alpha", "10", "--summary-only", "--format", "csv", *args)
    shown = "".join(warnings.formatwarning(w.message, w.category, w.filename, w.lineno) for w in caught)
    return SimpleNamespace(returncode=res.exit_code, stdout=res.stdout, stderr=res.stderr + shown)


def _one_line_usage_error(proc, *words):
    assert proc.returncode == 2
    assert proc.stdout == ""
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("deathsphere: error:"), proc.stderr
    assert "Traceback" not in proc.stderr and "Warning" not in proc.stderr
    for word in words:
        assert word in lines[0]


# ---- a/r so small that the spin swamps the orbit in float64 -----------------------

@pytest.mark.parametrize("a, r", [(1e-9, 1e9), (1e-7, 1e9), (1e-9, 1e6)])
def test_tiny_a_over_r_is_refused_not_reported_as_contact_lost(a, r):
    """The spin is ~r/a times the orbital rate; at a/r = 1e-18 float64 cannot
    even hold the start state (alpha read back 10 deg off), so the run used
    to end at once with a bogus contact_lost.  It is refused, saying why."""
    with pytest.raises(ParameterError, match="float64") as err:
        prepare_simulation(*simulation_request(dict(theta=60, alpha=10, a=a, r=r, periods=1)))
    assert "a/r >=" in str(err.value)
    # the orbit itself is fine there: only the integration is refused
    assert str(deathsphere.orbit(60, 10, a=a, r=r)["status"]) == "ok"


def test_tiny_a_over_r_is_refused_on_the_command_line_in_one_line(run):
    _one_line_usage_error(_cli(run, "-a", "1e-9", "-r", "1e9", "--periods", "1"), "float64", "a/r >=")


def test_the_spin_ratio_limit_is_not_a_budget():
    with pytest.raises(ParameterError, match="float64"):
        prepare_simulation(*simulation_request(dict(theta=60, alpha=10, a=1e-9, r=1e9, periods=1e-12, max_steps=10**15)))


def test_a_small_but_allowed_scale_stays_on_its_orbit():
    """a/r = 1e-3: the wheel spins ~870 radians per radian of orbit, ~2700
    steps a period; the steady orbit stays put."""
    sim_ = prepare_simulation(*simulation_request(dict(theta=60, alpha=10, a=0.03, r=30, periods=1, points_per_period=10)))
    assert sim_.spin_ratio[0] == pytest.approx(866, rel=0.01)
    _, summary = sim_.run()
    assert str(summary["status"][0]) == "completed"
    assert summary["max_theta_drift_deg"][0] < 1e-9 and summary["max_alpha_drift_deg"][0] < 1e-9


# ---- a run too long to finish: refused up front, or bounded ---------------------------

def test_a_run_over_the_step_budget_is_refused_before_any_work_with_its_estimate():
    with pytest.raises(ParameterError, match="max_steps") as err:
        prepare_simulation(*simulation_request(dict(theta=60, alpha=10, a=1e-3, r=1e3, periods=1)))
    assert "2.7e+06 steps" in str(err.value)


def test_the_budget_can_be_raised_and_the_estimate_is_the_step_cap():
    sim_ = prepare_simulation(*simulation_request(dict(theta=60, alpha=10, a=1e-3, r=1e3, periods=1, max_steps=3_000_000)))
    # one period needs ~pi times the spin ratio steps (the cap h <= 2 / S)
    assert sim_.estimated_steps == pytest.approx(np.pi * sim_.spin_ratio[0], rel=1e-3)
    assert 2.7e6 < sim_.estimated_steps < 2.75e6
    # and is integrated in pieces of a bounded number of steps
    assert sim_.pieces_per_chunk * runner._STEPS_PER_CALL >= sim_.estimated_steps
    assert sim_.n_progress == sim_.pieces_per_chunk > 100


def test_the_default_table1_run_is_well_within_the_budget():
    sim_ = prepare_simulation(*simulation_request(dict(theta=60, alpha=10)))
    assert sim_.estimated_steps < 1000 and sim_.pieces_per_chunk == 1 and sim_.n_progress == sim_.n_chunks


def test_a_run_over_the_step_budget_is_refused_on_the_command_line_in_one_line(run):
    _one_line_usage_error(_cli(run, "-a", "1e-3", "-r", "1e3", "--periods", "1"), "steps", "--max-steps")
    _one_line_usage_error(_cli(run, "--max-steps", "0"), "max_steps")


def test_memory_is_bounded_by_splitting_long_periods(monkeypatch):
    """Each solve_ivp call keeps all its steps; with many steps per period
    the period is split into calls of about _STEPS_PER_CALL steps by the
    estimate, and progress is reported piece by piece.  The
    result agrees with the unsplit run."""
    starts = sim.horizontal_starts(Setup(a=0.03, r=30.0), 60.0, 10.0, perturb_deg=1e-3)
    whole, whole_summary = sim.Simulation(starts, periods=1, points_per_period=10).run()

    kept = []
    real = integrator.solve_ivp

    def counting(*args, **kwargs):
        out = real(*args, **kwargs)
        kept.append(len(out.t))
        return out

    monkeypatch.setattr(runner, "_STEPS_PER_CALL", 400)
    monkeypatch.setattr(integrator, "solve_ivp", counting)   # the one call every run goes through
    split = sim.Simulation(starts, periods=1, points_per_period=10)
    assert split.pieces_per_chunk == 7
    calls = []
    pieces, summary = split.run(progress=lambda done, total: calls.append((done, total)))
    # the kick costs error-controlled steps beyond the cap's estimate, but
    # no call keeps more than a bounded share of the run
    assert len(kept) >= 7 and sum(kept) > 5000 and max(kept) < 1000
    assert calls == [(i, 7) for i in range(1, 8)]
    assert len(pieces) == len(whole) == 11
    np.testing.assert_allclose(pieces["theta_deg"], whole["theta_deg"], rtol=0, atol=1e-7)
    np.testing.assert_allclose(pieces["alpha_deg"], whole["alpha_deg"], rtol=0, atol=1e-7)
    assert str(summary["status"][0]) == str(whole_summary["status"][0]) == "completed"


# ---- rtol below what solve_ivp honours ----------------------------------------

def test_rtol_below_100_eps_is_refused():
    with pytest.raises(ParameterError, match="rtol"):
        prepare_simulation(*simulation_request(dict(theta=60, alpha=10, rtol=1e-14)))
    starts = sim.horizontal_starts(Setup(), 60.0, 10.0)
    with pytest.raises(ValueError, match="100 eps"):
        sim.Simulation(starts, rtol=1e-14)


def test_rtol_below_100_eps_is_refused_on_the_command_line_in_one_line(run):
    _one_line_usage_error(_cli(run, "--rtol", "1e-14"), "--rtol", "2.22045e-14")


def test_the_least_rtol_allowed_is_honoured_without_a_warning():
    assert RTOL_MIN == 100 * np.finfo(float).eps
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _, summary = deathsphere.simulate(60, 10, periods=0.05, points_per_period=20, rtol=RTOL_MIN)
    assert summary["rtol"][0] == RTOL_MIN and str(summary["status"][0]) == "completed"
