"""``vertical --input`` reads its own ``--points`` output: each point is a
request for its orbit, its speed at phi taken back to the top by energy
conservation (eq. 27); the other output columns are ignored."""

import csv
import io

import pytest


def rows(text: str) -> list[dict]:
    return list(csv.DictReader(io.StringIO(text)))


@pytest.mark.parametrize("side, theta, v_top", [("inside", 60, 6), ("inside", 90, 7.5), ("outside", 90, 0.5)])
def test_each_point_read_back_is_its_orbit(run, tmp_path, side, theta, v_top):
    setup = ["--side", side, "--theta", str(theta)]
    points = run("vertical", *setup, "--v-top", str(v_top), "--points", "13", "--format", "csv")
    path = tmp_path / "points.csv"
    path.write_text(points.stdout)
    orbit = rows(run("vertical", *setup, "--v-top", str(v_top), "--format", "csv", "--no-stability").stdout)[0]
    res = run("vertical", "--side", side, "--input", str(path), "--format", "csv", "--no-stability")
    again = rows(res.stdout)
    assert res.exit_code == 0, res.stderr
    assert [r["input_row"] for r in again] == [str(i) for i in range(1, 14)]
    for row in again:
        assert row["status"] == orbit["status"] and row["theta_deg"] == orbit["theta_deg"]
        for name in ("v_cm_m_s", "v_bottom_m_s", "normal_top_per_mass_m_s2", "phi_leave_deg"):
            if orbit[name] == "":  # undefined for this orbit (outside: no bottom reached)
                assert row[name] == "", name
            else:
                assert float(row[name]) == pytest.approx(float(orbit[name]), rel=1e-9, abs=1e-9), name


def test_a_speed_no_top_speed_gives_is_its_rows_reason(run):
    # from rest at the top a wheel has gained speed by phi = 180: 1 m/s there is too slow
    res = run("vertical", "--input", "-", "--format", "csv", "--no-stability",
              input="theta,v_top,phi\n90,1,180\n90,6,0\n")
    out = rows(res.stdout)
    assert res.exit_code == 1 and len(out) == 2
    assert out[0]["status"] == "invalid" and "from rest at the top" in out[0]["reason"]
    assert out[1]["status"] == "ok" and float(out[1]["v_cm_m_s"]) == 6.0


def test_a_top_speed_given_with_the_file_is_the_tops(run, tmp_path):
    path = tmp_path / "points.csv"
    path.write_text(run("vertical", "--theta", "90", "--v-top", "6", "--points", "5", "--format", "csv").stdout)
    out = rows(run("vertical", "--input", str(path), "--v-top", "7", "--format", "csv", "--no-stability").stdout)
    assert {float(r["v_cm_m_s"]) for r in out} == {7.0}
