"""``deathsphere ride`` and ``deathsphere machines`` on the command line."""

import csv
import io

import pytest


def _rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_ride_with_units_and_a_preset(run):
    res = run("ride", "--theta", "90", "--speed", "40km/h", "--diameter", "16ft", "--format", "csv")
    assert res.exit_code == 0
    (row,) = _rows(res.stdout)
    assert row["status"] == "ok" and float(row["v_contact_m_s"]) * 3.6 == pytest.approx(40.0)
    assert float(row["r_m"]) == pytest.approx(2.4384) and row["machine"] == "stunt125"


def test_the_riders_question_one_row_per_height(run):
    res = run("ride", "--diameter", "16ft", "--height", "0:2.4:0.2m", "--speed", "30:70:5km/h", "--mu", "1",
              "--max-g", "8", "--summary", "--format", "csv")
    assert res.exit_code == 0
    rows = _rows(res.stdout)
    assert [round(float(r["height_m"]), 6) for r in rows] == [round(0.2 * i, 6) for i in range(13)]
    assert all(r["speeds_tried"] == "9" for r in rows)          # a count
    equator = rows[-1]
    assert float(equator["speeds_ok"]) >= 1
    assert 30 / 3.6 <= float(equator["v_contact_min_m_s"]) <= float(equator["v_contact_max_m_s"]) <= 70 / 3.6


def test_overrides_and_machine_file(run, tmp_path):
    path = tmp_path / "m.toml"
    path.write_text("mass = 120\ncom_height = 0.7\n")
    a = _rows(run("ride", "--theta", "90", "--alpha", "15", "--machine-file", str(path), "--format", "csv").stdout)
    b = _rows(run("ride", "--theta", "90", "--alpha", "15", "--mass", "120", "--com-height", "0.7",
                  "--format", "csv").stdout)
    assert a[0]["omega_rad_s"] == b[0]["omega_rad_s"]
    c = _rows(run("ride", "--theta", "90", "--alpha", "15", "--format", "csv").stdout)
    assert c[0]["omega_rad_s"] != b[0]["omega_rad_s"]


@pytest.mark.parametrize("args, words", [
    (("--mass", "0"), "--mass"),
    (("--tyre-radius", "0.35"), "less than the wheel radius"),
    (("--roll-inertia", "100"), "triangle"),
    (("--machine", "bus"), "--machine"),
])
def test_bad_machines_exit_2(run, args, words):
    res = run("ride", "--theta", "90", "--alpha", "10", *args)
    assert res.exit_code == 2 and words in res.output


def test_machines_lists_the_presets(run):
    res = run("machines", "--format", "csv")
    rows = _rows(res.stdout)
    assert [(r["name"], r["kind"]) for r in rows] == [
        ("paper-wheel", "single-contact"), ("benchmark-bicycle-rigid", "single-contact"), ("stunt125", "single-contact"),
        ("benchmark-bicycle", "two-wheeler"), ("sport-tourer", "two-wheeler"), ("stunt125-steer", "two-wheeler")]
    # the two-wheelers' columns are appended: the single-contact machine's come first, as before
    assert list(rows[0])[:13] == ["name", "mass_kg", "com_height_m", "wheel_radius_m", "tyre_radius_m",
                                  "roll_inertia_kg_m2", "pitch_inertia_kg_m2", "yaw_inertia_kg_m2",
                                  "spin_inertia_kg_m2", "head_height_m", "source", "width_m", "kind"]
    assert all(r["source"] for r in rows)


def test_vertical_loops(run):
    res = run("ride", "--vertical", "--theta", "90", "--v-top", "20:40:10km/h", "--diameter", "16ft",
              "--format", "csv")
    rows = _rows(res.stdout)
    assert res.exit_code == 0 and [r["status"] for r in rows] == ["ok", "ok", "ok"]
    assert float(rows[0]["v_top_min_m_s"]) == pytest.approx((9.80665 * (2.4384 - 0.8)) ** 0.5)
    bad = run("ride", "--vertical", "--theta", "90", "--v-top", "5", "--alpha", "10")
    assert bad.exit_code == 2


def test_ride_rows_echo_their_inputs_and_never_hold_inf(run):
    """As every table: a speed typed in km/h reads back as typed, theta and
    alpha as given, and "no limit" is an empty cell, not inf."""
    text = run("ride", "--theta", "90", "--com-speed", "40km/h", "--diameter", "16ft", "--format", "csv").stdout
    rows = _rows(text)
    assert rows and all(r["v_cm_km_h"] == "40.0" and r["theta_deg"] == "90.0" for r in rows)
    contact = _rows(run("ride", "--theta", "90", "--speed", "40km/h", "--diameter", "16ft", "--format", "csv").stdout)
    assert contact and all(r["v_contact_m_s"] == repr(40 / 3.6) for r in contact)
    assert all(r["mu_available"] == "" and r["max_g"] == "" for r in rows) and "inf" not in text
    tilted = _rows(run("ride", "--theta", "60.1", "--alpha", "10.3", "--format", "csv").stdout)
    assert (tilted[0]["theta_deg"], tilted[0]["alpha_deg"]) == ("60.1", "10.3")


def test_a_vertical_loop_obeys_mu_and_max_g(run):
    """A loop that exceeds the load (here 7.8 g at the bottom) or slips
    somewhere says so in its status, as a horizontal orbit does."""
    args = ("ride", "--vertical", "--theta", "90", "--v-top", "30km/h", "--format", "csv")
    (free,) = _rows(run(*args).stdout)
    assert free["status"] == "ok" and float(free["load_bottom_g"]) > 7
    (limited,) = _rows(run(*args, "--mu", "0.1", "--max-g", "2").stdout)
    assert limited["status"] == "over_g" and "load_bottom_g" in limited["reason"]
    need = float(free["mu_required"])
    (slips,) = _rows(run(*args, "--mu", str(need * 0.99)).stdout)
    assert slips["status"] == "slips" and float(slips["mu_available"]) < need


def test_the_riders_table_groups_by_the_contact_point_asked_for(run):
    """Two contact points whose heights round alike (179.999 and 180 deg:
    4.6e-10 m apart) are two rows, each of the speeds tried there."""
    rows = _rows(run("ride", "--theta", "179.999", "--theta", "180", "--speed", "10:20:5", "--summary",
                     "--format", "csv").stdout)
    assert [r["theta_deg"] for r in rows] == ["179.999", "180.0"]
    assert [r["speeds_tried"] for r in rows] == ["3", "3"]


def test_the_riders_table_counts_why_speeds_fail(run):
    rows = _rows(run("ride", "--diameter", "16ft", "--height", "0.4", "--height", "2.4", "--com-speed",
                     "10:35:5km/h", "--mu", "1", "--max-g", "5", "--summary", "--format", "csv").stdout)
    detail = _rows(run("ride", "--diameter", "16ft", "--height", "0.4", "--height", "2.4", "--com-speed",
                       "10:35:5km/h", "--mu", "1", "--max-g", "5", "--no-stability", "--format", "csv").stdout)
    for row, height in zip(rows, ("0.4", "2.4")):
        mine = [d for d in detail if d["height_m"] == height]
        fails = {c: sum(d["status"] == s for d in mine) for c, s in (("slips", "slips"), ("over_g", "over_g"),
                                                                      ("no_contact", "no_contact"))}
        fails["head_hits"] = sum("head" in d["reason"] for d in mine)
        assert {c: int(row[c]) for c in fails} == fails
        assert int(row["speeds_ok"]) + sum(fails.values()) + int(row["no_orbit"]) == int(row["speeds_tried"]) == 6
        assert float(row["mu_available"]) == 1 and float(row["max_g"]) == 5
    assert int(rows[1]["head_hits"]) >= 1 and int(rows[0]["slips"]) >= 1


def test_the_riders_table_of_tilts_names_its_counts_for_tilts(run):
    (row,) = _rows(run("ride", "--theta", "90", "--alpha", "5:25:5", "--summary", "--format", "csv").stdout)
    assert row["tilts_tried"] == "5" and "speeds_tried" not in row


def test_mu_takes_a_range_like_the_other_axes(run):
    """A crew asks "mu 0.8 to 1": each value its rows (contact point outer,
    then mu, then speed), each judged against its own mu."""
    rows = _rows(run("ride", "--diameter", "16ft", "--height", "0.4", "--height", "1.2", "--speed", "10:20:5km/h",
                     "--mu", "0.6:1:0.2", "--no-stability", "--format", "csv").stdout)
    assert [r["mu_available"] for r in rows] == ["0.6"] * 3 + ["0.8"] * 3 + ["1.0"] * 3 + ["0.6"] * 3 + \
        ["0.8"] * 3 + ["1.0"] * 3
    assert [r["input_row"] for r in rows] == [str(i) for i in range(1, 19)]
    for r in rows:
        assert (r["status"] == "slips") == (float(r["mu_required"]) > float(r["mu_available"]))
    assert {r["status"] for r in rows} >= {"ok", "slips"}
    table = _rows(run("ride", "--diameter", "16ft", "--height", "0.4", "--speed", "10:20:5km/h", "--mu",
                      "0.6:1:0.2", "--summary", "--format", "csv").stdout)
    assert [r["mu_available"] for r in table] == ["0.6", "0.8", "1.0"]
    assert [int(r["speeds_ok"]) for r in table] == sorted(int(r["speeds_ok"]) for r in table)
    loops = _rows(run("ride", "--vertical", "--theta", "60", "--v-top", "30km/h", "--mu", "0.5", "--mu", "0.7",
                      "--machine", "benchmark-bicycle-rigid", "--format", "csv").stdout)
    assert [(r["mu_available"], r["status"]) for r in loops] == [("0.5", "slips"), ("0.7", "ok")]


def test_the_speed_options_one_at_a_time_naming_the_one_typed(run):
    res = run("ride", "--theta", "90", "--speed", "40km/h", "--com-speed", "30km/h", "--diameter", "16ft")
    assert res.exit_code == 2 and "--com-speed" in res.output and "Traceback" not in res.output
    res = run("ride", "--theta", "90", "--period", "3m", "--diameter", "16ft")
    assert res.exit_code == 2 and "--period" in res.output and "a time in s or min" in res.output
    (row,) = _rows(run("ride", "--height", "5ft", "--period", "1.3s", "--diameter", "16ft", "--format", "csv").stdout)
    assert row["period_s"] == "1.3" and row["status"] == "ok"


def test_speed_means_the_contacts_in_orbit_and_simulate_as_in_ride(run):
    """orbit's and simulate's --speed is the contact's, as ride's; --com-speed
    the centre's; both at once is refused naming the second."""
    speed = run("orbit", "--theta", "60", "--speed", "7", "--format", "csv")
    com = run("orbit", "--theta", "60", "--com-speed", "7", "--format", "csv")
    assert speed.exit_code == com.exit_code == 0 and speed.stdout != com.stdout
    assert _rows(speed.stdout)[0]["v_contact_m_s"] == "7.0" and _rows(com.stdout)[0]["v_cm_m_s"] == "7.0"
    both = run("sweep", "--theta", "60", "--speed", "7", "--com-speed", "7")
    assert both.exit_code == 2 and "--com-speed" in both.output and "Traceback" not in both.output
    res = run("simulate", "--machine", "stunt125", "--diameter", "16ft", "--theta", "100", "--com-speed", "25km/h",
              "--periods", "0.05", "--format", "csv", "--summary-only")
    assert res.exit_code == 0 and float(_rows(res.stdout)[0]["speed_m_s"]) == pytest.approx(25 / 3.6)
    ride = run("ride", "--machine", "stunt125", "--diameter", "16ft", "--theta", "100", "--speed", "25km/h",
               "--format", "csv")
    res = run("simulate", "--machine", "stunt125", "--diameter", "16ft", "--theta", "100", "--speed", "25km/h",
              "--periods", "0.05", "--format", "csv", "--summary-only")
    assert res.exit_code == 0 and float(_rows(res.stdout)[0]["alpha_deg"]) == pytest.approx(
        min(float(r["alpha_deg"]) for r in _rows(ride.stdout) if r["alpha_deg"]), abs=1e-9)
