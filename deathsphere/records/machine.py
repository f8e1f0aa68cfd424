"""The record of a single-contact machine (``deathsphere ride``): a
motorcycle and rider as one gyrostat (docs/machine.md), validated once, at
construction: a bad one raises :class:`~deathsphere.ParameterError` with
one line before any work.

Its fields are named as the parameter registry names them
(:data:`deathsphere.params.PARAMS`, see :data:`FIELD_PARAMS`).  It holds the
body only: gravity and the globe belong to the run.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace

import numpy as np

from deathsphere import params
from deathsphere.errors import ParameterError

#: Machine field -> registry parameter (its unit, bounds and option name).
FIELD_PARAMS = {"mass": "mass", "com_height": "com_height", "wheel_radius": "a", "tyre_radius": "tyre_radius",
                "spin_inertia": "spin_inertia", "head_height": "head_height", "width": "width"}
INERTIA_PARAMS = ("roll_inertia", "pitch_inertia", "yaw_inertia")
#: The short keywords of the first Machine (docs/machine.md's symbols h, a,
#: t), still accepted by the constructor so that scripts keep working.
ALIASES = {"h": "com_height", "a": "wheel_radius", "t": "tyre_radius", "head": "head_height"}
#: Relative slack of the rigid-body inequalities (round-off of published numbers).
INERTIA_RTOL = 1e-9
#: Characters an echoed text may not hold: the CSV output promises that
#: ``awk -F,`` splits every row (docs/contract.md, "Output columns").
UNECHOABLE = (",", "\n", "\r")


def _number(field: str, value) -> float:
    pname = FIELD_PARAMS.get(field, field)
    if isinstance(value, str):
        from deathsphere import units

        value = units.parse_value(str(value), params.PARAMS[pname].kind, pname)
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ParameterError(f"machine {field} must be a number (got {value!r})", pname)
    return float(value)


def echoable_text(what: str, value) -> str:
    """``value`` if it is text that can be echoed in every output row (no
    comma, no line break); else ParameterError naming the character."""
    if not isinstance(value, str):
        raise ParameterError(f"{what} must be text (got {value!r})", "machine")
    bad = next((c for c in UNECHOABLE if c in value), None)
    if bad is not None:
        shown = "a comma" if bad == "," else "a line break"
        raise ParameterError(f"{what} {value!r} holds {shown}: every output row echoes it and CSV rows must split "
                             "at each comma (write ';' or a space instead)", "machine")
    return value


@dataclass(frozen=True, kw_only=True)
class Machine:
    """A machine: a rigid frame (motorcycle and rider, wheels locked) with
    axisymmetric wheels spinning about one axle direction, rolling without
    slipping at one contact point (docs/machine.md).

    mass [kg]; com_height [m] height of the centre of mass above the
    contact along the up-axis (upright on flat ground); wheel_radius [m] to
    the tyre's crown; tyre_radius [m] the crown's radius (0: knife edge);
    inertia [kg m^2] (I_roll, I_pitch, I_yaw), principal moments of the
    whole machine with its wheels locked about its centre of mass;
    spin_inertia [kg m^2] the sum of the wheels' polar moments; head_height
    [m] the top of the rider's head above the contact along the up-axis
    (default com_height); width [m] handlebar or the rider's shoulders,
    whichever is wider: the diameter of the rider's envelope in a show
    (None: not known; a show refuses it); name and source describe it.

    The constructor also takes the short keywords of docs/machine.md's
    symbols (:data:`ALIASES`: ``h``, ``a``, ``t``, ``head``).

    >>> Machine(mass=0, h=0.8, a=0.3, inertia=(1, 1, 1), spin_inertia=0.5)
    Traceback (most recent call last):
    ...
    deathsphere.ParameterError: mass (machine mass) must be 1e-09..1e+09 kg (got 0)
    """

    mass: float
    com_height: float
    wheel_radius: float
    tyre_radius: float = 0.0
    inertia: tuple[float, float, float] = (0.0, 0.0, 0.0)
    spin_inertia: float = 0.0
    head_height: float | None = None
    width: float | None = None
    name: str = "custom"
    source: str = ""

    def __post_init__(self):
        set_ = object.__setattr__
        for field in ("name", "source"):
            set_(self, field, echoable_text(f"machine {field}", getattr(self, field)))
        for field, pname in FIELD_PARAMS.items():
            value = getattr(self, field)
            if field == "head_height" and value is None:
                value = self.com_height
            if field == "width" and value is None:
                continue
            value = _number(field, value)
            reason = params.problems(pname, [value])[0]
            if reason:
                raise ParameterError(reason, pname)
            set_(self, field, value)
        inertia = self.inertia
        if isinstance(inertia, (str, bytes)) or np.ndim(inertia) != 1 or len(inertia) != 3:
            raise ParameterError(f"machine inertia must be three numbers (I_roll, I_pitch, I_yaw) (got {inertia!r})",
                                 "roll_inertia")
        values = []
        for pname, value in zip(INERTIA_PARAMS, inertia):
            value = _number(pname, value)
            reason = params.problems(pname, [value])[0]
            if reason:
                raise ParameterError(reason, pname)
            values.append(value)
        set_(self, "inertia", tuple(values))
        if not self.tyre_radius < self.wheel_radius:
            raise ParameterError(f"tyre_radius t ({self.tyre_radius:g} m) must be less than the wheel radius a "
                                 f"({self.wheel_radius:g} m)", "tyre_radius")
        if not self.head_height >= self.com_height:
            raise ParameterError(f"head_height ({self.head_height:g} m) must be at least the centre-of-mass height h "
                                 f"({self.com_height:g} m)", "head_height")
        total = sum(values)
        for pname, value in zip(INERTIA_PARAMS, values):
            if value > total - value + INERTIA_RTOL * total:
                raise ParameterError(
                    f"{pname} ({value:g} kg m^2) exceeds the sum of the other two moments ({total - value:g}): no "
                    "rigid body has these principal moments (triangle inequality)", pname)
        if self.spin_inertia > values[1] * (1 + INERTIA_RTOL):
            raise ParameterError(
                f"spin_inertia ({self.spin_inertia:g} kg m^2) exceeds the pitch inertia ({values[1]:g}) of the whole "
                "machine, which contains the wheels' polar moments", "spin_inertia")

    @property
    def roll_inertia(self) -> float:
        return self.inertia[0]

    @property
    def pitch_inertia(self) -> float:
        return self.inertia[1]

    @property
    def yaw_inertia(self) -> float:
        return self.inertia[2]

    # read access by docs/machine.md's symbols, for the two-wheeler's presets
    # and files, which build on this record and still read them
    @property
    def h(self) -> float:
        return self.com_height

    @property
    def head(self) -> float:
        return self.head_height

    def with_overrides(self, **values) -> Machine:
        """A copy with some parameters replaced, by their registry names
        (``mass``, ``com_height``, ``a``, ``tyre_radius``, ``roll_inertia``,
        ... ``head_height``; ``wheel_radius`` too); None leaves a value as
        it is."""
        given = {k: v for k, v in values.items() if v is not None}
        if not given:
            return self
        by_param = {v: k for k, v in FIELD_PARAMS.items()} | {"wheel_radius": "wheel_radius"}
        changes, inertia = {}, list(self.inertia)
        for key, value in given.items():
            if key in by_param:
                changes[by_param[key]] = value
            elif key in INERTIA_PARAMS:
                inertia[INERTIA_PARAMS.index(key)] = value
            else:
                raise ParameterError(f"unknown machine parameter {key!r}", key)
        return replace(self, **changes, inertia=tuple(inertia), name=f"{self.name} (modified)")

    def row(self) -> dict:
        """The machine as a row of ``deathsphere machines``."""
        return {"name": self.name, "mass_kg": self.mass, "com_height_m": self.com_height,
                "wheel_radius_m": self.wheel_radius, "tyre_radius_m": self.tyre_radius,
                "roll_inertia_kg_m2": self.inertia[0], "pitch_inertia_kg_m2": self.inertia[1],
                "yaw_inertia_kg_m2": self.inertia[2], "spin_inertia_kg_m2": self.spin_inertia,
                "head_height_m": self.head_height, "source": self.source,
                "width_m": math.nan if self.width is None else self.width}


def _with_aliases(init):
    """The dataclass's constructor, taking :data:`ALIASES` too (one of
    each pair)."""

    @functools.wraps(init)
    def __init__(self, **values):
        for old, new in ALIASES.items():
            if old in values:
                if new in values:
                    raise ParameterError(f"machine: give {new} or its short name {old}, not both", FIELD_PARAMS[new])
                values[new] = values.pop(old)
        init(self, **values)

    return __init__


Machine.__init__ = _with_aliases(Machine.__init__)
