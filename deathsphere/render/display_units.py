"""The units a terminal view shows a quantity in beside its SI figure.

The command line knows what was typed (``--diameter 16ft``, ``--speed
40km/h``) and what ``--units`` asks for; it hands a view one
:class:`DisplayUnits` record, built from that, and the view asks it, per
column, which unit to show beside SI (docs/units.md).  The record carries
each unit's factor as a number, so a view converts without pint or the
unit parser: the factors are :mod:`deathsphere.units`'s exact ones,
rounded once by the command line that built the record.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class DisplayUnit:
    """A unit to show: its name, how many of it make one of the API's
    unit (``ft``: 1/0.3048), and that factor in words for a view's source
    column (``× 3.6``; empty when it has no short form)."""

    name: str
    per_api_unit: float
    how: str = ""

    def of(self, value):
        """``value`` (in the API's unit) in this unit; None and NaN as they are."""
        if value is None or isinstance(value, str):
            return value
        return float(value) * self.per_api_unit


#: The crew's units that views show beside SI when nothing else is asked
#: for, by kind: what a rider reads off a speedometer and a rev counter.
KM_H = DisplayUnit("km/h", 3.6, "× 3.6")
RPM = DisplayUnit("rpm", 60.0 / (2.0 * 3.141592653589793), "× 60/2π")


@dataclass(frozen=True)
class DisplayUnits:
    """Which unit a view shows beside SI, per quantity.

    ``typed``: an option (a registry name: ``height``, ``diameter``) typed
    with a unit other than the API's, and that unit; ``kinds``: a kind's
    unit for every quantity of it (``length``: ft when every length typed
    was in ft, or what ``--units imperial`` asks); ``crew``: whether a view
    may add its crew's unit (km/h, rpm) where nothing was asked for
    (``--units si``: no).  The empty record is "as typed" with nothing
    typed: each view's crew units only.
    """

    typed: dict = field(default_factory=dict)
    kinds: dict = field(default_factory=dict)
    crew: bool = True

    def unit(self, kind: str | None, params=(), crew: DisplayUnit | None = None) -> DisplayUnit | None:
        """The unit to show beside SI for a quantity of ``kind`` that was
        typed as one of ``params`` (if any); None: SI alone."""
        for name in (params,) if isinstance(params, str) else params:
            if name in self.typed:
                return self.typed[name]
        if kind in self.kinds:
            return self.kinds[kind]
        return crew if self.crew else None

    def was_typed(self, params=()) -> bool:
        """Whether one of ``params`` was typed in a unit of its own."""
        return any(name in self.typed for name in ((params,) if isinstance(params, str) else params))


#: As typed, with nothing typed: the views' own crew units.
AS_TYPED = DisplayUnits()
