"""The Whipple bicycle's parameters, named as in Meijaard, Papadopoulos,
Ruina & Schwab (2007), "Linearized dynamics equations for the balance and
steer of a bicycle: a benchmark and review", Proc. R. Soc. A 463:1955-1982,
Table 1 (beyond McDonald's paper; docs/two-wheeler.md sec. 1).

Lengths in m, masses in kg, moments of inertia in kg m^2, the steer axis
tilt ``lam`` in rad.  Table 1's gravity ``g`` is not the body's: it belongs
to the run, and the generated code takes it in its slot of
:data:`PARAMETER_NAMES` (:meth:`BicycleParameters.values`).  Positions of the mass centres
(xB, zB, xH, zH) are measured from the rear contact in the benchmark's
upright reference frame: x forward, y to the right, z down.  The products of
inertia (IBxz, IHxz) are entries of the inertia tensor, as in the paper.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

__all__ = ["BicycleParameters", "PARAMETER_NAMES", "FIELD_NAMES", "BENCHMARK_GRAVITY", "PRESETS", "SOURCE",
           "benchmark_bicycle"]

#: Where the preset's numbers come from.
SOURCE = ("Meijaard, Papadopoulos, Ruina & Schwab (2007), Proc. R. Soc. A 463:1955-1982, "
          "Table 1 (the benchmark bicycle)")
#: The gravity the benchmark is defined at (Table 1, m/s^2): its published
#: eigenvalues, weave and capsize speeds hold at this g, not at standard gravity.
BENCHMARK_GRAVITY = 9.81


@dataclass(frozen=True)
class BicycleParameters:
    """The body of the benchmark's Whipple bicycle: the 25 numbers of
    Meijaard et al. (2007), Table 1, but gravity (beyond McDonald's paper,
    docs/two-wheeler.md sec. 1).

    The field order is the order in which the generated equations take them,
    gravity left out (:meth:`values` puts it in its slot).
    """

    w: float      # wheel base
    c: float      # trail
    lam: float    # steer axis tilt from the vertical, rad
    rR: float     # rear wheel radius
    mR: float
    IRxx: float
    IRyy: float
    xB: float     # rear frame (with rider) mass centre, from the rear contact
    zB: float
    mB: float
    IBxx: float
    IByy: float
    IBzz: float
    IBxz: float
    xH: float     # front frame (fork and handlebar) mass centre
    zH: float
    mH: float
    IHxx: float
    IHyy: float
    IHzz: float
    IHxz: float
    rF: float     # front wheel radius
    mF: float
    IFxx: float
    IFyy: float

    def values(self, g) -> tuple:
        """The generated code's Table 1 arguments, in :data:`PARAMETER_NAMES`
        order, the run's gravity ``g`` (m/s^2) in its slot (Meijaard et al.
        2007, Table 1; docs/two-wheeler.md sec. 1); a subclass's own fields
        (a rider's head point, a name) are not among them."""
        return tuple(g if name == "g" else getattr(self, name) for name in PARAMETER_NAMES)


#: The record's fields, in order: Table 1 without gravity.
FIELD_NAMES = tuple(f.name for f in fields(BicycleParameters))
#: Table 1's 26 names in the order the generated code takes them: the fields
#: with gravity after the steer axis tilt.
PARAMETER_NAMES = FIELD_NAMES[:3] + ("g",) + FIELD_NAMES[3:]


def benchmark_bicycle() -> BicycleParameters:
    """The benchmark bicycle exactly as Meijaard et al. (2007) Table 1 gives
    it, but its gravity, :data:`BENCHMARK_GRAVITY`, which the run passes.

    >>> p = benchmark_bicycle()
    >>> p.w, p.c, round(p.lam, 6), p.mB
    (1.02, 0.08, 0.314159, 85.0)
    """
    return BicycleParameters(
        w=1.02, c=0.08, lam=math.pi / 10,
        rR=0.3, mR=2.0, IRxx=0.0603, IRyy=0.12,
        xB=0.3, zB=-0.9, mB=85.0, IBxx=9.2, IByy=11.0, IBzz=2.8, IBxz=2.4,
        xH=0.9, zH=-0.7, mH=4.0, IHxx=0.05892, IHyy=0.06, IHzz=0.00708, IHxz=-0.00756,
        rF=0.35, mF=3.0, IFxx=0.1405, IFyy=0.28,
    )


#: Named parameter sets.
PRESETS = {"benchmark-bicycle": benchmark_bicycle()}
