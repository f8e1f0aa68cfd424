"""A two-wheeler's run in 3-D (``deathsphere simulate --machine
benchmark-bicycle --steer free --output run.html|.gif``): the page carries
the simulation's own points (rims on the wheels' circles, touching the
globe at the contacts), the table keeps its columns, a loop is written,
and the page draws the bicycle in a real browser."""

import json

import numpy as np
import pytest
from view_page import body_attributes, dump_dom, page_data, point_set

from deathsphere.api.two_wheelers import SIMULATE_COLUMNS, simulate_two_wheeler
from deathsphere.viewer import write_scene
from deathsphere.viewer.html import decode_array, render_html
from deathsphere.viewer.two_wheeler_scene import POINT_KEYS, RIM_KEYS, decode_rim, two_wheeler_scene

RUN = dict(height=1.0, speed=5.0, diameter="16ft", periods=0.2, points_per_period=20, rtol=1e-6,
           steer_gains="10,10", perturb=0.5)
R = 2.4384
#: float32 in the page: a few parts in 1e7 of the globe's size
F32 = 2e-6


@pytest.fixture(scope="module")
def run():
    return simulate_two_wheeler("benchmark-bicycle", view=True, **RUN)


@pytest.fixture(scope="module")
def data(run):
    return page_data(render_html(two_wheeler_scene(*run)))["tracks"][0]


def test_the_view_adds_no_column_to_the_table(run):
    series, _, frames = run
    assert list(series.columns) == list(SIMULATE_COLUMNS)
    np.testing.assert_array_equal(frames["t"], series["t_s"])


def test_the_page_carries_the_simulations_points_turned_z_up(run, data):
    _, _, frames = run
    n = data["n"]
    assert n == frames["t"].size
    np.testing.assert_array_equal(decode_array(data["t"], dtype="<f8"), frames["t"])
    flip = np.array([1.0, -1.0, -1.0])[:, None]
    for key in POINT_KEYS:
        np.testing.assert_allclose(decode_array(point_set(data, key), rows=3), flip * frames[key], atol=F32)
    for key in RIM_KEYS:
        np.testing.assert_allclose(decode_rim(point_set(data, key), data["points"][key]["k"]),
                                   flip[..., None] * frames[key], atol=F32)
    # the view's z is up: the run starts on the lane 1 m above the globe's floor
    assert decode_array(point_set(data, "P"), rows=3)[2, 0] == pytest.approx(1.0 - R, abs=F32)


def test_the_drawn_rims_are_the_wheels_touching_the_globe(data):
    for rim, centre, contact, radius in (("rear_rim", "rear_wheel", "P", 0.3), ("front_rim", "front_wheel", "Q", 0.35)):
        pts = decode_rim(point_set(data, rim), data["points"][rim]["k"])
        c = decode_array(point_set(data, centre), rows=3)
        np.testing.assert_allclose(np.linalg.norm(pts - c[:, None], axis=0), radius, atol=F32)
        np.testing.assert_allclose(pts[:, 0], decode_array(point_set(data, contact), rows=3), atol=F32)
        np.testing.assert_allclose(np.linalg.norm(pts[:, 0], axis=0), R, atol=F32)


def test_a_loop_is_written(run, tmp_path):
    pytest.importorskip("matplotlib")
    from deathsphere.viewer.animation import write_animation

    out = tmp_path / "run.gif"
    frames = write_animation(out, two_wheeler_scene(*run), max_seconds=0.06, size_px=(240, 180))
    assert frames >= 2 and out.read_bytes()[:6] == b"GIF89a"


def test_the_page_draws_the_bicycle_in_a_browser(browser, run, tmp_path):
    """One headless chromium load (about 2 s): no script error, and every
    piece drawn inside the view with a size of its own."""
    out = tmp_path / "run.html"
    write_scene(out, two_wheeler_scene(*run))
    attrs = body_attributes(dump_dom(browser, out, budget_ms=1500))
    assert attrs["ready"] == "1" and attrs["errors"] == "0"
    assert int(attrs["frames"]) == len(run[0]) and float(attrs["time"]) > 0
    assert int(attrs["ink"]) > 500

    drawn = json.loads(attrs["drawn"].replace("&quot;", '"'))
    assert set(drawn) >= {"rear_rim", "front_rim", "rear_frame", "front_frame", "rider", "head", "contacts"}
    width, height = (float(x) for x in attrs["canvas"].split(","))
    for name, (x0, y0, x1, y1) in drawn.items():
        assert 0 <= x0 < x1 <= width and 0 <= y0 < y1 <= height, name
    for rim in RIM_KEYS:
        x0, y0, x1, y1 = drawn[rim]
        assert max(x1 - x0, y1 - y0) > 20, rim         # a wheel, not a dot


@pytest.fixture(scope="module")
def flat_run():
    return simulate_two_wheeler("benchmark-bicycle", view=True, flat=True, speed=5.0, turn_radius=8.0,
                                periods=0.05, points_per_period=200, rtol=1e-6, perturb=1.0)


def test_a_run_on_flat_ground_stands_on_the_ground(flat_run):
    """On flat ground the page draws the ground, not a globe: both contacts
    at z = 0 in every frame, the rims above it, the head above the wheels,
    and the camera frames the ground the run covers."""
    series, summary, frames = flat_run
    data = page_data(render_html(two_wheeler_scene(series, summary, frames)))
    ground, track = data["ground"], data["tracks"][0]
    assert ground["kind"] == "plane" and np.isfinite(ground["half_width"]) and ground["half_width"] >= 2.0
    for contact in ("P", "Q"):
        assert np.max(np.abs(decode_array(point_set(track, contact), 3)[2])) < F32
    for rim in RIM_KEYS:
        assert np.min(decode_rim(point_set(track, rim), track["points"][rim]["k"])[2]) > -F32
    head = decode_array(point_set(track, "head"), 3)[2]
    assert np.all(head > 1.0) and "flat ground" in data["title"]


def test_the_flat_page_draws_the_ground_and_the_bicycle_in_a_browser(browser, flat_run, tmp_path):
    out = tmp_path / "flat.html"
    write_scene(out, two_wheeler_scene(*flat_run))
    attrs = body_attributes(dump_dom(browser, out, budget_ms=1500))
    assert attrs["ready"] == "1" and attrs["errors"] == "0" and int(attrs["ink"]) > 500
    drawn = json.loads(attrs["drawn"].replace("&quot;", '"'))
    assert set(drawn) >= {"rear_rim", "front_rim", "head", "contacts"}


#: the wall of death's drum, 32 ft across, its top 12 ft up; a twentieth of a lap from the turn 2 m up at 60 km/h
DRUM_R, DRUM_TOP = 4.8768, 3.6576


@pytest.fixture(scope="module")
def wall_run():
    return simulate_two_wheeler("stunt125-steer", view=True, surface="cylinder", diameter="32ft", wall_height="12ft",
                                height=2.0, speed="60km/h", periods=0.05, points_per_period=200, rtol=1e-6,
                                perturb=1.0)


def test_a_run_on_the_drum_draws_the_drum_and_rides_its_wall(wall_run):
    """On a drum the page draws the drum from its meridian (the floor, then
    the wall at the drum's radius up to its top), not a globe: both
    contacts on the wall (at the drum's radius from its axis) in every
    frame, the rear one near its lane's height, the rims inside the wall
    and above the floor."""
    series, summary, frames = wall_run
    data = page_data(render_html(two_wheeler_scene(series, summary, frames)))
    ground, track = data["ground"], data["tracks"][0]
    rho, z = np.array(ground["rho"]), np.array(ground["z"])
    assert ground["kind"] == "revolution" and rho[0] == 0 and z[0] == 0
    np.testing.assert_allclose(rho[1:], DRUM_R, atol=1e-12)
    assert z[-1] == pytest.approx(DRUM_TOP, abs=1e-12)
    for contact in ("P", "Q"):
        xyz = decode_array(point_set(track, contact), 3)
        np.testing.assert_allclose(np.hypot(xyz[0], xyz[1]), DRUM_R, atol=F32 * DRUM_R)
    assert decode_array(point_set(track, "P"), 3)[2, 0] == pytest.approx(2.0, abs=F32 * DRUM_R)
    for rim in RIM_KEYS:
        pts = decode_rim(point_set(track, rim), track["points"][rim]["k"])
        assert np.max(np.hypot(pts[0], pts[1])) < DRUM_R * (1 + F32) and np.min(pts[2]) > 0.5
    assert "cylinder" in data["title"] and "\u03b8" not in "".join(r.get("label", "") for r in track["panel"])


def test_the_drums_page_draws_the_wall_and_the_bicycle_in_a_browser(browser, wall_run, tmp_path):
    out = tmp_path / "wall.html"
    write_scene(out, two_wheeler_scene(*wall_run))
    attrs = body_attributes(dump_dom(browser, out, budget_ms=1500))
    assert attrs["ready"] == "1" and attrs["errors"] == "0" and int(attrs["ink"]) > 500
    drawn = json.loads(attrs["drawn"].replace("&quot;", '"'))
    width, height = (float(x) for x in attrs["canvas"].split(","))
    for rim in RIM_KEYS:
        x0, y0, x1, y1 = drawn[rim]
        assert 0 <= x0 < x1 <= width and 0 <= y0 < y1 <= height, rim
        assert max(x1 - x0, y1 - y0) > 5, rim
