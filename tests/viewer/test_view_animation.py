"""The GIF / MP4 loop of the 3-D view (matplotlib's animation module)."""

import numpy as np
import pytest
from viewer_cases import run_case

from deathsphere.simulation.frames import body_frames
from deathsphere.viewer import write_view
from deathsphere.viewer.animation import SIZE_PX, loop_plan, number
from deathsphere.viewer.orbit_scene import build_scene

pytest.importorskip("matplotlib")


def test_gif_has_the_frames_and_size(tmp_path):
    Image = pytest.importorskip("PIL.Image")
    # 0.4 s of the run: 13 frames at the loop's default size (the event's last frame is
    # test_view_truth.py's test_the_gif_clock_is_true; each frame here costs 70 ms)
    series, summary, states, _ = run_case("unstable", seconds=0.4)
    scene = build_scene(series, summary, body_frames(summary, states))
    times, factor = loop_plan(scene)
    # 25 frames a second of loop, each factor / 25 s of the run, ending on the event
    assert times[-1] == series["t_s"][-1] and np.allclose(np.diff(times), factor / 25)
    assert times.size == int(np.floor(series["t_s"][-1] / (factor / 25) + 1e-9)) + 1
    out = tmp_path / "orbit.gif"
    write_view(out, series, summary, body_frames(summary, states))
    with Image.open(out) as im:
        assert im.format == "GIF" and im.size == SIZE_PX
        assert im.n_frames == times.size


def test_long_runs_loop_over_their_last_seconds():
    series, summary, states, _ = run_case("wheel_inside", periods=8)           # 14.7 s
    times, factor = loop_plan(build_scene(series, summary, body_frames(summary, states)), fps=25, max_seconds=10.0)
    assert factor < 1                                      # 7.9 m/s: 2 % of r takes 7.6 ms
    assert times.size == 251 and times[-1] == series["t_s"][-1]
    assert np.allclose(np.diff(times), factor / 25)


def test_panel_numbers():
    assert number(1.19234) == "1.192" and number(float("nan")) == "-" and number(1.2e14) == "1.200e+14"


def test_mp4_where_ffmpeg_is(tmp_path):
    from deathsphere.viewer import has_ffmpeg

    if not has_ffmpeg():
        pytest.skip("no ffmpeg on PATH: .mp4 is refused (tested in test_view_preflight.py)")
    series, summary, states, _ = run_case("wheel_inside", periods=0.05)      # 14 frames
    out = tmp_path / "orbit.mp4"
    write_view(out, series, summary, body_frames(summary, states))
    head = out.read_bytes()[:64]
    assert b"ftyp" in head
