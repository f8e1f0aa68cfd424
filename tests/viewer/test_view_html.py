"""The HTML 3-D view: embedded data match the run, the page is
self-contained, and a 20-period orbit stays small."""

import re

import numpy as np
import pytest
from view_page import page_data, point_set, readout
from viewer_cases import run_case

from deathsphere.simulation.frames import body_frames, frame_geometry
from deathsphere.viewer import write_view
from deathsphere.viewer.html import decode_array
from deathsphere.viewer.orbit_scene import build_scene
from deathsphere.viewer.scene import frame_indices


def _page(tmp_path, name, **run):
    series, summary, states, params = run_case(name, **run)
    out = tmp_path / f"{name}.html"
    size = write_view(out, series, summary, body_frames(summary, states))
    text = out.read_text(encoding="utf-8")
    assert size == len(text.encode("utf-8"))
    return text, series, summary, states, params


def assert_self_contained(page):
    # nothing is fetched: no external src/href, no stylesheet links, no imports
    assert not re.search(r"""(src|href)\s*=\s*["']?\s*(https?:)?//""", page, flags=re.I)
    assert not re.search(r"<(link|iframe|img|object|embed)\b", page, flags=re.I)
    assert not re.search(r"<script[^>]*\bsrc\s*=", page, flags=re.I)
    assert not re.search(r"\b(import\s*\(|importScripts|fetch\s*\(|XMLHttpRequest)", page)
    assert "http://" not in page and "https://" not in page


@pytest.mark.parametrize("name", ["wheel_kicked", "vertical", "sphere_inside", "wheel_outside", "unstable"])
def test_page_holds_the_run(tmp_path, name):
    page, series, summary, states, params = _page(tmp_path, name, periods=1)
    assert_self_contained(page)
    data = page_data(page)
    assert data["format"] == "deathsphere-scene/1"
    (body,) = data["tracks"]                                   # one body in, one body drawn
    t = decode_array(body["t"], dtype="<f8")
    assert body["n"] == t.size >= len(series)                  # every row, and frames between
    assert np.all(np.isin(series["t_s"], t))
    assert t[0] == 0.0 and t[-1] == series["t_s"][-1] == data["t_end"]
    assert body["status"] == summary["status"][0] and body["meta"]["body"] == summary["body"][0]
    centre = decode_array(point_set(body, "centre"), rows=3)
    rows = np.isin(t, series["t_s"])
    geo = frame_geometry(states["t_s"], states["state"], params)
    assert np.allclose(centre[:, rows], geo["centre"], atol=1e-6 * params.r)   # float32 storage
    theta = decode_array(readout(body, "theta"))
    assert np.allclose(theta[rows], series["theta_deg"], atol=1e-4)
    speed = decode_array(readout(body, "speed"))
    assert np.allclose(speed[rows], series["speed_m_s"], rtol=1e-6)
    assert np.allclose(decode_array(readout(body, "speed_km_h")), 3.6 * speed, rtol=1e-6)
    if summary["status"][0] == "contact_lost":
        assert body["event_time"] == summary["event_time_s"][0] == t[-1]
    else:
        assert body["event_time"] is None


def test_twenty_table1_periods_stay_well_under_10_mb(tmp_path, run):
    out = tmp_path / "orbit.html"
    res = run("simulate", "--theta", "60", "--alpha", "10", "--periods", "20", "--output", str(out),
              "--summary-only", "--format", "csv")
    assert res.exit_code == 0, res.stderr
    size = out.stat().st_size
    print(f"20-period Table 1 orbit: {size} bytes ({size / 1e6:.2f} MB)")
    assert size < 10_000_000
    assert res.stdout == ""                                    # the file is the output
    data = page_data(out.read_text(encoding="utf-8"))
    (body,) = data["tracks"]
    t = decode_array(body["t"], dtype="<f8")
    # 2001 rows, and frames between them so that the centre moves <= 2 % of r
    assert 2001 < body["n"] < 40_000 and data["t_end"] == pytest.approx(20 * body["meta"]["period"], rel=1e-9)
    assert t[0] == 0.0 and data["playback"] <= 1
    assert f"wrote {out}" in res.stderr


def test_very_long_runs_keep_their_last_frames_and_the_whole_trail():
    idx = frame_indices(100_001, 6000)
    assert idx.size <= 6000 + 1 and idx[0] == 0 and idx[-1] == 100_000
    assert np.all(np.diff(idx) > 0)
    series, summary, states, _ = run_case("unstable", points_per_period=2000)
    (scene,) = build_scene(series, summary, body_frames(summary, states), max_frames=50).tracks
    assert scene.n_frames == 50 and scene.t[-1] == series["t_s"][-1] == scene.event_time
    trail_t = scene.paths["trail"][0]
    assert trail_t[0] == 0.0 and trail_t[-1] == scene.t[-1]


def test_a_body_without_orbit_gives_a_page_saying_so(tmp_path, run):
    out = tmp_path / "none.html"
    res = run("simulate", "--body", "sphere", "--theta", "60", "--omega3", "40", "--output", str(out))
    assert res.exit_code == 0
    (body,) = page_data(out.read_text(encoding="utf-8"))["tracks"]
    assert body["n"] == 0 and body["status"] == "no_orbit" and body["reason"]
