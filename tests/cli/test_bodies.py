"""Every body and side through the CLI: formats, batches and usage errors."""

import csv
import io
import json

import numpy as np
import pytest

from deathsphere.physics import particle, sphere


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_sphere_with_spin_gives_both_branches(run):
    res = run("orbit", "--body", "sphere", "--theta", "120", "--omega3", "40", "--format", "csv")
    out = rows(res.stdout)
    assert [r["branch"] for r in out] == ["0", "1"] and [r["input_row"] for r in out] == ["1", "1"]
    assert all(r["k"] == "0.4" for r in out)  # solid ball by default
    assert float(out[0]["alpha_deg"]) == 30.0  # bank angle theta - 90 (sec. 4)
    slow, fast = sphere.orbit_rates(np.deg2rad(120), 40.0, 0.3, 3.0, 0.4, 9.80665)
    assert float(out[0]["omega_rad_s"]) == pytest.approx(float(slow), rel=1e-12)
    assert float(out[1]["omega_rad_s"]) == pytest.approx(float(fast), rel=1e-12)


def test_sphere_with_rate_gives_one_row(run):
    res = run("orbit", "--body", "sphere", "--theta", "60", "--omega", "3", "-k", "0.5", "--format", "json")
    (row,) = json.loads(res.stdout)
    assert row["omega_rad_s"] == 3.0 and row["k"] == 0.5 and row["branch"] in (0, 1)
    assert row["omega3_rad_s"] == pytest.approx(
        float(sphere.omega3_from_rate(np.deg2rad(60), 3.0, 0.3, 3.0, 0.5, 9.80665)), rel=1e-12)


def test_particle_only_below_the_equator(run):
    out = rows(run("orbit", "--body", "particle", "--theta", "60:150:30", "--format", "csv").stdout)
    assert [r["status"] for r in out] == ["no_orbit", "no_orbit", "ok", "ok"]
    assert out[0]["a_m"] == "" and out[0]["alpha_deg"] == ""
    expected = particle.particle_orbit(np.deg2rad(150.0), 3.0, 9.80665)["omega"]
    assert float(out[3]["omega_rad_s"]) == pytest.approx(float(expected), rel=1e-12)


@pytest.mark.parametrize("body, extra", [("wheel", ["--alpha", "80"]), ("sphere", ["--omega3", "60"]),
                                         ("particle", [])])
@pytest.mark.parametrize("fmt", ["csv", "json", "ndjson", "table"])
def test_every_body_side_and_format(run, body, extra, fmt):
    for side in ("inside", "outside"):
        res = run("orbit", "--body", body, "--side", side, "--theta", "30", *extra, "--format", fmt,
                  env={"COLUMNS": "100"})
        assert res.exit_code == 0, res.stderr
        assert res.stdout.strip()


def test_mixed_batch_with_body_and_side_columns(run):
    data = ("body,side,theta,alpha,omega3,omega\n"
            "wheel,inside,60,10,,\n"
            "sphere,inside,120,,40,\n"
            "particle,inside,150,,,\n"
            "sphere,outside,30,,,2\n"
            "wheel,outside,30,80,,\n"
            "sphere,inside,60,10,,\n"
            "bicycle,inside,60,10,,\n")
    res = run("orbit", "--input", "-", "--format", "csv", input=data)
    out = rows(res.stdout)
    assert res.exit_code == 1
    assert [r["input_row"] for r in out] == ["1", "2", "2", "3", "4", "5", "6", "7"]
    assert [r["body"] for r in out] == ["wheel", "sphere", "sphere", "particle", "sphere", "wheel", "sphere",
                                        "bicycle"]
    assert out[6]["status"] == "invalid" and "exactly one of omega3" in out[6]["reason"]
    assert out[7]["status"] == "invalid" and "body must be one of" in out[7]["reason"]


@pytest.mark.parametrize("args, words", [
    (["--body", "sphere", "--theta", "60", "--alpha", "10", "--omega3", "80"], "tilt is fixed"),
    (["--body", "sphere", "--theta", "60"], "exactly one of omega3"),
    (["--body", "sphere", "--theta", "60", "--omega3", "1", "--omega", "1"], "exactly one of omega3"),
    (["--theta", "60", "--alpha", "10", "--omega3", "5"], "for a sphere only"),
    (["--body", "particle", "--theta", "120", "--alpha", "10"], "a particle takes only theta"),
    (["--body", "sphere", "--theta", "60", "--omega3", "nan"], "must be a finite number"),
])
def test_body_usage_errors(run, args, words):
    res = run("orbit", *args)
    assert res.exit_code == 2 and words in res.stderr and len(res.stderr.strip().splitlines()) == 1


def test_wheel_speed_is_solved_for_every_alpha(run):
    out = rows(run("orbit", "--theta", "100", "--com-speed", "4", "--com-speed", "6", "--format", "csv").stdout)
    assert out and {r["input_row"] for r in out} == {"1", "2"}
    for r in out:
        assert float(r["v_cm_m_s"]) == pytest.approx(4.0 if r["input_row"] == "1" else 6.0, rel=1e-9)
        assert r["branch"] != "" and r["alpha_deg"] != ""
    # a dense scan of eq. (29) finds the same number of roots for 4 m/s
    alpha = np.linspace(-179.999, 179.999, 720001)
    from deathsphere.physics import wheel
    res = wheel.horizontal_orbit(np.deg2rad(100.0), np.deg2rad(alpha), 0.3, 3.0, 0.5, 9.80665)
    fits = res["status"] != 1  # not no_fit
    v = np.where(fits, res["v_cm"], np.nan) - 4.0
    crossings = np.count_nonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0)
    assert crossings == sum(r["input_row"] == "1" for r in out)


def test_wheel_rate_without_root_is_one_no_orbit_row(run):
    out = rows(run("orbit", "--theta", "90", "--omega", "0.1", "--format", "csv").stdout)
    assert len(out) == 1 and out[0]["status"] == "no_orbit" and "no tilt alpha" in out[0]["reason"]


def test_sphere_rows_report_the_least_spins(run):
    out = rows(run("orbit", "--body", "sphere", "--theta", "30", "--omega3", "200", "--format", "csv").stdout)
    k, a, rho, g, th = 0.4, 0.3, 2.7, 9.80665, np.deg2rad(30.0)
    least_real = np.sqrt(4 * (k + 1) * g * rho * np.cos(th)) / (k * a)  # eq. (56) at equality
    for r in out:
        assert float(r["omega3_min_real_rad_s"]) == pytest.approx(least_real, rel=1e-12)
        # above the equator and tan^2(30 deg) < k + 1: contact needs more spin (text after eq. 58)
        assert float(r["omega3_min_contact_rad_s"]) > least_real
