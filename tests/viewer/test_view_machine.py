"""The 3-D view of a machine (docs/simulation.md "3-D view", docs/machine.md
sec. 5): the page embeds the machine's centre of mass and head with its
wheel, where eq. M2 puts them, and the GIF loop draws them."""

import numpy as np
import pytest
from view_page import dump_dom, page_data, point_set, readout

import deathsphere
from deathsphere.api.machines import PRESETS
from deathsphere.viewer import write_view
from deathsphere.viewer.animation import write_animation
from deathsphere.viewer.html import decode_array
from deathsphere.viewer.orbit_scene import build_scene

STUNT = PRESETS["stunt125"]


def _run(**kw):
    sim = deathsphere.api.prepare_simulation(*deathsphere.api.simulation_request(dict(theta=60, alpha=14.05, machine="stunt125", diameter="16ft", perturb=0.01, periods=0.5,
                                             points_per_period=20, record_states=True, **kw)))
    series, summary = sim.run()
    return sim, series, summary


@pytest.fixture(scope="module")
def machine_page(tmp_path_factory):
    sim, series, summary = _run()
    out = tmp_path_factory.mktemp("machine") / "machine.html"
    write_view(out, series, summary, sim.view_frames())
    return out, series, summary


def test_the_page_holds_the_machines_frame_and_rider(machine_page):
    out, series, summary = machine_page
    (body,) = page_data(out.read_text(encoding="utf-8"))["tracks"]
    assert body["meta"]["body"] == "machine" and body["status"] == "completed"
    t = decode_array(body["t"], dtype="<f8")
    centre, e3, contact = (decode_array(point_set(body, k), rows=3) for k in ("centre", "e3", "contact"))
    com, head = decode_array(point_set(body, "com"), rows=3), decode_array(point_set(body, "head"), rows=3)
    assert com.shape == head.shape == centre.shape == (3, t.size) and t.size >= len(series)
    # eq. M2: G = C - (h - a) e3, H = Q - (head - t) e3 with Q = C + (a - t) e3 (float32 storage)
    np.testing.assert_allclose(com, centre - (STUNT.com_height - STUNT.wheel_radius) * e3, atol=1e-5)
    np.testing.assert_allclose(head, centre - (STUNT.head_height - STUNT.wheel_radius) * e3, atol=1e-5)
    # the contact, the hub and the head on one line (the up-axis), in that order
    up = head - contact
    along = np.sum((centre - contact) * up, axis=0) / np.sum(up * up, axis=0)
    assert np.all((along > 0) & (along < 1))
    r = float(summary["r_m"][0])
    np.testing.assert_allclose(np.linalg.norm(contact, axis=0), r, rtol=1e-6)
    rows = np.isin(t, series["t_s"])
    np.testing.assert_allclose(r - np.linalg.norm(head[:, rows], axis=0), series["head_clearance_m"], atol=1e-5)
    # the readout's speed is the rider's: the centre of mass's, as ride's v_cm and the series' v_cm_m_s
    speed = decode_array(readout(body, "speed"))
    np.testing.assert_allclose(speed[rows], series["v_cm_m_s"], rtol=1e-5)
    # and against ride's closed form (eq. M8), independent of the simulation's
    # rates: the 0.01 deg kick moves it by 5e-4 relative
    steady = float(deathsphere.ride(60, 14.05, machine="stunt125", diameter="16ft", stability=False)["v_cm_m_s"])
    np.testing.assert_allclose(speed[rows], steady, rtol=2e-3)


def test_a_wheels_page_has_no_machine():
    sim = deathsphere.api.prepare_simulation(*deathsphere.api.simulation_request(dict(theta=60, alpha=10, periods=0.2, points_per_period=10, record_states=True)))
    series, summary = sim.run()
    (scene,) = build_scene(series, summary, sim.view_frames()).tracks
    assert "com" not in scene.points and "head" not in scene.points


def test_the_page_draws_the_machine_in_a_browser(machine_page, browser):
    out, _, _ = machine_page
    dom = dump_dom(browser, out)
    assert 'data-errors="0"' in dom and 'data-ready="1"' in dom
    assert "machine inside the sphere" in dom


def test_the_gif_draws_the_machine(tmp_path):
    Image = pytest.importorskip("PIL.Image")
    sim, series, summary = _run()
    scene = build_scene(series, summary, sim.view_frames())
    out = tmp_path / "machine.gif"
    n = write_animation(out, scene, max_seconds=0.4)
    with Image.open(out) as im:
        assert im.n_frames == n >= 2
        # the rider's colours are in the picture, not only in the palette
        im.seek(n - 1)
        rgb = np.asarray(im.convert("RGB")).reshape(-1, 3).astype(int)
    purple = np.all(np.abs(rgb - [0x8E, 0x44, 0xAD]) < 30, axis=1)
    pink = np.all(np.abs(rgb - [0xE9, 0x1E, 0x9C]) < 30, axis=1)
    assert purple.sum() > 20 and pink.sum() > 5
