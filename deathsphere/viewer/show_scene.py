"""The act's 3-D view (``deathsphere show --output act.html|.gif|.mp4``;
docs/show.md, section 8): every rider's envelope moving in the globe with
the clock, the pair of least clearance marked at its closest moment, and
with ``--fail`` the fall's path and landing point.

Nothing here is physics: the riders' points are the show's own
(:meth:`ShowResult.positions`), the pair and the fall are the rows of its
tables.  The fall's path is the parabola those rows fix: it leaves the
rider's centre of mass where contact is lost and reaches the landing point
after the fall's duration under gravity alone, so its initial velocity is
(x1 - x0)/T + g T/2 z.  Frames are close enough that a straight line
between two of them is within a millimetre or so of the rider's path.
"""

from __future__ import annotations

import base64
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from deathsphere.table import Table
from deathsphere.writers.atomic import atomic_file

__all__ = ["ActScene", "act_scene", "act_data", "render_act_html", "write_act_view", "frame_step", "MAX_FRAMES",
           "DATA_MARK"]

#: where the template takes the data (a JavaScript expression)
DATA_MARK = "/*__DEATHSPHERE_ACT__*/null"
#: at most this many frames over the act (~36 bytes a rider a frame in the page)
MAX_FRAMES = 20_000
#: the most a rider's point moves between frames, in units of the globe's radius
MAX_MOVE_R = 0.05
#: points of a fall's drawn path
PATH_POINTS = 64
#: the clock runs this long past a fall's landing [s]
FALL_AFTER_S = 0.3
#: standard gravity [m/s^2], when the result does not say its own
G0 = 9.80665
#: the riders' colours (the pair of least clearance is drawn in red over them)
COLOURS = ("#4e9af1", "#f5b041", "#58d68d", "#af7ac5", "#48c9b0", "#f1948a", "#f7dc6f", "#85c1e9", "#d7bde2",
           "#a3e4d7", "#edbb99", "#aab7b8")


@dataclass
class ActScene:
    """What the view draws: the globe's radius ``r`` [m], frame times ``t``
    (F,), per rider its name, envelope radius [m] and points (3, F)
    (contact, head, centre of mass); the pair of least clearance; the fall."""

    r: float
    g: float
    t: np.ndarray
    names: list
    radii: list
    lanes: list
    points: dict = field(default_factory=dict)      # name -> {"contact","head","com"} (3, F)
    pair: dict | None = None
    fall: dict | None = None
    title: str = ""
    colours: list = field(default_factory=list)


def _plan_number(result, *path, default=None):
    obj = result
    for name in path:
        obj = getattr(obj, name, None)
        if obj is None:
            return default
    try:
        return float(obj)
    except (TypeError, ValueError):
        return default


def _globe_radius(positions: dict) -> float:
    """The globe's radius: every contact point is on it."""
    contact = next(iter(positions.values()))["contact"]
    return float(np.sqrt(np.sum(contact[:, 0] ** 2)))


def frame_step(positions: dict, t: np.ndarray, r: float) -> float:
    """The frame step [s]: the fastest point of any rider (from the sampled
    ``positions`` at times ``t``) moves at most :data:`MAX_MOVE_R` r."""
    fastest = 0.0
    dt = np.diff(t)
    for points in positions.values():
        for p in points.values():
            step = np.sqrt(np.sum(np.diff(p, axis=1) ** 2, axis=0))
            fastest = max(fastest, float(np.max(step / dt)))
    # the coarse samples cut corners: their chord speed is a little low
    return MAX_MOVE_R * r / (1.25 * fastest) if fastest > 0 else float(t[-1] - t[0]) / 100


def _least_pair(pairs: Table) -> dict | None:
    if pairs is None or len(pairs) == 0:
        return None
    clearance = np.asarray(pairs["min_clearance_m"], dtype=np.float64)
    if not np.isfinite(clearance).any():
        return None
    i = int(np.nanargmin(clearance))
    return {"a": str(pairs["rider_a"][i]), "b": str(pairs["rider_b"][i]), "t": float(pairs["t_s"][i]),
            "clearance": float(clearance[i]), "verdict": str(pairs["verdict"][i])}


def _unit_point(r, theta_deg, phi_deg):
    th, ph = math.radians(theta_deg), math.radians(phi_deg)
    return r * np.array([math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), math.cos(th)])


def _fall(result, falls: Table, r: float, g: float) -> dict | None:
    """The first fall of the table, drawn: its rider, times, the path of
    his centre of mass from contact lost to landing, the landing point and
    whom he hits."""
    if falls is None or len(falls) == 0:
        return None
    rider, t_fail = str(falls["rider"][0]), float(falls["t_fail_s"][0])
    rows = [i for i in range(len(falls)) if str(falls["rider"][i]) == rider and float(falls["t_fail_s"][i]) == t_fail]
    hits = [str(falls["victim"][i]) for i in rows if bool(falls["hit"][i]) and str(falls["victim"][i])]
    outcome = str(falls["outcome"][0])
    out = {"rider": rider, "t_fail": t_fail, "outcome": outcome, "hits": hits,
           "fraction": float(falls["speed_fraction"][0])}
    if outcome != "falls":
        return out
    t_lost, t_land, T = (float(falls[k][0]) for k in ("t_contact_lost_s", "t_land_s", "fall_time_s"))
    at_fail = result.positions(np.array([t_fail]))[rider]
    lane = _lane_of(result, rider)
    if lane == "vertical":
        # upright in the loop's plane: the centre of mass is on the contact's radius
        r_g = float(np.linalg.norm(at_fail["com"][:, 0]))
        x0 = _unit_point(r_g, float(falls["theta_lost_deg"][0]), float(falls["phi_lost_deg"][0]))
    else:
        x0 = at_fail["com"][:, 0]
    x1 = _unit_point(r, float(falls["theta_land_deg"][0]), float(falls["phi_land_deg"][0]))
    z = np.array([0.0, 0.0, 1.0])
    v0 = (x1 - x0) / T + 0.5 * g * T * z
    s = np.linspace(0.0, T, PATH_POINTS)
    path = x0[:, None] + v0[:, None] * s[None, :] - 0.5 * g * (s ** 2)[None, :] * z[:, None]
    out.update({"t_lost": t_lost, "t_land": t_land, "path_t": t_lost + s, "path": path, "land": x1,
                "impact": float(falls["impact_speed_m_s"][0])})
    return out


def _lane_of(result, name: str) -> str:
    riders = result.riders
    names = [str(n) for n in riders["name"]]
    return str(riders["lane"][names.index(name)]) if name in names else "horizontal"


def act_scene(result, falls: Table | None = None, *, max_frames: int = MAX_FRAMES) -> ActScene:
    """The act's frames: the riders' points over the act at a step that
    keeps every point within :data:`MAX_MOVE_R` r of the last (at most
    ``max_frames``), the pair of least clearance and the first fall of
    ``falls`` (the table of :meth:`ShowResult.fall`)."""
    duration = float(result.duration_s)
    probe_t = np.linspace(0.0, duration, 2001)
    probe = result.positions(probe_t)
    r = _globe_radius(probe)
    g = _plan_number(result, "plan", "globe", "g", default=G0)
    step = frame_step(probe, probe_t, r)
    fall = _fall(result, falls, r, g) if falls is not None else None
    if fall is not None and "t_land" in fall:
        # a fall may land after the act's end: the clock runs on to the landing
        duration = max(duration, fall["t_land"] + FALL_AFTER_S)
    n = int(min(max_frames, max(2, math.ceil(duration / step) + 1)))
    t = np.linspace(0.0, duration, n)
    pair = _least_pair(result.pairs)
    if pair is not None and not 0.0 <= pair["t"] <= duration:
        pair = None
    if pair is not None:
        # the closest moment is a frame of its own: the view can stop on it
        t = np.unique(np.append(t, pair["t"]))
    positions = result.positions(t)
    riders = result.riders
    names = [str(n) for n in riders["name"]]
    widths = _widths(result, names)
    scene = ActScene(r=r, g=g, t=t, names=names, radii=[0.5 * w for w in widths],
                     lanes=[str(x) for x in riders["lane"]],
                     points={name: {k: np.asarray(positions[name][k], dtype=np.float64)
                                    for k in ("contact", "head", "com")} for name in names},
                     pair=pair, fall=fall)
    scene.title = _title(scene)
    scene.colours = [COLOURS[k % len(COLOURS)] for k in range(len(names))]
    return scene


def _widths(result, names) -> list:
    """Each rider's width [m] (the riders table's, else his lane's)."""
    riders = result.riders
    if "width_m" in riders.names:
        return [float(w) for w in riders["width_m"]]
    lanes = {lane.name: lane for lane in result.lanes}
    return [float(lanes[name].width_m) for name in names]


def _title(scene: ActScene) -> str:
    words = f"{len(scene.names)} riders in a globe of {2 * scene.r:.2f} m, an act of {float(scene.t[-1]):.2f} s"
    if scene.pair is not None:
        words += (f"; least clearance {scene.pair['a']} – {scene.pair['b']} {scene.pair['clearance']:.3f} m "
                  f"at t = {scene.pair['t']:.3f} s ({scene.pair['verdict']})")
    return words


def _encode(x, dtype="<f4") -> str:
    return base64.b64encode(np.ascontiguousarray(x, dtype=dtype).tobytes()).decode("ascii")


def act_data(scene: ActScene) -> dict:
    """The JSON-able data the page reads: vectors as little-endian float32
    arrays in base64, frame-major x, y, z; times float64."""
    riders = []
    for k, name in enumerate(scene.names):
        p = scene.points[name]
        riders.append({"name": name, "colour": scene.colours[k], "radius": scene.radii[k],
                       "lane": scene.lanes[k], **{key: _encode(p[key].T) for key in ("contact", "head", "com")}})
    fall = None
    if scene.fall is not None:
        fall = {k: v for k, v in scene.fall.items() if k not in ("path", "path_t", "land")}
        if "path" in scene.fall:
            fall.update({"path": _encode(scene.fall["path"].T), "path_t": _encode(scene.fall["path_t"], "<f8"),
                         "land": [float(x) for x in scene.fall["land"]]})
    return {"format": "deathsphere-act/1", "title": scene.title, "r": scene.r, "g": scene.g,
            "n": int(scene.t.size), "t": _encode(scene.t, "<f8"), "riders": riders, "pair": scene.pair,
            "fall": fall}


def render_act_html(scene: ActScene) -> str:
    """The page's text (UTF-8): the template with the act's data."""
    from deathsphere.viewer.html import filled_template

    return filled_template("show_template.html", DATA_MARK, act_data(scene), "act view's")


def write_act_view(output, result, falls: Table | None = None) -> int:
    """Write the act's view to ``output`` (.html, .gif or .mp4 by its
    extension); returns the file's size in bytes."""
    from deathsphere.viewer import check_view_output

    fmt = check_view_output(output)
    scene = act_scene(result, falls)
    if fmt == "html":
        data = render_act_html(scene).encode("utf-8")
        with atomic_file(output, "wb") as out:       # whole or not at all
            out.write(data)
        return len(data)
    from deathsphere.viewer.show_animation import write_act_animation

    write_act_animation(output, scene)
    return Path(output).stat().st_size
