import csv
import io

import numpy as np
import pytest

from deathsphere.physics import vertical_orbit
from deathsphere.results.vertical import COLUMNS, POINT_COLUMNS


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_summary_row_shares_the_contract_prefix(run):
    res = run("vertical", "--theta", "90", "--v-top", "6", "--format", "csv")
    header = res.stdout.splitlines()[0].split(",")
    assert header == list(COLUMNS) and header[:11] == ["input_row", "body", "side", "theta_deg", "alpha_deg",
                                                       "a_m", "r_m", "k", "g_m_s2", "status", "reason"]
    (row,) = rows(res.stdout)
    assert row["status"] == "ok"
    # eq. (28a): contact needs v_top^2 > g r'
    assert float(row["v_top_min_m_s"]) == pytest.approx(np.sqrt(9.80665 * 2.7), rel=1e-12)


def test_below_the_minimum_top_speed_loses_contact(run):
    out = rows(run("vertical", "--theta", "90", "--v-top", "5", "--v-top", "5.2", "--format", "csv").stdout)
    assert [r["status"] for r in out] == ["no_contact", "ok"]


def test_rate_or_speed(run):
    a = rows(run("vertical", "--theta", "60", "--v-top", "6", "--format", "csv").stdout)[0]
    rate = 6 / (3 * np.sin(np.deg2rad(60)) - 0.3)
    b = rows(run("vertical", "--theta", "60", "--phidot-top", repr(float(rate)), "--format", "csv").stdout)[0]
    assert float(a["period_s"]) == pytest.approx(float(b["period_s"]), rel=1e-12)


def test_points_view(run):
    out = rows(run("vertical", "--theta", "90", "--v-top", "6", "--points", "13", "--format", "csv").stdout)
    assert list(out[0]) == list(POINT_COLUMNS) and len(out) == 13
    assert [float(r["phi_deg"]) for r in out] == pytest.approx(np.linspace(0, 360, 13))
    v = np.array([float(r["v_cm_m_s"]) for r in out])
    assert v[0] == pytest.approx(6.0) and v.argmax() == 6  # fastest at the bottom (eq. 27)


def test_outside_from_rest_leaves_at_eq82(run):
    (row,) = rows(run("vertical", "--side", "outside", "--theta", "90", "--v-top", "0", "--format", "csv").stdout)
    assert row["status"] == "no_contact"
    assert float(row["phi_leave_deg"]) == pytest.approx(np.rad2deg(np.arccos(2 / (3 + 2 * 0.5))), abs=1e-9)


def test_vertical_batch_input(run):
    data = "theta,v_top,side\n90,6,inside\n60,,inside\n90,0,outside\n"
    res = run("vertical", "--input", "-", "--format", "csv", input=data)
    out = rows(res.stdout)
    assert res.exit_code == 1 and [r["status"] for r in out] == ["ok", "invalid", "no_contact"]
    assert "exactly one of v_top" in out[1]["reason"]


def test_vertical_table_on_a_terminal(run):
    text = run("vertical", "--theta", "90", "--v-top", "6", "--format", "table", env={"COLUMNS": "90"}).stdout
    assert "least top speed for contact" in text and "lap time" in text


@pytest.mark.parametrize("args, words", [
    (["--theta", "90"], "exactly one of v_top"),
    (["--theta", "90", "--v-top", "-1"], "v_top (top speed) must be 0..1e+09 m/s"),
    (["--v-top", "5"], "Missing option '--theta'"),
    (["--theta", "90", "--v-top", "5", "-a", "0"], "a (body radius)"),
    (["--theta", "90", "--v-top", "5", "--points", "1"], "--points"),
])
def test_vertical_usage_errors(run, args, words):
    res = run("vertical", *args)
    assert res.exit_code == 2 and words in res.stderr and len(res.stderr.strip().splitlines()) == 1


def test_lap_time_matches_direct_quadrature():
    from scipy.integrate import quad

    theta, v_top, a, r, k, g = np.deg2rad(70.0), 5.5, 0.3, 3.0, 0.5, 9.80665
    rp = r * np.sin(theta) - a
    w0 = v_top / rp
    res = vertical_orbit.vertical_orbit(theta, w0, a, r, k, g)
    lap, _ = quad(lambda phi: 1 / np.sqrt(w0**2 + 2 * g * (1 - np.cos(phi)) / ((2 * k + 1) * rp)), 0, 2 * np.pi)
    assert float(res["period"]) == pytest.approx(lap, rel=1e-10)
