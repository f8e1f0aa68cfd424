"""The Whipple bicycle's parameters, named as in Meijaard, Papadopoulos,
Ruina & Schwab (2007), "Linearized dynamics equations for the balance and
steer of a bicycle: a benchmark and review", Proc. R. Soc. A 463:1955-1982,
Table 1 (beyond McDonald's paper; docs/two-wheeler.md sec. 1).

Lengths in m, masses in kg, moments of inertia in kg m^2, the steer axis
tilt ``lam`` in rad, gravity ``g`` in m/s^2.  Positions of the mass centres
(xB, zB, xH, zH) are measured from the rear contact in the benchmark's
upright reference frame: x forward, y to the right, z down.  The products of
inertia (IBxz, IHxz) are entries of the inertia tensor, as in the paper.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

__all__ = ["BicycleParameters", "PARAMETER_NAMES", "PRESETS", "SOURCE", "benchmark_bicycle"]

#: Where the preset's numbers come from.
SOURCE = ("Meijaard, Papadopoulos, Ruina & Schwab (2007), Proc. R. Soc. A 463:1955-1982, "
          "Table 1 (the benchmark bicycle)")


@dataclass(frozen=True)
class BicycleParameters:
    """The 26 numbers of the benchmark's Whipple bicycle (Meijaard et al.
    2007, Table 1; beyond McDonald's paper, docs/two-wheeler.md sec. 1).

    The field order is the order in which the generated equations take them
    (:meth:`values`).
    """

    w: float      # wheel base
    c: float      # trail
    lam: float    # steer axis tilt from the vertical, rad
    g: float      # gravity
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

    def values(self) -> tuple[float, ...]:
        """The numbers in :data:`PARAMETER_NAMES` order (Meijaard et al.
        2007, Table 1; docs/two-wheeler.md sec. 1); a subclass's own fields
        (a rider's head point, a name) are not among them."""
        return tuple(getattr(self, name) for name in PARAMETER_NAMES)


#: The names, in the order of the fields (and of the generated code's arguments).
PARAMETER_NAMES = tuple(f.name for f in fields(BicycleParameters))


def benchmark_bicycle() -> BicycleParameters:
    """The benchmark bicycle exactly as Meijaard et al. (2007) Table 1 gives it.

    >>> p = benchmark_bicycle()
    >>> p.w, p.c, round(p.lam, 6), p.mB
    (1.02, 0.08, 0.314159, 85.0)
    """
    return BicycleParameters(
        w=1.02, c=0.08, lam=math.pi / 10, g=9.81,
        rR=0.3, mR=2.0, IRxx=0.0603, IRyy=0.12,
        xB=0.3, zB=-0.9, mB=85.0, IBxx=9.2, IByy=11.0, IBzz=2.8, IBxz=2.4,
        xH=0.9, zH=-0.7, mH=4.0, IHxx=0.05892, IHyy=0.06, IHzz=0.00708, IHxz=-0.00756,
        rF=0.35, mF=3.0, IFxx=0.1405, IFyy=0.28,
    )


#: Named parameter sets.
PRESETS = {"benchmark-bicycle": benchmark_bicycle()}
