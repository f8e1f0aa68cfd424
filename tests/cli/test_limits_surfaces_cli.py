"""limits on the other surfaces (docs/limits.md sec. 8): the tilts on a lane,
the lowest and highest lanes, every bad input refused in one line naming
the option (exit 2), and a batch's bad rows as their status and reason."""

import csv
import io
import math

import pytest

import deathsphere


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


DRUM = ("--surface", "cylinder", "--diameter", "32ft")


def test_the_wall_of_death_lane_through_the_command_line(run):
    res = run("limits", *DRUM, "--height", "2m", "--mu", "1", "--max-g", "4", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    (row,) = rows(res.stdout)
    assert row["surface"] == "cylinder" and row["status"] == "ok" and row["intervals"] == "1"
    assert float(row["height_m"]) == 2.0 and float(row["wall_angle_deg"]) == 90.0
    # the drum's rules at the ends, independent of the code: mu = g r'/v^2 at the slow end, the centre's
    # acceleration v^2/(g r') = sqrt(max_g^2 - 1) at the fast end
    for alpha, v, rule in ((row["alpha_max_deg"], row["v_min_m_s"], 1.0),
                           (row["alpha_min_deg"], row["v_max_m_s"], 1 / math.sqrt(15.0))):
        rp = 4.8768 - 0.3 * math.cos(math.radians(float(alpha)))
        assert 9.80665 * rp / float(v) ** 2 == pytest.approx(rule, rel=1e-8)


def test_a_drum_without_a_top_has_no_highest_lane(run):
    res = run("limits", *DRUM, "--mu", "1", "--max-g", "4", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    low, high = rows(res.stdout)
    assert (low["lane"], low["bound"], float(low["height_m"])) == ("lowest", "floor", 0.0)
    assert (high["lane"], high["bound"], high["height_m"]) == ("highest", "none", "")
    assert "upright wall" in high["note"]
    res = run("limits", *DRUM, "--wall-height", "6", "--mu", "1", "--max-g", "4", "--format", "csv")
    high = rows(res.stdout)[1]
    assert (high["bound"], float(high["height_m"])) == ("top", 6.0)


def test_flat_ground_takes_a_turn_radius(run):
    res = run("limits", "--surface", "plane", "--turn-radius", "5", "--mu", "1", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    (row,) = rows(res.stdout)
    assert float(row["rho_contact_m"]) == 5.0 and row["intervals"] == "1"
    # on flat ground mu_required = v^2 / (g r'): at the slow end the friction limit binds
    rp = 5.0 - 0.3 * math.cos(math.radians(float(row["alpha_min_deg"])))
    assert float(row["v_max_m_s"]) ** 2 / (9.80665 * rp) == pytest.approx(1.0, rel=1e-8)


@pytest.mark.parametrize("args, option", [
    (("--theta", "60"), "--theta"),
    (("--height", "-1"), "--height"),
    (("--height", "2", "--turn-radius", "3"), "--turn-radius"),
    (("--height", "2", "--wall-angle", "80"), "--wall-angle"),
    (("--height", "2", "--body", "sphere"), "--body"),
])
def test_bad_input_is_one_line_naming_the_option(run, args, option):
    res = run("limits", *DRUM, *args)
    assert res.exit_code == 2
    assert option in res.stderr and len(res.stderr.strip().splitlines()) == 1 and "Traceback" not in res.stderr


def test_the_globe_refuses_a_height_naming_it(run):
    res = run("limits", "--height", "2")
    assert res.exit_code == 2 and "--height" in res.stderr and len(res.stderr.strip().splitlines()) == 1


def test_a_batch_gives_every_row_its_status_and_reason(run, tmp_path):
    path = tmp_path / "lanes.csv"
    path.write_text("height,mu,body\n2,1,wheel\n-3,1,wheel\n4,abc,wheel\n5,0.5,sphere\n")
    res = run("limits", *DRUM, "--input", str(path), "--format", "csv")
    got = rows(res.stdout)
    assert [r["input_row"] for r in got] == ["1", "2", "3", "4"]
    assert [r["status"] for r in got] == ["ok", "invalid", "invalid", "invalid"]
    assert "height" in got[1]["reason"] and "mu" in got[2]["reason"] and "wheel" in got[3]["reason"]


def test_the_api_broadcasts_lanes_and_limits():
    t = deathsphere.limits(surface="cone", diameter=6, wall_angle=80, wall_height=8, height=[0, 4, 8],
                           mu=[[1.0], [0.5]])
    assert t["input_row"].tolist() == [1, 2, 3, 4, 5, 6]
    assert t["mu_available"].tolist() == [1.0] * 3 + [0.5] * 3
    # less friction, a narrower window: every interval of mu = 0.5 lies in mu = 1's
    assert all(t["alpha_min_deg"][i + 3] >= t["alpha_min_deg"][i] - 1e-9 for i in range(3))
    assert all(t["alpha_max_deg"][i + 3] < t["alpha_max_deg"][i] for i in range(3))
