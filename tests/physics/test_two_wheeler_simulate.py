"""The Whipple bicycle's nonlinear motion integrated
(deathsphere.physics.two_wheeler.simulate, run by
deathsphere.simulation.two_wheeler), beyond the paper.

Checked against what is known independently: energy is conserved without
a steer torque; the benchmark's published self-stable speed window
(Meijaard et al. 2007: weave speed 4.292 m/s, capsize speed 6.024 m/s) on
flat ground; the linearisation about a steady turn on the globe
(stability.jacobian, by complex steps, a different computation) for a tiny
kick.
"""

import functools

import numpy as np
import pytest
from scipy.linalg import expm

from deathsphere.physics.two_wheeler import motion, stability, steady
from deathsphere.physics.ground import Plane, Sphere
from deathsphere.physics.two_wheeler.parameters import BENCHMARK_GRAVITY, benchmark_bicycle
from deathsphere.physics.two_wheeler.simulate import Kick, Solver, Steering, lock_torque
from deathsphere.simulation.two_wheeler import run_two_wheeler as simulate

GLOBE = 2.4384      # a 16-foot globe's radius, m
SPHERE, FLAT = Sphere(GLOBE), Plane()
#: The benchmark's gravity (Table 1), at which these cases were set: the run passes it.
G = BENCHMARK_GRAVITY
B = benchmark_bicycle()


def _straight(speed):
    q = np.zeros(8)
    q[motion.HEADING] = np.pi / 2
    return q, np.array([0.0, -speed / B.rR, 0.0])


@functools.lru_cache(maxsize=None)
def _globe_turn_found(speed, height):
    lane = np.arccos(height / GLOBE - 1)
    turn = steady.turns_for_speed(lane, speed, B, SPHERE, G)
    return turn["q"][:, 0, 0], turn["u"][:, 0, 0], float(turn["steer_torque"][0, 0])


def _globe_turn(speed=5.0, height=1.0):
    # the scan is sought once per file: each test gets its own copies
    q, u, torque = _globe_turn_found(speed, height)
    return q.copy(), u.copy(), torque


def test_energy_is_conserved_hands_free_on_flat_ground():
    q, u = _straight(4.0)
    _, summary = simulate(B, q, u, 1.0, kick=Kick(np.radians(2.0)), steering=Steering(hands_free=True),
                          solver=Solver(rtol=1e-10))
    assert summary["status"] == "completed"
    assert summary["max_energy_drift"] < 1e-8
    # the front contact's holonomic constraint holds to the tolerance (the rolling ones exactly)
    assert summary["max_constraint_residual"] < 1e-10


def test_energy_is_conserved_hands_free_on_the_globe():
    q, u, _ = _globe_turn()
    series, summary = simulate(B, q, u[list(motion.INDEPENDENT)], 0.5, ground=SPHERE, g=G,
                               kick=Kick(np.radians(0.5)), steering=Steering(hands_free=True), solver=Solver(rtol=1e-10))
    assert summary["max_energy_drift"] < 1e-8
    assert summary["max_constraint_residual"] < 1e-10
    # something moved: the steady turn's torque is not zero, so hands-free it leaves its lean
    assert summary["max_lean_deviation"] > np.radians(0.6)


@pytest.mark.parametrize("speed, stable", [(5.0, True), (3.0, False)])
def test_straight_running_is_self_stable_only_inside_the_benchmark_window(speed, stable):
    q, u = _straight(speed)
    kick = np.radians(0.5)
    series, summary = simulate(B, q, u, 4.0, kick=Kick(kick), steering=Steering(hands_free=True),
                               solver=Solver(rtol=1e-7, n_points=81))
    late = np.max(np.abs(series["lean"][-20:]))
    if stable:
        assert summary["status"] == "completed" and late < 0.6 * kick
    else:
        assert summary["status"] == "contact_lost" or late > 5 * kick


def test_a_tiny_kick_follows_the_linearisation_about_the_steady_turn():
    """The turn at 5 m/s, 1 m up a 16-foot globe, is unstable (growth 1.37/s):
    the kick grows, as exp(J t) applied to it predicts."""
    q, u, torque = _globe_turn()
    eps = 1e-7
    series, _ = simulate(B, q, u[list(motion.INDEPENDENT)], 2.0, ground=SPHERE, g=G, steering=Steering(torque),
                         kick=Kick(eps), solver=Solver(rtol=1e-12, atol=1e-14, n_points=5))
    J = stability.jacobian(q, u, torque, B, SPHERE, G)[0]
    x0 = np.zeros(J.shape[0])
    x0[2] = eps                   # the lean in the state (theta, heading, lean, steer, rates)
    predicted = np.array([(expm(J * t) @ x0)[2] for t in series["t"]])
    deviation = series["lean"] - q[motion.LEAN]
    assert np.max(np.abs(predicted)) > 5 * eps            # it did grow
    np.testing.assert_allclose(deviation, predicted, rtol=1e-3, atol=1e-3 * eps)


def test_a_riders_gains_hold_an_unstable_lane_that_zero_gains_do_not():
    q, u, torque = _globe_turn()
    kick = np.radians(0.2)
    run = dict(ground=SPHERE, g=G, kick=Kick(kick), solver=Solver(rtol=1e-6, n_points=61))
    _, held = simulate(B, q, u[list(motion.INDEPENDENT)], 3.0, steering=Steering(torque, k_lean=10.0, k_rate=10.0),
                       **run)
    _, loose = simulate(B, q, u[list(motion.INDEPENDENT)], 3.0, steering=Steering(torque), **run)
    assert held["status"] == "completed" and abs(held["final_lean_deviation"]) < kick
    assert loose["status"] == "contact_lost" or loose["max_lean_deviation"] > 10 * kick


def test_slip_stops_the_run_when_mu_is_below_the_turns_need():
    q, u, torque = _globe_turn()
    # the turn needs mu 0.209 at the rear, 0.247 at the front (ride's mu_required_*)
    _, summary = simulate(B, q, u[list(motion.INDEPENDENT)], 0.5, ground=SPHERE, g=G, steering=Steering(torque),
                          mu=0.2, solver=Solver(rtol=1e-6))
    assert summary["status"] == "slips" and summary["t_event"] < 1e-3


def test_the_contact_forces_at_a_steady_turn_are_the_steady_turns():
    """The run's forces (multipliers and the mass centre's acceleration by
    differences) against steady.turn_state's (the turn's rotation about the
    vertical, in closed form)."""
    q, u, torque = _globe_turn()
    lane = np.arccos(1.0 / GLOBE - 1)
    turn = steady.turns_for_speed(lane, 5.0, B, SPHERE, G)
    series, _ = simulate(B, q, u[list(motion.INDEPENDENT)], 0.1, ground=SPHERE, g=G, steering=Steering(torque),
                         solver=Solver(rtol=1e-10, n_points=3))
    for key in ("normal_rear", "normal_front", "friction_rear", "friction_front"):
        np.testing.assert_allclose(series[key], turn[key][0, 0], rtol=1e-6)


def _flat_turn(radius=10.0, speed=5.0):
    turn = steady.turns_for_speed(1 / radius, speed, B, FLAT, G)
    return turn["q"][:, 0, 0], turn["u"][:, 0, 0], float(turn["steer_torque"][0, 0])


@pytest.mark.parametrize("ground", [FLAT, SPHERE], ids=["plane", "sphere"])
def test_a_locked_steer_holds_its_angle_and_conserves_energy(ground):
    """No torque does work on a steer that does not turn; the lock's torque
    (the reduced steer row) is what the full equations with the contact
    multipliers need to keep the steer's acceleration zero."""
    q, u, torque = _flat_turn() if ground == FLAT else _globe_turn()
    run = dict(ground=ground, g=G, steering=Steering(locked=True), solver=Solver(rtol=1e-10, n_points=7))
    values = motion.parameter_values(B, G, ground)
    # unkicked, the lock holds the steady turn's torque (turn_state's G + w^2 H)
    T0, a0, _ = lock_torque(q, u[list(motion.INDEPENDENT)], values, ground)
    assert T0 == pytest.approx(torque, rel=1e-9) and np.max(np.abs(a0)) < 1e-9
    series, summary = simulate(B, q, u[list(motion.INDEPENDENT)], 0.2, kick=Kick(np.radians(1.0), lean_rate=0.1),
                               **run)
    assert summary["status"] == "completed" and summary["max_energy_drift"] < 1e-8
    assert summary["max_constraint_residual"] < 1e-10
    assert np.all(series["steer"] == q[motion.STEER]) and np.all(series["steer_rate"] == 0)
    assert summary["max_lean_deviation"] > np.radians(1.1)        # it falls, the steer does not help
    assert abs(series["steer_torque"][-1] - torque) > 1e-3
    # off the turn (leaning 2 degrees more, lean rate 0.3 rad/s), the full equations with the
    # lock's torque leave the steer unaccelerated, and without it they do not
    q1 = q.copy()
    q1[motion.LEAN] += np.radians(2.0)
    q1 = motion.pitch(q1, values, ground)
    u_ind = np.array([0.3, u[motion.REAR], 0.0])
    T, _, u1 = lock_torque(q1, u_ind, values, ground)
    udot, _ = motion.accelerations(q1, u1, values, T, ground)
    assert abs(udot[motion.STEER]) < 1e-9 * np.max(np.abs(udot))
    free, _ = motion.accelerations(q1, u1, values, 0.0, ground)
    assert abs(free[motion.STEER]) > 1e-3


def test_kicks_of_the_lean_and_steer_rates_start_there_and_conserve_energy():
    q, u = _straight(4.0)
    series, summary = simulate(B, q, u, 0.2, steering=Steering(hands_free=True),
                               kick=Kick(lean_rate=0.2, steer_rate=-0.5), solver=Solver(rtol=1e-10, n_points=4))
    assert series["lean_rate"][0] == 0.2 and series["steer_rate"][0] == -0.5
    assert series["v_rear"][0] == pytest.approx(4.0, rel=1e-12)
    # the kick moved the heading: the dependent speeds followed the steer rate
    assert abs(series["heading"][-1] - np.pi / 2) > 1e-3
    assert summary["max_energy_drift"] < 1e-8 and summary["max_constraint_residual"] < 1e-10
