"""3-D view of a run (docs/simulation.md, "3-D view"; docs/show.md sec. 8;
docs/two-wheeler.md sec. 10.1): an interactive HTML page, or a GIF / MP4
loop, of one kind of thing for every run, a scene.

* :mod:`deathsphere.viewer.scene` -- a scene: a ground described as data
  and per body a track (named point sets over time, its status, event and
  panel, and how it is drawn);
* the scene's builders from each kind of run: :mod:`~deathsphere.viewer.orbit_scene`
  (the paper's wheel or ball, the single-contact machine),
  :mod:`~deathsphere.viewer.two_wheeler_scene`, :mod:`~deathsphere.viewer.show_scene`
  (a show's act);
* :mod:`deathsphere.viewer.html` -- one self-contained HTML file from the
  one template (no third-party code; it ships as package data);
* :mod:`deathsphere.viewer.animation` -- GIF (Pillow) or MP4 (ffmpeg) of
  any scene, drawn with matplotlib (the ``plot`` extra) and written frame
  by frame (:mod:`deathsphere.viewer.streams`).

:func:`check_view_output` says, before anything is integrated, whether the
file can be written here; :func:`write_scene` writes a scene,
:func:`write_view` a simulated orbit's.
"""

from __future__ import annotations

import importlib
import shutil
from pathlib import Path

from deathsphere.table import Table

__all__ = ["VIEW_FORMATS", "ViewerUnavailable", "view_format", "check_view_output", "write_scene", "write_view",
           "has_ffmpeg"]

#: --output extensions that give the 3-D view
VIEW_FORMATS = ("html", "gif", "mp4")


class ViewerUnavailable(RuntimeError):
    """The requested view cannot be written on this machine (a missing
    extra or encoder); the message is one line saying what to install."""


def view_format(output) -> str:
    """The lower-case extension of ``output`` without the dot ('' if none)."""
    return Path(output).suffix.lower().lstrip(".")


def has_ffmpeg() -> bool:
    """Whether the ffmpeg encoder that a .mp4 view needs is on this
    machine (where matplotlib's ``animation.ffmpeg_path`` points)."""
    # matplotlib asks the same question (animation.writers.is_available)
    from matplotlib import rcParams

    return shutil.which(rcParams["animation.ffmpeg_path"]) is not None


def check_view_output(output) -> str:
    """Check that ``output`` (.html, .gif or .mp4) can be written here,
    without computing anything; returns its format.

    Raises
    ------
    ValueError          the extension is not one of :data:`VIEW_FORMATS`
    ViewerUnavailable   .gif / .mp4 without matplotlib (the ``plot`` extra),
                        or .mp4 without the ffmpeg encoder
    """
    fmt = view_format(output)
    if fmt not in VIEW_FORMATS:
        raise ValueError(f"a 3-D view is written as .html, .gif or .mp4, got {str(output)!r}")
    if fmt == "html":
        return fmt
    from deathsphere.render.figures import EXTRA_HINT

    try:
        importlib.import_module("matplotlib")
    except ImportError:
        raise ViewerUnavailable(f"writing .{fmt} needs matplotlib, which is not installed; "
                                f"install the extra: {EXTRA_HINT}") from None
    if fmt == "mp4" and not has_ffmpeg():
        raise ViewerUnavailable("writing .mp4 needs the ffmpeg encoder, which is not on PATH; "
                                "install ffmpeg, or write .gif or .html instead")
    return fmt


def write_scene(output, scene, *, loop_seconds: float | None = None, playback: float | None = None,
                progress=None) -> int:
    """Write ``scene`` (:class:`deathsphere.viewer.scene.Scene`) to ``output``
    (.html, .gif or .mp4, by its extension), whole or not at all; returns
    the file's size in bytes.  A GIF or MP4 loop lasts at most
    ``loop_seconds`` (None: :data:`~deathsphere.viewer.animation.MAX_SECONDS`)
    and plays ``playback`` times real time (None: the scene's, or chosen so
    that nothing aliases); ``progress(k, n)`` is called after each of its
    frames."""
    fmt = check_view_output(output)
    if fmt == "html":
        from deathsphere.viewer.html import write_html

        return write_html(output, scene)
    from deathsphere.viewer.animation import MAX_SECONDS, write_animation

    write_animation(output, scene, max_seconds=MAX_SECONDS if loop_seconds is None else loop_seconds,
                    playback=playback, progress=progress)
    return Path(output).stat().st_size


def write_view(output, series: Table, summary: Table, frames: dict, *, title: str = "",
               loop_seconds: float | None = None, playback: float | None = None, progress=None,
               ground=None) -> int:
    """Write the 3-D view of a simulated orbit to ``output`` (.html, .gif or
    .mp4, by its extension); returns the file's size in bytes.

    ``series``, ``summary`` and ``frames`` are the run's time series, its
    summary and :meth:`deathsphere.simulation.Simulation.view_frames` (the
    geometry to draw, computed by the simulation: the viewer only draws);
    the other options are :func:`write_scene`'s, their checked values from
    :func:`deathsphere.api.animation_options`; ``ground`` the ground record
    of a run off the globe (:attr:`deathsphere.simulation.Simulation.ground`).
    """
    from deathsphere.viewer.orbit_scene import build_scene

    check_view_output(output)
    return write_scene(output, build_scene(series, summary, frames, title=title, ground=ground),
                       loop_seconds=loop_seconds,
                       playback=playback, progress=progress)
