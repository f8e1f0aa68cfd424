"""Self-stability of the Whipple bicycle's steady turns: the eigenvalues of
the nonlinear equations linearised about a steady turn in the frame turning
with it (beyond the paper; docs/two-wheeler.md sec. 8.3).

The state in the turning frame: on the sphere (theta, heading, lean, steer,
lean rate, rear wheel rate, steer rate); on flat ground (lean, steer, lean
rate, rear wheel rate, steer rate).  Dropped as trivial, because the
equations do not depend on them: the azimuth (the sphere's symmetry about
its vertical axis; on flat ground x, y and the heading), the wheel angles
(round wheels); the pitch is fixed by the other coordinates (holonomic).
With the steer locked, the steer and the steer rate are dropped too (the
steer held at its steady value by whatever torque it takes).

One more direction is trivial: E - T steer (energy less the work of the
constant steer torque) is conserved, so the neighbouring steady turns form a
family and the Jacobian J has a zero eigenvalue along it; its image is the
level set of that integral.  The eigenvalues reported are those of J
restricted to its image (the leading singular vectors): every eigenvalue
of J but that zero.  Seven states give six eigenvalues on the sphere (free
steer; four locked), five give four on flat ground (the benchmark's four
in straight running; two locked).
"""

from __future__ import annotations

import numpy as np

from deathsphere.constants import STANDARD_GRAVITY
from deathsphere.physics.two_wheeler import grounds, motion, steady
from deathsphere.physics.two_wheeler.parameters import BicycleParameters

__all__ = ["STABLE_BELOW", "turn_state_vector", "eigenvalue_count", "jacobian", "jacobians", "eigenvalues",
           "verdict", "kind", "turns_with_stability"]

_STEP = 1e-30
#: A turn is stable when every eigenvalue's real part is below -STABLE_BELOW (1/s).
STABLE_BELOW = 1e-9


def _layout(ground, steer):
    """Indices of the state's coordinates in q and of its speeds in u_ind."""
    coords = list(grounds.of(ground).turning_coordinates)
    coords += [motion.LEAN] + ([motion.STEER] if steer == "free" else [])
    speeds = [0, 1] + ([2] if steer == "free" else [])
    return coords, speeds


def eigenvalue_count(ground, steer="free") -> int:
    """How many eigenvalues a steady turn on ``ground`` has, the steer
    ``free`` or ``locked``: the state's size less the trivial direction
    (beyond the paper; docs/two-wheeler.md sec. 8.3)."""
    coords, speeds = _layout(ground, steer)
    return len(coords) + len(speeds) - 1


def turn_state_vector(q, u, ground, steer="free"):
    """The state (k, ...) of a steady turn on ``ground`` from its q, u (8,
    ...) (beyond the paper; docs/two-wheeler.md sec. 8.3)."""
    coords, speeds = _layout(ground, steer)
    ind = np.asarray(u)[list(motion.INDEPENDENT)]
    return np.concatenate([np.asarray(q)[coords], ind[speeds]])


def _rates(x_coords, x_speeds, q_steady, p, torque, ground):
    """d/dt of the free-steer state (its coordinates x_coords, its speeds
    x_speeds, (k, n) each), the other coordinates at their steady values
    q_steady (8, n); and, from the same evaluation, the locked-steer
    state's rates (the steer row dropped, steer rate 0)."""
    coords, speeds = _layout(ground, "free")
    q = np.array(q_steady, dtype=np.result_type(x_coords, q_steady))
    q[coords] = x_coords
    q = motion.pitch(q, p, ground)
    u_ind = np.zeros((3,) + x_speeds.shape[1:], dtype=np.result_type(q, x_speeds))
    u_ind[speeds] = x_speeds
    mass, forcing, u = motion.reduced_mass_and_forcing(q, u_ind, p, torque, ground)
    out = []
    for mode in ("free", "locked"):
        c, sp = _layout(ground, mode)
        udot = np.linalg.solve(mass[..., sp, :][..., :, sp], forcing[..., sp][..., None])[..., 0]
        out.append(np.concatenate([u[c], np.moveaxis(udot, -1, 0)]))
    return out


def _locked_columns(ground):
    """Where the locked state's directions sit among the free state's."""
    free_c, free_s = _layout(ground, "free")
    locked_c, locked_s = _layout(ground, "locked")
    return [free_c.index(i) for i in locked_c] + [len(free_c) + free_s.index(i) for i in locked_s]


def jacobians(q, u, torque, parameters: BicycleParameters, ground, g=STANDARD_GRAVITY):
    """The Jacobians (n, k, k) of the state's rates at steady turns on
    ``ground`` under gravity ``g`` (q, u (8, n), the steady steer torque
    (n,) held constant), steer free and steer locked, by complex steps, the
    coordinates' in one batch and the speeds' in another (beyond the paper;
    docs/two-wheeler.md sec. 8.3)."""
    p = motion.parameter_values(parameters, g, ground)
    q, u = np.asarray(q, float).reshape(8, -1), np.asarray(u, float).reshape(8, -1)
    x0 = turn_state_vector(q, u, ground, "free")
    k, n = x0.shape
    kc = len(_layout(ground, "free")[0])
    torque = np.broadcast_to(np.asarray(torque, float).reshape(-1), (n,))
    columns = []
    # the speeds' directions leave q, the pitch, B and M real: half the cost of the coordinates' directions
    for group in (np.arange(kc), np.arange(kc, k)):
        m = group.size
        x = np.repeat(x0[:, :, None], m, axis=2).astype(complex)
        x[group, :, np.arange(m)] += 1j * _STEP
        x = x.reshape(k, -1)
        x_coords, x_speeds = (x[:kc], x[kc:].real) if group[0] < kc else (x[:kc].real, x[kc:])
        rates = _rates(x_coords, x_speeds, np.repeat(q[:, :, None], m, axis=2).reshape(8, -1), p,
                       np.repeat(torque[:, None], m, axis=1).reshape(-1), ground)
        columns.append([r.imag.reshape(-1, n, m) / _STEP for r in rates])
    J_free, J_locked = (np.moveaxis(np.concatenate(c, axis=2), 1, 0) for c in zip(*columns))
    return J_free, J_locked[..., _locked_columns(ground)]


def jacobian(q, u, torque, parameters: BicycleParameters, ground, g=STANDARD_GRAVITY, steer="free"):
    """The Jacobian (n, k, k) of the state's rates at steady turns, steer
    ``free`` (under the steady torque held constant) or ``locked``
    (:func:`jacobians`; beyond the paper; docs/two-wheeler.md sec. 8.3)."""
    J_free, J_locked = jacobians(q, u, torque, parameters, ground, g)
    return J_free if steer == "free" else J_locked


def eigenvalues(J):
    """The eigenvalues of J restricted to its image (every eigenvalue but
    the trivial zero along the family of steady turns), sorted by real part,
    largest first, ties by imaginary part: (n, k - 1) (beyond the paper;
    docs/two-wheeler.md sec. 8.3)."""
    U = np.linalg.svd(J)[0][..., :, :-1]
    reduced = np.swapaxes(U, -1, -2) @ J @ U
    values = np.linalg.eigvals(reduced)
    order = np.lexsort((-values.imag, -values.real), axis=-1)
    return np.take_along_axis(values, order, axis=-1)


def verdict(values):
    """'stable' where every real part is below -STABLE_BELOW, 'unstable'
    where one is above it, 'marginal' otherwise, and the growth rate (the
    largest real part, 1/s) (beyond the paper; docs/two-wheeler.md sec. 8.3)."""
    growth = values.real.max(axis=-1)
    out = np.where(growth < -STABLE_BELOW, "stable", np.where(growth > STABLE_BELOW, "unstable", "marginal"))
    return out, growth


def kind(values):
    """``damped``, ``neutral``, ``growing`` or ``unknown`` per row of
    eigenvalues (..., k) ('' where they are NaN: none): the shared
    :func:`~deathsphere.physics.stability.verdict.stability_kind` of the
    growth rate against the spectrum's size, the largest |eigenvalue|
    (beyond the paper; docs/two-wheeler.md sec. 8.3)."""
    from deathsphere.physics.stability.verdict import stability_kind

    values = np.asarray(values)
    return stability_kind(values.real.max(axis=-1), np.abs(values).max(axis=-1))


def turns_with_stability(lane, parameters: BicycleParameters, ground, g=STANDARD_GRAVITY, *, speed=None, torque=None,
                         head=(0.3, -1.7)):
    """Every steady turn of each lane (theta on a Sphere ``ground``,
    curvature on a Plane) under gravity ``g`` at the rear contact's ``speed`` or held with the steer
    ``torque``, and its stability with the steer free under the steady
    torque held constant and with the steer locked: the arrays of
    ``steady.turns_for_speed`` (n, k) plus ``eigenvalues_free`` (n, k, 6 on
    the sphere, 4 on flat ground), ``eigenvalues_locked`` (n, k, 4 or 2),
    ``stability_free``, ``stability_locked`` ('stable', 'marginal',
    'unstable', '' where no turn), ``growth_free``, ``growth_locked`` (1/s)
    (beyond the paper; docs/two-wheeler.md sec. 8.3)."""
    if (speed is None) == (torque is None):
        raise ValueError("give either speed or torque")
    if speed is not None:
        out = steady.turns_for_speed(lane, speed, parameters, ground, g, head)
    else:
        out = steady.turns_for_torque(lane, torque, parameters, ground, g, head)
    found = np.isfinite(out["lean"])
    rows, cols = np.nonzero(found)
    if rows.size:
        both = jacobians(out["q"][:, rows, cols], out["u"][:, rows, cols], out["steer_torque"][rows, cols],
                         parameters, ground, g)
    for mode in ("free", "locked"):
        size = eigenvalue_count(ground, mode)
        values = np.full(found.shape + (size,), np.nan + 0j)
        verdicts = np.full(found.shape, "", dtype="<U8")
        growth = np.full(found.shape, np.nan)
        if rows.size:
            ev = eigenvalues(both[0] if mode == "free" else both[1])
            values[rows, cols] = ev
            verdicts[rows, cols], growth[rows, cols] = verdict(ev)
        out[f"eigenvalues_{mode}"], out[f"stability_{mode}"], out[f"growth_{mode}"] = values, verdicts, growth
    return out
