"""The machine's exact equations of motion and the stability of its steady
orbits (docs/machine.md sec. 5): the paper's wheel is the house's wheel
state by state and mode by mode; eq. M8 is a fixed point of the full
equations for any machine."""

import numpy as np
import pytest

from machine_calls import Params as MachineParams
from machine_calls import jacobian as machine_jacobian
from machine_calls import orbit as ride_orbit
from machine_calls import orbit_state as machine_orbit_state
from machine_calls import rhs as machine_rhs
from machine_calls import stability as machine_stability
from machine_calls import tilts as solve_alpha_for_speed

from deathsphere.physics import dynamics as dyn
from deathsphere.records.machine_presets import as_machine
from deathsphere.physics.stability import wheel_stability
from deathsphere.physics.stability.verdict import Verdict

G = 9.80665


def _wheel(a, r, k, m=2.0):
    i = k * m * a * a
    return MachineParams(a, 0.0, r, a, G, m, i, 2 * i, i, 2 * i)


@pytest.mark.parametrize("a, r, k", [(0.3, 3.0, 0.5), (0.5, 1.5, 0.25)])
def test_the_papers_wheel_has_the_houses_equations_of_motion(a, r, k):
    """Not only on the orbit: at perturbed states too (the wheel's
    equations, physics.dynamics, derived separately in docs/dynamics.md)."""
    rng = np.random.default_rng(3)
    th = np.radians(rng.uniform(40, 150, 40))
    al = np.radians(rng.uniform(5, 40, 40))
    bp = dyn.body_params(a, r, k, G)
    X, _ = dyn.wheel_orbit_state(th, al, a, r, k, G)
    keep = np.all(np.isfinite(X), axis=0)
    X = dyn.project(X[:, keep] + 0.02 * rng.standard_normal((9, keep.sum())), bp)
    ref = dyn.rhs(X, bp)
    got = machine_rhs(X, _wheel(a, r, k))
    assert np.max(np.abs(got - ref)) < 1e-11 * np.max(np.abs(ref))


def test_eq_m8_is_a_fixed_point_of_the_full_equations():
    """The steady orbit of eq. M8 (rate, spin) placed in the exact equations
    in the frame turning at Omega: every rate vanishes, for machines with a
    round tyre and any inertia."""
    rng = np.random.default_rng(5)
    n = 300
    p = MachineParams(0.3, rng.uniform(0, 0.2, n), rng.uniform(1.5, 6, n), rng.uniform(0.3, 1.2, n), G, 150.0,
                      rng.uniform(5, 30, n), rng.uniform(20, 40, n), rng.uniform(5, 30, n), rng.uniform(0, 2, n))
    th = np.radians(rng.uniform(30, 170, n))
    al = np.radians(rng.uniform(-10, 80, n))
    res = ride_orbit(th, al, p.r, G, p.mass, p.h, p.a, p.t, p.pitch, p.yaw, p.spin, p.h + 1)
    ok = np.isfinite(res["omega"]) & (res["status"] != 1)
    assert ok.sum() > 100
    X, om = machine_orbit_state(th[ok], al[ok], MachineParams(*(np.broadcast_to(x, (n,))[ok] for x in p)))
    np.testing.assert_allclose(om, res["omega"][ok], rtol=1e-13)
    rates = machine_rhs(X, MachineParams(*(np.broadcast_to(x, (n,))[ok] for x in p)), om)
    scale = np.abs(om) * (np.abs(X[6:9]).max(axis=0) + 1)
    assert np.max(np.abs(rates) / scale) < 1e-11


def test_the_papers_wheel_has_the_houses_stability():
    a, r, k = 0.3, 3.0, 0.5
    th, al = np.meshgrid(np.radians(np.linspace(30, 160, 14)), np.radians(np.linspace(-30, 80, 12)))
    th, al = th.ravel(), al.ravel()
    ws = wheel_stability(th, al, a, r, k, G)
    ms = machine_stability(th, al, _wheel(a, r, k))
    known = np.isfinite(ws["growth_rate"])
    assert known.sum() > 60
    np.testing.assert_array_equal(np.isfinite(ms["growth_rate"]), known)
    diff = np.abs(ms["growth_rate"][known] - ws["growth_rate"][known]) / ws["rate_scale"][known]
    assert np.max(diff) < 1e-8
    np.testing.assert_allclose(ms["freq_fast"][known], ws["freq_fast"][known], rtol=1e-9)
    np.testing.assert_allclose(ms["freq_slow"][known], ws["freq_slow"][known], rtol=1e-8, atol=1e-9)
    np.testing.assert_array_equal(ms["verdict"][known], ws["verdict"][known])
    assert {Verdict.STABLE, Verdict.UNSTABLE} <= set(ws["verdict"][known].tolist())


def test_an_unsteered_motorcycle_is_unstable_on_most_orbits():
    p = MachineParams(0.3, 0.045, 2.4384, 0.8, G, 165.0, 25.0, 40.0, 20.0, 0.8)
    th, al = np.meshgrid(np.radians(np.linspace(60, 170, 12)), np.radians(np.linspace(-5, 60, 14)))
    st = machine_stability(th.ravel(), al.ravel(), p)
    known = np.isfinite(st["growth_rate"])
    assert known.sum() > 50
    assert np.mean(st["verdict"][known] == Verdict.UNSTABLE) > 0.9


@pytest.mark.parametrize("machine", ["stunt125", "benchmark-bicycle-rigid"])
def test_the_reduced_jacobian_is_reversible(machine):
    """The stability takes the eigenvalues from two invariants of K, which
    holds only if the odd coefficients of its characteristic polynomial
    vanish (lambda -> -lambda): checked on K itself, and the eigenvalues
    against a general eigenvalue solver."""
    m = as_machine(machine)
    p = MachineParams(m.wheel_radius, m.tyre_radius, 2.4384, m.com_height, G, m.mass, *m.inertia, m.spin_inertia)
    th, al = np.meshgrid(np.radians(np.linspace(20, 170, 16)), np.radians(np.linspace(-20, 70, 16)))
    K, scale, _ = machine_jacobian(th.ravel(), al.ravel(), p)
    known = np.isfinite(scale)
    assert known.sum() > 100
    K, s = K[known], scale[known][:, None]
    ev = np.linalg.eigvals(K)
    # coefficients of lambda^3 and lambda: -sum of the eigenvalues, -sum of their triple products
    c3 = np.sum(ev, axis=1)
    c1 = np.array([np.sum([e[i] * e[j] * e[k] for i, j, k in ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3))])
                   for e in ev])
    assert np.max(np.abs(c3) / s[:, 0]) < 1e-11
    assert np.max(np.abs(c1) / s[:, 0] ** 3) < 1e-11
    st = machine_stability(th.ravel(), al.ravel(), p)
    growth = np.max(ev.real, axis=1)
    np.testing.assert_allclose(st["growth_rate"][known], np.maximum(growth, 0), atol=1e-6 * s.max())


def _simulate(theta_deg, alpha_deg, p, periods, kick=1e-6):
    from scipy.integrate import solve_ivp

    from deathsphere.physics.machine_dynamics import machine_geometry

    th, al = np.radians([theta_deg]), np.radians([alpha_deg])
    X0, om = machine_orbit_state(th, al, p)
    X = X0[:, 0].copy()
    X[6:9] += kick * abs(om[0]) * np.array([0.3, -0.5, 0.2])      # a kick of the angular velocity
    T = periods * 2 * np.pi / om[0]
    sol = solve_ivp(lambda t, y: machine_rhs(y[:, None], p, om)[:, 0], (0, T), X, rtol=1e-11, atol=1e-13,
                    dense_output=True)
    ts = np.linspace(0, T, 400)
    Y = sol.sol(ts)
    _, e3, _, P = machine_geometry(Y[0:3], Y[3:6], p.a, p.t)
    dtheta = np.arccos(P[2] / np.linalg.norm(P, axis=0)) - th[0]
    dalpha = np.arcsin(-e3[2]) - al[0]
    return ts, np.hypot(dtheta, dalpha), machine_stability(th, al, p)


STUNT = MachineParams(0.3, 0.045, 2.4384, 0.8, G, 165.0, 25.0, 40.0, 20.0, 0.8)


@pytest.mark.parametrize("alpha_deg", [10.0, 18.0])
def test_simulation_confirms_an_unstable_machine_orbit(alpha_deg):
    """The equator of a 16-ft globe: at alpha = 10 deg a real pair of
    eigenvalues (capsize), at 18 deg a complex quartet (a growing
    nutation); the full nonlinear equations grow a small kick at the
    linearisation's growth rate."""
    ts, dev, st = _simulate(90.0, alpha_deg, STUNT, periods=2.5 if alpha_deg < 15 else 6)
    lam = st["growth_rate"][0]
    assert st["verdict"][0] == Verdict.UNSTABLE and lam > 1.0
    late = ts > ts[-1] / 2
    # the envelope of the deviation: a growing nutation oscillates within it
    t_peaks = [ts[late][i] for i in range(1, late.sum() - 1)
               if dev[late][i] >= dev[late][i - 1] and dev[late][i] >= dev[late][i + 1]]
    d_peaks = [dev[late][i] for i in range(1, late.sum() - 1)
               if dev[late][i] >= dev[late][i - 1] and dev[late][i] >= dev[late][i + 1]]
    if len(t_peaks) >= 2:
        rate = np.polyfit(t_peaks, np.log(d_peaks), 1)[0]
    else:
        rate = np.polyfit(ts[late], np.log(dev[late]), 1)[0]
    assert rate == pytest.approx(lam, rel=0.03)


def test_a_narrow_stable_band_on_the_equator_is_stable_in_the_full_equations():
    """Between the capsize pair's passage through zero (alpha ~ 14.6 deg)
    and the collision of the two nutations (~ 15.8 deg) the equator's
    orbits are stable: at alpha = 15 deg a kick stays bounded over six
    periods (an unstable orbit with the growth rate of its neighbours, 2 /s,
    would grow 10^6-fold)."""
    ts, dev, st = _simulate(90.0, 15.0, STUNT, periods=6)
    assert st["verdict"][0] == Verdict.STABLE
    first = ts <= ts[-1] / 2
    assert dev[~first].max() < 3 * dev[first].max()
    assert dev.max() < 1e-3


def _energy_run(theta_deg, alpha_deg, p, duration, kick):
    from scipy.integrate import solve_ivp

    from machine_calls import energy as machine_energy
    from machine_calls import residuals as machine_residuals
    from machine_calls import start as machine_start

    X, om = machine_start(np.radians([theta_deg]), np.radians([alpha_deg]), np.radians(kick), p)
    sol = solve_ivp(lambda t, y: machine_rhs(y[:, None], p)[:, 0], (0, duration), X[:, 0], rtol=1e-10,
                    atol=1e-12, dense_output=True, method="DOP853")
    Y = sol.sol(np.linspace(0, duration, 200))
    energy, kinetic = machine_energy(Y, p)
    res = machine_residuals(Y, p)
    return energy, kinetic, res, Y


@pytest.mark.parametrize("theta_deg, alpha_deg, machine, duration", [
    (90.0, 10.0, STUNT, 1.5),                                                      # round tyre, spinning wheels
    (120.0, 25.0, MachineParams(0.35, 0.08, 3.0, 1.1, G, 120.0, 30.0, 22.0, 14.0, 1.5), 1.0),   # I_p > I_y
    (60.0, 30.0, MachineParams(0.3, 0.0, 2.5, 0.9, G, 90.0, 12.0, 18.0, 9.0, 0.4), 1.0),       # knife edge
])
def test_a_kicked_machine_conserves_energy(theta_deg, alpha_deg, machine, duration):
    """The pitch constraint's reaction is the ideal one (docs/machine.md
    sec. 5): it does no work, so the energy of the full equations is
    conserved to the integrator's tolerance (rtol 1e-10) while a kick
    changes the kinetic energy by 0.3-25 %.  A reaction that did work -- a
    pure moment about the axle, M_p e1 -- changed the energy by as much as
    the kinetic energy changed."""
    energy, kinetic, res, Y = _energy_run(theta_deg, alpha_deg, machine, duration, kick=0.01)
    assert np.ptp(kinetic) > 2e-3 * kinetic.mean()           # the motion really changed
    assert np.max(np.abs(energy - energy[0])) < 1e-8 * kinetic.mean()
    assert np.max(np.abs(res["contact"])) < 1e-8 and np.max(np.abs(res["axis"])) < 1e-9


def test_the_pitch_reaction_does_no_work_on_any_admissible_motion():
    """At random states and angular velocities (not only near orbits): the
    rate of the energy from the full equations is zero -- the contact's
    reaction does no work by rolling, the pitch constraint's by being
    ideal, gravity is in the energy.  Checked by a complex-step derivative
    of the energy along the equations' own rates."""
    from machine_calls import energy as machine_energy
    from machine_calls import project as machine_project

    rng = np.random.default_rng(11)
    n = 200
    p = MachineParams(0.3, rng.uniform(0, 0.1, n), rng.uniform(2, 5, n), rng.uniform(0.4, 1.2, n), G, 150.0,
                      rng.uniform(5, 30, n), rng.uniform(20, 40, n), rng.uniform(5, 30, n), rng.uniform(0, 2, n))
    th = np.radians(rng.uniform(40, 150, n))
    al = np.radians(rng.uniform(0, 40, n))
    with np.errstate(invalid="ignore"):             # some random (theta, alpha) have no orbit: dropped
        X, _ = machine_orbit_state(th, al, p)
    keep = np.all(np.isfinite(X), axis=0)
    p = MachineParams(*(np.broadcast_to(x, (n,))[keep] for x in p))
    X = X[:, keep]
    X[0:6] += 0.02 * rng.standard_normal((6, keep.sum()))
    X[6:9] += 2.0 * rng.standard_normal((3, keep.sum()))
    X = machine_project(X, p)
    rates = machine_rhs(X, p)
    h = 1e-30
    e_rate = np.imag(machine_energy(X + 1j * h * rates, p)[0]) / h
    kinetic = machine_energy(X, p)[1]
    scale = kinetic * np.sqrt(np.sum(X[6:9] ** 2, axis=0))
    assert np.max(np.abs(e_rate) / scale) < 1e-10


def test_simulation_confirms_a_stable_machine_orbit():
    """High on the wall (theta = 20 deg, alpha = -10.34 deg, ~10 g): the
    linearisation's eigenvalues are all imaginary (nutations of 12.1 and
    37.4 rad/s); the full equations keep a kick bounded over three slow
    nutations: the second half no larger than the first."""
    ts, dev, st = _simulate(20.0, -10.34, STUNT, periods=12)
    assert st["verdict"][0] == Verdict.STABLE
    assert ts[-1] > 3 * 2 * np.pi / st["freq_slow"][0]
    first = ts <= ts[-1] / 2
    assert dev[~first].max() < 1.5 * dev[first].max()
    assert dev.max() < 1e-3


@pytest.mark.parametrize("v", [2.0, 10.0, 30.0])
def test_flat_ground_capsize_mode(v):
    """On flat ground (r = 1e6 m, a 2 km turn: nearly straight and upright)
    the lean mode of the single-contact machine is docs/machine.md eq. M20:
    (I_roll + m h^2) lambda^2 = m g h - (m h v + J v/a) J v / (a I_yaw):
    capsize (real lambda) below the critical speed, a wobble above."""
    m, h, a, t, i_r, i_p, i_y, j = 165.0, 0.8, 0.3, 0.0, 25.0, 40.0, 20.0, 0.8
    # the turn wide enough that the lean (v^2 / g R) stays below 1 %: M20 is upright running's
    r, R = 1e6, max(2000.0, 12.0 * v * v)
    th = np.pi - np.arcsin(R / r)
    roots = solve_alpha_for_speed([th], [v], r, G, m, h, a, t, i_p, i_y, j)[0]
    al = roots[np.isfinite(roots) & (roots > 0) & (roots < np.pi / 2)]
    st = machine_stability(np.array([th]), al, MachineParams(a, t, r, h, G, m, i_r, i_p, i_y, j))
    lam2 = (m * G * h - (m * h * v + j * v / a) * j * v / (a * i_y)) / (i_r + m * h * h)
    ev = st["eigenvalues"][0]
    main = ev[np.argmax(np.abs(ev))]
    assert (main ** 2).real == pytest.approx(lam2, rel=2e-4)
