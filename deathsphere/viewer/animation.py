"""The 3-D view as a GIF or MP4 loop from a fixed camera, for slides
(beyond the paper; docs/simulation.md, "3-D view").

Drawn with matplotlib's mplot3d and written by its animation module:
Pillow for .gif (Pillow comes with matplotlib), ffmpeg for .mp4.  The
loop plays the run in real time: all of it when it is short, else its
last ``max_seconds`` (where a kick has grown and an event ends the run);
the trail always goes back to t = 0.
"""

from __future__ import annotations

import numpy as np

from deathsphere.viewer.scene import BodyScene

__all__ = ["frame_times", "write_animation", "CAMERA", "FPS", "MAX_SECONDS", "SIZE_PX"]

FPS = 15
MAX_SECONDS = 10.0
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


def frame_times(scenes: list[BodyScene], fps: int = FPS, max_seconds: float = MAX_SECONDS) -> np.ndarray:
    """Times [s] of the loop's frames: every 1/fps s of the run's last
    ``max_seconds`` (all of it when shorter), ending on the run's end."""
    ends = [float(s.t[-1]) for s in scenes if s.n_frames]
    if not ends:
        return np.zeros(1)
    t_end = max(ends)
    span = min(t_end, max_seconds)
    n = int(np.floor(span * fps + 1e-9)) + 1
    return t_end - np.arange(n)[::-1] / fps


def _index(scene, t):
    return int(np.clip(np.searchsorted(scene.t, t, side="right") - 1, 0, scene.n_frames - 1))


def _unit(v):
    return v / np.linalg.norm(v)


def _between(scene, t):
    """Geometry at time t, linear between the samples around it (as the
    HTML view does; the panel shows the earlier sample's own numbers)."""
    i = _index(scene, t)
    j = min(i + 1, scene.n_frames - 1)
    f = 0.0 if j == i else float(np.clip((t - scene.t[i]) / (scene.t[j] - scene.t[i]), 0.0, 1.0))
    geo = scene.geometry
    out = {k: (1 - f) * geo[k][:, i] + f * geo[k][:, j]
           for k in ("centre", "axis", "e3", "contact", "normal_force", "friction_force", "spoke")}
    out["axis"] = _unit(out["axis"])
    if scene.body == "wheel":
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
    what = f"{'wheel' if scene.body == 'wheel' else 'ball'} {scene.side} the sphere, {scene.orbit} orbit"
    start = (f"\u03b8 = {scene.theta0_deg:.1f}\u00b0" if scene.orbit == "vertical"
             else f"\u03b8\u2080 = {scene.theta0_deg:.1f}\u00b0, \u03b1\u2080 = {scene.alpha0_deg:.1f}\u00b0")
    return (f"{title}: " if title else "") + f"{what} ({start}, a = {scene.a:g} m, r = {scene.r:g} m)"


def _panel(scene, i):
    P = scene.panel
    lines = [f"t = {number(scene.t[i])} s",
             f"\u03b8 = {number(P['theta'][i])}\u00b0   \u03b1 = {number(P['alpha'][i])}\u00b0",
             f"v = {number(P['speed'][i])} m/s   g-load = {number(P['g_load'][i])} g",
             f"\u03bc required = {number(P['mu'][i])}"]
    if scene.event_time is not None and i == scene.n_frames - 1:
        lines.append(f"{scene.status.replace('_', ' ').upper()} at t = {scene.event_time:.3f} s")
    return "\n".join(lines)


def write_animation(output, scenes: list[BodyScene], *, title: str = "", fps: int = FPS,
                    max_seconds: float = MAX_SECONDS, size_px=SIZE_PX, dpi: int = 90) -> int:
    """Write the loop to ``output`` (.gif with Pillow, .mp4 with ffmpeg);
    returns the number of frames.  Needs matplotlib (the ``plot`` extra)."""
    from deathsphere.render.figures import import_matplotlib

    import_matplotlib()
    from matplotlib import animation
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    first = scenes[0]
    r, a = first.r, first.a
    extent = (r + 2.2 * a if first.side == "outside" else r) * 1.02
    fig = Figure(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
    ax = fig.add_axes((0.0, 0.0, 1.0, 0.93), projection="3d")
    ax.set_axis_off()
    ax.set_box_aspect((1, 1, 1), zoom=1.45)
    for set_lim in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        set_lim(-extent, extent)
    ax.view_init(*CAMERA.get(first.orbit, CAMERA["horizontal"]))
    _sphere_lines(ax, r)
    fig.text(0.5, 0.965, title_text(first, title), ha="center", va="center", fontsize=12, fontweight="bold")
    panel = fig.text(0.015, 0.9, "", ha="left", va="top", fontsize=12, family="DejaVu Sans",
                     bbox=dict(boxstyle="round", fc="white", ec="#999999", alpha=0.9))
    fig.text(0.985, 0.03, "arrows: normal force (green), friction (orange), 0.1 r per g", ha="right",
             fontsize=9, color="#555555")
    times = frame_times(scenes, fps, max_seconds)
    drawn = [s for s in scenes if s.n_frames]
    artists = []
    for s in drawn:
        body = Poly3DCollection([], facecolor=_WHEEL, edgecolor="#333333" if s.body == "wheel" else "none",
                                linewidths=1.5, alpha=0.95)
        ax.add_collection3d(body)
        spoke, = ax.plot([], [], [], color=_SPOKE, lw=3)
        trail, = ax.plot([], [], [], color=_TRAIL, lw=1.6)
        normal, = ax.plot([], [], [], color=_NORMAL, lw=2.5)
        friction, = ax.plot([], [], [], color=_FRICTION, lw=2.5)
        artists.append((s, body, spoke, trail, normal, friction))

    def draw(k):
        t = times[k]
        for s, body, spoke, trail, normal, friction in artists:
            i, now = _between(s, t)
            c, e1, e3, p = now["centre"], now["axis"], now["e3"], now["contact"]
            if s.body == "wheel":
                body.set_verts([_disc(c, e1, e3, s.a)])
                tip = c + 0.95 * s.a * now["spoke"]
            else:
                body.set_verts(_ball(c, s.a))
                tip = c + 1.05 * s.a * now["spoke"]          # the body-fixed marker
            spoke.set_data_3d([c[0], tip[0]], [c[1], tip[1]], [c[2], tip[2]])
            tr = np.column_stack((s.geometry["contact"][:, : i + 1], p))
            trail.set_data_3d(tr[0], tr[1], tr[2])
            scale = FORCE_SCALE_R_PER_G * s.r / s.g
            for art, key in ((normal, "normal_force"), (friction, "friction_force")):
                q = p + scale * now[key]
                art.set_data_3d([p[0], q[0]], [p[1], q[1]], [p[2], q[2]])
        if drawn:
            panel.set_text(_panel(drawn[0], _index(drawn[0], t)))
        else:
            panel.set_text(f"{first.status}: {first.reason}")
        return []

    anim = animation.FuncAnimation(fig, draw, frames=len(times), interval=1000 / fps, blit=False)
    fmt = str(output).lower().rsplit(".", 1)[-1]
    writer = animation.PillowWriter(fps=fps) if fmt == "gif" else animation.FFMpegWriter(fps=fps)
    anim.save(str(output), writer=writer, dpi=dpi)
    return len(times)
