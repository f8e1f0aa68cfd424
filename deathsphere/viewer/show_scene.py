"""The act's 3-D view (``deathsphere show --output act.html|.gif|.mp4``;
docs/show.md, section 8): every rider's envelope moving in the globe with
the clock, the pair of least clearance marked at its closest moment, and
with ``--fail`` each fall's path and landing point (one fall per rider).

Nothing here is physics: the riders' points are the show's own
(:meth:`ShowResult.positions`), the pair and the fall are the rows of its
tables.  The fall's path is the parabola those rows fix: it leaves the
rider's centre of mass where contact is lost and reaches the landing point
after the fall's duration under gravity alone, so its initial velocity is
(x1 - x0)/T + g T/2 z.  Frames are close enough that a straight line
between two of them is within a millimetre or so of the rider's path.
"""

from __future__ import annotations

import math

import numpy as np

from deathsphere.table import Table
from deathsphere.viewer.scene import Scene, Track, sphere_ground, wall_ground

__all__ = ["act_scene", "frame_step", "MAX_FRAMES", "MAX_MOVE_R", "CAMERA", "PLAYBACK", "LOOP_PLAYBACK"]

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
#: (elevation, azimuth) [deg] of the camera
CAMERA = (22.0, -52.0)
#: simulated seconds per second shown as the page starts, and as the loop
#: plays (riders at 10 m/s move 0.2 m a frame of its 25 a second)
PLAYBACK = 0.25
LOOP_PLAYBACK = 0.5
_PAIR = "#ff3b30"
_FALL = "#ff6b5b"
#: the riders' colours (the pair of least clearance is drawn in red over them)
COLOURS = ("#4e9af1", "#f5b041", "#58d68d", "#af7ac5", "#48c9b0", "#f1948a", "#f7dc6f", "#85c1e9", "#d7bde2",
           "#a3e4d7", "#edbb99", "#aab7b8")


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


def fall_groups(falls: Table | None) -> list[list[int]]:
    """The rows of each fall of a falls table (one fall: a rider, a time
    and a fraction; a row per other rider), in the table's order."""
    if falls is None:
        return []
    groups: dict = {}
    for i in range(len(falls)):
        key = (str(falls["rider"][i]), float(falls["t_fail_s"][i]), float(falls["speed_fraction"][i]))
        groups.setdefault(key, []).append(i)
    return list(groups.values())


def one_fall_each(falls: Table | None) -> None:
    """ValueError naming the rider when two falls of the table are one
    rider's: a rider's track draws one fall (he cannot fall twice in one act)."""
    seen: dict = {}
    for rows in fall_groups(falls):
        rider = str(falls["rider"][rows[0]])
        if rider in seen:
            raise ValueError(f"the view draws one fall per rider: {rider} falls at t = {seen[rider]:g} s and at "
                             f"t = {float(falls['t_fail_s'][rows[0]]):g} s (draw them one at a time; the tables hold both)")
        seen[rider] = float(falls["t_fail_s"][rows[0]])


def _fall(result, falls: Table, rows: list[int], r: float, g: float) -> dict:
    """One fall of the table (its ``rows``), drawn: its rider, times, the
    path of his centre of mass from contact lost to landing, the landing
    point and whom he hits."""
    first = rows[0]
    rider, t_fail = str(falls["rider"][first]), float(falls["t_fail_s"][first])
    hits = [str(falls["victim"][i]) for i in rows if bool(falls["hit"][i]) and str(falls["victim"][i])]
    outcome = str(falls["outcome"][first])
    out = {"rider": rider, "t_fail": t_fail, "outcome": outcome, "hits": hits,
           "fraction": float(falls["speed_fraction"][first])}
    if outcome != "falls":
        return out
    t_lost, t_land, T = (float(falls[k][first]) for k in ("t_contact_lost_s", "t_land_s", "fall_time_s"))
    at_fail = result.positions(np.array([t_fail]))[rider]
    lane = _lane_of(result, rider)
    if lane == "vertical":
        # upright in the loop's plane: the centre of mass is on the contact's radius
        r_g = float(np.linalg.norm(at_fail["com"][:, 0]))
        x0 = _unit_point(r_g, float(falls["theta_lost_deg"][first]), float(falls["phi_lost_deg"][first]))
    else:
        x0 = at_fail["com"][:, 0]
    if math.isfinite(float(falls["theta_land_deg"][first])):
        x1 = _unit_point(r, float(falls["theta_land_deg"][first]), float(falls["phi_land_deg"][first]))
        z = np.array([0.0, 0.0, 1.0])
        v0 = (x1 - x0) / T + 0.5 * g * T * z
        s = np.linspace(0.0, T, PATH_POINTS)
        path_t = t_lost + s
        path = x0[:, None] + v0[:, None] * s[None, :] - 0.5 * g * (s ** 2)[None, :] * z[:, None]
    else:
        # on a drum or a cone the landing's height and azimuth leave its distance from the axis free: the
        # act's own flight
        flight = result.fall_path(rider, t_fail, float(falls["speed_fraction"][first]), PATH_POINTS)
        path_t, path = flight["t"], flight["com"]
        x1 = path[:, -1]
    out.update({"t_lost": t_lost, "t_land": t_land, "path_t": path_t, "path": path, "land": x1,
                "impact": float(falls["impact_speed_m_s"][first])})
    return out


def _lane_of(result, name: str) -> str:
    riders = result.riders
    names = [str(n) for n in riders["name"]]
    return str(riders["lane"][names.index(name)]) if name in names else "horizontal"


def act_scene(result, falls: Table | None = None, *, max_frames: int = MAX_FRAMES) -> Scene:
    """The act's scene: one track per rider, his points over the act at a
    step that keeps every point within :data:`MAX_MOVE_R` r of the last (at
    most ``max_frames``), the pair of least clearance and every fall of
    ``falls`` (the table of :meth:`ShowResult.fall`, or several joined) on
    its rider's track; ValueError when two falls are one rider's
    (:func:`one_fall_each`)."""
    one_fall_each(falls)
    duration = float(result.duration_s)
    probe_t = np.linspace(0.0, duration, 2001)
    probe = result.positions(probe_t)
    wall = _wall(result, probe)
    r = _globe_radius(probe) if wall is None else wall["r"]
    g = _plan_number(result, "plan", "globe", "g", default=G0)
    step = frame_step(probe, probe_t, r)
    drawn = [_fall(result, falls, rows, r, g) for rows in fall_groups(falls)]
    for fall in drawn:
        if "t_land" in fall:
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
    names = [str(x) for x in riders["name"]]
    lanes = [str(x) for x in riders["lane"]]
    widths = _widths(result, names)
    near = max(0.15, 0.01 * float(t[-1] - t[0]))
    tracks = []
    for k, name in enumerate(names):
        colour = COLOURS[k % len(COLOURS)]
        in_pair = pair is not None and name in (pair["a"], pair["b"])
        track = Track(name=name, t=t, points={key: np.asarray(value, dtype=np.float64)
                                              for key, value in positions[name].items()},
                      meta={"lane": lanes[k], "radius": 0.5 * widths[k], "colour": colour})
        track.draw = _rider_draw(track, in_pair, pair, near, _segments(result, name))
        for fall in drawn:
            if fall["rider"] == name:
                _add_fall(track, fall)
        tracks.append(track)
    ground, target, extent = ((sphere_ground(r), [0.0, 0.0, 0.0], 1.05 * r) if wall is None else
                              (wall["ground"], wall["target"], wall["extent"]))
    scene = Scene(ground=ground, tracks=tracks, playback=PLAYBACK, loop_playback=LOOP_PLAYBACK,
                  camera={"el": CAMERA[0], "az": CAMERA[1], "target": target, "extent": extent},
                  legend=[{"colour": tr.meta["colour"], "text": f"{tr.name} ({tr.meta['lane']})"} for tr in tracks])
    scene.title = _title(len(names), r, float(t[-1]), pair, None if wall is None else wall["what"])
    if pair is not None:
        scene.pair = {"tracks": [names.index(pair["a"]), names.index(pair["b"])], "t": pair["t"], "near": near,
                      **pair}
        scene.notes.append({"text": f"Least clearance: {pair['a']} \u2013 {pair['b']} {pair['clearance']:.3f} m at "
                                    f"t = {pair['t']:.3f} s ({pair['verdict']}), drawn in red."})
        scene.moments.append({"label": "Closest moment", "t": pair["t"]})
    for fall in drawn:
        scene.notes.append({"text": _fall_words(fall), "colour": "#ff9b8f"})
        if "path" in fall:
            scene.moments.append({"label": "The fall" if len(drawn) == 1 else f"{fall['rider']}'s fall",
                                  "t": fall["t_fail"]})
    if drawn:
        # the page's one fall marker and the loop's focus: the first; every fall is its rider's event
        first = drawn[0]
        scene.fall = {"track": names.index(first["rider"]), **{k: v for k, v in first.items()
                                                                if k not in ("path", "path_t", "land")}}
        scene.focus = first["t_fail"]
    elif pair is not None:
        scene.focus = pair["t"]
    return scene


def _segments(result, name: str) -> tuple:
    """The rider's envelope's segments by the names of their ends (a
    single-contact machine's one, contact to head; a two-wheeler's several)."""
    lanes = getattr(result, "lanes", None) or []
    return next((tuple(lane.segments) for lane in lanes if lane.name == name), (("contact", "head"),))


def _rider_draw(track: Track, in_pair: bool, pair: dict | None, near: float,
                segments=(("contact", "head"),)) -> list:
    """A rider: his envelope, a capsule per segment (a single-contact
    machine's from the contact to the head; a two-wheeler's from its
    contacts, head and wheels), and his name; the pair of least clearance
    ringed, red around its moment."""
    out = []
    for ends in segments:
        capsule = {"kind": "capsule", "name": track.name, "points": list(ends),
                   "radius": track.meta["radius"], "colour": track.meta["colour"], "print": track.meta["colour"]}
        if in_pair:
            capsule.update({"halo": "rgba(255,59,48,0.55)", "highlight": {"colour": _PAIR, "from": pair["t"] - near,
                                                                           "until": pair["t"] + near}})
        out.append(capsule)
    return out + [{"kind": "label", "name": track.name, "point": "head", "text": track.name}]


def _add_fall(track: Track, fall: dict) -> None:
    """The fall on its rider's track: its outcome, and where he falls the
    path from contact lost to the landing point (the envelope gives way to
    his centre of mass on it), the landing marked from the landing on."""
    track.status = fall["outcome"]
    track.event_time = fall["t_fail"]
    track.event_point = "head"
    if "path" not in fall:
        return
    track.paths["fall"] = (fall["path_t"], fall["path"])
    for item in track.draw:
        item["until"] = fall["t_lost"]
    radius = track.meta["radius"]
    track.draw += [{"kind": "path", "name": track.name, "path": "fall", "whole": True, "colour": "rgba(255,107,91,0.9)",
                    "print": _FALL, "width": 2, "dash": [6, 4], "from": fall["t_lost"]},
                   {"kind": "dot", "name": track.name, "path": "fall", "radius": radius, "min_px": 2,
                    "colour": _FALL, "print": _FALL, "from": fall["t_lost"]},
                   {"kind": "label", "name": track.name, "path": "fall", "text": track.name, "from": fall["t_lost"]},
                   {"kind": "cross", "name": track.name, "path": "fall", "colour": _FALL, "print": _FALL,
                    "from": fall["t_land"]}]


def _fall_words(fall: dict) -> str:
    words = (f"{fall['rider']} drops to {math.floor(100 * fall['fraction'] + 0.5)} % of the speed at t = {fall['t_fail']:.3f} s: "
             + fall["outcome"].replace("_", " "))
    if "path" in fall:
        words += (f"; leaves the wall at t = {fall['t_lost']:.3f} s, lands at t = {fall['t_land']:.3f} s at "
                  f"{3.6 * fall['impact']:.1f} km/h"
                  + (f"; falls into {', '.join(fall['hits'])}" if fall["hits"] else "; hits no one"))
    return words + "."


def _widths(result, names) -> list:
    """Each rider's width [m] (the riders table's, else his lane's)."""
    riders = result.riders
    if "width_m" in riders.names:
        return [float(w) for w in riders["width_m"]]
    lanes = {lane.name: lane for lane in result.lanes}
    return [float(lanes[name].width_m) for name in names]


def _wall(result, probe: dict) -> dict | None:
    """The drum or the cone of an ``[arena]`` plan as the scene draws it
    (None on the globe): its meridian from the floor's centre out along the
    floor and up the wall to its top (without a top, a little above the
    highest head), the radius ``r`` the frames' step is measured in (the
    widest of the meridian), the camera's target and extent, and the words
    of the title."""
    ground = result.plan.globe.ground
    if result.plan.globe.is_globe:
        return None
    drawn = wall_ground(ground, max(float(np.max(p["head"][2])) for p in probe.values()) + 0.5)
    rho, z = np.asarray(drawn["rho"]), np.asarray(drawn["z"])
    r = float(np.max(rho))
    return {"ground": drawn, "r": r, "target": [0.0, 0.0, 0.5 * float(z[-1] + z[0])],
            "extent": 1.05 * max(r, 0.5 * float(z[-1] - z[0])),
            # its widest: a drum's diameter, a cone's or a bowl's rim (a dome's floor may be a point)
            "what": f"on a {ground.name} {2 * r:.2f} m across"}


def _title(n: int, r: float, t_end: float, pair: dict | None, where: str | None = None) -> str:
    words = f"{n} riders {where or f'in a globe of {2 * r:.2f} m'}, an act of {t_end:.2f} s"
    if pair is not None:
        words += (f"; least clearance {pair['a']} \u2013 {pair['b']} {pair['clearance']:.3f} m "
                  f"at t = {pair['t']:.3f} s ({pair['verdict']})")
    return words
