"""Unit suffixes: each spelling against pint's own float registry and a hand
value, ranges, the Unicode minus, pint left unimported for a plain number,
and one-line refusals naming the allowed units."""

import math
import os
import subprocess
import sys

import numpy as np
import pint
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from deathsphere import units
from deathsphere.params import ParameterError

#: (spelling, kind, the API unit in pint's words, hand value of 1 spelling in the API unit)
SPELLINGS = [
    ("m", "length", "meter", 1.0),
    ("cm", "length", "meter", 0.01),
    ("mm", "length", "meter", 0.001),
    ("ft", "length", "meter", 0.3048),
    ("in", "length", "meter", 0.0254),
    ("m/s", "speed", "meter/second", 1.0),
    ("km/h", "speed", "meter/second", 1000.0 / 3600.0),
    ("mph", "speed", "meter/second", 1609.344 / 3600.0),
    ("rad/s", "rate", "radian/second", 1.0),
    ("rpm", "rate", "radian/second", 2.0 * math.pi / 60.0),
    ("deg/s", "rate", "radian/second", math.pi / 180.0),
    ("deg", "angle", "degree", 1.0),
    ("°", "angle", "degree", 1.0),
    ("rad", "angle", "degree", 180.0 / math.pi),
    ("m/s^2", "acceleration", "meter/second**2", 1.0),
    ("ft/s^2", "acceleration", "meter/second**2", 0.3048),
    ("g", "acceleration", "meter/second**2", 9.80665),
]

FLOAT_PINT = pint.UnitRegistry()


@pytest.mark.parametrize("unit, kind, api, hand", SPELLINGS)
def test_each_spelling_against_pint_and_by_hand(unit, kind, api, hand):
    f = units.factor(unit, kind)
    assert f == pytest.approx(hand, rel=1e-15)
    # a rider's g is standard gravity; pint's g is the gram
    spelled = "standard_gravity" if unit == "g" else unit
    assert f == pytest.approx(FLOAT_PINT.Quantity(1.0, spelled).to(api).magnitude, rel=1e-15)


@pytest.mark.parametrize("text, kind, expected", [
    ("40km/h", "speed", 40.0 / 3.6),
    ("8ft", "length", 2.4384),
    ("8 ft", "length", 2.4384),
    ("30rpm", "rate", math.pi),
    ("1rad", "angle", 57.29577951308232),
    ("60mph", "speed", 26.8224),
    ("96in", "length", 2.4384),
    ("60deg", "angle", 60.0),
    ("3m", "length", 3.0),
    ("7m/s", "speed", 7.0),
])
def test_hand_values(text, kind, expected):
    assert units.parse_value(text, kind) == pytest.approx(expected, rel=1e-15)


def test_a_foot_is_exactly_0_3048_m():
    # pint's float registry is one ulp off (0.30479999999999996); exact
    # fractions round pint's definition once
    assert units.factor("ft", "length") == 0.3048
    assert units.parse_value("8ft", "length") == 2.4384
    assert units.to_api_unit(16.0, "ft", "length") / 2 == 2.4384  # a 16 ft globe's radius


def test_the_api_unit_spelled_out_is_exactly_one():
    for kind, unit in units.KINDS.items():
        if unit:
            assert units.factor(unit, kind) == 1.0


@pytest.mark.parametrize("text, expected", [
    ("40km/h", ("40", "km/h")),
    ("0:2.4:0.2m", ("0:2.4:0.2", "m")),
    ("30:70:5km/h", ("30:70:5", "km/h")),
    ("-10:10:5 deg", ("-10:10:5", "deg")),
    ("8 ft", ("8", "ft")),
    (" 8ft ", ("8", "ft")),
    ("1e3m", ("1e3", "m")),
    ("1.5E-3 km", ("1.5E-3", "km")),
    ("1e-3", ("1e-3", None)),
    ("1e3", ("1e3", None)),
    ("-inf", ("-inf", None)),
    ("inf", ("inf", None)),
    ("nan", ("nan", None)),
    ("1_000", ("1_000", None)),
    ("４０", ("４０", None)),
    ("４０km/h", ("４０", "km/h")),
    ("0.2rad", ("0.2", "rad")),
    ("info", ("info", None)),
    ("km/h", ("km/h", None)),
    ("40 km/h", ("40", "km/h")),
])
def test_split_unit(text, expected):
    assert units.split_unit(text) == expected


def test_a_range_scales_as_a_whole():
    number, f = units.parse_suffix("0:2.4:0.2ft", "length")
    start, stop, step = (float(p) * f for p in number.split(":"))
    assert (start, stop, step) == (0.0, pytest.approx(0.73152, rel=1e-15), pytest.approx(0.06096, rel=1e-15))


@pytest.mark.parametrize("text", ["1em", "2e", "30km/h:70km/h"])
def test_ambiguous_text_is_refused(text):
    with pytest.raises(ParameterError) as err:
        units.parse_suffix(text, "length", "r")
    assert err.value.param == "r" and "\n" not in str(err.value) and repr(text) in str(err.value)


@pytest.mark.parametrize("dash", ["\u2212", "\u2012", "\u2013", "\u2014", "\u2015", "\ufe63", "\uff0d"])
def test_unicode_minus(dash):
    assert units.normalize_number_text(f" {dash}10 ") == "-10"
    assert units.parse_value(f"{dash}10", "angle") == -10.0
    assert units.parse_value(f"{dash}0.2rad", "angle") == pytest.approx(-0.2 * 180 / math.pi, rel=1e-15)
    assert units.split_unit(f"{dash}10:10:5deg") == ("-10:10:5", "deg")


def test_arrays_convert():
    out = units.to_api_unit(np.array([0.0, 30.0, 60.0]), "rpm", "rate")
    assert out.dtype == np.float64
    np.testing.assert_allclose(out, [0.0, math.pi, 2 * math.pi], rtol=1e-15)
    assert units.to_api_unit([1, 2], None, "length").tolist() == [1.0, 2.0]
    assert units.to_api_unit(3, None, "length") == 3.0


@pytest.mark.parametrize("text, kind, param, allowed, why", [
    ("40km", "speed", "speed", "m/s, km/h or mph", "km is a length"),
    ("40kmh", "speed", "speed", "m/s, km/h or mph", "unknown unit 'kmh'"),
    ("8furlongz", "length", "r", "m, cm, mm, ft or in", "unknown unit"),
    ("2Hz", "rate", "omega", "rad/s, rpm or deg/s", "no angle"),
    ("30", "rate", "omega", None, None),
    ("0.2m", "angle", "alpha", "deg or rad", "m is a length"),
    ("5deg", "rate", "omega3", "rad/s, rpm or deg/s", "deg is an angle"),
    ("3%", "angle", "theta", "deg or rad", "not an angle"),
    ("1g", "length", "a", "m, cm, mm, ft or in", "g is a mass"),
])
def test_wrong_dimension_or_unknown_unit(text, kind, param, allowed, why):
    if allowed is None:  # a plain number is the API's unit
        assert units.parse_value(text, kind, param) == 30.0
        return
    with pytest.raises(ParameterError) as err:
        units.parse_value(text, kind, param)
    message = str(err.value)
    assert err.value.param == param and "\n" not in message
    assert message.startswith(f"{param} must be ") and allowed in message and repr(text) in message
    assert why in message


def test_dimensionless_options_take_no_unit():
    with pytest.raises(ParameterError, match=r"k is a plain number and takes no unit \(got '0.5m'\)"):
        units.parse_value("0.5m", "none", "k")
    assert units.parse_value("0.5", "none", "k") == 0.5


def test_a_plain_number_does_not_import_pint():
    code = ("import sys; from deathsphere import units; "
            "assert units.parse_suffix('\u221212.5', 'speed') == ('-12.5', 1.0); "
            "assert units.parse_suffix('30:70:5', 'speed') == ('30:70:5', 1.0); "
            "assert units.parse_value('60deg', 'angle') == 60.0; "
            "print('pint' in sys.modules, 'numpy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=os.environ.copy(),
                         check=True)
    assert out.stdout.split() == ["False", "False"]
    # nor does a common suffix (its factor is written out); an uncommon one
    # does import it (so the checks above can fail)
    code = ("import sys; from deathsphere import units; units.parse_value('8ft', 'length'); "
            "units.parse_value('40km/h', 'speed'); units.parse_value('30rpm', 'rate'); print('pint' in sys.modules); "
            "units.parse_value('8yd', 'length'); print('pint' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=os.environ.copy(),
                         check=True)
    assert out.stdout.split() == ["False", "True"]


def test_the_written_out_factors_are_pints():
    """Every common suffix's factor that skips pint is exactly what pint's
    exact registry gives, and they cover every common spelling."""
    assert units._KNOWN, "no factor is written out"
    for (unit, kind), written in units._KNOWN.items():
        assert units._pint_factor_or_reason(unit, kind) == written, (unit, kind)
    common = {(u, k) for k, names in units.COMMON.items() for u in names if u != units.KINDS[k]}
    assert common == set(units._KNOWN)


_CASES = [(unit, kind) for unit, kind, _, _ in SPELLINGS]


@settings(derandomize=True, deadline=None, max_examples=200)
@given(st.sampled_from(_CASES), st.floats(-1e6, 1e6, allow_nan=False).filter(lambda x: abs(x) > 1e-6 or x == 0))
def test_text_round_trip(case, value):
    """A value written with a suffix reads back as pint converts it."""
    unit, kind = case
    text = f"{value!r}{unit}".replace("-", "\u2212")
    spelled = "standard_gravity" if unit == "g" else unit
    api = {"length": "meter", "speed": "meter/second", "rate": "radian/second", "angle": "degree",
           "acceleration": "meter/second**2"}[kind]
    expected = FLOAT_PINT.Quantity(value, spelled).to(api).magnitude
    assert units.parse_value(text, kind) == pytest.approx(expected, rel=1e-14, abs=1e-300)


def test_display_units_as_typed_and_by_system():
    """What the command line hands a terminal view: an option typed in a
    unit of its own shows in it; a kind's untyped quantities in the one
    unit every value of that kind was typed in; --units' systems by kind."""
    from deathsphere.cli.options import display_units

    shown = display_units(None, {"diameter": "16ft", "height": ("0:8:2ft",), "speed": ("40km/h",), "mu": ("1",)})
    assert shown.unit("length", ("height",)).name == "ft" and shown.unit("length").name == "ft"
    assert shown.unit("speed", ("speed",)).per_api_unit == 3.6
    mixed = display_units(None, {"diameter": "16ft", "height": ("0.4", "2.4")})
    assert mixed.unit("length", ("diameter",)).name == "ft"
    assert mixed.unit("length", ("height",)) is None and mixed.unit("length") is None
    assert display_units("si", {"height": ("8ft",)}).unit("length", ("height",)) is None
    imperial = display_units("imperial", {})
    assert [imperial.unit(k).name for k in ("length", "speed", "rate", "mass")] == ["ft", "mph", "rpm", "lb"]
    assert imperial.unit("length").per_api_unit * 0.3048 == pytest.approx(1, rel=1e-15)
    assert display_units("metric", {}).unit("length") is None  # m is SI: nothing beside it
