"""Any scene as a GIF or MP4 loop from a fixed camera, for slides
(docs/simulation.md, "3-D view"; docs/show.md sec. 8; docs/two-wheeler.md
sec. 10.1).

Drawn with matplotlib's mplot3d (the ``plot`` extra), one frame at a time,
and written as it is drawn (:mod:`deathsphere.viewer.streams`).  The ground
is drawn from its description (a globe's or any surface of revolution's
meridians and parallels, flat ground's grid) and every track from its
items, as the page does: one artist per item, moved each frame; an item's
``print`` colour is its colour on the loop's white.

The loop plays the run at the scene's playback factor (for a simulated
orbit: real time, or the slow motion in which nothing aliases between
frames, :func:`deathsphere.viewer.scene.playback_factor`, shown on every
frame): all of the run when it fits in ``max_seconds`` of loop, else its
last part (where a kick has grown and an event ends the run), or the part
about the scene's ``focus`` (a fall, the closest moment).  The last frame
is held ``END_HOLD_S``.
"""

from __future__ import annotations

import textwrap

import numpy as np

from deathsphere.viewer.scene import Scene, ground_extent, playback_factor, slow_motion_words
from deathsphere.viewer.streams import END_HOLD_S, FPS, SWATCHES, frame_delays_ms, write_frames

__all__ = ["loop_plan", "frame_times", "write_animation", "panel_text", "number", "FPS", "MAX_SECONDS", "SIZE_PX",
           "END_HOLD_S", "frame_delays_ms"]

#: the most seconds of loop (shown time, not simulated)
MAX_SECONDS = 10.0
SIZE_PX = (720, 540)
_WHEEL = "#e8c547"
_SPOKE = "#d62728"
_EVENT = "#c0392b"
_GRID = "#8796b0"
_MARKED = "#d4a017"


def loop_plan(scene: Scene, fps: int = FPS, max_seconds: float = MAX_SECONDS,
              playback: float | None = None) -> tuple[np.ndarray, float]:
    """(times [s], playback factor) of the loop's frames: one every
    factor / fps simulated seconds, at most ``max_seconds`` of loop, ending
    on the run's end, or, for a scene with a ``focus`` and too long to show
    whole, starting a little before the focus.  The factor is ``playback``
    (simulated seconds per second of loop) if given, else the scene's loop
    factor, else chosen from the fastest rotation and motion in the last
    ``max_seconds`` of the run, which holds any stretch a slower loop shows."""
    if not scene.drawn:
        return np.zeros(1), 1.0 if playback is None else float(playback)
    t_start, t_end = scene.t_start, scene.t_end
    if playback is not None:
        factor = float(playback)
    elif scene.loop_playback is not None:
        factor = scene.loop_playback
    else:
        factor = playback_factor(scene, 1.0 / fps, t_from=t_end - max_seconds)
    step = factor / fps
    span = max_seconds * factor
    if scene.focus is not None and t_end - t_start > span:
        start = min(max(t_start, scene.focus - 0.4 * span), t_end - span)
        n = int(np.floor(min(span, t_end - start) / step + 1e-9)) + 1
        return start + np.arange(n) * step, factor
    n = int(np.floor(min(t_end - t_start, span) / step + 1e-9)) + 1
    return t_end - np.arange(n)[::-1] * step, factor


def frame_times(scene: Scene, fps: int = FPS, max_seconds: float = MAX_SECONDS,
                playback: float | None = None) -> np.ndarray:
    """Times [s] of the loop's frames (:func:`loop_plan`)."""
    return loop_plan(scene, fps, max_seconds, playback)[0]


def number(x, digits=3) -> str:
    """x with ``digits`` decimals, in exponent form from 1e4 on (mu
    required grows without bound as the normal force goes to zero); '-'
    for NaN (no contact).  The HTML view formats alike."""
    if x is None or not np.isfinite(x):
        return "-"
    return f"{x:.{digits}f}" if abs(x) < 1e4 else f"{x:.{digits}e}"


def _frame(track, t):
    """(i, j, f): the frames about t and the blend between them, as the
    page's."""
    n = track.n_frames
    i = int(np.clip(np.searchsorted(track.t, t, side="right") - 1, 0, n - 1))
    j = min(i + 1, n - 1)
    f = 0.0 if j == i else float(np.clip((t - track.t[i]) / (track.t[j] - track.t[i]), 0.0, 1.0))
    return i, j, f


def _nearest(track, t):
    i = _frame(track, t)[0]
    return i + 1 if i + 1 < track.n_frames and track.t[i + 1] - t < t - track.t[i] else i


def _point(track, name, at):
    i, j, f = at
    x = track.points[name]
    return (1 - f) * x[..., i] + f * x[..., j]


def _path_point(path, t):
    times, xyz = path
    return np.array([np.interp(t, times, xyz[k]) for k in range(3)])


def _unit(v):
    return v / np.linalg.norm(v)


def _shown(item, t):
    return ("from" not in item or t >= item["from"]) and ("until" not in item or t < item["until"])


def _readout_text(readout, i) -> str:
    x = readout.at(i)
    return readout.none_text if x is None else number(x, readout.digits) + readout.unit


def panel_text(scene: Scene, t: float, factor: float) -> str:
    """The loop's readouts at time t: the clock and the playback factor,
    the panel's numbers at the frame nearest t (of the first track with a
    panel), the closest moment about its time, and every event from its
    time on."""
    lines = [f"t = {number(t)} s   ({slow_motion_words(factor)})"]
    panel = next((s for s in scene.tracks if s.panel), None)
    if panel is not None and not panel.n_frames:
        return f"{panel.status}: {panel.reason}"
    if panel is not None:
        i = _nearest(panel, t)
        for r in panel.panel:
            if not r.loop:
                continue
            words = f"{r.label} = {_readout_text(r, i)}" if r.label else _readout_text(r, i)
            if (r.join or r.loop_join) and len(lines) > 1:
                lines[-1] += (r.loop_join or r.join) + (words if r.loop_join else _readout_text(r, i))
            else:
                lines.append(words)
    pair = scene.pair
    if pair is not None and abs(t - pair["t"]) <= pair["near"]:
        lines.append(f"closest: {pair['a']} \u2013 {pair['b']} {pair['clearance']:.3f} m at t = {pair['t']:.3f} s")
    for s in scene.tracks:
        if s.event_time is not None and t >= s.event_time:
            who = f"{s.name}: " if len(scene.tracks) > 1 else ""
            lines.append(f"{who}{s.event_words.upper()} at t = {s.event_time:.3f} s")
    return "\n".join(lines)


def _ground_lines(ax, ground: dict):
    """The ground from its description: a surface of revolution's
    meridians every 30 deg and a few parallels (the widest marked), or a
    grid on flat ground."""
    if ground["kind"] == "plane":
        w, (cx, cy) = ground["half_width"], ground["centre"]
        step = 10.0 ** np.floor(np.log10(w / 5))
        step *= 5 if w / step > 20 else 2 if w / step > 10 else 1
        for x in np.arange(np.floor((cx - w) / step), np.ceil((cx + w) / step) + 1) * step:
            ax.plot([x, x], [cy - w, cy + w], [0, 0], color=_GRID, lw=0.6, alpha=0.55)
        for y in np.arange(np.floor((cy - w) / step), np.ceil((cy + w) / step) + 1) * step:
            ax.plot([cx - w, cx + w], [y, y], [0, 0], color=_GRID, lw=0.6, alpha=0.55)
        return
    if ground["kind"] == "sphere":
        r = ground["radius"]
        th = np.linspace(0, np.pi, 61)
        rho, z, parallels = r * np.sin(th), r * np.cos(th), list(range(10, 60, 10))
    else:
        rho, z = np.asarray(ground["rho"]), np.asarray(ground["z"])
        every = max(1, round((rho.size - 1) / 6))
        parallels = list(range(every, rho.size - 1, every))
    widest = int(np.argmax(rho))
    s = np.linspace(0, 2 * np.pi, 121)
    for ph in np.arange(0, np.pi - 1e-9, np.pi / 6):                # meridians, each with its opposite in one line
        ring = np.concatenate((rho, -rho[::-1]))
        ax.plot(ring * np.cos(ph), ring * np.sin(ph), np.concatenate((z, z[::-1])), color=_GRID, lw=0.6, alpha=0.55)
    for k in sorted(set(parallels) | ({widest} if 0 < widest < rho.size - 1 else set())):
        marked = k == widest
        ax.plot(rho[k] * np.cos(s), rho[k] * np.sin(s), np.full_like(s, z[k]), color=_MARKED if marked else _GRID,
                lw=2.2 if marked else 0.6, alpha=1.0 if marked else 0.55)
    span = float(np.ptp(z))
    ax.plot([0, 0], [0, 0], [z.min() - 0.075 * span, z.max() + 0.075 * span], color=_GRID, lw=0.8, ls="--")
    if ground["kind"] == "sphere":
        r = ground["radius"]
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


class _Item:
    """The artists of one item of a track, and how they move."""

    def __init__(self, ax, track, item, scene, px_per_m):
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection

        self.track, self.item, self.kind = track, item, item["kind"]
        colour = item.get("print", item.get("colour", "#333333"))
        self.artists = []
        if self.kind in ("wheel", "ball"):
            self.body = Poly3DCollection([], facecolor=_WHEEL, edgecolor="none" if self.kind == "ball" else "#333333",
                                         linewidths=1.5, alpha=0.95)
            ax.add_collection3d(self.body)
            self.spoke, = ax.plot([], [], [], color=_SPOKE, lw=3)
            self.artists = [self.body, self.spoke]
        elif self.kind == "dot":
            ms = 1.4 * item.get("min_px", 3) + 2
            edge = item.get("print_edge", item.get("edge"))
            self.line, = ax.plot([], [], [], "o", color=colour, ms=ms, mec=edge or colour, mew=2 if edge else 0)
        elif self.kind == "cross":
            self.line, = ax.plot([], [], [], "x", color=colour, ms=14, mew=3)
        elif self.kind == "label":
            self.text = ax.text(0, 0, 0, item["text"], fontsize=9, color="#222222")
            self.lift = 0.05 * ground_extent(scene.ground)
            self.artists = [self.text]
        elif self.kind == "capsule":
            width = max(2.0, 2 * item["radius"] * px_per_m)
            self.halo, = ax.plot([], [], [], color=item.get("highlight", {}).get("colour", "#ff3b30"), lw=width + 5,
                                 alpha=0.0, solid_capstyle="round")
            self.line, = ax.plot([], [], [], color=colour, lw=width, alpha=0.9, solid_capstyle="round")
            self.artists = [self.halo]
        else:
            width = {"path": 1.6, "ring": 2.2, "arrow": 2.5}.get(self.kind, 0.7 * item.get("width", 3))
            self.line, = ax.plot([], [], [], color=colour, lw=width, ls="--" if item.get("dash") else "-")
        if hasattr(self, "line"):
            self.artists.append(self.line)

    def draw(self, t):
        track, item = self.track, self.item
        visible = track.n_frames > 0 and _shown(item, t)
        for art in self.artists:
            art.set_visible(visible)
        if not visible:
            return
        at = _frame(track, t)
        p = lambda name: _point(track, name, at)    # noqa: E731 (the item's points now)
        moving = _path_point(track.paths[item["path"]], t) if "path" in item and not item.get("whole") else None
        if self.kind == "wheel":
            c, e1 = p(item["centre"]), _unit(p(item["axis"]))
            e3 = _unit(p(item["e3"]) - np.dot(p(item["e3"]), e1) * e1)
            i, j, f = at
            psi = (1 - f) * track.scalars[item["spin"]][i] + f * track.scalars[item["spin"]][j]
            self.body.set_verts([_disc(c, e1, e3, item["radius"])])
            tip = c + 0.95 * item["radius"] * (np.cos(psi) * e3 + np.sin(psi) * np.cross(e1, e3))
            self.spoke.set_data_3d([c[0], tip[0]], [c[1], tip[1]], [c[2], tip[2]])
        elif self.kind == "ball":
            c = p(item["centre"])
            self.body.set_verts(_ball(c, item["radius"]))
            tip = c + 1.05 * item["radius"] * _unit(p(item["marker"]))        # the body-fixed marker
            self.spoke.set_data_3d([c[0], tip[0]], [c[1], tip[1]], [c[2], tip[2]])
        elif self.kind == "label":
            q = moving if moving is not None else p(item["point"])
            self.text.set_position((q[0], q[1]))
            self.text.set_3d_properties(q[2] + self.lift, None)
        elif self.kind == "capsule":
            a, b = p(item["points"][0]), p(item["points"][1])
            for art in (self.halo, self.line):
                art.set_data_3d([a[0], b[0] + 1e-6], [a[1], b[1]], [a[2], b[2]])
            hl = item.get("highlight")
            self.halo.set_alpha(0.6 if hl and hl["from"] <= t <= hl["until"] else 0.0)
        else:
            self.line.set_data_3d(*self._xyz(p, moving, t))

    def _xyz(self, p, moving, t):
        track, item = self.track, self.item
        if self.kind == "chain":
            return np.column_stack([p(k) for k in item["points"]])
        if self.kind == "ring":
            rim = p(item["points"])
            return np.column_stack((rim, rim[:, :1]))
        if self.kind == "dot":
            return (moving if moving is not None else p(item["point"]))[:, None]
        if self.kind == "cross":
            return track.paths[item["path"]][1][:, -1:]
        if self.kind == "arrow":
            a = p(item["point"])
            return np.column_stack((a, a + item["scale"] * p(item["vector"])))
        # a path up to now: a point of the track over its frames, or a path on its own axis
        if "path" in item:
            times, xyz = track.paths[item["path"]]
            pts = xyz if item.get("whole") else xyz[:, :int(np.searchsorted(times, t, side="right"))]
        else:
            pts = np.column_stack((track.points[item["point"]][:, :_frame(track, t)[0] + 1], p(item["point"])))
        return np.column_stack((pts, p(item["to"]))) if "to" in item else pts


def write_animation(output, scene: Scene, *, fps: int = FPS, max_seconds: float = MAX_SECONDS,
                    playback: float | None = None, size_px=SIZE_PX, dpi: int = 90, progress=None) -> int:
    """Write the loop of ``scene`` to ``output`` (.gif with Pillow, .mp4
    with ffmpeg), each frame as it is drawn; returns the number of frames.
    Needs matplotlib (the ``plot`` extra).  ``max_seconds`` and
    ``playback``: see :func:`loop_plan`.  ``progress(k, n)``, if given, is
    called after each frame.  The file appears under ``output`` only when
    complete (:mod:`deathsphere.writers.atomic`)."""
    from deathsphere.render.figures import import_matplotlib

    import_matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
    canvas = FigureCanvasAgg(fig)
    ax = fig.add_axes((0.0, 0.04, 1.0, 0.84), projection="3d")
    ax.set_axis_off()
    ax.set_box_aspect((1, 1, 1), zoom=1.45)
    extent = 1.02 * scene.camera["extent"]
    for set_lim, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), scene.camera["target"]):
        set_lim(c - extent, c + extent)
    ax.view_init(scene.camera["el"], scene.camera["az"])
    _ground_lines(ax, scene.ground)
    fig.text(0.5, 0.995, textwrap.fill(scene.title, 84), ha="center", va="top", fontsize=11, fontweight="bold")
    panel = fig.text(0.015, 0.88, "", ha="left", va="top", fontsize=11, family="DejaVu Sans",
                     bbox=dict(boxstyle="round", fc="white", ec="#999999", alpha=0.9))
    fig.text(0.985, 0.015, textwrap.fill("; ".join(row["text"].replace("_", "") for row in scene.legend), 110),
             ha="right", fontsize=8, color="#555555")
    # a capsule's width in points from its radius in metres
    px_per_m = 0.5 * size_px[1] / (2.4 * ground_extent(scene.ground)) * 72 / dpi
    items = [_Item(ax, s, item, scene, px_per_m) for s in scene.drawn for item in s.draw]
    labels = [(s, ax.text(0, 0, 0, "", color=_EVENT, fontsize=13, fontweight="bold", ha="center",
                          bbox=dict(boxstyle="round", fc="white", ec=_EVENT)))
              for s in scene.drawn if s.event_time is not None]
    times, factor = loop_plan(scene, fps, max_seconds, playback)
    delays = frame_delays_ms(times.size, fps)
    swatches = tuple(dict.fromkeys(SWATCHES + tuple(i.item["print"] for i in items
                                                    if str(i.item.get("print", "")).startswith("#"))))

    def draw(t):
        for item in items:
            item.draw(t)
        for s, label in labels:
            ended = t >= s.event_time
            label.set_text(f"\u2716 {s.event_words}" if ended else "")
            if ended:
                q = _point(s, s.event_point, _frame(s, t))
                toward = (_point(s, "centre", _frame(s, t)) - q if "centre" in s.points
                          else (-q if scene.ground["kind"] == "sphere" else np.array([0.0, 0.0, 1.0])))
                q = q + 0.15 * ground_extent(scene.ground) * _unit(toward)
                label.set_position((q[0], q[1]))
                label.set_3d_properties(q[2], None)
        panel.set_text(panel_text(scene, t, factor))
        canvas.draw()
        return np.asarray(canvas.buffer_rgba())[..., :3]

    return write_frames(output, draw, times, delays, size_px, fps, progress, swatches)
