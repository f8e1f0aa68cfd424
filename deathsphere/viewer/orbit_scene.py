"""The scene of a simulated orbit (beyond the paper; docs/simulation.md,
"3-D view"): the paper's wheel or ball, or the single-contact machine, in
the globe, from the frame geometry of
:func:`deathsphere.simulation.frames.body_frames` (placed so that nothing
aliases between frames), the readouts' numbers at every frame, the trail
and the events.

Nothing here is physics: every number is the simulation's (its frames or
its time series), picked, interpolated between rows or converted in unit.
"""

from __future__ import annotations

import math

import numpy as np

from deathsphere.table import Table
from deathsphere.viewer.scene import (EVENT_STATUSES, Readout, Scene, Track, frame_indices, plane_ground, sphere_ground,
                                      wall_ground)

__all__ = ["build_scene", "MAX_FRAMES", "TRAIL_POINTS", "PANEL_COLUMNS", "CAMERA"]

#: at most this many frames per body are kept, the last ones (~170 bytes a
#: frame in the page: bounds its size under 10 MB)
MAX_FRAMES = 40_000
#: at most this many points of the contact point's trail (from t = 0)
TRAIL_POINTS = 6000
#: readout read from the time series (interpolated between rows to the
#: frames; the other readouts are the frames' own)
PANEL_COLUMNS = {"theta": "theta_deg", "alpha": "alpha_deg"}
#: (elevation, azimuth) [deg] of the camera: vertical orbits lie in a plane
#: normal to lab x, seen nearly face on; horizontal ones from a little
#: above the equator
CAMERA = {"horizontal": (24.0, -62.0), "vertical": (14.0, 25.0)}
#: the frame vectors a track carries
POINT_KEYS = ("centre", "axis", "e3", "contact", "normal_force", "friction_force", "com", "head")
#: arrow length per g of force per unit mass, in units of r
FORCE_SCALE_R_PER_G = 0.1


def _float(x):
    x = float(x)
    return x if math.isfinite(x) else None


def _panel(geo: dict, theta, alpha, mu_available, height=None) -> list:
    """The readouts: the frames' own numbers, a machine's speed its centre
    of mass's (ride's v_cm), theta (off the globe the contact's height)
    and alpha from the time series."""
    lane = (Readout("theta", "\u03b8 / \u03b1", "\u00b0", 2, theta, loop=False) if height is None
            else Readout("height", "height / \u03b1", " m", 2, height, loop=False))
    speed = geo.get("rider_speed", geo["speed"])
    return [Readout("speed", "speed", " m/s", 2, speed),
            Readout("speed_km_h", "", " km/h", 1, 3.6 * speed if "rider_speed" in geo else geo["speed_km_h"],
                    loop_join=" = "),
            Readout("load_g", "load", " g", 2, geo["load_g"]),
            Readout("mu", "\u03bc needed", "", 3, geo["mu_required"]),
            Readout("mu_available", "\u03bc available", "", 3, value=mu_available, none_text="no limit",
                    loop_join=", "),
            Readout("force_angle", "force \u2220 normal", "\u00b0", 1, geo["force_angle_deg"]),
            lane,
            Readout("alpha", "\u03b1", "\u00b0", 2, alpha, join=" / ", loop=False),
            Readout("normal", "N", " m/s\u00b2", 2, geo["normal"], note=True, loop=False),
            Readout("friction", "F_f", " m/s\u00b2", 2, geo["friction_magnitude"], note=True, loop=False)]


#: How each word of the summary's ``body`` column is drawn (the run's table
#: read as data; any other body, a machine, rolls on a wheel): its drawing
#: item's kind and fields but the radius, its legend and its name in the title.
DRAWN = {
    "sphere": ({"kind": "ball", "name": "ball", "centre": "centre", "marker": "axis"},
               "ball, red seam and marker", "ball"),
}
WHEEL_DRAWN = ({"kind": "wheel", "name": "wheel", "centre": "centre", "axis": "axis", "e3": "e3", "spin": "spin"},
               "wheel, red: the marked spoke", None)


def _drawn(body: str) -> tuple:
    return DRAWN.get(body, WHEEL_DRAWN)


def _draw(body: str, machine: bool, a: float, r: float, g: float) -> list:
    """The body's items: the wheel (or ball), a machine's frame and rider,
    the trail, the force arrows (colours: the page's, on its dark
    background; ``print``: the loop's, on white)."""
    items = [{**_drawn(body)[0], "radius": a}]
    if machine:
        # a line from the contact through the hub up to the head, the
        # centre of mass a dot on it, the head a ring
        items += [{"kind": "chain", "name": "rider", "points": ["contact", "centre", "head"], "colour": "#c77dff",
                   "print": "#8e44ad", "width": 5},
                  {"kind": "dot", "name": "rider", "point": "com", "radius": 0.3 * a, "min_px": 5,
                   "colour": "#ff4dd2", "print": "#e91e9c", "edge": "#1a1a1a"},
                  {"kind": "dot", "name": "head", "point": "head", "radius": 0.45 * a, "min_px": 7,
                   "colour": "rgba(255,255,255,0.85)", "print": "#ffffff", "edge": "#c77dff", "print_edge": "#8e44ad"}]
    scale = FORCE_SCALE_R_PER_G * r / g
    items += [{"kind": "path", "name": "trail", "path": "trail", "to": "contact", "colour": "#5fd3ff",
               "print": "#1f9bd1", "width": 3, "fade": True},
              {"kind": "arrow", "name": "forces", "point": "contact", "vector": "normal_force", "scale": scale,
               "colour": "#7cff7c", "print": "#1e8449", "width": 4, "toggle": "forces"},
              {"kind": "arrow", "name": "forces", "point": "contact", "vector": "friction_force", "scale": scale,
               "colour": "#ff9f1c", "print": "#e67e22", "width": 4, "toggle": "forces"}]
    return items


def _legend(body: str, machine: bool) -> list:
    rows = [{"colour": "#e8c547", "text": _drawn(body)[1]}]
    if machine:
        rows.append({"colour": "#c77dff", "text": "frame and rider: contact, hub, head; pink: centre of mass"})
    return rows + [{"colour": "#5fd3ff", "text": "trail of the contact point"},
                   {"colour": "#7cff7c", "text": "normal force N", "toggle": "forces"},
                   {"colour": "#ff9f1c", "text": "friction F_f (0.1 r per g)", "toggle": "forces"}]


def _title(meta: dict, title: str) -> str:
    what = f"{_drawn(meta['body'])[2] or meta['body']} {meta['side']} the sphere, {meta['orbit']} orbit"
    start = (f"\u03b8 = {meta['theta0_deg']:.1f}\u00b0" if meta["orbit"] == "vertical"
             else f"\u03b8\u2080 = {meta['theta0_deg']:.1f}\u00b0, \u03b1\u2080 = {meta['alpha0_deg']:.1f}\u00b0")
    return (f"{title}: " if title else "") + f"{what} ({start}, a = {meta['a']:g} m, r = {meta['r']:g} m)"


def _wall_title(meta: dict, title: str, ground) -> str:
    lane = "turn radius" if ground.name == "plane" else "height"
    at = meta["rho0"] if ground.name == "plane" else meta["height0"]
    where = "outside" if meta["side"] == "outside" else "on"
    return (f"{title}: " if title else "") + (
        f"{_drawn(meta['body'])[2] or meta['body']} {where} the {ground.name}, horizontal orbit ({lane} {at:.2f} m, "
        f"\u03b1\u2080 = {meta['alpha0_deg']:.1f}\u00b0, a = {meta['a']:g} m)")


def _wall_view(ground, series: Table, a: float) -> tuple:
    """(the ground as drawn, camera target, extent) of a run off the globe:
    a wall up to its top (an open one: twice the highest contact's height,
    and 4 a above it), flat ground the square the track covers."""
    rho = np.asarray(series["rho_contact_m"], dtype=np.float64)
    height = np.asarray(series["height_m"], dtype=np.float64)
    if not hasattr(ground, "highest_lane"):
        half = 1.2 * float(np.max(rho)) + 2 * a
        return plane_ground((0.0, 0.0), half), [0.0, 0.0, a], half
    drawn = wall_ground(ground, max(2.0 * float(np.max(height)), float(np.max(height)) + 4 * a))
    r, z = float(np.max(drawn["rho"])), np.asarray(drawn["z"])
    return drawn, [0.0, 0.0, 0.5 * float(z[-1] + z[0])], 1.05 * max(r, 0.5 * float(z[-1] - z[0]))


def build_scene(series: Table, summary: Table, frames: dict, *, title: str = "",
                max_frames: int = MAX_FRAMES, ground=None) -> Scene:
    """The scene of a run: one track per summary row (a body that could not
    start, status no_fit / no_orbit, has zero frames).

    Parameters
    ----------
    series, summary : the run's Tables (:data:`deathsphere.simulation.SERIES_COLUMNS`,
        :data:`deathsphere.simulation.SUMMARY_COLUMNS`)
    frames : :meth:`deathsphere.simulation.Simulation.view_frames`: per
        ``input_row``, the frame times ``t`` (the body's rows of ``series``
        and the frames placed between them) and the geometry at them
    title : put before the run's own words
    max_frames : frames kept per body, the last ones (the event is the
        last); the trail still goes back to t = 0
    ground : the ground record of a run off the globe (None: the globe
        of the summary's r): a wall drawn from its meridian, flat ground
        as a square
    """
    rows = np.asarray(series["input_row"])
    tracks = []
    for i, row in enumerate(np.asarray(summary["input_row"])):
        sel = np.flatnonzero(rows == row)
        t_rows = np.asarray(series["t_s"], dtype=np.float64)[sel]
        geo = frames.get(int(row))
        if sel.size and (geo is None or geo["t"][0] != t_rows[0] or geo["t"][-1] != t_rows[-1]
                         or np.any(np.diff(geo["t"]) <= 0)):
            raise ValueError("frames do not span the time series' rows of their body")
        status = str(summary["status"][i])
        ev = _float(summary["event_time_s"][i]) if status in EVENT_STATUSES else None
        if ev is not None and sel.size:
            # the event is the run's last row: shown at the last frame,
            # whatever the rounding of the times
            ev = float(t_rows[-1])
        meta = {"input_row": int(row), "body": str(summary["body"][i]), "side": str(summary["side"][i]),
                "orbit": str(summary["orbit"][i]), "a": float(summary["a_m"][i]), "r": float(summary["r_m"][i]),
                "g": float(summary["g_m_s2"][i]), "theta0_deg": float(summary["theta_deg"][i]),
                "alpha0_deg": float(summary["alpha_deg"][i]), "period": _float(summary["period_s"][i]),
                "mu_available": _float(summary["mu_available"][i]) if "mu_available" in summary.names else None}
        if ground is not None:
            # no polar angle off the globe: the lane is its height
            meta.update(theta0_deg=None, height0=float(summary["height_m"][i]), rho0=float(summary["r_m"][i]))
        track = Track(name=meta["body"], t=np.zeros(0), status=status, reason=str(summary["reason"][i]),
                      event_time=ev, event_point="contact", meta=meta)
        if sel.size:
            keep = slice(max(0, geo["t"].size - max_frames), None)
            track.t = geo["t"][keep]
            now = {k: np.asarray(v)[..., keep] for k, v in geo.items() if k not in ("t", "sample", "bounds")}
            track.points = {k: now[k] for k in POINT_KEYS if k in now}
            track.scalars = {"spin": now["spin"]}
            track.motion = {"rate": now["rate"], "speed": now["speed"], "bounds": tuple(geo["bounds"])}
            theta, alpha = (np.interp(track.t, t_rows, np.asarray(series[col], dtype=np.float64)[sel])
                            for col in PANEL_COLUMNS.values())
            height = (None if ground is None else
                      np.interp(track.t, t_rows, np.asarray(series["height_m"], dtype=np.float64)[sel]))
            track.panel = _panel(now, theta, alpha, meta["mu_available"], height)
            track.note = "(per unit mass)"
            track.draw = _draw(meta["body"], "com" in now, meta["a"], meta["r"], meta["g"])
            on_row = np.isin(geo["t"], t_rows)
            trail_t, trail = geo["t"][on_row], geo["contact"][:, on_row]
            pick = frame_indices(trail_t.size, TRAIL_POINTS)
            track.paths = {"trail": (trail_t[pick], trail[:, pick])}
        tracks.append(track)
    first = tracks[0].meta
    r, a = first["r"], first["a"]
    extent = r + 2.2 * a if first["side"] == "outside" else 1.05 * r
    el, az = CAMERA.get(first["orbit"], CAMERA["horizontal"])
    if ground is None:
        drawn, target, words = sphere_ground(r), [0.0, 0.0, 0.0], _title(first, title)
    else:
        (drawn, target, extent), words = _wall_view(ground, series, a), _wall_title(first, title, ground)
    return Scene(ground=drawn, tracks=tracks, title=words,
                 camera={"az": az, "el": el, "target": target, "extent": extent},
                 follow={"track": 0, "target": "centre", "heading": None,
                         "size": max(8 * a, 0.45 * 1.25 * extent)},
                 legend=_legend(first["body"], "com" in tracks[0].points))
