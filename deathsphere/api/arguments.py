"""Checking the API's arguments once, at its edge: every domain is in
:mod:`deathsphere.params`, every combination rule in the model's validators;
nothing is re-implemented here.  Shared by every command family."""

from __future__ import annotations

import math

import numpy as np

from deathsphere import params
from deathsphere.constants import (
    BODIES,
    SIDES,
    STANDARD_GRAVITY,
    TABLE1_SPHERE_RADIUS,
    TABLE1_WHEEL_RADIUS,
)
from deathsphere.grid import (
    Axis,
    RangeError,
    Segment,
    grid_size,
    parse_segment,
)
from deathsphere.model import (
    Setup,
)
from deathsphere.params import ParameterError
from deathsphere.physics.status import STATUS_LABELS
from deathsphere.table import Table

G = STANDARD_GRAVITY


A = TABLE1_WHEEL_RADIUS


R = TABLE1_SPHERE_RADIUS


INF = math.inf


#: Orbits per chunk of :func:`sweep` (the command line's ``--chunk-size`` default).
CHUNK = 16384


#: Row statuses (``only=`` of :func:`sweep`).
STATUSES = tuple(str(s) for s in STATUS_LABELS)


def checked_array(name: str, value) -> np.ndarray:
    """``value`` (a number, list or array) as a float array whose every
    element is an allowed ``name``; else ParameterError with the reason."""
    if isinstance(value, str):
        raise ParameterError(f"{name} must be a number (got {value!r})", name)
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a number (got {value!r})", name) from None
    reason = params.first_problem(name, arr)
    if reason:
        raise ParameterError(reason, name)
    return arr


def checked_scalar(name: str, value) -> float:
    """One allowed value of ``name`` (a number, or its text as typed on the
    command line; an array of one element is not one value)."""
    if isinstance(value, (list, tuple)) and len(value) == 1:
        value = value[0]
    if np.ndim(value) != 0:
        raise ParameterError(f"{name} takes one value (got an array of shape {np.shape(value)})", name)
    return params.check(name, value)


def checked_optional(name: str, value) -> float | None:
    return None if value is None else checked_scalar(name, value)


def checked_choice(name: str, value, allowed) -> str:
    if not isinstance(value, str):
        raise ParameterError(f"{name} must be one of {' | '.join(allowed)} (got {value!r})", name)
    return params.choice(name, value, allowed)


def broadcast_flat(values: dict[str, np.ndarray]) -> tuple[tuple[int, ...], dict[str, np.ndarray]]:
    """The broadcast shape and every array flattened to it (row-major)."""
    try:
        shape = np.broadcast_shapes(*(v.shape for v in values.values()))
    except ValueError:
        shapes = ", ".join(f"{n} {v.shape}" for n, v in values.items() if v.ndim)
        raise ParameterError(f"the arguments cannot be broadcast together (shapes: {shapes})") from None
    return shape, {n: np.broadcast_to(v, shape).reshape(-1) for n, v in values.items()}


def checked_setup(body, side, a, r, k, g, mu) -> Setup:
    """A :class:`Setup` from one value each (the command's scalar options)."""
    body, side = checked_choice("body", body, BODIES), checked_choice("side", side, SIDES)
    numbers = {name: checked_scalar(name, v) for name, v in (("a", a), ("r", r), ("k", k), ("g", g), ("mu", mu))
               if v is not None}
    try:
        return Setup(body=body, side=side, **numbers)
    except ValueError as exc:  # a combination, e.g. r <= a inside
        raise ParameterError(str(exc)) from None


def is_given(value) -> bool:
    """Whether an optional axis was given (None and an empty list are not)."""
    return value is not None and not (isinstance(value, (list, tuple)) and len(value) == 0)


class ValuesAxis(Axis):
    """An axis of explicit values (an array given to :func:`sweep`): a chunk
    indexes the array, however many values it holds."""

    def __init__(self, values: np.ndarray):
        super().__init__([])
        self._values = np.asarray(values, dtype=float).reshape(-1)

    def __len__(self) -> int:
        return int(self._values.size)

    def take(self, index) -> np.ndarray:
        return self._values[np.asarray(index, dtype=np.int64)]


def checked_segment(name: str, item) -> Segment:
    """One value or ``start:stop:step`` range of ``name``, every value allowed
    (a range is monotone: its ends decide, and it is never built)."""
    if isinstance(item, str) and ":" not in item:
        seg = Segment(params.check(name, item), 0.0, 1, None)
    elif isinstance(item, str):
        try:
            seg = parse_segment(item, name)
        except RangeError as exc:
            raise ParameterError(str(exc).split(": ", 1)[-1], name) from None
    else:
        seg = Segment(float(checked_array(name, item)), 0.0, 1, None)
    reason = params.first_problem(name, [seg.first, seg.last])
    if not reason and params.PARAMS[name].nonzero and Axis([seg]).contains_zero():
        reason = f"{name} must not be 0 ({params.PARAMS[name].allowed()})"
    if reason:
        raise ParameterError(reason, name)
    return seg


def checked_axis(name: str, value, default=None) -> Axis:
    """An axis of a grid from a value, a list or array of values, or text as
    on the command line (``"5:175:1"``, or a list mixing values and ranges,
    in order).  Never materialised; ``default`` (None: NaN, "not given")
    when ``value`` is not given."""
    if not is_given(value):
        return Axis.of([math.nan if default is None else default])
    items = [value] if isinstance(value, str) else value
    if isinstance(items, (list, tuple)) and any(isinstance(v, str) for v in items):
        return Axis([checked_segment(name, v) for v in items])
    return ValuesAxis(np.atleast_1d(checked_array(name, value)).reshape(-1))


def one_default(name: str, value) -> float | None:
    """A default for an input file's missing ``name`` column: one value."""
    if not is_given(value):
        return None
    axis = checked_axis(name, value)
    if len(axis) != 1:
        raise ParameterError(f"with an input file, {name} may give one default value, not a list or range", name)
    return float(axis.take(np.zeros(1, dtype=np.int64))[0])


def checked_grid_size(axes: dict) -> int:
    try:
        return grid_size(axes)
    except RangeError as exc:
        raise ParameterError(str(exc)) from None


def raise_if_all_invalid(table: Table) -> Table:
    """A call none of whose rows can be computed is bad input, not data: raise
    the first row's reason (for one request that is the only reason)."""
    status = table["status"]
    if len(table) and np.all(status == "invalid"):
        raise ParameterError(str(table["reason"][0]))
    return table
