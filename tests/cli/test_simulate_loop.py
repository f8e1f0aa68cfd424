"""simulate's GIF/MP4 loop: --loop-seconds, --playback and the frames'
progress bar, read back from the files written."""

import io
import json
import math
import shutil
import subprocess

import pytest

import deathsphere

pytest.importorskip("matplotlib")

FPS = 25
HOLD_MS = 1500
RUN = ("simulate", "--theta", "60", "--alpha", "10", "--periods", "1")


def _run_end_s():
    series, _ = deathsphere.simulate(60, 10, periods=1)
    return float(series["t_s"][-1])


def _frames(loop_seconds, playback):
    """Frames of the loop: one every playback / FPS simulated seconds, back
    from the run's end, over at most loop_seconds of loop."""
    span = min(_run_end_s(), loop_seconds * playback)
    return math.floor(span / (playback / FPS) + 1e-9) + 1


def test_gif_plays_at_the_playback_factor_with_a_bar_on_a_terminal(run, tmp_path, monkeypatch):
    from PIL import Image
    from rich.console import Console

    import deathsphere.cli.base as base

    screen = io.StringIO()
    monkeypatch.setattr(base, "_isatty", lambda stream: True)
    monkeypatch.setattr(base, "PROGRESS_DELAY_S", 0.0)
    monkeypatch.setattr(base, "stderr_console", lambda: Console(file=screen, force_terminal=True, width=80))
    target = tmp_path / "run.gif"
    # ten times real time: the whole run fits in the loop, so the factor sets the count
    res = run(*RUN, "--output", str(target), "--playback", "10")
    assert res.exit_code == 0
    n = _frames(10.0, 10.0)
    with Image.open(target) as im:
        durations = []
        for k in range(im.n_frames):
            im.seek(k)
            durations.append(im.info["duration"])
    assert len(durations) == n and durations == [1000 // FPS] * (n - 1) + [HOLD_MS]
    assert "frames" in screen.getvalue() and f"{n}/{n}" in screen.getvalue()


def test_mp4_lasts_the_loop_seconds_asked(run, tmp_path):
    from deathsphere.viewer import has_ffmpeg

    if not has_ffmpeg() or shutil.which("ffprobe") is None:
        pytest.skip("ffmpeg and ffprobe are not installed")
    target = tmp_path / "run.mp4"
    assert run(*RUN, "--output", str(target), "--loop-seconds", "0.1", "--playback", "1").exit_code == 0
    probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                            "stream=nb_read_frames,r_frame_rate", "-of", "json", str(target)],
                           capture_output=True, text=True, check=True)
    stream = json.loads(probe.stdout)["streams"][0]
    n = _frames(0.1, 1.0)
    # each drawn frame repeated for its duration at the fixed rate, the last held
    assert stream["r_frame_rate"] == f"{FPS}/1"
    assert int(stream["nb_read_frames"]) == ((n - 1) * 1000 // FPS + HOLD_MS) * FPS // 1000


@pytest.mark.parametrize("args, word", [(("--loop-seconds", "3"), "loop_seconds"),
                                        (("--playback", "2", "--output", "x.html"), "playback"),
                                        (("--loop-seconds", "0", "--output", "x.gif"), "loop_seconds")])
def test_loop_options_are_checked_before_any_work(run, tmp_path, args, word):
    res = run(*RUN, *[str(tmp_path / a) if a.startswith("x.") else a for a in args])
    assert res.exit_code == 2 and word in res.stderr and list(tmp_path.iterdir()) == []


def test_animation_options_of_the_api():
    assert deathsphere.api.animation_options("a.mp4", loop_seconds="4", playback=0.5) == {
        "loop_seconds": 4.0, "playback": 0.5}
    assert deathsphere.api.animation_options("a.png") == {"loop_seconds": None, "playback": None}
    with pytest.raises(deathsphere.ParameterError, match="gif or .mp4"):
        deathsphere.api.animation_options("a.png", playback=1)
