"""A scene as one self-contained HTML file (docs/simulation.md, "3-D
view"; docs/show.md sec. 8; docs/two-wheeler.md sec. 10.1).

Every page is ``template.html`` (package data: plain JavaScript drawing on
a 2-D canvas with its own perspective projection and depth-sorted drawing,
no third-party code) with the scene embedded as JSON in place of its one
data mark: numbers are little-endian float32 arrays in base64, about 5.3
characters a number; times are float64, so that the last frame is the
run's end (an event's time) exactly, not its float32 rounding.
"""

from __future__ import annotations

import base64
import json
from importlib import resources

import numpy as np

from deathsphere.viewer.scene import PLAYBACK_FACTORS, Scene, Track, playback_factor
from deathsphere.writers.atomic import atomic_file

__all__ = ["scene_data", "render_html", "write_html", "decode_array", "encode_array", "DATA_MARK", "TEMPLATE",
           "FORMAT", "SCREEN_INTERVAL_S"]

#: the one page template, and where it takes the data (a JavaScript expression)
TEMPLATE = "template.html"
DATA_MARK = "/*__DEATHSPHERE_SCENE__*/null"
FORMAT = "deathsphere-scene/1"
#: the screen refresh the page's default playback factor is chosen for
#: (60 Hz: a slower screen shows fewer frames, the clock still true)
SCREEN_INTERVAL_S = 1 / 60


def encode_array(x, dtype="<f4") -> str:
    return base64.b64encode(np.ascontiguousarray(x, dtype=dtype).tobytes()).decode("ascii")


def decode_array(text: str, rows: int = 1, dtype="<f4") -> np.ndarray:
    """Inverse of the encoding: (F,) for rows 1, else (rows, F); times are
    ``dtype="<f8"``."""
    x = np.frombuffer(base64.b64decode(text), dtype=dtype).astype(np.float64)
    return x if rows == 1 else x.reshape(-1, rows).T


def _points(x: np.ndarray) -> dict:
    """(3, F) or (3, K, F), stored frame-major, then point, then x, y, z."""
    x = np.asarray(x)
    return {"k": 1 if x.ndim == 2 else int(x.shape[1]), "xyz": encode_array(x.T if x.ndim == 2 else
                                                                             np.transpose(x, (2, 1, 0)))}


def _readout(r) -> dict:
    out = {"key": r.key, "label": r.label, "unit": r.unit, "digits": r.digits}
    if r.values is not None:
        out["values"] = encode_array(r.values)
    else:
        out.update({"value": r.value, "none": r.none_text})
    out.update({k: getattr(r, k) for k in ("join", "note") if getattr(r, k)})
    return out


def _track(s: Track) -> dict:
    return {"name": s.name, "n": s.n_frames, "t": encode_array(s.t, "<f8"), "status": s.status, "reason": s.reason,
            "event_time": s.event_time, "event_words": s.event_words, "event_point": s.event_point,
            "points": {k: _points(v) for k, v in s.points.items()},
            "scalars": {k: encode_array(v) for k, v in s.scalars.items()},
            "paths": {k: {"t": encode_array(t, "<f8"), "xyz": encode_array(np.asarray(x).T)}
                      for k, (t, x) in s.paths.items()},
            "draw": s.draw, "panel": [_readout(r) for r in s.panel], "note": s.note, "meta": s.meta}


def scene_data(scene: Scene) -> dict:
    """The JSON-able data the page reads: the scene's ground, camera and
    words, ``t_start`` and ``t_end`` [s] (the earliest and latest frame of
    any track), ``playback`` (the factor it starts at: the scene's, or
    :func:`~deathsphere.viewer.scene.playback_factor` at 60 frames a
    second), ``factors`` (those the page offers) and ``tracks`` (arrays
    base64, see :func:`decode_array`)."""
    return {"format": FORMAT, "title": scene.title, "ground": scene.ground, "camera": scene.camera,
            "follow": scene.follow, "t_start": scene.t_start, "t_end": scene.t_end,
            "playback": playback_factor(scene, SCREEN_INTERVAL_S), "factors": list(PLAYBACK_FACTORS),
            "legend": scene.legend, "notes": scene.notes, "moments": scene.moments, "pair": scene.pair,
            "fall": scene.fall, "tracks": [_track(s) for s in scene.tracks]}


def render_html(scene: Scene) -> str:
    """The page's text (UTF-8): the template with the scene as JSON in
    place of its data mark."""
    # nothing in the data may close the script element
    text = json.dumps(scene_data(scene), separators=(",", ":"), allow_nan=False).replace("</", "<\\/")
    page = resources.files("deathsphere.viewer").joinpath(TEMPLATE).read_text(encoding="utf-8")
    if page.count(DATA_MARK) != 1:
        raise RuntimeError("the viewer's template lacks its data mark")
    return page.replace(DATA_MARK, text, 1)


def write_html(output, scene: Scene) -> int:
    """Write the page to ``output``, whole or not at all; returns its size
    in bytes."""
    data = render_html(scene).encode("utf-8")
    with atomic_file(output, "wb") as out:
        out.write(data)
    return len(data)
