"""The act's 3-D view (``deathsphere show --output act.html|.gif``): the
page carries the show's own points, frames close enough to draw straight
lines between, the pair of least clearance, the fall's path from where
contact is lost to the landing point; and it draws in a real browser."""

import numpy as np
import pytest
from view_page import body_attributes, dump_dom, point_set

from deathsphere.api.shows import EXAMPLE_PLAN, show
from deathsphere.viewer import write_scene
from deathsphere.viewer.html import decode_array, render_html, scene_data
from deathsphere.viewer.show_scene import MAX_MOVE_R, act_scene


@pytest.fixture(scope="module")
def act(tmp_path_factory):
    path = tmp_path_factory.mktemp("act") / "act.toml"
    path.write_text(EXAMPLE_PLAN, encoding="utf-8")
    result = show(str(path))
    return result, result.fall("Ben", 1.2, 0.3)


@pytest.fixture(scope="module")
def scene(act):
    result, falls = act
    return act_scene(result, falls)


def test_the_page_carries_the_shows_points(act, scene):
    result, _ = act
    data = scene_data(scene)
    t = decode_array(data["tracks"][0]["t"], dtype="<f8")
    assert t[0] == 0.0 and t[-1] == pytest.approx(result.duration_s)
    truth = result.positions(t)
    for rider in data["tracks"]:
        for key in ("contact", "head", "com"):
            drawn = decode_array(point_set(rider, key), rows=3)
            assert np.allclose(drawn, truth[rider["name"]][key], atol=1e-5)   # float32 in the page


def test_no_rider_jumps_between_frames(scene):
    for track in scene.tracks:
        for p in track.points.values():
            step = np.sqrt(np.sum(np.diff(p, axis=1) ** 2, axis=0))
            assert step.max() <= MAX_MOVE_R * scene.ground["radius"]


def test_the_least_clearance_pair_is_marked_at_its_moment(act, scene):
    result, _ = act
    clearance = np.asarray(result.pairs["min_clearance_m"], dtype=float)
    i = int(np.nanargmin(clearance))
    assert (scene.pair["a"], scene.pair["b"]) == (result.pairs["rider_a"][i], result.pairs["rider_b"][i])
    assert scene.pair["t"] in scene.tracks[0].t


def test_the_fall_path_runs_from_contact_lost_to_the_landing_point(act, scene):
    _, falls = act
    row = {name: falls[name][0] for name in falls.names}
    fall = scene.tracks[scene.fall["track"]].paths
    if row["outcome"] != "falls":
        assert "fall" not in fall
        return
    path_t, path = fall["fall"]
    land = path[:, -1]
    r = scene.ground["radius"]
    assert np.linalg.norm(land) == pytest.approx(r, rel=1e-9)
    theta = np.degrees(np.arccos(land[2] / r))
    phi = np.degrees(np.arctan2(land[1], land[0])) % 360
    assert theta == pytest.approx(row["theta_land_deg"], abs=1e-6)
    assert phi == pytest.approx(row["phi_land_deg"], abs=1e-6)
    # the path is a parabola under gravity alone: constant horizontal velocity
    dt = np.diff(path_t)
    v = np.diff(path, axis=1) / dt
    assert np.allclose(v[:2], v[:2, :1], atol=1e-9)
    assert path_t[-1] == pytest.approx(row["t_land_s"])


def test_the_page_draws_in_a_browser(browser, act, tmp_path):
    result, falls = act
    out = tmp_path / "act.html"
    write_scene(out, act_scene(result, falls))
    attrs = body_attributes(dump_dom(browser, out, budget_ms=2000))
    assert attrs["ready"] == "1" and attrs["errors"] == "0"
    assert int(attrs["tracks"]) == len(result.riders)
    assert int(attrs["ink"]) > 500                      # the globe and the riders are on the canvas
    clearance = np.asarray(result.pairs["min_clearance_m"], dtype=float)
    i = int(np.nanargmin(clearance))
    assert attrs["pair"] == f"{result.pairs['rider_a'][i]} \u2013 {result.pairs['rider_b'][i]}"
    assert attrs["fall"] == ("path" if falls["outcome"][0] == "falls" else falls["outcome"][0])
    assert float(attrs["time"]) > 0                     # the clock runs


def test_the_page_is_self_contained(scene):
    page = render_html(scene)
    assert "http://" not in page and "https://" not in page and "<script src" not in page


def test_a_gif_is_written(act, tmp_path):
    pytest.importorskip("matplotlib")
    from deathsphere.viewer.animation import write_animation

    _, falls = act
    out = tmp_path / "act.gif"
    frames = write_animation(out, act_scene(act[0], falls), max_seconds=0.12, size_px=(320, 240))
    assert frames >= 2 and out.read_bytes()[:6] == b"GIF89a"


def test_the_clock_runs_on_to_a_late_landing(act):
    result, _ = act
    falls = result.fall("Eve", 0.6, 0.6)
    assert falls["outcome"][0] == "falls" and float(falls["t_land_s"][0]) > result.duration_s
    late = act_scene(result, falls)
    assert late.t_end > float(falls["t_land_s"][0])
    assert late.tracks[late.fall["track"]].paths["fall"][0][-1] == pytest.approx(float(falls["t_land_s"][0]))
