"""The named machines of ``--machine`` (docs/machine.md secs. 4 and 7):
McDonald's wheel, the benchmark bicycle with rider, a stunt motorcycle;
each a :class:`~deathsphere.records.machine.Machine` record."""

from __future__ import annotations

import numpy as np

from deathsphere.constants import TABLE1_WHEEL_RADIUS
from deathsphere.errors import ParameterError
from deathsphere.records.machine import Machine

def paper_wheel(a: float = TABLE1_WHEEL_RADIUS, k: float = 0.5, mass: float = 1.0) -> Machine:
    """McDonald's wheel as a machine: h = a, t = 0, inertia (k, 2k, k) m a^2,
    spin inertia 2 k m a^2, the head at the hub (docs/machine.md sec. 4)."""
    i = k * mass * a * a
    return Machine(mass=mass, com_height=a, wheel_radius=a, tyre_radius=0.0, inertia=(i, 2 * i, i), spin_inertia=2 * i,
                   head_height=a, width=0.0,
                   name="paper-wheel", source="McDonald (1993) Table 1: a = 0.3 m k = 1/2 (mass 1 kg: any mass gives "
                   "the same orbits); width 0: the paper's thin wheel")


#: Meijaard, Papadopoulos, Ruina and Schwab (2007), Proc. R. Soc. A 463,
#: 1955-1982, Table 1 (the benchmark bicycle with rider).  Axes: x forward,
#: z down, origin at the rear contact; (mass kg, x m, z m, Ixx, Iyy, Izz, Ixz
#: kg m^2).  Wheels: Izz = Ixx.
BENCHMARK_BODIES = {
    "rear wheel R": (2.0, 0.0, -0.3, 0.0603, 0.12, 0.0603, 0.0),
    "rear frame and rider B": (85.0, 0.3, -0.9, 9.2, 11.0, 2.8, 2.4),
    "front fork and handlebar H": (4.0, 0.9, -0.7, 0.05892, 0.06, 0.00708, -0.00756),
    "front wheel F": (3.0, 1.02, -0.35, 0.1405, 0.28, 0.1405, 0.0),
}
#: The benchmark's wheel radii rR, rF [m] and polar moments IRyy, IFyy [kg m^2].
BENCHMARK_WHEELS = ((0.3, 0.12), (0.35, 0.28))
#: Estimate (not in the benchmark): top of a seated adult rider's head [m].
BENCHMARK_HEAD_ESTIMATE = 1.75
#: Estimate (not in the benchmark): a city bicycle's handlebar, wider than
#: an adult's shoulders (about 0.45 m) [m].
BENCHMARK_WIDTH_ESTIMATE = 0.60


def benchmark_totals():
    """Total mass [kg], centre of mass (x, height) [m] and the inertia
    (Ixx, Iyy, Izz, Ixz) [kg m^2] about it of the benchmark bicycle with
    rider, wheels locked (parallel-axis theorem over the four bodies)."""
    rows = np.array(list(BENCHMARK_BODIES.values()))
    m, x, z = rows[:, 0], rows[:, 1], rows[:, 2]
    mt = m.sum()
    xt, zt = (m * x).sum() / mt, (m * z).sum() / mt
    dx, dz = x - xt, z - zt
    ixx = (rows[:, 3] + m * dz * dz).sum()
    iyy = (rows[:, 4] + m * (dx * dx + dz * dz)).sum()
    izz = (rows[:, 5] + m * dx * dx).sum()
    ixz = (rows[:, 6] - m * dx * dz).sum()
    return float(mt), float(xt), float(-zt), (float(ixx), float(iyy), float(izz), float(ixz))


def benchmark_bicycle_rigid() -> Machine:
    """The benchmark bicycle with rider as one rigid frame on one contact, its
    steer locked (docs/machine.md sec. 7; ``benchmark-bicycle`` names the
    benchmark's own model, the Whipple two-wheeler that steers):
    mass and centre of mass from its Table 1; the locked inertia's diagonal
    in its axes (its product Ixz neglected); one wheel of the mean radius
    a = (rR + rF)/2 with the spin inertia J = a (IRyy/rR + IFyy/rF), which
    keeps the wheels' spin angular momentum at a given speed exact."""
    mt, _, h, (ixx, iyy, izz, _) = benchmark_totals()
    (r_r, i_r), (r_f, i_f) = BENCHMARK_WHEELS
    a = 0.5 * (r_r + r_f)
    return Machine(mass=mt, com_height=h, wheel_radius=a, tyre_radius=0.0, inertia=(ixx, iyy, izz),
                   spin_inertia=a * (i_r / r_r + i_f / r_f), head_height=BENCHMARK_HEAD_ESTIMATE,
                   width=BENCHMARK_WIDTH_ESTIMATE, name="benchmark-bicycle-rigid",
                   source="Meijaard Papadopoulos Ruina Schwab (2007) Table 1; head height and width estimates")


def stunt125() -> Machine:
    """A light 125 cc trail/stunt motorcycle with rider: every number an
    estimate (docs/machine.md sec. 7)."""
    return Machine(mass=165.0, com_height=0.80, wheel_radius=0.30, tyre_radius=0.045, inertia=(25.0, 40.0, 20.0),
                   spin_inertia=0.8, head_height=1.65, width=0.80, name="stunt125",
                   source="estimates (docs/machine.md sec. 7): 90 kg bike + 75 kg rider; "
                   "tyres 70/100-19 and 90/100-16; handlebar 0.8 m")


#: The presets of ``--machine``, by name.
PRESETS = {m.name: m for m in (paper_wheel(), benchmark_bicycle_rigid(), stunt125())}
DEFAULT_MACHINE = "stunt125"


def as_machine(machine) -> Machine:
    """A :class:`Machine` from a Machine or a preset's name."""
    if isinstance(machine, Machine):
        return machine
    if isinstance(machine, str):
        key = machine.strip().lower()
        if key in PRESETS:
            return PRESETS[key]
        raise ParameterError(f"machine must be one of {' | '.join(PRESETS)} or a deathsphere.Machine "
                             f"(got {machine!r})", "machine")
    raise ParameterError(f"machine must be a deathsphere.Machine or a preset's name (got {machine!r})", "machine")
