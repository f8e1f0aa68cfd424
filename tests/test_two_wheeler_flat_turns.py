"""A two-wheeler's steady turns on flat ground's circles through ``ride``
(``surface="plane", turn_radius=R``; docs/two-wheeler.md sec. 12.8): the
turn radius is the rear contact's distance from the turn's centre, and the
turns are checked against derivations that do not share the table's path:

* the general surface-of-revolution module on flat ground
  (``OnRevolution(Plane())``: the meridian as data, a lane the contact's
  distance from the axis), not flat ground's own closed form;
* a cone of wall angle 0.01 degrees at the same distance from its axis (the
  cone -> flat limit of sec. 12.4): the lean from the vertical, the steer
  and the steer torque, linear in the bank;
* far out (R = 1000 m) the linear steady turn of the benchmark's
  equations, (g K0 + v^2 K2) (lean, steer) = (0, T) with the steer from the
  path's curvature, steer = w kappa / cos(lambda) (Meijaard et al. 2007).
"""

import numpy as np
import pytest

import deathsphere as ds
from deathsphere.params import ParameterError
from deathsphere.physics.ground import Plane
from deathsphere.physics.two_wheeler import linear, steady
from deathsphere.physics.two_wheeler.grounds import OnRevolution
from deathsphere.records.two_wheeler_presets import as_two_wheeler

G = 9.80665
V = 20 / 3.6
MACHINE = "stunt125-steer"


def _turn(**typed):
    return ds.ride(machine=MACHINE, steer="free", speed=V, **typed)


def test_the_turn_radius_is_the_rear_contacts_and_the_table_is_the_plane_s():
    table = _turn(surface="plane", turn_radius=10)
    assert len(table) == 1 and table["status"][0] == "ok"
    # the rear contact runs at v round the circle of radius R: the heading rate is v / R
    assert float(table["omega_rad_s"][0]) == pytest.approx(V / 10, rel=1e-12)
    assert float(table["rho_contact_m"][0]) == 10.0 and float(table["height_m"][0]) == 0.0
    assert table["surface"][0] == "plane" and float(table["wall_angle_deg"][0]) == 0.0
    assert np.isnan(float(table["theta_deg"][0])) and np.isnan(float(table["r_m"][0]))
    # flat ground's spectrum: four eigenvalues with the steer free (no lane coordinate)
    assert "eig_4_re" in table.names and "eig_5_re" not in table.names
    # the lean from the ground's normal is the lean from the vertical; the head is above the ground
    assert float(table["lean_wall_deg"][0]) == pytest.approx(float(table["lean_vertical_deg"][0]), abs=1e-9)
    assert 1.0 < float(table["head_clearance_m"][0]) < 2.0


def test_the_plane_s_turn_is_the_general_surface_module_s():
    t = as_two_wheeler(MACHINE)
    table = _turn(surface="plane", turn_radius=10)
    out = steady.turns_for_speed(10.0, V, t.parameters(), OnRevolution(Plane()), G, t.head)
    assert int(out["count"][0]) == 1
    for column, key, scale in (("lean_deg", "lean", np.degrees), ("steer_deg", "steer", np.degrees),
                               ("steer_torque_n_m", "steer_torque", float), ("head_clearance_m", "head_clearance",
                                                                             float)):
        assert float(table[column][0]) == pytest.approx(float(scale(out[key][0, 0])), rel=1e-9)


def test_a_cone_of_a_hundredth_of_a_degree_is_flat_ground():
    """The cone's lane 10 m from its axis (its foot at 9 m, the lane 1 m out
    along a wall rising at 0.01 deg): the same turn to O(beta) (measured:
    lean 1e-6, steer 6e-6, torque 1.2e-4, relative)."""
    flat = _turn(surface="plane", turn_radius=10)
    cone = _turn(surface="cone", diameter=18, wall_angle=0.01, height=np.tan(np.radians(0.01)))
    assert float(cone["rho_contact_m"][0]) == pytest.approx(10.0, rel=1e-12)
    assert float(flat["lean_vertical_deg"][0]) == pytest.approx(float(cone["lean_vertical_deg"][0]), rel=1e-4)
    assert float(flat["steer_deg"][0]) == pytest.approx(float(cone["steer_deg"][0]), rel=1e-4)
    assert float(flat["steer_torque_n_m"][0]) == pytest.approx(float(cone["steer_torque_n_m"][0]), rel=1e-3)
    assert float(flat["omega_rad_s"][0]) == pytest.approx(float(cone["omega_rad_s"][0]), rel=1e-6)


def test_a_wide_turn_is_the_benchmarks_linear_steady_turn():
    """R = 1000 m: lean and steer of a fifth and a tenth of a degree, where
    the nonlinear turn is the linear one to O(lean^2) and O(w / R)
    (measured: 6e-6, 7e-6 and 4e-5 of the torque)."""
    t = as_two_wheeler(MACHINE)
    p = t.parameters()
    m = linear.benchmark_matrices(p, G)
    radius = 1000.0
    steer = p.w / radius / np.cos(p.lam)
    stiffness = G * m.K0 + V * V * m.K2
    lean = -stiffness[0, 1] * steer / stiffness[0, 0]
    torque = stiffness[1, 0] * lean + stiffness[1, 1] * steer
    table = _turn(surface="plane", turn_radius=radius)
    assert float(table["lean_deg"][0]) == pytest.approx(np.degrees(lean), rel=1e-4)
    assert float(table["steer_deg"][0]) == pytest.approx(np.degrees(steer), rel=1e-4)
    assert float(table["steer_torque_n_m"][0]) == pytest.approx(torque, rel=1e-3)


def test_a_grid_of_radii_and_speeds_keeps_its_shape_and_names_its_axes():
    table = ds.ride(machine=MACHINE, steer="free", surface="plane", turn_radius=[[10.0], [20.0]], speed=[4.0, 6.0],
                    stability=False)
    assert table.shape == (2, 2) and table.axes == ("rho_contact_m", "v_contact_m_s")
    np.testing.assert_allclose(np.asarray(table["omega_rad_s"], dtype=float).reshape(2, 2),
                               [[0.4, 0.6], [0.2, 0.3]], rtol=1e-12)


def test_the_riders_table_on_flat_ground_is_per_turn_radius():
    """--summary: a row per circle, its radius appended (every height 0), its
    counts and spans those of the turns' own table."""
    typed = dict(surface="plane", turn_radius=[[10.0], [30.0]], speed=[4.0, 8.0, 12.0])
    summary = ds.ride(machine=MACHINE, steer="free", summary=True, **typed)
    turns = ds.ride(machine=MACHINE, steer="free", **typed)
    assert summary.names[-1] == "rho_contact_m"
    np.testing.assert_array_equal(np.asarray(summary["rho_contact_m"], dtype=float), [10.0, 30.0])
    assert np.all(np.asarray(summary["height_m"], dtype=float) == 0.0)
    rho = np.asarray(turns["rho_contact_m"], dtype=float)
    ok = np.asarray(turns["status"]) == "ok"
    lean = np.asarray(turns["lean_vertical_deg"], dtype=float)
    for i, radius in enumerate((10.0, 30.0)):
        mine = (rho == radius) & ok
        assert int(summary["speeds_tried"][i]) == 3 and int(summary["speeds_ok"][i]) == mine.sum()
        assert float(summary["lean_vertical_max_deg"][i]) == pytest.approx(lean[mine].max(), rel=1e-12)


@pytest.mark.parametrize("typed, key", [
    (dict(surface="plane"), "turn_radius"),                                  # no lane
    (dict(surface="plane", turn_radius=10, height=1), "height"),             # a wall's lane
    (dict(surface="plane", turn_radius=10, theta=60), "theta"),
    (dict(surface="cylinder", diameter=10, height=1, turn_radius=10), "turn_radius"),
    (dict(turn_radius=10, theta=60), "turn_radius"),                         # the globe's lane is theta
    (dict(surface="plane", turn_radius=-1), "turn_radius"),
])
def test_what_flat_ground_does_not_take_is_refused_by_name(typed, key):
    with pytest.raises(ParameterError) as err:
        _turn(**typed)
    assert err.value.param == key


def test_flat_is_straight_running_and_points_to_the_plane_for_a_turn():
    with pytest.raises(ParameterError, match="surface plane") as err:
        ds.ride(machine=MACHINE, flat=True, speed=5, turn_radius=10)
    assert err.value.param == "turn_radius"
