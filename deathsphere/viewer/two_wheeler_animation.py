"""A two-wheeler's run as a GIF or MP4 loop from a fixed camera, for
slides (docs/two-wheeler.md sec. 10.1): the globe, both rims, the rear and
front frames, the rider's head and the contact points' paths, from the
scene of :func:`deathsphere.viewer.two_wheeler_scene.two_wheeler_scene`.
Drawn with matplotlib (the ``plot`` extra) and written frame by frame
through :func:`deathsphere.viewer.animation.write_frames`, so the memory
stays flat.
"""

from __future__ import annotations

import numpy as np

from deathsphere.viewer.animation import FPS, SIZE_PX, frame_delays_ms, globe_loop_figure, write_frames
from deathsphere.viewer.scene import slow_motion_words

__all__ = ["two_wheeler_loop_times", "write_two_wheeler_animation", "MAX_SECONDS", "CAMERA"]

#: the most seconds of loop (shown time)
MAX_SECONDS = 10.0
#: (elevation, azimuth) [deg] of the fixed camera, as the page's: looking
#: down into the globe, where the wheels' planes show them round
CAMERA = (58.0, -62.0)
_WHEEL = "#d4a017"
_REAR = "#8e44ad"
_FRONT = "#e67e22"
_RIDER = "#555555"
_PATH_REAR = "#1f9bd1"
_PATH_FRONT = "#1e8449"
_EVENT = "#c0392b"


def two_wheeler_loop_times(scene, fps: int = FPS, max_seconds: float = MAX_SECONDS) -> np.ndarray:
    """Times [s] of the loop's frames: 1/fps of shown time apart at the
    scene's playback factor, ending on the run's end, at most
    ``max_seconds`` of loop."""
    t0, t1 = float(scene.t[0]), float(scene.t[-1])
    step = scene.playback / fps
    n = int(np.floor(min(t1 - t0, max_seconds * scene.playback) / step + 1e-9)) + 1
    return t1 - np.arange(n)[::-1] * step


def _at(scene, key, t):
    """A point (3,) or a rim (3, K) at time t, linear between frames."""
    x = scene.points[key]
    i = int(np.clip(np.searchsorted(scene.t, t, side="right") - 1, 0, scene.t.size - 1))
    j = min(i + 1, scene.t.size - 1)
    f = 0.0 if j == i else float(np.clip((t - scene.t[i]) / (scene.t[j] - scene.t[i]), 0.0, 1.0))
    return (1 - f) * x[..., i] + f * x[..., j]


def write_two_wheeler_animation(output, scene, *, fps: int = FPS, max_seconds: float = MAX_SECONDS,
                                size_px=SIZE_PX, dpi: int = 90, progress=None) -> int:
    """Write the loop to ``output`` (.gif or .mp4), each frame as it is
    drawn; returns the number of frames.  ``progress(k, n)`` after each."""
    r = scene.r
    fig, canvas, ax, clock = globe_loop_figure(r, scene.title, CAMERA, size_px, dpi)
    fig.text(0.985, 0.015, "rims (yellow), rear frame (purple), front frame (orange), rider to head; "
             "paths of the rear (blue) and front (green) contacts", ha="right", fontsize=8, color="#555555")

    def line(colour, lw, **kw):
        return ax.plot([], [], [], color=colour, lw=lw, **kw)[0]

    rims = {k: line(_WHEEL, 2.2) for k in ("rear_rim", "front_rim")}
    rear, front, bar, rider = line(_REAR, 2.5), line(_FRONT, 2.5), line(_FRONT, 2.5), line(_RIDER, 2.0)
    head = line("white", 0, marker="o", ms=9, mec=_REAR, mew=2)
    paths = {"P": line(_PATH_REAR, 1.4), "Q": line(_PATH_FRONT, 1.4)}
    times = two_wheeler_loop_times(scene, fps, max_seconds)
    delays = frame_delays_ms(times.size, fps)

    def set_line(art, xyz):
        art.set_data_3d(*xyz)

    def chain(art, at, keys):
        set_line(art, np.column_stack([at[k] for k in keys]))

    def draw(t):
        at = {k: _at(scene, k, t) for k, x in scene.points.items() if x.ndim == 2}
        for k, art in rims.items():
            rim = _at(scene, k, t)
            set_line(art, np.column_stack((rim, rim[:, :1])))
        chain(rear, at, ("rear_wheel", "steer_bottom", "steer_top", "rear_frame", "rear_wheel"))
        chain(front, at, ("steer_top", "steer_bottom", "front_wheel"))
        chain(bar, at, ("bar_left", "bar_right"))
        chain(rider, at, ("rear_frame", "head"))
        chain(head, at, ("head",))
        upto = int(np.searchsorted(scene.t, t, side="right"))
        for k, art in paths.items():
            set_line(art, np.column_stack((scene.points[k][:, :upto], at[k])))
        i = int(np.clip(np.searchsorted(scene.t, t), 0, scene.t.size - 1))
        words = [f"t = {t:.3f} s   ({slow_motion_words(scene.playback)})",
                 f"lean {scene.panel['lean'][i]:.2f}\u00b0, steer {scene.panel['steer'][i]:.2f}\u00b0"]
        if scene.event_time is not None and t >= scene.t[-1]:
            words.append(f"{scene.event_words.upper()} at t = {scene.event_time:.3f} s")
        clock.set_text("\n".join(words))
        clock.set_color(_EVENT if len(words) > 2 else "black")
        canvas.draw()
        return np.asarray(canvas.buffer_rgba())[..., :3]

    return write_frames(output, draw, times, delays, size_px, fps, progress)
