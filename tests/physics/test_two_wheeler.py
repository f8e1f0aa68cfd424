"""The Whipple bicycle (deathsphere.physics.two_wheeler), beyond the paper.

The project's own nonlinear equations (Kane's method in sympy, printed as
numpy code) linearised about upright straight running on flat ground must
give the benchmark of Meijaard, Papadopoulos, Ruina & Schwab (2007),
Proc. R. Soc. A 463:1955-1982: its M, C1, K0, K2, its eigenvalues (Table 2)
and its weave and capsize speeds.  The numbers below are the paper's
published values, used only as expected values; the benchmark is defined
at g = 9.81 m/s^2 (BENCHMARK_GRAVITY), which every comparison passes.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from deathsphere.physics.ground import Plane, Sphere
from deathsphere.physics.two_wheeler import _generated, grounds, linear, motion
from deathsphere.physics.two_wheeler.parameters import BENCHMARK_GRAVITY, PARAMETER_NAMES, PRESETS, benchmark_bicycle

# Meijaard et al. (2007), numerical results for Table 1: the benchmark bicycle's matrices, to 14 digits.
PUBLISHED = {
    "M": [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]],
    "C1": [[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]],
    "K0": [[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]],
    "K2": [[0.0, 76.59734589573222], [0.0, 2.65431523794604]],
}
# Meijaard et al. (2007), numerical results for Table 1: the weave and capsize speeds, m/s.
WEAVE, CAPSIZE = 4.29238253634111, 6.02426201538837
# Meijaard et al. (2007), Table 2: eigenvalues at speeds of 0, 4, 5 and 10 m/s.
TABLE2 = {
    0.0: [-5.53094371765393, -3.13164324790656, 3.13164324790656, 5.53094371765393],
    4.0: [-12.15861426576447, -1.42944427361326, 0.41325331521125 - 3.07910818603206j,
          0.41325331521125 + 3.07910818603206j],
    5.0: [-14.07838969279822, -0.32286642900409, -0.77534188219585 - 4.46486771378823j,
          -0.77534188219585 + 4.46486771378823j],
    10.0: [-24.62459635017404, 0.16105338653172, -3.72016840437287 - 10.90681139476287j,
           -3.72016840437287 + 10.90681139476287j],
}


@pytest.fixture(scope="module")
def matrices():
    return linear.benchmark_matrices(benchmark_bicycle(), BENCHMARK_GRAVITY)


def test_the_preset_is_table_1():
    p = PRESETS["benchmark-bicycle"]
    assert PARAMETER_NAMES[:5] == ("w", "c", "lam", "g", "rR") and len(PARAMETER_NAMES) == 26
    # Table 1's gravity is the run's: the record holds the body, the benchmark's g is passed
    assert (p.w, p.c, p.lam, BENCHMARK_GRAVITY, p.rR, p.rF) == (1.02, 0.08, np.pi / 10, 9.81, 0.3, 0.35)
    assert not hasattr(p, "g") and p.values(BENCHMARK_GRAVITY)[PARAMETER_NAMES.index("g")] == 9.81
    assert (p.mR, p.mB, p.mH, p.mF) == (2.0, 85.0, 4.0, 3.0)
    assert (p.IBxx, p.IByy, p.IBzz, p.IBxz, p.IHxz) == (9.2, 11.0, 2.8, 2.4, -0.00756)


@pytest.mark.parametrize("name", sorted(PUBLISHED))
def test_linearised_equations_are_the_benchmark(matrices, name):
    got, want = getattr(matrices, name), np.array(PUBLISHED[name])
    assert want.shape == got.shape == (2, 2)
    scale = np.abs(want).max()
    # the zeros of C1 and K2 are exact zeros of the equations, not roundings
    assert np.all(got[want == 0] == 0)
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12 * scale)


def test_weave_and_capsize_speeds(matrices):
    assert abs(linear.weave_speed(matrices) - WEAVE) < 1e-10 * WEAVE
    assert abs(linear.capsize_speed(matrices) - CAPSIZE) < 1e-10 * CAPSIZE


@pytest.mark.parametrize("speed", sorted(TABLE2))
def test_eigenvalues_are_table_2(matrices, speed):
    got = linear.eigenvalues(matrices, speed)
    want = np.sort_complex(np.array(TABLE2[speed], dtype=complex))
    np.testing.assert_allclose(np.sort_complex(got), want, rtol=0, atol=1e-12)


def test_the_self_stable_range_is_between_weave_and_capsize(matrices):
    speeds = np.array([4.2, 4.4, 6.0, 6.1])
    stable = (linear.eigenvalues(matrices, speeds).real < 0).all(axis=-1)
    assert stable.tolist() == [False, True, True, False]


def test_upright_straight_running_is_an_equilibrium():
    p = motion.parameter_values(benchmark_bicycle(), BENCHMARK_GRAVITY)
    q = motion.pitch(np.zeros(8), p)
    u = motion.dependent_speeds(q, np.array([0.0, -5.0 / 0.3, 0.0]), p)
    udot, multipliers = motion.accelerations(q, u, p)
    assert q[motion.PITCH] == 0 and u[0] == pytest.approx(5.0) and np.abs(u[[1, 2, 3, 4, 6]]).max() == 0
    assert np.abs(udot).max() < 1e-12
    # the ground carries the weight: the front wheel's normal multiplier (z down)
    # and the two wheels' share follows from the mass centres (statics)
    m = benchmark_bicycle()
    total = 9.81 * (m.mR + m.mB + m.mH + m.mF)
    moment = 9.81 * (m.mB * m.xB + m.mH * m.xH + m.mF * m.w)
    assert -multipliers[4] == pytest.approx(moment / m.w, rel=1e-12) and -multipliers[4] < total


def _initial_state(lean, steer, speed, lean_rate=0.0, steer_rate=0.0):
    p = motion.parameter_values(benchmark_bicycle(), BENCHMARK_GRAVITY)
    q = np.zeros(8)
    q[motion.LEAN], q[motion.STEER] = lean, steer
    q = motion.pitch(q, p)
    u = motion.dependent_speeds(q, np.array([lean_rate, -speed / 0.3, steer_rate]), p)
    return p, np.concatenate([q, u])


def test_energy_is_conserved_without_steer_torque():
    """An independent check of the derived equations: with no torque and
    ideal rolling constraints, T + V is a constant of the motion."""
    p, x0 = _initial_state(lean=0.05, steer=0.1, speed=4.0, lean_rate=0.3)
    sol = solve_ivp(lambda t, x: motion.state_rates(x, p), (0.0, 1.0), x0, method="DOP853",
                    rtol=1e-12, atol=1e-12, dense_output=False)
    assert sol.success
    q, u = sol.y[:8], sol.y[8:]
    e = motion.energy(q, u, p)
    kinetic, _ = _generated.flat_energy(q, u, p)
    assert np.abs(e - e[0]).max() < 1e-8 * abs(e[0])
    # something happened: the bicycle leaned, steered and exchanged energy
    assert np.ptp(q[motion.LEAN]) > 0.02 and np.ptp(kinetic[0]) > 1e-3 * abs(e[0])
    # the holonomic constraint held along the way
    h, _ = _generated.flat_holonomic(q, p)
    assert np.abs(h).max() < 1e-9


def test_the_shipped_code_is_vectorised_over_a_batch():
    p, x0 = _initial_state(lean=0.05, steer=0.1, speed=4.0, lean_rate=0.3)
    x1 = _initial_state(lean=-0.2, steer=0.3, speed=2.0)[1]
    batch = np.stack([x0, x1], axis=1)
    rates = motion.state_rates(batch, p)
    assert rates.shape == (16, 2)
    np.testing.assert_array_equal(rates[:, 0], motion.state_rates(x0, p))
    np.testing.assert_array_equal(rates[:, 1], motion.state_rates(x1, p))


def test_a_batch_larger_than_a_block_is_the_blocks_joined():
    """The generated code evaluates a large batch in blocks (docs/two-wheeler.md sec. 5): a two-axis batch
    of complex states over three blocks, a parameter and the steer torque varying along it, gives what one
    pass over the whole batch gives."""
    rng = np.random.default_rng(5)
    n = 1500                                    # (3, 1500): 4500 complex states, blocks of 2048
    assert 3 * n > 2 * _generated.BLOCK_BYTES // 16
    q = rng.uniform(-0.3, 0.3, (8, 3, n)) + 1e-3j * rng.uniform(-1, 1, (8, 3, n))
    u = rng.uniform(-2.0, 2.0, (8, 3, n))
    p = list(motion.parameter_values(benchmark_bicycle(), BENCHMARK_GRAVITY))
    p[PARAMETER_NAMES.index("g")] = rng.uniform(9.0, 10.0, n)
    torque = rng.uniform(-1.0, 1.0, (3, 1))
    blocked = _generated.flat_equations(q, u, tuple(p), torque)
    whole = _generated.flat_equations.__wrapped__(q, u, tuple(p), torque)
    for got, expected in zip(blocked, whole):
        assert got.shape == expected.shape and got.shape[-2:] == (3, n)
        np.testing.assert_allclose(got, expected, rtol=1e-14, atol=1e-12)


@pytest.mark.parametrize("ground", [Plane(), Sphere(3.0)], ids=["plane", "sphere"])
def test_the_constraint_matrix_and_the_forcing_at_rest_are_the_equations_own(ground):
    """The generated B alone and Kane's forcing at u = 0 (docs/two-wheeler.md sec. 5) are what the
    equations give at a random state and at rest."""
    rng = np.random.default_rng(6)
    on = grounds.of(ground)
    q = rng.uniform(-0.4, 0.4, (8, 40)) + np.array([np.pi / 2 if isinstance(ground, Sphere) else 0.0] + [0.0] * 7)[:, None]
    u = rng.uniform(-2.0, 2.0, (8, 40))
    p = motion.parameter_values(benchmark_bicycle(), BENCHMARK_GRAVITY, ground)
    equations = on.equations
    _, _, B, _ = equations(q, u, p, 0.7)
    _, rest, _, _ = equations(q, 0 * u, p, 0.7)
    np.testing.assert_allclose(on.constraint_matrix(q, p), B, rtol=1e-13, atol=1e-14)
    np.testing.assert_allclose(on.forcing_at_rest(q, p, 0.7), rest, rtol=1e-12,
                               atol=1e-12 * np.abs(rest).max())


def _shipped_blocks():
    """The shipped _generated.py cut where the generator joins its parts:
    (header, {surface: that surface's functions}).  The generator writes the
    header, then for each surface "\n\n" and its functions; each surface's
    block starts at the decorator of its first function."""
    from deathsphere import codegen
    from deathsphere.physics.two_wheeler.derivation import SURFACES

    shipped = codegen.GENERATED.read_text(encoding="utf-8")
    starts = [shipped.index(f"\n\n@_in_blocks(2)\ndef {s}_equations(") for s in SURFACES]
    assert starts == sorted(starts)
    ends = starts[1:] + [len(shipped)]
    return shipped[:starts[0]], {s: shipped[a + 2:b] for s, a, b in zip(SURFACES, starts, ends)}


def test_the_shipped_header_is_the_generators():
    """The shipped file is the generator's header and the surfaces' blocks,
    nothing else: with each block checked against a fresh derivation below,
    the whole file is what the generator writes today."""
    import sympy as sm

    from deathsphere import codegen
    from deathsphere.physics.two_wheeler.derivation import SURFACES

    header, blocks = _shipped_blocks()
    assert header == codegen._HEADER.format(version=sm.__version__, surfaces=tuple(SURFACES))
    assert codegen.GENERATED.read_text(encoding="utf-8") == header + "".join("\n\n" + blocks[s] for s in SURFACES)
    assert "def _in_blocks" not in header and _generated.BLOCK_BYTES == 32768


@pytest.mark.longest
@pytest.mark.parametrize("surface", ["sphere", "revolution", "flat"])
def test_regenerating_the_shipped_code_changes_nothing(surface):
    """The generator writes today, for each ground, exactly the shipped
    functions of _generated.py, byte for byte (regenerate with
    ``python tools/generate_two_wheeler.py --write``).  One test per ground,
    so that the three derivations (the suite's most expensive work, seconds
    of sympy each: the sphere's and the revolution's about 8 s of CPU with
    their printing, flat ground's 3 s) run side by side on a parallel run.  On flat
    ground the fresh symbolic equations, evaluated at a random state, also
    agree with the shipped numeric code."""
    from deathsphere import codegen
    from deathsphere.physics.two_wheeler import derivation

    d = derivation.derive(surface)
    assert codegen.generated_functions(d) == _shipped_blocks()[1][surface]
    if surface == "flat":
        _fresh_equations_agree_with_the_shipped(d)


def _fresh_equations_agree_with_the_shipped(d):
    import sympy as sm

    rng = np.random.default_rng(7)
    q, u = rng.uniform(-0.5, 0.5, 8), rng.uniform(-2.0, 2.0, 8)
    p = np.array(benchmark_bicycle().values(BENCHMARK_GRAVITY)) * rng.uniform(0.8, 1.2, 26)
    torque = 1.7
    values = dict(zip(d.q, map(sm.Float, q))) | dict(zip(d.u, map(sm.Float, u)))
    values |= dict(zip(d.parameters, map(sm.Float, p))) | {d.steer_torque: sm.Float(torque)}

    def fresh(expr):
        return np.array(sm.Matrix(expr).xreplace(values).evalf(), dtype=float)

    shipped = _generated.flat_equations(q, u, tuple(p), torque)
    for got, expr in zip(shipped, (d.mass_matrix, d.forcing, d.constraint_matrix, d.constraint_bias)):
        want = fresh(expr).reshape(got.shape)
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12 * np.abs(want).max())
    for got, exprs in ((_generated.flat_holonomic(q, tuple(p)), (d.holonomic, d.holonomic_dpitch)),
                       (_generated.flat_energy(q, u, tuple(p)), (d.kinetic, d.potential))):
        for value, expr in zip(got, exprs):
            assert value[0] == pytest.approx(float(fresh([expr])[0, 0]), rel=1e-12, abs=1e-12)


def _sphere_state(r, theta, heading, lean, steer, speed, lean_rate=0.0):
    p = motion.parameter_values(benchmark_bicycle(), BENCHMARK_GRAVITY, Sphere(r))
    q = np.zeros(8)
    q[0], q[motion.HEADING], q[motion.LEAN], q[motion.STEER] = theta, heading, lean, steer
    q = motion.pitch(q, p, Sphere(r))
    u = motion.dependent_speeds(q, np.array([lean_rate, -speed / 0.3, 0.0]), p, Sphere(r))
    return p, np.concatenate([q, u])


def test_energy_is_conserved_on_the_wall_of_a_sphere():
    """Inside a sphere of radius 3 m, on the equator, heading along it and
    leaning into the wall: free motion keeps T + V."""
    p, x0 = _sphere_state(r=3.0, theta=np.pi / 2, heading=np.pi / 2, lean=-1.0, steer=0.05, speed=8.0)
    h, _ = _generated.sphere_holonomic(x0[:8], p)
    assert abs(h[0]) < 1e-12
    sol = solve_ivp(lambda t, x: motion.state_rates(x, p, ground=Sphere(3.0)), (0.0, 0.3), x0,
                    method="DOP853", rtol=1e-12, atol=1e-12)
    assert sol.success
    e = motion.energy(sol.y[:8], sol.y[8:], p, Sphere(3.0))
    assert np.abs(e - e[0]).max() < 1e-8 * abs(e[0])
    # it moved along the wall and its height changed (energy was exchanged)
    assert np.ptp(sol.y[1]) > 0.3 and np.ptp(sol.y[0]) > 1e-3


def test_a_huge_sphere_near_its_floor_is_flat_ground():
    """The sphere's equations tend to the flat ground's as r grows: at the
    floor of a sphere of 1e5 m, lean, rear wheel and steer accelerations
    agree with flat ground's to the curvature's order (w / r = 1e-5); the
    pitch differs by the sag of the floor under the wheel base, w / (2 r)."""
    p_flat, x_flat = _initial_state(lean=0.1, steer=0.2, speed=4.0, lean_rate=0.3)
    p, x = _sphere_state(r=1e5, theta=np.pi - 1e-7, heading=0.0, lean=0.1, steer=0.2, speed=4.0,
                         lean_rate=0.3)
    sag = 1.02 / (2 * 1e5)
    assert abs(x[motion.PITCH] - x_flat[motion.PITCH] - sag) < 0.05 * sag
    flat = motion.state_rates(x_flat, p_flat)[8:][list(motion.INDEPENDENT)]
    sphere = motion.state_rates(x, p, ground=Sphere(1e5))[8:][list(motion.INDEPENDENT)]
    np.testing.assert_allclose(sphere, flat, rtol=1e-4, atol=1e-4 * np.abs(flat).max())
