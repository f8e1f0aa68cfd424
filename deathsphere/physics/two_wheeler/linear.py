"""Linearisation of the Whipple bicycle's nonlinear equations about upright
straight running on flat ground: the benchmark's M, C1, K0, K2, the
eigenvalues against speed and the weave and capsize speeds (Meijaard,
Papadopoulos, Ruina & Schwab 2007, the linearised equations and their
numerical results for Table 1; here computed from the project's own equations, docs/two-wheeler.md sec. 7).

The matrices are the derivatives of Kane's reduced equations
(``motion.reduced_residual``) at lean = steer = 0, rear wheel rate -v/rR,
taken by the complex step: each is exact to rounding, no step-size
trade-off.  The linear equations are those of the benchmark,

    M q'' + v C1 q' + (g K0 + v^2 K2) q = f,   q = (lean, steer).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics.two_wheeler import motion
from deathsphere.physics.two_wheeler.parameters import BicycleParameters

__all__ = ["BenchmarkMatrices", "benchmark_matrices", "eigenvalues", "weave_speed", "capsize_speed"]

#: Complex step: far below float64's resolution of any term it touches.
_STEP = 1e-30
#: The rows and columns (lean, steer) among the independent speeds (lean, rear wheel, steer).
_LEAN_STEER = [0, 2]


@dataclass(frozen=True)
class BenchmarkMatrices:
    """M, C1, K0, K2 of Meijaard et al. (2007) (the linearised equations), each (2, 2), rows
    and columns (lean, steer); g the gravity they were taken with."""

    M: np.ndarray
    C1: np.ndarray
    K0: np.ndarray
    K2: np.ndarray
    g: float


def _jacobian(parameters: BicycleParameters, g: float, speed: float) -> np.ndarray:
    """d(lean and steer rows of Kane's reduced equations)/d(lean, steer,
    lean rate, steer rate, lean acc., steer acc.) at upright straight running
    on flat ground under gravity g, by the complex step: (2, 6)."""
    p = motion.parameter_values(parameters, g)
    n = 6
    q = np.zeros((8, n), dtype=complex)
    u_ind = np.zeros((3, n), dtype=complex)
    udot_ind = np.zeros((3, n), dtype=complex)
    u_ind[1] = -speed / parameters.rR
    q[motion.LEAN, 0] = q[motion.STEER, 1] = 1j * _STEP
    u_ind[0, 2] = u_ind[2, 3] = 1j * _STEP
    udot_ind[0, 4] = udot_ind[2, 5] = 1j * _STEP
    q = motion.pitch(q, p)
    residual = motion.reduced_residual(q, u_ind, udot_ind, p)
    return residual.imag[_LEAN_STEER] / _STEP


def benchmark_matrices(parameters: BicycleParameters, g: float = STANDARD_GRAVITY) -> BenchmarkMatrices:
    """M, C1, K0, K2 (Meijaard et al. 2007, the linearised equations) from the project's
    nonlinear equations, under the run's gravity ``g`` (m/s^2; the benchmark's
    published values hold at its g = 9.81, ``parameters.BENCHMARK_GRAVITY``)
    (docs/two-wheeler.md sec. 7).

    K0 is the stiffness at rest per unit g, K2 the stiffness at 1 m/s
    without gravity, C1 the damping at 1 m/s: each exact, because Kane's
    equations are affine in g and quadratic in the speeds.
    """
    at_rest = _jacobian(parameters, g, 0.0)
    moving = _jacobian(parameters, 0.0, 1.0)
    return BenchmarkMatrices(M=at_rest[:, 4:6], C1=moving[:, 2:4], K0=at_rest[:, 0:2] / g,
                             K2=moving[:, 0:2], g=g)


def _state_matrix(m: BenchmarkMatrices, speed):
    """The first-order matrices (..., 4, 4) of x = (lean, steer, lean rate, steer rate)."""
    speed = np.asarray(speed, dtype=float)[..., None, None]
    Minv = np.linalg.inv(m.M)
    K = m.g * m.K0 + speed**2 * m.K2
    C = speed * m.C1
    top = np.broadcast_to(np.hstack([np.zeros((2, 2)), np.eye(2)]), speed.shape[:-2] + (2, 4))
    bottom = np.concatenate([-Minv @ K, -Minv @ C], axis=-1)
    return np.concatenate([top, bottom], axis=-2)


def eigenvalues(m: BenchmarkMatrices, speed) -> np.ndarray:
    """The four eigenvalues at each speed (Meijaard et al. 2007,
    Table 2), sorted by real part then imaginary part: (..., 4) complex.

    Beyond the paper: docs/two-wheeler.md sec. 7.
    """
    values = np.linalg.eigvals(_state_matrix(m, speed))
    order = np.lexsort((values.imag, values.real), axis=-1)
    return np.take_along_axis(values, order, axis=-1)


def _characteristic(m: BenchmarkMatrices, speed):
    """Coefficients (a4, a3, a2, a1, a0) of det(M s^2 + v C1 s + g K0 + v^2 K2)."""
    M, C, K = m.M, speed * m.C1, m.g * m.K0 + speed**2 * m.K2

    def mixed(X, Y):
        return X[0, 0] * Y[1, 1] + Y[0, 0] * X[1, 1] - X[0, 1] * Y[1, 0] - Y[0, 1] * X[1, 0]

    return (np.linalg.det(M), mixed(M, C), mixed(M, K) + np.linalg.det(C), mixed(C, K), np.linalg.det(K))


def _hurwitz(m: BenchmarkMatrices, speed):
    """The Hurwitz determinant a1 a2 a3 - a0 a3^2 - a1^2 a4: zero where a
    pair of eigenvalues crosses the imaginary axis."""
    a4, a3, a2, a1, a0 = _characteristic(m, speed)
    return a1 * a2 * a3 - a0 * a3**2 - a1**2 * a4


def _roots(function, low, high, samples=200):
    """Every sign change of function on [low, high] sampled at ``samples``
    speeds, each refined by Brent's method, in increasing order."""
    speeds = np.linspace(low, high, samples)
    values = np.array([function(v) for v in speeds])
    change = np.nonzero(np.sign(values[:-1]) != np.sign(values[1:]))[0]
    return [brentq(function, speeds[k], speeds[k + 1], xtol=1e-15, rtol=4 * np.finfo(float).eps) for k in change]


def _root(function, low, high, samples=200):
    """The first sign change of function on [low, high], refined by Brent's method."""
    roots = _roots(function, low, high, samples)
    return roots[0] if roots else float("nan")


#: A pair of eigenvalues is on the imaginary axis at a Hurwitz root when its
#: real parts are below this fraction of the largest eigenvalue's size, and
#: it is a complex pair (an oscillation) when its imaginary parts are above it.
AXIS_RTOL = 1e-6


def _weave_crossing(m: BenchmarkMatrices, speed) -> bool:
    """Whether a complex pair of eigenvalues sits on the imaginary axis at
    ``speed`` and lies left of it just above: the weave becoming stable.  The
    Hurwitz determinant also vanishes wherever any two eigenvalues sum to
    zero (a real pair +-x, as the Browser bicycle has at 0.51 m/s), which is
    no crossing at all."""
    at, above = eigenvalues(m, speed), eigenvalues(m, speed * (1 + 1e-6) + 1e-9)
    scale = np.max(np.abs(at))
    on_axis = (np.abs(at.real) <= AXIS_RTOL * scale) & (np.abs(at.imag) > AXIS_RTOL * scale)
    if not on_axis.any():
        return False
    # the pair just above the root: the complex eigenvalues nearest the axis
    frequency = np.abs(at.imag[on_axis]).max()
    near = np.abs(np.abs(above.imag) - frequency) <= 1e-3 * scale + 1e-6 * frequency
    return bool(near.any() and above.real[near].max() < 0.0)


def weave_speed(m: BenchmarkMatrices, low=0.5, high=10.0) -> float:
    """The speed where the weave pair crosses into the left half plane
    (Meijaard et al. 2007: 4.29238253634111 m/s for Table 1 at g = 9.81),
    by Brent's method on the Hurwitz determinant: the first of its roots in
    [low, high] at which a complex pair of eigenvalues crosses the imaginary
    axis into the left half plane (a root where two real eigenvalues sum to
    zero is passed over); nan if none.

    Beyond the paper: docs/two-wheeler.md sec. 7.
    """
    for speed in _roots(lambda v: _hurwitz(m, v), low, high):
        if _weave_crossing(m, speed):
            return speed
    return float("nan")


def capsize_speed(m: BenchmarkMatrices, low=0.5, high=10.0) -> float:
    """The speed where the capsize eigenvalue crosses zero (Meijaard et al.
    2007: 6.02426201538837 m/s for Table 1, at its g = 9.81): the root of
    det(g K0 + v^2 K2) by Brent's method; nan if none in [low, high].

    Beyond the paper: docs/two-wheeler.md sec. 7.
    """
    return _root(lambda v: np.linalg.det(m.g * m.K0 + v**2 * m.K2), low, high)
