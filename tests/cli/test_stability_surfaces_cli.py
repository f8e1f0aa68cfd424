"""stability on the other surfaces: only the exact rows, which say that the
paper's results are the globe's, checked against a closed form (the ball
in the drum bobs at Omega sqrt(k / (k + 1)), docs/dynamics.md eq. G9)."""

import csv
import io

import numpy as np
import pytest

import deathsphere


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_off_the_globe_only_the_exact_rows_answer(run):
    res = run("stability", "--body", "sphere", "--surface", "cylinder", "--diameter", "32ft", "--height", "2",
              "--omega", "6", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    got = rows(res.stdout)
    assert {r["source"] for r in got} == {"exact"}
    assert {r["surface"] for r in got} == {"cylinder"} and {r["height_m"] for r in got} == {"2.0"}
    fast = next(r for r in got if r["quantity"] == "fast nutation frequency")
    assert float(fast["exact"]) == pytest.approx(6 * np.sqrt(0.4 / 1.4), rel=1e-9)
    assert "only the exact rows apply" in fast["note"]


def test_a_wheel_on_a_drum_has_no_paper_rows_and_the_globe_keeps_them():
    off = deathsphere.stability(surface="cylinder", diameter=9.7536, height=[2.0, 4.0], alpha=10)
    assert set(off["source"]) == {"exact"} and sorted(set(off["input_row"].tolist())) == [1, 2]
    on = deathsphere.stability(90, 45)
    assert any(s.startswith("paper") for s in on["source"]) and set(on["surface"]) == {"sphere"}
    # the exact rows are orbit's own stability columns on that lane
    orbit = deathsphere.orbit(surface="cylinder", diameter=9.7536, height=2.0, alpha=10)
    growth = [r for r in off if r["quantity"].startswith("growth") and r["input_row"] == 1][0]
    assert growth["exact"] == pytest.approx(float(orbit["growth_rate_1_s"]), abs=1e-12)


def test_theta_off_the_globe_is_refused_naming_it(run):
    res = run("stability", "--surface", "cylinder", "--diameter", "32ft", "--theta", "20", "--alpha", "10")
    assert res.exit_code == 2 and "--theta" in res.stderr and len(res.stderr.strip().splitlines()) == 1
    res = run("stability", "--surface", "cylinder", "--diameter", "32ft", "--alpha", "10")
    assert res.exit_code == 2 and "--height" in res.stderr
