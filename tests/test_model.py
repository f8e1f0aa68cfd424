import math

import numpy as np
import pytest

from deathsphere import Setup
from deathsphere.model import COLUMNS, evaluate, make_requests


@pytest.mark.parametrize("kwargs, words", [
    (dict(a=0), "a (body radius) must be 1e-09"),
    (dict(a=-1), "a (body radius) must be 1e-09"),
    (dict(r=0.3), "must be > a"),
    (dict(k=-0.1), "k (inertia factor)"),
    (dict(g=0), "g (gravity) must be 1e-09"),
    (dict(a=math.nan), "finite"),
    (dict(r=math.inf), "finite"),
    (dict(body="bicycle"), "body must be one of"),
    (dict(side="above"), "side must be one of"),
    (dict(mu=-1), "mu (friction coefficient) must be >= 0"),
])
def test_setup_rejects_invalid_parameters(kwargs, words):
    with pytest.raises(ValueError, match=words.replace("(", r"\(").replace(")", r"\)")):
        Setup(**kwargs)


def test_setup_outside_allows_r_below_a():
    assert Setup(side="outside", a=1.0, r=0.5).r == 0.5


def test_default_inertia_by_body():
    assert Setup().k == 0.5 and Setup(body="sphere").k == 0.4 and Setup(k=0.25).k == 0.25


def test_setup_orbit_grid_and_columns():
    t = Setup().orbit(np.array([30.0, 60.0])[:, None], np.array([5.0, 10.0, 25.0])[None, :])
    assert len(t) == 6 and t.names == list(COLUMNS)
    assert t["theta_deg"].tolist() == [30, 30, 30, 60, 60, 60]
    assert t["alpha_deg"].tolist() == [5, 10, 25] * 2


def test_setup_orbit_rejects_bad_angles():
    with pytest.raises(ValueError, match="theta"):
        Setup().orbit(181, 10)
    with pytest.raises(ValueError, match="alpha"):
        Setup().orbit(60, math.nan)


def test_one_bad_row_never_sinks_the_rest():
    req = make_requests(4, theta=np.array([60.0, 60.0, 200.0, 90.0]), alpha=np.array([10.0, 10.0, 10.0, 25.0]),
                        a=np.array([0.3, -1.0, 0.3, 0.3]))
    t = evaluate(req)
    assert t["status"].tolist() == ["ok", "invalid", "invalid", "ok"]
    assert t["input_row"].tolist() == [1, 2, 3, 4]
    assert "a (body radius)" in t["reason"][1] and "theta" in t["reason"][2]
    assert np.isnan(t["omega_rad_s"][1]) and np.isfinite(t["omega_rad_s"][3])


def test_records_for_notebooks():
    rec = Setup().orbit(60, 10).records()[0]
    assert rec["status"] == "ok" and rec["mu_available"] is None
    assert rec["v_cm_m_s"] == pytest.approx(7.8767, rel=1e-4)


def test_no_row_keeps_an_infinite_value():
    """The backstop behind the input bounds: an infinite result is blanked,
    and a row that claimed an orbit with one becomes invalid with the reason."""
    import numpy as np

    from deathsphere.model import OVERFLOW_REASON, finite_or_blank

    columns = {"status": np.array(["ok", "no_fit", "slips"], dtype=object),
               "reason": np.array(["", "does not fit", ""], dtype=object),
               "v_cm_m_s": np.array([np.inf, -np.inf, 3.0]), "input_row": np.array([1, 2, 3])}
    finite_or_blank(columns)
    assert np.isnan(columns["v_cm_m_s"][:2]).all() and columns["v_cm_m_s"][2] == 3.0
    assert columns["status"].tolist() == ["invalid", "no_fit", "slips"]
    assert columns["reason"].tolist() == [OVERFLOW_REASON, "does not fit", ""]
