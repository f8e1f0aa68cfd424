"""A two-wheeler's run in 3-D (``deathsphere simulate --machine
benchmark-bicycle --steer free --output run.html|.gif|.mp4``;
docs/two-wheeler.md sec. 10.1): the globe (or, on flat ground, the
ground), both wheels' rims, the rear and front frames, the rider's head and
the contact points' paths.

Nothing here is physics: every point is the simulation's
(:func:`deathsphere.api.two_wheelers.simulate_two_wheeler` with ``view``:
the points of the physics core's ``geometry.outline`` at every row of the
series), every readout a column of its series.  The view only turns the
core's axes (z down, the benchmark's) to its own (z up) and keeps at most
:data:`MAX_FRAMES` of the rows.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from deathsphere.table import Table
from deathsphere.viewer.html import _encode, decode_array
from deathsphere.viewer.scene import EVENT_STATUSES, frame_indices
from deathsphere.writers.atomic import atomic_file

__all__ = ["TwoWheelerScene", "two_wheeler_scene", "two_wheeler_data", "render_two_wheeler_html",
           "write_two_wheeler_view", "decode_rim", "POINT_KEYS", "RIM_KEYS", "PANEL_COLUMNS", "MAX_FRAMES",
           "PLAYBACK", "DATA_MARK"]

#: where the template takes the data (a JavaScript expression)
DATA_MARK = "/*__DEATHSPHERE_TWO_WHEELER__*/null"
#: the points drawn at every frame, (3, F) each
POINT_KEYS = ("P", "Q", "rear_wheel", "front_wheel", "rear_frame", "front_frame", "head", "steer_bottom",
              "steer_top", "bar_left", "bar_right")
#: the rims, (3, points on the rim, F) each, from the wheel's contact
RIM_KEYS = ("rear_rim", "front_rim")
#: readout -> the series' column it shows
PANEL_COLUMNS = {"lean": "lean_surface_deg", "steer": "steer_deg", "theta": "theta_rear_deg",
                 "speed": "v_rear_m_s", "torque": "steer_torque_n_m", "normal_rear": "normal_rear_per_mass_m_s2",
                 "normal_front": "normal_front_per_mass_m_s2"}
#: at most this many frames (rows of the series, evenly strided; ~1 kB a
#: frame in the page, so it stays under 5 MB)
MAX_FRAMES = 4000
#: simulated seconds per second shown, as the page and the loop start:
#: slow enough to see the steer move at a stunt's speed
PLAYBACK = 0.5
#: the core's axes have z down (the benchmark's), the view's z up: turned
#: half a turn about x, a rotation, so the bicycle is not mirrored
_UP = np.array([1.0, -1.0, -1.0])


@dataclass
class TwoWheelerScene:
    """What the view draws: the globe's radius ``r`` [m] (on ``flat``
    ground: the half-width of the run's ground, what the camera frames),
    frame times ``t`` (F,), the points (:data:`POINT_KEYS`, (3, F)) and rims
    (:data:`RIM_KEYS`, (3, K, F)) in the view's axes (origin the globe's
    centre or the ground's origin, z up), the readouts
    (:data:`PANEL_COLUMNS`, (F,)), how the run ended, a title and the
    playback factor the page and the loop start at."""

    r: float
    t: np.ndarray
    points: dict = field(default_factory=dict)
    panel: dict = field(default_factory=dict)
    status: str = "completed"
    event_time: float | None = None
    title: str = ""
    playback: float = PLAYBACK
    flat: bool = False

    @property
    def event_words(self) -> str:
        """'contact lost', 'slips', 'failed' ('' without an event)."""
        return self.status.replace("_", " ") if self.event_time is not None else ""


def _flat(summary: Table) -> bool:
    return "surface" in summary.columns and str(summary["surface"][0]) == "flat"


def _title(summary: Table) -> str:
    row = summary[0]
    if not _flat(summary):
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


def two_wheeler_scene(series: Table, summary: Table, frames: dict, *, max_frames: int = MAX_FRAMES) -> TwoWheelerScene:
    """The scene of a run: ``series`` and ``summary`` as
    :func:`~deathsphere.api.two_wheelers.simulate_two_wheeler` returns them,
    ``frames`` its third item (``view=True``): ``t`` and the points at the
    series' rows."""
    t = np.asarray(frames["t"], dtype=np.float64)
    if t.size != len(series) or not np.array_equal(t, np.asarray(series["t_s"], dtype=np.float64)):
        raise ValueError("the frames are not at the series' rows")
    keep = frame_indices(t.size, max_frames)
    points = {k: _UP[:, None] * np.asarray(frames[k])[:, keep] for k in POINT_KEYS}
    points.update({k: _UP[:, None, None] * np.asarray(frames[k])[..., keep] for k in RIM_KEYS})
    status = str(summary["status"][0])
    event = float(t[-1]) if status in EVENT_STATUSES and math.isfinite(float(summary["t_event_s"][0])) else None
    flat = _flat(summary)
    return TwoWheelerScene(r=_ground(points) if flat else float(summary["r_m"][0]), t=t[keep], points=points,
                           panel={k: np.asarray(series[c], dtype=np.float64)[keep] for k, c in PANEL_COLUMNS.items()},
                           status=status, event_time=event, title=_title(summary), flat=flat)


def _ground(points: dict) -> float:
    """Half the width of the ground a run on flat ground covers [m]: the
    contacts' paths and the bicycle's size, at least 2 m."""
    paths = np.concatenate([points["P"][:2], points["Q"][:2]], axis=1)
    size = float(np.max(np.linalg.norm(points["head"] - points["P"], axis=0)))
    return max(0.5 * float(np.max(np.ptp(paths, axis=1))) + size, 2.0)


def two_wheeler_data(scene: TwoWheelerScene) -> dict:
    """The JSON-able data the page reads: points frame-major (x, y, z per
    frame), rims frame-major then rim point; float32, times float64."""
    rims = {k: _encode(np.transpose(scene.points[k], (2, 1, 0))) for k in RIM_KEYS}
    return {"format": "deathsphere-two-wheeler/1", "title": scene.title, "r": scene.r, "n": int(scene.t.size),
            "rim": int(scene.points[RIM_KEYS[0]].shape[1]), "t": _encode(scene.t, "<f8"),
            "points": {k: _encode(scene.points[k].T) for k in POINT_KEYS}, "rims": rims,
            "panel": {k: _encode(v) for k, v in scene.panel.items()}, "status": scene.status,
            "event_time": scene.event_time, "event_words": scene.event_words, "playback": scene.playback,
            "flat": scene.flat}


def decode_rim(text: str, n_rim: int) -> np.ndarray:
    """A rim of the page's data back as (3, K, F)."""
    return np.transpose(decode_array(text).reshape(-1, n_rim, 3), (2, 1, 0))


def render_two_wheeler_html(scene: TwoWheelerScene) -> str:
    """The page's text (UTF-8): the template with the run's data."""
    from deathsphere.viewer.html import filled_template

    return filled_template("two_wheeler_template.html", DATA_MARK, two_wheeler_data(scene), "two-wheeler view's")


def write_two_wheeler_view(output, series: Table, summary: Table, frames: dict, *, progress=None) -> int:
    """Write the run's view to ``output`` (.html, .gif or .mp4 by its
    extension), whole or not at all; returns the file's size in bytes.
    ``progress(k, n)`` after each frame of a loop."""
    from deathsphere.viewer import check_view_output

    fmt = check_view_output(output)
    scene = two_wheeler_scene(series, summary, frames)
    if fmt == "html":
        data = render_two_wheeler_html(scene).encode("utf-8")
        with atomic_file(output, "wb") as out:
            out.write(data)
        return len(data)
    from deathsphere.viewer.two_wheeler_animation import write_two_wheeler_animation

    write_two_wheeler_animation(output, scene, progress=progress)
    return Path(output).stat().st_size
