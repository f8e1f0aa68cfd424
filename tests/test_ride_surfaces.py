"""``ride`` on the drum and the cone (docs/machine.md, "On any surface of
revolution"): the API's keywords build the arena, the rows are the physics'
at the lane asked for, the arena's columns are appended on every surface,
and what a wall does not take is refused in one line naming it."""

import math

import numpy as np
import pytest

import deathsphere
from deathsphere.api.rides import RIDE_COLUMNS
from deathsphere.errors import ParameterError
from deathsphere.physics.ground import Cone, Cylinder, Plane, Profile
from deathsphere.physics.machine_arrays import machine_arrays
from deathsphere.physics.machine_dynamics_on import machine_stability_on
from deathsphere.physics.machine_surface import ride_orbit_on
from deathsphere.records.machine_presets import PRESETS
from deathsphere.requests.arena import arena

FT = 0.3048
G = 9.80665


def test_the_arena_is_built_from_the_keywords_as_typed():
    drum = arena("cylinder", diameter="32ft", wall_height="12ft")
    assert isinstance(drum, Cylinder) and drum.radius == pytest.approx(16 * FT, rel=1e-15)
    assert drum.wall_height == pytest.approx(12 * FT, rel=1e-15)
    assert arena("cone", r=4.0, wall_angle="80") == Cone(4.0, math.radians(80))
    assert arena("sphere", diameter="16ft").radius == pytest.approx(8 * FT, rel=1e-15)


@pytest.mark.parametrize("kw, param", [
    (dict(surface="drum", r=4.0), "surface"),
    (dict(surface="cone", r=4.0), "wall_angle"),
    (dict(surface="cone", r=4.0, wall_angle=180), "wall_angle"),
    (dict(surface="cylinder", r=4.0, wall_angle=80), "wall_angle"),
    (dict(surface="sphere", r=4.0, wall_height=3), "wall_height"),
    (dict(surface="cylinder", r=4.0, diameter=8.0), "diameter"),
])
def test_what_an_arena_does_not_take_is_refused_naming_it(kw, param):
    with pytest.raises(ParameterError) as err:
        arena(**kw)
    assert err.value.param == param and "\n" not in str(err.value)


@pytest.mark.parametrize("held", ["com_speed", "speed"])
def test_a_lap_on_the_drum_is_the_physics_at_the_lane_asked_for(held):
    """By the centre of mass's speed or the contact's (a speedometer's,
    the contact running round the drum's wall at its radius)."""
    t = deathsphere.ride(machine="stunt125", surface="cylinder", diameter="32ft", wall_height="12ft",
                         height="5ft", **{held: "40km/h"})
    assert tuple(t.columns) == RIDE_COLUMNS
    row = t[0]
    assert row["status"] == "ok" and row["surface"] == "cylinder" and row["theta_deg"] is None
    assert row["wall_angle_deg"] == 90.0 and row["rho_contact_m"] == pytest.approx(16 * FT, rel=1e-15)
    orb = ride_orbit_on(5 * FT, math.radians(row["alpha_deg"]), Cylinder(16 * FT, 12 * FT), G,
                        machine_arrays(PRESETS["stunt125"]))
    assert float(orb["v_cm" if held == "com_speed" else "v_contact"]) * 3.6 == pytest.approx(40.0, rel=1e-9)
    assert float(orb["v_contact"]) == pytest.approx(float(orb["omega"]) * 16 * FT, rel=1e-12)
    assert row["mu_required"] == pytest.approx(float(orb["mu_required"]), rel=1e-12)
    assert row["friction_per_mass_m_s2"] == pytest.approx(-G, rel=1e-12)
    # the drum's own linearisation (docs/machine.md, "On any ground"), the physics' at the row's tilt
    st = machine_stability_on(np.array([5 * FT]), np.radians([row["alpha_deg"]]), Cylinder(16 * FT, 12 * FT), G,
                              machine_arrays(PRESETS["stunt125"]))
    assert row["stability_method"] == "exact-linearisation-steer-locked"
    assert row["growth_rate_1_s"] == pytest.approx(float(st["growth_rate"][0]), rel=1e-12)
    assert row["freq_fast_rad_s"] == pytest.approx(float(st["freq_fast"][0]), rel=1e-12)
    assert row["stability"] in ("stable", "unstable") and row["stability_kind"] in ("neutral", "growing")


def test_the_globes_rows_carry_their_contact_radius_and_wall_angle():
    t = deathsphere.ride(np.array([60.0, 90.0, 120.0]), 15, machine="stunt125", diameter="16ft",
                         stability=False)
    np.testing.assert_array_equal(t["surface"], ["sphere"] * 3)
    np.testing.assert_allclose(t["rho_contact_m"], 8 * FT * np.sin(np.radians([60, 90, 120])), rtol=1e-15)
    np.testing.assert_allclose(t["wall_angle_deg"], [120.0, 90.0, 60.0], rtol=1e-15)


def test_the_riders_table_on_a_cone_counts_the_speeds_per_lane():
    t = deathsphere.ride(machine="stunt125", surface="cone", wall_angle=80, diameter="32ft",
                         height=np.array([3.0, 5.0])[:, None] * FT, speed=np.array([5.0, 40, 60]) / 3.6, mu=1,
                         summary=True)
    assert len(t) == 2
    assert list(t["speeds_tried"]) == [3, 3]
    assert all(t["speeds_ok"] >= 2)


@pytest.mark.parametrize("kw, param", [
    (dict(theta=90, speed=10), "theta"),
    (dict(height="13ft", speed=10), "height"),
    (dict(height=1.0, alpha=10, speed=10), "speed"),     # the second hold typed, as the lane decoder names it
    (dict(height=1.0, vertical=True, v_top=10), "vertical"),
])
def test_a_lane_a_wall_does_not_have_is_refused_in_one_line(kw, param):
    with pytest.raises(ParameterError) as err:
        deathsphere.ride(machine="stunt125", surface="cylinder", diameter="32ft", wall_height="12ft", **kw)
    assert err.value.param == param and "\n" not in str(err.value)


def test_a_two_wheeler_rides_the_wall_not_the_globe():
    """Its turns are the drum's (docs/two-wheeler.md sec. 12), not a globe's
    of that diameter; on flat ground a lane by height is refused naming
    height (a circle there is its turn radius)."""
    rows = deathsphere.ride(machine="benchmark-bicycle", steer="free", surface="cylinder", diameter="32ft",
                            height=1, speed=8)
    globe = deathsphere.ride(machine="benchmark-bicycle", steer="free", diameter="32ft", height=1, speed=8)
    assert set(rows["surface"]) == {"cylinder"} and np.all(rows["wall_angle_deg"] == 90.0)
    assert np.isnan(rows["theta_deg"]).all() and not np.isnan(globe["theta_deg"]).any()
    assert not np.allclose(rows["lean_wall_deg"][0], globe["lean_wall_deg"][0])
    with pytest.raises(ParameterError) as err:
        deathsphere.ride(machine="benchmark-bicycle", steer="free", surface="plane", height=1, speed=8)
    assert err.value.param == "height" and "turn_radius" in str(err.value) and "\n" not in str(err.value)


def test_the_riders_table_counts_a_head_reaching_a_wall_as_head_hits():
    # a cone leaning in at 140 degrees: upright tilts put the head into the overhang
    kw = dict(machine="stunt125", surface="cone", wall_angle=140, r=2.0, height=0.8,
              alpha=np.linspace(-80, 170, 51))
    rows = deathsphere.ride(**kw, stability=False)
    hits = int(np.sum(rows["reason"] == deathsphere.api.rides.REASON_TEXT[deathsphere.api.rides.Reason.HEAD_HITS_WALL]))
    assert hits > 0
    table = deathsphere.ride(**kw, summary=True)
    assert int(table["head_hits"][0]) == hits


def test_a_lap_on_flat_ground_by_its_turn_radius():
    """On flat ground the lane is the contact's distance from the turn's
    centre: the contact's speed fixes Omega = v / R, the row is the physics
    at that lane, and its height is 0 (the contact's, on the ground)."""
    t = deathsphere.ride(machine="stunt125", surface="plane", turn_radius=[20.0, 50.0], speed="30km/h")
    assert tuple(t.columns) == RIDE_COLUMNS and len(t) == 2
    for row, turn in zip(t, (20.0, 50.0)):
        assert row["status"] == "ok" and row["surface"] == "plane" and row["r_m"] is None
        assert row["height_m"] == 0.0 and row["rho_contact_m"] == turn and row["wall_angle_deg"] == 0.0
        assert row["omega_rad_s"] == pytest.approx(30 / 3.6 / turn, rel=1e-12)
        orb = ride_orbit_on(turn, math.radians(row["alpha_deg"]), Plane(), G, machine_arrays(PRESETS["stunt125"]))
        assert row["lean_deg"] == pytest.approx(90.0 - row["alpha_deg"])
        assert row["mu_required"] == pytest.approx(float(orb["mu_required"]), rel=1e-12)
    # the tighter turn leans further (the textbook's tan(phi) = v^2 / (g R), corrected)
    assert t[0]["lean_deg"] > t[1]["lean_deg"] > math.degrees(math.atan((30 / 3.6) ** 2 / (G * 50.0)))


def test_a_lap_on_a_profile_by_its_height(tmp_path):
    rho = np.linspace(0.0, 12.0, 61)
    path = tmp_path / "bowl.csv"
    path.write_text("rho_m,z_m\n" + "".join(f"{float(a)!r},{float(0.08 * a * a)!r}\n" for a in rho))
    t = deathsphere.ride(machine="stunt125", surface="profile", profile=str(path), height=[1.0, 4.0],
                         com_speed=10.0)
    assert [row["status"] for row in t] == ["ok", "ok"]
    bowl = Profile(rho, 0.08 * rho ** 2)
    for row, h in zip(t, (1.0, 4.0)):
        assert row["height_m"] == h and row["rho_contact_m"] == pytest.approx(math.sqrt(h / 0.08), rel=1e-5)
        # the wall angle of z = c rho^2: tan(beta) = 2 c rho
        assert math.tan(math.radians(row["wall_angle_deg"])) == pytest.approx(2 * 0.08 * math.sqrt(h / 0.08),
                                                                               rel=1e-4)
        orb = ride_orbit_on(h, math.radians(row["alpha_deg"]), bowl, G, machine_arrays(PRESETS["stunt125"]))
        assert float(orb["v_cm"]) == pytest.approx(10.0, rel=1e-9)
    # the stability on the profile's parallel surface (the meridian moved along its normal), row by row
    alpha = np.radians(np.asarray(t["alpha_deg"], dtype=float))
    st = machine_stability_on(np.array([1.0, 4.0]), alpha, bowl, G, machine_arrays(PRESETS["stunt125"]))
    assert np.isfinite(st["growth_rate"]).all()
    np.testing.assert_allclose(np.asarray(t["growth_rate_1_s"], dtype=float), st["growth_rate"], rtol=1e-12)
    assert set(t["stability_method"]) == {"exact-linearisation-steer-locked"}


def test_flat_ground_and_the_cone_are_analysed_row_by_row():
    t = deathsphere.ride(machine="stunt125", surface="plane", turn_radius=[10.0, 20.0], com_speed="40km/h")
    u = deathsphere.ride(machine="stunt125", surface="cone", wall_angle=80, diameter="32ft", height=[1.0, 1.5],
                         com_speed="50km/h")
    for table, ground, lanes in ((t, Plane(), [10.0, 20.0]), (u, Cone(16 * FT, math.radians(80)), [1.0, 1.5])):
        alpha = np.radians(np.asarray(table["alpha_deg"], dtype=float))
        st = machine_stability_on(np.array(lanes), alpha, ground, G, machine_arrays(PRESETS["stunt125"]))
        np.testing.assert_allclose(np.asarray(table["growth_rate_1_s"], dtype=float), st["growth_rate"], rtol=1e-12)
        assert set(table["stability_method"]) == {"exact-linearisation-steer-locked"}


@pytest.mark.parametrize("kw, param", [
    (dict(surface="plane", height=3.0), "height"),
    (dict(surface="plane"), "turn_radius"),
    (dict(surface="plane", theta=60, turn_radius=3.0), "theta"),
    (dict(surface="cylinder", r=5.0, turn_radius=3.0), "turn_radius"),
    (dict(turn_radius=3.0), "turn_radius"),
])
def test_a_lane_its_ground_does_not_have_is_refused_naming_it(kw, param):
    with pytest.raises(ParameterError) as err:
        deathsphere.ride(machine="stunt125", speed=8.0, **kw)
    assert err.value.param == param and "\n" not in str(err.value)


def test_ride_on_flat_ground_through_the_command_line(run):
    res = run("ride", "--surface", "plane", "--turn-radius", "20", "--speed", "30km/h", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    assert "plane" in res.stdout and ",20.0,0.0" in res.stdout
    bad = run("ride", "--surface", "plane", "--height", "3", "--speed", "8", "--format", "csv")
    assert bad.exit_code == 2 and bad.stderr.count("\n") == 1 and "--height" in bad.stderr
    bad = run("ride", "--turn-radius", "3", "--speed", "8", "--format", "csv")
    assert bad.exit_code == 2 and bad.stderr.count("\n") == 1 and "--turn-radius" in bad.stderr


def test_the_riders_table_on_flat_ground_names_each_lane_by_its_turn_radius():
    table = deathsphere.ride(machine="stunt125", surface="plane", turn_radius=[[10.0], [30.0]], speed=[6.0, 12.0],
                             summary=True)
    assert list(table["rho_contact_m"]) == [10.0, 30.0] and list(table["height_m"]) == [0.0, 0.0]
    assert list(table["speeds_ok"]) == [2, 2]
    # on the globe the contact's distance from the axis, r sin(theta)
    globe = deathsphere.ride(theta=[[60.0], [90.0]], speed=[8.0, 10.0], diameter="16ft", summary=True)
    np.testing.assert_allclose(globe["rho_contact_m"], 8 * FT * np.sin(np.radians([60.0, 90.0])), rtol=1e-15)


def test_the_terminal_views_name_a_flat_lane_by_its_turn_radius(run):
    many = run("ride", "--surface", "plane", "--turn-radius", "10:30:10", "--speed", "30km/h", "--format", "table")
    assert many.exit_code == 0, many.stderr
    assert "turn" in many.stdout and "radius" in many.stdout
    globe = run("ride", "--diameter", "16ft", "--height", "0.8:2.4:0.8m", "--speed", "20km/h", "--format", "table")
    assert globe.exit_code == 0 and "radius" not in globe.stdout
