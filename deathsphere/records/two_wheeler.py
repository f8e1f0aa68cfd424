"""The two-wheeler's record: a bicycle or motorcycle with its rider as the
Whipple bicycle of Meijaard, Papadopoulos, Ruina & Schwab (2007), its body
only (no gravity, no ground: the run's), validated once at construction
through the parameter registry (:data:`deathsphere.params.PARAMS`), and the
benchmark bicycle as a preset (beyond the paper; docs/two-wheeler.md sec. 1).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from deathsphere import params
from deathsphere.errors import ParameterError
from deathsphere.records.machine import echoable_text
from deathsphere.physics.two_wheeler.parameters import FIELD_NAMES, BicycleParameters, benchmark_bicycle

__all__ = ["TwoWheeler", "DEFAULT_HEAD", "benchmark_two_wheeler"]

#: The rider's head point (x, z) from the rear contact upright when none is
#: given: 1.7 m above the ground over the benchmark's rear frame mass centre
#: (an assumption: the benchmark has no head).
DEFAULT_HEAD = (0.3, -1.7)
_MASSES = ("mR", "mB", "mH", "mF")


def _number(name: str, value) -> float:
    """One of the 25 numbers, checked by the registry (its unit and bounds)."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) \
            or not math.isfinite(value):
        raise ParameterError(f"two-wheeler {params.PARAMS[name].label()} must be a finite number (got {value!r})",
                             "machine")
    problem = params.first_problem(name, [value])
    if problem:
        raise ParameterError(f"two-wheeler {problem}", "machine")
    return float(value)


def _check_geometry(t) -> None:
    """Refuse, in one line with the reason, a two-wheeler that cannot be
    built, whatever the lane: wheels that overlap (the rims, upright in one
    plane, cross) and a body whose mass centre is at or below the ground
    line through the contacts (z is down: the frames stand above the
    ground, so zB and zH are negative where their body has mass)."""
    gap = math.hypot(t.w, t.rR - t.rF) - (t.rR + t.rF)
    if gap < 0:
        raise ParameterError(f"two-wheeler: the wheels overlap: wheel base w = {t.w:g} m is too short for wheels of "
                             f"radius rR = {t.rR:g} m and rF = {t.rF:g} m (their centres are "
                             f"{math.hypot(t.w, t.rR - t.rF):g} m apart, less than rR + rF)", "machine")
    for body, what in (("B", "rear frame"), ("H", "front frame")):
        z = getattr(t, f"z{body}")
        if getattr(t, f"m{body}") > 0 and z >= 0:
            raise ParameterError(f"two-wheeler z{body} = {z:g} m puts the {what}'s mass centre at or below the ground "
                                 f"(z is down from the rear contact: z{body} must be < 0, above the ground)",
                                 "machine")


@dataclass(frozen=True, kw_only=True)
class TwoWheeler(BicycleParameters):
    """A two-wheeler (bicycle or motorcycle with its rider) as the Whipple
    bicycle of Meijaard, Papadopoulos, Ruina & Schwab (2007): the 25
    parameters of their Table 1 but gravity, by the same names and in SI
    (``lam`` in rad; the registry's units and bounds), ``head`` the top of
    the rider's head (x, z) [m] from the rear contact in the upright
    reference configuration (z down, like xB, zB), ``name`` and ``source``
    (docs/two-wheeler.md sec. 1): the physics core's
    :class:`~deathsphere.physics.two_wheeler.parameters.BicycleParameters`
    with a rider's head and a name, checked.  Gravity is the run's.

    >>> TwoWheeler(**{**benchmark_two_wheeler().benchmark_values(), "w": -1.0})
    Traceback (most recent call last):
    ...
    deathsphere.ParameterError: two-wheeler w (wheel base) must be 0.05..10 m (got -1)
    """

    head: tuple[float, float] = DEFAULT_HEAD
    name: str = "custom two-wheeler"
    source: str = ""

    def __post_init__(self):
        set_ = object.__setattr__
        for field in ("name", "source"):
            set_(self, field, echoable_text(f"two-wheeler {field}", getattr(self, field)))
        for name in FIELD_NAMES:
            set_(self, name, _number(name, getattr(self, name)))
        head = self.head
        if isinstance(head, (str, bytes)) or np.ndim(head) != 1 or len(head) != 2 \
                or not all(isinstance(v, (int, float, np.integer, np.floating)) and math.isfinite(v) for v in head):
            raise ParameterError(f"two-wheeler head must be two finite numbers (x, z) in m (got {head!r})", "machine")
        set_(self, "head", (float(head[0]), float(head[1])))
        if not sum(getattr(self, name) for name in _MASSES) > 0:
            raise ParameterError("two-wheeler: the masses mR + mB + mH + mF must add up to more than 0 kg",
                                 "machine")
        _check_geometry(self)
        for body in ("B", "H"):
            ixx, izz, ixz = (getattr(self, f"I{body}{k}") for k in ("xx", "zz", "xz"))
            if ixz * ixz > ixx * izz * (1 + 1e-9):
                raise ParameterError(f"two-wheeler I{body}xz ({ixz:g} kg m^2) is too large for I{body}xx "
                                     f"({ixx:g}) and I{body}zz ({izz:g}): the inertia tensor must be positive "
                                     f"(I{body}xz^2 <= I{body}xx I{body}zz)", "machine")

    def benchmark_values(self) -> dict:
        """The 25 parameters by the benchmark's names (Meijaard et al. 2007, Table 1, but gravity)."""
        return {k: v for k, v in asdict(self).items() if k not in ("head", "name", "source")}

    def parameters(self) -> BicycleParameters:
        """The physics core's :class:`BicycleParameters` (the 25 numbers alone)."""
        return BicycleParameters(**self.benchmark_values())

    @property
    def mass(self) -> float:
        return self.mR + self.mB + self.mH + self.mF

    def row(self) -> dict:
        """The two-wheeler as a row of ``deathsphere machines`` (its
        single-contact columns from the four bodies: total mass, the centre
        of mass's height upright on flat ground, the head's height; the
        rest empty)."""
        m = self.mass
        h = (self.mR * self.rR - self.mB * self.zB - self.mH * self.zH + self.mF * self.rF) / m
        nan = math.nan
        return {"name": self.name, "mass_kg": m, "com_height_m": h, "wheel_radius_m": nan, "tyre_radius_m": nan,
                "roll_inertia_kg_m2": nan, "pitch_inertia_kg_m2": nan, "yaw_inertia_kg_m2": nan,
                "spin_inertia_kg_m2": self.IRyy + self.IFyy, "head_height_m": -self.head[1], "source": self.source,
                "width_m": nan, "kind": "two-wheeler", "wheel_base_m": self.w, "trail_m": self.c,
                "steer_axis_tilt_deg": math.degrees(self.lam), "rear_wheel_radius_m": self.rR,
                "front_wheel_radius_m": self.rF}


def benchmark_two_wheeler() -> TwoWheeler:
    """The benchmark bicycle (Meijaard et al. 2007, Table 1 exactly, but its
    gravity, which the run passes) with the assumed head point."""
    return TwoWheeler(**asdict(benchmark_bicycle()), head=DEFAULT_HEAD, name="benchmark-bicycle",
                      source="Meijaard Papadopoulos Ruina & Schwab (2007) Proc. R. Soc. A 463:1955-1982 Table 1 "
                             "exactly; head point (0.3; -1.7) m an assumption")
