"""The act as a GIF or MP4 loop from a fixed camera, for slides
(docs/show.md, section 8): every rider's envelope moving with the clock,
the pair of least clearance in red around its closest moment, the fall's
path and landing point, from the scene of
:func:`deathsphere.viewer.show_scene.act_scene`.  Drawn with matplotlib (the ``plot`` extra) and
written frame by frame through the simulate view's streams
(:mod:`deathsphere.viewer.animation`), so the memory stays flat."""

from __future__ import annotations

import numpy as np

from deathsphere.viewer.animation import FPS, SIZE_PX, frame_delays_ms, globe_loop_figure, write_frames
from deathsphere.viewer.scene import slow_motion_words

__all__ = ["loop_times", "write_act_animation", "MAX_SECONDS", "CAMERA"]

#: the most seconds of loop (shown time)
MAX_SECONDS = 10.0
#: (elevation, azimuth) [deg] of the fixed camera
CAMERA = (22.0, -52.0)
_PAIR = "#ff3b30"
_FALL = "#ff6b5b"


def loop_times(scene, fps: int = FPS, max_seconds: float = MAX_SECONDS) -> tuple[np.ndarray, float]:
    """(times [s], playback factor): frames 1/fps of shown time apart at
    half speed (riders at 10 m/s move 0.2 m a frame), over the act from
    its start, or over ``max_seconds`` of loop centred on the fall or, with
    no fall, on the closest moment."""
    factor = 0.5
    step = factor / fps
    t0, t1 = float(scene.t[0]), float(scene.t[-1])
    span = max_seconds * factor
    if t1 - t0 <= span:
        start = t0
    else:
        focus = scene.fall["t_fail"] if scene.fall else (scene.pair["t"] if scene.pair else t0 + 0.5 * span)
        start = min(max(t0, focus - 0.4 * span), t1 - span)
    n = int(np.floor(min(span, t1 - start) / step + 1e-9)) + 1
    return start + np.arange(n) * step, factor


def _at(scene, name: str, key: str, t: float) -> np.ndarray:
    p = scene.points[name][key]
    return np.array([np.interp(t, scene.t, p[k]) for k in range(3)])


def _fall_point(fall: dict, t: float) -> np.ndarray:
    return np.array([np.interp(t, fall["path_t"], fall["path"][k]) for k in range(3)])


def write_act_animation(output, scene, *, fps: int = FPS, max_seconds: float = MAX_SECONDS,
                        size_px=SIZE_PX, dpi: int = 90) -> int:
    """Write the loop to ``output`` (.gif or .mp4), each frame as it is
    drawn; returns the number of frames."""
    r = scene.r
    fig, canvas, ax, clock = globe_loop_figure(r, scene.title, CAMERA, size_px, dpi)
    # a capsule drawn as a thick line: its width in points from the rider's width
    points_per_m = 0.5 * size_px[1] / (2.4 * r) * 72 / dpi
    artists = {}
    for k, name in enumerate(scene.names):
        width = max(2.0, 2 * scene.radii[k] * points_per_m)
        halo, = ax.plot([], [], [], color=_PAIR, lw=width + 5, alpha=0.0, solid_capstyle="round")
        body, = ax.plot([], [], [], color=scene.colours[k], lw=width, alpha=0.9, solid_capstyle="round")
        label = ax.text(0, 0, 0, name, fontsize=9, color="#222222")
        artists[name] = (halo, body, label)
    fall = scene.fall if scene.fall and "path" in scene.fall else None
    path_line, = ax.plot([], [], [], color=_FALL, lw=2, ls="--")
    landing, = ax.plot([], [], [], "x", color=_FALL, ms=14, mew=3)
    times, factor = loop_times(scene, fps, max_seconds)
    delays = frame_delays_ms(times.size, fps)
    pair = scene.pair
    near = max(0.15, 0.01 * float(scene.t[-1] - scene.t[0]))

    def draw(t):
        closest = pair is not None and abs(t - pair["t"]) <= near
        for name, (halo, body, label) in artists.items():
            if fall is not None and name == fall["rider"] and t >= fall["t_lost"]:
                a = b = _fall_point(fall, t)
                body.set_color(_FALL)
            else:
                a, b = _at(scene, name, "contact", t), _at(scene, name, "head", t)
            for art in (halo, body):
                art.set_data_3d([a[0], b[0] + 1e-6], [a[1], b[1]], [a[2], b[2]])
            halo.set_alpha(0.6 if closest and name in (pair["a"], pair["b"]) else 0.0)
            label.set_position((b[0], b[1]))
            label.set_3d_properties(b[2] + 0.05 * r, None)
        words = [f"t = {t:.3f} s   ({slow_motion_words(factor)})"]
        if closest:
            words.append(f"closest: {pair['a']} – {pair['b']} {pair['clearance']:.3f} m at t = {pair['t']:.3f} s")
        if fall is not None and t >= fall["t_lost"]:
            path_line.set_data_3d(*fall["path"])
            words.append(f"{fall['rider']} falls: lands at t = {fall['t_land']:.3f} s, "
                         f"{3.6 * fall['impact']:.1f} km/h" + (f", into {', '.join(fall['hits'])}" if fall["hits"] else ""))
            if t >= fall["t_land"]:
                landing.set_data_3d([fall["land"][0]], [fall["land"][1]], [fall["land"][2]])
        clock.set_text("\n".join(words))
        canvas.draw()
        return np.asarray(canvas.buffer_rgba())[..., :3]

    return write_frames(output, draw, times, delays, size_px, fps)
