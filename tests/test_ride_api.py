"""deathsphere.Machine and deathsphere.ride (docs/machine.md): validation,
broadcasting, every tilt for a speed, height and diameter, the presets (the
benchmark bicycle's totals recomputed from its published table here)."""

import numpy as np
import pytest

import deathsphere
from deathsphere import Machine, ParameterError
from deathsphere.api.machines import PRESETS, benchmark_bicycle_rigid, machine_file

STUNT = dict(mass=165.0, h=0.8, a=0.3, t=0.045, inertia=(25.0, 40.0, 20.0), spin_inertia=0.8, head=1.65)


@pytest.mark.parametrize("change, words", [
    (dict(mass=0.0), "mass (machine mass) must be"),
    (dict(mass=-3.0), "mass (machine mass) must be"),
    (dict(h=-0.1), "com_height"),
    (dict(t=0.3), "must be less than the wheel radius"),
    (dict(t=0.5), "must be less than the wheel radius"),
    (dict(head=0.5), "must be at least the centre-of-mass height"),
    (dict(mass=float("nan")), "must be a finite number"),
    (dict(a=float("inf")), "must be a finite number"),
    (dict(inertia=(1.0, 1.0, 3.0)), "triangle inequality"),
    (dict(inertia=(1.0, 1.0)), "three numbers"),
    (dict(inertia=(1.0, float("nan"), 1.0)), "finite"),
    (dict(spin_inertia=50.0), "exceeds the pitch inertia"),
])
def test_bad_machines_raise_one_line(change, words):
    with pytest.raises(ParameterError) as info:
        Machine(**{**STUNT, **change})
    assert words in str(info.value) and "\n" not in str(info.value)


def test_the_cli_refuses_a_bad_machine_with_status_2():
    from click.testing import CliRunner

    from deathsphere.cli import cli

    res = CliRunner().invoke(cli, ["ride", "--theta", "90", "--alpha", "10", "--head-height", "0.1"])
    assert res.exit_code == 2 and "head_height" in res.output


def test_the_benchmark_bicycle_from_its_published_table():
    """Meijaard et al. (2007) Table 1, typed here again: masses R 2, B 85,
    H 4, F 3 kg at (x, z) = (0, -0.3), (0.3, -0.9), (0.9, -0.7), (1.02,
    -0.35) m: total 94 kg, centre of mass 0.8612 m above the ground."""
    m = np.array([2.0, 85.0, 4.0, 3.0])
    x = np.array([0.0, 0.3, 0.9, 1.02])
    z = np.array([-0.3, -0.9, -0.7, -0.35])
    bike = benchmark_bicycle_rigid()
    assert bike.mass == m.sum() == 94.0
    assert bike.com_height == pytest.approx(-(m * z).sum() / m.sum(), rel=1e-12)
    assert bike.com_height == pytest.approx(0.86117, abs=1e-5)
    # the spin inertia keeps the wheels' angular momentum at a speed: J/a = IRyy/rR + IFyy/rF
    assert bike.spin_inertia / bike.wheel_radius == pytest.approx(0.12 / 0.3 + 0.28 / 0.35)
    # pitch inertia by the parallel-axis theorem, by hand
    xt, zt = (m * x).sum() / 94, (m * z).sum() / 94
    iyy = 0.12 + 11 + 0.06 + 0.28 + (m * ((x - xt) ** 2 + (z - zt) ** 2)).sum()
    assert bike.inertia[1] == pytest.approx(iyy, rel=1e-12)


def test_ride_broadcasts_like_orbit():
    t = deathsphere.ride([[60], [90], [120]], [5, 15], machine="stunt125", stability=False)
    assert t.shape == (3, 2) and len(t) == 6
    one = deathsphere.ride(90, 15, machine="stunt125", diameter="16ft")
    assert one.shape == () and str(one["status"]) == "ok"
    assert float(one["r_m"]) == pytest.approx(2.4384)
    assert float(one["v_cm_km_h"]) == pytest.approx(8.30136 * 3.6, abs=1e-4)


def test_ride_reproduces_orbit_for_the_papers_wheel():
    t = deathsphere.ride([[30], [60], [90], [150]], [-40, 5, 10, 30, 60], machine="paper-wheel", r=3.0,
                         stability=False)
    o = deathsphere.orbit([[30], [60], [90], [150]], [-40, 5, 10, 30, 60], r=3.0, stability=False)
    np.testing.assert_array_equal(t["status"], o["status"])
    ok = o["status"] == "ok"
    for a, b in (("omega_rad_s", "omega_rad_s"), ("v_cm_m_s", "v_cm_m_s"), ("mu_required", "mu_required"),
                 ("normal_per_mass_m_s2", "normal_per_mass_m_s2")):
        np.testing.assert_allclose(t[a][ok], o[b][ok], rtol=1e-12)


def test_every_tilt_for_a_speed_and_the_rows_verify():
    t = deathsphere.ride(height=[[0.3], [1.2], [2.4]], com_speed=["25km/h", "40km/h"], machine="stunt125",
                         diameter="16ft", stability=False)
    assert t.shape == (3, 2) and len(t) == 6      # one tilt per speed here: the grid keeps its axes
    assert set(t["input_row"].tolist()) == set(range(1, 7))
    found = np.isfinite(t["alpha_deg"])
    np.testing.assert_allclose(t["v_cm_m_s"][found], np.array([25 / 3.6, 40 / 3.6])[
        (t["input_row"][found] - 1) % 2], rtol=1e-9)
    # each root re-evaluated with alpha given: the same row
    again = deathsphere.ride(t["theta_deg"][found], t["alpha_deg"][found], machine="stunt125", diameter="16ft",
                             stability=False)
    np.testing.assert_allclose(again["v_cm_m_s"], t["v_cm_m_s"][found], rtol=1e-12)
    np.testing.assert_allclose(t["height_m"], np.repeat([0.3, 1.2, 2.4], 2)[t["input_row"] - 1], rtol=1e-12)


def test_a_speed_no_tilt_gives_is_one_no_orbit_row():
    t = deathsphere.ride(90, speed=0.5, machine="stunt125", r=2.45, stability=False)
    assert len(t) == 1 and t["status"][0] == "no_orbit" and "M12" in t["reason"][0]


def test_inputs_are_checked():
    with pytest.raises(ParameterError, match="exactly one of theta and height"):
        deathsphere.ride(90, height=1.0, alpha=10, machine="stunt125")
    with pytest.raises(ParameterError, match="exactly one of alpha, speed, com_speed and period"):
        deathsphere.ride(90, machine="stunt125")
    with pytest.raises(ParameterError, match="at most the globe's diameter"):
        deathsphere.ride(height=6.0, alpha=10, machine="stunt125", diameter="16ft")
    with pytest.raises(ParameterError, match="machine must be one of"):
        deathsphere.ride(90, 10, machine="unicycle")
    with pytest.raises(ParameterError, match="needs r > a"):
        deathsphere.ride(90, 10, machine="stunt125", r=0.2)


def test_the_head_hits_the_globe_when_the_up_axis_runs_along_the_wall():
    """Above the equator with the up-axis close to the wall (theta = 60,
    alpha = 50 deg): the head point H = P + (head - t) u + t n_in lies
    outside the sphere (by hand: |H| = 2.68 m > r = 2.45 m)."""
    t = deathsphere.ride(60, 50, machine=Machine(**STUNT), r=2.45, stability=False)
    P = 2.45 * np.array([np.sin(np.radians(60)), np.cos(np.radians(60))])
    u = np.array([-np.cos(np.radians(50)), np.sin(np.radians(50))])
    H = P - 0.045 * P / 2.45 + (1.65 - 0.045) * u
    assert float(t["head_clearance_m"]) == pytest.approx(2.45 - np.hypot(*H), rel=1e-12)
    assert str(t["status"]) == "no_fit" and "head" in str(t["reason"]) and float(t["head_clearance_m"]) < 0


def test_machine_files(tmp_path):
    toml = tmp_path / "bike.toml"
    toml.write_text('name = "my bike"\nmass = 170\nwheel_radius = "12in"\nhead_height = 1.7\n')
    m = machine_file(toml)
    assert (m.name, m.mass, m.head_height) == ("my bike", 170.0, 1.7) and m.wheel_radius == pytest.approx(0.3048)
    assert m.inertia == PRESETS["stunt125"].inertia
    csv = tmp_path / "bike.csv"
    csv.write_text("mass,com_height,head_height\n150,0.7,1.6\n")
    assert machine_file(csv).h == 0.7
    bad = tmp_path / "bad.toml"
    bad.write_text("mas = 3\n")
    with pytest.raises(ParameterError, match="unknown key 'mas'"):
        machine_file(bad)
    worse = tmp_path / "worse.toml"
    worse.write_text("mass = -1\n")
    with pytest.raises(ParameterError, match="mass"):
        machine_file(worse)


def test_the_stability_columns_of_the_papers_wheel_are_orbits():
    th, al = [[40], [90], [130]], [-20, 10, 30, 60, 80]
    t = deathsphere.ride(th, al, machine="paper-wheel", r=3.0)
    o = deathsphere.orbit(th, al, r=3.0)
    np.testing.assert_array_equal(t["stability"], o["stability"])
    assert set(t["stability"].tolist()) >= {"stable", "unstable"}
    np.testing.assert_allclose(t["freq_fast_rad_s"], o["freq_fast_rad_s"], rtol=1e-9)
    a = deathsphere.ride(90, [10, 20, 30], machine="stunt125", diameter="16ft")
    assert set(a["stability"].tolist()) == {"unstable"} and a["stability_method"][0] == "exact-linearisation-steer-locked"
    assert all(a["growth_rate_1_s"] > 0)


@pytest.mark.parametrize("target", [{"alpha": 10.0}, {"speed": "40km/h"}])
def test_a_height_is_echoed_as_typed(target):
    """0.6 m reaches theta through arccos and would read back as
    0.6000000000000003: the row prints the height the rider gave."""
    t = deathsphere.ride(height=[0.6, 1.2], machine="stunt125", diameter="16ft", stability=False, **target)
    rows = t["input_row"].ravel()
    assert set(rows.tolist()) == {1, 2}
    assert t["height_m"].ravel().tolist() == np.array([0.6, 1.2])[rows - 1].tolist()


def test_the_api_speaks_the_commands_language():
    """The command's default machine, its overrides by the options' names,
    units as text, and the rider's table."""
    t = deathsphere.ride(90, speed="30km/h", diameter="16ft")
    assert t[0]["machine"] == "stunt125" and t[0]["status"] == "ok"
    heavy = deathsphere.ride(90, speed="30km/h", diameter="16ft", mass=150, com_height=0.7, wheel_radius="12in",
                             tyre_radius=0.04, head_height=1.6, roll_inertia=20, pitch_inertia=35, yaw_inertia=18,
                             spin_inertia=0.7)
    same = deathsphere.ride(90, speed="30km/h", diameter="16ft", machine=Machine(
        mass=150, h=0.7, a=0.3048, t=0.04, inertia=(20, 35, 18), spin_inertia=0.7, head=1.6))
    assert heavy[0]["lean_deg"] == same[0]["lean_deg"] != t[0]["lean_deg"]
    with pytest.raises(ParameterError, match="mass"):
        deathsphere.ride(90, speed="30km/h", mass=0)
    summary = deathsphere.ride(height=[[0.4], [2.4]], speed=["10km/h", "20km/h", "30km/h"], diameter="16ft", mu=1,
                               max_g=5, summary=True)
    assert summary["height_m"].tolist() == [0.4, 2.4] and summary["speeds_tried"].tolist() == [3, 3]


def test_a_speed_grid_keeps_its_axes_in_xarray_with_units():
    pytest.importorskip("xarray")
    t = deathsphere.ride(height=[[0.8], [1.6], [2.4]], com_speed=["15km/h", "20km/h", "25km/h", "30km/h"],
                         diameter="16ft", stability=False)
    ds = t.to_xarray()
    assert ds["load_g"].dims == ("height_m", "v_cm_m_s") and ds.sizes == {"height_m": 3, "v_cm_m_s": 4}
    np.testing.assert_allclose(ds["height_m"].values, [0.8, 1.6, 2.4])
    np.testing.assert_allclose(ds["v_cm_km_h"].sel(height_m=1.6).values, [15, 20, 25, 30])
    assert (ds["load_g"].attrs["units"], ds["height_m"].attrs["units"], ds["v_cm_km_h"].attrs["units"],
            ds["mu_required"].attrs["units"], ds["omega_rad_s"].attrs["units"]) == ("g", "m", "km/h", "1", "rad/s")
    assert "units" not in ds["status"].attrs
    by_contact = deathsphere.ride(height=[[0.8], [1.6]], speed=["30km/h", "40km/h"], diameter="16ft",
                                  stability=False).to_xarray()
    assert by_contact["load_g"].dims == ("height_m", "v_contact_m_s")
    np.testing.assert_allclose(by_contact["v_contact_m_s"].values, [30 / 3.6, 40 / 3.6])
    by_theta = deathsphere.ride([60, 90], [[5], [15]], diameter="16ft", stability=False).to_xarray()
    assert by_theta["v_cm_m_s"].dims == ("alpha_deg", "theta_deg")


def test_the_functions_api_md_names_exist_where_it_says():
    """Every function of docs/api.md's table of commands is in deathsphere
    (and in deathsphere.api), as the page says."""
    import re
    from pathlib import Path

    text = (Path(deathsphere.__file__).parent / "docs" / "api.md").read_text(encoding="utf-8")
    table = text[text.index("## Commands and functions"):text.index("## Results")]
    names = set(re.findall(r"`([A-Za-z_][A-Za-z0-9_]*)\(", table))
    assert {"ride", "ride_summary", "Machine", "machines_table", "machine_file", "limits_input",
            "stability_input"} <= names
    # horizontal_orbit is named as what Setup.orbit replaced
    missing = sorted(n for n in names - {"horizontal_orbit"} if not hasattr(deathsphere, n))
    assert missing == []
    commands = names - {"horizontal_orbit", "Setup", "docs_topics", "doc_text"}
    assert sorted(n for n in commands if not hasattr(deathsphere.api, n)) == []


def test_the_riders_table_of_one_request_and_of_paired_arrays():
    one = deathsphere.ride(90, speed=10, summary=True)
    assert len(one) == 1 and one[0]["speeds_tried"] == 1
    # theta and speed paired along one axis: each request is its own contact point
    paired = deathsphere.ride([60, 90], speed=[8, 10], summary=True)
    assert paired["theta_deg"].tolist() == [60.0, 90.0] and paired["speeds_tried"].tolist() == [1, 1]
    grid = deathsphere.ride([[60], [90]], [5, 10, 15], summary=True)
    assert grid["tilts_tried"].tolist() == [3, 3]


def test_ride_summary_of_a_table_groups_by_the_inputs_as_given():
    """Given a table only: a grid groups along its last axis, a flat table
    by its contact inputs exactly as given (never a rounded height)."""
    t = deathsphere.ride([[179.999], [180]], speed=[10, 15, 20], stability=False)
    flat = t[np.arange(len(t))]
    for table in (t, flat):
        s = deathsphere.ride_summary(table)
        assert s["theta_deg"].tolist() == [179.999, 180.0] and s["speeds_tried"].tolist() == [3, 3]
    with pytest.raises(ParameterError, match="tried"):
        deathsphere.ride_summary(t, tried="laps")


def test_the_speed_is_the_contacts_and_the_centre_of_mass_runs_at_omega_r_g():
    """For random lanes: the row's contact speed is the one asked for, by the
    sphere's geometry (the contact at r sin(theta) from the axis), and its
    centre of mass runs at Omega |r_G| of the forward model at the tilt
    returned (ride by alpha: an independent evaluation)."""
    rng = np.random.default_rng(11)
    height = rng.uniform(0.3, 2.6, 12)
    v = rng.uniform(20.0, 45.0, 12) / 3.6
    t = deathsphere.ride(height=height, speed=v, machine="stunt125", diameter="16ft", stability=False)
    found = np.isfinite(t["alpha_deg"])
    assert found.sum() >= 8
    req = t["input_row"][found] - 1
    r = 16 * 0.3048 / 2
    theta = np.arccos(height[req] / r - 1.0)
    np.testing.assert_allclose(t["omega_rad_s"][found] * r * np.sin(theta), v[req], rtol=1e-9)
    np.testing.assert_array_equal(t["v_contact_m_s"][found], v[req])        # echoed as asked
    again = deathsphere.ride(t["theta_deg"][found], t["alpha_deg"][found], machine="stunt125", diameter="16ft",
                             stability=False)
    np.testing.assert_allclose(again["v_contact_m_s"], v[req], rtol=1e-9)
    np.testing.assert_allclose(t["v_cm_m_s"][found], again["omega_rad_s"] * np.abs(again["com_orbit_radius_m"]),
                               rtol=1e-9)


def test_a_lap_time_is_the_rate_two_pi_over_it_and_a_16ft_globe_lane_moves_as_the_changelog_says():
    t = deathsphere.ride(height="5ft", period=["1.3s", "0.02min"], machine="stunt125", diameter="16ft",
                         stability=False)
    assert list(t["period_s"]) == [1.3, 1.2] and list(t["status"]) == ["ok", "ok"]
    np.testing.assert_allclose(t["omega_rad_s"], 2 * np.pi / np.array([1.3, 1.2]), rtol=1e-9)
    contact = deathsphere.ride(height="5ft", speed="40km/h", diameter="16ft", stability=False)[0]
    centre = deathsphere.ride(height="5ft", com_speed="40km/h", diameter="16ft", stability=False)[0]
    assert round(contact["load_g"], 2) == 3.81 and round(centre["load_g"], 2) == 8.63
    assert round(contact["v_cm_km_h"], 1) == 26.4 and round(centre["v_contact_m_s"] * 3.6, 1) == 61.6


def test_exactly_one_way_to_hold_a_lane_and_the_refusal_names_the_keyword():
    for extra, named in (({"speed": 8, "com_speed": 8}, "com_speed"), ({"alpha": 10, "period": 1.3}, "period"),
                         ({"speed": 8, "period": 1.3}, "period")):
        with pytest.raises(ParameterError) as err:
            deathsphere.ride(90, machine="stunt125", diameter="16ft", **extra)
        assert err.value.param == named and "exactly one of" in str(err.value)
    with pytest.raises(ParameterError, match="does not take com_speed"):
        deathsphere.ride(machine="stunt125-steer", steer="free", height=1, com_speed=5, diameter="16ft")
    with pytest.raises(ParameterError, match="period"):
        deathsphere.ride(90, period=0, diameter="16ft")


def test_a_contact_speed_at_the_floor_is_a_no_orbit_row_with_its_reason():
    t = deathsphere.ride(height=[0.0, 1.0], speed=8.0, diameter="16ft", stability=False)
    assert list(t["status"]) == ["no_orbit", "ok"]
    assert "vertical axis" in t["reason"][0]


def test_a_two_wheelers_speed_is_its_rear_contacts_as_the_single_contact_machines():
    """The same word on both models: a two-wheeler's speed runs its rear
    contact round the parallel r sin(theta_rear) at the turn's rate."""
    r = 16 * 0.3048 / 2
    (turn,) = deathsphere.ride(machine="stunt125-steer", steer="free", height="5ft", speed="40km/h",
                               diameter="16ft", stability=False)
    assert turn["v_contact_m_s"] == turn["v_rear_m_s"] == 40 / 3.6
    assert turn["omega_rad_s"] * r * np.sin(np.radians(turn["theta_deg"])) == pytest.approx(40 / 3.6, rel=1e-9)
    (one,) = deathsphere.ride(machine="stunt125", height="5ft", speed="40km/h", diameter="16ft", stability=False)
    assert one["theta_deg"] == pytest.approx(turn["theta_deg"], abs=1e-9)
    assert round(turn["load_g"], 2) == 3.62 and round(one["load_g"], 2) == 3.81
