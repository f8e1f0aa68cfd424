"""The API reads values once, at its edge, as docs/api.md says: text as on
the command line (a number, ``"inf"``, a unit suffix, a typographic minus),
and refuses what is not a real number instead of coercing it."""

import numpy as np
import pytest

import deathsphere
from deathsphere import ParameterError


def test_text_is_read_as_the_command_line_reads_it():
    assert float(deathsphere.orbit("60", "10")["v_cm_m_s"]) == float(deathsphere.orbit(60, 10)["v_cm_m_s"])
    assert np.isnan(float(deathsphere.orbit(60, 10, mu="inf")["mu_available"]))   # inf: no limit, empty
    assert str(deathsphere.vertical(60, 6, mu="inf")["status"]) == "ok"
    assert float(deathsphere.orbit(60, "\u221210")["alpha_deg"]) == -10.0          # U+2212 from a PDF
    assert float(deathsphere.orbit(60, 10, r="10ft")["r_m"]) == 3.048
    assert float(deathsphere.orbit(60, 10, diameter="20ft")["r_m"]) == 3.048


@pytest.mark.parametrize("kwargs, words", [
    ({"theta": 60 + 1j}, "real number"),
    ({"theta": np.array([60 + 0j, 70 + 1j])}, "real number"),
    ({"theta": np.ma.masked_array([60.0, 70.0], [False, True])}, "masked"),
    ({"theta": True}, "boolean"),
    ({"stability": "no"}, "True or False"),
    ({"theta": "sixty"}, "theta"),
    ({"alpha": "10kg"}, "alpha"),
])
def test_values_that_are_not_real_numbers_are_refused(kwargs, words):
    args = {"theta": 60, "alpha": 10, **kwargs}
    with pytest.raises(ParameterError, match=words):
        deathsphere.orbit(**args)


def test_flags_are_booleans_on_every_function():
    for call in (lambda: deathsphere.vertical(90, 6, stability="yes"),
                 lambda: deathsphere.sweep(60, 10, stability=1),
                 lambda: deathsphere.simulate(60, 10, vertical="no")):
        with pytest.raises(ParameterError, match="True or False"):
            call()


def test_an_out_of_range_value_is_shown_to_its_last_digit(run):
    res = run("orbit", "--theta", "180.00000000000003", "--alpha", "10")
    assert res.exit_code == 2 and "(got 180.00000000000003)" in res.stderr
    with pytest.raises(ParameterError, match=r"\(got 200\)"):
        deathsphere.orbit(200, 10)


def test_a_typographic_minus_on_the_command_line(run):
    res = run("orbit", "--theta", "60", "--alpha", "\u221210", "--format", "csv")
    assert res.exit_code == 0 and ",-10.0," in res.stdout.splitlines()[1]
