"""The 3-D view's cost: the frames placed between the rows, the page's size,
and the GIF / MP4 loop's peak memory and time per frame.

Run:  python benchmarks/bench_view.py [--periods 20] [--mp4]

Prints, for a Table 1 orbit (theta 60, alpha 10, wheel inside) of
--periods periods, a vertical loop and a fast ball (theta 120, omega3 80):
1. rows, frames after refinement, the time to place them, and the largest
   turn and centre step between frames (bounds: 90 deg, 2 % of r);
2. the HTML page's size and the time to write it;
3. for the Table 1 orbit, `deathsphere simulate ... --output F.gif` (and
   .mp4 with --mp4) run in a child process: wall time, frames, time per
   frame and peak resident memory (the child's ru_maxrss), and the file's
   size.  The child is the command line itself, so the figure includes the
   simulation and Python's start-up.
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from deathsphere import simulation as sim
from deathsphere.model import Setup
from deathsphere.simulation.frames import body_frames
from deathsphere.viewer import write_view


def _run(starts, periods):
    s = sim.Simulation(starts, periods=periods, points_per_period=100, record_states=True)
    series, summary = s.run()
    return series, summary, s.sample_states()


def frames_and_page(name, starts, periods, folder):
    series, summary, states = _run(starts, periods)
    t0 = time.perf_counter()
    frames = body_frames(summary, states)
    placed = time.perf_counter() - t0
    (geo,) = frames.values()
    r = float(summary["r_m"][0])
    turn = np.degrees(np.max(0.5 * (geo["rate"][1:] + geo["rate"][:-1]) * np.diff(geo["t"])))
    step = np.max(np.linalg.norm(np.diff(geo["centre"], axis=1), axis=0)) / r
    raw = states["state"]
    raw_step = np.max(np.linalg.norm(np.diff(raw[0:3], axis=1), axis=0)) / r
    t0 = time.perf_counter()
    size = write_view(Path(folder) / f"{name}.html", series, summary, frames)
    page = time.perf_counter() - t0
    print(f"{name:12s} rows {len(series):6d}  frames {geo['t'].size:6d}  placed in {placed:5.2f} s  "
          f"max turn {turn:5.1f} deg  max step {100 * step:4.2f} % r (rows alone: {100 * raw_step:4.2f} %)  "
          f"page {size / 1e6:5.2f} MB in {page:4.2f} s")


def loop(periods, ext, folder):
    out = Path(folder) / f"orbit.{ext}"
    code = ("import resource, runpy, sys; sys.argv = sys.argv[1:]\n"
            "try:\n    runpy.run_module('deathsphere', run_name='__main__')\n"
            "finally:\n    print('maxrss_kb', resource.getrusage(resource.RUSAGE_SELF).ru_maxrss, file=sys.stderr)\n")
    args = [sys.executable, "-c", code, "deathsphere", "simulate", "--theta", "60", "--alpha", "10",
            "--periods", str(periods), "--output", str(out)]
    t0 = time.perf_counter()
    res = subprocess.run(args, capture_output=True, text=True, env={**os.environ, "PYTHONWARNINGS": "ignore"})
    wall = time.perf_counter() - t0
    if res.returncode:
        print(res.stderr)
        return
    rss = [int(line.split()[1]) for line in res.stderr.splitlines() if line.startswith("maxrss_kb")][0]
    if ext == "gif":
        from PIL import Image

        with Image.open(out) as im:
            n = im.n_frames
    else:
        n = None
    # the frames' share of the wall time: the same run writing nothing
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "deathsphere", "simulate", "--theta", "60", "--alpha", "10", "--periods",
                    str(periods), "--summary-only", "--format", "csv"], capture_output=True)
    base = time.perf_counter() - t0
    per = f"{1000 * (wall - base) / n:5.1f} ms a frame" if n else ""
    print(f"{ext}: {wall:5.1f} s (the run alone {base:4.1f} s)  frames {n}  {per}  peak RSS {rss / 1024:6.1f} MB  "
          f"file {out.stat().st_size / 1e6:5.2f} MB  stdout {len(res.stdout)} bytes")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--periods", type=float, default=20)
    ap.add_argument("--mp4", action="store_true")
    opts = ap.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        frames_and_page("table1", sim.horizontal_starts(Setup(), 60, 10), opts.periods, folder)
        frames_and_page("vertical", sim.vertical_starts(Setup(), 90, speed=6.0), 5, folder)
        frames_and_page("fast ball", sim.horizontal_starts(Setup(body="sphere"), 120, omega3=80.0), 5, folder)
        loop(opts.periods, "gif", folder)
        if opts.mp4:
            loop(opts.periods, "mp4", folder)
    print(f"this process: peak RSS {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MB")


if __name__ == "__main__":
    main()
