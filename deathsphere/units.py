"""Units a rider writes: a suffix on a number or a range (``40km/h``,
``8ft``, ``30rpm``, ``0.2rad``, ``30:70:5km/h``) converted to the unit the
API uses (docs/units.md).

A plain number never imports pint, nor does the API's own unit spelled out
(``60deg``, ``3m``, ``7m/s``) or one of the common suffixes (:data:`COMMON`:
``ft``, ``km/h``, ``rpm`` ...), whose exact factors are written out here
from pint's definitions (and checked against pint by the tests).  pint's
registry is built only for any other spelling (``yd``, ``knot``), the first
time one appears, and kept (importing pint and building it costs 0.7-2.5 s).

The factors are pint's definitions as exact fractions, and a value is
converted by multiplying the number as written by the exact factor and
rounding once: ``12in`` is ``0.3048`` and ``30rpm`` is ``math.pi`` to the
last bit (a float product of the number and a rounded factor gets
``0.30479999999999996`` and ``3.1415926535897936``).  Arrays (the values of
a range) are multiplied in double-double arithmetic, which rounds the same
way except within 2**-100 of a tie.
"""

from __future__ import annotations

import functools
import math
import re
from fractions import Fraction

#: The physical kinds an input can have, and the unit the API takes each in
#: (angles are degrees in the API, as on the command line).
KINDS: dict[str, str] = {
    "length": "m",
    "speed": "m/s",
    "rate": "rad/s",
    "angle": "deg",
    "acceleration": "m/s^2",
    "mass": "kg",
    "load": "g",
    "time": "s",
    "none": "",
}

#: The spellings named in messages and docs; pint accepts more (``yd``,
#: ``knot``, ``turn/min`` ...), as long as the dimension is right.
COMMON: dict[str, tuple[str, ...]] = {
    "length": ("m", "cm", "mm", "ft", "in"),
    "speed": ("m/s", "km/h", "mph"),
    "rate": ("rad/s", "rpm", "deg/s"),
    "angle": ("deg", "rad"),
    "acceleration": ("m/s^2", "ft/s^2", "g"),
    "mass": ("kg", "lb"),
    "load": ("g", "m/s^2"),
    "time": ("s", "min"),
    "none": (),
}

_NOUN = {"length": "a length", "speed": "a speed", "rate": "an angular rate", "angle": "an angle",
         "acceleration": "an acceleration", "mass": "a mass", "load": "a load in g",
         "time": "a time", "none": "a plain number"}

#: pint's spelling of each API unit, for the conversion and the dimension check.
_PINT_API = {"length": "meter", "speed": "meter / second", "rate": "radian / second", "angle": "degree",
             "acceleration": "meter / second ** 2", "mass": "kilogram", "load": "standard_gravity",
             "time": "second"}

#: pint has no angle dimension (a radian is 1), so it would take ``2Hz`` or
#: ``3%`` for an angular rate or an angle; angles are recognised by name.
_ANGLE_UNITS = frozenset({"radian", "degree", "turn", "revolution", "milliradian", "arcminute",
                          "arcsecond", "gradian"})
_NAMED_RATES = frozenset({"revolutions_per_minute", "revolutions_per_second"})

#: A rider's spellings pint reads otherwise: ``g`` is a gram to pint.
_ALIASES = {("acceleration", "g"): "standard_gravity", ("load", "g"): "standard_gravity"}

#: Minus signs and dashes that text copied from a PDF or a word processor
#: uses for a minus; float() refuses all of them.
_MINUSES = dict.fromkeys(map(ord, "\u2212\u2010\u2011\u2012\u2013\u2014\u2015\ufe63\uff0d"), "-")

_D = r"\d(?:_?\d)*"
# inf/nan only when no letter follows, so 'info' is not 'inf' in unit 'o'
_NUM = rf"[+-]?(?:(?:{_D}(?:\.(?:{_D})?)?|\.{_D})(?:[eE][+-]?{_D})?|(?:infinity|inf|nan)(?![^\W\d_]))"
_SPLIT = re.compile(rf"({_NUM}(?:\s*:\s*{_NUM})*)\s*(.*)", re.IGNORECASE | re.DOTALL)


def _error(message: str, param: str | None):
    from deathsphere.errors import ParameterError
    return ParameterError(message, param)


def normalize_number_text(text: str) -> str:
    """``text`` with surrounding whitespace removed and Unicode minus signs
    and dashes (U+2212, U+2010..U+2015, U+FE63, U+FF0D) as ``-``.

    >>> normalize_number_text(" \u221210 ")
    '-10'
    """
    return str(text).translate(_MINUSES).strip()


def _is_plain(text: str) -> bool:
    try:
        for part in text.split(":"):
            float(part)
    except ValueError:
        return False
    return True


def split_unit(text: str) -> tuple[str, str | None]:
    """``(number_text, unit)`` of a number or ``start:stop:step`` range with
    an optional unit suffix (one for the whole range); ``unit`` is None
    when there is none, and also when ``text`` does not start with a number
    (the caller's number parser then says what is wrong).

    >>> split_unit("40km/h"), split_unit("0:2.4:0.2m"), split_unit("8 ft")
    (('40', 'km/h'), ('0:2.4:0.2', 'm'), ('8', 'ft'))
    >>> split_unit("1e3m"), split_unit("1e-3"), split_unit("-inf")
    (('1e3', 'm'), ('1e-3', None), ('-inf', None))
    """
    text = normalize_number_text(text)
    # whatever float() reads stays as it is (1_000, full-width digits, nan)
    if _is_plain(text):
        return text, None
    m = _SPLIT.fullmatch(text)
    if m is None or not m.group(2):
        return text, None
    number, unit = m.group(1), m.group(2).strip()
    if text[len(number)] in "eE" and (number[-1].isdigit() or number[-1] == "."):
        raise _error(f"{text!r} is not a number with a unit: an 'e' right after the digits starts an "
                     f"exponent (1e3); write the exponent's digits, or a space before the unit", None)
    if ":" in unit:
        raise _error(f"{text!r}: a range takes one unit, after its last number (e.g. 30:70:5km/h)", None)
    return number, unit


@functools.lru_cache(maxsize=1)
def registry():
    """pint's unit registry, built once.  Exact fractions, so each factor is
    pint's definition rounded to float64 once rather than after a chain of
    float products."""
    from fractions import Fraction

    import pint

    return pint.UnitRegistry(non_int_type=Fraction)


def _is_kind(unit, kind: str) -> bool:
    """Whether a parsed pint unit measures ``kind`` (angles by name, see above)."""
    terms = dict(unit._units)
    if kind == "angle":
        return len(terms) == 1 and next(iter(terms.items())) in {(a, 1) for a in _ANGLE_UNITS}
    if kind == "rate":
        if len(terms) == 1 and next(iter(terms.items())) in {(r, 1) for r in _NAMED_RATES}:
            return True
        angles = [name for name in terms if name in _ANGLE_UNITS]
        return len(angles) == 1 and terms[angles[0]] == 1 and dict(unit.dimensionality) == {"[time]": -1}
    return kind != "none" and unit.dimensionality == registry().parse_units(_PINT_API[kind]).dimensionality


_BASE_WORDS = {"[mass]": "a mass", "[time]": "a time", "[temperature]": "a temperature"}


def _what_it_is(unit) -> str:
    """What a unit of the wrong kind measures, in words."""
    for kind in _PINT_API:
        if _is_kind(unit, kind):
            return _NOUN[kind]
    dims = dict(unit.dimensionality)
    if not dims:
        return "a plain ratio, not an angle"
    if dims == {"[time]": -1}:
        return "a frequency with no angle (write rpm, turn/s or rad/s)"
    if len(dims) == 1 and next(iter(dims.values())) == 1:
        return _BASE_WORDS.get(next(iter(dims)), f"a {next(iter(dims)).strip('[]')}")
    # spelled out here: pint's own formatting fails on the exact registry's
    # Fraction exponents (TypeError from Fraction.__format__)
    def power(name, p):
        return name.strip("[]") + ("" if abs(p) == 1 else f"^{abs(p)}")
    up = " ".join(power(n, p) for n, p in dims.items() if p > 0) or "1"
    down = " ".join(power(n, p) for n, p in dims.items() if p < 0)
    return f"of dimension {up}/{down}" if down else f"of dimension {up}"


def allowed_text(kind: str) -> str:
    """The common units of ``kind`` in words, e.g. ``m/s, km/h or mph``."""
    names = COMMON[kind]
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} or {names[-1]}"


#: pi as pint defines it (its ``constants_en.txt``: ``pi = 3.14159...``
#: to 49 decimals), so the factors below are pint's to the last digit.
_PINT_PI = Fraction("3.1415926535897932384626433832795028841971693993751")

#: The common suffixes' exact factors (:data:`COMMON`), written out from
#: pint's definitions so that a crew's ``16ft`` or ``40km/h`` needs no pint:
#: building pint's registry costs 0.7-2.5 s a command on a loaded machine
#: (docs/units.md, "What it costs").  tests/test_units.py checks every entry
#: against pint's own conversion; any other spelling is read by pint.
_KNOWN: dict[tuple[str, str], Fraction] = {
    ("cm", "length"): Fraction(1, 100), ("mm", "length"): Fraction(1, 1000),
    ("ft", "length"): Fraction(381, 1250), ("in", "length"): Fraction(127, 5000),
    ("km/h", "speed"): Fraction(5, 18), ("mph", "speed"): Fraction(1397, 3125),
    ("rpm", "rate"): 2 * _PINT_PI / 60, ("deg/s", "rate"): _PINT_PI / 180,
    ("rad", "angle"): 180 / _PINT_PI,
    ("ft/s^2", "acceleration"): Fraction(381, 1250), ("g", "acceleration"): Fraction(196133, 20000),
    ("lb", "mass"): Fraction(45359237, 100000000),
    ("m/s^2", "load"): Fraction(20000, 196133),
    ("min", "time"): Fraction(60),
}


@functools.lru_cache(maxsize=256)
def _factor_or_reason(unit: str, kind: str) -> Fraction | str:
    if unit == KINDS[kind]:
        return Fraction(1)
    if kind == "none":
        return "takes no unit"
    known = _KNOWN.get((unit, kind))
    return known if known is not None else _pint_factor_or_reason(unit, kind)


def _pint_factor_or_reason(unit: str, kind: str) -> Fraction | str:
    """The factor of ``unit`` for ``kind`` as pint reads it, or the reason
    it cannot be one (an unknown unit, another dimension)."""
    ureg = registry()
    try:
        parsed = ureg.parse_units(_ALIASES.get((kind, unit), unit))
    except Exception:  # pint's parser raises several types; any of them means it cannot read the text
        return f"unknown unit {unit!r}"
    if not _is_kind(parsed, kind):
        return f"{unit} is {_what_it_is(parsed)}"
    return Fraction(ureg.Quantity(1, parsed).to(_PINT_API[kind]).magnitude)


def _factor(unit: str, kind: str, param: str | None, given: str) -> Fraction:
    if kind not in KINDS:
        raise ValueError(f"unknown kind {kind!r}; one of {', '.join(KINDS)}")
    got = _factor_or_reason(unit.strip(), kind)
    if isinstance(got, Fraction):
        return got
    name = param or kind
    if kind == "none":
        raise _error(f"{name} is a plain number and takes no unit (got {given!r})", param)
    raise _error(f"{name} must be {_NOUN[kind]} in {allowed_text(kind)} (got {given!r}: {got})", param)


def exact_factor(unit: str, kind: str, param: str | None = None) -> Fraction:
    """What a value in ``unit`` is multiplied by to be in the API's unit
    for ``kind``, as an exact fraction (1 for the API's unit itself);
    ParameterError for a unit pint does not know or one of another
    dimension.  ``param`` names the option in the message (default: the kind).

    >>> exact_factor("in", "length")
    Fraction(127, 5000)
    """
    return _factor(unit, kind, param, unit)


def factor(unit: str, kind: str, param: str | None = None) -> float:
    """:func:`exact_factor` rounded to float64 (for display; a conversion
    multiplies by the exact factor, :func:`convert`).

    >>> factor("km/h", "speed") * 36
    10.0
    """
    return float(exact_factor(unit, kind, param))


def per_api_unit(unit: str, kind: str, param: str | None = None) -> float:
    """How many of ``unit`` make one of the API's unit for ``kind``: the
    exact factor's inverse, rounded once, to show an SI value in the unit
    it was typed in (a terminal view's ``8 ft`` beside ``2.438 m``).

    >>> per_api_unit("km/h", "speed"), per_api_unit("ft", "length") * 2.4384
    (3.6, 8.0)
    """
    return float(1 / exact_factor(unit, kind, param))


def convert(number, scale: Fraction) -> float:
    """``number`` (its text as written, or a float) times the exact
    ``scale``, rounded to float64 once: ``convert("12", exact_factor("in",
    "length"))`` is ``0.3048``.  Text is read as the decimal written, so
    ``0.1ft`` is the float nearest 0.03048 m.

    >>> convert("30", exact_factor("rpm", "rate")) == math.pi
    True
    """
    if scale == 1:
        return float(number)
    try:
        exact = Fraction(number.replace("_", "")) if isinstance(number, str) else Fraction(number)
    except (ValueError, OverflowError):
        value = float(number)  # full-width digits (as float reads them), inf, nan
        if not math.isfinite(value):
            return value * float(scale)
        exact = Fraction(value)
    return float(exact * scale)


def _split(x):
    """Veltkamp's split of float64 ``x`` into two halves of 26 bits, whose
    products are exact."""
    c = 134217729.0 * x
    hi = c - (c - x)
    return hi, x - hi


def scale_array(values, scale: Fraction):
    """float64 ``values`` times the exact ``scale``, each rounded once: the
    product in double-double arithmetic (Dekker's exact product with the
    scale's head, plus the scale's tail), so ``np.arange(5) * 12in`` gives
    ``0.3048`` for 12 where ``12 * 0.0254`` gives ``0.30479999999999996``.
    Values beyond 1e290 or below 1e-250 in magnitude (out of every
    parameter's range anyway) are multiplied plainly: the split overflows
    there, and the error terms underflow."""
    import numpy as np

    v = np.asarray(values, dtype=np.float64)
    head = float(scale)
    if scale == 1:
        return v
    tail = float(scale - Fraction(head))
    with np.errstate(over="ignore", invalid="ignore", under="ignore"):
        inside = (np.abs(v) < 1e290) & (np.abs(v) > 1e-250)
        safe = np.where(inside, v, 0.0)
        p = safe * head
        vh, vl = _split(safe)
        hh, hl = _split(head)
        err = ((vh * hh - p) + vh * hl + vl * hh) + vl * hl
        out = p + (err + safe * tail)
        return np.where(inside, out, v * head)


def scale_written(values, decimals: int | None, scale: Fraction):
    """Values of a range as written (each rounded to ``decimals``, None: in
    exponent notation) times the exact ``scale``, rounded once: the decimal
    written is the integer ``k / 10**decimals``, so it is ``k`` that is
    converted (``0.1ft`` is the float nearest 0.03048, not 0.1's float times
    a foot).  Beyond 15 decimals or 2**52 in ``k``, the float is converted."""
    import numpy as np

    v = np.asarray(values, dtype=np.float64)
    if decimals is None or decimals > 15 or not np.all(np.abs(v) < 2.0**52 / 10.0**decimals):
        return scale_array(v, scale)
    return scale_array(np.round(v * 10.0**decimals), scale / 10**decimals)


def to_api_unit(value, unit: str | None, kind: str, param: str | None = None):
    """``value`` (a number or an array) in ``unit`` converted to the API's
    unit for ``kind``, as float64; ``unit`` None means it is already.

    >>> to_api_unit(8, "ft", "length")
    2.4384
    """
    scale = Fraction(1) if unit is None else exact_factor(unit, kind, param)
    if isinstance(value, (int, float)):
        return convert(value, scale)
    return scale_array(value, scale)


def parse_suffix(text: str, kind: str, param: str | None = None) -> tuple[str, Fraction]:
    """``(number_text, factor)`` of a number or range with an optional unit:
    the caller parses ``number_text`` as before and converts with the exact
    ``factor`` (1 without a unit; a range scales linearly, so once for the
    whole): :func:`convert` for one number, :func:`scale_array` for many.

    >>> parse_suffix("30:70:5km/h", "speed")
    ('30:70:5', Fraction(5, 18))
    >>> parse_suffix("\u221210", "angle")
    ('-10', Fraction(1, 1))
    """
    try:
        number, unit = split_unit(text)
    except ValueError as exc:  # split_unit's ParameterError does not know the option
        if hasattr(exc, "param") and exc.param is None:
            exc.param = param
        raise
    return number, (Fraction(1) if unit is None else _factor(unit, kind, param, normalize_number_text(text)))


def parse_value(text: str, kind: str, param: str | None = None) -> float:
    """One number with an optional unit, in the API's unit for ``kind``."""
    number, scale = parse_suffix(text, kind, param)
    try:
        value = float(number)
    except ValueError:
        raise _error(f"{param or kind} must be a number (got {text!r})", param) from None
    return value if scale == 1 else convert(number, scale)
