"""Sweep throughput and memory.

Run:  python benchmarks/bench_sweep.py [--rows 1000000] [--big 10000000]

Prints
1. CSV rows/s of deathsphere's writer against numpy.savetxt of the same
   float columns (savetxt gets the easier job: no text columns, no empty
   cells), both to /dev/null, in one process;
2. peak resident memory of `deathsphere sweep` processes of 1e5 and --big
   orbits to /dev/null (each in its own child, so ru_maxrss is its own).
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time

import numpy as np

from deathsphere.grid import grid_chunks
from deathsphere.model import TEXT_COLUMNS, evaluate, make_requests
from deathsphere.render import write_csv

CHUNK = 16384


def tables(rows: int):
    side = int(np.ceil(np.sqrt(rows)))
    axes = {"theta": np.linspace(0, 180, side), "alpha": np.linspace(-90, 90, side)}
    produced = 0
    for first, grid in grid_chunks(axes, CHUNK):
        if produced >= rows:
            return
        n = min(len(grid["theta"]), rows - produced)
        yield evaluate(make_requests(n, input_row=np.arange(first + 1, first + n + 1),
                                     theta=grid["theta"][:n], alpha=grid["alpha"][:n]))
        produced += n


def peak_rss_mb(n_theta: int, n_alpha: int) -> tuple[float, float]:
    """Peak RSS [MB] and wall time [s] of one sweep process to /dev/null."""
    code = (
        "import resource, subprocess, sys, time\n"
        "t = time.perf_counter()\n"
        f"subprocess.run([sys.executable, '-m', 'deathsphere', 'sweep', '--theta', '0:180:{180 / (n_theta - 1)!r}',"
        f" '--alpha', '-90:90:{180 / (n_alpha - 1)!r}'], stdout=subprocess.DEVNULL, check=True)\n"
        "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024, time.perf_counter() - t)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    rss, wall = map(float, out.split())
    return rss, wall


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--rows", type=int, default=1_000_000)
    p.add_argument("--big", type=int, default=10_000_000)
    args = p.parse_args()

    chunks = list(tables(args.rows))
    with open(os.devnull, "w") as devnull:
        t = time.perf_counter()
        write_csv(iter(chunks), devnull)
        ours = time.perf_counter() - t
        floats = [n for n in chunks[0].names if n not in TEXT_COLUMNS]
        t = time.perf_counter()
        for c in chunks:
            np.savetxt(devnull, np.column_stack([c[n].astype(float) for n in floats]), fmt="%.17g", delimiter=",")
        theirs = time.perf_counter() - t
    print(f"CSV writer   : {args.rows / ours:12,.0f} rows/s  ({len(chunks[0].names)} columns, {ours:.2f} s)")
    print(f"numpy.savetxt: {args.rows / theirs:12,.0f} rows/s  ({len(floats)} float columns, {theirs:.2f} s)")
    print(f"ratio writer/savetxt speed: {theirs / ours:.2f}x")

    small = peak_rss_mb(317, 316)                     # ~1e5 orbits
    side = int(np.ceil(np.sqrt(args.big)))
    big = peak_rss_mb(side, side)
    print(f"peak RSS, sweep of {317 * 316:>12,} orbits: {small[0]:7.1f} MB  ({small[1]:.1f} s)")
    print(f"peak RSS, sweep of {side * side:>12,} orbits: {big[0]:7.1f} MB  ({big[1]:.1f} s, "
          f"{side * side / big[1]:,.0f} rows/s end to end)")
    print(f"memory growth: {big[0] - small[0]:+.1f} MB (goal: within 20 MB)")


if __name__ == "__main__":
    main()
