"""The bodies of a simulated run, ready to draw: the frame geometry of
:func:`deathsphere.simulation.frames.body_frames` (placed so that nothing
aliases between frames), the readouts' numbers at every frame, the trail,
the events, and the playback factor (beyond the paper; docs/simulation.md,
"3-D view").  Shared by the HTML viewer and the GIF / MP4 loop.

Nothing here is physics: every number is the simulation's (its frames or
its time series), picked, interpolated between rows or converted in unit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from deathsphere.table import Table

__all__ = ["BodyScene", "build_scenes", "frame_indices", "playback_factor", "slow_motion_words",
           "MAX_FRAMES", "TRAIL_POINTS", "PLAYBACK_FACTORS", "PANEL_COLUMNS", "EVENT_STATUSES"]

#: at most this many frames per body are kept, the last ones (~170 bytes a
#: frame in the page: bounds its size under 10 MB)
MAX_FRAMES = 40_000
#: at most this many points of the contact point's trail (from t = 0)
TRAIL_POINTS = 6000
#: the playback factors offered (simulated seconds per second shown), from
#: real time down: a fast run plays at the largest that does not alias
PLAYBACK_FACTORS = (10.0, 5.0, 2.0, 1.0) + tuple(
    1.0 / (m * 10.0 ** e) for e in range(4) for m in (1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10) if m * 10 ** e > 1)
#: statuses that end a run at an event of the simulation
EVENT_STATUSES = ("contact_lost", "slips", "failed")

#: readout read from the time series (interpolated between rows to the
#: frames; the other readouts are the frames' own)
PANEL_COLUMNS = {"theta": "theta_deg", "alpha": "alpha_deg"}
#: readout -> frame-geometry key it is
FRAME_PANEL = {"speed": "speed", "speed_km_h": "speed_km_h", "g_load": "g_load", "mu": "mu_required", "normal": "normal",
               "friction": "friction_magnitude", "force_angle": "force_angle_deg"}


@dataclass
class BodyScene:
    """One body of the run: its description, and arrays at its F frames
    (``t`` (F,), vectors (3, F), readouts (F,)).  ``geometry`` holds the
    keys of :func:`deathsphere.simulation.frames.frame_geometry`; ``panel``
    the readouts (:data:`PANEL_COLUMNS`, :data:`FRAME_PANEL`); ``trail``
    (3, T) the contact point at the time series' rows (at most
    :data:`TRAIL_POINTS`) with their times ``trail_t``; ``bounds`` the
    most turn [rad] and centre step [r] allowed between frames (the
    simulation's, handed over with its frames)."""

    input_row: int
    body: str
    side: str
    orbit: str
    a: float
    r: float
    g: float
    theta0_deg: float
    alpha0_deg: float
    period: float
    status: str
    reason: str
    event_time: float | None
    mu_available: float | None
    t: np.ndarray
    geometry: dict = field(default_factory=dict)
    panel: dict = field(default_factory=dict)
    trail_t: np.ndarray = field(default_factory=lambda: np.zeros(0))
    trail: np.ndarray = field(default_factory=lambda: np.zeros((3, 0)))
    bounds: tuple = (0.5 * math.pi, 0.02)

    @property
    def n_frames(self) -> int:
        return int(self.t.size)

    @property
    def event_words(self) -> str:
        """'contact lost', 'slips', 'failed' ('' without an event)."""
        return self.status.replace("_", " ") if self.event_time is not None else ""


def frame_indices(n: int, max_points: int) -> np.ndarray:
    """Indices of at most ``max_points`` (+1) of n points, evenly strided,
    always with the first and the last."""
    if n <= max_points:
        return np.arange(n)
    step = math.ceil((n - 1) / (max_points - 1))
    idx = np.arange(0, n, step)
    return idx if idx[-1] == n - 1 else np.append(idx, n - 1)


def _float(x):
    x = float(x)
    return x if math.isfinite(x) else None


def playback_factor(scenes: list[BodyScene], frame_interval: float, t_from: float = -math.inf) -> float:
    """The largest of :data:`PLAYBACK_FACTORS`, at most 1 (real time), at
    which frames ``frame_interval`` [s] apart on screen show every body
    turning at most a quarter turn and its centre moving at most 2 % of r
    from one to the next, over the frames from ``t_from`` on: the fastest
    rotation |w| and centre speed of the simulation's frames decide."""
    need = 1.0
    for s in scenes:
        keep = s.t >= t_from
        if s.n_frames < 2 or not keep.any():
            continue
        rate = np.nanmax(s.geometry["rate"][keep])
        speed = np.nanmax(s.geometry["speed"][keep])
        with np.errstate(divide="ignore"):
            turn, move = s.bounds
            need = min(need, turn / (rate * frame_interval), move * s.r / (speed * frame_interval))
    return max([f for f in PLAYBACK_FACTORS if f <= need], default=PLAYBACK_FACTORS[-1])


def slow_motion_words(factor_: float) -> str:
    """'real time', 'slow motion x4', '2x real time'."""
    if abs(factor_ - 1.0) < 1e-12:
        return "real time"
    if factor_ < 1.0:
        return f"slow motion \u00d7{1 / factor_:g}"
    return f"{factor_:g}\u00d7 real time"


def build_scenes(series: Table, summary: Table, frames: dict, *, max_frames: int = MAX_FRAMES) -> list[BodyScene]:
    """One :class:`BodyScene` per summary row (a body that could not start,
    status no_fit / no_orbit, has zero frames).

    Parameters
    ----------
    series, summary : the run's Tables (:data:`deathsphere.simulation.SERIES_COLUMNS`,
        :data:`deathsphere.simulation.SUMMARY_COLUMNS`)
    frames : :meth:`deathsphere.simulation.Simulation.view_frames`: per
        ``input_row``, the frame times ``t`` (the body's rows of ``series``
        and the frames placed between them) and the geometry at them
    max_frames : frames kept per body, the last ones (the event is the
        last); the trail still goes back to t = 0
    """
    rows = np.asarray(series["input_row"])
    scenes = []
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
        mu_av = _float(summary["mu_available"][i]) if "mu_available" in summary.names else None
        scene = BodyScene(
            input_row=int(row), body=str(summary["body"][i]), side=str(summary["side"][i]),
            orbit=str(summary["orbit"][i]), a=float(summary["a_m"][i]), r=float(summary["r_m"][i]),
            g=float(summary["g_m_s2"][i]),
            theta0_deg=float(summary["theta_deg"][i]), alpha0_deg=float(summary["alpha_deg"][i]),
            period=float(summary["period_s"][i]), status=status, reason=str(summary["reason"][i]),
            event_time=ev, mu_available=mu_av, t=np.zeros(0))
        if sel.size:
            keep = slice(max(0, geo["t"].size - max_frames), None)
            scene.t = geo["t"][keep]
            scene.bounds = tuple(geo["bounds"])
            scene.geometry = {k: np.asarray(v)[..., keep] for k, v in geo.items()
                              if k not in ("t", "sample", "bounds")}
            scene.panel = {k: np.interp(scene.t, t_rows, np.asarray(series[col], dtype=np.float64)[sel])
                           for k, col in PANEL_COLUMNS.items()}
            scene.panel.update({k: scene.geometry[key] for k, key in FRAME_PANEL.items()})
            if "rider_speed" in scene.geometry:  # a machine reads out its centre of mass's speed (ride's v_cm)
                v = scene.geometry["rider_speed"]
                scene.panel.update({"speed": v, "speed_km_h": v * 3.6})
            on_row = np.isin(geo["t"], t_rows)
            trail_t, trail = geo["t"][on_row], geo["contact"][:, on_row]
            pick = frame_indices(trail_t.size, TRAIL_POINTS)
            scene.trail_t, scene.trail = trail_t[pick], trail[:, pick]
        scenes.append(scene)
    return scenes
