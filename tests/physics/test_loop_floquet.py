"""Floquet stability of a wheel's vertical loop inside a closed profile
(physics/stability/loop_floquet.py; beyond the paper, docs/stability.md
sec. 2.1): on a sampled sphere against the globe's own analysis (the
sphere's equations of motion, physics/stability/floquet.py), and on an egg
against the nonlinear flow integrated by scipy over laps (a monodromy by
finite differences of kicked runs: no dual numbers, no reversal)."""

import numpy as np
import pytest
from sampled_grounds import sampled_sphere
from scipy.integrate import solve_ivp

from deathsphere.physics import dynamics_on as don
from deathsphere.physics.ground import Profile
from deathsphere.physics.meridian_loop import Loop
from deathsphere.physics.stability.floquet import REVERSAL, vertical_floquet
from deathsphere.physics.stability.loop_floquet import loop_floquet_on, loop_neutral_basis_on, loop_state_on
from deathsphere.physics.stability.verdict import Verdict

G = 9.80665
R = 3.0


@pytest.fixture(scope="module")
def sphere_loop():
    """The globe of radius 3 m sampled at 2001 points from its bottom to its top."""
    return Loop.of(sampled_sphere(R))


@pytest.fixture(scope="module")
def egg_loop():
    """An egg (not a sphere): rho = 3 sin u, z = 3 cos u + 0.4 cos^2 u, its pointed end up."""
    u = np.linspace(np.pi, 0.0, 1201)
    return Loop.of(Profile(np.abs(3 * np.sin(u)), 3 * np.cos(u) + 0.4 * np.cos(u) ** 2))


#: An unstable and a stable loop inside the egg (found by scanning k and the top speed near the least).
EGG_LOOPS = dict(v_top=np.array([3.3454, 3.742]), a=np.array([1.5, 1.2]), k=np.array([0.1, 0.1]))


@pytest.fixture(scope="module")
def egg_floquet(egg_loop):
    return loop_floquet_on(egg_loop, EGG_LOOPS["v_top"], EGG_LOOPS["a"], EGG_LOOPS["k"], G)


def test_one_dual_pass_gives_the_rates_and_their_derivatives(egg_loop):
    p = don.ground_body(egg_loop.ground, np.array([0.5, 1.0]), np.array([0.5, 0.1]), G)
    X = loop_state_on(egg_loop.z[-1], np.array([4.0, 5.0]), p.a)
    X = don.project_on(X + np.array([0.2, 0.05, 0.0, 0.0, 0.0, 0.1, 0.3, 0.0, 0.2])[:, None], p)   # off the axis
    d = np.random.default_rng(1).normal(size=(9, 3, 2))
    f, jd = don.rhs_jvp_on(X, d, p)
    np.testing.assert_allclose(f, don.rhs_on(X, p), rtol=0, atol=1e-13)
    np.testing.assert_allclose(jd, don.jvp_on(X, d, p), rtol=0, atol=1e-12)


def test_the_mirror_through_the_axis_reverses_the_flow_on_a_profile(egg_loop):
    """G f(X) = -f(G X) (G: x -> -x of c, e1, w), which the half lap's
    reversal needs, holds on any surface of revolution: the egg's rates at a
    state off the loop and at its mirror."""
    p = don.ground_body(egg_loop.ground, 0.7, 0.3, G)
    X = loop_state_on(egg_loop.z[-1], 4.0, np.array([0.7]))
    X = don.project_on(X + np.array([0.3, 0.1, -0.2, 0.05, 0.0, 0.1, 0.4, 0.2, -0.1])[:, None], p)
    mirrored = don.rhs_on(REVERSAL[:, None] * X, p)
    np.testing.assert_allclose(REVERSAL[:, None] * don.rhs_on(X, p), -mirrored, rtol=0, atol=1e-11)


def test_on_a_sampled_sphere_the_multipliers_are_the_globes(sphere_loop):
    """A stable and an unstable loop of a wheel half the globe's radius (the
    unstable one in a resonance tongue of a light rim, k = 0.1, found on the
    globe): the globe's nutation pair (or its real pair) to 1e-6, the same
    verdict, and the two further multipliers at 1 (the globe's theta family
    and its further neutral direction)."""
    a, k = 1.5, np.array([0.5, 0.1])
    v = np.array([1.2, 1.1]) * np.sqrt(G * (R - a))
    globe = vertical_floquet(np.pi / 2, v / (R - a), a, R, k, G)
    assert globe["verdict"].tolist() == [Verdict.STABLE, Verdict.UNSTABLE]
    got = loop_floquet_on(sphere_loop, v, a, k, G)
    assert got["verdict"].tolist() == globe["verdict"].tolist()
    np.testing.assert_allclose(got["max_abs"], globe["max_abs"], rtol=1e-6)
    np.testing.assert_allclose(got["period"], globe["period"], rtol=1e-8)
    for mine, theirs in zip(got["multipliers"], globe["multipliers"]):
        pair = theirs[np.argsort(np.abs(theirs - 1.0))[1:]]          # the globe's two off 1
        nearest = [mine[np.argmin(np.abs(mine - m))] for m in pair]
        np.testing.assert_allclose(nearest, pair, rtol=0, atol=1e-6)
        rest = mine[np.argsort(np.abs(mine - 1.0))[:2]]
        np.testing.assert_allclose(rest, 1.0, rtol=0, atol=1e-6)
    assert np.all(got["return_error"] < 1e-7)


@pytest.mark.longest
def test_on_an_egg_kicked_runs_grow_by_the_multipliers_lap_after_lap(egg_loop, egg_floquet):
    """The nonlinear flow (scipy's DOP853 on the equations of motion) from
    the top, and from the top kicked along each of the quotient's four
    directions: the kicks' deviations after n laps, on the same quotient,
    are the n-th power of the one-lap monodromy, so their matrix's largest
    |eigenvalue| ^ (1/n) is max |mu|: 2.18 per lap on the unstable loop (a
    real pair, the loop's plane tilting away), 1 on the stable one
    (bounded); the unkicked run returns to the top after one lap."""
    a, k, v = EGG_LOOPS["a"], EGG_LOOPS["k"], EGG_LOOPS["v_top"]
    floquet = egg_floquet
    assert floquet["verdict"].tolist() == [Verdict.UNSTABLE, Verdict.STABLE]
    T = floquet["period"]
    X0 = loop_state_on(egg_loop.z[-1], v, a)
    p = don.ground_body(egg_loop.ground, a, k, G)
    D = np.concatenate((np.broadcast_to(a, (3, 2)), np.ones((3, 2)), np.broadcast_to(v / a, (3, 2))))
    dspeed = np.zeros((9, 2))
    dspeed[7] = 1.0 / a
    W = loop_neutral_basis_on(X0, p, dspeed, D)                        # (2, 9, 4)
    eps = 1e-6
    starts = np.concatenate([np.column_stack([X0[:, i]] + [X0[:, i] + eps * W[i, :, j] * D[:, i] for j in range(4)])
                             for i in range(2)], axis=1)               # (9, 10): each loop's run, then its kicks
    runs = don.ground_body(egg_loop.ground, np.repeat(a, 5), np.repeat(k, 5), G)
    laps = 2
    sol = solve_ivp(don.ode_on(runs), (0.0, laps * T.max()), starts.reshape(-1), method="DOP853", rtol=1e-7,
                    atol=1e-11, dense_output=True)
    assert sol.success
    for i in range(2):
        assert np.linalg.norm(sol.sol(T[i]).reshape(9, 10)[0:3, 5 * i] - X0[0:3, i]) < 1e-6
        for n in range(1, laps + 1):
            X = sol.sol(n * T[i]).reshape(9, 10)
            ref = X[:, 5 * i]
            Y = np.column_stack([W[i].T @ ((X[:, 5 * i + 1 + j] - ref) / D[:, i]) / eps for j in range(4)])
            grown = np.max(np.abs(np.linalg.eigvals(Y))) ** (1.0 / n)
            assert grown == pytest.approx(floquet["max_abs"][i], rel=1e-4)


def test_a_loop_without_an_orbit_or_with_k_0_is_not_analysed(egg_loop):
    """Too slow to keep contact, k = 0 (singular equations), a wheel that does not fit: no multipliers, no warning."""
    got = loop_floquet_on(egg_loop, np.array([0.5, 4.0, 4.0]), np.array([0.5, 0.5, 3.0]), np.array([0.5, 0.0, 0.5]),
                          G)
    assert got["verdict"].tolist() == [Verdict.UNKNOWN] * 3
    assert not got["analysed"].any()
    for key in ("max_abs", "growth_rate", "period", "return_error"):
        assert np.isnan(got[key]).all()


def test_a_loops_multipliers_do_not_depend_on_the_loops_computed_with_it(egg_loop, egg_floquet):
    """Each loop takes its own number of steps (a loop done waits for the
    others): the egg's unstable loop alone, or beside the stable one, which
    needs 21 steps to its 20."""
    alone = loop_floquet_on(egg_loop, EGG_LOOPS["v_top"][0], EGG_LOOPS["a"][0], EGG_LOOPS["k"][0], G)
    together = egg_floquet
    assert together["analysed"].all()
    np.testing.assert_allclose(together["multipliers"][0], alone["multipliers"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(together["return_error"][0], alone["return_error"], rtol=1e-6)
