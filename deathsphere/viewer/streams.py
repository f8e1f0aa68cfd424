"""A loop's frames written as they are drawn (docs/simulation.md, "3-D
view"): a GIF through Pillow's frame encoder with one palette for all
frames (taken from the first frame and the view's colours), an MP4 by
piping raw frames to ffmpeg.  No frame is held after it is written, so the
memory does not grow with the loop's length.
"""

from __future__ import annotations

import shutil
import subprocess

import numpy as np

from deathsphere.writers.atomic import atomic_path, signals_held

__all__ = ["frame_delays_ms", "write_frames", "SWATCHES", "FPS", "END_HOLD_S"]

#: frames a second of a loop: 40 ms, a whole number of the GIF's 10 ms
#: units, so the GIF's clock is exact
FPS = 25
#: how long the last frame (the run's end, an event's label) is held [s]
END_HOLD_S = 1.5

#: colours the GIF's palette must hold although the first frame may lack
#: them (an event's red may first appear at the end); a loop adds its own
SWATCHES = ("#e8c547", "#1f9bd1", "#1e8449", "#e67e22", "#d62728", "#c0392b", "#8e44ad", "#e91e9c", "#333333",
            "#8796b0", "#d4a017", "#9a7400", "#555555", "#ffffff", "#000000")


def frame_delays_ms(n: int, fps: int = FPS, hold_s: float = END_HOLD_S) -> list[int]:
    """How long each of n frames shows [ms], in the GIF's 10 ms units: the
    rounding is carried from frame to frame, so frame k starts at
    k * 1000 / fps ms within 10 ms and the loop's clock never drifts; the
    last frame is held ``hold_s``."""
    edges = np.round(np.arange(n) * 100.0 / fps).astype(np.int64) * 10
    delays = np.diff(edges).tolist()
    return [int(d) for d in delays] + [int(round(hold_s * 100)) * 10]


def _hex_rgb(colour):
    return tuple(int(colour[k:k + 2], 16) for k in (1, 3, 5))


class _GifStream:
    """A GIF written frame by frame (Pillow's GIF encoder, one global
    palette): nothing is held but the palette and the open file."""

    def __init__(self, path, swatches=SWATCHES):
        self._path = path
        self._swatches = swatches
        self._fp = None
        self._palette = None
        self._previous = None

    def start(self):
        self._fp = open(self._path, "wb")

    def add(self, rgb, duration_ms: int):
        from PIL import GifImagePlugin, Image

        im = Image.fromarray(rgb, "RGB")
        if self._palette is None:
            # the first frame's colours, and the view's own (an event's red
            # may first appear at the end): one palette for every frame,
            # so a frame's colours never flicker
            probe = Image.new("RGB", (im.width, im.height + 24))
            probe.paste(im, (0, 0))
            for k, colour in enumerate(self._swatches):
                probe.paste(Image.new("RGB", (24, 24), _hex_rgb(colour)), (24 * k, im.height))
            self._palette = probe.quantize(colors=256, method=Image.Quantize.MEDIANCUT)
            first = im.quantize(palette=self._palette, dither=Image.Dither.NONE)
            header, _ = GifImagePlugin.getheader(first, info={"loop": 0, "optimize": False})
            for chunk in header:
                self._fp.write(chunk)
            frame = first
        else:
            frame = im.quantize(palette=self._palette, dither=Image.Dither.NONE)
        # only the rectangle that changed is stored (the sphere and most of
        # the picture stay): the file is several times smaller
        pixels = np.asarray(frame)
        offset = (0, 0)
        if self._previous is not None:
            rows = np.flatnonzero(np.any(pixels != self._previous, axis=1))
            cols = np.flatnonzero(np.any(pixels != self._previous, axis=0))
            box = (cols[0], rows[0], cols[-1] + 1, rows[-1] + 1) if rows.size else (0, 0, 1, 1)
            offset = (int(box[0]), int(box[1]))
            frame = frame.crop(tuple(int(x) for x in box))
        self._previous = pixels
        for chunk in GifImagePlugin.getdata(frame, offset, duration=int(duration_ms), disposal=1):
            self._fp.write(chunk)

    def close(self):
        self._fp.write(b";")
        self._fp.close()

    def abort(self):
        if self._fp is not None:
            self._fp.close()


class _Mp4Stream:
    """Raw RGB frames piped to ffmpeg (H.264, yuv420p, playable in slide
    software); a frame's duration is repeated frames at the fixed rate."""

    def __init__(self, path, size, fps):
        from matplotlib import rcParams

        binary = shutil.which(rcParams["animation.ffmpeg_path"])
        if binary is None:      # refused before any work by check_view_output; here for direct callers
            raise RuntimeError("writing .mp4 needs the ffmpeg encoder, which is not on PATH; "
                               "install ffmpeg, or write .gif or .html instead")
        self._ms = 1000.0 / fps
        self._shown = 0.0
        self._sent = 0
        self._command = [binary, "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s",
                         f"{size[0]}x{size[1]}", "-r", str(fps), "-i", "-", "-c:v", "libx264", "-pix_fmt",
                         "yuv420p", "-movflags", "+faststart", str(path)]
        self._proc = None

    def start(self):
        # a session of its own: Ctrl-C at the terminal reaches this process
        # only, which stops the encoder itself (abort) before the partial
        # file is removed; an encoder stopped first would look like a reader
        # gone away (a broken pipe).  Started with the signals held, so
        # that an encoder started is always one recorded to be stopped.
        with signals_held():
            self._proc = subprocess.Popen(self._command, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                          stderr=subprocess.PIPE, start_new_session=True)

    def add(self, rgb, duration_ms: int):
        self._shown += duration_ms
        data = np.ascontiguousarray(rgb).tobytes()
        while (self._sent + 1) * self._ms <= self._shown + 1e-6:
            try:
                self._proc.stdin.write(data)
            except BrokenPipeError:
                # the encoder ended early: its own failure, not a reader gone
                self._proc.wait()
                raise RuntimeError(f"ffmpeg failed: {self._errors()}") from None
            self._sent += 1

    def _errors(self) -> str:
        return self._proc.stderr.read().decode(errors="replace").strip()[-500:]

    def close(self):
        self._proc.stdin.close()
        err = self._errors()
        if self._proc.wait() != 0:
            raise RuntimeError(f"ffmpeg failed: {err}")

    def abort(self):
        if self._proc is None:
            return
        self._proc.kill()
        self._proc.wait()
        for pipe in (self._proc.stdin, self._proc.stderr):
            try:
                pipe.close()
            except OSError:
                pass


def write_frames(output, draw, times, delays, size_px, fps, progress=None, swatches=SWATCHES) -> int:
    """Write the frames ``draw(t)`` (RGB arrays) at ``times`` with the GIF
    ``delays`` (or ``fps`` for an MP4 of ``size_px``) to ``output``, .gif or
    .mp4 by its extension, whole or not at all (:mod:`deathsphere.writers.atomic`;
    an interrupted encoder is stopped); ``progress(done, total)`` after each
    frame.  Returns the number of frames."""
    fmt = str(output).lower().rsplit(".", 1)[-1]
    with atomic_path(output) as temp:
        stream = _GifStream(temp, swatches) if fmt == "gif" else _Mp4Stream(temp, size_px, fps)
        try:
            stream.start()
            for k, t in enumerate(times):
                stream.add(draw(float(t)), delays[k])
                if progress is not None:
                    progress(k + 1, len(times))
        except BaseException:
            stream.abort()
            raise
        stream.close()
    return len(times)
