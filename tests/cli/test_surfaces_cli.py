"""orbit and sweep on the other surfaces (docs/surfaces.md): the arena's
options, its columns, and every bad input refused in one line (exit 2), or
in a batch as the row's status and reason."""

import csv
import io

import numpy as np
import pytest

import deathsphere
from deathsphere.physics import revolution
from deathsphere.physics.ground import Cone, Cylinder


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_the_wall_of_death_through_the_command_line(run):
    res = run("orbit", "--surface", "cylinder", "--diameter", "32ft", "--wall-height", "6", "--height", "2",
              "--alpha", "10", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    (row,) = rows(res.stdout)
    assert row["surface"] == "cylinder" and row["theta_deg"] == "" and row["status"] == "ok"
    assert float(row["r_m"]) == pytest.approx(4.8768) and float(row["height_m"]) == 2.0
    assert float(row["wall_angle_deg"]) == 90.0 and float(row["rho_contact_m"]) == pytest.approx(4.8768)
    want = revolution.wheel_orbit(Cylinder(4.8768, 6.0), 2.0, np.radians(10.0), 0.3, 0.5, 9.80665)
    assert float(row["mu_required"]) == pytest.approx(float(want["mu_required"]), rel=1e-15)
    # the wall of death's rule, independent of the code: mu = g r' / v^2
    rp, v = float(row["r_prime_m"]), float(row["v_cm_m_s"])
    assert float(row["mu_required"]) == pytest.approx(9.80665 * rp / v ** 2, rel=1e-12)
    assert row["stability"] == "stable" and row["stability_method"] == "exact-linearisation"


def test_the_golfers_dilemma_in_the_orbit_table(run):
    """A ball in the drum bobs at omega_bob = Omega sqrt(k / (k + 1))
    (Gualtieri et al., Am. J. Phys. 74, 497 (2006); docs/dynamics.md eq. G9):
    the closed form against the table's numerical linearisation."""
    res = run("orbit", "--body", "sphere", "--surface", "cylinder", "--diameter", "32ft", "--height", "2",
              "--omega", "3", "--omega", "6", "--omega", "11", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    got = rows(res.stdout)
    assert [r["stability"] for r in got] == ["stable"] * 3
    for r in got:
        omega, k = float(r["omega_rad_s"]), float(r["k"])
        assert float(r["freq_fast_rad_s"]) == pytest.approx(omega * np.sqrt(k / (k + 1)), rel=1e-9)


def test_outside_another_surface_the_stability_is_the_exact_linearisations(run):
    # on top of a cone leaning in at 150 degrees (a roof): steady orbits exist outside
    res = run("orbit", "--surface", "cone", "--diameter", "6", "--wall-angle", "150", "--height", "0.5",
              "--alpha", "50", "--alpha", "70", "--side", "outside", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    got = rows(res.stdout)
    assert [r["status"] for r in got] == ["ok", "ok"]
    from deathsphere.physics.stability.on_ground import wheel_stability_on

    roof = Cone(3.0, np.radians(150.0))
    for r, alpha in zip(got, (50.0, 70.0)):
        assert r["stability_method"] == "exact-linearisation" and r["stability"] in ("stable", "unstable")
        want = wheel_stability_on(roof, 0.5, np.radians(alpha), 0.3, 0.5, 9.80665, outside=True)
        assert float(r["growth_rate_1_s"]) == pytest.approx(float(want["growth_rate"]), rel=1e-12, abs=1e-12)


def test_a_cone_sweep_and_the_api_agree(run):
    res = run("sweep", "--surface", "cone", "--diameter", "6", "--wall-angle", "80", "--height", "0:4:2",
              "--alpha", "5", "--alpha", "10", "--no-stability")
    assert res.exit_code == 0, res.stderr
    got = rows(res.stdout)
    table = deathsphere.orbit(surface="cone", diameter=6, wall_angle=80, height=[[0], [2], [4]], alpha=[5, 10],
                              stability=False)
    assert [float(r["v_cm_m_s"]) for r in got] == table["v_cm_m_s"].tolist()
    assert {r["surface"] for r in got} == {"cone"}
    record = deathsphere.orbit(surface=Cone(3.0, np.radians(80.0)), height=2, alpha=10, stability=False)
    assert float(record["v_cm_m_s"]) == float(table.grid("v_cm_m_s")[1, 1])


def test_the_globe_by_height_is_the_globe_by_theta(run):
    by_theta = rows(run("orbit", "--theta", "60", "--alpha", "10", "--format", "csv").stdout)[0]
    by_height = rows(run("orbit", "--height", "4.5", "--alpha", "10", "--format", "csv").stdout)[0]
    assert float(by_height["theta_deg"]) == pytest.approx(60.0, abs=1e-12)
    assert float(by_height["v_cm_m_s"]) == pytest.approx(float(by_theta["v_cm_m_s"]), rel=1e-12)
    assert by_theta["surface"] == "sphere" and float(by_theta["wall_angle_deg"]) == 120.0


def test_flat_ground_and_a_profile(run, tmp_path):
    res = run("orbit", "--surface", "plane", "--turn-radius", "10", "--alpha", "70", "--format", "csv")
    (row,) = rows(res.stdout)
    assert row["surface"] == "plane" and float(row["rho_contact_m"]) == 10.0 and float(row["height_m"]) == 0.0
    path = tmp_path / "drum.csv"
    path.write_text("rho_ft,z_ft\n16,0\n16,5\n16,10\n16,20\n")
    res = run("orbit", "--surface", "profile", "--profile", str(path), "--height", "2", "--alpha", "10",
              "--format", "csv")
    assert res.exit_code == 0, res.stderr
    drum = rows(run("orbit", "--surface", "cylinder", "--diameter", "32ft", "--height", "2", "--alpha", "10",
                    "--format", "csv").stdout)[0]
    (row,) = rows(res.stdout)
    assert row["surface"] == "profile" and row["r_m"] == ""
    assert float(row["mu_required"]) == pytest.approx(float(drum["mu_required"]), rel=1e-10)


def test_an_input_batch_on_a_drum_gives_a_row_per_line(run, tmp_path):
    path = tmp_path / "lanes.csv"
    path.write_text("height,alpha\n1,10\n9,10\noops,5\n-1,5\n")
    res = run("orbit", "--input", str(path), "--surface", "cylinder", "--diameter", "9", "--wall-height", "6",
              "--format", "csv")
    got = rows(res.stdout)
    assert [r["status"] for r in got] == ["ok", "no_fit", "invalid", "invalid"]
    assert "outside the wall" in got[1]["reason"] and "not a number" in got[2]["reason"]
    assert "height" in got[3]["reason"]


@pytest.mark.parametrize("args, words", [
    (["--surface", "drum", "--height", "1", "--alpha", "10"], "--surface"),
    (["--surface", "cone", "--diameter", "6", "--height", "1", "--alpha", "10"], "--wall-angle"),
    (["--surface", "cone", "--diameter", "6", "--wall-angle", "0", "--height", "1", "--alpha", "10"],
     "must be > 0 and < 180"),
    (["--surface", "cone", "--diameter", "6", "--wall-angle", "180", "--height", "1", "--alpha", "10"],
     "must be > 0 and < 180"),
    (["--surface", "cylinder", "--height", "1", "--alpha", "10"], "diameter"),
    (["--surface", "cylinder", "--diameter", "9", "--theta", "60", "--alpha", "10"], "theta is the sphere's"),
    (["--surface", "cylinder", "--diameter", "9", "--alpha", "10"], "height"),
    (["--surface", "cylinder", "--diameter", "9", "--wall-angle", "80", "--height", "1", "--alpha", "10"],
     "not a shape of the cylinder"),
    (["--surface", "plane", "--height", "1", "--alpha", "10"], "turn_radius"),
    (["--theta", "60", "--alpha", "10", "--wall-height", "3"], "not a shape of the sphere"),
])
def test_bad_arena_options_are_one_line_and_exit_2(run, args, words):
    res = run("orbit", *args, "--format", "csv")
    assert res.exit_code == 2, (res.exit_code, res.stdout)
    assert res.stderr.count("\n") == 1 and words in res.stderr and "Traceback" not in res.stderr


def test_the_wall_of_death_given_its_speed(run):
    """--speed on the drum: every tilt of eq. S2, one row each; the contact
    runs round the drum's radius, so Omega = v / R, and eq. S2 written out
    holds at the printed tilt; a speed no tilt gives is one no_orbit row."""
    res = run("orbit", "--surface", "cylinder", "--diameter", "32ft", "--wall-height", "6", "--height", "2",
              "--speed", "30mph", "--speed", "1", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    fast, slow = rows(res.stdout)
    assert fast["status"] == "ok" and fast["branch"] == "0" and float(fast["v_contact_m_s"]) == 13.4112
    omega, alpha = float(fast["omega_rad_s"]), np.radians(float(fast["alpha_deg"]))
    assert omega == pytest.approx(13.4112 / 4.8768, rel=1e-12)
    rp = 4.8768 - 0.3 * np.cos(alpha)
    assert omega ** 2 == pytest.approx(9.80665 / np.tan(alpha) / (2 * rp + 0.5 * 0.3 * np.cos(alpha)), rel=1e-10)
    assert slow["status"] == "no_orbit" and "S2 has no root" in slow["reason"] and slow["branch"] == ""
    assert float(slow["rho_contact_m"]) == pytest.approx(4.8768)


@pytest.mark.parametrize("command, extra", [
    ("orbit", ["--height", "2", "--height", "4", "--alpha", "10"]),
    ("sweep", ["--height", "0:4:0.5", "--alpha", "10"]),
    ("limits", ["--height", "2", "--height", "4"]),
    ("map", ["--height", "0:4:0.1"]),
    ("ride", ["--height", "4", "--speed", "40km/h"]),
    ("stability", ["--height", "4", "--alpha", "10"]),
    ("simulate", ["--height", "4", "--alpha", "10", "--periods", "0.1"]),
    ("simulate", ["--machine", "stunt125", "--height", "4", "--speed", "40km/h", "--periods", "0.1"]),
])
def test_a_lane_typed_above_the_wall_is_refused_by_every_command(run, command, extra):
    # one meaning everywhere: the wall's top is the arena's, a lane over it is bad input
    res = run(command, "--surface", "cylinder", "--diameter", "9", "--wall-height", "3", *extra, "--format", "csv")
    assert res.exit_code == 2 and res.stdout == "" and res.stderr.count("\n") == 1
    assert "'--height'" in res.stderr and "at most 3 m on this cylinder" in res.stderr and "got 4 m" in res.stderr


def _rows_of_a_file_on_the_drum(run, tmp_path, command, text):
    """``command --input`` of the lanes ``text`` on a 9 m drum 3 m high: its rows."""
    path = tmp_path / "lanes.csv"
    path.write_text(text)
    res = run(command, "--input", str(path), "--surface", "cylinder", "--diameter", "9", "--wall-height", "3",
              "--format", "csv")
    assert res.exit_code == 0, res.stderr
    return rows(res.stdout)


def test_a_row_of_a_file_off_the_wall_is_a_status(run, tmp_path):
    # in a batch every row yields its row: the one above the wall's top says why
    got = _rows_of_a_file_on_the_drum(run, tmp_path, "orbit", "height,alpha\n2,10\n4,10\n")
    assert [r["status"] for r in got] == ["ok", "no_fit"] and "above the wall's top" in got[1]["reason"]


@pytest.mark.parametrize("text, words", [
    (b"", "empty"),
    (b"rho_m,z_m\n\x00\x01\n", "not a text file"),
    (b"rho_m,z_m\n1,0\n1,2\n1,1\n1,3\n", "row 3: z must rise strictly"),
    (b"rho_m,z_m\n1,0\n1,1\n2,2\n3,2.2\n4,2.4\n", "turns by 45"),
])
def test_bad_profile_files_are_one_line_and_exit_2(run, tmp_path, text, words):
    path = tmp_path / "p.csv"
    path.write_bytes(text)
    res = run("orbit", "--surface", "profile", "--profile", str(path), "--height", "1", "--alpha", "10")
    assert res.exit_code == 2 and res.stderr.count("\n") == 1 and words in res.stderr


def test_limits_of_a_file_row_off_the_wall_is_its_no_fit_row(run, tmp_path):
    on, off = _rows_of_a_file_on_the_drum(run, tmp_path, "limits", "height\n2\n4\n")
    assert on["status"] == "ok" and int(on["intervals"]) == 1
    # the lane echoed as given, its status and reason the orbit's
    assert (off["status"], float(off["height_m"])) == ("no_fit", 4.0) and "above the wall's top" in off["reason"]


def test_a_rim_that_meets_a_profile_away_from_its_contact_is_no_fit(run, tmp_path):
    """A wheel of 1 m on a lane 4 m up a profile with a neck (its wall
    bulging out above the lane): at 80 deg it rides, at 100 deg it fits the
    wall's bend at the contact (S4) but its rim crosses the wall higher up
    (docs/surfaces.md eq. S4g)."""
    z = np.linspace(0.0, 6.0, 121)
    path = tmp_path / "neck.csv"
    path.write_text("rho_m,z_m\n" + "".join(f"{2.0 - 0.9 * np.sin(0.9 * v):.12f},{v:.12f}\n" for v in z))
    res = run("orbit", "--surface", "profile", "--profile", str(path), "-a", "1", "--height", "4",
              "--alpha", "80", "--alpha", "100", "--no-stability", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    rides, crosses = rows(res.stdout)
    assert rides["status"] == "ok"
    assert crosses["status"] == "no_fit"
    assert crosses["reason"].startswith("the wheel's rim crosses the wall away from its contact")
    # S4 holds there: the local margin sin(alpha + beta) - a kappa_parallel is positive
    beta, rho = np.radians(float(crosses["wall_angle_deg"])), float(crosses["rho_contact_m"])
    assert np.sin(np.radians(100.0) + beta) - 1.0 * np.sin(beta) / rho > 0.05
