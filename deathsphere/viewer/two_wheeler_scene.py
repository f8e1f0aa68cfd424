"""The scene of a two-wheeler's run (``deathsphere simulate --machine
benchmark-bicycle --steer free --output run.html|.gif|.mp4``;
docs/two-wheeler.md sec. 10.1 and 12.7): the globe (on flat ground, the
ground; on a drum, a cone or a profile, its wall drawn from its meridian,
as the paper's bodies' and the show's views draw it), both wheels' rims,
the rear and front frames, the rider's head and the contact points' paths.

Nothing here is physics: every point is the simulation's
(:func:`deathsphere.api.two_wheelers.simulate_two_wheeler` with ``view``:
the points of the physics core's ``geometry.outline`` at every row of the
series), every readout a column of its series.  The view only turns the
core's axes (z down, the benchmark's) to its own (z up) and keeps at most
:data:`MAX_FRAMES` of the rows.
"""

from __future__ import annotations

import math

import numpy as np

from deathsphere.table import Table
from deathsphere.viewer.html import decode_array
from deathsphere.viewer.scene import (EVENT_STATUSES, Readout, Scene, Track, frame_indices, plane_ground, sphere_ground,
                                      wall_ground)

__all__ = ["two_wheeler_scene", "decode_rim", "POINT_KEYS", "RIM_KEYS", "PANEL_COLUMNS", "MAX_FRAMES", "PLAYBACK"]

#: the points drawn at every frame, (3, F) each
POINT_KEYS = ("P", "Q", "rear_wheel", "front_wheel", "rear_frame", "front_frame", "head", "steer_bottom",
              "steer_top", "bar_left", "bar_right")
#: the rims, (3, points on the rim, F) each, from the wheel's contact
RIM_KEYS = ("rear_rim", "front_rim")
#: readout -> the series' column it shows
PANEL_COLUMNS = {"lean": "lean_surface_deg", "steer": "steer_deg", "theta": "theta_rear_deg",
                 "speed": "v_rear_m_s", "torque": "steer_torque_n_m", "normal_rear": "normal_rear_per_mass_m_s2",
                 "normal_front": "normal_front_per_mass_m_s2"}
#: label and unit of each readout; theta only in a globe
_READOUTS = {"lean": ("lean", "\u00b0"), "steer": ("steer", "\u00b0"), "theta": ("\u03b8 (rear)", "\u00b0"),
             "speed": ("speed (rear)", " m/s"), "torque": ("steer torque", " N m"),
             "normal_rear": ("normal, rear", " m/s\u00b2"), "normal_front": ("normal, front", " m/s\u00b2")}
#: at most this many frames (rows of the series, evenly strided; ~1 kB a
#: frame in the page, so it stays under 5 MB)
MAX_FRAMES = 4000
#: simulated seconds per second shown, as the page and the loop start:
#: slow enough to see the steer move at a stunt's speed
PLAYBACK = 0.5
#: the core's axes have z down (the benchmark's), the view's z up: turned
#: half a turn about x, a rotation, so the bicycle is not mirrored
_UP = np.array([1.0, -1.0, -1.0])
#: (elevation, azimuth) [deg]: looking down into the globe, the wheels, in
#: planes nearly along the wall, show as wheels rather than as edges; and
#: riding along, from the bicycle's right rear and above
CAMERA = (58.0, -62.0)
FOLLOW = (50.0, -30.0)
_FOLLOW_SCALE = math.cos(math.radians(19.0)) / 1.4

#: the bicycle's pieces: rims, the frames as chains of their points, hubs,
#: seat, head and contacts (page colours; ``print``: the loop's on white)
DRAW = (
    [{"kind": "path", "name": "paths", "point": "P", "colour": "rgba(95,211,255,0.9)", "print": "#1f9bd1", "width": 2.5},
     {"kind": "path", "name": "paths", "point": "Q", "colour": "rgba(124,255,124,0.9)", "print": "#1e8449",
      "width": 2.5}]
    + [{"kind": "ring", "name": k, "points": k, "colour": "#e8c547", "print": "#d4a017", "width": 3.5} for k in RIM_KEYS]
    + [{"kind": "chain", "name": "rear_frame", "points": ["rear_wheel", "steer_bottom", "steer_top", "rear_frame",
                                                          "rear_wheel"], "colour": "#c77dff", "print": "#8e44ad",
        "width": 4},
       {"kind": "chain", "name": "front_frame", "points": ["steer_top", "steer_bottom", "front_wheel"],
        "colour": "#ff9f1c", "print": "#e67e22", "width": 4},
       {"kind": "chain", "name": "front_frame", "points": ["bar_left", "steer_top", "bar_right"], "colour": "#ff9f1c",
        "print": "#e67e22", "width": 4},
       {"kind": "chain", "name": "rider", "points": ["rear_frame", "head"], "colour": "#f4f4f4", "print": "#555555",
        "width": 3}])


def _dots(wheel: float) -> list:
    """Hubs, seat, head and contacts, sized from the rear wheel's radius."""
    return [{"kind": "dot", "name": "rear_frame", "point": "rear_wheel", "radius": 0.08 * wheel, "min_px": 3,
             "colour": "#e8c547", "print": "#d4a017"},
            {"kind": "dot", "name": "front_frame", "point": "front_wheel", "radius": 0.08 * wheel, "min_px": 3,
             "colour": "#e8c547", "print": "#d4a017"},
            {"kind": "dot", "name": "rear_frame", "point": "rear_frame", "radius": 0.1 * wheel, "min_px": 3,
             "colour": "#c77dff", "print": "#8e44ad"},
            {"kind": "dot", "name": "head", "point": "head", "radius": 0.33 * wheel, "min_px": 3,
             "colour": "rgba(244,244,244,0.9)", "print": "#ffffff", "edge": "#c77dff", "print_edge": "#8e44ad"},
            {"kind": "dot", "name": "contacts", "point": "P", "radius": 0.06 * wheel, "min_px": 3,
             "colour": "#5fd3ff", "print": "#1f9bd1"},
            {"kind": "dot", "name": "contacts", "point": "Q", "radius": 0.06 * wheel, "min_px": 3,
             "colour": "#7cff7c", "print": "#1e8449"}]


LEGEND = [{"colour": "#e8c547", "text": "wheels (rims), hubs"},
          {"colour": "#c77dff", "text": "rear frame: axle, head tube, seat (its mass centre)"},
          {"colour": "#ff9f1c", "text": "front frame: handlebar, steer axis, fork to the axle"},
          {"colour": "#f4f4f4", "text": "rider: seat to head"},
          {"colour": "#5fd3ff", "text": "rear contact's path"},
          {"colour": "#7cff7c", "text": "front contact's path"}]


def _flat(summary: Table) -> bool:
    """Whether the run is on flat ground: the summary's surface column is
    the only place that says so; the scene's ground says it from here on."""
    return "surface" in summary.columns and str(summary["surface"][0]) == "flat"


def _wall(frames: dict):
    """The wall ridden (a ground record with lanes up to a highest one: a drum, a cone, a profile), or None on
    the globe and flat ground."""
    ground = frames.get("ground")
    return ground if hasattr(ground, "highest_lane") else None


def _title(summary: Table, flat: bool, wall=None) -> str:
    row = summary[0]
    if wall is not None:
        words = (f"{row['machine']}: simulated from its steady turn {row['height_m']:.3g} m up the {wall.name}, "
                 f"{row['v_rear_m_s']:.3g} m/s")
    elif not flat:
        words = (f"{row['machine']}: simulated from its steady turn at \u03b8 = {row['theta_deg']:.1f}\u00b0, "
                 f"{row['v_rear_m_s']:.3g} m/s, in a globe of {2 * row['r_m']:.3g} m")
    elif math.isfinite(float(summary["turn_radius_m"][0])):
        words = (f"{row['machine']}: simulated on flat ground from its steady turn of radius "
                 f"{row['turn_radius_m']:.3g} m at {row['v_rear_m_s']:.3g} m/s")
    else:
        words = f"{row['machine']}: simulated on flat ground from upright straight running at {row['v_rear_m_s']:.3g} m/s"
    control = {"rider": f"a rider's gains {row['k_lean_n_m_rad']:g}, {row['k_rate_n_m_s_rad']:g}",
               "hands-free": "hands free"}.get(row["control"], "the steady steer torque held")
    kick = f"kicked {row['perturb_deg']:g}\u00b0 in lean" if row["perturb_deg"] else "not kicked"
    return f"{words}; {kick}, {control}"


def two_wheeler_scene(series: Table, summary: Table, frames: dict, *, max_frames: int = MAX_FRAMES) -> Scene:
    """The scene of a run: ``series`` and ``summary`` as
    :func:`~deathsphere.api.two_wheelers.simulate_two_wheeler` returns them,
    ``frames`` its third item (``view=True``): ``t`` and the points at the
    series' rows, and the ``ground`` record (a wall is drawn from it)."""
    t = np.asarray(frames["t"], dtype=np.float64)
    if t.size != len(series) or not np.array_equal(t, np.asarray(series["t_s"], dtype=np.float64)):
        raise ValueError("the frames are not at the series' rows")
    keep = frame_indices(t.size, max_frames)
    points = {k: _UP[:, None] * np.asarray(frames[k])[:, keep] for k in POINT_KEYS}
    points.update({k: _UP[:, None, None] * np.asarray(frames[k])[..., keep] for k in RIM_KEYS})
    status = str(summary["status"][0])
    event = float(t[-1]) if status in EVENT_STATUSES and math.isfinite(float(summary["t_event_s"][0])) else None
    flat, wall = _flat(summary), _wall(frames)
    panel = [Readout(k, *_READOUTS[k], 2, np.asarray(series[c], dtype=np.float64)[keep],
                     loop=k in ("lean", "steer"))
             for k, c in PANEL_COLUMNS.items() if not ((flat or wall is not None) and k == "theta")]
    wheel = float(np.linalg.norm(points["P"][:, 0] - points["rear_wheel"][:, 0]))
    track = Track(name=str(summary["machine"][0]), t=t[keep], points=points, draw=list(DRAW) + _dots(wheel),
                  panel=panel, status=status, event_time=event, event_point="P",
                  note=("lean from the vertical" if flat else "lean from the wall's normal at the rear contact")
                  + "; normal forces per unit mass")
    target_z = 0.0
    if flat:
        centre, half = _ground(points)
        ground = plane_ground(centre, half)
    elif wall is not None:
        ground, centre, half, target_z = _wall_view(wall, points)
    else:
        ground = sphere_ground(float(summary["r_m"][0]))
        centre, half = (0.0, 0.0), float(summary["r_m"][0])
    size = max(_apart(points, "head", "P"), _apart(points, "Q", "P"))
    return Scene(ground=ground, tracks=[track], title=_title(summary, flat, wall), playback=PLAYBACK,
                 legend=list(LEGEND),
                 camera={"el": CAMERA[0], "az": CAMERA[1], "target": [centre[0], centre[1], target_z],
                         "extent": 0.96 * half},
                 follow={"track": 0, "target": "rear_frame", "heading": ["P", "Q"],
                         "size": _FOLLOW_SCALE * size, "el": FOLLOW[0], "az": FOLLOW[1]})


def _apart(points: dict, a: str, b: str) -> float:
    return float(np.linalg.norm(points[a][:, 0] - points[b][:, 0]))


def _wall_view(wall, points: dict) -> tuple:
    """(the wall as drawn, camera centre, half extent, camera height) of a run on a wall: up to its top (an
    open one: twice the head's highest height, at least 1 m above it), framed as the paper's bodies' views
    frame it."""
    top = float(np.max(points["head"][2]))
    drawn = wall_ground(wall, max(2.0 * top, top + 1.0))
    rho, z = np.asarray(drawn["rho"]), np.asarray(drawn["z"])
    return drawn, (0.0, 0.0), 1.05 * max(float(rho.max()), 0.5 * float(z[-1] - z[0])) / 0.96, 0.5 * float(
        z[-1] + z[0])


def _ground(points: dict) -> tuple:
    """The middle of the ground a run on flat ground covers and half its
    width [m]: the contacts' paths and the bicycle's size, at least 2 m."""
    paths = np.concatenate([points["P"][:2], points["Q"][:2]], axis=1)
    size = float(np.max(np.linalg.norm(points["head"] - points["P"], axis=0)))
    centre = 0.5 * (paths.min(axis=1) + paths.max(axis=1))
    return centre, max(0.5 * float(np.max(np.ptp(paths, axis=1))) + size, 2.0)


def decode_rim(text: str, n_rim: int) -> np.ndarray:
    """A rim of the page's data back as (3, K, F)."""
    return np.transpose(decode_array(text).reshape(-1, n_rim, 3), (2, 1, 0))
