"""Units of a compound dimension are refused in one line by the API, and an
--input cell reads a unit suffix or a typographic minus as the option does."""

import io
import math

import pytest

import deathsphere
from deathsphere.inputs import RequestReader
from deathsphere.model import REQUEST_FIELDS
from deathsphere.params import ParameterError


@pytest.mark.parametrize("kw, words", [
    ({"theta": 90, "speed": "40km/h km/h"}, "length^2/time^2"),
    ({"theta": 90, "alpha": 10, "r": "3 m^2"}, "length^2"),
    ({"theta": 90, "alpha": 10, "g": "1N"}, "mass length/time^2"),
])
def test_a_unit_of_a_compound_dimension_is_a_parameter_error(kw, words):
    with pytest.raises(ParameterError, match="must be") as caught:
        deathsphere.orbit(**kw)
    assert words in str(caught.value) and "\n" not in str(caught.value)


def _column(text: str, name: str):
    data = io.BytesIO(text.encode())
    chunk = next(RequestReader(data, REQUEST_FIELDS, {}).chunks())
    return chunk.values[name], chunk.invalid


def test_cells_with_units_read_as_the_options_read_them():
    speed, invalid = _column("theta,speed\n90,40km/h\n90,7\n90,40km\n", "speed")
    assert speed[0] == deathsphere.api.arguments.number_from_text("speed", "40km/h") == 40 / 3.6
    assert speed[1] == 7.0 and math.isnan(speed[2])
    assert list(invalid[:2]) == ["", ""] and "km is a length" in invalid[2]


def test_a_length_cell_in_feet_and_a_typographic_minus():
    r, _ = _column("theta,r\n90,8ft\n", "r")
    alpha, _ = _column("theta,alpha\n90,\u221210\n", "alpha")
    assert r[0] == 2.4384 and alpha[0] == -10.0


def test_a_body_cell_with_a_comma_is_echoed_without_it(tmp_path):
    f = tmp_path / "in.csv"
    f.write_text('theta,alpha,body,side\n90,10,"bi,ke",inside\n90,10,wheel,"in,side"\n')
    t = next(iter(deathsphere.api.orbit_input(f)))
    assert list(t["status"]) == ["invalid", "invalid"]
    assert list(t["body"]) == ["bi;ke", "wheel"] and list(t["side"]) == ["inside", "in;side"]
    # the reason still shows the text typed, recoverably (a comma as \x2c)
    assert "(got 'bi\\x2cke')" in t["reason"][0]


def test_a_rows_refusal_names_its_column_as_the_header_typed_it(tmp_path):
    """A result CSV fed back names its columns theta_deg, alpha_deg,
    mu_available: a bad cell or a value out of bounds is refused under that
    name (the registry's words after it); a column named as the registry
    names it reads as before."""
    import deathsphere

    path = tmp_path / "back.csv"
    path.write_text("theta_deg,alpha_deg,mu_available\n200,10,1\n60,oops,1\n60,10,-1\n60,10kg,1\n")
    reasons = deathsphere.orbit_input(str(path), stability=False).table()["reason"].tolist()
    assert reasons == ["theta_deg: theta (polar angle) must be 0..180 deg (got 200)",
                       "alpha_deg: 'oops' is not a number",
                       "mu_available: mu (friction coefficient) must be >= 0 or inf (no limit) (got -1)",
                       "alpha_deg must be an angle in deg or rad (got '10kg': kg is a mass)"]
    path.write_text("theta,alpha\n200,10\n60,oops\n")
    reasons = deathsphere.orbit_input(str(path), stability=False).table()["reason"].tolist()
    assert reasons == ["theta (polar angle) must be 0..180 deg (got 200)", "alpha: 'oops' is not a number"]


def test_a_vertical_rows_refusal_names_its_column_as_typed(tmp_path):
    import deathsphere

    path = tmp_path / "loops.csv"
    path.write_text("theta_deg,v_cm_m_s,g_m_s2\n90,6,9.8\n90,-1,9.8\n90,6,-3\n")
    table = deathsphere.vertical_input(str(path), stability=False).table()
    assert table["status"].tolist()[0] != "invalid" and table["reason"].tolist()[1:] == [
        "v_cm_m_s: v_top (top speed) must be 0..1e+09 m/s (got -1)",
        "g_m_s2: g (gravity) must be 1e-09..1e+09 m/s^2 (got -3)"]


def test_no_reason_stays_none_whatever_the_column_is_called():
    from deathsphere.requests.decode import as_typed

    assert as_typed("theta", "", {"theta": "theta_deg"}) == ""
    assert as_typed("theta", "bad", {"theta": "theta"}) == "bad"
    assert as_typed("theta", "bad", {"theta": "THETA"}) == "THETA: bad"
