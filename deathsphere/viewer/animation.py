"""The 3-D view as a GIF or MP4 loop from a fixed camera, for slides
(beyond the paper; docs/simulation.md, "3-D view").

Drawn with matplotlib's mplot3d, one frame at a time, and written as it is
drawn: a GIF through Pillow's frame encoder with one palette for all
frames (taken from the first frame and the view's colours), an MP4 by
piping raw frames to ffmpeg.  No frame is held after it is written, so the
memory does not grow with the loop's length.

The loop plays the run at the playback factor of
:func:`deathsphere.viewer.scene.playback_factor` (real time, or the slow
motion in which nothing aliases between frames, shown on every frame): all
of the run when it fits in ``max_seconds`` of loop, else its last part
(where a kick has grown and an event ends the run); the trail always goes
back to t = 0.  The last frame is the run's end, held ``END_HOLD_S``.
"""

from __future__ import annotations

import shutil
import subprocess
import textwrap

import numpy as np

from deathsphere.viewer.scene import BodyScene, playback_factor, slow_motion_words
from deathsphere.writers.atomic import atomic_path, signals_held

__all__ = ["frame_times", "loop_plan", "frame_delays_ms", "write_animation", "globe_loop_figure", "CAMERA", "FPS", "MAX_SECONDS",
           "SIZE_PX", "END_HOLD_S"]

#: frames a second of the loop: 40 ms, a whole number of the GIF's 10 ms
#: units, so the GIF's clock is exact
FPS = 25
#: the most seconds of loop (shown time, not simulated)
MAX_SECONDS = 10.0
#: how long the last frame (the run's end, an event's label) is held [s]
END_HOLD_S = 1.5
SIZE_PX = (720, 540)
#: (elevation, azimuth) [deg] of the fixed camera, as the HTML view's default
CAMERA = {"horizontal": (24.0, -62.0), "vertical": (14.0, 25.0)}
#: arrow length per g of force per unit mass, in units of r (as the HTML view)
FORCE_SCALE_R_PER_G = 0.1

_WHEEL = "#e8c547"
_TRAIL = "#1f9bd1"
_NORMAL = "#1e8449"
_FRICTION = "#e67e22"
_SPOKE = "#d62728"
_RIDER = "#8e44ad"
_COM = "#e91e9c"
#: a machine's frame points (simulation.frames): centre of mass, head
_MACHINE = ("com", "head")
_EVENT = "#c0392b"
#: colours the GIF's palette must hold although the first frame may lack them
_SWATCHES = (_WHEEL, _TRAIL, _NORMAL, _FRICTION, _SPOKE, _EVENT, _RIDER, _COM, "#333333", "#8796b0", "#d4a017", "#9a7400",
             "#555555", "#ffffff", "#000000")


def loop_plan(scenes: list[BodyScene], fps: int = FPS, max_seconds: float = MAX_SECONDS,
              playback: float | None = None) -> tuple[np.ndarray, float]:
    """(times [s], playback factor) of the loop's frames: one every
    factor / fps simulated seconds, ending on the run's end, at most
    ``max_seconds`` of loop.  The factor is ``playback`` (simulated
    seconds per second of loop) if given, else chosen from the fastest
    rotation and motion in the last ``max_seconds`` of the run, which
    holds any stretch a slower loop shows."""
    drawn = [s for s in scenes if s.n_frames]
    if not drawn:
        return np.zeros(1), 1.0 if playback is None else float(playback)
    t_end = max(float(s.t[-1]) for s in drawn)
    t_start = min(float(s.t[0]) for s in drawn)
    factor = (playback_factor(drawn, 1.0 / fps, t_from=t_end - max_seconds) if playback is None
              else float(playback))
    step = factor / fps
    span = min(t_end - t_start, max_seconds * factor)
    n = int(np.floor(span / step + 1e-9)) + 1
    return t_end - np.arange(n)[::-1] * step, factor


def frame_times(scenes: list[BodyScene], fps: int = FPS, max_seconds: float = MAX_SECONDS,
                playback: float | None = None) -> np.ndarray:
    """Times [s] of the loop's frames (:func:`loop_plan`)."""
    return loop_plan(scenes, fps, max_seconds, playback)[0]


def frame_delays_ms(n: int, fps: int = FPS, hold_s: float = END_HOLD_S) -> list[int]:
    """How long each of n frames shows [ms], in the GIF's 10 ms units: the
    rounding is carried from frame to frame, so frame k starts at
    k * 1000 / fps ms within 10 ms and the loop's clock never drifts; the
    last frame is held ``hold_s``."""
    edges = np.round(np.arange(n) * 100.0 / fps).astype(np.int64) * 10
    delays = np.diff(edges).tolist()
    return [int(d) for d in delays] + [int(round(hold_s * 100)) * 10]


def _index(scene, t):
    return int(np.clip(np.searchsorted(scene.t, t, side="right") - 1, 0, scene.n_frames - 1))


def _unit(v):
    return v / np.linalg.norm(v)


def _between(scene, t):
    """Geometry at time t, linear between the frames around it (as the
    HTML view does): frames are at most a quarter turn apart, so a blend
    of two directions, normalised, turns the same way as the body."""
    i = _index(scene, t)
    j = min(i + 1, scene.n_frames - 1)
    f = 0.0 if j == i else float(np.clip((t - scene.t[i]) / (scene.t[j] - scene.t[i]), 0.0, 1.0))
    geo = scene.geometry
    out = {k: (1 - f) * geo[k][:, i] + f * geo[k][:, j]
           for k in ("centre", "axis", "e3", "contact", "normal_force", "friction_force", "spoke", *_MACHINE)
           if k in geo}
    out["axis"] = _unit(out["axis"])
    if scene.body != "sphere":
        e3 = out["e3"] - np.dot(out["e3"], out["axis"]) * out["axis"]
        out["e3"] = _unit(e3)
        psi = (1 - f) * geo["spin"][i] + f * geo["spin"][j]
        out["spoke"] = np.cos(psi) * out["e3"] + np.sin(psi) * np.cross(out["axis"], out["e3"])
    else:
        out["e3"] = _unit(out["e3"])
        out["spoke"] = _unit(out["spoke"])
    return i, out


def _sphere_lines(ax, r):
    s = np.linspace(0, 2 * np.pi, 121)
    for ph in np.arange(0, np.pi, np.pi / 6):          # meridians (full great circles)
        ax.plot(r * np.sin(s) * np.cos(ph), r * np.sin(s) * np.sin(ph), r * np.cos(s), color="#8796b0", lw=0.6,
                alpha=0.55)
    for th in np.arange(1, 6) * np.pi / 6:             # parallels, the equator marked
        eq = abs(th - np.pi / 2) < 1e-9
        ax.plot(r * np.sin(th) * np.cos(s), r * np.sin(th) * np.sin(s), np.full_like(s, r * np.cos(th)),
                color="#d4a017" if eq else "#8796b0", lw=2.2 if eq else 0.6, alpha=1.0 if eq else 0.55)
    ax.plot([0, 0], [0, 0], [-1.15 * r, 1.15 * r], color="#8796b0", lw=0.8, ls="--")
    ax.text(0, 0, 1.22 * r, "top pole", color="#9a7400", ha="center", fontsize=11, fontweight="bold")
    ax.text(0, 0, -1.3 * r, "bottom pole", color="#9a7400", ha="center", fontsize=11, fontweight="bold")


def _disc(c, e1, e3, a, n=36):
    u = np.cross(e1, e3)
    b = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return c[None, :] + a * (np.cos(b)[:, None] * e3[None, :] + np.sin(b)[:, None] * u[None, :])


def _ball(c, a, n=10):
    th = np.linspace(0, np.pi, n + 1)
    ph = np.linspace(0, 2 * np.pi, 2 * n + 1)
    quads = []
    for i in range(n):
        for j in range(2 * n):
            tt, pp = th[[i, i + 1, i + 1, i]], ph[[j, j, j + 1, j + 1]]
            quads.append(c + a * np.column_stack((np.sin(tt) * np.cos(pp), np.sin(tt) * np.sin(pp), np.cos(tt))))
    return quads


def number(x, digits=3) -> str:
    """x with ``digits`` decimals, in exponent form from 1e4 on (mu
    required grows without bound as the normal force goes to zero); '-'
    for NaN (no contact).  The HTML view formats alike."""
    if not np.isfinite(x):
        return "-"
    return f"{x:.{digits}f}" if abs(x) < 1e4 else f"{x:.{digits}e}"


def title_text(scene: BodyScene, title: str = "") -> str:
    """The line above the view: body, side, orbit and its start."""
    what = f"{'ball' if scene.body == 'sphere' else scene.body} {scene.side} the sphere, {scene.orbit} orbit"
    start = (f"\u03b8 = {scene.theta0_deg:.1f}\u00b0" if scene.orbit == "vertical"
             else f"\u03b8\u2080 = {scene.theta0_deg:.1f}\u00b0, \u03b1\u2080 = {scene.alpha0_deg:.1f}\u00b0")
    return (f"{title}: " if title else "") + f"{what} ({start}, a = {scene.a:g} m, r = {scene.r:g} m)"


def _nearest(scene, t):
    i = _index(scene, t)
    return i + 1 if i + 1 < scene.n_frames and scene.t[i + 1] - t < t - scene.t[i] else i


def _panel(scene, t, factor):
    """The readouts at time t: the clock, the playback factor, and the
    simulation's numbers at the frame nearest t."""
    i = _nearest(scene, t)
    P = scene.panel
    mu_av = "no limit" if scene.mu_available is None else number(scene.mu_available)
    lines = [f"t = {number(t)} s   ({slow_motion_words(factor)})",
             f"v = {number(P['speed'][i], 2)} m/s = {number(P['speed_km_h'][i], 1)} km/h",
             f"g-load = {number(P['g_load'][i], 2)} g",
             f"\u03bc needed = {number(P['mu'][i])}  (available: {mu_av})",
             f"force \u2220 normal = {number(P['force_angle'][i], 1)}\u00b0"]
    if scene.event_time is not None and t >= scene.t[-1]:
        lines.append(f"{scene.event_words.upper()} at t = {scene.event_time:.3f} s")
    return "\n".join(lines)


def _hex_rgb(colour):
    return tuple(int(colour[k:k + 2], 16) for k in (1, 3, 5))


class _GifStream:
    """A GIF written frame by frame (Pillow's GIF encoder, one global
    palette): nothing is held but the palette and the open file."""

    def __init__(self, path):
        self._path = path
        self._fp = None
        self._palette = None
        self._previous = None

    def start(self):
        self._fp = open(self._path, "wb")

    def add(self, rgb, duration_ms: int):
        from PIL import GifImagePlugin, Image

        im = Image.fromarray(rgb, "RGB")
        if self._palette is None:
            # the first frame's colours, and the view's own (an event's red
            # may first appear at the end): one palette for every frame,
            # so a frame's colours never flicker
            probe = Image.new("RGB", (im.width, im.height + 24))
            probe.paste(im, (0, 0))
            for k, colour in enumerate(_SWATCHES):
                probe.paste(Image.new("RGB", (24, 24), _hex_rgb(colour)), (24 * k, im.height))
            self._palette = probe.quantize(colors=256, method=Image.Quantize.MEDIANCUT)
            first = im.quantize(palette=self._palette, dither=Image.Dither.NONE)
            header, _ = GifImagePlugin.getheader(first, info={"loop": 0, "optimize": False})
            for chunk in header:
                self._fp.write(chunk)
            frame = first
        else:
            frame = im.quantize(palette=self._palette, dither=Image.Dither.NONE)
        # only the rectangle that changed is stored (the sphere and most of
        # the picture stay): the file is several times smaller
        pixels = np.asarray(frame)
        offset = (0, 0)
        if self._previous is not None:
            rows = np.flatnonzero(np.any(pixels != self._previous, axis=1))
            cols = np.flatnonzero(np.any(pixels != self._previous, axis=0))
            box = (cols[0], rows[0], cols[-1] + 1, rows[-1] + 1) if rows.size else (0, 0, 1, 1)
            offset = (int(box[0]), int(box[1]))
            frame = frame.crop(tuple(int(x) for x in box))
        self._previous = pixels
        for chunk in GifImagePlugin.getdata(frame, offset, duration=int(duration_ms), disposal=1):
            self._fp.write(chunk)

    def close(self):
        self._fp.write(b";")
        self._fp.close()

    def abort(self):
        if self._fp is not None:
            self._fp.close()


class _Mp4Stream:
    """Raw RGB frames piped to ffmpeg (H.264, yuv420p, playable in slide
    software); a frame's duration is repeated frames at the fixed rate."""

    def __init__(self, path, size, fps):
        from matplotlib import rcParams

        binary = shutil.which(rcParams["animation.ffmpeg_path"])
        if binary is None:      # refused before any work by check_view_output; here for direct callers
            raise RuntimeError("writing .mp4 needs the ffmpeg encoder, which is not on PATH; "
                               "install ffmpeg, or write .gif or .html instead")
        self._ms = 1000.0 / fps
        self._shown = 0.0
        self._sent = 0
        self._command = [binary, "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s",
                         f"{size[0]}x{size[1]}", "-r", str(fps), "-i", "-", "-c:v", "libx264", "-pix_fmt",
                         "yuv420p", "-movflags", "+faststart", str(path)]
        self._proc = None

    def start(self):
        # a session of its own: Ctrl-C at the terminal reaches this process
        # only, which stops the encoder itself (abort) before the partial
        # file is removed; an encoder stopped first would look like a reader
        # gone away (a broken pipe).  Started with the signals held, so
        # that an encoder started is always one recorded to be stopped.
        with signals_held():
            self._proc = subprocess.Popen(self._command, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                          stderr=subprocess.PIPE, start_new_session=True)

    def add(self, rgb, duration_ms: int):
        self._shown += duration_ms
        data = np.ascontiguousarray(rgb).tobytes()
        while (self._sent + 1) * self._ms <= self._shown + 1e-6:
            try:
                self._proc.stdin.write(data)
            except BrokenPipeError:
                # the encoder ended early: its own failure, not a reader gone
                self._proc.wait()
                raise RuntimeError(f"ffmpeg failed: {self._errors()}") from None
            self._sent += 1

    def _errors(self) -> str:
        return self._proc.stderr.read().decode(errors="replace").strip()[-500:]

    def close(self):
        self._proc.stdin.close()
        err = self._errors()
        if self._proc.wait() != 0:
            raise RuntimeError(f"ffmpeg failed: {err}")

    def abort(self):
        if self._proc is None:
            return
        self._proc.kill()
        self._proc.wait()
        for pipe in (self._proc.stdin, self._proc.stderr):
            try:
                pipe.close()
            except OSError:
                pass


def write_animation(output, scenes: list[BodyScene], *, title: str = "", fps: int = FPS,
                    max_seconds: float = MAX_SECONDS, playback: float | None = None, size_px=SIZE_PX,
                    dpi: int = 90, progress=None) -> int:
    """Write the loop to ``output`` (.gif with Pillow, .mp4 with ffmpeg),
    each frame as it is drawn; returns the number of frames.  Needs
    matplotlib (the ``plot`` extra).  ``max_seconds`` and ``playback``:
    see :func:`loop_plan`.  ``progress(k, n)``, if given, is called after
    each frame.  The file appears under ``output`` only when complete
    (:mod:`deathsphere.writers.atomic`)."""
    from deathsphere.render.figures import import_matplotlib

    import_matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    first = scenes[0]
    r, a = first.r, first.a
    extent = (r + 2.2 * a if first.side == "outside" else r) * 1.02
    fig = Figure(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
    canvas = FigureCanvasAgg(fig)
    ax = fig.add_axes((0.0, 0.05, 1.0, 0.83), projection="3d")
    ax.set_axis_off()
    ax.set_box_aspect((1, 1, 1), zoom=1.45)
    for set_lim in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        set_lim(-extent, extent)
    ax.view_init(*CAMERA.get(first.orbit, CAMERA["horizontal"]))
    _sphere_lines(ax, r)
    fig.text(0.5, 0.995, textwrap.fill(title_text(first, title), 78), ha="center", va="top", fontsize=12,
             fontweight="bold")
    panel = fig.text(0.015, 0.9, "", ha="left", va="top", fontsize=11, family="DejaVu Sans",
                     bbox=dict(boxstyle="round", fc="white", ec="#999999", alpha=0.9))
    fig.text(0.985, 0.015, "arrows: normal force (green), friction (orange), 0.1 r per g", ha="right",
             fontsize=9, color="#555555")
    times, factor = loop_plan(scenes, fps, max_seconds, playback)
    delays = frame_delays_ms(times.size, fps)
    drawn = [s for s in scenes if s.n_frames]
    artists = []
    for s in drawn:
        body = Poly3DCollection([], facecolor=_WHEEL, edgecolor="none" if s.body == "sphere" else "#333333",
                                linewidths=1.5, alpha=0.95)
        ax.add_collection3d(body)
        spoke, = ax.plot([], [], [], color=_SPOKE, lw=3)
        trail, = ax.plot([], [], [], color=_TRAIL, lw=1.6)
        normal, = ax.plot([], [], [], color=_NORMAL, lw=2.5)
        friction, = ax.plot([], [], [], color=_FRICTION, lw=2.5)
        label = ax.text(0, 0, 0, "", color=_EVENT, fontsize=13, fontweight="bold", ha="center",
                        bbox=dict(boxstyle="round", fc="white", ec=_EVENT))
        rider = None
        if "com" in s.geometry:     # a machine: contact - hub - head, the centre of mass and the head marked
            rider = (ax.plot([], [], [], color=_RIDER, lw=3.5)[0],
                     ax.plot([], [], [], "o", color=_COM, ms=9, mec="#1a1a1a")[0],
                     ax.plot([], [], [], "o", color="white", ms=12, mec=_RIDER, mew=2.5)[0])
        artists.append((s, body, spoke, trail, normal, friction, label, rider))

    def draw(t):
        for s, body, spoke, trail, normal, friction, label, rider in artists:
            _, now = _between(s, t)
            c, e1, e3, p = now["centre"], now["axis"], now["e3"], now["contact"]
            if rider is not None:
                frame, com, head = rider
                g, h = now["com"], now["head"]
                frame.set_data_3d([p[0], c[0], h[0]], [p[1], c[1], h[1]], [p[2], c[2], h[2]])
                com.set_data_3d([g[0]], [g[1]], [g[2]])
                head.set_data_3d([h[0]], [h[1]], [h[2]])
            if s.body != "sphere":
                body.set_verts([_disc(c, e1, e3, s.a)])
                tip = c + 0.95 * s.a * now["spoke"]
            else:
                body.set_verts(_ball(c, s.a))
                tip = c + 1.05 * s.a * now["spoke"]          # the body-fixed marker
            spoke.set_data_3d([c[0], tip[0]], [c[1], tip[1]], [c[2], tip[2]])
            upto = int(np.searchsorted(s.trail_t, t, side="right"))
            tr = np.column_stack((s.trail[:, :upto], p))
            trail.set_data_3d(tr[0], tr[1], tr[2])
            scale = FORCE_SCALE_R_PER_G * s.r / s.g
            for art, key in ((normal, "normal_force"), (friction, "friction_force")):
                q = p + scale * now[key]
                art.set_data_3d([p[0], q[0]], [p[1], q[1]], [p[2], q[2]])
            ended = s.event_time is not None and t >= s.t[-1]
            label.set_text(f"\u2716 {s.event_words}" if ended else "")
            q = p * (1.15 if s.side == "outside" else 0.85)
            label.set_position((q[0], q[1]))
            label.set_3d_properties(q[2], None)
        if drawn:
            panel.set_text(_panel(drawn[0], t, factor))
        else:
            panel.set_text(f"{first.status}: {first.reason}")
        canvas.draw()
        return np.asarray(canvas.buffer_rgba())[..., :3]

    return write_frames(output, draw, times, delays, size_px, fps, progress)


def globe_loop_figure(r, title, camera, size_px=SIZE_PX, dpi: int = 90):
    """A loop's figure of a globe of radius ``r`` from the fixed ``camera``
    (elevation, azimuth) [deg], its wireframe drawn, ``title`` above and an
    empty clock box at the top left: (figure, canvas, 3-D axes, clock).
    Needs matplotlib (the ``plot`` extra)."""
    from deathsphere.render.figures import import_matplotlib

    import_matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
    canvas = FigureCanvasAgg(fig)
    ax = fig.add_axes((0.0, 0.02, 1.0, 0.86), projection="3d")
    ax.set_axis_off()
    ax.set_box_aspect((1, 1, 1), zoom=1.4)
    for set_lim in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        set_lim(-r, r)
    ax.view_init(*camera)
    _sphere_lines(ax, r)
    fig.text(0.5, 0.995, textwrap.fill(title, 90), ha="center", va="top", fontsize=10, fontweight="bold")
    clock = fig.text(0.015, 0.86, "", ha="left", va="top", fontsize=11,
                     bbox=dict(boxstyle="round", fc="white", ec="#999999", alpha=0.9))
    return fig, canvas, ax, clock


def write_frames(output, draw, times, delays, size_px, fps, progress=None) -> int:
    """Write the frames ``draw(t)`` (RGB arrays) at ``times`` with the GIF
    ``delays`` (or ``fps`` for an MP4 of ``size_px``) to ``output``, .gif or
    .mp4 by its extension, whole or not at all (:mod:`deathsphere.writers.atomic`;
    an interrupted encoder is stopped); ``progress(done, total)`` after each
    frame.  Returns the number of frames."""
    fmt = str(output).lower().rsplit(".", 1)[-1]
    with atomic_path(output) as temp:
        stream = _GifStream(temp) if fmt == "gif" else _Mp4Stream(temp, size_px, fps)
        try:
            stream.start()
            for k, t in enumerate(times):
                stream.add(draw(float(t)), delays[k])
                if progress is not None:
                    progress(k + 1, len(times))
        except BaseException:
            stream.abort()
            raise
        stream.close()
    return len(times)
