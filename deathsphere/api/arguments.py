"""Checking the API's arguments once, at its edge: every domain is in
:mod:`deathsphere.params`, every combination rule in the model's validators;
nothing is re-implemented here.  Shared by every command family."""

from __future__ import annotations

import math

import numpy as np

from deathsphere import params
from deathsphere.constants import (
    SIDES,
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
from deathsphere.requests.decode import decode_paper_body
from deathsphere.physics.status import STATUS_LABELS
from deathsphere.table import Table

#: The API's defaults, from the parameter registry (one place).
G = params.PARAMS["g"].default
A = params.PARAMS["a"].default
R = params.PARAMS["r"].default
INF = math.inf
#: Orbits per chunk of :func:`sweep` (the command line's ``--chunk-size`` default).
CHUNK = params.CHUNK

#: Row statuses (``only=`` of :func:`sweep`).
STATUSES = tuple(str(s) for s in STATUS_LABELS)


def number_from_text(name: str, text: str) -> float:
    """One value of ``name`` typed as text, with an optional unit suffix
    (``"40km/h"``, ``"8ft"``, ``"-10"`` with a typographic minus, ``"inf"``),
    in the API's unit (:mod:`deathsphere.units`).  Not range-checked."""
    from deathsphere import units

    return units.parse_value(str(text), params.PARAMS[name].kind, name)


def _real_array(name: str, value) -> np.ndarray:
    """``value`` as a float64 array, refusing what is not a real number
    instead of coercing it: complex values (their imaginary part would be
    lost), booleans, masked arrays (their mask would be ignored) and text
    that is not a number (text that is one, with a unit or not, is read)."""
    if np.ma.isMaskedArray(value):
        raise ParameterError(f"{name}: a masked array is not accepted (its mask would be ignored); pass "
                             "np.ma.filled(x, value) or x.compressed()", name)
    if isinstance(value, str):
        return np.asarray(number_from_text(name, value), dtype=float)
    if isinstance(value, (list, tuple)) and any(isinstance(v, str) for v in np.ravel(np.asarray(value, dtype=object))):
        items = np.asarray(value, dtype=object)
        return np.vectorize(lambda v: number_from_text(name, v) if isinstance(v, str) else _one_real(name, v),
                            otypes=[float])(items)
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a number (got {value!r})", name) from None
    if arr.dtype.kind == "c":
        raise ParameterError(f"{name} must be a real number (got the complex {value!r})", name)
    if arr.dtype.kind == "b":
        raise ParameterError(f"{name} must be a number (got the boolean {value!r})", name)
    if arr.dtype.kind in "OUS":
        return np.vectorize(lambda v: _one_real(name, v), otypes=[float])(arr)
    try:
        return arr.astype(float)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a number (got {value!r})", name) from None


def _one_real(name: str, v) -> float:
    if isinstance(v, str):
        return number_from_text(name, v)
    if isinstance(v, (bool, np.bool_)) or isinstance(v, (complex, np.complexfloating)) or v is None:
        raise ParameterError(f"{name} must be a real number (got {v!r})", name)
    try:
        return float(v)
    except (TypeError, ValueError):
        raise ParameterError(f"{name} must be a number (got {v!r})", name) from None


def checked_array(name: str, value) -> np.ndarray:
    """``value`` (a number, text, list or array) as a float array whose every
    element is an allowed ``name``; else ParameterError with the reason."""
    arr = _real_array(name, value)
    reason = params.first_problem(name, arr)
    if reason:
        raise ParameterError(reason, name)
    return arr


def checked_flag(name: str, value) -> bool:
    """A True/False argument: a bool (or numpy bool) only, so that
    ``stability="no"`` is refused rather than read as True."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise ParameterError(f"{name} must be True or False (got {value!r})", name)


def refuse_radius_with_diameter(r, diameter) -> None:
    """A globe is given by its radius or by its diameter: both refused (the
    default radius yields to a diameter)."""
    if diameter is not None and is_given(r) and r is not R:
        raise ParameterError("give the sphere's radius r or its diameter, not both", "diameter")


def sphere_radius(r, diameter):
    """The sphere's radius from ``r`` or ``diameter`` (one of them; a globe
    is sold by its diameter).  Returns ``r`` unchanged when no diameter is
    given (it is checked where it is used, as a scalar or an array)."""
    if diameter is None:
        return r
    refuse_radius_with_diameter(r, diameter)
    d = _real_array("diameter", diameter)
    reason = params.first_problem("diameter", d)
    if reason:
        raise ParameterError(reason, "diameter")
    return d / 2.0 if d.ndim else float(d) / 2.0


def checked_scalar(name: str, value) -> float:
    """One allowed value of ``name`` (a number, or its text as typed on the
    command line; an array of one element is not one value)."""
    if isinstance(value, (list, tuple)) and len(value) == 1:
        value = value[0]
    if np.ndim(value) != 0:
        raise ParameterError(f"{name} takes one value (got an array of shape {np.shape(value)})", name)
    value = float(_real_array(name, value))
    reason = params.problems(name, [value])[0]
    if reason:
        raise ParameterError(reason, name)
    return value


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
    body, side = decode_paper_body(body), checked_choice("side", side, SIDES)
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


def axis_max(axis: Axis) -> float:
    """The largest value of an axis (-inf when empty), a range's without
    materialising it: each segment is monotone, so its largest is an end."""
    if isinstance(axis, ValuesAxis):
        return float(np.max(axis.take(np.arange(len(axis))))) if len(axis) else -math.inf
    return max((max(s.first, s.last) for s in axis.segments), default=-math.inf)


class UnitSegment(Segment):
    """A range written with a unit: each value converted from the decimal
    written with the unit's exact factor (``scale``, a Fraction), rounded
    once (:func:`deathsphere.units.scale_written`), as one number with that
    unit is: ``0:8:2ft`` gives 0.6096, 1.2192, ..., not their round-off."""

    def take(self, i: np.ndarray) -> np.ndarray:
        from deathsphere import units

        v = self.start + self.step * i.astype(float)
        written = v if self.decimals is None else np.round(v, self.decimals)
        return units.scale_written(written, self.decimals, self.scale)


def checked_segment(name: str, item) -> Segment:
    """One value or ``start:stop:step`` range of ``name``, every value allowed
    (a range is monotone: its ends decide, and it is never built)."""
    if isinstance(item, str) and ":" not in item:
        seg = Segment(checked_scalar(name, item), 0.0, 1, None)
    elif isinstance(item, str):
        from deathsphere import units

        number, scale = units.parse_suffix(item, params.PARAMS[name].kind, name)
        try:
            seg = parse_segment(number, name)
        except RangeError as exc:
            raise ParameterError(str(exc).split(": ", 1)[-1], name) from None
        if scale != 1:  # the range in the unit written, each value converted
            seg = UnitSegment(seg.start, seg.step, seg.n, seg.decimals, scale)
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


#: At most this many tilts give a machine one speed: eq. M12 has at most 8
#: zeros per period (:func:`deathsphere.physics.machine.solve_alpha_for_speed`).
TILTS_PER_SPEED = 8


def value_counts(options: dict) -> dict[str, int]:
    """How many values each given option holds (the command line's repeated
    values and ``start:stop:step`` ranges, with units), counted from start,
    stop and step: nothing is built.  Options not given are left out."""
    return {name: len(checked_axis(name, list(v) if isinstance(v, tuple) else v))
            for name, v in options.items() if is_given(v)}


def grid_shape(arrays: dict) -> tuple[int, ...]:
    """The broadcast shape of ``arrays`` from their shapes alone (nothing is
    allocated); ParameterError if they do not broadcast."""
    try:
        return np.broadcast_shapes(*(np.shape(v) for v in arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{n} {np.shape(v)}" for n, v in arrays.items() if np.ndim(v))
        raise ParameterError(f"the arguments cannot be broadcast together (shapes: {shapes})") from None


#: What to do instead when a command that holds its rows cannot stream them.
SPLIT = "split the ranges into several runs"


def refuse_large_grid(counts, *, command: str, limit: int, instead: str = SPLIT, per_point: int = 1,
                      param: str | None = None) -> int:
    """The number of grid points of ``counts`` (option -> number of values,
    their product; or a broadcast shape), or one line of ParameterError when
    the rows they may give (``per_point`` at most per point) exceed
    ``limit``, the rows ``command`` holds in memory; ``instead`` says what to
    run instead, ``param`` names the option to blame (None: the grid).  Checked from the counts alone, before anything is built:
    the one check of every command whose results are held in memory."""
    sizes = list(counts.values()) if isinstance(counts, dict) else list(counts)
    points = math.prod(int(n) for n in sizes)
    if points * per_point <= limit:
        return points
    if isinstance(counts, dict) and len(counts) > 1:
        spelled = " x ".join(f"{n} {name.replace('_', '-')}" for name, n in counts.items())
        points_text = f"{points:.3g} orbits ({spelled} values)"
    else:
        points_text = f"{points:.3g} orbits"
    each = f", up to {per_point} rows each," if per_point > 1 else ""
    raise ParameterError(f"the grid has {points_text}{each} and {command} holds at most {limit:.3g} rows in "
                         f"memory: {instead}", param)


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


def checked_statuses(only) -> list[str] | None:
    """The statuses of ``only=`` (one or a list), checked; None keeps every row."""
    if only is None or (isinstance(only, (list, tuple)) and not only):
        return None
    return [checked_choice("only", s, STATUSES) for s in ([only] if isinstance(only, str) else only)]


class _HalvedAxis(Axis):
    """Radii from an axis of diameters (half of each value)."""

    def __init__(self, diameters: Axis):
        super().__init__([])
        self._diameters = diameters

    def __len__(self) -> int:
        return len(self._diameters)

    def take(self, index) -> np.ndarray:
        return self._diameters.take(index) / 2.0


def radii_of(diameters: Axis) -> Axis:
    """The axis of sphere radii of an axis of diameters (``--diameter 16ft``)."""
    return _HalvedAxis(diameters)
