"""A value the request fixes comes back exactly as written: unit
conversions rounded once from the exact factor (one number and every value
of a range), and simulate's summary echoing the requested speed and rates."""

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import deathsphere
from deathsphere import units
from deathsphere.api.arguments import checked_axis
from deathsphere.api.machines import Machine


@pytest.mark.parametrize("text, kind, exact", [
    ("12in", "length", Fraction("0.3048")),
    ("2ft", "length", Fraction("0.6096")),
    ("0.1ft", "length", Fraction("0.03048")),
    ("7km/h", "speed", Fraction(7000, 3600)),
    ("55mph", "speed", Fraction("55") * Fraction("1609.344") / 3600),
])
def test_one_value_is_the_exact_product_rounded_once(text, kind, exact):
    assert units.parse_value(text, kind) == float(exact)


def test_thirty_rpm_is_pi_to_the_last_bit():
    assert units.parse_value("30rpm", "rate") == math.pi
    assert units.parse_value("180deg/s", "rate") == math.pi


def test_every_value_of_a_range_is_converted_as_one_value_is():
    heights = checked_axis("height", "0:8:2ft").values()
    assert heights.tolist() == [0.0, 0.6096, 1.2192, 1.8288, 2.4384]
    fine = checked_axis("height", "0:3:0.1ft").values()
    assert fine.tolist() == [float(Fraction(i, 10) * Fraction("0.3048")) for i in range(31)]
    rates = checked_axis("omega", "10:100:10rpm").values()
    assert rates[2] == math.pi and rates[5] == 2 * math.pi


@settings(max_examples=300, deadline=None)
@given(st.floats(-1e6, 1e6, allow_nan=False).filter(lambda v: v == 0 or abs(v) > 1e-200),
       st.sampled_from([("in", "length"), ("mph", "speed"), ("rpm", "rate"), ("rad", "angle"), ("g", "acceleration")]))
def test_arrays_are_rounded_once_like_fractions(value, unit_kind):
    scale = units.exact_factor(*unit_kind)
    assert units.scale_array(np.array([value]), scale)[0] == float(Fraction(value) * scale)


def test_a_machine_in_inches_keeps_its_inches():
    m = Machine(mass=100, h=0.5, a="12in", inertia=(10, 10, 10), spin_inertia=1)
    assert m.wheel_radius == 0.3048


@pytest.mark.parametrize("request_, column, value", [
    ({"com_speed": 7}, "speed_m_s", 7.0),
    ({"com_speed": "30km/h"}, "speed_m_s", float(Fraction(30000, 3600))),
    ({"omega": "30rpm"}, "omega_rad_s", math.pi),
    ({"omega": 2.1}, "omega_rad_s", 2.1),
    ({"machine": "stunt125", "com_speed": 8}, "speed_m_s", 8.0),
])
def test_simulate_echoes_the_requested_speed_and_rate(request_, column, value):
    _, summary = deathsphere.simulate(90, periods=0.05, points_per_period=4, **request_)
    assert summary[column][0] == value


def test_a_sphere_echoes_its_spin():
    _, summary = deathsphere.simulate(60, body="sphere", omega3=80.3, periods=0.05, points_per_period=4)
    assert summary["omega3_rad_s"][0] == 80.3
