"""Every 3-D page is the one template drawing a scene: the package ships one
page template with one data mark, and each kind of run (an orbit, the
machine, a show's act, a two-wheeler in the globe and on flat ground)
renders through it in a real browser with no script error and every body
drawn inside the canvas."""

import json
import re
from importlib import resources

import pytest
from view_page import body_attributes, dump_dom, page_data
from viewer_cases import run_case

import deathsphere
from deathsphere.api.shows import EXAMPLE_PLAN, show
from deathsphere.api.two_wheelers import simulate_two_wheeler
from deathsphere.simulation.frames import body_frames
from deathsphere.viewer import write_scene
from deathsphere.viewer.html import DATA_MARK, TEMPLATE
from deathsphere.viewer.orbit_scene import build_scene
from deathsphere.viewer.scene import revolution_ground
from deathsphere.viewer.show_scene import act_scene
from deathsphere.viewer.two_wheeler_scene import two_wheeler_scene

MARK = re.compile(r"/\*__DEATHSPHERE_[A-Z_]+__\*/")


def test_the_package_ships_one_template_with_one_data_mark():
    files = resources.files("deathsphere.viewer")
    pages = sorted(f.name for f in files.iterdir() if f.name.endswith((".html", ".htm")))
    assert pages == [TEMPLATE]
    assert MARK.findall(files.joinpath(TEMPLATE).read_text(encoding="utf-8")) == [DATA_MARK.removesuffix("null")]
    # no module keeps a mark of its own
    for f in files.iterdir():
        if f.name.endswith(".py") and f.name != "html.py":
            assert not MARK.search(f.read_text(encoding="utf-8")), f.name


def _orbit():
    series, summary, states, _ = run_case("wheel_kicked", periods=0.3)
    return build_scene(series, summary, body_frames(summary, states))


def _machine():
    sim = deathsphere.api.prepare_simulation(*deathsphere.api.simulation_request(dict(theta=60, alpha=14.05, machine="stunt125", diameter="16ft", periods=0.2,
                                             points_per_period=20, record_states=True)))
    series, summary = sim.run()
    return build_scene(series, summary, sim.view_frames())


def _act(tmp_path):
    path = tmp_path / "act.toml"
    path.write_text(EXAMPLE_PLAN, encoding="utf-8")
    result = show(str(path))
    return act_scene(result, result.fall("Eve", 0.6, 0.6))       # a fall with its path


def _two_wheeler():
    return two_wheeler_scene(*simulate_two_wheeler("benchmark-bicycle", view=True, height=1.0, speed=5.0,
                                                   diameter="16ft", periods=0.1, points_per_period=20, rtol=1e-6,
                                                   steer_gains="10,10", perturb=0.5))


def _flat():
    return two_wheeler_scene(*simulate_two_wheeler("benchmark-bicycle", view=True, flat=True, speed=5.0,
                                                   turn_radius=8.0, periods=0.03, points_per_period=200,
                                                   rtol=1e-6, perturb=1.0))


def _drum():
    """An orbit's scene on a drum: one more kind of ground, drawn from its
    meridian by the same page."""
    scene = _orbit()
    scene.ground = revolution_ground([3.0] * 13, [-2.0 + k / 3 for k in range(13)])
    return scene


@pytest.mark.parametrize("kind", ["orbit", "machine", "act", "two_wheeler", "flat", "drum"])
def test_every_kind_of_run_draws_through_the_one_template(browser, tmp_path, kind):
    scene = {"orbit": _orbit, "machine": _machine, "act": lambda: _act(tmp_path), "two_wheeler": _two_wheeler,
             "flat": _flat, "drum": _drum}[kind]()
    out = tmp_path / f"{kind}.html"
    write_scene(out, scene)
    page = out.read_text(encoding="utf-8")
    assert page_data(page)["ground"]["kind"] == scene.ground["kind"]
    attrs = body_attributes(dump_dom(browser, out, budget_ms=1500))
    assert attrs["ready"] == "1" and attrs["errors"] == "0"
    assert int(attrs["tracks"]) == len(scene.tracks) and int(attrs["ink"]) > 500
    drawn = json.loads(attrs["drawn"].replace("&quot;", '"'))
    width, height = (float(x) for x in attrs["canvas"].split(","))
    for track in scene.tracks:
        x0, y0, x1, y1 = drawn[track.name]
        assert 0 <= x0 < x1 <= width and 0 <= y0 < y1 <= height, (track.name, drawn[track.name], width, height)
