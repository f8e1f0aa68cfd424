"""The bodies of a simulated run, ready to draw: frame geometry at a
bounded number of frames plus the panel's numbers (beyond the paper;
docs/simulation.md, "3-D view").  Shared by the HTML viewer and the GIF.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from deathsphere.table import Table

__all__ = ["BodyScene", "build_scenes", "frame_indices", "MAX_FRAMES", "PANEL_COLUMNS"]

#: at most this many frames per body are kept (a 20-period run at the
#: default 100 points per period has 2001): bounds the HTML file's size
MAX_FRAMES = 6000

#: panel quantity -> time-series column it is read from
PANEL_COLUMNS = {
    "theta": "theta_deg", "alpha": "alpha_deg", "speed": "speed_m_s",
    "normal": "normal_per_mass_m_s2", "friction": "friction_magnitude_per_mass_m_s2", "mu": "mu_required",
}


@dataclass
class BodyScene:
    """One body of the run: its description, and arrays at its F frames
    (``t`` (F,), vectors (3, F), panel scalars (F,)).  ``geometry`` holds
    the keys of :func:`deathsphere.simulation.frames.frame_geometry`;
    ``panel`` the keys of :data:`PANEL_COLUMNS` and ``g_load``."""

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
    t: np.ndarray
    geometry: dict = field(default_factory=dict)
    panel: dict = field(default_factory=dict)

    @property
    def n_frames(self) -> int:
        return int(self.t.size)


def frame_indices(n: int, max_frames: int = MAX_FRAMES) -> np.ndarray:
    """Indices of at most ``max_frames`` of n samples, evenly strided,
    always with the first and the last (an event is the last sample)."""
    if n <= max_frames:
        return np.arange(n)
    step = math.ceil((n - 1) / (max_frames - 1))
    idx = np.arange(0, n, step)
    return idx if idx[-1] == n - 1 else np.append(idx, n - 1)


def _float(x):
    x = float(x)
    return x if math.isfinite(x) else None


def build_scenes(series: Table, summary: Table, frames: dict, *, max_frames: int = MAX_FRAMES) -> list[BodyScene]:
    """One :class:`BodyScene` per summary row (a body that could not start,
    status no_fit / no_orbit, has zero frames).

    Parameters
    ----------
    series, summary : the run's Tables (:data:`deathsphere.simulation.SERIES_COLUMNS`,
        :data:`deathsphere.simulation.SUMMARY_COLUMNS`)
    frames : :meth:`deathsphere.simulation.Simulation.view_frames`: per
        ``input_row``, the sample times ``t`` and the geometry at them, row for
        row with that body's rows of ``series``
    max_frames : frames kept per body (:func:`frame_indices`); the spin is
        integrated over every sample before the frames are picked
    """
    rows = np.asarray(series["input_row"])
    scenes = []
    for i, row in enumerate(np.asarray(summary["input_row"])):
        sel = np.flatnonzero(rows == row)
        t = np.asarray(series["t_s"])[sel]
        geo = frames.get(int(row))
        if sel.size and (geo is None or not np.array_equal(geo["t"], t)):
            raise ValueError("frames do not match the time series row for row")
        status = str(summary["status"][i])
        ev = _float(summary["event_time_s"][i]) if status in ("contact_lost", "slips", "failed") else None
        scene = BodyScene(
            input_row=int(row), body=str(summary["body"][i]), side=str(summary["side"][i]),
            orbit=str(summary["orbit"][i]), a=float(summary["a_m"][i]), r=float(summary["r_m"][i]),
            g=float(summary["g_m_s2"][i]),
            theta0_deg=float(summary["theta_deg"][i]), alpha0_deg=float(summary["alpha_deg"][i]),
            period=float(summary["period_s"][i]), status=status, reason=str(summary["reason"][i]),
            event_time=ev, t=np.zeros(0))
        if sel.size:
            keep = frame_indices(sel.size, max_frames)
            scene.t = t[keep]
            scene.geometry = {k: v[..., keep] for k, v in geo.items() if k != "t"}
            scene.panel = {k: np.asarray(series[col])[sel][keep] for k, col in PANEL_COLUMNS.items()}
            scene.panel["g_load"] = geo["g_load"][keep]
        scenes.append(scene)
    return scenes
