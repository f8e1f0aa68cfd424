"""The one thing every 3-D view draws: a scene (docs/simulation.md, "3-D
view"; docs/show.md sec. 8; docs/two-wheeler.md sec. 10.1).

A scene is a ground and, per body, a track.  The ground is data: the globe
``{"kind": "sphere", "radius": r}``, flat ground ``{"kind": "plane",
"centre": [x, y], "half_width": w}``, or any surface of revolution about z
given by its meridian ``{"kind": "revolution", "rho": [...], "z": [...]}``
(a drum, a cone): the page and the loop draw each from that description,
not from the kind of run.

A track is named point sets over time (the contact, wheel rims, frame,
rider, force vectors ...) at its frames, paths on time axes of their own
(a trail, a fall), its status and event, the panel's readouts (numbers
with labels and units) and how it is drawn: a list of items, each a
drawing primitive naming the points it joins (:data:`DRAW_KINDS`).  Body
shapes are items, not code paths of the viewer.

Nothing here is physics: the builders (:mod:`~deathsphere.viewer.orbit_scene`,
:mod:`~deathsphere.viewer.two_wheeler_scene`, :mod:`~deathsphere.viewer.show_scene`)
pick the simulation's own numbers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Scene", "Track", "Readout", "sphere_ground", "plane_ground", "revolution_ground", "wall_ground", "WALL_POINTS", "ground_extent",
           "frame_indices", "playback_factor", "slow_motion_words", "PLAYBACK_FACTORS", "EVENT_STATUSES",
           "DRAW_KINDS"]

#: the playback factors offered (simulated seconds per second shown), from
#: real time down: a fast run plays at the largest that does not alias
PLAYBACK_FACTORS = (10.0, 5.0, 2.0, 1.0) + tuple(
    1.0 / (m * 10.0 ** e) for e in range(4) for m in (1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10) if m * 10 ** e > 1)
#: statuses that end a run at an event of the simulation: the labels of
#: deathsphere.simulation.status.ENDED_EARLY, written out because the viewer
#: reads tables only (a test keeps the two equal)
EVENT_STATUSES = ("contact_lost", "slips", "failed", "hits_floor", "over_the_top")
#: the drawing primitives a track's items name (their keys: docs/simulation.md, "3-D view")
DRAW_KINDS = ("wheel", "ball", "chain", "ring", "dot", "path", "arrow", "capsule", "cross", "label")


def sphere_ground(radius: float) -> dict:
    """The globe of radius r [m], centred at the origin."""
    return {"kind": "sphere", "radius": float(radius)}


def plane_ground(centre, half_width: float) -> dict:
    """Flat ground z = 0: the square of ``half_width`` [m] about ``centre``
    (x, y) that the run covers."""
    return {"kind": "plane", "centre": [float(centre[0]), float(centre[1])], "half_width": float(half_width)}


def revolution_ground(rho, z) -> dict:
    """A surface of revolution about z, its meridian the table (rho, z) [m]
    from one end to the other (a drum: rho constant; a cone: rho linear in z)."""
    return {"kind": "revolution", "rho": [float(x) for x in rho], "z": [float(x) for x in z]}


#: Points of a drum's, a cone's or a profile's drawn meridian up its wall.
WALL_POINTS = 25


def wall_ground(ground, open_top: float) -> dict:
    """A wall's ground record (a drum, a cone, a profile) as the scene draws
    it: its meridian from the floor's centre out along the floor and up the
    wall to its top (a wall without a top: up to the height ``open_top``
    [m] above its lowest point), :data:`WALL_POINTS` points up the wall,
    evenly spaced along the meridian (a profile's bowl, whose wall leaves
    the floor flat, is drawn as finely there as up its side)."""
    top = float(ground.highest_lane)
    if not math.isfinite(top):
        top = float(open_top)
    rho, z = ground.meridian(np.linspace(0.0, float(ground.arc_length(top)), WALL_POINTS))[:2]
    rho, z = np.concatenate(([0.0], rho)), np.concatenate(([float(ground.lowest)], z))
    return revolution_ground(rho, z)


def ground_extent(ground: dict) -> float:
    """Half the size of the ground [m]: what a camera frames."""
    if ground["kind"] == "sphere":
        return ground["radius"]
    if ground["kind"] == "plane":
        return ground["half_width"]
    rho, z = np.asarray(ground["rho"]), np.asarray(ground["z"])
    return float(max(rho.max(), 0.5 * np.ptp(z)))


@dataclass
class Readout:
    """One number of the panel: ``values`` at the track's frames, or a
    constant ``value`` (None: ``none_text``); shown as label, value with
    ``digits`` decimals, and unit.  ``join`` puts it on the previous
    readout's row after that separator; ``note`` in the panel's small
    line ("label = value unit"); ``loop`` in a GIF / MP4 loop's panel too,
    on the previous line after ``loop_join`` if that is given (a loop's
    panel is drawn every frame: fewer lines, less to draw)."""

    key: str
    label: str
    unit: str = ""
    digits: int = 2
    values: np.ndarray | None = None
    value: float | None = None
    none_text: str = "-"
    join: str = ""
    note: bool = False
    loop: bool = True
    loop_join: str = ""

    def at(self, i: int) -> float | None:
        return float(self.values[i]) if self.values is not None else self.value


@dataclass
class Track:
    """One body over time.  ``t`` (F,) its frame times [s]; ``points`` name
    -> (3, F), or (3, K, F) for K points a frame (a rim); ``scalars`` name
    -> (F,) (a spin angle); ``paths`` name -> (times (T,), points (3, T)) on
    an axis of their own; ``draw`` its items (dicts, ``kind`` one of
    :data:`DRAW_KINDS`); ``panel`` its :class:`Readout` rows, ``note`` the
    panel's small print; ``event_time`` [s] (None: no event), shown from
    then on with ``event_words`` at the point ``event_point``; ``motion``
    the fastest turn and move per frame (``rate`` [rad/s], ``speed``
    [m/s] (F,), ``bounds``: turn [rad], move [in ground sizes]) that
    choose the playback factor; ``meta`` what else the page may say of
    it (JSON-able)."""

    name: str
    t: np.ndarray
    points: dict = field(default_factory=dict)
    scalars: dict = field(default_factory=dict)
    paths: dict = field(default_factory=dict)
    draw: list = field(default_factory=list)
    panel: list = field(default_factory=list)
    note: str = ""
    status: str = "completed"
    reason: str = ""
    event_time: float | None = None
    event_point: str = ""
    motion: dict | None = None
    meta: dict = field(default_factory=dict)

    @property
    def n_frames(self) -> int:
        return int(self.t.size)

    @property
    def event_words(self) -> str:
        """'contact lost', 'slips', 'failed' ('' without an event)."""
        return self.status.replace("_", " ") if self.event_time is not None else ""

    def readout(self, key: str) -> Readout:
        return next(r for r in self.panel if r.key == key)


@dataclass
class Scene:
    """A ground, the tracks on it, and how to show them: ``title``;
    ``camera`` (``az``, ``el`` [deg], ``target`` [m], ``extent`` [m] the
    half-size framed); ``follow`` (None, or the camera riding along: the
    ``track`` index and its point ``target``, a ``heading`` pair of points
    whose direction is ahead, the ground's normal at the first up (None:
    the lab's axes), ``size`` [m] framed, and the
    angles ``az``, ``el`` [deg] it starts at); ``playback`` the factor to
    start at (None: chosen from the tracks' motion), ``loop_playback`` a GIF
    / MP4 loop's (None: the same); ``focus`` the time [s] a loop too short
    for the whole run centres on (None: it shows the run's end); ``legend`` rows
    (``colour``, ``text``, optional ``toggle``); ``notes`` (``text``,
    optional ``colour``) under the legend; ``moments`` (``label``, ``t``)
    the controls jump to; ``pair`` two tracks marked at a moment (``tracks``,
    ``t``, ``near`` [s]); ``fall`` (``track``, ``outcome``)."""

    ground: dict
    tracks: list
    title: str = ""
    camera: dict = field(default_factory=dict)
    follow: dict | None = None
    playback: float | None = None
    loop_playback: float | None = None
    focus: float | None = None
    legend: list = field(default_factory=list)
    notes: list = field(default_factory=list)
    moments: list = field(default_factory=list)
    pair: dict | None = None
    fall: dict | None = None

    @property
    def drawn(self) -> list:
        return [s for s in self.tracks if s.n_frames]

    @property
    def t_start(self) -> float:
        return min((float(s.t[0]) for s in self.drawn), default=0.0)

    @property
    def t_end(self) -> float:
        return max((float(s.t[-1]) for s in self.drawn), default=0.0)


def frame_indices(n: int, max_points: int) -> np.ndarray:
    """Indices of at most ``max_points`` (+1) of n points, evenly strided,
    always with the first and the last."""
    if n <= max_points:
        return np.arange(n)
    step = math.ceil((n - 1) / (max_points - 1))
    idx = np.arange(0, n, step)
    return idx if idx[-1] == n - 1 else np.append(idx, n - 1)


def playback_factor(scene: Scene, frame_interval: float, t_from: float = -math.inf) -> float:
    """The scene's own factor if it has one; else the largest of
    :data:`PLAYBACK_FACTORS`, at most 1 (real time), at which frames
    ``frame_interval`` [s] apart on screen show every track turning at most
    its bound and moving at most its bound (a fraction of the ground's
    size) from one to the next, over the frames from ``t_from`` on: the
    fastest rotation |w| and speed of the simulation's frames decide."""
    if scene.playback is not None:
        return scene.playback
    need, size = 1.0, ground_extent(scene.ground)
    for s in scene.tracks:
        keep = s.t >= t_from
        if s.motion is None or s.n_frames < 2 or not keep.any():
            continue
        rate = np.nanmax(s.motion["rate"][keep])
        speed = np.nanmax(s.motion["speed"][keep])
        with np.errstate(divide="ignore"):
            turn, move = s.motion["bounds"]
            need = min(need, turn / (rate * frame_interval), move * size / (speed * frame_interval))
    return max([f for f in PLAYBACK_FACTORS if f <= need], default=PLAYBACK_FACTORS[-1])


def slow_motion_words(factor_: float) -> str:
    """'real time', 'slow motion x4', '2x real time'."""
    if abs(factor_ - 1.0) < 1e-12:
        return "real time"
    if factor_ < 1.0:
        return f"slow motion \u00d7{1 / factor_:g}"
    return f"{factor_:g}\u00d7 real time"
