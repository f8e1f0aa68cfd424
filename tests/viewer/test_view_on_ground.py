"""The 3-D view of a run off the globe (docs/simulation.md, "On any ground"):
the page draws the ground from its meridian (a cone with a top: the floor,
the wall and its top edge) and the body's track on that wall, and loads in
a real browser without errors."""

import numpy as np
from view_page import body_attributes, dump_dom, page_data, point_set

from deathsphere.api.simulation import prepare_simulation, simulation_request
from deathsphere.viewer import write_view
from deathsphere.viewer.html import decode_array

#: the well of death: a 6 m floor, the wall at 80 degrees up to 4 m
CONE = dict(surface="cone", diameter=6, wall_angle=80, wall_height=4)


def test_the_page_draws_the_cone_and_the_track_on_its_wall(tmp_path, browser):
    sim = prepare_simulation(*simulation_request(dict(height=2, alpha=10, perturb=2, periods=0.5,
                                                      points_per_period=20, record_states=True, **CONE)))
    series, summary = sim.run()
    out = tmp_path / "cone.html"
    write_view(out, series, summary, sim.view_frames(), ground=sim.ground)
    data = page_data(out.read_text(encoding="utf-8"))
    ground = data["ground"]
    rho, z = np.asarray(ground["rho"]), np.asarray(ground["z"])
    # the floor's centre, then the wall from its foot (r = 3 m at z = 0) up to its top at 4 m,
    # rho = 3 + z cot(80 deg) on it
    assert ground["kind"] == "revolution" and rho[0] == 0.0 and z[0] == 0.0
    np.testing.assert_allclose(rho[1:], 3.0 + z[1:] / np.tan(np.radians(80.0)), rtol=1e-12)
    assert z[1] == 0.0 and z[-1] == 4.0
    (track,) = data["tracks"]
    contact = decode_array(point_set(track, "contact"), rows=3)
    # every drawn contact on the cone's wall (float32 storage): clearance from the generator
    rho_p = np.hypot(contact[0], contact[1])
    clearance = (rho_p - 3.0) * -np.sin(np.radians(80.0)) + contact[2] * np.cos(np.radians(80.0))
    assert np.max(np.abs(clearance)) < 1e-5
    assert 1.5 < contact[2].min() and contact[2].max() < 2.5
    assert "on the cone" in data["title"]
    attrs = body_attributes(dump_dom(browser, out))
    assert attrs["errors"] == "0" and attrs["ready"] == "1"
    assert int(attrs["frame"]) > 0


def test_the_page_draws_a_cone_roof_and_the_wheel_on_its_outside(tmp_path, browser):
    """A wheel round a cone's roof (the wall leaning in at 120 degrees, a 10 m
    foot, up to 3 m): the ground is the same meridian, the contacts on it,
    the wheel's centre on the far side of the wall from the inside (its
    clearance negative: outside) and the title says so."""
    roof = dict(surface="cone", diameter=10, wall_angle=120, wall_height=3)
    sim = prepare_simulation(*simulation_request(dict(height=2, alpha=235, a=2.0, side="outside", perturb=0.5,
                                                      periods=0.5, points_per_period=20, record_states=True,
                                                      **roof)))
    series, summary = sim.run()
    assert summary["status"][0] == "completed"
    out = tmp_path / "roof.html"
    write_view(out, series, summary, sim.view_frames(), ground=sim.ground)
    data = page_data(out.read_text(encoding="utf-8"))
    ground = data["ground"]
    rho, z = np.asarray(ground["rho"]), np.asarray(ground["z"])
    assert ground["kind"] == "revolution" and rho[0] == 0.0 and z[-1] == 3.0
    np.testing.assert_allclose(rho[1:], 5.0 + z[1:] / np.tan(np.radians(120.0)), rtol=1e-12)
    (track,) = data["tracks"]
    n_out = -np.sin(np.radians(120.0)), np.cos(np.radians(120.0))        # the inward normal (rho, z)

    def clearance(points):
        return (np.hypot(points[0], points[1]) - 5.0) * n_out[0] + points[2] * n_out[1]

    contact, centre = (decode_array(point_set(track, key), rows=3) for key in ("contact", "centre"))
    assert np.max(np.abs(clearance(contact))) < 1e-5
    # the rim's centre a |sin(alpha + beta)| = 2 sin(5 deg) = 0.174 m out from the wall
    np.testing.assert_allclose(clearance(centre), -2.0 * np.sin(np.radians(5.0)), atol=0.02)
    assert "wheel outside the cone" in data["title"]
    attrs = body_attributes(dump_dom(browser, out))
    assert attrs["errors"] == "0" and attrs["ready"] == "1"
