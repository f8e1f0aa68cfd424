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
from deathsphere.physics.ground import Cone, Cylinder
from deathsphere.physics.machine_arrays import machine_arrays
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
    assert "not analysed" in row["stability_method"]


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
    of that diameter; a surface it does not ride is refused naming surface."""
    rows = deathsphere.ride(machine="benchmark-bicycle", steer="free", surface="cylinder", diameter="32ft",
                            height=1, speed=8)
    globe = deathsphere.ride(machine="benchmark-bicycle", steer="free", diameter="32ft", height=1, speed=8)
    assert set(rows["surface"]) == {"cylinder"} and np.all(rows["wall_angle_deg"] == 90.0)
    assert np.isnan(rows["theta_deg"]).all() and not np.isnan(globe["theta_deg"]).any()
    assert not np.allclose(rows["lean_wall_deg"][0], globe["lean_wall_deg"][0])
    with pytest.raises(ParameterError) as err:
        deathsphere.ride(machine="benchmark-bicycle", steer="free", surface="plane", height=1, speed=8)
    assert err.value.param == "surface" and "\n" not in str(err.value)


def test_the_riders_table_counts_a_head_reaching_a_wall_as_head_hits():
    # a cone leaning in at 140 degrees: upright tilts put the head into the overhang
    kw = dict(machine="stunt125", surface="cone", wall_angle=140, r=2.0, height=0.8,
              alpha=np.linspace(-80, 170, 51))
    rows = deathsphere.ride(**kw, stability=False)
    hits = int(np.sum(rows["reason"] == deathsphere.api.rides.REASON_TEXT[deathsphere.api.rides.Reason.HEAD_HITS_WALL]))
    assert hits > 0
    table = deathsphere.ride(**kw, summary=True)
    assert int(table["head_hits"][0]) == hits
