"""The 3-D view as one self-contained HTML file (beyond the paper;
docs/simulation.md, "3-D view").

The page is ``template.html`` (package data: plain JavaScript drawing on a
2-D canvas with its own perspective projection and depth-sorted drawing,
no third-party code) with the run's frames embedded as JSON: numbers are
little-endian float32 arrays in base64, about 5.3 characters a number;
times are float64, so that the last frame is the run's end (an event's
time) exactly, not its float32 rounding.
"""

from __future__ import annotations

import base64
import json
from importlib import resources

import numpy as np

from deathsphere.viewer.scene import PLAYBACK_FACTORS, BodyScene, playback_factor
from deathsphere.writers.atomic import atomic_file

__all__ = ["view_data", "filled_template", "render_html", "write_html", "decode_array", "DATA_MARK", "VECTOR_KEYS", "MACHINE_KEYS",
           "SCALAR_KEYS", "PANEL_KEYS", "SCREEN_INTERVAL_S"]

#: where the template takes the data (a JavaScript expression)
DATA_MARK = "/*__DEATHSPHERE_DATA__*/null"
#: frame vectors stored, (3, F) each, frame-major x, y, z
VECTOR_KEYS = ("centre", "axis", "e3", "contact", "normal_force", "friction_force")
#: a machine's frame vectors, stored when its frames have them: the centre
#: of mass and the top of the rider's head (simulation.frames)
MACHINE_KEYS = ("com", "head")
#: frame scalars stored, (F,) each
SCALAR_KEYS = ("spin",)
PANEL_KEYS = ("theta", "alpha", "speed", "speed_km_h", "g_load", "mu", "normal", "friction", "force_angle")
#: the screen refresh the page's default playback factor is chosen for
#: (60 Hz: a slower screen shows fewer frames, the clock still true)
SCREEN_INTERVAL_S = 1 / 60


def _encode(x, dtype="<f4") -> str:
    return base64.b64encode(np.ascontiguousarray(x, dtype=dtype).tobytes()).decode("ascii")


def decode_array(text: str, rows: int = 1, dtype="<f4") -> np.ndarray:
    """Inverse of the encoding: (F,) for rows 1, else (rows, F); times
    (``t``, ``trail_t``) are ``dtype="<f8"``."""
    x = np.frombuffer(base64.b64decode(text), dtype=dtype).astype(np.float64)
    return x if rows == 1 else x.reshape(-1, rows).T


def _body(scene: BodyScene) -> dict:
    out = {
        "input_row": scene.input_row, "body": scene.body, "side": scene.side, "orbit": scene.orbit,
        "a": scene.a, "r": scene.r, "g": scene.g, "theta0_deg": scene.theta0_deg,
        "alpha0_deg": scene.alpha0_deg, "period": scene.period if np.isfinite(scene.period) else None,
        "status": scene.status, "reason": scene.reason, "event_time": scene.event_time,
        "event_words": scene.event_words, "mu_available": scene.mu_available,
        "n": scene.n_frames, "t": _encode(scene.t, "<f8"),
        "trail_t": _encode(scene.trail_t, "<f8"), "trail": _encode(scene.trail.T) if scene.trail.size else "",
    }
    for key in VECTOR_KEYS:
        out[key] = _encode(scene.geometry[key].T) if scene.n_frames else ""
    for key in MACHINE_KEYS:
        if key in scene.geometry:
            out[key] = _encode(scene.geometry[key].T) if scene.n_frames else ""
    for key in SCALAR_KEYS:
        out[key] = _encode(scene.geometry[key]) if scene.n_frames else ""
    out["panel"] = {key: (_encode(scene.panel[key]) if scene.n_frames else "") for key in PANEL_KEYS}
    return out


def view_data(scenes: list[BodyScene], title: str = "") -> dict:
    """The JSON-able data the page reads: ``title``, ``t_start`` and
    ``t_end`` [s] (the earliest and latest frame of any body), ``playback``
    (the default playback factor, :func:`deathsphere.viewer.scene.playback_factor`
    at 60 frames a second), ``factors`` (those the page offers) and
    ``bodies`` (one dict per body, arrays base64, see :func:`decode_array`)."""
    drawn = [s for s in scenes if s.n_frames]
    return {"format": "deathsphere-view/2", "title": title,
            "t_start": min(float(s.t[0]) for s in drawn) if drawn else 0.0,
            "t_end": max(float(s.t[-1]) for s in drawn) if drawn else 0.0,
            "playback": playback_factor(scenes, SCREEN_INTERVAL_S), "factors": list(PLAYBACK_FACTORS),
            "bodies": [_body(s) for s in scenes]}


def filled_template(name: str, mark: str, data: dict, what: str) -> str:
    """The page ``name`` (a template of this package) with ``data`` as JSON
    in place of its ``mark``; every 3-D page is made so."""
    # nothing in the data may close the script element
    text = json.dumps(data, separators=(",", ":"), allow_nan=False).replace("</", "<\\/")
    page = resources.files("deathsphere.viewer").joinpath(name).read_text(encoding="utf-8")
    if mark not in page:
        raise RuntimeError(f"the {what} template lacks its data mark")
    return page.replace(mark, text, 1)


def render_html(scenes: list[BodyScene], title: str = "") -> str:
    """The page's text (UTF-8)."""
    return filled_template("template.html", DATA_MARK, view_data(scenes, title), "viewer")


def write_html(output, scenes: list[BodyScene], title: str = "") -> int:
    """Write the page to ``output``; returns its size in bytes."""
    data = render_html(scenes, title).encode("utf-8")
    with atomic_file(output, "wb") as out:
        out.write(data)
    return len(data)
